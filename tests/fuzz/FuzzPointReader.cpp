// libFuzzer target: feeds arbitrary bytes through readPointStream in one format (OSGGLYPHS_FUZZ_FORMAT),
// once from a seekable stream (size known) and once from one that cannot seek (size unknown).
// Each read either succeeds with consistent frames or fails with exactly one error line naming the
// input, and both reads agree on success and on the data. A successful read is read again as a
// growing file, then resumed from where its complete frames end: together the two give the same
// frames. The first frame, of up to 1000 points, is mapped to glyphs (the default radius searches
// nearest neighbours).

#include <osgGlyphsData/GlyphMapping>
#include <osgGlyphsData/PointReader>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <streambuf>
#include <string>

#ifndef OSGGLYPHS_FUZZ_FORMAT
#error "define OSGGLYPHS_FUZZ_FORMAT to a format name"
#endif

namespace
{

// Hands out the bytes in small pieces and cannot seek.
class PipeBuffer : public std::streambuf
{
public:
    PipeBuffer(const char* data, std::size_t size) : _data(data), _size(size), _at(0) {}

protected:
    int_type underflow() override
    {
        if (_at >= _size)
            return traits_type::eof();
        const std::size_t piece = std::min<std::size_t>(_size - _at, 4093);
        char* begin = const_cast<char*>(_data + _at);
        setg(begin, begin, begin + piece);
        _at += piece;
        return traits_type::to_int_type(*begin);
    }

private:
    const char* _data;
    std::size_t _size;
    std::size_t _at;
};

bool isOneLineAboutTheInput(const std::string& message)
{
    return !message.empty() && message.find('\n') == std::string::npos && message.compare(0, 4, "fuzz") == 0;
}

osg::ref_ptr<osgGlyphsData::PointDataset> read(std::istream& stream, std::string& error,
                                               osgGlyphsData::PointReadOptions options = {})
{
    options.warning = [](const std::string& warning)
    {
        if (!isOneLineAboutTheInput(warning))
            std::abort();
    };
    osg::ref_ptr<osgGlyphsData::PointDataset> dataset =
        osgGlyphsData::readPointStream(stream, OSGGLYPHS_FUZZ_FORMAT, "fuzz", options, error);
    if (!dataset.valid())
    {
        if (!isOneLineAboutTheInput(error))
            std::abort();
        return dataset;
    }
    for (const auto& frame : dataset->getFrames())
    {
        for (std::size_t c = 0; c < frame->getNumColumns(); ++c)
        {
            if (frame->getColumn(c)->size() != frame->getNumPoints())
                std::abort();
        }
        std::vector<osg::Vec3f> positions;
        osgGlyphsData::getPositions(*frame, {}, positions, error);
    }
    return dataset;
}

bool sameFrame(const osgGlyphsData::PointData& x, const osgGlyphsData::PointData& y)
{
    if (x.getColumnNames() != y.getColumnNames() || x.getNumPoints() != y.getNumPoints() ||
        x.getTimestep() != y.getTimestep())
        return false;
    for (std::size_t c = 0; c < x.getNumColumns(); ++c)
    {
        if (*x.getColumn(c) != *y.getColumn(c))
            return false;
    }
    return true;
}

bool same(const osgGlyphsData::PointDataset& a, const osgGlyphsData::PointDataset& b)
{
    if (a.getNumFrames() != b.getNumFrames())
        return false;
    for (std::size_t f = 0; f < a.getNumFrames(); ++f)
    {
        if (!sameFrame(*a.getFrame(f), *b.getFrame(f)))
            return false;
    }
    return true;
}

// The input read as a file still being written, then from where that reading's complete frames
// end: the frames of the two readings are those of the whole input read at once.
void checkResumedReading(const std::string& bytes, const osgGlyphsData::PointDataset& whole)
{
    std::istringstream first(bytes);
    osgGlyphsData::PointReadOptions options;
    options.growing = true;
    std::string error;
    osg::ref_ptr<osgGlyphsData::PointDataset> growing = read(first, error, options);
    if (!growing.valid())
        std::abort();
    const osgGlyphsData::PointStreamPosition end = growing->getEndOfCompleteFrames();
    if (end.offset > bytes.size())
        std::abort();
    std::istringstream rest(bytes.substr(end.offset));
    options.growing = false;
    options.start = end;
    osg::ref_ptr<osgGlyphsData::PointDataset> resumed = read(rest, error, options);
    if (!resumed.valid() || growing->getNumFrames() + resumed->getNumFrames() != whole.getNumFrames())
        std::abort();
    for (std::size_t f = 0; f < whole.getNumFrames(); ++f)
    {
        const std::size_t before = growing->getNumFrames();
        const osgGlyphsData::PointData* part =
            f < before ? growing->getFrame(f) : resumed->getFrame(f - before);
        if (!sameFrame(*part, *whole.getFrame(f)))
            std::abort();
    }
}

// Maps the first frame to glyphs with the default mapping: failures are one line. Frames of many
// points are left alone: the default radius of a cluster of thousands of points takes up to its
// budget of 10 million steps, which would leave little time for the readers.
void checkMapping(const osgGlyphsData::PointDataset& dataset)
{
    if (dataset.getFrame(0)->getNumPoints() > 1000)
        return;
    std::string error;
    osgGlyphsData::GlyphMapper mapper{osgGlyphsData::GlyphMappingOptions()};
    if (mapper.prepare(dataset, 0, error))
        mapper.createCloud(*dataset.getFrame(0), error);
    if (error.find('\n') != std::string::npos)
        std::abort();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size)
{
    const char* bytes = reinterpret_cast<const char*>(data);
    std::istringstream seekable(std::string(bytes, size));
    PipeBuffer pipe(bytes, size);
    std::istream unseekable(&pipe);
    std::string error;
    osg::ref_ptr<osgGlyphsData::PointDataset> known = read(seekable, error);
    osg::ref_ptr<osgGlyphsData::PointDataset> unknown = read(unseekable, error);
    if (known.valid() != unknown.valid() || (known.valid() && !same(*known, *unknown)))
        std::abort();
    if (known.valid())
    {
        checkResumedReading(std::string(bytes, size), *known);
        checkMapping(*known);
    }
    return 0;
}
