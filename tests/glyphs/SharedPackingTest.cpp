/* GlyphCloud::setSharedPackingScales: a cloud holding a share of the glyphs packs them, given the
 * scales of all of them, exactly as one cloud of all the glyphs does. */

#include <osgGlyphs/GlyphCloud>

#include <gtest/gtest.h>

#include <vector>

namespace
{

const std::vector<float> RADII = {0.3f, 0.0517f, 2.5f, 0.77f, 1.3f, 0.0123f};
const std::vector<float> SCALARS = {3.0f, -1.25f, 7.5f, 0.1f, 2.0f, 5.5f};

/** Glyphs first .. last-1 of the six, along x. */
osg::ref_ptr<osgGlyphs::GlyphCloud> createCloud(unsigned int first, unsigned int last)
{
    osg::ref_ptr<osg::Vec3Array> positions = new osg::Vec3Array;
    osg::ref_ptr<osg::FloatArray> radii = new osg::FloatArray, scalars = new osg::FloatArray;
    for (unsigned int i = first; i < last; ++i)
    {
        positions->push_back(osg::Vec3(3.0f * i, 0.0f, 0.0f));
        radii->push_back(RADII[i]);
        scalars->push_back(SCALARS[i]);
    }
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = new osgGlyphs::GlyphCloud;
    cloud->setPositions(positions.get());
    cloud->setRadii(radii.get());
    cloud->setScalars(scalars.get());
    return cloud;
}

}

TEST(SharedPacking, AShareDecodesItsGlyphsAsTheWholeCloud)
{
    osg::ref_ptr<osgGlyphs::GlyphCloud> whole = createCloud(0, 6);
    const osgGlyphs::GlyphCloud::PackingScales scales = whole->getOwnPackingScales();
    EXPECT_EQ(scales.scalarMin, -1.25f);
    EXPECT_EQ(scales.scalarMax, 7.5f);
    EXPECT_EQ(scales.largestRadius, 2.5f);

    // The share without the largest radius and the extreme scalars.
    osg::ref_ptr<osgGlyphs::GlyphCloud> share = createCloud(3, 6);
    share->setSharedPackingScales(scales);
    for (unsigned int i = 0; i < 3; ++i)
    {
        const osg::BoundingBox a = share->computeGlyphBox(i), b = whole->computeGlyphBox(3 + i);
        EXPECT_EQ(a._max.y(), b._max.y()) << "radius of glyph " << 3 + i; // the decoded radius
        EXPECT_EQ(a._min.z(), b._min.z()) << "radius of glyph " << 3 + i;
    }
    EXPECT_EQ(share->getScalarRangeMin(), whole->getScalarRangeMin());
    EXPECT_EQ(share->getScalarRangeMax(), whole->getScalarRangeMax());
}
