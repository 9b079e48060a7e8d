// The osgGlyphs wrapper domain and its versions (DomainVersion.h): files written before the domain
// (tests/data/osgdb, see make-fixtures.sh there) read with every property as it was set, files
// written in a version say so and read back, a file of a later version reads as far as this code
// knows it, a tile archive written before still opens, and one written now declares the version.

#include "DomainVersion.h"
#include "GlyphTestScenes.h"
#include "RenderHarness.h"
#include "SameBits.h"
#include "SerializerFixtures.h"

#include <osgGlyphs/ColorMap>
#include <osgGlyphs/DepthPeeling>
#include <osgGlyphs/GlyphCloud>
#include <osgGlyphs/ScreenEffects>
#include <osgGlyphs/Version>
#include <osgGlyphsPaper/Techniques>
#include <osgGlyphsTiles/TileBuilder>
#include <osgGlyphsTiles/TileChecksum>
#include <osgGlyphsTiles/TileRoot>

#include <osg/Geode>
#include <osg/PagedLOD>
#include <osg/Quat>
#include <osgDB/Archive>
#include <osgDB/InputStream>
#include <osgDB/ObjectWrapper>
#include <osgDB/OutputStream>
#include <osgDB/ReadFile>
#include <osgDB/Registry>
#include <osgDB/WriteFile>

#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <string>

using osgGlyphs::GlyphCloud;

