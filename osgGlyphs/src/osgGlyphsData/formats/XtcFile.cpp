// XTC trajectories (GROMACS, MDAnalysis, LAMMPS' dump xtc): XDR, so big-endian; no index. A frame:
//   magic 1995 (or 2023, whose byte count below takes 8 bytes), atoms, step (int32 each), time
//   (float, ps), the box (3 x 3 floats: the cell's vectors a, b, c as rows, nm), atoms again;
//   then up to 9 atoms' positions as floats, or more atoms compressed (XtcCoordinates.h): the
//   precision, the integers' minimum and maximum (3 int32 each), the index of the size of small
//   differences, the byte count and the bytes, padded to a multiple of 4.
// Opening reads each frame's header and skips its bytes, so that any frame is then read directly.
// Positions stay in nm and times in ps, as stored. The box is GROMACS's lower-triangular cell. The
// compression runs through the whole frame, so a share decodes all of it and keeps its range.

#include "BinaryFile.h"
#include "CellBox.h"
#include "FormatFrameFile.h"
#include "Formats.h"
#include "XtcCoordinates.h"

#include <algorithm>
#include <cmath>

using namespace osgGlyphsData;
using namespace osgGlyphsData::formats;

namespace
{

const int32_t XTC_MAGIC = 1995;
/** GROMACS 2023's magic for frames whose byte count needs 64 bits; the frames are otherwise the same. */
const int32_t XTC_MAGIC_WIDE = 2023;
/** magic, atoms, step, time, box, atoms again. */
const uint64_t HEADER_BYTES = 56;
/** precision, minimum, maximum and the size index, before the byte count. */
const uint64_t COMPRESSED_HEADER_BYTES = 32;
/** Up to this many atoms are stored as floats. */
const uint32_t UNCOMPRESSED_ATOMS = 9;
/** The most compressed bytes a thread keeps for its next frame. */
const std::size_t KEPT_BYTES = std::size_t(64) << 20;

struct XtcFrame
{
    uint64_t offset = 0;
    uint64_t end = 0;
    int64_t step = 0;
    float time = 0.0f;
    uint32_t atoms = 0;
    bool wideCount = false;
};

/** A lower-triangular GROMACS box, its rows the cell's vectors, as the frame's box. */
void setGromacsBox(PointData& data, const float box[9])
{
    setCellVectors(data, osg::Vec3d(box[0], box[1], box[2]), osg::Vec3d(box[3], box[4], box[5]),
                   osg::Vec3d(box[6], box[7], box[8]));
}

class XtcFile : public FormatFrameFile
{
public:
    explicit XtcFile(const std::string& path) : FormatFrameFile(path, "xtc") {}

    void findFrames() override
    {
        if (_file.getSize() == 0)
            FilePlace{&_path}.fail(0, "not an XTC file: it is empty");
        uint64_t at = 0;
        while (at < _file.getSize())
        {
            const FilePlace place{&_path, _frames.size()};
            XtcFrame frame;
            if (!readExtent(at, place, frame))
            {
                _warnings.push_back(place.describe(at, "the last frame is cut short (the file ends at byte " +
                                                           std::to_string(_file.getSize()) +
                                                           "); it is left out"));
                break;
            }
            _frames.push_back(frame);
            at = frame.end;
        }
    }

    std::size_t getNumFrames() const override { return _frames.size(); }

    FrameInfo getFrameInfo(std::size_t frame) const override
    {
        FrameInfo info;
        if (frame >= _frames.size())
            return info;
        const XtcFrame& found = _frames[frame];
        info.offset = found.offset;
        info.end = found.end;
        info.timestep = found.step;
        info.points = found.atoms;
        info.fileFrame = frame;
        info.hasTime = true;
        info.time = found.time;
        return info;
    }

private:
    int32_t readInt(uint64_t at, const FilePlace& place, const char* what) const
    {
        return _file.readValue<int32_t>(at, true, place, what);
    }

