// GlyphCloud, ScreenEffects and DepthPeeling through OSG's native formats: every attribute
// survives .osgt, .osgb and .osgx bit for bit, and the read scene renders the same pixels.

#include "GlyphTestScenes.h"
#include "SameBits.h"
#include "SerializerFixtures.h"

#include <osgGlyphs/DepthPeeling>
#include <osgGlyphs/GlyphCloud>
#include <osgGlyphs/ScreenEffects>
#include <osgGlyphsPaper/Techniques>

#include <osgDB/ReadFile>
#include <osgDB/WriteFile>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>

using namespace osgGlyphsTest;
using osgGlyphs::GlyphCloud;

namespace
{

osg::ref_ptr<GlyphCloud> createFullCloud()
{
    osg::ref_ptr<GlyphCloud> cloud = new GlyphCloud;
    cloud->setName("everything");
    cloud->setShape(osgGlyphs::GlyphShape::Arrow);
    cloud->setPositions(makeArray<osg::Vec3Array>(
        {osg::Vec3(-1.5f, 0.1f, 0.3f), osg::Vec3(0.2f, -0.4f, 0.0f), osg::Vec3(1.4f, 0.3f, -0.5f)}));
    cloud->setVectors(makeArray<osg::Vec3Array>(
        {osg::Vec3(0.3f, 0.2f, 1.1f), osg::Vec3(-1.0f, 0.1f, 0.4f), osg::Vec3(0.5f, 0.5f, -0.9f)}));
    cloud->setRadii(makeArray<osg::FloatArray>({0.11f, 0.17f, 0.123456f}));
    cloud->setScalars(makeArray<osg::FloatArray>({-2.5f, 0.1f, 7.25f}));
    cloud->setColorMap(new osgGlyphs::ColorMap(
        "custom", {osg::Vec4(0.1f, 0.2f, 0.3f, 1.0f), osg::Vec4(0.9f, 0.5f, 0.1f, 1.0f)}));
    cloud->setScalarRange(-1.0f, 5.0f);
    cloud->setLit(false);
    cloud->setCompressedAttributes(false);
    cloud->setMaterial(0.31f, 0.27f, 17.0f);
    cloud->setOpacity(0.35f);
    cloud->setLengthScale(0.75f);
    cloud->setUniformLength(true);
    cloud->setAnchor(osgGlyphs::GlyphAnchor::Tail);
    cloud->setArrowHead(0.4f, 1.7f);
    cloud->setOrigin(osg::Vec3d(0.25, -0.125, 0.5));
    cloud->setCulling(osgGlyphs::GlyphCulling::Frustum);
    cloud->setCullingChunkSize(64);
    cloud->setOcclusion(makeArray<osg::Vec4ubArray>(
        {osg::Vec4ub(1, 2, 3, 4), osg::Vec4ub(128, 127, 255, 0), osg::Vec4ub(9, 8, 7, 200)}));
    osg::ref_ptr<osgGlyphsPaper::PolygonsTechnique> polygons = new osgGlyphsPaper::PolygonsTechnique;
    polygons->setResolution(12, 6);
    cloud->setTechnique(polygons.get());
    return cloud;
}

void expectSameCloud(const GlyphCloud& a, const GlyphCloud& b)
{
    EXPECT_EQ(a.getName(), b.getName());
    EXPECT_EQ(a.getShape(), b.getShape());
    ASSERT_NE(b.getTechnique(), nullptr);
    EXPECT_STREQ(a.getTechnique()->className(), b.getTechnique()->className());
    EXPECT_TRUE(sameBits(a.getPositions(), b.getPositions()));
    EXPECT_TRUE(sameBits(a.getVectors(), b.getVectors()));
    EXPECT_TRUE(sameBits(a.getRadii(), b.getRadii()));
    EXPECT_TRUE(sameBits(a.getScalars(), b.getScalars()));
    EXPECT_TRUE(sameBits(a.getColors(), b.getColors()));
    EXPECT_TRUE(sameBits(a.getOcclusion(), b.getOcclusion()));
    EXPECT_EQ(a.getColorMode(), b.getColorMode());
    ASSERT_NE(b.getColorMap(), nullptr);
    EXPECT_EQ(a.getColorMap()->getName(), b.getColorMap()->getName());
    EXPECT_EQ(a.getColorMap()->getColors(), b.getColorMap()->getColors());
    EXPECT_EQ(a.getScalarRangeIsAutomatic(), b.getScalarRangeIsAutomatic());
    EXPECT_EQ(a.getScalarRangeMin(), b.getScalarRangeMin());
    EXPECT_EQ(a.getScalarRangeMax(), b.getScalarRangeMax());
    EXPECT_EQ(a.getLit(), b.getLit());
    EXPECT_EQ(a.getCompressedAttributes(), b.getCompressedAttributes());
    EXPECT_EQ(a.getAmbient(), b.getAmbient());
    EXPECT_EQ(a.getSpecular(), b.getSpecular());
    EXPECT_EQ(a.getShininess(), b.getShininess());
    EXPECT_EQ(a.getOpacity(), b.getOpacity());
    EXPECT_EQ(a.getLengthScale(), b.getLengthScale());
    EXPECT_EQ(a.getUniformLength(), b.getUniformLength());
    EXPECT_EQ(a.getAnchor(), b.getAnchor());
    EXPECT_EQ(a.getArrowHeadLengthRatio(), b.getArrowHeadLengthRatio());
    EXPECT_EQ(a.getArrowHeadRadiusRatio(), b.getArrowHeadRadiusRatio());
    const auto* polygonsA = dynamic_cast<const osgGlyphsPaper::PolygonsTechnique*>(a.getTechnique());
    const auto* polygonsB = dynamic_cast<const osgGlyphsPaper::PolygonsTechnique*>(b.getTechnique());
    ASSERT_EQ(polygonsA != nullptr, polygonsB != nullptr);
    if (polygonsA)
    {
        EXPECT_EQ(polygonsA->getSlices(), polygonsB->getSlices());
        EXPECT_EQ(polygonsA->getStacks(), polygonsB->getStacks());
    }
    EXPECT_EQ(a.getColor(), b.getColor());
    EXPECT_EQ(a.getRadius(), b.getRadius());
    EXPECT_EQ(a.getOrigin(), b.getOrigin());
    EXPECT_EQ(a.getCulling(), b.getCulling());
    EXPECT_EQ(a.getCullingChunkSize(), b.getCullingChunkSize());
}

class NativeFormats : public ::testing::TestWithParam<std::string>
{
};

}