namespace
{

std::string fixturePath(const std::string& name)
{
    return std::string(OSGGLYPHS_OSGDB_FIXTURE_DIR) + "/" + name;
}

std::string fileBytes(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/** The custom domains and versions a .osgt or .osgb file declares in its header. */
std::map<std::string, int> declaredDomains(const std::string& path)
{
    std::map<std::string, int> domains;
    std::ifstream in(path, std::ios::binary);
    if (path.substr(path.size() - 4) == "osgt")
    {
        std::string word, name;
        int version = 0;
        while (in >> word && word != "{")
            if (word == "#CustomDomain" && in >> name >> version)
                domains[name] = version;
        return domains;
    }
    // The binary header: two magic words, type, OSG's version, attributes (bit 0: custom domains),
    // then their count and each one's name (length, bytes) and version.
    auto next = [&in]()
    {
        unsigned int word = 0;
        in.read(reinterpret_cast<char*>(&word), sizeof(word));
        return word;
    };
    in.seekg(16);
    if ((next() & 1u) == 0)
        return domains;
    for (unsigned int i = 0, count = next(); i < count && in; ++i)
    {
        std::string name(next(), '\0');
        in.read(&name[0], static_cast<std::streamsize>(name.size()));
        domains[name] = static_cast<int>(next());
    }
    return domains;
}

osg::ref_ptr<osgDB::Options> optionsForVersion(int version)
{
    osg::ref_ptr<osgDB::Options> options = new osgDB::Options;
    options->setPluginStringData("CustomDomains", osgGlyphsWrappers::domainVersionEntry(version));
    return options;
}

void expectSameTechnique(const GlyphCloud& read, const GlyphCloud& built)
{
    ASSERT_NE(read.getTechnique(), nullptr);
    EXPECT_STREQ(read.getTechnique()->className(), built.getTechnique()->className());
    const auto* polygons = dynamic_cast<const osgGlyphsPaper::PolygonsTechnique*>(built.getTechnique());
    if (!polygons)
        return;
    const auto* readPolygons = dynamic_cast<const osgGlyphsPaper::PolygonsTechnique*>(read.getTechnique());
    ASSERT_NE(readPolygons, nullptr);
    EXPECT_EQ(readPolygons->getSlices(), polygons->getSlices());
    EXPECT_EQ(readPolygons->getStacks(), polygons->getStacks());
}

void expectSameArrays(const GlyphCloud& read, const GlyphCloud& built)
{
    // 16-bit positions read back as the grid points the GPU draws.
    EXPECT_EQ(read.getCompressedPositions(), built.getCompressedPositions());
    EXPECT_TRUE(sameBits(read.getPositions(), built.computeDrawnPositions().get()));
    EXPECT_EQ(read.getPositionGrid(), built.getPositionGrid());
    EXPECT_EQ(read.getRadius(), built.getRadius());
    EXPECT_TRUE(sameBits(read.getRadii(), built.getRadii()));
    EXPECT_TRUE(sameBits(read.getVectors(), built.getVectors()));
    EXPECT_TRUE(sameBits(read.getColors(), built.getColors()));
    EXPECT_TRUE(sameBits(read.getScalars(), built.getScalars()));
    EXPECT_TRUE(sameBits(read.getOcclusion(), built.getOcclusion()));
    EXPECT_EQ(read.getColorMode(), built.getColorMode());
}

/** osg::Node's properties, which the cloud's wrapper reads and writes before its own. */
void expectSameNode(const GlyphCloud& read, const GlyphCloud& built)
{
    EXPECT_EQ(read.getNodeMask(), built.getNodeMask());
    EXPECT_EQ(read.getDescriptions(), built.getDescriptions());
    ASSERT_NE(read.getStateSet(), nullptr);
    EXPECT_EQ(read.getStateSet()->getBinNumber(), built.getStateSet()->getBinNumber());
    EXPECT_EQ(read.getStateSet()->getBinName(), built.getStateSet()->getBinName());
}

/** Text files hold doubles in decimal, which osgDB reads through osg::asciiToDouble(): within a
 * few units in the last place (0.75 reads 1 above). */
void expectSameOrigin(const osg::Vec3d& read, const osg::Vec3d& built, bool text)
{
    for (int i = 0; i < 3; ++i)
    {
        const double tolerance = text ? 4.0 * DBL_EPSILON * std::max(1.0, std::abs(built[i])) : 0.0;
        EXPECT_LE(std::abs(read[i] - built[i]), tolerance) << "origin[" << i << "]";
    }
}

void expectSameStyle(const GlyphCloud& read, const GlyphCloud& built)
{
    EXPECT_EQ(read.getShape(), built.getShape());
    EXPECT_EQ(read.getColor(), built.getColor());
    ASSERT_NE(read.getColorMap(), nullptr);
    EXPECT_EQ(read.getColorMap()->getName(), built.getColorMap()->getName());
    EXPECT_EQ(read.getColorMap()->getColors(), built.getColorMap()->getColors());
    EXPECT_FALSE(read.getScalarRangeIsAutomatic());
    EXPECT_EQ(read.getScalarRangeMin(), built.getScalarRangeMin());
    EXPECT_EQ(read.getScalarRangeMax(), built.getScalarRangeMax());
    EXPECT_EQ(read.getLit(), built.getLit());
    EXPECT_EQ(read.getAmbient(), built.getAmbient());
    EXPECT_EQ(read.getSpecular(), built.getSpecular());
    EXPECT_EQ(read.getShininess(), built.getShininess());
    EXPECT_EQ(read.getLengthScale(), built.getLengthScale());
    EXPECT_EQ(read.getUniformLength(), built.getUniformLength());
    EXPECT_EQ(read.getAnchor(), built.getAnchor());
    EXPECT_EQ(read.getArrowHeadLengthRatio(), built.getArrowHeadLengthRatio());
    EXPECT_EQ(read.getArrowHeadRadiusRatio(), built.getArrowHeadRadiusRatio());
    EXPECT_EQ(read.getCompressedAttributes(), built.getCompressedAttributes());
    EXPECT_EQ(read.getCulling(), built.getCulling());
    EXPECT_EQ(read.getCullingChunkSize(), built.getCullingChunkSize());
    EXPECT_EQ(read.getOpacity(), built.getOpacity());
}

const GlyphCloud* cloudOf(const osg::Node* node)
{
    const osg::Geode* geode = node ? node->asGeode() : nullptr;
    if (!geode || geode->getNumDrawables() != 1)
        return nullptr;
    return dynamic_cast<const GlyphCloud*>(geode->getDrawable(0));
}

/** Every cloud of what was read (from a text file: text) against the clouds the fixtures were
 * made of. */
void expectTheFixtureClouds(const osg::Node* read, bool text)
{
    const osg::ref_ptr<osg::Group> built = osgGlyphsFixtures::createClouds();
    ASSERT_TRUE(read && read->asGroup());
    ASSERT_EQ(read->asGroup()->getNumChildren(), built->getNumChildren());
    for (unsigned int i = 0; i < built->getNumChildren(); ++i)
    {
        const GlyphCloud* readCloud = cloudOf(read->asGroup()->getChild(i));
        const GlyphCloud& builtCloud = *cloudOf(built->getChild(i));
        SCOPED_TRACE(builtCloud.getName());
        ASSERT_NE(readCloud, nullptr);
        EXPECT_EQ(readCloud->getName(), builtCloud.getName());
        expectSameNode(*readCloud, builtCloud);
        expectSameTechnique(*readCloud, builtCloud);
        expectSameArrays(*readCloud, builtCloud);
        expectSameStyle(*readCloud, builtCloud);
        expectSameOrigin(readCloud->getOrigin(), builtCloud.getOrigin(), text);
    }
}

void expectTheFixtureEffects(const osg::Node* read)
{
    const auto* effects = dynamic_cast<const osgGlyphs::ScreenEffects*>(read);
    ASSERT_NE(effects, nullptr);
    EXPECT_EQ(effects->getName(), "effects");
    EXPECT_TRUE(effects->getAmbientOcclusion());
    EXPECT_EQ(effects->getOcclusionRadius(), 0.3f);
    EXPECT_EQ(effects->getOcclusionStrength(), 0.7f);
    EXPECT_EQ(effects->getOcclusionSamples(), 24u);
    EXPECT_TRUE(effects->getOutlines());
    EXPECT_EQ(effects->getOutlineWidth(), 2.5f);
    EXPECT_EQ(effects->getOutlineColor(), osg::Vec4(0.2f, 0.0f, 0.1f, 0.9f));
    ASSERT_EQ(effects->getNumChildren(), 1u);
    const auto* peeling = dynamic_cast<const osgGlyphs::DepthPeeling*>(effects->getChild(0));
    ASSERT_NE(peeling, nullptr);
    EXPECT_EQ(peeling->getName(), "peeling");
    EXPECT_EQ(peeling->getNumLayers(), 3u);
    EXPECT_FALSE(peeling->getEnabled());
    EXPECT_EQ(peeling->getMethod(), osgGlyphs::DepthPeeling::PEEL_PASSES);
}

/** The fixture's TileRoot. Text files written before the domain hold its budget to 6 significant
 * digits (sixDigits), as the wrapper wrote doubles then. */
void expectTheFixtureTileRoot(const osg::Node* read, bool sixDigits)
{
    const auto* root = dynamic_cast<const osgGlyphsTiles::TileRoot*>(read);
    ASSERT_NE(root, nullptr);
    EXPECT_EQ(root->getName(), "tile-root");
    EXPECT_EQ(root->getGlyphBudget(), sixDigits ? 123457000000ull : 123456789012ull);
}

class FilesBeforeTheDomain : public ::testing::TestWithParam<std::string>
{
protected:
    std::string fixture(const std::string& name) const { return fixturePath(name + "." + GetParam()); }
};

}

TEST(WrapperDomain, EveryWrapperIsInTheDomainUnderItsClassName)
{
    osgDB::ObjectWrapperManager* wrappers = osgDB::Registry::instance()->getObjectWrapperManager();
    for (const char* name :
         {"osgGlyphs::GlyphCloud", "osgGlyphs::ColorMap", "osgGlyphs::ScreenEffects",
          "osgGlyphs::DepthPeeling", "osgGlyphs::GlyphTechnique", "osgGlyphs::GeometryShaderTechnique",
          "osgGlyphs::InstancedTechnique", "osgGlyphs::PointSpriteTechnique",
          "osgGlyphsPaper::PolygonsTechnique", "osgGlyphsPaper::PaperQuadTechnique",
          "osgGlyphsPaper::TextureBlendTechnique", "osgGlyphsPaper::TextureMultiTechnique",
          "osgGlyphsPaper::PointsFloorTechnique", "osgGlyphsTiles::TileRoot"})
    {
        const osgDB::ObjectWrapper* wrapper = wrappers->findWrapper(name);
        ASSERT_NE(wrapper, nullptr) << name;
        EXPECT_EQ(wrapper->getDomain(), osgGlyphsWrappers::DOMAIN_NAME) << name;
        EXPECT_EQ(wrapper->getName(), name);
    }
}

TEST_P(FilesBeforeTheDomain, DeclareNoDomain)
{
    for (const char* name : {"clouds", "effects", "tileroot"})
        EXPECT_TRUE(declaredDomains(fixture(name)).empty()) << fixture(name);
}

/** The properties version 2 added (DomainVersion.h). */
static bool isOfVersionTwo(const std::string& property)
{
    return property == "SemiAxes" || property == "Orientations" || property == "Exponents";
}

// Each property of versions 0 and 1 appears in the old text files: the fixtures set every one of them.
TEST(TextFilesBeforeTheDomain, HoldEveryProperty)
{
    std::string text;
    for (const char* name : {"clouds.osgt", "effects.osgt", "tileroot.osgt"})
        text += fileBytes(fixturePath(name));
    osgDB::ObjectWrapperManager* wrappers = osgDB::Registry::instance()->getObjectWrapperManager();
    for (const char* name :
         {"osgGlyphs::GlyphCloud", "osgGlyphs::ColorMap", "osgGlyphs::ScreenEffects",
          "osgGlyphs::DepthPeeling", "osgGlyphsPaper::PolygonsTechnique", "osgGlyphsTiles::TileRoot"})
        for (const auto& serializer : wrappers->findWrapper(name)->getSerializerList())
        {
            if (!isOfVersionTwo(serializer->getName())) // the fixtures were written before it
            {
                EXPECT_NE(text.find(" " + serializer->getName() + " "), std::string::npos)
                    << name << "::" << serializer->getName();
            }
        }
}

TEST_P(FilesBeforeTheDomain, CloudsReadWithEveryProperty)
{
    expectTheFixtureClouds(osgDB::readRefNodeFile(fixture("clouds")).get(), GetParam() == "osgt");
}

TEST_P(FilesBeforeTheDomain, EffectsReadWithEverySetting)
{
    expectTheFixtureEffects(osgDB::readRefNodeFile(fixture("effects")).get());
}

TEST_P(FilesBeforeTheDomain, TileRootReadsWithItsBudget)
{
    expectTheFixtureTileRoot(osgDB::readRefNodeFile(fixture("tileroot")).get(), GetParam() == "osgt");
}

// Written without asking for a version, files are the old ones byte for byte; but for a TileRoot in
// text, whose budget is now written whole.
TEST_P(FilesBeforeTheDomain, AreWhatTodaysCodeWritesWithoutAVersion)
{
    std::map<std::string, osg::ref_ptr<osg::Node>> scenes = {{"clouds", osgGlyphsFixtures::createClouds()},
                                                             {"effects", osgGlyphsFixtures::createEffects()}};
    if (GetParam() == "osgb")
        scenes["tileroot"] = osgGlyphsFixtures::createTileRoot();
    for (const auto& [name, scene] : scenes)
    {
        const std::string path = osgGlyphsTest::outputPath("unversioned_" + name + "." + GetParam());
        ASSERT_TRUE(osgDB::writeNodeFile(*scene, path)) << path;
        EXPECT_TRUE(fileBytes(path) == fileBytes(fixture(name))) << path << " differs from " << fixture(name);
    }
}

INSTANTIATE_TEST_SUITE_P(, FilesBeforeTheDomain, ::testing::Values("osgt", "osgb"),
                         [](const ::testing::TestParamInfo<std::string>& param) { return param.param; });

namespace
{

class FilesInTheDomain : public ::testing::TestWithParam<std::string>
{
protected:
    /** The scene written at version into the output folder (name.<format>), and read back. */
    osg::ref_ptr<osg::Node> writeAndRead(const osg::Node& scene, const std::string& name, int version)
    {
        _path = osgGlyphsTest::outputPath(name + "." + GetParam());
        if (!osgDB::writeNodeFile(scene, _path, optionsForVersion(version).get()))
            return nullptr;
        return osgDB::readRefNodeFile(_path);
    }