    /** Reads the frame's header at offset (in one read) and finds where the frame ends; false
     * when the file ends inside the frame. Throws when the header is not an XTC frame's or its
     * counts do not agree. */
    bool readExtent(uint64_t offset, const FilePlace& place, XtcFrame& frame) const
    {
        unsigned char head[HEADER_BYTES + COMPRESSED_HEADER_BYTES + 8];
        const uint64_t held = std::min<uint64_t>(sizeof(head), _file.getSize() - offset);
        _file.read(offset, head, std::size_t(held), place, "the frame's header");
        if (held < 4 && offset == 0)
            place.fail(0, "not an XTC file: it is shorter than a frame's header");
        if (held < 4)
            return false;
        frame.wideCount = checkMagic(big<int32_t>(head), offset, place);
        if (held < HEADER_BYTES)
            return false;
        frame.offset = offset;
        frame.atoms = checkAtoms(big<int32_t>(head + 4), big<int32_t>(head + 52), offset, place);
        frame.step = big<int32_t>(head + 8);
        frame.time = big<float>(head + 12);
        uint64_t end = offset + HEADER_BYTES + 12 * uint64_t(frame.atoms);
        if (frame.atoms > UNCOMPRESSED_ATOMS)
        {
            const uint64_t countAt = HEADER_BYTES + COMPRESSED_HEADER_BYTES;
            const uint64_t countBytes = frame.wideCount ? 8 : 4;
            if (held < countAt + countBytes)
                return false;
            const int64_t count =
                frame.wideCount ? big<int64_t>(head + countAt) : big<int32_t>(head + countAt);
            end = offset + countAt + countBytes +
                  (checkByteCount(count, frame, offset + countAt, place) + 3) / 4 * 4;
        }
        if (end > _file.getSize())
            return false;
        frame.end = end;
        return true;
    }

    template <typename T>
    static T big(const unsigned char* at)
    {
        return readers::loadScalar<T>(reinterpret_cast<const char*>(at), true);
    }

    /** Whether the frame's byte count takes 8 bytes (magic 2023). */
    bool checkMagic(int32_t magic, uint64_t offset, const FilePlace& place) const
    {
        if (magic == XTC_MAGIC || magic == XTC_MAGIC_WIDE)
            return magic == XTC_MAGIC_WIDE;
        if (offset == 0)
            place.fail(0, "not an XTC file: it starts with " + std::to_string(magic) +
                              ", not the magic number " + std::to_string(XTC_MAGIC));
        place.fail(offset, "the magic number is " + std::to_string(magic) + ", not " +
                               std::to_string(XTC_MAGIC) + " (the frame before ends here by its byte count)");
    }

    /** The frame's atom count, which the header gives and the coordinates repeat. */
    uint32_t checkAtoms(int32_t atoms, int32_t again, uint64_t offset, const FilePlace& place) const
    {
        if (atoms < 0)
            place.fail(offset + 4, "the atom count is " + std::to_string(atoms));
        if (again != atoms)
            place.fail(offset + 52, "the atom count before the coordinates is " + std::to_string(again) +
                                        ", the frame's header says " + std::to_string(atoms));
        return static_cast<uint32_t>(atoms);
    }

    uint64_t checkByteCount(int64_t count, const XtcFrame& frame, uint64_t at, const FilePlace& place) const
    {
        // Each atom takes at least 2 bits (its integers when they cannot differ, and the run flag).
        if (count < 0 || uint64_t(count) > maxXtcCompressedBytes(frame.atoms) ||
            uint64_t(count) < frame.atoms / 4)
            place.fail(at, "the compressed coordinates' byte count is " + std::to_string(count) + ", which " +
                               std::to_string(frame.atoms) + " atoms cannot take");
        return static_cast<uint64_t>(count);
    }

