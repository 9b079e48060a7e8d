// GlyphCloud's data path: colour modes and colour maps, attribute updates, bounds and culling,
// GPU footprint, invalid input, shader overrides, and a lit regression baseline.

#include "GlyphTestScenes.h"

#include <osgGlyphs/GlyphCloud>
#include <osgGlyphs/GlyphStateCache>
#include <osgGlyphs/ImpostorTechniques>
#include <osgGlyphs/ProgramErrorFilter>

#include <osg/MatrixTransform>
#include <osg/Sequence>
#include <osg/ShapeDrawable>
#include <osgDB/FileUtils>
#include <osgUtil/Optimizer>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <mutex>

using namespace osgGlyphsTest;
using osgGlyphs::ColorMap;
using osgGlyphs::GlyphCloud;

namespace
{

osg::Vec4ub toBytes(const osg::Vec4& color)
{
    osg::Vec4ub bytes;
    for (int c = 0; c < 4; ++c)
        bytes[c] = static_cast<unsigned char>(std::lround(std::clamp(color[c], 0.0f, 1.0f) * 255.0f));
    return bytes;
}

/** Three unlit spheres in a row, coloured by scalars. */
osg::ref_ptr<GlyphCloud> createScalarRow(const std::vector<float>& values)
{
    osg::ref_ptr<osg::Vec3Array> positions = new osg::Vec3Array;
    for (size_t i = 0; i < values.size(); ++i)
        positions->push_back(osg::Vec3(-2.5f + 2.5f * i, 0.0f, 0.0f));
    osg::ref_ptr<GlyphCloud> cloud = new GlyphCloud;
    cloud->setPositions(positions.get());
    cloud->setRadius(0.8f);
    cloud->setScalars(new osg::FloatArray(values.begin(), values.end()));
    cloud->setLit(false);
    return cloud;
}

/** The colour at the projected centre of each glyph of a cloud. */
std::vector<osg::Vec4ub> centreColours(const Frame& frame, const GlyphCloud& cloud)
{
    std::vector<osg::Vec4ub> colours;
    for (const osg::Vec3& p : *cloud.getPositions())
    {
        const osg::Vec3d window = frame.project(p);
        colours.push_back(frame.colorAt(int(window.x()), int(window.y())));
    }
    return colours;
}

class GlyphCloudData : public ::testing::Test
{
protected:
    Renderer renderer{160, 120};
};

}

TEST_F(GlyphCloudData, ScalarsFollowTheColorMapAndItsRange)
{
    osg::ref_ptr<GlyphCloud> cloud = createScalarRow({10.0f, 15.0f, 20.0f});
    const ColorMap* viridis = ColorMap::getBuiltin("viridis");
    ASSERT_NE(viridis, nullptr);
    osg::ref_ptr<osg::Node> scene = group({cloud.get()});

    std::vector<osg::Vec4ub> colours = centreColours(renderer.render(scene.get()), *cloud);
    for (int i = 0; i < 3; ++i)
        EXPECT_TRUE(colorNear(renderer.render(scene.get()), 0, 0, osg::Vec4ub(0, 0, 0, 255), 0));
    EXPECT_TRUE(labelOfColor(colours[0], {toBytes(viridis->getColor(0.0f))}, 2) == 0);
    EXPECT_TRUE(labelOfColor(colours[1], {toBytes(viridis->getColor(0.5f))}, 2) == 0);
    EXPECT_TRUE(labelOfColor(colours[2], {toBytes(viridis->getColor(1.0f))}, 2) == 0);

    cloud->setScalarRange(15.0f, 25.0f);
    colours = centreColours(renderer.render(scene.get()), *cloud);
    EXPECT_TRUE(labelOfColor(colours[0], {toBytes(viridis->getColor(0.0f))}, 2) == 0) << "clamped below";
    EXPECT_TRUE(labelOfColor(colours[1], {toBytes(viridis->getColor(0.0f))}, 2) == 0);
    EXPECT_TRUE(labelOfColor(colours[2], {toBytes(viridis->getColor(0.5f))}, 2) == 0);

    osg::ref_ptr<ColorMap> custom =
        new ColorMap("red-blue", {osg::Vec4(1.0f, 0.0f, 0.0f, 1.0f), osg::Vec4(0.0f, 0.0f, 1.0f, 1.0f)});
    cloud->setColorMap(custom.get());
    cloud->resetScalarRange();
    colours = centreColours(renderer.render(scene.get()), *cloud);
    EXPECT_TRUE(labelOfColor(colours[0], {osg::Vec4ub(255, 0, 0, 255)}, 2) == 0);
    EXPECT_TRUE(labelOfColor(colours[1], {osg::Vec4ub(128, 0, 128, 255)}, 2) == 0);
    EXPECT_TRUE(labelOfColor(colours[2], {osg::Vec4ub(0, 0, 255, 255)}, 2) == 0);
}

TEST_F(GlyphCloudData, BuiltinColorMapsParseAndDiffer)
{
    const std::vector<std::string> names = ColorMap::getBuiltinNames();
    EXPECT_GE(names.size(), 4u);
    for (const std::string& name : names)
    {
        const ColorMap* map = ColorMap::getBuiltin(name);
        ASSERT_NE(map, nullptr) << name;
        EXPECT_GE(map->getColors().size(), 2u) << name;
    }
    // The diverging map is symmetric around a light centre.
    const ColorMap* coolwarm = ColorMap::getBuiltin("coolwarm");
    const osg::Vec4 centre = coolwarm->getColor(0.5f);
    EXPECT_GT(centre.r() + centre.g() + centre.b(), 2.4f);
    EXPECT_EQ(ColorMap::getBuiltin("no-such-map"), nullptr);

    std::string error;
    EXPECT_FALSE(ColorMap::parse("bad", "#ff0000\nnot-a-colour\n", error).valid());
    EXPECT_NE(error.find("bad:2"), std::string::npos) << error;
}

