#include "BenchOptions.h"

#include "BenchReport.h"

#include <osgGlyphs/Version>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <sstream>

const char* const PROGRAM = "osgglyphbench";

namespace
{

bool parseDataPath(const std::string& name, DataPath& path)
{
    for (DataPath candidate : {DataPath::VBO, DataPath::ClientArrays, DataPath::DisplayList})
    {
        if (name == getDataPathName(candidate))
        {
            path = candidate;
            return true;
        }
    }
    return false;
}

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

/** The --quick preset; options given explicitly override it afterwards. */
void applyQuick(BenchSettings& settings)
{
    settings.counts = {100, 1000, 10000};
    settings.frames = 3;
    settings.width = 320;
    settings.height = 240;
}

bool parseOnOff(const std::string& text, bool& on)
{
    on = text == "on";
    return on || text == "off";
}

bool parseScreenEffects(const std::string& text, ScreenEffectsChoice& choice)
{
    for (ScreenEffectsChoice candidate : {ScreenEffectsChoice::Off, ScreenEffectsChoice::AmbientOcclusion,
                                          ScreenEffectsChoice::Outlines, ScreenEffectsChoice::Both})
    {
        if (text == getScreenEffectsName(candidate))
        {
            choice = candidate;
            return true;
        }
    }
    return false;
}

bool parseOpacity(const std::string& text, float& opacity)
{
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !(value > 0.0 && value <= 1.0))
        return false;
    opacity = static_cast<float>(value);
    return true;
}

bool parseTransparency(const std::string& text, osgGlyphs::DepthPeeling::Method& method)
{
    for (osgGlyphs::DepthPeeling::Method candidate :
         {osgGlyphs::DepthPeeling::K_BUFFER, osgGlyphs::DepthPeeling::PEEL_PASSES})
        if (text == getTransparencyName(candidate))
        {
            method = candidate;
            return true;
        }
    return false;
}

bool readLists(osg::ArgumentParser& arguments, BenchSettings& settings)
{
    std::string text;
    if (arguments.read("--techniques", text) &&
        !parseList(arguments, "--techniques", text, getTechniqueChoices(), parseTechnique,
                   settings.techniques))
        return false;
    if (arguments.read("--shapes", text) &&
        !parseList(arguments, "--shapes", text, "sphere, cone, arrow, cylinder, ellipsoid, superquadric",
                   osgGlyphs::parseShape, settings.shapes))
        return false;
    if (arguments.read("--n", text) &&
        !parseList(arguments, "--n", text, "positive integers", parseCount, settings.counts))
        return false;
    if (arguments.read("--culling", text) &&
        !parseList(arguments, "--culling", text, "off, frustum, occlusion", osgGlyphs::parseCulling,
                   settings.cullings))
        return false;
    if (arguments.read("--ao", text) &&
        !parseList(arguments, "--ao", text, "off, on", parseOnOff, settings.ambientOcclusion))
        return false;
    if (arguments.read("--screen-effects", text) &&
        !parseList(arguments, "--screen-effects", text, "off, ao, outline, both", parseScreenEffects,
                   settings.screenEffects))
        return false;
    if (arguments.read("--opacity", text) &&
        !parseList(arguments, "--opacity", text, "numbers above 0 up to 1", parseOpacity, settings.opacities))
        return false;
    if (arguments.read("--transparency", text) &&
        !parseList(arguments, "--transparency", text, "k-buffer, peel", parseTransparency,
                   settings.transparencyMethods))
        return false;
    if (arguments.read("--data-path", text) && !parseDataPath(text, settings.dataPath))
    {
        arguments.reportError("--data-path: unknown value '" + text + "' (vbo, client-arrays, display-list)");
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
    if (arguments.read("--positions", text))
    {
        if (text != "float" && text != "16")
        {
            arguments.reportError("--positions: unknown value '" + text + "' (float, 16)");
            return false;
        }
        settings.compressedPositions = text == "16";
    }
    if (arguments.read("--headless", text) &&
        !osgGlyphsHeadless::parseHeadlessBackend(text, settings.backend))
    {
        arguments.reportError("--headless: unknown backend '" + text + "' (osmesa, egl)");
        return false;
    }
    return true;
}

void readValues(osg::ArgumentParser& arguments, BenchSettings& settings)
{
    arguments.read("--size", settings.width, settings.height);
    arguments.read("--frames", settings.frames);
    arguments.read("--repeat", settings.repeat);
    arguments.read("--peel-layers", settings.peelLayers);
    arguments.read("--radius", settings.radius);
    arguments.read("--radius-spacing", settings.radiusSpacing);
    arguments.read("--smallest-axis", settings.smallestAxis);
    settings.equalCoverage = arguments.read("--equal-coverage");
    arguments.read("--seed", settings.seed);
    arguments.read("--max-ms", settings.maxMs);
    arguments.read("--csv", settings.csvFile);
    arguments.read("--archive", settings.archive);
    arguments.read("--plot", settings.plotFile);
    if (settings.width <= 0 || settings.height <= 0)
        arguments.reportError("--size: width and height must be positive");
    if (settings.frames == 0)
        arguments.reportError("--frames: at least one frame");
    if (settings.repeat == 0)
        arguments.reportError("--repeat: at least one pass");
    if (!(settings.smallestAxis > 0.0f && settings.smallestAxis <= 1.0f))
        arguments.reportError("--smallest-axis: a share of the radius in (0, 1]");
    if (settings.peelLayers == 0)
        arguments.reportError("--peel-layers: at least one layer");
}

}