TEST_P(NativeFormats, RoundTripIsBitExact)
{
    osg::ref_ptr<GlyphCloud> original = createFullCloud();
    osg::ref_ptr<osg::Geode> scene = group({original.get()});
    const std::string path = outputPath("roundtrip." + GetParam());
    ASSERT_TRUE(osgDB::writeNodeFile(*scene, path)) << path;

    osg::ref_ptr<osg::Node> read = osgDB::readRefNodeFile(path);
    ASSERT_TRUE(read.valid()) << path;
    osg::Geode* geode = read->asGeode();
    ASSERT_NE(geode, nullptr);
    ASSERT_EQ(geode->getNumDrawables(), 1u);
    const GlyphCloud* copy = dynamic_cast<const GlyphCloud*>(geode->getDrawable(0));
    ASSERT_NE(copy, nullptr) << "read back as " << geode->getDrawable(0)->className();
    expectSameCloud(*original, *copy);

    Renderer renderer(160, 120);
    const Frame expected = renderer.render(scene.get());
    const Frame actual = renderer.render(read.get());
    int differing = 0;
    for (int y = 0; y < expected.height(); ++y)
        for (int x = 0; x < expected.width(); ++x)
            differing += expected.colorAt(x, y) != actual.colorAt(x, y) ? 1 : 0;
    EXPECT_EQ(differing, 0);
    int covered = 0;
    for (int y = 0; y < actual.height(); ++y)
        for (int x = 0; x < actual.width(); ++x)
            covered += actual.isCovered(x, y) ? 1 : 0;
    EXPECT_GT(covered, 100);
}

TEST(NativeFormatDefaults, DefaultCloudRoundTrips)
{
    osg::ref_ptr<GlyphCloud> original = new GlyphCloud;
    original->setPositions(makeArray<osg::Vec3Array>({osg::Vec3(1.0f, 2.0f, 3.0f)}));
    const std::string path = outputPath("roundtrip_default.osgt");
    ASSERT_TRUE(osgDB::writeObjectFile(*original, path));
    osg::ref_ptr<GlyphCloud> copy = osgDB::readRefFile<GlyphCloud>(path);
    ASSERT_TRUE(copy.valid());
    expectSameCloud(*original, *copy);
    EXPECT_TRUE(copy->getScalarRangeIsAutomatic());
}