TEST_F(GlyphCloudData, UpdatesRepackAndReuploadOnlyWhatChanged)
{
    osg::ref_ptr<GlyphCloud> cloud = createScalarRow({0.0f, 1.0f, 2.0f});
    osg::ref_ptr<osg::Node> scene = group({cloud.get()});
    const ColorMap* viridis = ColorMap::getBuiltin("viridis");
    renderer.render(scene.get());

    const osg::Array* packed = cloud->getVertexAttribArray(osgGlyphs::RADIUS_SCALAR_ATTRIBUTE);
    const unsigned int packedCount = packed->getModifiedCount();
    const unsigned int positionCount = cloud->getPositions()->getModifiedCount();

    // New scalars: the packed attribute is re-uploaded, the positions are not.
    (*cloud->getScalars())[0] = 2.0f;
    (*cloud->getScalars())[2] = 0.0f;
    cloud->getScalars()->dirty();
    cloud->dirtyGlyphs();
    EXPECT_GT(packed->getModifiedCount(), packedCount);
    EXPECT_EQ(cloud->getPositions()->getModifiedCount(), positionCount);
    std::vector<osg::Vec4ub> colours = centreColours(renderer.render(scene.get()), *cloud);
    EXPECT_TRUE(labelOfColor(colours[0], {toBytes(viridis->getColor(1.0f))}, 2) == 0);
    EXPECT_TRUE(labelOfColor(colours[2], {toBytes(viridis->getColor(0.0f))}, 2) == 0);

    // Moved glyphs: the positions are re-uploaded, the unchanged packed attribute is not.
    const unsigned int packedAfterScalars = packed->getModifiedCount();
    (*cloud->getPositions())[1].z() = 1.5f;
    cloud->getPositions()->dirty();
    cloud->dirtyGlyphs();
    EXPECT_EQ(packed->getModifiedCount(), packedAfterScalars);
    const Frame moved = renderer.render(scene.get());
    const osg::Vec3d top = moved.project(osg::Vec3(0.0f, 0.0f, 1.5f));
    EXPECT_TRUE(moved.isCovered(int(top.x()), int(top.y())));
    const osg::Vec3d old = moved.project(osg::Vec3(0.0f, 0.0f, -0.6f));
    EXPECT_FALSE(moved.isCovered(int(old.x()), int(old.y())));
    EXPECT_GE(cloud->getBound().radius(), 0.0f);
    EXPECT_NEAR(cloud->getBoundingBox().zMax(), 1.5f + 0.8f, 1e-3f);
}

// A culling cloud whose glyphs are not listed in spatial order draws copies of its arrays in that
// order: gathered right, refilled after an edit of only what was edited, and dropped when it stops
// culling; each glyph keeps its colour.
TEST_F(GlyphCloudData, CulledCloudsDrawCopiesInSpatialOrder)
{
    osg::ref_ptr<GlyphCloud> cloud = createScalarRow({0.0f, 1.0f, 2.0f});
    osg::Vec3Array& positions = *cloud->getPositions();
    std::reverse(positions.begin(), positions.end()); // glyph 0 at the right end
    positions.dirty();
    cloud->dirtyGlyphs();
    osg::ref_ptr<osg::Node> scene = group({cloud.get()});
    const ColorMap* viridis = ColorMap::getBuiltin("viridis");

    const osgGlyphs::GlyphArrays source = cloud->getGlyphArrays(), drawn = cloud->getDrawnArrays();
    ASSERT_NE(drawn.positions, source.positions);
    ASSERT_EQ(drawn.count, 3u);
    const auto& drawnPositions = static_cast<const osg::Vec3Array&>(*drawn.positions);
    const auto& drawnPacked = static_cast<const osg::UIntArray&>(*drawn.radiusScalar);
    const auto& packed = static_cast<const osg::UIntArray&>(*source.radiusScalar);
    for (unsigned int k = 0; k < 3; ++k)
    {
        EXPECT_EQ(drawnPositions[k], positions[2 - k]) << k;
        EXPECT_EQ(drawnPacked[k], packed[2 - k]) << k;
    }
    std::vector<osg::Vec4ub> colours = centreColours(renderer.render(scene.get()), *cloud);
    for (unsigned int i = 0; i < 3; ++i)
        EXPECT_EQ(labelOfColor(colours[i], {toBytes(viridis->getColor(i / 2.0f))}, 2), 0) << i;

    const unsigned int positionsCount = drawn.positions->getModifiedCount();
    const unsigned int packedCount = drawn.radiusScalar->getModifiedCount();
    (*cloud->getScalars())[0] = 2.0f;
    (*cloud->getScalars())[2] = 0.0f;
    cloud->getScalars()->dirty();
    cloud->dirtyGlyphs();
    EXPECT_EQ(cloud->getDrawnArrays().radiusScalar, drawn.radiusScalar) << "refilled, not replaced";
    EXPECT_GT(drawn.radiusScalar->getModifiedCount(), packedCount);
    EXPECT_EQ(drawn.positions->getModifiedCount(), positionsCount);
    colours = centreColours(renderer.render(scene.get()), *cloud);
    EXPECT_EQ(labelOfColor(colours[0], {toBytes(viridis->getColor(1.0f))}, 2), 0);
    EXPECT_EQ(labelOfColor(colours[2], {toBytes(viridis->getColor(0.0f))}, 2), 0);

    cloud->setCulling(osgGlyphs::GlyphCulling::Off);
    EXPECT_EQ(cloud->getDrawnArrays().positions, source.positions);
    EXPECT_EQ(cloud->getVertexArray(), source.positions);
}

