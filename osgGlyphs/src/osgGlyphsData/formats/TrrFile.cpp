// TRR trajectories (GROMACS, MDAnalysis): XDR, so big-endian; no index. A frame:
//   magic 1993, the version "GMX_trn_file" as an XDR string (13, its length plus one; 12; the 12
//   bytes), the byte sizes of the blocks ir, e, box, vir, pres, top, sym, x, v and f, then atoms,
//   step and nre (int32 each), time and lambda (float or double: the sizes give the precision),
//   then the blocks whose sizes are not 0: box, vir and pres (3 x 3 each), x, v and f (3 per atom).
// Opening reads each frame's header, whose sizes give where the next frame starts. Frames read as
// x y z, vx vy vz, fx fy fz, kept in the file's nm, nm/ps and kJ/(mol nm), in single precision;
// the box is GROMACS's lower-triangular cell. Frames without positions are left out with a
// warning. A share reads its range of atoms from each block.

#include "BinaryFile.h"
#include "CellBox.h"
#include "FormatFrameFile.h"
#include "Formats.h"

#include <algorithm>
#include <cmath>

using namespace osgGlyphsData;
using namespace osgGlyphsData::formats;

namespace
{

const int32_t TRR_MAGIC = 1993;
const char VERSION[] = "GMX_trn_file";
/** magic, version, the ten block sizes, atoms, step and nre: then time and lambda. */
const uint64_t FIXED_HEADER_BYTES = 76;

/** The block sizes of the header, in the file's order. */
enum Block
{
    InputRecord,
    Energies,
    Box,
    Virial,
    Pressure,
    Topology,
    Symmetry,
    Positions,
    Velocities,
    Forces,
    BlockCount
};

const char* const BLOCK_NAMES[BlockCount] = {"ir", "e", "box", "vir", "pres", "top", "sym", "x", "v", "f"};

struct TrrFrame
{
    uint64_t offset = 0;
    uint64_t end = 0;
    std::size_t fileFrame = 0;
    int64_t step = 0;
    double time = 0.0;
    uint32_t atoms = 0;
    /** Bytes of a real number: 4 or 8. */
    uint32_t real = 4;
    /** Where each block starts; 0 when the frame has none. */
    uint64_t blocks[BlockCount] = {};
};

class TrrFile : public FormatFrameFile
{
public:
    explicit TrrFile(const std::string& path) : FormatFrameFile(path, "trr") {}

    void findFrames() override
    {
        if (_file.getSize() == 0)
            FilePlace{&_path}.fail(0, "not a TRR file: it is empty");
        uint64_t at = 0;
        std::size_t fileFrames = 0;
        std::size_t withoutPositions = 0;
        std::string firstWithout;
        for (; at < _file.getSize(); ++fileFrames)
        {
            const FilePlace place{&_path, fileFrames};
            TrrFrame frame;
            if (!readExtent(at, place, frame))
            {
                _warnings.push_back(place.describe(at, "the last frame is cut short (the file ends at byte " +
                                                           std::to_string(_file.getSize()) +
                                                           "); it is left out"));
                break;
            }
            frame.fileFrame = fileFrames;
            if (frame.blocks[Positions] != 0)
                _frames.push_back(frame);
            else if (withoutPositions++ == 0)
                firstWithout = place.describe(at, "");
            at = frame.end;
        }
        if (withoutPositions > 0)
            _warnings.push_back(firstWithout + std::to_string(withoutPositions) +
                                " frames without positions (velocities or forces only) are left out");
    }

    std::size_t getNumFrames() const override { return _frames.size(); }

