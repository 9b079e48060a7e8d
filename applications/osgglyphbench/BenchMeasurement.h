// osgglyphbench: measuring one case: its scene, its frames, their times and what they cover.

#ifndef OSGGLYPHBENCH_BENCHMEASUREMENT_H
#define OSGGLYPHBENCH_BENCHMEASUREMENT_H 1

#include "BenchOptions.h"

#include <osgGlyphs/GlyphTechnique>

#include <osg/Camera>

#include <string>
#include <vector>

/** Looks at the unit cube's centre from a distance that fits its bounding sphere into the 30 degree
 * field of view, orbiting a degree a frame: the view of every benchmark frame, in one process or
 * over MPI. */
void placeBenchCamera(osg::Camera& camera, unsigned int frame);

/** One case to measure: a technique drawing n glyphs of a shape. */
struct BenchCase
{
    std::string technique;
    osgGlyphs::GlyphShape shape;
    unsigned int n;
    osgGlyphs::GlyphCulling culling = osgGlyphs::GlyphCulling::Off;
    bool ambientOcclusion = false;
    ScreenEffectsChoice screenEffects = ScreenEffectsChoice::Off;
    float opacity = 1.0f;
    osgGlyphs::DepthPeeling::Method transparency = osgGlyphs::DepthPeeling::K_BUFFER;
};

/** One measured case: a row of the CSV. */
struct BenchResult
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
    osgGlyphs::GlyphCulling culling = osgGlyphs::GlyphCulling::Off;
    /** Fragments shaded per pixel drawn on, in one more frame (a pipeline statistics query);
     * negative where GL cannot count them. */
    double overdraw = -1.0;
    /** The fraction of the glyphs that culling sent to the GPU in the last frame. */
    double submitted = 1.0;
    bool ambientOcclusion = false;
    /** Seconds GlyphCloud::computeOcclusion() took, with ambient occlusion. */
    double occlusionSeconds = 0.0;
    ScreenEffectsChoice screenEffects = ScreenEffectsChoice::Off;
    float opacity = 1.0f;
    osgGlyphs::DepthPeeling::Method transparency = osgGlyphs::DepthPeeling::K_BUFFER;
};

/** Measures one case, a random cloud of glyphs of this radius, in a fresh headless viewer: one
 * warm-up frame and then settings.frames timed frames. The renderer string is filled in. False
 * with a one-line error without a headless context, or when a glyph program fails to compile or
 * link (osgGlyphs::GlyphStateCache::getProgramError()). */
bool measureCase(const BenchCase& c, float radius, const BenchSettings& settings, BenchResult& result,
                 std::string& renderer, std::string& error);

/** Measures settings.archive, a paged tile archive: its first frame, the frames until the
 * pager has nothing left to load (pagingFrames), then settings.frames timed frames of the same
 * orbit as the cases. False with a one-line error when it cannot be read or drawn. */
bool measureArchive(const BenchSettings& settings, BenchResult& result, unsigned int& pagingFrames,
                    std::string& error);

/** The median of the values (the mean of the middle two for an even count); one value at least. */
double median(std::vector<double> values);

/** Prints the cost of a frame that draws nothing: clearing and reading the colour buffer back. */
void printFrameOverhead(const BenchSettings& settings);

#endif