// Arrays shrunk in place and a setter called before dirtyGlyphs(): the cloud first catches up with
// the arrays rather than gathering copies from the glyphs they no longer hold (a read past the end
// that only a sanitizer saw).
TEST_F(GlyphCloudData, ASetterAfterArraysShrunkInPlaceCatchesUp)
{
    osg::ref_ptr<GlyphCloud> cloud = createScalarRow({0.0f, 1.0f, 2.0f});
    osg::Vec3Array& positions = *cloud->getPositions();
    std::reverse(positions.begin(), positions.end()); // drawn from copies in spatial order
    positions.dirty();
    cloud->dirtyGlyphs();
    ASSERT_NE(cloud->getDrawnArrays().positions, cloud->getGlyphArrays().positions);
    ASSERT_EQ(cloud->getNumGlyphs(), 3u);

    positions.resize(2);
    cloud->getScalars()->resize(2);
    positions.dirty();
    cloud->getScalars()->dirty();
    cloud->setScalarRange(-2.0f, 6.0f); // another quantisation range: the scalars are packed again
    EXPECT_EQ(cloud->getNumGlyphs(), 2u);
    const osgGlyphs::GlyphArrays drawn = cloud->getDrawnArrays();
    EXPECT_EQ(drawn.count, 2u);
    if (drawn.positions != cloud->getGlyphArrays().positions)
    {
        ASSERT_EQ(drawn.positions->getNumElements(), 2u);
        const auto& drawnPositions = static_cast<const osg::Vec3Array&>(*drawn.positions);
        EXPECT_TRUE((drawnPositions[0] == positions[0] && drawnPositions[1] == positions[1]) ||
                    (drawnPositions[0] == positions[1] && drawnPositions[1] == positions[0]));
    }
    const Frame frame = renderer.render(group({cloud.get()}).get());
    for (unsigned int i = 0; i < 2; ++i)
    {
        const osg::Vec3d centre = frame.project(positions[i]);
        EXPECT_TRUE(frame.isCovered(int(centre.x()), int(centre.y()))) << i;
    }
}

// Sorted spatially, a cloud draws its own arrays: every glyph keeps its values, a glyph that is
// not drawn goes last, and the picture is the same.
TEST_F(GlyphCloudData, SortedSpatiallyACloudDrawsItsOwnArrays)
{
    osg::ref_ptr<GlyphCloud> cloud = createScalarRow({0.0f, 1.0f, 2.0f, 3.0f, 4.0f});
    osg::Vec3Array& positions = *cloud->getPositions();
    std::reverse(positions.begin(), positions.end());
    positions[2].x() = std::nanf(""); // the middle glyph is not drawn
    positions.dirty();
    cloud->setRadii(makeArray<osg::FloatArray>({0.2f, 0.3f, 0.4f, 0.5f, 0.6f}));
    osg::ref_ptr<osg::Node> scene = group({cloud.get()});
    const Frame before = renderer.render(scene.get());
    ASSERT_NE(cloud->getDrawnArrays().positions, cloud->getGlyphArrays().positions);
    std::map<float, std::pair<float, float>> valuesAt; // x: scalar, radius
    for (unsigned int i = 0; i < 5; ++i)
        if (i != 2)
            valuesAt[positions[i].x()] = {(*cloud->getScalars())[i], (*cloud->getRadii())[i]};

    cloud->sortSpatially();
    EXPECT_EQ(cloud->getDrawnArrays().positions, cloud->getGlyphArrays().positions);
    const osg::Vec3Array& sorted = *cloud->getPositions();
    ASSERT_EQ(sorted.size(), 5u);
    EXPECT_TRUE(std::isnan(sorted[4].x())) << "the glyph not drawn goes last";
    EXPECT_EQ((*cloud->getScalars())[4], 2.0f);
    for (unsigned int i = 0; i < 4; ++i)
    {
        ASSERT_EQ(valuesAt.count(sorted[i].x()), 1u) << i;
        EXPECT_EQ((*cloud->getScalars())[i], valuesAt[sorted[i].x()].first) << i;
        EXPECT_EQ((*cloud->getRadii())[i], valuesAt[sorted[i].x()].second) << i;
        if (i > 0)
        {
            EXPECT_LT(sorted[i - 1].x(), sorted[i].x()) << "a row is sorted along it";
        }
    }
    const Frame after = renderer.render(scene.get());
    EXPECT_EQ(std::memcmp(after.color->data(), before.color->data(), after.color->getTotalSizeInBytes()), 0);
    EXPECT_EQ(std::memcmp(after.depth->data(), before.depth->data(), after.depth->getTotalSizeInBytes()), 0);
}

TEST_F(GlyphCloudData, GPUFootprintPerGlyph)
{
    for (bool reversed : {false, true})
    {
        // Culled, the glyphs are drawn in ranges of arrays in spatial order: the caller's, or
        // copies in that order (reversed), in place of them; no index buffer.
        std::vector<float> values = {0.0f, 1.0f, 2.0f, 3.0f};
        if (reversed)
            std::reverse(values.begin(), values.end());
        osg::ref_ptr<GlyphCloud> cloud = createScalarRow(values);
        if (reversed)
            std::reverse(cloud->getPositions()->begin(), cloud->getPositions()->end());
        cloud->dirtyGlyphs();
        cloud->setRadii(makeArray<osg::FloatArray>({0.5f, 0.6f, 0.7f, 0.8f}));
        EXPECT_EQ(cloud->getDrawnArrays().positions != cloud->getGlyphArrays().positions, reversed);
        EXPECT_EQ(cloud->getGPUBytesPerGlyph(), 16.0) << "position + radius + scalar";
        cloud->setCompressedPositions(true);
        EXPECT_EQ(cloud->getGPUBytesPerGlyph(), 10.0) << "16-bit position + radius + scalar";
        cloud->setCompressedPositions(false);
    }
    osg::ref_ptr<GlyphCloud> cloud = createScalarRow({0.0f, 1.0f, 2.0f, 3.0f});
    cloud->setCulling(osgGlyphs::GlyphCulling::Off);
    EXPECT_EQ(cloud->getGPUBytesPerGlyph(), 16.0) << "position + radius + scalar";
    cloud->setColors(makeArray<osg::Vec4ubArray>({osg::Vec4ub(1, 2, 3, 4), osg::Vec4ub(1, 2, 3, 4),
                                                  osg::Vec4ub(1, 2, 3, 4), osg::Vec4ub(1, 2, 3, 4)}));
    EXPECT_EQ(cloud->getGPUBytesPerGlyph(), 20.0) << "position + radius + RGBA8";
}