    FrameInfo getFrameInfo(std::size_t frame) const override
    {
        FrameInfo info;
        if (frame >= _frames.size())
            return info;
        const TrrFrame& found = _frames[frame];
        info.offset = found.offset;
        info.end = found.end;
        info.timestep = found.step;
        info.points = found.atoms;
        info.fileFrame = found.fileFrame;
        info.hasTime = true;
        info.time = found.time;
        return info;
    }

private:
    /** Reads the frame's header at offset (in one read) and finds its blocks; false when the file
     * ends inside the frame. Throws when the header is not a TRR frame's or its sizes do not agree. */
    bool readExtent(uint64_t offset, const FilePlace& place, TrrFrame& frame) const
    {
        unsigned char head[FIXED_HEADER_BYTES + 16];
        const uint64_t held = std::min<uint64_t>(sizeof(head), _file.getSize() - offset);
        _file.read(offset, head, std::size_t(held), place, "the frame's header");
        if (held < 4 && offset == 0)
            place.fail(0, "not a TRR file: it is shorter than a frame's header");
        if (held < 4)
            return false;
        checkMagic(big<int32_t>(head), offset, place);
        if (held < FIXED_HEADER_BYTES)
            return false;
        checkVersion(head, offset, place);
        int32_t sizes[BlockCount];
        for (int block = 0; block < BlockCount; ++block)
            sizes[block] = big<int32_t>(head + 24 + 4 * block);
        const int32_t atoms = big<int32_t>(head + 64);
        if (atoms < 0)
            place.fail(offset + 64, "the atom count is " + std::to_string(atoms));
        frame.offset = offset;
        frame.atoms = static_cast<uint32_t>(atoms);
        frame.step = big<int32_t>(head + 68);
        frame.real = realSize(offset, sizes, frame.atoms, place);
        const uint64_t header = FIXED_HEADER_BYTES + 2 * uint64_t(frame.real);
        if (held < header)
            return false;
        frame.time =
            frame.real == 8 ? big<double>(head + FIXED_HEADER_BYTES) : big<float>(head + FIXED_HEADER_BYTES);
        uint64_t at = offset + header;
        for (int block = 0; block < BlockCount; ++block)
        {
            checkBlockSize(offset, Block(block), sizes[block], frame, place);
            if (sizes[block] != 0)
                frame.blocks[block] = at;
            at += uint64_t(sizes[block]);
        }
        if (at > _file.getSize())
            return false;
        frame.end = at;
        return true;
    }

    template <typename T>
    static T big(const unsigned char* at)
    {
        return readers::loadScalar<T>(reinterpret_cast<const char*>(at), true);
    }

    void checkMagic(int32_t magic, uint64_t offset, const FilePlace& place) const
    {
        if (magic == TRR_MAGIC)
            return;
        if (offset == 0)
            place.fail(0, "not a TRR file: it starts with " + std::to_string(magic) +
                              ", not the magic number " + std::to_string(TRR_MAGIC));
        place.fail(offset, "the magic number is " + std::to_string(magic) + ", not " +
                               std::to_string(TRR_MAGIC) + " (the frame before ends here by its sizes)");
    }

    /** The version string: its length with the terminating null, its length, its 12 bytes. */
    void checkVersion(const unsigned char* head, uint64_t offset, const FilePlace& place) const
    {
        if (big<int32_t>(head + 4) != 13 || big<int32_t>(head + 8) != 12 ||
            std::string(reinterpret_cast<const char*>(head + 12), 12) != VERSION)
            place.fail(offset + 4, std::string("the version is not \"") + VERSION + "\"");
    }

    /** The bytes of a real number, from the first block whose size gives it. */
    uint32_t realSize(uint64_t offset, const int32_t sizes[BlockCount], uint32_t atoms,
                      const FilePlace& place) const
    {
        const struct
        {
            Block block;
            uint64_t reals;
        } givers[] = {{Box, 9},
                      {Positions, 3 * uint64_t(atoms)},
                      {Velocities, 3 * uint64_t(atoms)},
                      {Forces, 3 * uint64_t(atoms)}};
        for (const auto& giver : givers)
        {
            if (sizes[giver.block] != 0 && giver.reals != 0)
            {
                const int64_t size = sizes[giver.block];
                if (size == int64_t(4 * giver.reals) || size == int64_t(8 * giver.reals))
                    return static_cast<uint32_t>(uint64_t(size) / giver.reals);
                break;
            }
        }
        place.fail(offset + 24,
                   "the block sizes give no precision: neither a box of 9 nor blocks of 3 per atom "
                   "(of " +
                       std::to_string(atoms) + ") of 4- or 8-byte numbers");
    }

