// libFuzzer target of the frame index: arbitrary bytes are read as an index file (which must be
// refused or give ordered frames), scanned as a LAMMPS dump and as an XYZ file in blocks split
// where the input says (the frames found must not depend on the blocks), and opened as a
// trajectory whose every frame is read (each read succeeds or fails in one line naming the file).

#include "frames/FrameIndexFile.h"
#include "frames/FrameScanner.h"

#include <osgGlyphsData/FrameSource>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

using namespace osgGlyphsData;

namespace
{

std::string scratchFile(const char* name)
{
    return "/tmp/osgglyphs_fuzz_frames_" + std::to_string(::getpid()) + "_" + name;
}

void writeFile(const std::string& path, const uint8_t* data, std::size_t size)
{
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
}

std::vector<FrameInfo> scan(const std::string& format, const uint8_t* data, std::size_t size,
                            std::size_t piece, std::vector<std::string>& warnings)
{
    std::vector<FrameInfo> frames;
    frames::FrameScanner scanner(
        format, "fuzz", frames::ScanPosition(),
        [&frames](const FrameInfo& frame) { frames.push_back(frame); },
        [&warnings](const std::string& warning) { warnings.push_back(warning); });
    for (std::size_t at = 0; at < size; at += piece)
        scanner.feed(reinterpret_cast<const char*>(data) + at, std::min(piece, size - at));
    scanner.finish(false);
    return frames;
}

bool sameFrames(const std::vector<FrameInfo>& a, const std::vector<FrameInfo>& b)
{
    if (a.size() != b.size())
        return false;
    for (std::size_t i = 0; i < a.size(); ++i)
    {
        if (a[i].offset != b[i].offset || a[i].end != b[i].end || a[i].line != b[i].line ||
            a[i].points != b[i].points || a[i].timestep != b[i].timestep)
            return false;
    }
    return true;
}

}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size)
{
    const std::string path = scratchFile("input");
    writeFile(path, data, size);

    frames::StoredFrameIndex index;
    std::string error;
    if (frames::readFrameIndex(path, index, error))
    {
        for (std::size_t i = 1; i < index.frames.size(); ++i)
        {
            if (index.frames[i].offset < index.frames[i - 1].end)
                std::abort(); // readFrameIndex lets only ordered frames through
        }
    }

    const std::size_t piece = size > 0 ? 1 + data[0] % 61 : 1;
    for (const char* format : {"lammps", "xyz"})
    {
        std::vector<std::string> wholeWarnings, pieceWarnings;
        const std::vector<FrameInfo> whole = scan(format, data, size, size + 1, wholeWarnings);
        const std::vector<FrameInfo> pieces = scan(format, data, size, piece, pieceWarnings);
        if (!sameFrames(whole, pieces) || wholeWarnings != pieceWarnings)
            std::abort(); // the blocks must not matter
        for (const FrameInfo& frame : whole)
        {
            if (frame.end > size || frame.offset >= frame.end)
                std::abort();
        }
    }

    FrameSourceOptions options;
    options.indexLocation = FrameIndexLocation::None;
    options.warning = [](const std::string& warning)
    {
        if (warning.find('\n') != std::string::npos)
            std::abort();
    };
    for (const char* format : {"lammps", "xyz"})
    {
        options.format = format;
        osg::ref_ptr<FrameSource> source = FrameSource::open(path, options, error);
        if (!source)
        {
            if (error.empty() || error.find('\n') != std::string::npos)
                std::abort();
            continue;
        }
        source->waitForIndex();
        for (std::size_t frame = 0; frame < std::min<std::size_t>(source->getNumFrames(), 64); ++frame)
        {
            if (!source->readFrame(frame, error) &&
                (error.find('\n') != std::string::npos || error.compare(0, path.size(), path) != 0))
                std::abort();
        }
    }
    ::unlink(path.c_str());
    return 0;
}