// Compressed positions: the nearest points of a power-of-two grid that spans the box in 65,532
// steps, which compress to themselves; the host arrays keep the caller's values.
TEST_F(GlyphCloudData, CompressedPositionsAreTheNearestPointsOfTheirGrid)
{
    const osg::Vec3 low(1000.0f, -2.0f, 0.0f), size(3.0f, 1.0f, 0.001f);
    osg::ref_ptr<osg::Vec3Array> positions = new osg::Vec3Array;
    for (int i = 0; i < 5000; ++i)
        positions->push_back(low + osg::Vec3(size.x() * std::fmod(0.618034f * i, 1.0f),
                                             size.y() * std::fmod(0.414214f * i, 1.0f),
                                             size.z() * std::fmod(0.732051f * i, 1.0f)));
    positions->push_back(osg::Vec3(std::nanf(""), 0.0f, 0.0f));
    osg::ref_ptr<GlyphCloud> cloud = new GlyphCloud;
    cloud->setPositions(positions.get());
    cloud->setRadius(0.01f);
    cloud->setCompressedPositions(true);
    EXPECT_EQ(cloud->getPositions(), positions.get());

    const osg::Vec4 grid = cloud->getPositionGrid();
    int exponent = 0;
    EXPECT_EQ(std::frexp(grid.w(), &exponent), 0.5f) << "a power of two: " << grid.w();
    double extent = 0.0;
    for (const osg::Vec3& p : *positions)
        if (std::isfinite(p.x()))
            extent = std::max(extent, double(p.x()) - low.x());
    EXPECT_LE(extent, 65532.0 * grid.w());
    EXPECT_GT(extent, 65532.0 * grid.w() / 2.0);

    const osg::ref_ptr<osg::Vec3Array> drawn = cloud->computeDrawnPositions();
    ASSERT_EQ(drawn->size(), positions->size());
    double largestError = 0.0;
    for (std::size_t i = 0; i + 1 < positions->size(); ++i)
        for (int axis = 0; axis < 3; ++axis)
        {
            const double error = std::abs(double((*drawn)[i][axis]) - double((*positions)[i][axis]));
            largestError = std::max(largestError, error);
            const double steps = (double((*drawn)[i][axis]) - grid[axis]) / grid.w();
            EXPECT_EQ(steps, std::round(steps)) << i; // on the grid
        }
    EXPECT_LE(largestError, grid.w() / 2.0);
    EXPECT_GT(largestError, grid.w() / 4.0) << "the positions were quantised";
    EXPECT_TRUE(std::isnan(drawn->back().x())) << "a skipped glyph stays skipped";
    EXPECT_EQ(cloud->getNumSkippedGlyphs(), 1u);

    // The box and the picked surfaces are the drawn glyphs'.
    EXPECT_NEAR(cloud->getLocalBoundingBox().xMin(), 1000.0f - 0.01f, grid.w());
    osg::BoundingBox drawnBox;
    for (std::size_t i = 0; i + 1 < drawn->size(); ++i)
        drawnBox.expandBy(cloud->computeGlyphBox(unsigned(i)));
    EXPECT_EQ(drawnBox.xMax(), cloud->getLocalBoundingBox().xMax());

    // Grid points compress to themselves, through a cloud or through the 16-bit values.
    osg::ref_ptr<GlyphCloud> again = new GlyphCloud;
    again->setPositions(drawn.get());
    again->setCompressedPositions(true);
    const osg::ref_ptr<osg::Vec3Array> drawnAgain = again->computeDrawnPositions();
    for (std::size_t i = 0; i + 1 < drawn->size(); ++i)
        ASSERT_EQ((*drawnAgain)[i], (*drawn)[i]) << i;
    const auto* quantised = dynamic_cast<const osg::Vec3sArray*>(cloud->getGlyphArrays().positions);
    ASSERT_NE(quantised, nullptr);
    osg::ref_ptr<GlyphCloud> fromIntegers = new GlyphCloud;
    fromIntegers->setCompressedPositions(*quantised, grid);
    EXPECT_TRUE(fromIntegers->getCompressedPositions());
    for (std::size_t i = 0; i + 1 < drawn->size(); ++i)
        ASSERT_EQ((*fromIntegers->getPositions())[i], (*drawn)[i]) << i;

    // Off again: the caller's floats reach the GPU.
    cloud->setCompressedPositions(false);
    EXPECT_EQ(cloud->getGlyphArrays().positions, positions.get());
    EXPECT_EQ((*cloud->computeDrawnPositions())[7], (*positions)[7]);
}

TEST_F(GlyphCloudData, RadiiKeepTheirPrecisionAtAnyScale)
{
    // Radii are packed as half floats relative to the largest one.
    for (float scale : {1e-6f, 1.0f, 1e6f})
    {
        osg::ref_ptr<GlyphCloud> cloud = new GlyphCloud;
        cloud->setPositions(makeArray<osg::Vec3Array>({osg::Vec3(), osg::Vec3(10.0f * scale, 0.0f, 0.0f)}));
        cloud->setRadii(makeArray<osg::FloatArray>({0.3f * scale, 1.7f * scale}));
        const osg::BoundingBox box = cloud->getBoundingBox();
        EXPECT_NEAR(box.xMin(), -0.3f * scale, 0.3f * scale * 1e-3f);
        EXPECT_NEAR(box.xMax(), 11.7f * scale, 1.7f * scale * 1e-3f);
    }
}

