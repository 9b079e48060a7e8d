// osgdb_glyphs: point files read by osgDB as glyph scenes. The read scene renders the analytic
// spheres of the file; options choose the mapping; every failure is a message, never a crash;
// stock osgconv converts through the plugin.

#include "GlyphTestScenes.h"

#include <osgGlyphs/GlyphCloud>
#include <osgGlyphsData/GlyphMapping>
#include <osgGlyphsData/PointReader>

#include <osg/Sequence>
#include <osgDB/ReadFile>
#include <osgDB/Registry>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include <sys/wait.h>

using namespace osgGlyphsTest;
using osgGlyphs::GlyphCloud;
using ReadResult = osgDB::ReaderWriter::ReadResult;

namespace
{

const osg::Vec4ub RED(255, 0, 0, 255);
const osg::Vec4ub GREEN(0, 255, 0, 255);
const osg::Vec4ub BLUE(0, 0, 255, 255);

/** Radii are k/4 of the largest, which the half-float radius holds exactly. */
const std::vector<SphereSpec> SPHERES = {{osg::Vec3(-1.5f, 0.0f, 0.0f), 1.0f, RED},
                                         {osg::Vec3(1.2f, 0.3f, 0.4f), 0.75f, GREEN},
                                         {osg::Vec3(0.0f, -0.5f, -1.0f), 0.5f, BLUE}};

const double EXACT_DEPTH = 2.5e-7;

std::string writeTestFile(const std::string& name, const std::string& text)
{
    std::filesystem::create_directories(OSGGLYPHS_PLUGIN_TEST_DIR);
    const std::string path = std::string(OSGGLYPHS_PLUGIN_TEST_DIR) + "/" + name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

/** The spheres as CSV columns x,y,z,radius,red,green,blue (colours 0..1). */
std::string spheresCsv()
{
    std::ostringstream text;
    text << "x,y,z,radius,red,green,blue\n";
    for (const SphereSpec& s : SPHERES)
        text << s.center.x() << "," << s.center.y() << "," << s.center.z() << "," << s.radius << ","
             << s.color.r() / 255.0 << "," << s.color.g() / 255.0 << "," << s.color.b() / 255.0 << "\n";
    return text.str();
}

/** Three frames of two atoms with velocities. */
std::string threeFrameDump()
{
    std::string text;
    for (int step = 0; step < 3; ++step)
        text += "ITEM: TIMESTEP\n" + std::to_string(step * 100) +
                "\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS pp pp pp\n0 4\n0 4\n0 4\n"
                "ITEM: ATOMS id type x y z vx vy vz\n"
                "1 1 1 1 1 0.5 0 0\n2 2 3 3 " +
                std::to_string(1 + step) + " 0 0 " + std::to_string(step + 1) + "\n";
    return text;
}

osg::ref_ptr<osgDB::Options> withOptions(const std::string& text)
{
    return new osgDB::Options(text);
}

/** A PLY file that OSG's own ply plugin reads (as a mesh of two points), and the reader's error. */
const std::string BAD_PLY = "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
                            "property float z\nend_header\n1 2 3\n4 five 6\n";
const std::string BAD_PLY_ERROR = ":9: column 'y': 'five' is not a number";

bool hasOsgconv()
{
    return std::system("command -v osgconv >/dev/null 2>&1") == 0;
}

/** Runs stock osgconv with the arguments (quoted for the shell); returns its exit code, with
 * what it printed in log. */
int runOsgconv(const std::string& arguments, std::string& log)
{
    const std::string logFile = std::string(OSGGLYPHS_PLUGIN_TEST_DIR) + "/osgconv.log";
    // Sanitizer builds: the stock program needs the ASan runtime before our plugin.
    const std::string preload = OSGGLYPHS_STOCK_TOOL_PRELOAD;
    const std::string environment =
        preload.empty() ? std::string() : "env LD_PRELOAD=" + preload + " ASAN_OPTIONS=detect_leaks=0 ";
    const std::string command = environment + "osgconv " + arguments + " >'" + logFile + "' 2>&1";
    const int status = std::system(command.c_str());
    std::ifstream in(logFile);
    log = command + "\n" + std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

ReadResult readWithPlugin(const std::string& file, const std::string& options = std::string())
{
    osgDB::ReaderWriter* plugin = osgDB::Registry::instance()->getReaderWriterForExtension("glyphs");
    if (!plugin)
        return ReadResult("no osgdb_glyphs plugin on OSG_LIBRARY_PATH");
    return plugin->readNode(file, withOptions(options).get());
}

GlyphCloud* asCloud(osg::Node* node)
{
    return dynamic_cast<GlyphCloud*>(node);
}

/** Renders a scene read from a file and compares it with the analytic spheres. */
void expectAnalyticSpheres(osg::Node* scene, const std::string& name)
{
    ASSERT_NE(scene, nullptr);
    AnalyticScene truth;
    addSpheres(truth, SPHERES);
    Renderer renderer(160, 120);
    const Frame frame = renderer.render(scene);
    saveFrame(frame, name);
    const Agreement agreement = compareWithTruth(frame, truth, {RED, GREEN, BLUE}, EXACT_DEPTH);
    EXPECT_GT(agreement.covered, 1300); // pi * 16.48^2 * (1 + 0.75^2 + 0.5^2) = 1546, less overlap
    EXPECT_EQ(agreement.wrongLabel, 0) << "of " << agreement.certain << " certain pixels";
    EXPECT_EQ(agreement.wrongDepth, 0) << "worst depth error " << agreement.worstDepthError;
}

}

TEST(GlyphsPlugin, ReadsAFileByItsExtensionIntoTheSpheresItDescribes)
{
    const std::string file = writeTestFile("spheres.csv", spheresCsv());
    osg::ref_ptr<osg::Node> scene = osgDB::readRefNodeFile(file, withOptions("radius-by=radius unlit").get());
    ASSERT_NE(asCloud(scene.get()), nullptr);
    EXPECT_EQ(asCloud(scene.get())->getPositions()->size(), SPHERES.size());
    expectAnalyticSpheres(scene.get(), "plugin_csv_spheres");
}

TEST(GlyphsPlugin, OptionsChooseShapeColourAndColourMap)
{
    const std::string file = writeTestFile("atoms.lammpstrj", threeFrameDump());
    ReadResult result = readWithPlugin(file, "glyph=cone color=speed colormap=magma frame=2 other=1");
    GlyphCloud* cloud = asCloud(result.getNode());
    ASSERT_NE(cloud, nullptr) << result.message();
    EXPECT_EQ(cloud->getShape(), osgGlyphs::GlyphShape::Cone);
    EXPECT_EQ(cloud->getColorMap()->getName(), "magma");
    ASSERT_NE(cloud->getScalars(), nullptr);
    EXPECT_FLOAT_EQ((*cloud->getScalars())[1], 3.0f); // |v| of atom 2 in frame 2
    EXPECT_FLOAT_EQ((*cloud->getPositions())[1].z(), 3.0f);
    EXPECT_TRUE(cloud->getLit());
}

TEST(GlyphsPlugin, EveryFrameOfAFileBecomesASequence)
{
    const std::string file = writeTestFile("frames.lammpstrj", threeFrameDump());
    ReadResult result = readWithPlugin(file);
    osg::Sequence* sequence = dynamic_cast<osg::Sequence*>(result.getNode());
    ASSERT_NE(sequence, nullptr) << result.message();
    ASSERT_EQ(sequence->getNumChildren(), 3u);
    for (unsigned int i = 0; i < 3; ++i)
    {
        GlyphCloud* cloud = asCloud(sequence->getChild(i));
        ASSERT_NE(cloud, nullptr);
        EXPECT_FLOAT_EQ((*cloud->getPositions())[1].z(), 1.0f + i);
    }
    EXPECT_EQ(sequence->getMode(), osg::Sequence::START);
}

// Every frame is a cloud: without a frame option a long dump shows its first frame (and says so)
// rather than build a cloud for each of its frames; frame=all still plays them all.
TEST(GlyphsPlugin, ALongDumpShowsItsFirstFrameUnlessAllAreAskedFor)
{
    std::string text;
    for (int step = 0; step < 1001; ++step)
        text += "ITEM: TIMESTEP\n" + std::to_string(step) +
                "\nITEM: NUMBER OF ATOMS\n1\nITEM: ATOMS id x y z\n1 0 0 " + std::to_string(step) + "\n";
    const std::string file = writeTestFile("long.lammpstrj", text);
    ReadResult first = readWithPlugin(file, "radius=1");
    GlyphCloud* cloud = asCloud(first.getNode());
    ASSERT_NE(cloud, nullptr) << first.message();
    EXPECT_FLOAT_EQ((*cloud->getPositions())[0].z(), 0.0f);

    ReadResult all = readWithPlugin(file, "radius=1 frame=all");
    osg::Sequence* sequence = dynamic_cast<osg::Sequence*>(all.getNode());
    ASSERT_NE(sequence, nullptr) << all.message();
    EXPECT_EQ(sequence->getNumChildren(), 1001u);

    ReadResult last = readWithPlugin(file, "radius=1 frame=1000");
    ASSERT_NE(asCloud(last.getNode()), nullptr) << last.message();
    EXPECT_FLOAT_EQ((*asCloud(last.getNode())->getPositions())[0].z(), 1000.0f);
}

// Messages about a frame name it, and show the bytes of a column name that would not show.
TEST(GlyphMapper, MessagesNameTheFrameAndShowHiddenBytes)
{
    const std::string text =
        "ITEM: TIMESTEP\n100\nITEM: NUMBER OF ATOMS\n1\nITEM: ATOMS id element x y z\n1 C 0 0 0\n"
        "ITEM: TIMESTEP\n200\nITEM: NUMBER OF ATOMS\n1\nITEM: ATOMS id type x y z\n1 1 0 0 0\n";
    std::istringstream stream(text);
    std::string error;
    osg::ref_ptr<osgGlyphsData::PointDataset> dataset = osgGlyphsData::readPointStream(
        stream, "lammps", "run.lammpstrj", osgGlyphsData::PointReadOptions(), error);
    ASSERT_TRUE(dataset.valid()) << error;
    osgGlyphsData::GlyphMapper mapper{osgGlyphsData::GlyphMappingOptions()};
    ASSERT_TRUE(mapper.prepare(*dataset, 0, error)) << error;
    EXPECT_FALSE(mapper.createCloud(*dataset->getFrame(1), error).valid());
    EXPECT_EQ(error,
              "run.lammpstrj timestep 200: no column 'element' for the radii of the elements; available "
              "columns: id type x y z");

    std::istringstream bom("# exported\n\xEF\xBB\xBFx,y,z\n1,2,3\n");
    dataset = osgGlyphsData::readPointStream(bom, "csv", "bom.csv", osgGlyphsData::PointReadOptions(), error);
    ASSERT_TRUE(dataset.valid()) << error;
    EXPECT_EQ(dataset->getFrame(0)->getColumnNames(), (std::vector<std::string>{"x", "y", "z"}));

    std::istringstream hidden(
        "ITEM: TIMESTEP\n1\nITEM: NUMBER OF ATOMS\n1\nITEM: ATOMS id \xEF\xBB\xBFx y z\n1 0 0 0\n");
    dataset = osgGlyphsData::readPointStream(hidden, "lammps", "bom.lammpstrj",
                                             osgGlyphsData::PointReadOptions(), error);
    ASSERT_TRUE(dataset.valid()) << error;
    EXPECT_FALSE(mapper.prepare(*dataset, 0, error));
    EXPECT_EQ(error,
              "bom.lammpstrj: no position columns (x y z, xu yu zu, xs ys zs or xsu ysu zsu); available "
              "columns: id '\\xef\\xbb\\xbfx' y z");
}

TEST(GlyphsPlugin, PseudoExtensionAndPreloadedPluginTakePlyFromOsgsOwnReader)
{
    std::string ply = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                      "property float z\nproperty float radius\nproperty uchar red\nproperty uchar green\n"
                      "property uchar blue\nend_header\n";
    for (const SphereSpec& s : SPHERES)
        ply += std::to_string(s.center.x()) + " " + std::to_string(s.center.y()) + " " +
               std::to_string(s.center.z()) + " " + std::to_string(s.radius) + " " +
               std::to_string(s.color.r()) + " " + std::to_string(s.color.g()) + " " +
               std::to_string(s.color.b()) + "\n";
    const std::string file = writeTestFile("spheres.ply", ply);

    osg::ref_ptr<osg::Node> pseudo =
        osgDB::readRefNodeFile(file + ".glyphs", withOptions("radius-by=radius unlit").get());
    ASSERT_NE(asCloud(pseudo.get()), nullptr);
    expectAnalyticSpheres(pseudo.get(), "plugin_ply_spheres");

    ReadResult direct = readWithPlugin(file, "radius-by=radius unlit");
    ASSERT_NE(asCloud(direct.getNode()), nullptr) << direct.message();
}

TEST(GlyphsPlugin, StreamsAreReadInTheFormatTheOptionsName)
{
    osgDB::ReaderWriter* plugin = osgDB::Registry::instance()->getReaderWriterForExtension("glyphs");
    ASSERT_NE(plugin, nullptr);
    std::istringstream csv(spheresCsv());
    ReadResult result = plugin->readNode(csv, withOptions("format=csv radius-by=radius unlit").get());
    ASSERT_NE(asCloud(result.getNode()), nullptr) << result.message();
    expectAnalyticSpheres(result.getNode(), "plugin_stream_spheres");

    std::istringstream unnamed(spheresCsv());
    EXPECT_EQ(plugin->readNode(unnamed, withOptions("").get()).status(), ReadResult::FILE_NOT_HANDLED);
    std::istringstream broken("x,y,z\n1,2\n");
    result = plugin->readNode(broken, withOptions("format=csv").get());
    EXPECT_EQ(result.status(), ReadResult::ERROR_IN_READING_FILE);
    EXPECT_NE(result.message().find("osgdb_glyphs: stream:2: "), std::string::npos) << result.message();
}

TEST(GlyphsPlugin, TakesEveryExtensionOfThePointFormats)
{
    osgDB::ReaderWriter* plugin = osgDB::Registry::instance()->getReaderWriterForExtension("glyphs");
    ASSERT_NE(plugin, nullptr);
    for (const osgGlyphsData::PointFormat& format : osgGlyphsData::getPointFormats())
    {
        for (const std::string& extension : format.extensions)
            EXPECT_TRUE(plugin->acceptsExtension(extension)) << extension;
    }
}

TEST(GlyphsPlugin, ForeignExtensionsAreNotHandled)
{
    ReadResult result = readWithPlugin(writeTestFile("model.obj", "v 0 0 0\n"));
    EXPECT_EQ(result.status(), ReadResult::FILE_NOT_HANDLED);
    EXPECT_EQ(readWithPlugin(std::string(OSGGLYPHS_PLUGIN_TEST_DIR) + "/missing.xyz").status(),
              ReadResult::FILE_NOT_FOUND);
}

TEST(GlyphsPlugin, FailuresAreOneMessage)
{
    struct Case
    {
        std::string file, contents, options, message;
    };
    const std::vector<Case> cases = {
        {"bad.xyz", "2\ncomment\nH 0 0 0\nH 0 zero 0\n", "", "bad.xyz:4: "},
        {"ok.csv", "x,y,z\n1,2,3\n", "glyph=blob", "osgdb_glyphs: glyph 'blob': unknown shape"},
        {"ok2.csv", "x,y,z\n1,2,3\n", "color=speed", "color-by speed needs velocities"},
        {"ok3.csv", "x,y,z\n1,2,3\n", "radius=-2", "osgdb_glyphs: radius '-2': must be a positive number"},
        {"ok4.csv", "x,y,z\n1,2,3\n", "frame=7", "frame 7 asked for, the file has 1"},
        {"ok5.csv", "x,y,z\n1,2,3\n", "frame=x", "osgdb_glyphs: frame 'x': a frame number from 0, or all"},
        {"ok6.csv", "x,y,z\n1,2,3\n", "format=netcdf", "unknown point format 'netcdf'"},
        {"empty.vtk", "", "", "empty.vtk"},
    };
    for (const Case& c : cases)
    {
        ReadResult result = readWithPlugin(writeTestFile(c.file, c.contents), c.options);
        EXPECT_EQ(result.getNode(), nullptr) << c.file;
        EXPECT_EQ(result.status(), ReadResult::ERROR_IN_READING_FILE) << c.file;
        EXPECT_NE(result.message().find(c.message), std::string::npos)
            << c.file << " with '" << c.options << "': " << result.message();
        EXPECT_EQ(result.message().find('\n'), std::string::npos) << result.message();
    }
}

TEST(GlyphsPlugin, ItsErrorIsTheReadErrorOfAFileOsgsOwnPluginWouldReadToo)
{
    // Loaded first (as by osgconv -e glyphs), the plugin rejects the file; osgDB must not then
    // load osgdb_ply, whose reader turns the same file into a mesh.
    ASSERT_NE(osgDB::Registry::instance()->getReaderWriterForExtension("glyphs"), nullptr);
    const std::string file = writeTestFile("bad.ply", BAD_PLY);
    ReadResult result = osgDB::Registry::instance()->readNode(file, withOptions("").get());
    EXPECT_EQ(result.getNode(), nullptr);
    EXPECT_EQ(result.status(), ReadResult::ERROR_IN_READING_FILE);
    EXPECT_EQ(result.message(), "osgdb_glyphs: " + file + BAD_PLY_ERROR);
}

TEST(GlyphsPlugin, AFileOfGlyphsThatWouldNotShowIsReadWithAWarningThatSaysWhy)
{
    const std::string file =
        writeTestFile("still.csv", "x,y,z,vx,vy,vz\n-1,0,0,0,0,0\n1,0,0,0,0,0\n0,0,1,0,0,0\n");
    osg::ref_ptr<NotifyCapture> capture = new NotifyCapture;
    ReadResult result = readWithPlugin(file, "glyph=cone");
    const std::string warnings = capture->stop();
    ASSERT_NE(asCloud(result.getNode()), nullptr) << result.message();
    EXPECT_NE(
        warnings.find("osgdb_glyphs: " + file +
                      ": warning: no glyph is drawn: every glyph is skipped (3 of 3 have a zero vector"),
        std::string::npos)
        << warnings;

    capture = new NotifyCapture;
    result = readWithPlugin(file, "radius=1e-6");
    EXPECT_NE(capture->stop().find("warning: the glyphs hardly show: every glyph is under a pixel wide"),
              std::string::npos);
    capture = new NotifyCapture;
    result = readWithPlugin(file, "glyph=cone vector=x,y,z");
    EXPECT_EQ(capture->stop().find("warning"), std::string::npos);
}

TEST(GlyphsPlugin, StockOsgconvConvertsThroughThePlugin)
{
    if (!hasOsgconv())
        GTEST_SKIP() << "osgconv is not installed (Debian package openscenegraph)";
    const std::string file = writeTestFile("convert.csv", spheresCsv());
    const std::string output = std::string(OSGGLYPHS_PLUGIN_TEST_DIR) + "/converted.osgb";
    std::filesystem::remove(output);
    std::string log;
    ASSERT_EQ(runOsgconv("-O 'radius-by=radius unlit' '" + file + "' '" + output + "'", log), 0) << log;
    osg::ref_ptr<osg::Node> converted = osgDB::readRefNodeFile(output);
    ASSERT_NE(asCloud(converted.get()), nullptr);
    expectAnalyticSpheres(converted.get(), "plugin_osgconv_spheres");
}

TEST(GlyphsPlugin, StockOsgconvFailsWithTheReadersLineOnAPlyFileThePluginRejects)
{
    if (!hasOsgconv())
        GTEST_SKIP() << "osgconv is not installed (Debian package openscenegraph)";
    const std::string file = writeTestFile("bad.ply", BAD_PLY);
    const std::string output = std::string(OSGGLYPHS_PLUGIN_TEST_DIR) + "/bad.osgt";
    std::filesystem::remove(output);
    std::string log;
    EXPECT_NE(runOsgconv("-e glyphs '" + file + "' '" + output + "'", log), 0) << log;
    EXPECT_NE(log.find("osgdb_glyphs: " + file + BAD_PLY_ERROR), std::string::npos) << log;
    EXPECT_FALSE(std::filesystem::exists(output));
}

TEST(GlyphMappingOptions, EveryOptionParsesItsValueOrSaysWhatIsWrong)
{
    osgGlyphsData::GlyphMappingOptions options;
    options.optionPrefix = "--";
    std::string error;
    EXPECT_TRUE(osgGlyphsData::setGlyphMappingOption(options, "vector", "a,b,c", error));
    EXPECT_EQ(options.vectorColumns, (std::vector<std::string>{"a", "b", "c"}));
    EXPECT_TRUE(osgGlyphsData::setGlyphMappingOption(options, "range", "-1,2.5", error));
    EXPECT_TRUE(options.hasRange);
    EXPECT_FLOAT_EQ(options.rangeMin, -1.0f);
    EXPECT_FLOAT_EQ(options.rangeMax, 2.5f);
    EXPECT_TRUE(osgGlyphsData::setGlyphMappingOption(options, "lit", "off", error));
    EXPECT_FALSE(options.lit);
    EXPECT_TRUE(osgGlyphsData::setGlyphMappingOption(options, "technique", "default", error));

    const std::vector<std::pair<std::pair<std::string, std::string>, std::string>> failures = {
        {{"position", "x,y"}, "--position 'x,y': give 3 column names separated by commas"},
        {{"vector", "a,,c"}, "--vector 'a,,c': give 3 column names separated by commas"},
        {{"radius", "0"}, "--radius '0': must be a positive number"},
        {{"length-scale", "1e99"}, "--length-scale '1e99': must be a positive number"},
        {{"range", "3,1"}, "--range '3,1': the minimum must be less than the maximum"},
        {{"range", "1"}, "--range '1': give the minimum and the maximum"},
        {{"colormap", "nope"}, "--colormap 'nope': neither a built-in colour map"},
        {{"technique", "magic"}, "--technique 'magic': unknown technique (default, geometry-shader"},
        {{"lit", "maybe"}, "--lit 'maybe': on or off"},
        {{"unlit", "yes"}, "--unlit: takes no value"},
        {{"color-by", ""}, "--color-by: needs a column name"},
        {{"size", "3"}, "--size: unknown option (position, vector"},
    };
    for (const auto& failure : failures)
    {
        error.clear();
        EXPECT_FALSE(
            osgGlyphsData::setGlyphMappingOption(options, failure.first.first, failure.first.second, error));
        EXPECT_EQ(error.compare(0, failure.second.size(), failure.second), 0) << error;
    }
}