    void checkBlockSize(uint64_t offset, Block block, int32_t size, const TrrFrame& frame,
                        const FilePlace& place) const
    {
        const uint64_t at = offset + 24 + 4 * uint64_t(block);
        uint64_t expected = 0;
        if (block == Box || block == Virial || block == Pressure)
            expected = 9 * uint64_t(frame.real);
        else if (block == Positions || block == Velocities || block == Forces)
            expected = 3 * uint64_t(frame.atoms) * frame.real;
        else if (size != 0)
            place.fail(at, std::string("the frame holds a block '") + BLOCK_NAMES[block] + "' (" +
                               std::to_string(size) + " bytes), which TRR files are not read with");
        if (size != 0 && uint64_t(int64_t(size)) != expected)
            place.fail(at, std::string("the block '") + BLOCK_NAMES[block] + "' announces " +
                               std::to_string(size) + " bytes, not " + std::to_string(expected));
    }

    osg::ref_ptr<PointData> decodeFrame(std::size_t frame, const PointShare& share) const override
    {
        if (frame >= _frames.size())
            FilePlace{&_path, frame}.fail(_file.getSize(), "no such frame (the file holds " +
                                                               std::to_string(_frames.size()) + ")");
        const TrrFrame& found = _frames[frame];
        const FilePlace place{&_path, found.fileFrame};
        osg::ref_ptr<PointData> data = new PointData;
        data->setAngstromsPerUnit(10.0); // nm
        if (found.blocks[Box] != 0)
            readBox(found, place, *data);
        const PointRange range = getShareRange(share, found.atoms);
        data->setNumPoints(std::size_t(range.end - range.begin));
        static const char* const columns[3][3] = {{"x", "y", "z"}, {"vx", "vy", "vz"}, {"fx", "fy", "fz"}};
        const Block blocks[3] = {Positions, Velocities, Forces};
        for (int i = 0; i < 3; ++i)
        {
            if (found.blocks[blocks[i]] != 0)
                readVectors(found, found.blocks[blocks[i]], range, place, columns[i], *data);
        }
        data->setTimestep(found.step);
        data->setFilePointCount(found.atoms);
        return data;
    }

    void readBox(const TrrFrame& frame, const FilePlace& place, PointData& data) const
    {
        unsigned char bytes[9 * 8];
        _file.read(frame.blocks[Box], bytes, 9 * frame.real, place, "the box");
        double box[9];
        for (std::size_t i = 0; i < 9; ++i)
            box[i] = frame.real == 8 ? big<double>(bytes + 8 * i) : big<float>(bytes + 4 * i);
        setCellVectors(data, osg::Vec3d(box[0], box[1], box[2]), osg::Vec3d(box[3], box[4], box[5]),
                       osg::Vec3d(box[6], box[7], box[8]));
    }

    /** Reads the range's atoms of a block of 3 reals per atom into three columns. */
    void readVectors(const TrrFrame& frame, uint64_t block, const PointRange& range, const FilePlace& place,
                     const char* const names[3], PointData& data) const
    {
        const std::size_t count = std::size_t(range.end - range.begin);
        const uint64_t at = block + 3 * range.begin * frame.real;
        std::vector<float> values(3 * count);
        if (frame.real == 8)
        {
            std::vector<double> wide(3 * count);
            _file.readValues(at, wide.data(), wide.size(), true, place, names[0]);
            for (std::size_t i = 0; i < wide.size(); ++i)
                values[i] = static_cast<float>(wide[i]);
        }
        else
            _file.readValues(at, values.data(), values.size(), true, place, names[0]);
        std::vector<float> columns[3];
        for (int axis = 0; axis < 3; ++axis)
            columns[axis].resize(count);
        for (std::size_t i = 0; i < values.size(); ++i)
        {
            if (!std::isfinite(values[i]))
                place.fail(at + i * frame.real, std::string(names[i % 3]) + " of atom " +
                                                    std::to_string(range.begin + i / 3 + 1) +
                                                    " is not a finite number");
            columns[i % 3][i / 3] = values[i];
        }
        for (int axis = 0; axis < 3; ++axis)
            data.addColumn(names[axis], std::move(columns[axis]));
    }

    std::vector<TrrFrame> _frames;
};

}

osg::ref_ptr<FrameFile> formats::openTrr(const std::string& path, const FrameFileOptions&, std::string& error)
{
    return openFormatFile<TrrFile>(path, error);
}