TEST_F(GlyphCloudData, NarrowColourRangesKeepTheirResolution)
{
    // One outlier stretches the data's range: over it, 16-bit steps (0.015) would be wider than
    // the colour range. Scalars are quantised over the colour range instead, and re-packed
    // when it changes.
    osg::ref_ptr<GlyphCloud> cloud = createScalarRow({0.5f, 0.5004f, 0.5008f, 1000.0f});
    cloud->setScalarRange(0.5f, 0.5008f);
    const ColorMap* viridis = ColorMap::getBuiltin("viridis");
    osg::ref_ptr<osg::Node> scene = group({cloud.get()});
    for (bool compressed : {true, false})
    {
        cloud->setCompressedAttributes(compressed);
        const std::vector<osg::Vec4ub> colours = centreColours(renderer.render(scene.get()), *cloud);
        for (int i = 0; i < 3; ++i)
            EXPECT_EQ(labelOfColor(colours[i], {toBytes(viridis->getColor(0.5f * i))}, 2), 0)
                << "glyph " << i << (compressed ? ", compressed" : ", uncompressed");
    }
    cloud->setCompressedAttributes(true);
    cloud->resetScalarRange();
    const std::vector<osg::Vec4ub> colours = centreColours(renderer.render(scene.get()), *cloud);
    for (int i = 0; i < 3; ++i)
        EXPECT_EQ(labelOfColor(colours[i], {toBytes(viridis->getColor(0.0f))}, 2), 0) << "glyph " << i;
}

TEST_F(GlyphCloudData, UncompressedRadiiAreExact)
{
    // 0.7001 of the largest radius is 0.7002 as a half float: 1e-4 off, a hundred 24-bit depth
    // steps at the sphere's front. As floats the depth is exact.
    const std::vector<SphereSpec> spheres = {
        {osg::Vec3(-2.0f, 0.0f, 0.0f), 1.0f, osg::Vec4ub(255, 0, 0, 255)},
        {osg::Vec3(1.5f, 0.0f, 0.0f), 0.7001f, osg::Vec4ub(0, 255, 0, 255)}};
    AnalyticScene truth;
    addSpheres(truth, spheres);
    osg::ref_ptr<GlyphCloud> cloud = createSphereCloud(spheres);
    const std::vector<osg::Vec4ub> palette = {spheres[0].color, spheres[1].color};
    const double exactDepth = 2.5e-7; // 4 steps of a 24-bit depth buffer

    const Agreement compressed =
        compareWithTruth(renderer.render(group({cloud.get()}).get()), truth, palette, exactDepth);
    EXPECT_GT(compressed.wrongDepth, 100) << "half-float radii are rounded";

    cloud->setCompressedAttributes(false);
    cloud->setCulling(osgGlyphs::GlyphCulling::Off);
    EXPECT_EQ(cloud->getGPUBytesPerGlyph(), 24.0) << "position + RGBA8 + radius and scalar as floats";
    const Agreement exact =
        compareWithTruth(renderer.render(group({cloud.get()}).get()), truth, palette, exactDepth);
    EXPECT_GT(exact.covered, 1000);
    EXPECT_EQ(exact.wrongLabel, 0);
    EXPECT_EQ(exact.wrongDepth, 0) << "worst depth error " << exact.worstDepthError;
    EXPECT_NEAR(cloud->getBoundingBox().xMax(), 1.5f + 0.7001f, 1e-6f);
}

TEST_F(GlyphCloudData, GlyphsReachingIntoTheViewAreNotCulled)
{
    // The centre lies outside the view frustum; only the radius brings the sphere into view.
    const std::vector<SphereSpec> spheres = {
        {osg::Vec3(5.2f, 0.0f, 0.0f), 1.5f, osg::Vec4ub(255, 0, 0, 255)}};
    AnalyticScene truth;
    addSpheres(truth, spheres);
    const Frame frame = renderer.render(group({createSphereCloud(spheres).get()}).get());
    EXPECT_GT(frame.project(spheres[0].center).x(), frame.width()) << "the centre must be off screen";
    EXPECT_TRUE(coverageMatches(
        frame, [&](int x, int y) { return truth.castPixel(frame, x, y).hit(); }, 4, "cull_edge"));
    int covered = 0;
    for (int y = 0; y < frame.height(); ++y)
        for (int x = 0; x < frame.width(); ++x)
            covered += frame.isCovered(x, y) ? 1 : 0;
    EXPECT_GT(covered, 200);
}

TEST_F(GlyphCloudData, AutomaticNearFarKeepsWholeSpheres)
{
    // OSG computes near and far from the bounding volumes: they must include the radii.
    renderer.getViewer()->getCamera()->setComputeNearFarMode(
        osg::CullSettings::COMPUTE_NEAR_FAR_USING_BOUNDING_VOLUMES);
    // Radii whose ratio a half float holds exactly, so that the depths are exact too.
    const std::vector<SphereSpec> spheres = {
        {osg::Vec3(0.0f, -3.0f, 0.0f), 1.875f, osg::Vec4ub(255, 0, 0, 255)},
        {osg::Vec3(0.5f, 6.0f, 0.5f), 2.5f, osg::Vec4ub(0, 255, 0, 255)}};
    AnalyticScene truth;
    addSpheres(truth, spheres);
    const Frame frame = renderer.render(group({createSphereCloud(spheres).get()}).get());
    int wrong = 0, checked = 0;
    for (int y = 0; y < frame.height(); ++y)
    {
        for (int x = 0; x < frame.width(); ++x)
        {
            const int label = truth.certainLabel(frame, x, y);
            if (label < 0)
                continue;
            ++checked;
            const double expected = frame.windowDepth(truth.castPixel(frame, x, y).point);
            const bool bad = !frame.isCovered(x, y) || std::fabs(frame.depthAt(x, y) - expected) > 1e-5;
            wrong += bad ? 1 : 0;
        }
    }
    EXPECT_GT(checked, 5000);
    EXPECT_EQ(wrong, 0);
}

