#include "ChunkDrawer.h"
#include "BinRounds.h"
#include "CullingRounds.h"
#include "OcclusionContext.h"
#include "ScreenCover.h"

#include <osg/ContextData>
#include <osg/Depth>
#include <osg/GLExtensions>

#include <algorithm>
#include <cmath>

using namespace osgGlyphs;
using namespace osgGlyphs::detail;

namespace
{

/** Where the rounds after the first end, as fractions of the chunks in view that do not cover the
 * view first (putScreenCoverFirst), nearest first: each is tested against everything before it. */
const double ROUND_ENDS[] = {1.0 / 8.0, 1.0 / 2.0, 1.0};

/** Too few chunks in view to be worth reading the depth back. */
const size_t MIN_CHUNKS_FOR_OCCLUSION = 16;

/** How far behind the pyramid a chunk or glyph must lie (window depth): 16 steps of a 24-bit
 * depth buffer, against rounding. */
const float OCCLUSION_MARGIN = 1.0f / (1 << 20);

/** The texels per axis over which a chunk is tested: a fine bound over its whole rectangle, since
 * random packings leave narrow gaps that show far into a cloud. */
const int CHUNK_TEST_TEXELS = 16;

/** Projects a chunk's box: false when it is outside the view. */
bool projectChunk(const osg::BoundingBox& box, const osg::Matrixd& modelViewProjection, double width,
                  double height, double depthNear, double depthFar, ChunkInView& projected)
{
    unsigned int outside[6] = {0, 0, 0, 0, 0, 0};
    bool behindEye = false;
    double xMin = 1e300, yMin = 1e300, zMin = 1e300, xMax = -1e300, yMax = -1e300;
    for (unsigned int corner = 0; corner < 8; ++corner)
    {
        const osg::Vec4d clip = osg::Vec4d(box.corner(corner), 1.0) * modelViewProjection;
        const double w = clip.w();
        outside[0] += clip.x() < -w;
        outside[1] += clip.x() > w;
        outside[2] += clip.y() < -w;
        outside[3] += clip.y() > w;
        outside[4] += clip.z() < -w;
        outside[5] += clip.z() > w;
        if (w <= 0.0 || clip.z() < -w)
        {
            behindEye = true;
            continue;
        }
        xMin = std::min(xMin, clip.x() / w);
        xMax = std::max(xMax, clip.x() / w);
        yMin = std::min(yMin, clip.y() / w);
        yMax = std::max(yMax, clip.y() / w);
        zMin = std::min(zMin, clip.z() / w);
    }
    for (unsigned int count : outside)
        if (count == 8)
            return false;
    if (behindEye)
    {
        // Crosses the near plane: it may cover any pixel, at any depth.
        projected.nearest = 0.0f;
        projected.x0 = projected.y0 = 0;
        projected.x1 = int(width) - 1;
        projected.y1 = int(height) - 1;
        return true;
    }
    const double windowZ = 0.5 * ((depthFar - depthNear) * zMin + depthNear + depthFar);
    projected.nearest = float(std::max(0.0, windowZ));
    projected.x0 = int(std::floor(std::clamp((xMin + 1.0) * 0.5 * width, 0.0, width - 1.0)));
    projected.x1 = int(std::floor(std::clamp((xMax + 1.0) * 0.5 * width, 0.0, width - 1.0)));
    projected.y0 = int(std::floor(std::clamp((yMin + 1.0) * 0.5 * height, 0.0, height - 1.0)));
    projected.y1 = int(std::floor(std::clamp((yMax + 1.0) * 0.5 * height, 0.0, height - 1.0)));
    return true;
}

/** Whether the depth buffer holds what a pyramid test assumes: nearer wins and every glyph drawn
 * writes its depth, one sample per pixel. */
bool depthIsTestable(osg::State& state, float& depthNear, float& depthFar)
{
    const auto* depth =
        dynamic_cast<const osg::Depth*>(state.getLastAppliedAttribute(osg::StateAttribute::DEPTH));
    depthNear = depth ? float(depth->getZNear()) : 0.0f;
    depthFar = depth ? float(depth->getZFar()) : 1.0f;
    const osg::Depth::Function function = depth ? depth->getFunction() : osg::Depth::LESS;
    const bool writes = depth ? depth->getWriteMask() : true;
    if (!state.getLastAppliedMode(GL_DEPTH_TEST) || !writes || depthNear > depthFar ||
        (function != osg::Depth::LESS && function != osg::Depth::LEQUAL))
        return false;
    GLint sampleBuffers = 0;
    glGetIntegerv(GL_SAMPLE_BUFFERS, &sampleBuffers);
    return sampleBuffers == 0;
}

/** The glyph programs' occlusion test: on against the context's pyramid of these levels, or off. */
void setProgramTest(osg::State& state, int levels, const OcclusionContext* context = nullptr)
{
    const osg::Program::PerContextProgram* program = state.getLastAppliedProgramObject();
    if (!program)
        return;
    osg::GLExtensions* ext = state.get<osg::GLExtensions>();
    static const unsigned int testID = osg::Uniform::getNameID("osgGlyphs_occlusion");
    static const unsigned int levelsID = osg::Uniform::getNameID("osgGlyphs_pyramidLevels");
    const GLint test = program->getUniformLocation(testID);
    if (test >= 0)
        ext->glUniform3f(test, levels > 0 ? 1.0f : 0.0f, float(levels), OCCLUSION_MARGIN);
    const GLint rectangles = program->getUniformLocation(levelsID);
    if (rectangles >= 0 && levels > 0 && context)
        ext->glUniform4iv(rectangles, levels, context->getAtlasLevels().data());
}

void recordOutcome(std::vector<unsigned char>* outcomes, unsigned int chunk, unsigned char outcome)
{
    if (outcomes)
        (*outcomes)[chunk] = outcome;
}

/** Draws chunks as one multi-draw of their ranges of the drawn arrays; chunks that follow each
 * other in the arrays as well as in the list make one range. */
class RangeDrawer
{
public:
    RangeDrawer(osg::State& state, const GlyphChunks& chunks) : _state(state), _chunks(chunks) {}