    osg::ref_ptr<PointData> decodeFrame(std::size_t frame, const PointShare& share) const override
    {
        const FilePlace place{&_path, frame};
        if (frame >= _frames.size())
            place.fail(_file.getSize(),
                       "no such frame (the file holds " + std::to_string(_frames.size()) + ")");
        const XtcFrame& found = _frames[frame];
        osg::ref_ptr<PointData> data = new PointData;
        data->setAngstromsPerUnit(10.0); // nm
        float box[9];
        _file.readValues(found.offset + 16, box, 9, true, place, "the box");
        setGromacsBox(*data, box);

        std::vector<float> columns[3];
        for (std::vector<float>& column : columns)
            column.resize(found.atoms);
        const uint64_t coordinates = found.offset + HEADER_BYTES;
        if (found.atoms <= UNCOMPRESSED_ATOMS)
            readUncompressed(coordinates, found.atoms, place, columns);
        else
            readCompressed(coordinates, found, place, columns);

        const PointRange range = getShareRange(share, found.atoms);
        static const char* const axes[3] = {"x", "y", "z"};
        data->setNumPoints(std::size_t(range.end - range.begin));
        for (int axis = 0; axis < 3; ++axis)
        {
            std::vector<float>& values = columns[axis];
            if (range.end - range.begin != values.size())
                values = std::vector<float>(values.begin() + std::ptrdiff_t(range.begin),
                                            values.begin() + std::ptrdiff_t(range.end));
            data->addColumn(axes[axis], std::move(values));
        }
        data->setTimestep(found.step);
        data->setFilePointCount(found.atoms);
        return data;
    }

    void readUncompressed(uint64_t at, uint32_t atoms, const FilePlace& place,
                          std::vector<float> columns[3]) const
    {
        float values[3 * UNCOMPRESSED_ATOMS];
        _file.readValues(at, values, 3 * std::size_t(atoms), true, place, "the positions");
        static const char* const axes[3] = {"x", "y", "z"};
        for (uint32_t atom = 0; atom < atoms; ++atom)
        {
            for (int axis = 0; axis < 3; ++axis)
            {
                const float value = values[3 * atom + uint32_t(axis)];
                if (!std::isfinite(value))
                    place.fail(at + 4 * (3 * atom + uint32_t(axis)), std::string(axes[axis]) + " of atom " +
                                                                         std::to_string(atom + 1) +
                                                                         " is not a finite number");
                columns[axis][atom] = value;
            }
        }
    }

    void readCompressed(uint64_t at, const XtcFrame& frame, const FilePlace& place,
                        std::vector<float> columns[3]) const
    {
        XtcCompressed header;
        header.precision = _file.readValue<float>(at, true, place, "the precision");
        _file.readValues(at + 4, header.minimum, 3, true, place, "the minimum");
        _file.readValues(at + 16, header.maximum, 3, true, place, "the maximum");
        header.smallIndex = readInt(at + 28, place, "the size index");
        const std::string wrong = checkXtcCompressed(header);
        if (!wrong.empty())
            place.fail(at, wrong);
        const uint64_t countAt = at + COMPRESSED_HEADER_BYTES;
        const int64_t stored = frame.wideCount
                                   ? _file.readValue<int64_t>(countAt, true, place, "the byte count")
                                   : readInt(countAt, place, "the byte count");
        const uint64_t count = checkByteCount(stored, frame, countAt, place);
        const uint64_t bytesAt = countAt + (frame.wideCount ? 8 : 4);
        // Each thread keeps the buffer from frame to frame (fresh memory costs about as much as
        // decoding), up to KEPT_BYTES.
        thread_local std::vector<unsigned char> bytes;
        bytes.resize(static_cast<std::size_t>(count));
        _file.read(bytesAt, bytes.data(), bytes.size(), place, "the compressed coordinates");
        float* const out[3] = {columns[0].data(), columns[1].data(), columns[2].data()};
        std::size_t byte = 0;
        const std::string error =
            decodeXtcCoordinates(header, bytes.data(), bytes.size(), frame.atoms, out, byte);
        if (bytes.capacity() > KEPT_BYTES)
            std::vector<unsigned char>().swap(bytes);
        if (!error.empty())
            place.fail(bytesAt + byte, error);
    }

    std::vector<XtcFrame> _frames;
};

}

osg::ref_ptr<FrameFile> formats::openXtc(const std::string& path, const FrameFileOptions&, std::string& error)
{
    return openFormatFile<XtcFile>(path, error);
}
