// DCD trajectories (CHARMM, NAMD, LAMMPS, MDAnalysis): Fortran unformatted records, each framed by
// its length before and after it (4 bytes, or 8 from some compilers), in either byte order.
//   header: "CORD" and 20 int32 control words; the title lines; the atom count;
//   each frame: the unit cell (6 doubles, when control word 10 says so), then X, Y and Z
//   (float32 each, one record each), and W in the rare 4D files.
// Every frame has the same size, so frame n lies at header + n * frame size.

#include "BinaryFile.h"
#include "CellBox.h"
#include "FormatFrameFile.h"
#include "Formats.h"

#include <cmath>

using namespace osgGlyphsData;
using namespace osgGlyphsData::formats;

namespace
{

/** The control words of the header that this reader uses (CHARMM's ICNTRL, 0-based). */
enum Control
{
    FrameCount = 0,
    FirstStep = 1,
    StepsBetweenFrames = 2,
    FixedAtoms = 8,
    HasUnitCell = 10,
    FourDimensions = 11,
    CharmmVersion = 19
};

class DcdFile : public FormatFrameFile
{
public:
    explicit DcdFile(const std::string& path) : FormatFrameFile(path, "dcd") {}

    void findFrames() override
    {
        const FilePlace place{&_path};
        detectMarkers(place);
        uint64_t at = 0;
        const uint64_t controlRecord = readRecordLength(at, place, "the header record");
        if (controlRecord != 84)
            place.fail(at, "the header record holds " + std::to_string(controlRecord) + " bytes, not 84");
        char magic[4];
        _file.read(at + _marker, magic, 4, place, "the CORD signature");
        int32_t control[20];
        _file.readValues(at + _marker + 4, control, 20, _bigEndian, place, "the control words");
        at = skipRecord(at, controlRecord, place, "the header record");

        const uint64_t titleRecord = readRecordLength(at, place, "the title record");
        at = skipRecord(at, titleRecord, place, "the title record");
        const uint64_t atomRecord = readRecordLength(at, place, "the atom count record");
        if (atomRecord != 4)
            place.fail(at, "the atom count record holds " + std::to_string(atomRecord) + " bytes, not 4");
        const int32_t atoms = _file.readValue<int32_t>(at + _marker, _bigEndian, place, "the atom count");
        const uint64_t atomsAt = at + _marker;
        at = skipRecord(at, atomRecord, place, "the atom count record");

        if (atoms <= 0)
            place.fail(atomsAt, "the atom count is " + std::to_string(atoms));
        if (control[FixedAtoms] != 0)
            place.fail(_marker + 4 + 4 * FixedAtoms,
                       std::to_string(control[FixedAtoms]) +
                           " fixed atoms: DCD files with fixed atoms are not read");
        _atoms = static_cast<uint32_t>(atoms);
        _hasCell = control[HasUnitCell] != 0;
        _fourDimensions = control[FourDimensions] != 0;
        _firstStep = control[FirstStep];
        _stepsBetween = control[StepsBetweenFrames] > 0 ? control[StepsBetweenFrames] : 1;
        _headerBytes = at;
        const uint64_t coordinateRecord = 2 * _marker + 4 * uint64_t(_atoms);
        _frameBytes = (_hasCell ? 2 * _marker + 48 : 0) + (_fourDimensions ? 4 : 3) * coordinateRecord;

        const uint64_t body = _file.getSize() - _headerBytes;
        _frames = static_cast<std::size_t>(body / _frameBytes);
        if (body % _frameBytes != 0)
            _warnings.push_back(FilePlace{&_path, _frames}.describe(
                _headerBytes + _frames * _frameBytes,
                "the last frame is cut short (" + std::to_string(body % _frameBytes) + " of " +
                    std::to_string(_frameBytes) + " bytes); it is left out"));
        // Writers that append frames (NAMD, LAMMPS) may leave the count behind: the size decides.
        if (control[FrameCount] > 0 && static_cast<uint64_t>(control[FrameCount]) != _frames)
            _warnings.push_back(
                place.describe(_marker + 4, "the header counts " + std::to_string(control[FrameCount]) +
                                                " frames, the file's size holds " + std::to_string(_frames)));
    }

    std::size_t getNumFrames() const override { return _frames; }

    FrameInfo getFrameInfo(std::size_t frame) const override
    {
        FrameInfo info;
        if (frame >= _frames)
            return info;
        info.offset = _headerBytes + frame * _frameBytes;
        info.end = info.offset + _frameBytes;
        info.timestep = _firstStep + static_cast<int64_t>(frame) * _stepsBetween;
        info.points = _atoms;
        info.fileFrame = frame;
        return info;
    }

private:
    void detectMarkers(const FilePlace& place)
    {
        unsigned char head[12] = {};
        _file.read(0, head, _file.getSize() < 12 ? static_cast<std::size_t>(_file.getSize()) : 12, place,
                   "the header");
        const bool little32 = head[0] == 84 && head[1] == 0 && head[2] == 0 && head[3] == 0;
        const bool big32 = head[0] == 0 && head[1] == 0 && head[2] == 0 && head[3] == 84;
        const bool magic4 = head[4] == 'C' && head[5] == 'O' && head[6] == 'R' && head[7] == 'D';
        const bool magic8 = head[8] == 'C' && head[9] == 'O' && head[10] == 'R' && head[11] == 'D';
        if ((little32 || big32) && magic4)
        {
            _marker = 4;
            _bigEndian = big32;
        }
        else if (magic8 && (head[0] == 84 || head[7] == 84))
        {
            _marker = 8;
            _bigEndian = head[7] == 84;
        }
        else
            place.fail(0, "not a DCD file: it does not start with a record of 84 bytes holding \"CORD\"");
    }