    std::string _path;
};

}

TEST_P(FilesInTheDomain, DeclareTheDomainVersionAndReadBack)
{
    const int version = osgGlyphsWrappers::DOMAIN_VERSION;
    const std::map<std::string, int> declared = {{osgGlyphsWrappers::DOMAIN_NAME, version}};
    expectTheFixtureClouds(
        writeAndRead(*osgGlyphsFixtures::createClouds(), "versioned_clouds", version).get(),
        GetParam() == "osgt");
    EXPECT_EQ(declaredDomains(_path), declared) << _path;
    expectTheFixtureEffects(
        writeAndRead(*osgGlyphsFixtures::createEffects(), "versioned_effects", version).get());
    EXPECT_EQ(declaredDomains(_path), declared) << _path;
    expectTheFixtureTileRoot(
        writeAndRead(*osgGlyphsFixtures::createTileRoot(), "versioned_tileroot", version).get(), false);
    EXPECT_EQ(declaredDomains(_path), declared) << _path;
}

namespace
{

/** A property of a later version of the domain, as a later release would add it after
 * UPDATE_TO_VERSION_SCOPED(version) to GlyphCloud's wrapper: an integer after every other property.
 * Added while the object lives. */
class LaterProperty
{
public:
    explicit LaterProperty(int version)
        : _wrapper(
              osgDB::Registry::instance()->getObjectWrapperManager()->findWrapper("osgGlyphs::GlyphCloud"))
    {
        osgDB::UpdateWrapperVersionProxy scope(_wrapper, version);
        _wrapper->addSerializer(new osgDB::UserSerializer<GlyphCloud>("LaterProperty", &check, &read, &write),
                                osgDB::BaseSerializer::RW_USER);
        reads = 0;
    }

