// libFuzzer target: feeds arbitrary bytes through readPointStream in one format (OSGGLYPHS_FUZZ_FORMAT),
// once from a seekable stream (size known) and once from one that cannot seek (size unknown).
// Each read either succeeds with consistent frames or fails with exactly one error line naming the
// input, and both reads agree on success and on the data.

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

osg::ref_ptr<osgGlyphsData::PointDataset> read(std::istream& stream, std::string& error)
{
    osg::ref_ptr<osgGlyphsData::PointDataset> dataset = osgGlyphsData::readPointStream(
        stream, OSGGLYPHS_FUZZ_FORMAT, "fuzz", osgGlyphsData::PointReadOptions(), error);
    if (!dataset.valid())
    {
        if (error.empty() || error.find('\n') != std::string::npos || error.compare(0, 4, "fuzz") != 0)
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

bool same(const osgGlyphsData::PointDataset& a, const osgGlyphsData::PointDataset& b)
{
    if (a.getNumFrames() != b.getNumFrames())
        return false;
    for (std::size_t f = 0; f < a.getNumFrames(); ++f)
    {
        const osgGlyphsData::PointData& x = *a.getFrame(f);
        const osgGlyphsData::PointData& y = *b.getFrame(f);
        if (x.getColumnNames() != y.getColumnNames() || x.getNumPoints() != y.getNumPoints())
            return false;
        for (std::size_t c = 0; c < x.getNumColumns(); ++c)
        {
            if (*x.getColumn(c) != *y.getColumn(c))
                return false;
        }
    }
    return true;
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
    return 0;
}