    unsigned int drawChunks(const std::vector<unsigned int>& chunkIndices)
    {
        _firsts.clear();
        _counts.clear();
        unsigned int glyphs = 0;
        for (unsigned int index : chunkIndices)
        {
            const GlyphChunk& chunk = _chunks.chunks[index];
            if (!_counts.empty() && GLint(chunk.first) == _firsts.back() + _counts.back())
                _counts.back() += GLsizei(chunk.count);
            else
            {
                _firsts.push_back(GLint(chunk.first));
                _counts.push_back(GLsizei(chunk.count));
            }
            glyphs += chunk.count;
        }
        if (!_counts.empty())
            _state.get<osg::GLExtensions>()->glMultiDrawArrays(GL_POINTS, _firsts.data(), _counts.data(),
                                                               GLsizei(_counts.size()));
        return glyphs;
    }

private:
    osg::State& _state;
    const GlyphChunks& _chunks;
    std::vector<GLint> _firsts;
    std::vector<GLsizei> _counts;
};

}

std::vector<ChunkInView> osgGlyphs::detail::projectChunks(const GlyphChunks& chunks,
                                                          const osg::Matrixd& modelViewProjection,
                                                          double width, double height, float depthNear,
                                                          float depthFar)
{
    std::vector<ChunkInView> inView;
    inView.reserve(chunks.chunks.size());
    for (unsigned int index = 0; index < chunks.chunks.size(); ++index)
    {
        ChunkInView projected;
        projected.chunk = index;
        if (projectChunk(chunks.chunks[index].box, modelViewProjection, width, height, depthNear, depthFar,
                         projected))
            inView.push_back(projected);
    }
    std::sort(inView.begin(), inView.end(),
              [](const ChunkInView& a, const ChunkInView& b) { return a.nearest < b.nearest; });
    return inView;
}

std::vector<size_t> osgGlyphs::detail::getRoundEnds(size_t cover, size_t size, bool testedFromStart)
{
    std::vector<size_t> ends = {cover};
    for (double end : ROUND_ENDS)
        if (!testedFromStart || end == 1.0)
            ends.push_back(cover + size_t(std::ceil(end * double(size - cover))));
    return ends;
}

bool osgGlyphs::detail::isChunkHidden(const ChunkInView& chunk, const DepthPyramid& pyramid)
{
    return chunk.nearest >
           pyramid.farthest(chunk.x0, chunk.y0, chunk.x1, chunk.y1, CHUNK_TEST_TEXELS) + OCCLUSION_MARGIN;
}

namespace
{

/** One cloud's rounds: each draws the chunks chosen in it and counts them in the statistics. */
class CloudRounds : public CullingRounds
{
public:
    CloudRounds(osg::State& state, OcclusionContext& context, RangeDrawer& drawer,
                GlyphCullingStatistics& statistics, std::vector<unsigned char>* outcomes)
        : _state(state), _context(context), _drawer(drawer), _statistics(statistics), _outcomes(outcomes)
    {
    }

protected:
    void depthRead(bool testing) override
    {
        ++_statistics.depthReadbacks;
        setProgramTest(_state, testing ? _context.applyPyramidTexture(_state) : 0, &_context);
    }

    void choose(unsigned int round, const ChunkInView& chunk, bool hidden) override
    {
        if (hidden)
        {
            ++_statistics.chunksOccluded;
            recordOutcome(_outcomes, chunk.chunk, CULLING_OCCLUDED);
            return;
        }
        _chunks.push_back(chunk.chunk);
        recordOutcome(_outcomes, chunk.chunk, static_cast<unsigned char>(CULLING_FIRST_ROUND + round));
    }

