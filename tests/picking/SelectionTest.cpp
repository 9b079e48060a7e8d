// Selection: the selected glyphs, and only they, are drawn tinted, and selecting re-packs nothing.

#include "RenderHarness.h"

#include <osgGlyphs/GlyphCloud>
#include <osgGlyphs/ImpostorTechniques>

#include <gtest/gtest.h>
#include <osgUtil/LineSegmentIntersector>

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace osgGlyphsTest;
using osgGlyphs::GlyphCloud;
using osgGlyphs::GlyphCulling;
using osgGlyphs::GlyphShape;

namespace
{

const int SIZE = 120;

/** Six glyphs in two rows; listed in spatial order, or in reverse, which a culling cloud draws
 * from copies of its arrays in spatial order. */
osg::ref_ptr<GlyphCloud> createCloud(GlyphShape shape, bool reversed)
{
    osg::ref_ptr<osg::Vec3Array> positions = new osg::Vec3Array, vectors = new osg::Vec3Array;
    osg::ref_ptr<osg::Vec4ubArray> colors = new osg::Vec4ubArray;
    for (int k = 0; k < 6; ++k)
    {
        const int i = reversed ? 5 - k : k;
        positions->push_back(
            osg::Vec3(float(i % 3) * 2.2f - 2.2f, float(i) * 0.3f, float(i / 3) * 2.2f - 1.1f));
        vectors->push_back(osg::Vec3(0.3f, 0.2f, 1.0f));
        colors->push_back(osg::Vec4ub(40 * i, 200 - 30 * i, 90, 255));
    }
    osg::ref_ptr<GlyphCloud> cloud = new GlyphCloud;
    cloud->setShape(shape);
    cloud->setPositions(positions.get());
    cloud->setVectors(vectors.get());
    cloud->setRadius(0.8f);
    cloud->setColors(colors.get());
    cloud->setLengthScale(1.5f);
    cloud->setLit(false);
    return cloud;
}

/** The glyph seen at each pixel, by picking through its centre (-1: none). */
std::vector<int> glyphUnderEachPixel(Renderer& renderer, osg::Node& scene)
{
    std::vector<int> labels;
    osgViewer::View& view = *renderer.getViewer();
    for (int y = 0; y < SIZE; ++y)
        for (int x = 0; x < SIZE; ++x)
        {
            osgUtil::LineSegmentIntersector::Intersections hits;
            osg::NodePath path{&scene};
            labels.push_back(view.computeIntersections(view.getCamera(), osgUtil::Intersector::WINDOW,
                                                       x + 0.5f, y + 0.5f, path, hits)
                                 ? int(hits.begin()->primitiveIndex)
                                 : -1);
        }
    return labels;
}

/** Per pixel: unselected glyphs and background unchanged, selected glyphs tinted as the shader mixes. */
void expectSelectionDrawn(const Frame& plain, const Frame& selected, const std::vector<int>& labels,
                          const std::vector<unsigned int>& selection, const osg::Vec4& tint)
{
    int tinted = 0, unchanged = 0;
    for (int y = 1; y < SIZE - 1; ++y)
        for (int x = 1; x < SIZE - 1; ++x)
        {
            // Silhouette pixels, where the pick's pixel centre and the rasterised sample may disagree.
            const int label = labels[y * SIZE + x];
            bool edge = false;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    edge = edge || labels[(y + dy) * SIZE + x + dx] != label;
            if (edge)
                continue;
            const osg::Vec4ub before = plain.colorAt(x, y), after = selected.colorAt(x, y);
            const bool isSelected = label >= 0 && std::find(selection.begin(), selection.end(),
                                                            unsigned(label)) != selection.end();
            if (!isSelected)
            {
                ASSERT_EQ(before, after) << "pixel " << x << " " << y << " of glyph " << label << " changed";
                ++unchanged;
                continue;
            }
            for (int c = 0; c < 3; ++c)
            {
                const double expected = 255.0 * (before[c] / 255.0 * (1.0 - tint.a()) + tint[c] * tint.a());
                ASSERT_NEAR(after[c], expected, 2.0) << "pixel " << x << " " << y << " of glyph " << label;
            }
            ++tinted;
        }
    EXPECT_GT(tinted, 100);
    EXPECT_GT(unchanged, 100);
}

}

TEST(Selection, TintsExactlyTheSelectedGlyphs)
{
    for (GlyphShape shape : {GlyphShape::Sphere, GlyphShape::Arrow})
        for (GlyphCulling culling : {GlyphCulling::Off, GlyphCulling::Occlusion})
            for (bool pointSprites : {false, true})
                for (bool reversed : {false, true})
                {
                    SCOPED_TRACE(std::string(osgGlyphs::getShapeName(shape)) +
                                 (pointSprites ? " point sprites" : "") +
                                 (culling == GlyphCulling::Off ? " unculled" : " culled") +
                                 (reversed ? ", listed in reverse" : ""));
                    osg::ref_ptr<GlyphCloud> cloud = createCloud(shape, reversed);
                    cloud->setCulling(culling);
                    if (pointSprites)
                        cloud->setTechnique(new osgGlyphs::PointSpriteTechnique);
                    const bool drawnFromCopies =
                        cloud->getDrawnArrays().positions != cloud->getGlyphArrays().positions;
                    EXPECT_EQ(drawnFromCopies, reversed && culling != GlyphCulling::Off);
                    Renderer renderer(SIZE, SIZE);
                    renderer.setLookAt(osg::Vec3d(0.5, -12.0, 1.0), osg::Vec3d(0.0, 0.0, 0.0),
                                       osg::Vec3d(0, 0, 1));
                    const Frame plain = renderer.render(cloud.get());
                    const std::vector<int> labels = glyphUnderEachPixel(renderer, *cloud);

                    const osg::Array* packed = cloud->getGlyphArrays().radiusScalar;
                    const unsigned int packedCount = packed->getModifiedCount();
                    const unsigned int positionsCount = cloud->getPositions()->getModifiedCount();
                    const std::vector<unsigned int> selection = {1, 3, 4, 1000}; // 1000: no such glyph
                    cloud->setSelection(selection);
                    const Frame selected = renderer.render(cloud.get());
                    EXPECT_EQ(packed->getModifiedCount(), packedCount);
                    EXPECT_EQ(cloud->getPositions()->getModifiedCount(), positionsCount);
                    EXPECT_EQ(cloud->getGlyphArrays().radiusScalar, packed);
                    expectSelectionDrawn(plain, selected, labels, selection, cloud->getSelectionColor());
                    if (shape == GlyphShape::Sphere && culling == GlyphCulling::Occlusion && !pointSprites)
                        saveFrame(selected, "selection_spheres");

                    cloud->setSelection({});
                    const Frame cleared = renderer.render(cloud.get());
                    EXPECT_EQ(std::memcmp(cleared.color->data(), plain.color->data(),
                                          cleared.color->getTotalSizeInBytes()),
                              0);
                }
}