namespace
{

/** Spheres of a cloud at an opacity, drawn by the default technique. */
osg::ref_ptr<osg::Geode> sphereCloud(float x, float opacity)
{
    osg::ref_ptr<GlyphCloud> cloud = new GlyphCloud;
    cloud->setPositions(makeArray<osg::Vec3Array>(
        {osg::Vec3(x - 0.5f, 0.0f, 0.0f), osg::Vec3(x, 0.2f, -0.3f), osg::Vec3(x + 0.4f, -0.3f, 0.4f)}));
    cloud->setRadii(makeArray<osg::FloatArray>({0.45f, 0.5f, 0.35f}));
    cloud->setScalars(makeArray<osg::FloatArray>({0.0f, 0.5f, 1.0f}));
    cloud->setOpacity(opacity);
    return group({cloud.get()});
}

}

TEST_P(NativeFormats, ScreenEffectsAndDepthPeelingRoundTrip)
{
    // Outlined, occluded opaque spheres on the left; transparent ones peeled on the right.
    osg::ref_ptr<osgGlyphs::ScreenEffects> effects = osgGlyphsFixtures::createScreenEffects();
    effects->addChild(sphereCloud(-0.7f, 1.0f).get());
    osg::ref_ptr<osgGlyphs::DepthPeeling> peeling = osgGlyphsFixtures::createDepthPeeling();
    peeling->addChild(sphereCloud(0.7f, 0.5f).get());
    osg::ref_ptr<osg::Group> scene = new osg::Group;
    scene->addChild(effects.get());
    scene->addChild(peeling.get());
    const std::string path = outputPath("effects." + GetParam());
    ASSERT_TRUE(osgDB::writeNodeFile(*scene, path)) << path;

    osg::ref_ptr<osg::Node> read = osgDB::readRefNodeFile(path);
    ASSERT_TRUE(read.valid() && read->asGroup() && read->asGroup()->getNumChildren() == 2u) << path;
    const auto* readEffects = dynamic_cast<const osgGlyphs::ScreenEffects*>(read->asGroup()->getChild(0));
    const auto* readPeeling = dynamic_cast<const osgGlyphs::DepthPeeling*>(read->asGroup()->getChild(1));
    ASSERT_NE(readEffects, nullptr);
    ASSERT_NE(readPeeling, nullptr);
    EXPECT_EQ(readEffects->getAmbientOcclusion(), true);
    EXPECT_EQ(readEffects->getOcclusionRadius(), 0.3f);
    EXPECT_EQ(readEffects->getOcclusionStrength(), 0.7f);
    EXPECT_EQ(readEffects->getOcclusionSamples(), 24u);
    EXPECT_EQ(readEffects->getOutlines(), true);
    EXPECT_EQ(readEffects->getOutlineWidth(), 2.5f);
    EXPECT_EQ(readEffects->getOutlineColor(), osg::Vec4(0.2f, 0.0f, 0.1f, 0.9f));
    EXPECT_EQ(readEffects->getNumChildren(), 1u);
    EXPECT_EQ(readPeeling->getNumLayers(), 3u);
    EXPECT_EQ(readPeeling->getMethod(), osgGlyphs::DepthPeeling::PEEL_PASSES);
    EXPECT_EQ(readPeeling->getEnabled(), true);
    EXPECT_EQ(readPeeling->getNumChildren(), 1u);

    // The same picture, and not the one without the effects and the peeling.
    Renderer renderer(160, 120);
    const Frame expected = renderer.render(scene.get());
    const Frame actual = renderer.render(read.get());
    effects->setOutlines(false);
    effects->setAmbientOcclusion(false);
    peeling->setEnabled(false);
    const Frame plain = renderer.render(scene.get());
    int differing = 0, changed = 0;
    for (int y = 0; y < expected.height(); ++y)
        for (int x = 0; x < expected.width(); ++x)
        {
            differing += expected.colorAt(x, y) != actual.colorAt(x, y) ? 1 : 0;
            changed += expected.colorAt(x, y) != plain.colorAt(x, y) ? 1 : 0;
        }
    EXPECT_EQ(differing, 0);
    EXPECT_GT(changed, 200);
}

namespace
{

/** Writes the cloud into path and reads it back; bytes: the file's size. Null when either fails. */
osg::ref_ptr<GlyphCloud> writeAndReadBack(const GlyphCloud& cloud, const std::string& path,
                                          std::uintmax_t& bytes)
{
    if (!osgDB::writeObjectFile(cloud, path))
        return nullptr;
    bytes = std::filesystem::file_size(path);
    return osgDB::readRefFile<GlyphCloud>(path);
}

}