    unsigned int draw(unsigned int, bool) override
    {
        const unsigned int drawn = _drawer.drawChunks(_chunks);
        _chunks.clear();
        _statistics.glyphsSubmitted += drawn;
        ++_statistics.rounds;
        return drawn;
    }

private:
    osg::State& _state;
    OcclusionContext& _context;
    RangeDrawer& _drawer;
    GlyphCullingStatistics& _statistics;
    std::vector<unsigned char>* _outcomes;
    std::vector<unsigned int> _chunks;
};

/** Draws the chunks a FRONT_TO_BACK_BIN chose for the cloud in this round (drawBinInRounds). */
void drawBinRound(osg::State& state, OcclusionContext& context, const GlyphChunks& chunks,
                  GlyphCulling culling, CloudRound& planned, GlyphCullingStatistics& statistics,
                  std::vector<unsigned char>* outcomes)
{
    RangeDrawer drawer(state, chunks);
    if (planned.round == 0)
    {
        statistics = GlyphCullingStatistics();
        statistics.chunks = static_cast<unsigned int>(chunks.chunks.size());
        statistics.chunksOutsideView = statistics.chunks - static_cast<unsigned int>(planned.inView.size());
        if (outcomes)
        {
            outcomes->assign(chunks.chunks.size(), CULLING_OUTSIDE_VIEW);
            for (unsigned int chunk : planned.inView)
                (*outcomes)[chunk] = CULLING_OCCLUDED;
        }
        // The bin projected the chunks with the default depth range.
        float depthNear = 0.0f, depthFar = 1.0f;
        if (culling != GlyphCulling::Occlusion || !depthIsTestable(state, depthNear, depthFar) ||
            depthNear != 0.0f || depthFar != 1.0f)
        {
            // Not culled against the others: every chunk in view now.
            planned.drewAll = true;
            planned.chunks = planned.inView;
        }
    }
    statistics.depthReadbacks += planned.depthReadbacks;
    planned.depthReadbacks = 0;
    if (planned.chunks.empty())
        return;
    if (planned.testing && !planned.drewAll)
        setProgramTest(state, context.applyPyramidTexture(state), &context);
    for (unsigned int chunk : planned.chunks)
        if (outcomes)
            (*outcomes)[chunk] = static_cast<unsigned char>(CULLING_FIRST_ROUND + planned.round);
    statistics.glyphsSubmitted += drawer.drawChunks(planned.chunks);
    statistics.rounds = planned.round + 1;
    planned.chunksDrawn += static_cast<unsigned int>(planned.chunks.size());
    statistics.chunksOccluded = static_cast<unsigned int>(planned.inView.size()) - planned.chunksDrawn;
    setProgramTest(state, 0);
}

}

bool osgGlyphs::detail::drawChunks(osg::RenderInfo& renderInfo, const GlyphChunks& chunks,
                                   GlyphCulling culling, GlyphCullingStatistics& statistics,
                                   std::vector<unsigned char>* outcomes)
{
    osg::State& state = *renderInfo.getState();
    OcclusionContext* context = osg::get<OcclusionContext>(state.getContextID());
    if (CloudRound* planned = context->findBinRound(&chunks))
    {
        drawBinRound(state, *context, chunks, culling, *planned, statistics, outcomes);
        return planned->round == 0;
    }
    if (outcomes)
        outcomes->assign(chunks.chunks.size(), CULLING_OUTSIDE_VIEW);
    statistics = GlyphCullingStatistics();
    statistics.chunks = static_cast<unsigned int>(chunks.chunks.size());
    const osg::Viewport* viewport = state.getCurrentViewport();
    if (!viewport || chunks.chunks.empty())
        return true;

    float depthNear = 0.0f, depthFar = 1.0f;
    const bool occlusion = culling == GlyphCulling::Occlusion && depthIsTestable(state, depthNear, depthFar);
    std::vector<ChunkInView> inView =
        projectChunks(chunks, state.getModelViewMatrix() * state.getProjectionMatrix(), viewport->width(),
                      viewport->height(), depthNear, depthFar);
    statistics.chunksOutsideView = statistics.chunks - static_cast<unsigned int>(inView.size());

    RangeDrawer drawer(state, chunks);
    std::vector<unsigned int> round;
    if (!occlusion || inView.size() < MIN_CHUNKS_FOR_OCCLUSION)
    {
        for (const ChunkInView& chunk : inView)
        {
            round.push_back(chunk.chunk);
            recordOutcome(outcomes, chunk.chunk, CULLING_FIRST_ROUND);
        }
        statistics.glyphsSubmitted = drawer.drawChunks(round);
        statistics.rounds = 1;
        return true;
    }

    CloudRounds rounds(state, *context, drawer, statistics, outcomes);
    rounds.run(renderInfo, *viewport, *context, inView);
    setProgramTest(state, 0);
    return true;
}
