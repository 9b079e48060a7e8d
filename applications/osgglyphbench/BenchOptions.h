// osgglyphbench: the command line.

#ifndef OSGGLYPHBENCH_BENCHOPTIONS_H
#define OSGGLYPHBENCH_BENCHOPTIONS_H 1

#include <osgGlyphs/DepthPeeling>
#include <osgGlyphs/GlyphCulling>
#include <osgGlyphs/GlyphTechnique>
#include <osgGlyphsHeadless/HeadlessContext>

#include <osg/ApplicationUsage>
#include <osg/ArgumentParser>

#include <string>
#include <vector>

/** The program's name in messages. */
extern const char* const PROGRAM;

/** How vertex data reaches the GPU (paper section 3). */
enum class DataPath
{
    VBO,
    ClientArrays,
    DisplayList
};

/** "vbo", "client-arrays" or "display-list", as --data-path and the CSV spell it. */
const char* getDataPathName(DataPath path);

/** The screen-space effects of a case (osgGlyphs::ScreenEffects; --screen-effects). */
enum class ScreenEffectsChoice
{
    Off,
    AmbientOcclusion,
    Outlines,
    Both
};

/** "off", "ao", "outline" or "both", as --screen-effects and the CSV spell it. */
/** "k-buffer" or "peel". */
const char* getTransparencyName(osgGlyphs::DepthPeeling::Method method);

const char* getScreenEffectsName(ScreenEffectsChoice choice);

/** Everything the command line sets. */
struct BenchSettings
{
    std::vector<std::string> techniques = osgGlyphs::getTechniqueNames();
    std::vector<osgGlyphs::GlyphShape> shapes = {osgGlyphs::GlyphShape::Sphere};
    std::vector<unsigned int> counts = {100, 316, 1000, 3162, 10000, 31623, 100000, 316228, 1000000};
    int width = 800;
    int height = 600;
    unsigned int frames = 10;
    /** Passes over all the cases (--repeat): each case keeps the median of its passes' medians. */
    unsigned int repeat = 1;
    float radius = 0.0f;        // <= 0: getDefaultRandomRadius(n)
    float radiusSpacing = 0.0f; // > 0: the radius is this multiple of the mean spacing n^(-1/3)
    float smallestAxis = 0.25f; // ellipsoids' and superquadrics' other semi-axes: [this, 1] x radius
    std::vector<osgGlyphs::GlyphCulling> cullings = {osgGlyphs::GlyphCulling::Occlusion};
    /** Per-glyph ambient occlusion off, on, or both (--ao). */
    std::vector<bool> ambientOcclusion = {false};
    /** Screen-space ambient occlusion and outlines (--screen-effects). */
    std::vector<ScreenEffectsChoice> screenEffects = {ScreenEffectsChoice::Off};
    /** The clouds' opacities (--opacity): 1 draws them opaque, less under a DepthPeeling node. */
    std::vector<float> opacities = {1.0f};
    /** How transparent clouds are sorted (--transparency): DepthPeeling's methods. */
    std::vector<osgGlyphs::DepthPeeling::Method> transparencyMethods = {osgGlyphs::DepthPeeling::K_BUFFER};
    unsigned int peelLayers = osgGlyphs::DepthPeeling::DEFAULT_NUM_LAYERS; // --peel-layers
    bool equalCoverage = false;
    unsigned int seed = 1;
    double maxMs = 0.0; // 0: no limit
    std::string csvFile;
    std::string plotFile;
    /** A paged tile archive (osgglyphconvert) to measure under the same camera (--archive). */
    std::string archive;
    DataPath dataPath = DataPath::VBO;
    bool compressedAttributes = true;
    bool compressedPositions = false;
    osgGlyphsHeadless::HeadlessBackend backend = osgGlyphsHeadless::HeadlessBackend::Default;
};

/** Lists every option in usage. */
void describeBenchOptions(osg::ApplicationUsage& usage);

/** Prints what the benchmark measures and how, the options of usage and the CSV columns. */
void printBenchHelp(osg::ApplicationUsage& usage);

/** Reads the settings; false when the command line is wrong (the errors are in arguments). */
bool readBenchSettings(osg::ArgumentParser& arguments, BenchSettings& settings);

#endif