// Compressed positions are written as their 16-bit integers and grid (6 bytes a glyph instead of 12)
// and read back as the grid points the GPU drew, which draw the same picture.
TEST_P(NativeFormats, CompressedPositionsRoundTripAsTheirGridPoints)
{
    osg::ref_ptr<GlyphCloud> original = new GlyphCloud;
    osg::ref_ptr<osg::Vec3Array> positions = new osg::Vec3Array;
    for (int i = 0; i < 2000; ++i)
        positions->push_back(osg::Vec3(std::sin(0.37f * i), std::cos(0.61f * i), 0.001f * i - 1.0f) * 1.3f +
                             osg::Vec3(40.0f, -7.0f, 3.0f));
    original->setPositions(positions.get());
    original->setOrigin(osg::Vec3d(-40.0, 7.0, -3.0));
    original->setRadius(0.05f);
    std::map<bool, std::uintmax_t> bytes;
    for (bool compressed : {false, true})
    {
        original->setCompressedPositions(compressed);
        const std::string path =
            outputPath(std::string("positions_") + (compressed ? "16" : "32") + "." + GetParam());
        osg::ref_ptr<GlyphCloud> copy = writeAndReadBack(*original, path, bytes[compressed]);
        ASSERT_TRUE(copy.valid()) << path;
        EXPECT_EQ(copy->getCompressedPositions(), compressed);
        EXPECT_TRUE(sameBits(original->computeDrawnPositions().get(), copy->getPositions())) << path;
        EXPECT_TRUE(sameBits(original->computeDrawnPositions().get(), copy->computeDrawnPositions().get()))
            << path;
        Renderer renderer(160, 120);
        const Frame expected = renderer.render(group({original.get()}).get());
        const Frame actual = renderer.render(group({copy.get()}).get());
        int differing = 0, covered = 0;
        for (int y = 0; y < expected.height(); ++y)
            for (int x = 0; x < expected.width(); ++x)
            {
                differing += expected.colorAt(x, y) != actual.colorAt(x, y) ||
                                     expected.depthAt(x, y) != actual.depthAt(x, y)
                                 ? 1
                                 : 0;
                covered += actual.isCovered(x, y) ? 1 : 0;
            }
        EXPECT_EQ(differing, 0) << path;
        EXPECT_GT(covered, 1000) << path;
    }
    if (GetParam() == "osgb")
    {
        EXPECT_LE(bytes[true] + 2000 * 6, bytes[false] + 256) << "6 bytes less per glyph, and the grid";
    }
}

// Scalars that are the values of their 16-bit steps (as tiles store them) are written as the steps,
// 2 bytes a glyph instead of 4, and read back bit for bit; others stay floats.
TEST_P(NativeFormats, ScalarsOnTheirStepsRoundTripIn16Bits)
{
    const osg::Vec2 range(-3.0f, 5.0f);
    osg::ref_ptr<osg::FloatArray> scalars = new osg::FloatArray, steps = new osg::FloatArray;
    osg::ref_ptr<osg::Vec3Array> positions = new osg::Vec3Array;
    for (int i = 0; i < 3000; ++i)
    {
        const float s = -3.0f + 8.0f * std::fmod(0.618034f * i, 1.0f);
        scalars->push_back(s);
        steps->push_back(GlyphCloud::dequantiseScalar(GlyphCloud::quantiseScalar(s, range), range));
        positions->push_back(osg::Vec3(float(i % 50), float(i / 50), 0.0f));
    }
    std::map<bool, std::uintmax_t> bytes;
    for (bool onSteps : {false, true})
    {
        osg::ref_ptr<GlyphCloud> original = new GlyphCloud;
        original->setScalarRange(range.x(), range.y());
        original->setScalars(onSteps ? steps.get() : scalars.get());
        original->setPositions(positions.get());
        const std::string path =
            outputPath(std::string("scalars_") + (onSteps ? "16" : "32") + "." + GetParam());
        osg::ref_ptr<GlyphCloud> copy = writeAndReadBack(*original, path, bytes[onSteps]);
        ASSERT_TRUE(copy.valid()) << path;
        EXPECT_TRUE(sameBits(original->getScalars(), copy->getScalars())) << path;
        EXPECT_EQ(copy->getScalarRangeMin(), range.x());
        EXPECT_EQ(copy->getColorMode(), osgGlyphs::GlyphColorMode::Scalar);
    }
    if (GetParam() == "osgb")
    {
        EXPECT_LE(bytes[true] + 3000 * 2, bytes[false] + 64) << "2 bytes less per glyph";
    }
}

INSTANTIATE_TEST_SUITE_P(, NativeFormats, ::testing::Values("osgt", "osgb", "osgx"),
                         [](const ::testing::TestParamInfo<std::string>& param) { return param.param; });