    ~LaterProperty()
    {
        _wrapper->getSerializerList().pop_back();
        _wrapper->getTypeList().pop_back();
    }

    static int reads;

private:
    static bool check(const GlyphCloud&) { return true; }
    static bool read(osgDB::InputStream& is, GlyphCloud&)
    {
        int value = 0;
        is >> value;
        reads += value == 42 ? 1 : 0;
        return true;
    }
    static bool write(osgDB::OutputStream& os, const GlyphCloud&)
    {
        os << 42 << std::endl;
        return true;
    }

    osgDB::ObjectWrapper* _wrapper;
};

int LaterProperty::reads = 0;

}

// A property of version 2 is written only where the writer asks for version 2, and read only from
// files that declare it: old files read as before with it registered.
TEST_P(FilesInTheDomain, ALaterPropertyIsWrittenAndReadOnlyInItsVersion)
{
    const osg::ref_ptr<osg::Group> clouds = osgGlyphsFixtures::createClouds();
    LaterProperty later(2);
    expectTheFixtureClouds(writeAndRead(*clouds, "version1_clouds", 1).get(), GetParam() == "osgt");
    EXPECT_EQ(LaterProperty::reads, 0);
    EXPECT_EQ(fileBytes(_path).find("LaterProperty"), std::string::npos);
    expectTheFixtureClouds(osgDB::readRefNodeFile(fixturePath("clouds." + GetParam())).get(),
                           GetParam() == "osgt");
    EXPECT_EQ(LaterProperty::reads, 0);
    expectTheFixtureClouds(writeAndRead(*clouds, "version2_clouds", 2).get(), GetParam() == "osgt");
    EXPECT_EQ(LaterProperty::reads, static_cast<int>(clouds->getNumChildren()));
}

// A file of a later version than this code knows (as a later release writes it, with a property
// appended to every cloud) reads as osgDB reads any: the properties this code knows, in order; the
// rest of each object skipped (to its closing bracket in text, and to the end its size gives in
// binary), without a word. The clouds after the first read whole.
TEST_P(FilesInTheDomain, AFileOfALaterVersionReadsAsFarAsThisCodeKnows)
{
    const osg::ref_ptr<osg::Group> clouds = osgGlyphsFixtures::createClouds();
    {
        LaterProperty later(3);
        ASSERT_TRUE(writeAndRead(*clouds, "version3_clouds", 3).valid());
        EXPECT_EQ(LaterProperty::reads, static_cast<int>(clouds->getNumChildren()));
    }
    EXPECT_EQ(declaredDomains(_path).at(osgGlyphsWrappers::DOMAIN_NAME), 3);
    expectTheFixtureClouds(osgDB::readRefNodeFile(_path).get(), GetParam() == "osgt");
}

namespace
{

osg::ref_ptr<GlyphCloud> createEllipsoidCloud()
{
    osg::ref_ptr<osg::Vec3Array> positions = new osg::Vec3Array, semiAxes = new osg::Vec3Array;
    osg::ref_ptr<osg::Vec4Array> orientations = new osg::Vec4Array;
    for (int i = 0; i < 5; ++i)
    {
        positions->push_back(osg::Vec3(float(i), 0.5f * i, -0.25f * i));
        semiAxes->push_back(osg::Vec3(0.3f + 0.1f * i, 0.2f, 0.1f + 0.01f * i));
        orientations->push_back(osg::Quat(0.3 * i, osg::Vec3d(1.0, 0.5, -0.2)).asVec4());
    }
    osg::ref_ptr<GlyphCloud> cloud = new GlyphCloud;
    cloud->setName("ellipsoids");
    cloud->setShape(osgGlyphs::GlyphShape::Ellipsoid);
    cloud->setSemiAxes(semiAxes.get());
    cloud->setOrientations(orientations.get());
    cloud->setPositions(positions.get());
    return cloud;
}

}

// Ellipsoids' semi-axes and orientations are properties of version 2: they read back exactly from a
// file of version 2; a file of an earlier version leaves them out, and writing one says so.
TEST_P(FilesInTheDomain, EllipsoidsKeepTheirSemiAxesAndTurnsFromVersionTwo)
{
    const osg::ref_ptr<GlyphCloud> cloud = createEllipsoidCloud();
    osg::ref_ptr<osg::Group> scene = new osg::Group;
    scene->addChild(cloud.get());
    const osg::ref_ptr<osg::Node> read = writeAndRead(*scene, "ellipsoids_v2", 2);
    ASSERT_TRUE(read.valid()) << _path;
    const auto* readCloud = dynamic_cast<const GlyphCloud*>(read->asGroup()->getChild(0));
    ASSERT_NE(readCloud, nullptr);
    EXPECT_EQ(readCloud->getShape(), osgGlyphs::GlyphShape::Ellipsoid);
    ASSERT_NE(readCloud->getSemiAxes(), nullptr);
    ASSERT_NE(readCloud->getOrientations(), nullptr);
    EXPECT_EQ(readCloud->getSemiAxes()->asVector(), cloud->getSemiAxes()->asVector());
    EXPECT_EQ(readCloud->getOrientations()->asVector(), cloud->getOrientations()->asVector());
    EXPECT_EQ(readCloud->getNumGlyphs(), 5u);

    // Superquadrics: their exponents too.
    osg::ref_ptr<osg::Vec2Array> exponents = new osg::Vec2Array;
    for (unsigned int i = 0; i < 5; ++i)
        exponents->push_back(osg::Vec2(0.1f + 0.3f * i, 1.9f - 0.2f * i));
    cloud->setShape(osgGlyphs::GlyphShape::Superquadric);
    cloud->setExponents(exponents.get());
    const osg::ref_ptr<osg::Node> superquadrics = writeAndRead(*scene, "superquadrics_v2", 2);
    ASSERT_TRUE(superquadrics.valid()) << _path;
    const auto* readSuperquadrics = dynamic_cast<const GlyphCloud*>(superquadrics->asGroup()->getChild(0));
    ASSERT_NE(readSuperquadrics, nullptr);
    EXPECT_EQ(readSuperquadrics->getShape(), osgGlyphs::GlyphShape::Superquadric);
    ASSERT_NE(readSuperquadrics->getExponents(), nullptr);
    EXPECT_EQ(readSuperquadrics->getExponents()->asVector(), exponents->asVector());
    EXPECT_EQ(readSuperquadrics->getNumGlyphs(), 5u);
    cloud->setShape(osgGlyphs::GlyphShape::Ellipsoid);

    osg::ref_ptr<osgGlyphsTest::NotifyCapture> capture = new osgGlyphsTest::NotifyCapture;
    const osg::ref_ptr<osg::Node> old = writeAndRead(*scene, "ellipsoids_v1", 1);
    const std::string warnings = capture->stop();
    ASSERT_TRUE(old.valid()) << _path;
    EXPECT_EQ(dynamic_cast<const GlyphCloud*>(old->asGroup()->getChild(0))->getSemiAxes(), nullptr);
    EXPECT_NE(warnings.find("\"ellipsoids\" is written without its glyphs' semi-axes"), std::string::npos)
        << warnings;
}

INSTANTIATE_TEST_SUITE_P(, FilesInTheDomain, ::testing::Values("osgt", "osgb"),
                         [](const ::testing::TestParamInfo<std::string>& param) { return param.param; });

// A glyph budget beyond 32 bits, and beyond the 6 digits text streams give doubles, reads back
// whole from every format.
TEST(TileRootBudget, ReadsBackWholeFromEveryFormat)
{
    for (const char* format : {"osgt", "osgb", "osgx"})
    {
        const std::string path = osgGlyphsTest::outputPath(std::string("budget.") + format);
        ASSERT_TRUE(osgDB::writeNodeFile(*osgGlyphsFixtures::createTileRoot(), path)) << path;
        expectTheFixtureTileRoot(osgDB::readRefNodeFile(path).get(), false);
    }
}

// The archive osgglyphconvert wrote before the domain: its root is a TileRoot with the budget it
// was given, and every tile reads with the glyphs its checksum was made of.
TEST(TileArchiveBeforeTheDomain, OpensAndEveryTileReadsWithItsChecksum)
{
    const std::string path = fixturePath("tiles.osga");
    osg::ref_ptr<osg::Node> root = osgDB::readRefNodeFile(path);
    const auto* tileRoot = dynamic_cast<const osgGlyphsTiles::TileRoot*>(root.get());
    ASSERT_NE(tileRoot, nullptr) << path;
    EXPECT_EQ(tileRoot->getGlyphBudget(), osgGlyphsFixtures::ARCHIVE_GLYPH_BUDGET);
    ASSERT_GT(tileRoot->getNumChildren(), 0u);
    EXPECT_NE(dynamic_cast<const osg::PagedLOD*>(tileRoot->getChild(0)), nullptr);

    osg::ref_ptr<osgDB::Archive> archive = osgDB::openArchive(path, osgDB::ReaderWriter::READ);
    ASSERT_TRUE(archive.valid()) << path;
    osgDB::Archive::FileNameList names;
    ASSERT_TRUE(archive->getFileNames(names));
    EXPECT_GE(names.size(), 2u);
    EXPECT_EQ(std::count(names.begin(), names.end(), "root.osgb"), 1);
    for (const std::string& name : names)
    {
        osg::ref_ptr<osg::Node> tile = archive->readNode(name).getNode();
        ASSERT_TRUE(tile.valid()) << name;
        std::string error;
        EXPECT_TRUE(osgGlyphsTiles::checkTileChecksum(*tile, error)) << name << ": " << error;
    }
}

// An archive written today asks for the domain's version: each of its files (.osgb, stored whole)
// carries the binary header's domain entry, the name's length and bytes and the version.
TEST(TileArchiveInTheDomain, EveryFileDeclaresTheDomainVersion)
{
    EXPECT_EQ(std::string(OSGGLYPHS_SERIALIZER_DOMAIN_ENTRY), osgGlyphsWrappers::domainVersionEntry());
    osg::ref_ptr<GlyphCloud> cloud = new GlyphCloud;
    osg::ref_ptr<osg::Vec3Array> positions = new osg::Vec3Array;
    for (int i = 0; i < 120; ++i)
        positions->push_back(osg::Vec3(float(i % 5), float(i / 5 % 4), float(i / 20)));
    cloud->setPositions(positions.get());
    osgGlyphsTiles::TileOptions options;
    options.maxGlyphsPerTile = 30;
    options.cellsPerAxis = 2;
    options.threads = 1;
    osg::ref_ptr<osgGlyphsTiles::TileBuilder> builder = new osgGlyphsTiles::TileBuilder(*cloud, options);
    const std::string path = osgGlyphsTest::outputPath("osgdb_versioned_tiles.osga");
    std::string error;
    ASSERT_TRUE(builder->addGlyphs(*cloud, error)) << error;
    ASSERT_TRUE(builder->write(path, error)) << error;

    osg::ref_ptr<osgDB::Archive> archive = osgDB::openArchive(path, osgDB::ReaderWriter::READ);
    ASSERT_TRUE(archive.valid()) << path;
    osgDB::Archive::FileNameList names;
    ASSERT_TRUE(archive->getFileNames(names));
    ASSERT_GE(names.size(), 2u);
    std::string entry;
    auto putWord = [&entry](uint32_t word)
    { entry.append(reinterpret_cast<const char*>(&word), sizeof(word)); };
    putWord(static_cast<uint32_t>(std::strlen(OSGGLYPHS_SERIALIZER_DOMAIN)));
    entry += OSGGLYPHS_SERIALIZER_DOMAIN;
    putWord(static_cast<uint32_t>(OSGGLYPHS_SERIALIZER_VERSION));
    const std::string bytes = fileBytes(path);
    size_t declared = 0;
    for (size_t at = bytes.find(entry); at != std::string::npos; at = bytes.find(entry, at + 1))
        ++declared;
    // At least one a file: the builder stores a placeholder root first, which the root replaces.
    EXPECT_GE(declared, names.size()) << "files in " << path << " that declare the domain";
    for (const std::string& name : names)
        EXPECT_TRUE(archive->readNode(name).getNode()) << name;
}
