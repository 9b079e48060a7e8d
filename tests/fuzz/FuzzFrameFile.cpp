// libFuzzer target of a format read as a frame file (OSGGLYPHS_FUZZ_FORMAT: dcd, xtc, gsd, ...):
// the bytes are written to a file, opened with FrameSource and every frame decoded, in order, at
// random and as shares. Each opening and each frame either succeeds with consistent columns or
// fails with one line naming the file; a frame read twice is the same; the shares of a frame are
// the frame. The first frame, of up to 1000 points, is mapped to glyphs.

#include <osgGlyphsData/FrameSource>
#include <osgGlyphsData/GlyphMapping>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <unistd.h>

#ifndef OSGGLYPHS_FUZZ_FORMAT
#error "define OSGGLYPHS_FUZZ_FORMAT to a format name"
#endif

namespace
{

const std::string& inputPath()
{
    static const std::string path =
        "/tmp/osgglyphs_fuzz_" + std::to_string(::getpid()) + "." + OSGGLYPHS_FUZZ_FORMAT;
    return path;
}

bool isOneLineAboutTheInput(const std::string& message)
{
    return !message.empty() && message.find('\n') == std::string::npos && message.rfind(inputPath(), 0) == 0;
}

void check(bool condition)
{
    if (!condition)
        std::abort();
}

/** Aborts, printing it, on a message that is not one line naming the input. */
void checkMessage(const std::string& message)
{
    if (isOneLineAboutTheInput(message))
        return;
    std::fprintf(stderr, "not one line naming the input: [%s]\n", message.c_str());
    std::abort();
}

void checkColumns(const osgGlyphsData::PointData& frame)
{
    for (std::size_t c = 0; c < frame.getNumColumns(); ++c)
        check(frame.getColumn(c)->size() == frame.getNumPoints());
}

bool sameFrame(const osgGlyphsData::PointData& x, const osgGlyphsData::PointData& y)
{
    if (x.getColumnNames() != y.getColumnNames() || x.getNumPoints() != y.getNumPoints() ||
        x.getTimestep() != y.getTimestep())
        return false;
    for (std::size_t c = 0; c < x.getNumColumns(); ++c)
    {
        const std::vector<float>& a = *x.getColumn(c);
        const std::vector<float>& b = *y.getColumn(c);
        for (std::size_t i = 0; i < a.size(); ++i)
        {
            if (!(a[i] == b[i] || (a[i] != a[i] && b[i] != b[i])))
                return false;
        }
    }
    return true;
}

osg::ref_ptr<osgGlyphsData::FrameSource> open(const osgGlyphsData::PointShare& share = {})
{
    osgGlyphsData::FrameSourceOptions options;
    options.format = OSGGLYPHS_FUZZ_FORMAT;
    options.indexLocation = osgGlyphsData::FrameIndexLocation::None;
    options.share = share;
    options.warning = [](const std::string& warning) { checkMessage(warning); };
    std::string error;
    osg::ref_ptr<osgGlyphsData::FrameSource> source =
        osgGlyphsData::FrameSource::open(inputPath(), options, error);
    if (!source)
        checkMessage(error);
    return source;
}

}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size)
{
    std::ofstream(inputPath(), std::ios::binary | std::ios::trunc)
        .write(reinterpret_cast<const char*>(data), std::streamsize(size));
    osg::ref_ptr<osgGlyphsData::FrameSource> source = open();
    if (!source)
        return 0;
    const std::size_t frames = std::min<std::size_t>(source->getNumFrames(), 64);
    std::vector<osg::ref_ptr<osgGlyphsData::PointData>> decoded(frames);
    for (std::size_t frame = 0; frame < frames; ++frame)
    {
        std::string error;
        decoded[frame] = source->readFrame(frame, error);
        if (!decoded[frame])
            checkMessage(error);
        else
            checkColumns(*decoded[frame]);
    }
    // Backwards: the same frames, or the same failures.
    for (std::size_t frame = frames; frame-- > 0;)
    {
        std::string error;
        osg::ref_ptr<osgGlyphsData::PointData> again = source->readFrame(frame, error);
        check(again.valid() == decoded[frame].valid());
        if (again)
            check(sameFrame(*again, *decoded[frame]));
    }
    if (frames > 0 && decoded[0] && decoded[0]->getNumPoints() <= 1000)
    {
        osg::ref_ptr<osgGlyphsData::FrameSource> half = open({1, 2});
        std::string error;
        osg::ref_ptr<osgGlyphsData::PointData> part = half ? half->readFrame(0, error) : nullptr;
        if (part)
            check(part->getNumPoints() <= decoded[0]->getNumPoints());
        osg::ref_ptr<osgGlyphsData::PointDataset> dataset = new osgGlyphsData::PointDataset;
        dataset->addFrame(decoded[0].get());
        osgGlyphsData::GlyphMapper mapper{osgGlyphsData::GlyphMappingOptions()};
        error.clear();
        if (mapper.prepare(*dataset, 0, error))
            mapper.createCloud(*decoded[0], error);
        check(error.find('\n') == std::string::npos);
    }
    return 0;
}
