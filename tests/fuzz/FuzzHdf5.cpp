// libFuzzer target of the HDF5 formats (osgGlyphsHdf5). HDF5's own parser is not hardened
// against malformed bytes, so the input does not become the file's bytes: it chooses a valid HDF5
// file's STRUCTURE (tests/formats/Hdf5Layout.h writes it through HDF5's C library): which
// datasets exist (H5MD elements, their value, step and time, the box, connectivity; snapshot
// groups; named datasets), their ranks, dims (disagreeing, empty, absurd), types (floats, integers, strings,
// NaN), values, and gzip chunking. The file is opened with FrameSource as h5md or hdf5 and every
// frame decoded, whole and as shares. Nothing may crash; every failure is one line naming the
// file (and, from the reader, the dataset); a frame read twice is the same.

#include "../formats/Hdf5Layout.h"

#include <osgGlyphsData/FrameSource>
#include <osgGlyphsHdf5/Hdf5Formats>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <unistd.h>

namespace
{

const std::string& inputPath()
{
    static const std::string path = "/tmp/osgglyphs_fuzz_" + std::to_string(::getpid()) + ".h5md";
    return path;
}

void check(bool condition)
{
    if (!condition)
        std::abort();
}

/** One line about the input: from the reader, it names the dataset. */
bool isOneLineAboutTheInput(const std::string& message)
{
    if (message.empty() || message.find('\n') != std::string::npos || message.rfind(inputPath(), 0) != 0)
        return false;
    const std::string what = message.substr(inputPath().size());
    return what.find(": dataset ") != std::string::npos || what.find(" has no ") != std::string::npos ||
           what == ": no frames" || what.rfind(": neither H5MD", 0) == 0 ||
           what.rfind(": particle groups", 0) != std::string::npos ||
           what.find(" particle groups, read together") != std::string::npos ||
           what.rfind(": cannot open as HDF5", 0) == 0;
}

/** Reads the input's bytes in order; zeros past the end. */
class Bytes
{
public:
    Bytes(const uint8_t* data, std::size_t size) : _data(data), _size(size) {}
    uint8_t next() { return _at < _size ? _data[_at++] : 0; }
    bool done() const { return _at >= _size; }

private:
    const uint8_t* _data;
    std::size_t _size;
    std::size_t _at = 0;
};

const char* const Paths[] = {"/particles/all/position/value",
                             "/particles/all/position/step",
                             "/particles/all/position/time",
                             "/particles/all/position",
                             "/particles/all/id/value",
                             "/particles/all/id/step",
                             "/particles/all/species",
                             "/particles/all/velocity/value",
                             "/particles/all/velocity/step",
                             "/particles/all/box/edges",
                             "/particles/all/box/offset",
                             "/particles/all/mass",
                             "/particles/other/position/value",
                             "/particles/other/position/step",
                             "/PartType0/Coordinates",
                             "/PartType0/Masses",
                             "/PartType0/ParticleIDs",
                             "/PartType1/Coordinates",
                             "/PartType1/Velocities",
                             "/data/points",
                             "/data/column",
                             "/connectivity/bonds",
                             "/connectivity/bonds/value",
                             "/connectivity/bonds/step",
                             "/connectivity/angles"};
const std::size_t PathCount = sizeof(Paths) / sizeof(Paths[0]);

hsize_t dimFrom(uint8_t byte)
{
    if (byte == 255)
        return hsize_t(1) << 40; // absurd: announced, never written
    return byte % 9;
}

hdf5layout::Spec specFrom(Bytes& bytes)
{
    hdf5layout::Spec spec;
    const uint8_t kind = bytes.next();
    spec.kind = static_cast<hdf5layout::Kind>(kind % 6);
    spec.gzip = (kind & 0x80) != 0;
    const std::size_t rank = bytes.next() % 5;
    for (std::size_t axis = 0; axis < rank; ++axis)
        spec.dims.push_back(dimFrom(bytes.next()));
    if (spec.kind != hdf5layout::Kind::Unwritten)
    {
        hsize_t count = 1;
        for (hsize_t& dim : spec.dims)
            count *= dim == 0 ? 1 : dim;
        if (count > 4096) // values the writer would write: keep the file small
            spec.kind = hdf5layout::Kind::Unwritten;
    }
    spec.start = double(int8_t(bytes.next()));
    spec.step = double(int8_t(bytes.next())) / 4.0;
    return spec;
}

hdf5layout::Layout layoutFrom(Bytes& bytes)
{
    hdf5layout::Layout layout;
    if (bytes.next() & 1)
        layout = hdf5layout::smallH5md(1 + bytes.next() % 4, bytes.next() % 6);
    for (int entry = 0; entry < 12 && !bytes.done(); ++entry)
    {
        const uint8_t choice = bytes.next();
        const std::string path = Paths[choice % PathCount];
        if (choice & 0x80)
            layout.erase(path);
        else
            layout[path] = specFrom(bytes);
    }
    return layout;
}

osg::ref_ptr<osgGlyphsData::FrameSource> open(const std::string& format,
                                              const std::vector<std::string>& datasets,
                                              const osgGlyphsData::PointShare& share = {})
{
    osgGlyphsData::FrameSourceOptions options;
    options.format = format;
    options.datasets = datasets;
    options.indexLocation = osgGlyphsData::FrameIndexLocation::None;
    options.share = share;
    options.warning = [](const std::string& warning) { check(isOneLineAboutTheInput(warning)); };
    std::string error;
    osg::ref_ptr<osgGlyphsData::FrameSource> source =
        osgGlyphsData::FrameSource::open(inputPath(), options, error);
    if (!source)
        check(isOneLineAboutTheInput(error));
    return source;
}

bool sameFrame(const osgGlyphsData::PointData& x, const osgGlyphsData::PointData& y)
{
    if (x.getColumnNames() != y.getColumnNames() || x.getNumPoints() != y.getNumPoints())
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

}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size)
{
    osgGlyphsHdf5::registerFormats();
    Bytes bytes(data, size);
    const uint8_t mode = bytes.next();
    const hdf5layout::Layout layout = layoutFrom(bytes);
    if (!hdf5layout::writeLayout(inputPath(), layout))
        return 0;
    const std::string format = mode & 1 ? "hdf5" : "h5md";
    std::vector<std::string> datasets;
    if (mode & 2)
        datasets = {"/data/points", "/data/column"};
    osg::ref_ptr<osgGlyphsData::FrameSource> source = open(format, datasets);
    if (!source)
        return 0;
    const std::size_t frames = std::min<std::size_t>(source->getNumFrames(), 16);
    for (std::size_t frame = 0; frame < frames; ++frame)
    {
        std::string error;
        osg::ref_ptr<osgGlyphsData::PointData> first = source->readFrame(frame, error);
        if (!first)
        {
            check(isOneLineAboutTheInput(error));
            continue;
        }
        for (std::size_t c = 0; c < first->getNumColumns(); ++c)
            check(first->getColumn(c)->size() == first->getNumPoints());
        osg::ref_ptr<osgGlyphsData::PointData> again = source->readFrame(frame, error);
        check(again.valid() && sameFrame(*first, *again));
        // The shares of a frame are the frame.
        std::size_t points = 0;
        for (unsigned int index = 0; index < 2; ++index)
        {
            osg::ref_ptr<osgGlyphsData::FrameSource> half = open(format, datasets, {index, 2});
            osg::ref_ptr<osgGlyphsData::PointData> part = half ? half->readFrame(frame, error) : nullptr;
            check(part.valid());
            points += part->getNumPoints();
        }
        check(points == first->getNumPoints());
    }
    return 0;
}