TEST_F(GlyphCloudData, InvalidGlyphsAreSkippedWithAWarning)
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    osg::ref_ptr<osg::Vec3Array> positions = makeArray<osg::Vec3Array>(
        {osg::Vec3(-2.0f, 0.0f, 0.0f), osg::Vec3(nan, 0.0f, 0.0f), osg::Vec3(0.0f, inf, 0.0f),
         osg::Vec3(2.0f, 0.0f, 0.0f), osg::Vec3(0.0f, 0.0f, 2.0f), osg::Vec3(0.0f, 0.0f, -2.0f),
         osg::Vec3(1.0f, 1.0f, 1.0f)});
    osg::ref_ptr<osg::FloatArray> radii =
        makeArray<osg::FloatArray>({0.5f, 0.5f, 0.5f, 0.0f, -1.0f, 0.5f, nan});
    osg::ref_ptr<osg::FloatArray> scalars =
        makeArray<osg::FloatArray>({1.0f, 2.0f, 3.0f, 4.0f, 5.0f, inf}); // one short

    osg::ref_ptr<NotifyCapture> capture = new NotifyCapture;
    osg::ref_ptr<GlyphCloud> cloud = new GlyphCloud;
    cloud->setName("bad");
    cloud->setPositions(positions.get());
    cloud->setRadii(radii.get());
    cloud->setScalars(scalars.get());
    const std::string warnings = capture->stop();

    EXPECT_NE(warnings.find("the scalar array has 6 values for 7 positions"), std::string::npos) << warnings;
    EXPECT_NE(warnings.find("2 of 6 glyphs have a non-finite position"), std::string::npos) << warnings;
    EXPECT_NE(warnings.find("2 of 6 glyphs have a radius that is not finite and > 0"), std::string::npos)
        << warnings;
    EXPECT_NE(warnings.find("1 of 6 glyphs have a non-finite scalar"), std::string::npos) << warnings;
    EXPECT_EQ(cloud->getNumGlyphs(), 6u);
    EXPECT_EQ(cloud->getNumSkippedGlyphs(), 5u);

    // A new colour range or encoding re-packs the same data: nothing new to warn about.
    capture = new NotifyCapture;
    cloud->setScalarRange(2.0f, 3.0f);
    cloud->setCompressedAttributes(false);
    EXPECT_EQ(capture->stop(), "");
    EXPECT_EQ(cloud->getNumSkippedGlyphs(), 5u);

    // Only the valid glyph at (-2, 0, 0) is drawn, and the bounds ignore the rest.
    const osg::BoundingBox box = cloud->getBoundingBox();
    EXPECT_FLOAT_EQ(box.xMin(), -2.5f);
    EXPECT_FLOAT_EQ(box.xMax(), -1.5f);
    AnalyticScene truth;
    truth.addSphere(osg::Vec3d(-2.0, 0.0, 0.0), 0.5);
    cloud->setLit(false);
    const Frame frame = renderer.render(group({cloud.get()}).get());
    EXPECT_TRUE(coverageMatches(
        frame, [&](int x, int y) { return truth.castPixel(frame, x, y).hit(); }, 4, "invalid_glyphs"));
}

TEST_F(GlyphCloudData, AShaderFileOnTheDataPathOverridesTheEmbeddedCopy)
{
    const std::string directory = writeShaderOverride(
        "shader-override", "lighting.glsl",
        "uniform vec3 osgGlyphs_material;\n"
        "vec3 shade(vec3 base, vec3 position, vec3 normal, vec3 toEye, float ambientLight) { "
        "return vec3(1.0, 0.0, 1.0); }\n");
    osg::ref_ptr<GlyphCloud> cloud = createSphereCloud({{osg::Vec3(), 1.0f, osg::Vec4ub(0, 255, 0, 255)}});
    osg::ref_ptr<osg::Node> scene = group({cloud.get()});
    const osg::Vec4ub magenta(255, 0, 255, 255);

    const Frame overridden = renderWithShaderFolder(renderer, scene.get(), directory);
    const Frame restored = renderer.render(scene.get());

    EXPECT_TRUE(colorNear(overridden, 80, 60, magenta, 0));
    EXPECT_TRUE(colorNear(restored, 80, 60, osg::Vec4ub(0, 255, 0, 255), 0));
}

TEST_F(GlyphCloudData, ShaderFilesInTheWorkingFolderAreIgnored)
{
    // A stray lighting.glsl, by its bare name and under osgGlyphs/, where the program runs.
    const std::string directory = outputPath("stray-shaders");
    osgDB::makeDirectory(directory + "/osgGlyphs");
    const std::string magenta =
        "uniform vec3 osgGlyphs_material;\n"
        "vec3 shade(vec3 base, vec3 position, vec3 normal, vec3 toEye) { return vec3(1.0, 0.0, 1.0); }\n";
    std::ofstream(directory + "/lighting.glsl") << magenta;
    std::ofstream(directory + "/osgGlyphs/lighting.glsl") << magenta;
    const std::string builtIn = osgGlyphs::readShaderSource("osgGlyphs/lighting.glsl");
    osg::ref_ptr<GlyphCloud> cloud = createSphereCloud({{osg::Vec3(), 1.0f, osg::Vec4ub(0, 255, 0, 255)}});
    osg::ref_ptr<osg::Node> scene = group({cloud.get()});

    const std::filesystem::path workingFolder = std::filesystem::current_path();
    std::filesystem::current_path(directory);
    osgGlyphs::GlyphStateCache::instance()->reloadShaders();
    const std::string read = osgGlyphs::readShaderSource("osgGlyphs/lighting.glsl");
    const Frame frame = renderer.render(scene.get());
    std::filesystem::current_path(workingFolder);
    osgGlyphs::GlyphStateCache::instance()->reloadShaders();

    EXPECT_EQ(read, builtIn);
    EXPECT_TRUE(colorNear(frame, 80, 60, osg::Vec4ub(0, 255, 0, 255), 0));
}