const char* getTransparencyName(osgGlyphs::DepthPeeling::Method method)
{
    return method == osgGlyphs::DepthPeeling::K_BUFFER ? "k-buffer" : "peel";
}

const char* getScreenEffectsName(ScreenEffectsChoice choice)
{
    switch (choice)
    {
    case ScreenEffectsChoice::AmbientOcclusion:
        return "ao";
    case ScreenEffectsChoice::Outlines:
        return "outline";
    case ScreenEffectsChoice::Both:
        return "both";
    default:
        return "off";
    }
}

const char* getDataPathName(DataPath path)
{
    switch (path)
    {
    case DataPath::ClientArrays:
        return "client-arrays";
    case DataPath::DisplayList:
        return "display-list";
    default:
        return "vbo";
    }
}

void describeBenchOptions(osg::ApplicationUsage& usage)
{
    usage.setCommandLineUsage(std::string(PROGRAM) + " [options]");
    usage.addCommandLineOption(
        "--techniques <a,b,...>",
        "Techniques to measure: " + getTechniqueChoices() +
            " (default: all). 'default' is the library's default technique. A technique that cannot "
            "draw a shape yet is skipped; points-floor is always measured.");
    usage.addCommandLineOption(
        "--shapes <a,b,...>",
        "Shapes: sphere, cone, arrow, cylinder, ellipsoid, superquadric (default sphere).");
    usage.addCommandLineOption("--n <n1,n2,...>", "Glyph counts (default 100,316,1000,...,316228,1000000).");
    usage.addCommandLineOption("--size <w> <h>", "Image size in pixels (default 800 600).");
    usage.addCommandLineOption("--frames <k>",
                               "Timed frames per case, after one warm-up frame (default 10).");
    usage.addCommandLineOption(
        "--repeat <k>",
        "Measure all the cases k times, one pass after another, and keep each case's median over the "
        "passes (default 1): the ratios between cases of one run then outlast the machine's slow spells.");
    usage.addCommandLineOption("--radius <r>",
                               "Glyph radius (default: getDefaultRandomRadius(n) = 0.5/sqrt(n), "
                               "at most 0.1, for a constant covered fraction of the view).");
    usage.addCommandLineOption(
        "--smallest-axis <f>",
        "Ellipsoids' and superquadrics' two other semi-axes, uniform in [f, 1] times the largest, the "
        "radius (default 0.25); 1 draws ellipsoids as spheres, to compare shapes that hide as much.");
    usage.addCommandLineOption(
        "--radius-spacing <f>",
        "Dense data: the radius is f times the mean spacing of the points, n^(-1/3) in "
        "the unit cube (0.4 is osgglyphviewer's default radius; glyphs touch at 0.5).");
    usage.addCommandLineOption(
        "--culling <a,b,...>",
        "How clouds skip hidden glyphs, each measured in turn: off, frustum, occlusion "
        "(default occlusion; GlyphCloud::setCulling). Techniques that cannot cull are "
        "measured once, with culling off.");
    usage.addCommandLineOption(
        "--ao <off,on>", "Per-glyph ambient occlusion (GlyphCloud::computeOcclusion, setOcclusion): off "
                         "(default), on, or both, each case measured with each; its computation time is "
                         "printed and written to the CSV.");
    usage.addCommandLineOption(
        "--screen-effects <off,ao,outline,both>",
        "Screen-space ambient occlusion and outlines (osgGlyphs::ScreenEffects, default settings) around "
        "the cloud: off (default), ao, outline, both, each case measured with each, so that their cost "
        "compares with the plain frame of the same run.");
    usage.addCommandLineOption(
        "--opacity <a1,a2,...>",
        "Cloud opacities (default 1): below 1 the cloud is transparent, under an osgGlyphs::DepthPeeling "
        "node, so that 1,0.5 gives the cost of transparency against the opaque frame.");
    usage.addCommandLineOption("--peel-layers <k>", "The layers depth peeling draws (default 4).");
    usage.addCommandLineOption("--transparency <m1,m2,...>",
                               "How transparent clouds are sorted: k-buffer (the default: one pass into "
                               "per-pixel lists) or peel (a pass per layer).");
    usage.addCommandLineOption("--equal-coverage",
                               "Give cones, arrows and cylinders the radius at which they cover as much of "
                               "the view as spheres of the radius above, at the same n (from one untimed "
                               "frame of each, scaling the radius by the square root of the coverage "
                               "ratio), so that shapes are compared at the same fragment load.");
    usage.addCommandLineOption("--seed <s>", "Seed of the random clouds (default 1).");
    usage.addCommandLineOption("--data-path <vbo|client-arrays|display-list>",
                               "How vertex data reaches the GPU (paper section 3; default vbo). The "
                               "instanced techniques are skipped with display-list: GL compiles no "
                               "instanced draw into a display list.");
    usage.addCommandLineOption("--attributes <compressed|float>",
                               "A glyph's radius and scalar as a half float and 16 bits in one word "
                               "(default), or as two floats (paper section 3; GlyphCloud::"
                               "setCompressedAttributes).");
    usage.addCommandLineOption("--positions <float|16>",
                               "Positions as floats (default), or as 16-bit integers on a grid over the "
                               "cloud, as paged tiles draw them (GlyphCloud::setCompressedPositions).");
    usage.addCommandLineOption("--max-ms <ms>", "Skip the larger n of a technique and shape once its median "
                                                "frame time exceeds ms (default: no limit).");
    usage.addCommandLineOption(
        "--headless <osmesa|egl>",
        "The headless GL backend (default: OSGGLYPHS_HEADLESS, else EGL, else OSMesa).");
    usage.addCommandLineOption("--csv <file>", "Write one row per case (columns below), as it goes.");
    usage.addCommandLineOption(
        "--archive <file.osga>",
        "Also measure a paged tile archive (osgglyphconvert; one of the unit cube, such as "
        "osgglyphconvert --random N) under the same camera, once its tiles have paged in, "
        "against each case of the run.");
    usage.addCommandLineOption("--plot <file.png>", "Plot frames per second against n, log-log, one line per "
                                                    "technique and one panel per shape, with gnuplot (Debian "
                                                    "package gnuplot-nox).");
    usage.addCommandLineOption("--quick",
                               "CI mode: n = 100,1000,10000, 3 frames, 320x240 (explicit options win).");
    usage.addCommandLineOption("-h or --help", "Display this help.");
}

void printBenchHelp(osg::ApplicationUsage& usage)
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

bool readBenchSettings(osg::ArgumentParser& arguments, BenchSettings& settings)
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