    /** The length that the record at offset announces. */
    uint64_t readRecordLength(uint64_t offset, const FilePlace& place, const char* what) const
    {
        if (_marker == 4)
            return _file.readValue<uint32_t>(offset, _bigEndian, place, what);
        return _file.readValue<uint64_t>(offset, _bigEndian, place, what);
    }

    /** Checks the record's closing marker; returns where the next record starts. */
    uint64_t skipRecord(uint64_t offset, uint64_t length, const FilePlace& place, const char* what) const
    {
        if (!_file.holds(offset, 2 * _marker) || !_file.holds(offset + 2 * _marker, length))
            place.fail(offset, std::string(what) + " announces " + std::to_string(length) +
                                   " bytes, past the end of the file at byte " +
                                   std::to_string(_file.getSize()));
        const uint64_t end = offset + _marker + length;
        const uint64_t closing = readRecordLength(end, place, what);
        if (closing != length)
            place.fail(end, std::string(what) + " ends with the length " + std::to_string(closing) +
                                " after starting with " + std::to_string(length));
        return end + _marker;
    }

    /** Checks the markers of a record of the expected length at offset. */
    void expectRecord(uint64_t offset, uint64_t length, const FilePlace& place, const char* what) const
    {
        const uint64_t opening = readRecordLength(offset, place, what);
        if (opening != length)
            place.fail(offset, std::string(what) + " record announces " + std::to_string(opening) +
                                   " bytes, not " + std::to_string(length));
        skipRecord(offset, length, place, what);
    }

    osg::ref_ptr<PointData> decodeFrame(std::size_t frame, const PointShare& share) const override
    {
        const FilePlace place{&_path, frame};
        if (frame >= _frames)
            place.fail(_file.getSize(), "no such frame (the file holds " + std::to_string(_frames) + ")");
        const PointRange range = getShareRange(share, _atoms);
        const std::size_t count = static_cast<std::size_t>(range.end - range.begin);
        osg::ref_ptr<PointData> data = new PointData;
        uint64_t at = _headerBytes + frame * _frameBytes;
        if (_hasCell)
        {
            expectRecord(at, 48, place, "the unit cell");
            double cell[6];
            _file.readValues(at + _marker, cell, 6, _bigEndian, place, "the unit cell");
            setCell(*data, cell);
            at += 2 * _marker + 48;
        }
        const uint64_t record = 4 * uint64_t(_atoms);
        static const char* const axes[3] = {"x", "y", "z"};
        for (int axis = 0; axis < 3; ++axis)
        {
            expectRecord(at, record, place, axes[axis]);
            std::vector<float> values(count);
            _file.readValues(at + _marker + 4 * range.begin, values.data(), count, _bigEndian, place,
                             axes[axis]);
            for (std::size_t i = 0; i < count; ++i)
            {
                if (!std::isfinite(values[i]))
                    place.fail(at + _marker + 4 * (range.begin + i), std::string(axes[axis]) + " of atom " +
                                                                         std::to_string(range.begin + i + 1) +
                                                                         " is not a finite number");
            }
            data->setNumPoints(count);
            data->addColumn(axes[axis], std::move(values));
            at += 2 * _marker + record;
        }
        data->setTimestep(getFrameInfo(frame).timestep);
        data->setFilePointCount(_atoms);
        return data;
    }

    /** CHARMM's order: a, gamma, b, beta, alpha, c; angles in degrees, or (older CHARMM and LAMMPS
     * triclinic files) as their cosines. */
    static void setCell(PointData& data, const double cell[6])
    {
        double angles[3] = {cell[4], cell[3], cell[1]}; // alpha, beta, gamma
        const bool cosines =
            std::fabs(angles[0]) <= 1.0 && std::fabs(angles[1]) <= 1.0 && std::fabs(angles[2]) <= 1.0;
        if (cosines)
        {
            for (double& angle : angles)
                angle = std::acos(angle) * 180.0 / std::acos(-1.0);
        }
        setCellLengthsAngles(data, cell[0], cell[2], cell[5], angles[0], angles[1], angles[2]);
    }

    uint64_t _marker = 4;
    bool _bigEndian = false;
    uint32_t _atoms = 0;
    bool _hasCell = false;
    bool _fourDimensions = false;
    int64_t _firstStep = 0;
    int64_t _stepsBetween = 1;
    uint64_t _headerBytes = 0;
    uint64_t _frameBytes = 0;
    std::size_t _frames = 0;
};

}

osg::ref_ptr<FrameFile> formats::openDcd(const std::string& path, const FrameFileOptions&, std::string& error)
{
    return openFormatFile<DcdFile>(path, error);
}