namespace
{

/** Records every message, of every severity, and passes it on to the next handler if any. */
class NotifyRecorder : public osg::NotifyHandler
{
public:
    explicit NotifyRecorder(osg::NotifyHandler* next = nullptr) : _next(next) {}
    void notify(osg::NotifySeverity severity, const char* message) override
    {
        {
            std::lock_guard<std::mutex> lock(_mutex);
            _text += message;
        }
        if (_next.valid())
            _next->notify(severity, message);
    }
    std::string getText() const
    {
        std::lock_guard<std::mutex> lock(_mutex);
        return _text;
    }

private:
    osg::ref_ptr<osg::NotifyHandler> _next;
    mutable std::mutex _mutex;
    std::string _text;
};

/** Renders the scene with the shader files of directory on OSG's data path; returns the program
 * error and what osg::notify printed, through a ProgramErrorFilter in filtered. */
std::string renderWithShadersOf(Renderer& renderer, osg::Node* scene, const std::string& directory,
                                std::string& printed, std::string& filtered)
{
    osg::ref_ptr<NotifyRecorder> kept = new NotifyRecorder;
    osg::ref_ptr<NotifyRecorder> all = new NotifyRecorder(new osgGlyphs::ProgramErrorFilter(kept.get()));
    osg::ref_ptr<osg::NotifyHandler> previous = osg::getNotifyHandler();
    osg::setNotifyHandler(all.get());
    osgDB::getDataFilePathList().push_front(directory);
    osgGlyphs::GlyphStateCache::instance()->reloadShaders();
    renderer.render(scene);
    const std::string error = osgGlyphs::GlyphStateCache::instance()->getProgramError();
    osgDB::getDataFilePathList().pop_front();
    osgGlyphs::GlyphStateCache::instance()->reloadShaders();
    osg::setNotifyHandler(previous.get());
    printed = all->getText();
    filtered = kept->getText();
    return error;
}

}

TEST_F(GlyphCloudData, AShaderThatDoesNotCompileIsOneLineNamingItsFileAndLine)
{
    // The sphere's code, which both the geometry and the fragment stage include, with no GLSL on line 3.
    const std::string directory =
        writeShaderOverride("broken-shader", "sphere.glsl", "// broken\n\nthis is not GLSL;\n");
    osg::ref_ptr<GlyphCloud> cloud = createSphereCloud({{osg::Vec3(), 1.0f, osg::Vec4ub(0, 255, 0, 255)}});
    cloud->setLit(false);
    osg::ref_ptr<osg::Node> scene = group({cloud.get()});

    std::string printed, filtered;
    const std::string error = renderWithShadersOf(renderer, scene.get(), directory, printed, filtered);
    const std::string expected = "glyph program 'osgGlyphs geometry-shader' does not compile: " + directory +
                                 "/osgGlyphs/sphere.glsl:3: error: ";
    EXPECT_EQ(error.compare(0, expected.size(), expected), 0) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    EXPECT_NE(printed.find("osgGlyphs: " + error + "\n"), std::string::npos) << printed;
    EXPECT_EQ(filtered.find("osgGlyphs"), std::string::npos) << filtered;

    // Reloaded without the broken file, the program works and the error is gone.
    EXPECT_EQ(osgGlyphs::GlyphStateCache::instance()->getProgramError(), "");
    const Frame frame = renderer.render(scene.get());
    EXPECT_EQ(osgGlyphs::GlyphStateCache::instance()->getProgramError(), "");
    EXPECT_TRUE(colorNear(frame, 80, 60, osg::Vec4ub(0, 255, 0, 255), 0));
}

TEST_F(GlyphCloudData, AProgramThatDoesNotLinkIsOneLine)
{
    // Lighting declared and never defined: every stage compiles, the program cannot link.
    const std::string directory = writeShaderOverride(
        "unlinkable-shader", "lighting.glsl",
        "uniform vec3 osgGlyphs_material;\nvec3 shade(vec3 base, vec3 position, vec3 normal, vec3 toEye, "
        "float ambientLight);\n");
    osg::ref_ptr<GlyphCloud> cloud = createSphereCloud({{osg::Vec3(), 1.0f, osg::Vec4ub(0, 255, 0, 255)}});
    osg::ref_ptr<osg::Node> scene = group({cloud.get()});

    std::string printed, filtered;
    const std::string error = renderWithShadersOf(renderer, scene.get(), directory, printed, filtered);
    const std::string expected = "glyph program 'osgGlyphs geometry-shader' does not link: ";
    EXPECT_EQ(error.compare(0, expected.size(), expected), 0) << error;
    EXPECT_NE(error.find("error"), std::string::npos) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    EXPECT_EQ(filtered.find("osgGlyphs"), std::string::npos) << filtered;
}

