// osgglyphbench: the performance comparison of "Rendering Large Point Datasets with GPU Shaders"
// (Aguirre, Gutierrez, Perrin, TPCG 2010), reproduced and extended on osgGlyphs: frames per
// second of every glyph technique for random clouds of 100 to 1,000,000 glyphs, headless.

#include <osgGlyphs/GlyphCloud>
#include <osgGlyphs/Version>
#include <osgGlyphsData/RandomCloud>
#include <osgGlyphsHeadless/OffscreenViewer>
#include <osgGlyphsPaper/Techniques>

#include <osg/ArgumentParser>
#include <osg/Geode>
#include <osg/Point>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace
{

const char* const PROGRAM = "osgglyphbench";

const char* const CSV_HEADER = "technique,shape,n,width,height,frames,ms_median,ms_min,ms_max,first_frame_ms,"
                               "gpu_bytes_per_glyph,data_path,coverage,radius,attributes";

/** How vertex data reaches the GPU (paper section 3). */
enum class DataPath
{
    VBO,
    ClientArrays
};

const char* getDataPathName(DataPath path)
{
    switch (path)
    {
    case DataPath::ClientArrays:
        return "client-arrays";
    default:
        return "vbo";
    }
}

bool parseDataPath(const std::string& name, DataPath& path)
{
    for (DataPath candidate : {DataPath::VBO, DataPath::ClientArrays})
    {
        if (name == getDataPathName(candidate))
        {
            path = candidate;
            return true;
        }
    }
    return false;
}

struct Settings
{
    std::vector<std::string> techniques = osgGlyphs::getTechniqueNames();
    std::vector<osgGlyphs::GlyphShape> shapes = {osgGlyphs::GlyphShape::Sphere};
    std::vector<unsigned int> counts = {100, 316, 1000, 3162, 10000, 31623, 100000, 316228, 1000000};
    int width = 800;
    int height = 600;
    unsigned int frames = 10;
    float radius = 0.0f; // <= 0: getDefaultRandomRadius(n)
    bool equalCoverage = false;
    unsigned int seed = 1;
    double maxMs = 0.0; // 0: no limit
    std::string csvFile;
    std::string plotFile;
    DataPath dataPath = DataPath::VBO;
    bool compressedAttributes = true;
    osgGlyphsHeadless::HeadlessBackend backend = osgGlyphsHeadless::HeadlessBackend::Default;
};

/** One measured case: a row of the CSV. */
struct Result
{
    std::string technique;
    osgGlyphs::GlyphShape shape;
    unsigned int n;
    double msMedian;
    double msMin;
    double msMax;
    double firstFrameMs;
    double bytesPerGlyph;
    double coverage;
    float radius;
};

// ---------------------------------------------------------------------------------------------
// Command line

std::vector<std::string> splitList(const std::string& text)
{
    std::vector<std::string> items;
    std::istringstream stream(text);
    std::string item;
    while (std::getline(stream, item, ','))
        items.push_back(item);
    return items;
}

/** Parses a comma-separated list with parseItem, dropping repeats; reports the first bad item. */
template <class T, class Parse>
bool parseList(osg::ArgumentParser& arguments, const std::string& option, const std::string& text,
               const std::string& choices, Parse parseItem, std::vector<T>& values)
{
    std::vector<T> parsed;
    for (const std::string& item : splitList(text))
    {
        T value;
        if (!parseItem(item, value))
        {
            arguments.reportError(option + ": unknown value '" + item + "' (" + choices + ")");
            return false;
        }
        if (std::find(parsed.begin(), parsed.end(), value) == parsed.end())
            parsed.push_back(value);
    }
    if (parsed.empty())
    {
        arguments.reportError(option + ": empty list (" + choices + ")");
        return false;
    }
    values = parsed;
    return true;
}

bool parseCount(const std::string& text, unsigned int& count)
{
    char* end = nullptr;
    const unsigned long value = std::strtoul(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || text[0] == '-' || value == 0 || value > 100000000ul)
        return false;
    count = static_cast<unsigned int>(value);
    return true;
}

/** A registered technique's name, "default" for the default one. */
bool parseTechnique(const std::string& name, std::string& technique)
{
    const osg::ref_ptr<osgGlyphs::GlyphTechnique> created = osgGlyphs::createTechnique(name);
    if (created)
        technique = created->getTechniqueName();
    return created.valid();
}

std::string getTechniqueChoices()
{
    std::string choices = "default";
    for (const std::string& technique : osgGlyphs::getTechniqueNames())
        choices += std::string(", ") + technique;
    return choices;
}

void describeOptions(osg::ApplicationUsage& usage)
{
    usage.setCommandLineUsage(std::string(PROGRAM) + " [options]");
    usage.addCommandLineOption(
        "--techniques <a,b,...>",
        "Techniques to measure: " + getTechniqueChoices() +
            " (default: all). 'default' is the library's default technique. A technique that cannot "
            "draw a shape yet is skipped; points-floor is always measured.");
    usage.addCommandLineOption("--shapes <a,b,...>",
                               "Shapes: sphere, cone, arrow, cylinder (default sphere).");
    usage.addCommandLineOption("--n <n1,n2,...>", "Glyph counts (default 100,316,1000,...,316228,1000000).");
    usage.addCommandLineOption("--size <w> <h>", "Image size in pixels (default 800 600).");
    usage.addCommandLineOption("--frames <k>",
                               "Timed frames per case, after one warm-up frame (default 10).");
    usage.addCommandLineOption("--radius <r>",
                               "Glyph radius (default: getDefaultRandomRadius(n) = 0.5/sqrt(n), "
                               "at most 0.1, for a constant covered fraction of the view).");
    usage.addCommandLineOption("--equal-coverage",
                               "Give cones, arrows and cylinders the radius at which they cover as much of "
                               "the view as spheres of the radius above, at the same n (from one untimed "
                               "frame of each, scaling the radius by the square root of the coverage "
                               "ratio), so that shapes are compared at the same fragment load.");
    usage.addCommandLineOption("--seed <s>", "Seed of the random clouds (default 1).");
    usage.addCommandLineOption("--data-path <vbo|client-arrays>",
                               "How vertex data reaches the GPU (paper section 3; default vbo). "
                               "display-list is refused: glyph clouds cannot be drawn from display lists.");
    usage.addCommandLineOption("--attributes <compressed|float>",
                               "A glyph's radius and scalar as a half float and 16 bits in one word "
                               "(default), or as two floats (paper section 3; GlyphCloud::"
                               "setCompressedAttributes).");
    usage.addCommandLineOption("--max-ms <ms>", "Skip the larger n of a technique and shape once its median "
                                                "frame time exceeds ms (default: no limit).");
    usage.addCommandLineOption("--headless <osmesa|egl>",
                               "The headless GL backend (default: OSGGLYPHS_HEADLESS, else osmesa).");
    usage.addCommandLineOption("--csv <file>", "Write one row per case (columns below), as it goes.");
    usage.addCommandLineOption("--plot <file.png>", "Plot frames per second against n, log-log, one line per "
                                                    "technique and one panel per shape, with gnuplot (Debian "
                                                    "package gnuplot-nox).");
    usage.addCommandLineOption("--quick",
                               "CI mode: n = 100,1000,10000, 3 frames, 320x240 (explicit options win).");
    usage.addCommandLineOption("-h or --help", "Display this help.");
}

void printHelp(osg::ApplicationUsage& usage)
{
    std::cout << PROGRAM << " measures frames per second of osgGlyphs' glyph techniques (osgGlyphs "
              << osgGlyphsGetVersion() << ") for random clouds in the unit cube, headless,\n"
              << "as in Aguirre, Gutierrez and Perrin, TPCG 2010.\n\n"
              << "Each case (technique, shape, n) gets a fresh headless viewer. first_frame_ms times the\n"
              << "first frame (upload and shader compilation); then each of the timed frames, with the\n"
              << "camera orbiting 1 degree per frame about the data's centre, is timed around\n"
              << "viewer->frame(): update, cull, draw and the read-back of the colour buffer, which waits\n"
              << "for the frame to finish (glFinish semantics; depth is not read back). The overhead of an\n"
              << "empty frame is printed first. Ratios at the end are within this run.\n\n"
              << "Environment: MESA_SHADER_CACHE_DISABLE is set to true unless already set, so that\n"
              << "first_frame_ms includes compiling the shaders; OSGGLYPHS_HEADLESS picks the backend.\n\n";
    usage.write(std::cout, osg::ApplicationUsage::COMMAND_LINE_OPTION);
    std::cout << "\nCSV columns: " << CSV_HEADER << "\n(data_path, coverage, the fraction of the view "
              << "drawn on, the glyph radius and the attribute encoding follow the required columns.)"
              << std::endl;
}

/** The --quick preset; options given explicitly override it afterwards. */
void applyQuick(Settings& settings)
{
    settings.counts = {100, 1000, 10000};
    settings.frames = 3;
    settings.width = 320;
    settings.height = 240;
}

bool readLists(osg::ArgumentParser& arguments, Settings& settings)
{
    std::string text;
    if (arguments.read("--techniques", text) &&
        !parseList(arguments, "--techniques", text, getTechniqueChoices(), parseTechnique,
                   settings.techniques))
        return false;
    if (arguments.read("--shapes", text) &&
        !parseList(arguments, "--shapes", text, "sphere, cone, arrow, cylinder", osgGlyphs::parseShape,
                   settings.shapes))
        return false;
    if (arguments.read("--n", text) &&
        !parseList(arguments, "--n", text, "positive integers", parseCount, settings.counts))
        return false;
    if (arguments.read("--data-path", text) && !parseDataPath(text, settings.dataPath))
    {
        if (text == "display-list")
            arguments.reportError(
                "--data-path display-list: glyph clouds set per-cloud uniforms while drawing, "
                "which a display list does not replay (see GlyphCloud); use vbo or client-arrays");
        else
            arguments.reportError("--data-path: unknown value '" + text + "' (vbo, client-arrays)");
        return false;
    }
    if (arguments.read("--attributes", text))
    {
        if (text != "compressed" && text != "float")
        {
            arguments.reportError("--attributes: unknown value '" + text + "' (compressed, float)");
            return false;
        }
        settings.compressedAttributes = text == "compressed";
    }
    if (arguments.read("--headless", text) &&
        !osgGlyphsHeadless::parseHeadlessBackend(text, settings.backend))
    {
        arguments.reportError("--headless: unknown backend '" + text + "' (osmesa, egl)");
        return false;
    }
    return true;
}

void readValues(osg::ArgumentParser& arguments, Settings& settings)
{
    arguments.read("--size", settings.width, settings.height);
    arguments.read("--frames", settings.frames);
    arguments.read("--radius", settings.radius);
    settings.equalCoverage = arguments.read("--equal-coverage");
    arguments.read("--seed", settings.seed);
    arguments.read("--max-ms", settings.maxMs);
    arguments.read("--csv", settings.csvFile);
    arguments.read("--plot", settings.plotFile);
    if (settings.width <= 0 || settings.height <= 0)
        arguments.reportError("--size: width and height must be positive");
    if (settings.frames == 0)
        arguments.reportError("--frames: at least one frame");
}

/** Reads the settings; false when the command line is wrong (the errors are in arguments). */
bool readSettings(osg::ArgumentParser& arguments, Settings& settings)
{
    if (arguments.read("--quick"))
        applyQuick(settings);
    if (!readLists(arguments, settings))
        return false;
    readValues(arguments, settings);
    arguments.reportRemainingOptionsAsUnrecognized();
    for (int i = 1; i < arguments.argc(); ++i)
    {
        if (!arguments.isOption(i))
            arguments.reportError(std::string("unexpected argument '") + arguments[i] + "'");
    }
    return !arguments.errors();
}

// ---------------------------------------------------------------------------------------------
// The scene of one case

void applyDataPath(osg::Geometry& geometry, DataPath path)
{
    geometry.setUseDisplayList(false);
    geometry.setUseVertexBufferObjects(path == DataPath::VBO);
}

/** The floor of vertex processing, where the library cannot draw it: the positions as GL points
 * of size 1 in one colour. */
osg::ref_ptr<osg::Geometry> createPointsFloor(osg::Vec3Array* positions)
{
    osg::ref_ptr<osg::Geometry> geometry = new osg::Geometry;
    geometry->setVertexArray(positions);
    osg::ref_ptr<osg::Vec4Array> color = new osg::Vec4Array;
    color->push_back(osg::Vec4(1.0f, 1.0f, 1.0f, 1.0f));
    geometry->setColorArray(color.get(), osg::Array::BIND_OVERALL);
    geometry->addPrimitiveSet(new osg::DrawArrays(GL_POINTS, 0, static_cast<GLsizei>(positions->size())));
    osg::StateSet* stateSet = geometry->getOrCreateStateSet();
    stateSet->setMode(GL_LIGHTING, osg::StateAttribute::OFF);
    stateSet->setAttribute(new osg::Point(1.0f));
    return geometry;
}

/** The drawable of a case and its GPU bytes per glyph. */
osg::ref_ptr<osg::Geometry> createDrawable(std::string technique, osgGlyphs::GlyphShape shape, unsigned int n,
                                           float radius, const Settings& settings, double& bytesPerGlyph)
{
    osgGlyphsData::RandomCloudOptions options;
    options.count = n;
    options.seed = settings.seed;
    options.shape = shape;
    options.radius = radius;
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = osgGlyphsData::createRandomCloud(options);
    osg::ref_ptr<osg::Geometry> drawable = cloud;
    if (osgGlyphs::createTechnique(technique)->supportsShape(shape))
    {
        cloud->setTechnique(osgGlyphs::createTechnique(technique).get());
        cloud->setCompressedAttributes(settings.compressedAttributes);
        bytesPerGlyph = cloud->getGPUBytesPerGlyph();
    }
    else // only points-floor gets here
    {
        drawable = createPointsFloor(cloud->getPositions());
        bytesPerGlyph = sizeof(osg::Vec3);
    }
    applyDataPath(*drawable, settings.dataPath);
    return drawable;
}

// ---------------------------------------------------------------------------------------------
// Timing

/** Looks at the unit cube's centre from a distance that fits its bounding sphere into the
 * viewer's 30 degree field of view, orbiting 1 degree per frame. */
void placeCamera(osgGlyphsHeadless::OffscreenViewer& viewer, unsigned int frame)
{
    const osg::Vec3d centre(0.5, 0.5, 0.5);
    const double distance = 0.5 * std::sqrt(3.0) / std::sin(osg::DegreesToRadians(15.0));
    const double azimuth = osg::DegreesToRadians(30.0 + frame);
    const double elevation = osg::DegreesToRadians(20.0);
    const osg::Vec3d direction(std::cos(elevation) * std::cos(azimuth),
                               std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
    viewer.getCamera()->setViewMatrixAsLookAt(centre - direction * distance, centre,
                                              osg::Vec3d(0.0, 0.0, 1.0));
}

double timeFrame(osgGlyphsHeadless::OffscreenViewer& viewer, unsigned int frame)
{
    placeCamera(viewer, frame);
    const auto start = std::chrono::steady_clock::now();
    viewer.frame();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

double median(std::vector<double> values)
{
    std::sort(values.begin(), values.end());
    const size_t middle = values.size() / 2;
    return values.size() % 2 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

/** The fraction of pixels the scene drew on (the clear colour is transparent black). */
double getCoverage(const osg::Image& image)
{
    const unsigned char* pixels = image.data();
    const size_t count = static_cast<size_t>(image.s()) * image.t();
    if (!pixels || count == 0)
        return 0.0;
    size_t covered = 0;
    for (size_t i = 0; i < count; ++i)
        covered += (pixels[4 * i] | pixels[4 * i + 1] | pixels[4 * i + 2] | pixels[4 * i + 3]) != 0;
    return static_cast<double>(covered) / count;
}

/** A fresh viewer of the settings' size, realized, reading back colour only. */
osg::ref_ptr<osgGlyphsHeadless::OffscreenViewer> createViewer(const Settings& settings, osg::Node* scene)
{
    osg::ref_ptr<osgGlyphsHeadless::OffscreenViewer> viewer =
        new osgGlyphsHeadless::OffscreenViewer(settings.width, settings.height, settings.backend);
    if (!viewer->valid())
        return nullptr;
    viewer->getFrameCapture()->setCaptureDepth(false);
    viewer->getCamera()->setClearColor(osg::Vec4(0.0f, 0.0f, 0.0f, 0.0f));
    viewer->setSceneData(scene);
    viewer->realize();
    return viewer;
}

/** Times one warm-up frame and then settings.frames frames; false without a context. */
bool measure(const Settings& settings, osg::Node* scene, double& firstFrameMs, std::vector<double>& frameMs,
             osg::ref_ptr<osgGlyphsHeadless::OffscreenViewer>& viewer)
{
    viewer = createViewer(settings, scene);
    if (!viewer)
        return false;
    firstFrameMs = timeFrame(*viewer, 0);
    frameMs.clear();
    for (unsigned int frame = 1; frame <= settings.frames; ++frame)
        frameMs.push_back(timeFrame(*viewer, frame));
    return true;
}

// ---------------------------------------------------------------------------------------------
// Output

std::string format(double value, int decimals)
{
    std::ostringstream text;
    text << std::fixed << std::setprecision(decimals) << value;
    return text.str();
}

/** Milliseconds with three significant digits or more. */
std::string formatMs(double ms)
{
    return format(ms, ms >= 100.0 ? 0 : ms >= 10.0 ? 1 : ms >= 1.0 ? 2 : 3);
}

std::string describeCase(std::string technique, osgGlyphs::GlyphShape shape, unsigned int n)
{
    return technique + " " + osgGlyphs::getShapeName(shape) + " n=" + std::to_string(n);
}

/** "[index/total] technique shape n=N: " */
std::string getProgressPrefix(size_t index, size_t total, std::string technique, osgGlyphs::GlyphShape shape,
                              unsigned int n)
{
    return "[" + std::to_string(index) + "/" + std::to_string(total) + "] " +
           describeCase(technique, shape, n) + ": ";
}

void printProgress(const Result& result, size_t index, size_t total)
{
    std::cout << getProgressPrefix(index, total, result.technique, result.shape, result.n) << "median "
              << formatMs(result.msMedian) << " ms (min " << formatMs(result.msMin) << ", max "
              << formatMs(result.msMax) << "), first frame " << formatMs(result.firstFrameMs) << " ms, "
              << format(result.bytesPerGlyph, 1) << " B/glyph, covers " << format(100.0 * result.coverage, 1)
              << "% of the view" << (result.coverage > 0.0 ? "" : " (WARNING: it drew nothing)") << std::endl;
}

void writeCsvRow(std::ostream& csv, const Result& result, const Settings& settings)
{
    csv << result.technique << ',' << osgGlyphs::getShapeName(result.shape) << ',' << result.n << ','
        << settings.width << ',' << settings.height << ',' << settings.frames << ','
        << format(result.msMedian, 4) << ',' << format(result.msMin, 4) << ',' << format(result.msMax, 4)
        << ',' << format(result.firstFrameMs, 4) << ',' << format(result.bytesPerGlyph, 2) << ','
        << getDataPathName(settings.dataPath) << ',' << format(result.coverage, 4) << ','
        << format(result.radius, 7) << ',' << (settings.compressedAttributes ? "compressed" : "float") << '\n'
        << std::flush;
}

const Result* findResult(const std::vector<Result>& results, std::string technique,
                         osgGlyphs::GlyphShape shape, unsigned int n)
{
    for (const Result& result : results)
    {
        if (result.technique == technique && result.shape == shape && result.n == n)
            return &result;
    }
    return nullptr;
}

std::string formatRatio(const Result& result, const Result* reference)
{
    if (!reference)
        return "-";
    const double ratio = result.msMedian / reference->msMedian;
    return format(ratio, ratio >= 10.0 ? 1 : ratio >= 1.0 ? 2 : 3) + "x";
}

/** ms_median of every case relative to points-floor and to polygons at the same shape and n. */
void printSummary(const std::vector<Result>& results, const Settings& settings)
{
    std::cout << "\nSummary: median ms per frame, and relative to points-floor and to polygons (same "
                 "shape and n, this run)\n";
    std::cout << std::left << std::setw(10) << "shape" << std::setw(10) << "n" << std::setw(18) << "technique"
              << std::right << std::setw(10) << "ms" << std::setw(12) << "/floor" << std::setw(12)
              << "/polygons"
              << "\n";
    for (osgGlyphs::GlyphShape shape : settings.shapes)
    {
        for (unsigned int n : settings.counts)
        {
            const Result* floor = findResult(results, "points-floor", shape, n);
            const Result* polygons = findResult(results, "polygons", shape, n);
            for (const std::string& technique : settings.techniques)
            {
                const Result* result = findResult(results, technique, shape, n);
                if (!result)
                    continue;
                std::cout << std::left << std::setw(10) << osgGlyphs::getShapeName(shape) << std::setw(10)
                          << n << std::setw(18) << technique << std::right << std::setw(10)
                          << formatMs(result->msMedian) << std::setw(12) << formatRatio(*result, floor)
                          << std::setw(12) << formatRatio(*result, polygons) << "\n";
            }
        }
    }
    std::cout << std::flush;
}

// ---------------------------------------------------------------------------------------------
// Plot

std::string findExecutable(const std::string& name)
{
    const char* path = std::getenv("PATH");
    std::istringstream folders(path ? path : "");
    std::string folder;
    while (std::getline(folders, folder, ':'))
    {
        const std::string candidate = (folder.empty() ? std::string(".") : folder) + "/" + name;
        if (access(candidate.c_str(), X_OK) == 0)
            return candidate;
    }
    return std::string();
}

/** A string literal in gnuplot's single quotes. */
std::string quoteGnuplot(const std::string& text)
{
    std::string quoted = "'";
    for (char c : text)
        quoted += c == '\'' ? std::string("''") : std::string(1, c);
    return quoted + "'";
}

/** A word for sh, in single quotes. */
std::string quoteShell(const std::string& text)
{
    std::string quoted = "'";
    for (char c : text)
        quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

/** The same colour for a technique in every panel; the floor is a dashed black reference. */
std::string getLineStyle(std::string technique)
{
    if (technique == "points-floor")
        return "lc rgb '#000000' dt 2 lw 2 pt 7 ps 0.8";
    static const char* const colors[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728",
                                         "#9467bd", "#8c564b", "#e377c2", "#17becf"};
    const std::vector<std::string> all = osgGlyphs::getTechniqueNames();
    const size_t index = std::find(all.begin(), all.end(), technique) - all.begin();
    return std::string("lc rgb '") + colors[index % 8] + "' lw 2 pt 7 ps 0.8";
}

/** One data file per (shape, technique): n, fps at the median, at the slowest and the fastest
 * frame. Returns the plot command of the shape's panel, or an empty string without data. */
std::string writePanelData(const std::filesystem::path& folder, const std::vector<Result>& results,
                           const Settings& settings, osgGlyphs::GlyphShape shape)
{
    std::string plot;
    for (const std::string& technique : settings.techniques)
    {
        const std::string name = std::string(osgGlyphs::getShapeName(shape)) + "-" + technique + ".dat";
        std::ofstream data(folder / name);
        bool any = false;
        for (unsigned int n : settings.counts)
        {
            if (const Result* result = findResult(results, technique, shape, n))
            {
                data << n << ' ' << 1000.0 / result->msMedian << ' ' << 1000.0 / result->msMax << ' '
                     << 1000.0 / result->msMin << '\n';
                any = true;
            }
        }
        if (!any)
            continue;
        plot += std::string(plot.empty() ? "plot " : ", \\\n     ") + quoteGnuplot((folder / name).string()) +
                " using 1:2:3:4 with yerrorlines " + getLineStyle(technique) + " title " +
                quoteGnuplot(technique);
    }
    return plot;
}

/** The gnuplot script: a multiplot of one log-log panel per shape. */
std::string writePlotScript(const std::filesystem::path& folder, const std::vector<Result>& results,
                            const Settings& settings, const std::string& renderer)
{
    const unsigned int panels = static_cast<unsigned int>(settings.shapes.size());
    const unsigned int columns = std::min(panels, 2u), rows = (panels + 1) / 2;
    std::ostringstream script;
    script
        << "set terminal pngcairo size " << 720 * columns << "," << 540 * rows << " font 'sans,11'\n"
        << "set output " << quoteGnuplot(settings.plotFile) << "\n"
        << "set multiplot layout " << rows << "," << columns << " title "
        << quoteGnuplot("osgGlyphs, " + renderer + ", " + std::to_string(settings.width) + "x" +
                        std::to_string(settings.height) + ", " + getDataPathName(settings.dataPath))
        << "\n"
        << "set logscale xy\nset offsets graph 0.03, graph 0.03, 0, 0\nset grid xtics ytics mxtics mytics\n"
        << "set format x '10^{%L}'\n"
        << "set xlabel 'glyphs (N)'\nset ylabel 'frames per second'\nset key bottom left box opaque\n";
    for (osgGlyphs::GlyphShape shape : settings.shapes)
    {
        const std::string plot = writePanelData(folder, results, settings, shape);
        script << "set title "
               << quoteGnuplot(std::string(osgGlyphs::getShapeName(shape)) +
                               "s: median, bars from the slowest to the fastest frame")
               << "\n"
               << (plot.empty() ? std::string("plot 1/0 notitle") : plot) << "\n";
    }
    script << "unset multiplot\n";
    const std::filesystem::path file = folder / "plot.gp";
    std::ofstream(file) << script.str();
    return file.string();
}

/** Writes settings.plotFile with gnuplot from a script and data in a temporary folder. */
bool writePlot(const std::vector<Result>& results, const Settings& settings, const std::string& renderer)
{
    const std::string gnuplot = findExecutable("gnuplot");
    if (gnuplot.empty())
    {
        std::cerr << PROGRAM << ": error: --plot needs gnuplot, which is not on PATH: install the Debian "
                  << "package gnuplot-nox (apt-get install gnuplot-nox). No plot written"
                  << (settings.csvFile.empty() ? "." : "; the CSV is in " + settings.csvFile + ".")
                  << std::endl;
        return false;
    }
    std::string folder = (std::filesystem::temp_directory_path() / "osgglyphbench-XXXXXX").string();
    if (!mkdtemp(&folder[0]))
    {
        std::cerr << PROGRAM << ": error: cannot create a temporary folder for the plot" << std::endl;
        return false;
    }
    const std::string script = writePlotScript(folder, results, settings, renderer);
    if (std::system((quoteShell(gnuplot) + " " + quoteShell(script)).c_str()) != 0)
    {
        std::cerr << PROGRAM << ": error: gnuplot failed on " << script << std::endl;
        return false;
    }
    std::filesystem::remove_all(folder);
    std::cout << PROGRAM << ": wrote " << settings.plotFile << std::endl;
    return true;
}

// ---------------------------------------------------------------------------------------------
// The run

struct Case
{
    std::string technique;
    osgGlyphs::GlyphShape shape;
    unsigned int n;
};

bool canMeasure(std::string technique, osgGlyphs::GlyphShape shape)
{
    return technique == "points-floor" || osgGlyphs::createTechnique(technique)->supportsShape(shape);
}

/** Every case to measure, by shape, then n, then technique, so that an interrupted run has
 * every technique at the smaller n. Prints the (technique, shape) pairs skipped. */
std::vector<Case> listCases(const Settings& settings)
{
    std::vector<Case> cases;
    for (osgGlyphs::GlyphShape shape : settings.shapes)
    {
        for (const std::string& technique : settings.techniques)
        {
            if (!canMeasure(technique, shape))
                std::cout << "[skipped] " << technique << " " << osgGlyphs::getShapeName(shape)
                          << ": the library cannot draw it yet" << std::endl;
        }
        for (unsigned int n : settings.counts)
        {
            for (const std::string& technique : settings.techniques)
            {
                if (canMeasure(technique, shape))
                    cases.push_back(Case{technique, shape, n});
            }
        }
    }
    return cases;
}

/** Measures one case; false without a headless context. The renderer string is filled in. */
bool measureCase(const Case& c, float radius, const Settings& settings, Result& result, std::string& renderer)
{
    result = Result{c.technique, c.shape, c.n, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, radius};
    osg::ref_ptr<osg::Geode> scene = new osg::Geode;
    scene->addDrawable(
        createDrawable(c.technique, c.shape, c.n, radius, settings, result.bytesPerGlyph).get());
    std::vector<double> frameMs;
    osg::ref_ptr<osgGlyphsHeadless::OffscreenViewer> viewer;
    if (!measure(settings, scene.get(), result.firstFrameMs, frameMs, viewer))
        return false;
    result.msMedian = median(frameMs);
    result.msMin = *std::min_element(frameMs.begin(), frameMs.end());
    result.msMax = *std::max_element(frameMs.begin(), frameMs.end());
    result.coverage = getCoverage(*viewer->getColorImage());
    renderer = viewer->getFrameCapture()->getGLRenderer();
    return true;
}

/** The fraction of the view that n glyphs of this shape and radius cover in one untimed frame of
 * the default technique; negative without a headless context. */
double measureCoverage(osgGlyphs::GlyphShape shape, unsigned int n, float radius, const Settings& settings)
{
    Settings once = settings;
    once.frames = 1;
    Result result;
    std::string renderer;
    if (!measureCase(Case{osgGlyphs::DEFAULT_GLYPH_TECHNIQUE, shape, n}, radius, once, result, renderer))
        return -1.0;
    return result.coverage;
}

/** The glyph radius of a case: --radius or getDefaultRandomRadius(n); with --equal-coverage, a
 * vector shape's is scaled until it covers the view as spheres of that radius do (within 2%,
 * at most 5 untimed frames). Coverage grows as a power of the radius, close to 2; each step
 * solves for the power through the last two frames. 0 without a context. */
float getCaseRadius(const Case& c, const Settings& settings,
                    std::map<std::pair<int, unsigned int>, float>& cache)
{
    const float radius =
        settings.radius > 0.0f ? settings.radius : osgGlyphsData::getDefaultRandomRadius(c.n);
    if (!settings.equalCoverage || c.shape == osgGlyphs::GlyphShape::Sphere)
        return radius;
    const std::pair<int, unsigned int> key(static_cast<int>(c.shape), c.n);
    if (cache.count(key))
        return cache[key];
    const double target = measureCoverage(osgGlyphs::GlyphShape::Sphere, c.n, radius, settings);
    double scaled = radius, coverage = 0.0, power = 2.0;
    double lastScaled = 0.0, lastCoverage = 0.0;
    for (int step = 0; step < 5; ++step)
    {
        coverage = measureCoverage(c.shape, c.n, static_cast<float>(scaled), settings);
        if (target <= 0.0 || coverage <= 0.0)
            return 0.0f;
        if (std::fabs(coverage / target - 1.0) < 0.02)
            break;
        if (lastCoverage > 0.0 && lastCoverage != coverage)
            power = std::clamp(std::log(coverage / lastCoverage) / std::log(scaled / lastScaled), 0.5, 4.0);
        lastScaled = scaled;
        lastCoverage = coverage;
        scaled *= std::pow(target / coverage, 1.0 / power);
    }
    std::cout << "[equal coverage] " << osgGlyphs::getShapeName(c.shape) << " n=" << c.n << ": radius "
              << format(scaled / radius, 3) << " x the spheres', covering " << format(100.0 * coverage, 1)
              << "% of the view (spheres: " << format(100.0 * target, 1) << "%)" << std::endl;
    return cache[key] = static_cast<float>(scaled);
}

/** The cost of a frame that draws nothing: clearing and reading the colour buffer back. */
void printFrameOverhead(const Settings& settings)
{
    double firstFrameMs = 0.0;
    std::vector<double> frameMs;
    osg::ref_ptr<osgGlyphsHeadless::OffscreenViewer> viewer;
    osg::ref_ptr<osg::Group> empty = new osg::Group;
    if (measure(settings, empty.get(), firstFrameMs, frameMs, viewer))
        std::cout << "Empty frame (clear + colour read-back, " << settings.width << "x" << settings.height
                  << "): median " << formatMs(median(frameMs)) << " ms, with "
                  << viewer->getFrameCapture()->getGLRenderer() << std::endl;
}

/** Whether an earlier n of the same technique and shape went over --max-ms. */
bool isOverBudget(const std::vector<Result>& results, const Case& c, const Settings& settings)
{
    if (settings.maxMs <= 0.0)
        return false;
    for (const Result& result : results)
    {
        if (result.technique == c.technique && result.shape == c.shape && result.msMedian > settings.maxMs)
            return true;
    }
    return false;
}

/** Prints the system's 1-minute load average, where /proc/loadavg has it: other processes on
 * the machine make every time noisier. */
void printLoad(const char* when)
{
    std::ifstream file("/proc/loadavg");
    std::string load;
    if (file >> load)
        std::cout << "Load average " << when << ": " << load << std::endl;
}

/** Sets MESA_SHADER_CACHE_DISABLE=true unless the user set it; says which. */
void disableShaderCache()
{
    const bool userSet = std::getenv("MESA_SHADER_CACHE_DISABLE") != nullptr;
    if (!userSet)
        setenv("MESA_SHADER_CACHE_DISABLE", "true", 0);
    std::cout << "MESA_SHADER_CACHE_DISABLE=" << std::getenv("MESA_SHADER_CACHE_DISABLE")
              << (userSet ? " (set by the user)" : "") << std::endl;
}

int run(const Settings& settings)
{
    std::ofstream csv;
    if (!settings.csvFile.empty())
    {
        csv.open(settings.csvFile);
        if (!csv)
        {
            std::cerr << PROGRAM << ": error: cannot write " << settings.csvFile << std::endl;
            return 1;
        }
        csv << CSV_HEADER << '\n' << std::flush;
    }
    disableShaderCache();
    printLoad("at the start");
    printFrameOverhead(settings);
    const std::vector<Case> cases = listCases(settings);
    std::vector<Result> results;
    std::string renderer;
    std::map<std::pair<int, unsigned int>, float> radii; // with --equal-coverage: by (shape, n)
    for (size_t i = 0; i < cases.size(); ++i)
    {
        const Case& c = cases[i];
        if (isOverBudget(results, c, settings))
        {
            std::cout << getProgressPrefix(i + 1, cases.size(), c.technique, c.shape, c.n)
                      << "skipped (over --max-ms)" << std::endl;
            continue;
        }
        Result result;
        const float radius = getCaseRadius(c, settings, radii);
        if (radius <= 0.0f || !measureCase(c, radius, settings, result, renderer))
        {
            std::cerr << PROGRAM << ": error: no headless GL context" << std::endl;
            return 1;
        }
        printProgress(result, i + 1, cases.size());
        if (csv.is_open())
            writeCsvRow(csv, result, settings);
        results.push_back(result);
    }
    printLoad("at the end");
    printSummary(results, settings);
    if (csv.is_open())
        std::cout << PROGRAM << ": wrote " << settings.csvFile << std::endl;
    if (!settings.plotFile.empty() && !writePlot(results, settings, renderer))
        return 1;
    return 0;
}

}

int main(int argc, char** argv)
{
    osgGlyphsPaper::registerTechniques(); // the paper's techniques are the benchmark's references
    osg::ArgumentParser arguments(&argc, argv);
    osg::ApplicationUsage* usage = arguments.getApplicationUsage();
    usage->setApplicationName(PROGRAM);
    describeOptions(*usage);
    if (arguments.read("-h") || arguments.read("--help"))
    {
        printHelp(*usage);
        return 0;
    }
    Settings settings;
    if (!readSettings(arguments, settings))
    {
        arguments.writeErrorMessages(std::cerr);
        std::cerr << "(" << PROGRAM << " --help lists the options)" << std::endl;
        return 1;
    }
    return run(settings);
}