TEST(ProgramErrorFilter, DropsTheReportsOfGlyphProgramsThatFailAndNothingElse)
{
    osg::ref_ptr<NotifyRecorder> kept = new NotifyRecorder;
    osg::ref_ptr<osgGlyphs::ProgramErrorFilter> filter = new osgGlyphs::ProgramErrorFilter(kept.get());
    filter->notify(osg::WARN, "FRAGMENT glCompileShader \"osgGlyphs/impostor.frag\" FAILED\n");
    filter->notify(osg::WARN, "FRAGMENT Shader \"osgGlyphs/impostor.frag\" infolog:\n0:3(1): error: x\n");
    filter->notify(osg::NOTICE, "glLinkProgram 0x5\"osgGlyphs geometry-shader\" FAILED\n");
    filter->notify(osg::NOTICE, "Program \"osgGlyphs paper-quad\" infolog:\nerror: y\n");
    filter->notify(osg::WARN, "osgGlyphs: glyph program 'osgGlyphs instanced' does not link: error: y\n");
    const std::string others[] = {"VERTEX glCompileShader \"mine.vert\" FAILED\n",
                                  "Program \"osgGlyphs geometry-shader\" link succeeded, infolog:\nwarning\n",
                                  "osgGlyphs: 2 of 6 glyphs have a non-finite position\n"};
    filter->notify(osg::WARN, others[0].c_str());
    filter->notify(osg::INFO, others[1].c_str());
    filter->notify(osg::WARN, others[2].c_str());
    EXPECT_EQ(kept->getText(), others[0] + others[1] + others[2]);
}

TEST_F(GlyphCloudData, LitSceneMatchesBaseline)
{
    renderer.setLookAt(osg::Vec3d(2.0, -6.0, 4.5), osg::Vec3d(), osg::Vec3d(0.0, 0.0, 1.0));
    osg::ref_ptr<osg::Vec3Array> positions = new osg::Vec3Array;
    osg::ref_ptr<osg::FloatArray> scalars = new osg::FloatArray;
    osg::ref_ptr<osg::FloatArray> radii = new osg::FloatArray;
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j)
        {
            positions->push_back(osg::Vec3(-2.0f + i, -2.0f + j, 0.3f * std::sin(float(i * j))));
            scalars->push_back(float(i + j));
            radii->push_back(0.3f + 0.04f * float((i * 7 + j * 3) % 5));
        }
    osg::ref_ptr<GlyphCloud> cloud = new GlyphCloud;
    cloud->setPositions(positions.get());
    cloud->setRadii(radii.get());
    cloud->setScalars(scalars.get());
    osg::ref_ptr<osg::ShapeDrawable> slab =
        new osg::ShapeDrawable(new osg::Box(osg::Vec3(), 5.0f, 5.0f, 0.2f));
    const Frame frame = renderer.render(group({cloud.get(), slab.get()}).get());
    Tolerance tolerance;
    tolerance.colorChannel = 3;
    tolerance.colorPixelBudget = 8;
    tolerance.depth = 1e-6f;
    tolerance.depthPixelBudget = 8;
    EXPECT_TRUE(matchesBaseline(frame, "glyphs_lit_scene", tolerance));
}

TEST_F(GlyphCloudData, TheOptimizerLeavesCloudsAndTheirTransformsAlone)
{
    // osgconv's default optimisation merged the clouds of a sequence into one broken cloud, and
    // would bake a static transform into positions but not into radii.
    auto createCloud = [](const osg::Vec3& position)
    {
        osg::ref_ptr<GlyphCloud> cloud = new GlyphCloud;
        cloud->setPositions(new osg::Vec3Array(1, &position));
        cloud->setRadius(0.25f);
        return cloud;
    };
    osg::ref_ptr<osg::Sequence> frames = new osg::Sequence;
    for (float x : {-1.0f, 0.0f, 1.0f})
        frames->addChild(createCloud(osg::Vec3(x, 0.0f, 0.0f)).get());
    osg::ref_ptr<GlyphCloud> scaledCloud = createCloud(osg::Vec3(0.0f, 0.0f, 1.0f));
    osg::ref_ptr<osg::MatrixTransform> scaled = new osg::MatrixTransform(osg::Matrix::scale(2.0, 2.0, 2.0));
    scaled->setDataVariance(osg::Object::STATIC);
    scaled->addChild(scaledCloud.get());
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(frames.get());
    root->addChild(scaled.get());

    osgUtil::Optimizer optimizer;
    optimizer.optimize(root.get(), osgUtil::Optimizer::ALL_OPTIMIZATIONS);

    ASSERT_EQ(frames->getNumChildren(), 3u);
    for (unsigned int i = 0; i < 3; ++i)
    {
        GlyphCloud* cloud = dynamic_cast<GlyphCloud*>(frames->getChild(i));
        ASSERT_NE(cloud, nullptr);
        EXPECT_EQ(cloud->getPositions()->size(), 1u);
    }
    EXPECT_EQ((*scaledCloud->getPositions())[0], osg::Vec3(0.0f, 0.0f, 1.0f)); // not transformed
    ASSERT_EQ(scaledCloud->getNumParents(), 1u);
    EXPECT_NE(dynamic_cast<osg::MatrixTransform*>(scaledCloud->getParent(0)), nullptr);
}

TEST_F(GlyphCloudData, DisplayListsAreOfferedWhereTheTechniqueDrawsWithoutInstancing)
{
    osg::ref_ptr<GlyphCloud> cloud = createSphereCloud({{osg::Vec3(), 1.0f, osg::Vec4ub(255, 0, 0, 255)}});
    EXPECT_TRUE(cloud->getSupportsDisplayList());
    EXPECT_FALSE(cloud->getUseDisplayList()); // vertex buffer objects by default
    cloud->setTechnique(new osgGlyphs::InstancedTechnique);
    EXPECT_FALSE(cloud->getSupportsDisplayList());
    osg::ref_ptr<GlyphCloud> copy = new GlyphCloud(*cloud);
    EXPECT_FALSE(copy->getSupportsDisplayList());
    cloud->setTechnique(nullptr);
    EXPECT_TRUE(cloud->getSupportsDisplayList());
}
