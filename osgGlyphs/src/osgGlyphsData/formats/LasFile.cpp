// LAS (ASPRS LAS 1.0 to 1.4 lidar point clouds; read from the specifications 1.2, 1.3 R11 and
// 1.4 R13): a file is one point cloud, read as one frame.
//   public header (227 bytes in 1.0-1.2, 235 in 1.3, 375 in 1.4; the header size field may say
//   more): "LASF", the version, the header size, the offset to the points, the point format and
//   record length, the point count (the legacy uint32, and in 1.4 a uint64), per axis the scale
//   and offset, the bounds;
//   VLRs: skipped (but for LASzip's, which marks a compressed file);
//   the point records, all of the record length (the format's fields, then extra bytes, skipped);
//   1.3 waveform data and 1.4 extended VLRs after the points: skipped, as are the waveform packet
//   fields of formats 4, 5, 9 and 10 (pointers into that data).
// LAZ (LASzip-compressed LAS) is refused: Debian has no LASzip library.
//
// The columns, by point format (LAS field, and what the column holds):
//   all         x y z                X, Y, Z: int32 * scale + offset, offsets from a double origin
//               intensity            as stored (0-65535)
//               return_number        0-5: 3 bits; 6-10: 4 bits
//               number_of_returns    0-5: 3 bits; 6-10: 4 bits
//               scan_direction       the scan direction flag, 0 or 1
//               edge_of_flight_line  0 or 1
//               classification       the ASPRS class number (0-5: 5 bits; 6-10: 8 bits), numeric:
//                                    2 ground, 3-5 vegetation, 6 building, 7 noise, 9 water...
//               classification_flags synthetic 1, key-point 2, withheld 4, overlap 8 (6-10 only)
//               scan_angle           degrees (0-5: the int8 rank; 6-10: int16 * 0.006)
//               user_data            as stored
//               point_source_id      as stored
//   6-10        scanner_channel      0-3
//   1, 3-10     gps_time             seconds, offsets from a double origin (the first point's)
//   2,3,5,7,8,10 red green blue      as stored (0-65535)
//   8, 10       nir                  as stored (0-65535)
//
// A share reads its records alone: record n lies at offset to points + n * record length.

#include "BinaryFile.h"
#include "FormatFrameFile.h"
#include "Formats.h"

#include <algorithm>
#include <cctype>
#include <cfloat>
#include <cmath>
#include <cstring>

using namespace osgGlyphsData;
using namespace osgGlyphsData::formats;

namespace
{

/** Where the public header's fields lie (bytes from the start of the file). */
enum HeaderField : uint64_t
{
    VersionMajor = 24,
    VersionMinor = 25,
    HeaderSizeField = 94,
    OffsetToPoints = 96,
    VlrCountField = 100,
    PointFormatField = 104,
    RecordLengthField = 105,
    LegacyPointCount = 107,
    ScaleFields = 131,
    OffsetFields = 155,
    BoundFields = 179, // max x, min x, max y, min y, max z, min z
    WaveformStart = 227,
    EvlrStart = 235,
    EvlrCountField = 243,
    PointCount = 247
};

/** The header's size in each version (1.0 to 1.2 share 1.2's). */
uint64_t headerSizeOf(unsigned int minor)
{
    return minor >= 4 ? 375 : minor == 3 ? 235 : 227;
}

enum Column
{
    X,
    Y,
    Z,
    Intensity,
    ReturnNumber,
    NumberOfReturns,
    ScanDirection,
    EdgeOfFlightLine,
    Classification,
    ClassificationFlags,
    ScannerChannel,
    ScanAngle,
    UserData,
    PointSourceId,
    GpsTime,
    Red,
    Green,
    Blue,
    Nir,
    ColumnCount
};

const char* const COLUMN_NAMES[ColumnCount] = {"x",
                                               "y",
                                               "z",
                                               "intensity",
                                               "return_number",
                                               "number_of_returns",
                                               "scan_direction",
                                               "edge_of_flight_line",
                                               "classification",
                                               "classification_flags",
                                               "scanner_channel",
                                               "scan_angle",
                                               "user_data",
                                               "point_source_id",
                                               "gps_time",
                                               "red",
                                               "green",
                                               "blue",
                                               "nir"};

/** Bytes of each point format's fields. */
const uint16_t FORMAT_SIZES[11] = {20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};

/** What the point formats have besides the fields common to all. */
struct FormatFields
{
    bool extended; // formats 6-10: 4-bit returns, 8-bit class, int16 scan angle, scanner channel
    bool gps;
    bool rgb;
    bool nir;
};

FormatFields fieldsOf(unsigned int format)
{
    const bool extended = format >= 6;
    const bool gps = format != 0 && format != 2;
    const bool rgb = format == 2 || format == 3 || format == 5 || format == 7 || format == 8 || format == 10;
    return {extended, gps, rgb, format == 8 || format == 10};
}

/** X = int32 * scale + offset, stored as a float offset from origin: int32 * scale + shift. */
struct Transform
{
    double scale[3];
    double shift[3];
    double gpsOrigin;
};

template <typename T>
inline T load(const char* p)
{
    return readers::loadScalar<T>(p, false);
}

/** Decodes count records, stride bytes apart, into the columns at point index at. */
template <bool Extended, bool HasGps, bool HasRgb, bool HasNir>
void decodeRecords(const char* records, std::size_t count, std::size_t stride, const Transform& transform,
                   float* const* out, std::size_t at)
{
    // Legacy formats: GPS time at 20, colours after it; extended: GPS time at 22, colours at 30.
    constexpr std::size_t gpsAt = Extended ? 22 : 20;
    constexpr std::size_t rgbAt = Extended ? 30 : HasGps ? 28 : 20;
    for (std::size_t i = 0; i < count; ++i)
    {
        const char* r = records + i * stride;
        const std::size_t p = at + i;
        for (int axis = 0; axis < 3; ++axis)
            out[axis][p] =
                static_cast<float>(static_cast<double>(load<int32_t>(r + 4 * axis)) * transform.scale[axis] +
                                   transform.shift[axis]);
        out[Intensity][p] = load<uint16_t>(r + 12);
        const uint8_t returns = static_cast<uint8_t>(r[14]);
        if (Extended)
        {
            const uint8_t flags = static_cast<uint8_t>(r[15]);
            out[ReturnNumber][p] = returns & 15;
            out[NumberOfReturns][p] = returns >> 4;
            out[ClassificationFlags][p] = flags & 15;
            out[ScannerChannel][p] = (flags >> 4) & 3;
            out[ScanDirection][p] = (flags >> 6) & 1;
            out[EdgeOfFlightLine][p] = flags >> 7;
            out[Classification][p] = static_cast<uint8_t>(r[16]);
            out[UserData][p] = static_cast<uint8_t>(r[17]);
            out[ScanAngle][p] = static_cast<float>(load<int16_t>(r + 18) * 0.006);
            out[PointSourceId][p] = load<uint16_t>(r + 20);
        }
        else
        {
            const uint8_t classification = static_cast<uint8_t>(r[15]);
            out[ReturnNumber][p] = returns & 7;
            out[NumberOfReturns][p] = (returns >> 3) & 7;
            out[ScanDirection][p] = (returns >> 6) & 1;
            out[EdgeOfFlightLine][p] = returns >> 7;
            out[Classification][p] = classification & 31;
            out[ClassificationFlags][p] = classification >> 5;
            out[ScanAngle][p] = static_cast<int8_t>(r[16]);
            out[UserData][p] = static_cast<uint8_t>(r[17]);
            out[PointSourceId][p] = load<uint16_t>(r + 18);
        }
        if (HasGps)
            out[GpsTime][p] = static_cast<float>(load<double>(r + gpsAt) - transform.gpsOrigin);
        if (HasRgb)
        {
            out[Red][p] = load<uint16_t>(r + rgbAt);
            out[Green][p] = load<uint16_t>(r + rgbAt + 2);
            out[Blue][p] = load<uint16_t>(r + rgbAt + 4);
        }
        if (HasNir)
            out[Nir][p] = load<uint16_t>(r + 36);
    }
}

using Decoder = void (*)(const char*, std::size_t, std::size_t, const Transform&, float* const*, std::size_t);

Decoder decoderOf(const FormatFields& f)
{
    if (f.extended)
    {
        if (f.nir)
            return decodeRecords<true, true, true, true>;
        return f.rgb ? decodeRecords<true, true, true, false> : decodeRecords<true, true, false, false>;
    }
    if (f.gps)
        return f.rgb ? decodeRecords<false, true, true, false> : decodeRecords<false, true, false, false>;
    return f.rgb ? decodeRecords<false, false, true, false> : decodeRecords<false, false, false, false>;
}

bool endsWithLaz(const std::string& path)
{
    if (path.size() < 4)
        return false;
    std::string extension = path.substr(path.size() - 4);
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension == ".laz";
}

const char* const LAZ_REASON = "LAZ (LASzip-compressed LAS) cannot be read: Debian has no LASzip library; "
                               "decompress it to LAS first (laszip or pdal translate)";

/** The records decoded per read. */
constexpr std::size_t ChunkBytes = std::size_t(2) << 20;

class LasFile : public FormatFrameFile
{
public:
    explicit LasFile(const std::string& path) : FormatFrameFile(path, "las") {}

    void findFrames() override
    {
        const FilePlace place{&_path};
        char header[375] = {};
        readSignature(place);
        if (endsWithLaz(_path))
            place.fail(0, LAZ_REASON);
        _file.read(0, header, 227, place, "the public header");
        const unsigned int minor = checkVersion(header, place);
        const uint64_t headerSize = checkHeaderSize(header, minor, place);
        _file.read(0, header, static_cast<std::size_t>(headerSizeOf(minor)), place, "the public header");
        const unsigned int format = static_cast<uint8_t>(header[PointFormatField]);
        if (format & 128)
            place.fail(PointFormatField,
                       "point format " + std::to_string(format) + " has bit 7 set: " + LAZ_REASON);
        _pointsAt = readers::loadScalar<uint32_t>(header + OffsetToPoints, false);
        if (_pointsAt < headerSize || _pointsAt > _file.getSize())
            place.fail(OffsetToPoints,
                       "the offset to the point data, " + std::to_string(_pointsAt) + ", lies " +
                           (_pointsAt < headerSize
                                ? "inside the " + std::to_string(headerSize) + "-byte header"
                                : "past the end of the file at byte " + std::to_string(_file.getSize())));
        checkVlrs(readers::loadScalar<uint32_t>(header + VlrCountField, false), headerSize, place);
        checkPointFormat(header, format, minor, place);
        readPointCount(header, minor, place);
        readTransform(header, place);
    }

    std::size_t getNumFrames() const override { return 1; }

    FrameInfo getFrameInfo(std::size_t frame) const override
    {
        FrameInfo info;
        if (frame != 0)
            return info;
        info.offset = _pointsAt;
        info.end = _pointsAt + _points * _recordLength;
        info.points = _points;
        return info;
    }

private:
    void readSignature(const FilePlace& place) const
    {
        char signature[4] = {};
        _file.read(0, signature, static_cast<std::size_t>(std::min<uint64_t>(_file.getSize(), 4)), place,
                   "the signature");
        if (std::memcmp(signature, "LASF", 4) != 0)
            place.fail(0, "not a LAS file: it does not start with \"LASF\"");
    }

    static unsigned int checkVersion(const char* header, const FilePlace& place)
    {
        const unsigned int major = static_cast<uint8_t>(header[VersionMajor]);
        const unsigned int minor = static_cast<uint8_t>(header[VersionMinor]);
        if (major != 1 || minor > 4)
            place.fail(VersionMajor, "LAS version " + std::to_string(major) + "." + std::to_string(minor) +
                                         " is not read (1.0 to 1.4 are)");
        return minor;
    }

    uint64_t checkHeaderSize(const char* header, unsigned int minor, const FilePlace& place) const
    {
        const uint64_t size = readers::loadScalar<uint16_t>(header + HeaderSizeField, false);
        const uint64_t required = headerSizeOf(minor);
        if (size < required)
            place.fail(HeaderSizeField, "the header size is " + std::to_string(size) + " bytes, LAS 1." +
                                            std::to_string(minor) + " needs " + std::to_string(required));
        if (size > _file.getSize())
            place.fail(HeaderSizeField, "the header size is " + std::to_string(size) +
                                            " bytes, past the end of the file at byte " +
                                            std::to_string(_file.getSize()));
        return size;
    }

    /** Walks the VLRs between the header and the points, for LASzip's: its files are refused. */
    void checkVlrs(uint32_t count, uint64_t headerSize, const FilePlace& place)
    {
        uint64_t at = headerSize;
        for (uint32_t i = 0; i < count; ++i)
        {
            if (at > _pointsAt || _pointsAt - at < 54)
            {
                _warnings.push_back(place.describe(
                    at, "VLR " + std::to_string(i + 1) + " of " + std::to_string(count) +
                            " would run past the offset to the point data (byte " +
                            std::to_string(_pointsAt) + "); the VLR count at byte 100 is wrong"));
                return;
            }
            char vlr[22];
            _file.read(at + 2, vlr, sizeof(vlr), place, "a VLR header");
            const uint16_t recordId = readers::loadScalar<uint16_t>(vlr + 16, false);
            if (std::strncmp(vlr, "laszip encoded", 16) == 0 && recordId == 22204)
                place.fail(at, std::string("a LASzip VLR: ") + LAZ_REASON);
            at += 54 + readers::loadScalar<uint16_t>(vlr + 18, false);
        }
    }

    void checkPointFormat(const char* header, unsigned int format, unsigned int minor, const FilePlace& place)
    {
        if (format > 10)
            place.fail(PointFormatField,
                       "point format " + std::to_string(format) + " is not read (0 to 10 are)");
        _recordLength = readers::loadScalar<uint16_t>(header + RecordLengthField, false);
        if (_recordLength < FORMAT_SIZES[format])
            place.fail(RecordLengthField, "the point record length is " + std::to_string(_recordLength) +
                                              " bytes, shorter than point format " + std::to_string(format) +
                                              "'s " + std::to_string(FORMAT_SIZES[format]));
        const unsigned int needs = format >= 6 ? 4 : format >= 4 ? 3 : format >= 2 ? 2 : 0;
        if (minor < needs)
            _warnings.push_back(place.describe(
                PointFormatField, "point format " + std::to_string(format) + " belongs to LAS 1." +
                                      std::to_string(needs) + ", not 1." + std::to_string(minor) +
                                      "; read as format " + std::to_string(format)));
        _fields = fieldsOf(format);
        _decoder = decoderOf(_fields);
    }

    /** The point count (the legacy field, or 1.4's 64-bit one), checked against the bytes that the
     * file has for the points: up to its end, its 1.3 waveform data or its 1.4 extended VLRs. */
    void readPointCount(const char* header, unsigned int minor, const FilePlace& place)
    {
        const uint64_t legacy = readers::loadScalar<uint32_t>(header + LegacyPointCount, false);
        uint64_t countAt = LegacyPointCount;
        _points = legacy;
        uint64_t limit = _file.getSize();
        const char* limitName = "the end of the file";
        if (minor >= 4)
        {
            const uint64_t extended = readers::loadScalar<uint64_t>(header + PointCount, false);
            if (legacy != 0 && extended != 0 && legacy != extended)
                place.fail(PointCount, "the number of point records, " + std::to_string(extended) +
                                           ", differs from the legacy one at byte 107, " +
                                           std::to_string(legacy));
            if (extended != 0)
            {
                _points = extended;
                countAt = PointCount;
            }
            const uint64_t evlrs = readers::loadScalar<uint32_t>(header + EvlrCountField, false);
            const uint64_t evlrAt = readers::loadScalar<uint64_t>(header + EvlrStart, false);
            if (evlrs > 0 && evlrAt >= _pointsAt && evlrAt < limit)
            {
                limit = evlrAt;
                limitName = "the extended VLRs";
            }
        }
        if (minor >= 3)
        {
            const uint64_t waveform = readers::loadScalar<uint64_t>(header + WaveformStart, false);
            if (waveform > _pointsAt && waveform < limit)
            {
                limit = waveform;
                limitName = "the waveform data";
            }
        }
        const uint64_t room = (limit - _pointsAt) / _recordLength;
        if (_points > room)
            place.fail(countAt, "the header counts " + std::to_string(_points) + " point records of " +
                                    std::to_string(_recordLength) + " bytes from byte " +
                                    std::to_string(_pointsAt) + ", " + limitName + " at byte " +
                                    std::to_string(limit) + " leaves room for " + std::to_string(room));
        const uint64_t end = _pointsAt + _points * _recordLength;
        if (end < limit)
            _warnings.push_back(place.describe(end, std::to_string(limit - end) + " bytes after the " +
                                                        std::to_string(_points) +
                                                        " point records counted by the header are not read"));
    }

    /** Scales, offsets and the origins: coordinates are stored as floats from a double origin per
     * axis, the centre of the header's bounds (or the first point, when the bounds do not hold it),
     * rounded to a whole unit. A float keeps 24 bits, so within 16 km (2^14 m) of the origin at a
     * scale of 0.001 m it rounds by less than half the scale: the file's values are recovered. */
    void readTransform(const char* header, const FilePlace& place)
    {
        double first[3] = {0.0, 0.0, 0.0};
        char firstRecord[32] = {};
        if (_points > 0)
            _file.read(_pointsAt, firstRecord, _fields.gps ? (_fields.extended ? 30 : 28) : 12, place,
                       "the first point record");
        static const char* const axes[3] = {"x", "y", "z"};
        for (int axis = 0; axis < 3; ++axis)
        {
            const double scale = readers::loadScalar<double>(header + ScaleFields + 8 * axis, false);
            const double offset = readers::loadScalar<double>(header + OffsetFields + 8 * axis, false);
            if (!std::isfinite(scale) || scale == 0.0)
                place.fail(ScaleFields + 8 * axis,
                           std::string("the ") + axes[axis] + " scale factor is " + std::to_string(scale));
            if (!std::isfinite(offset))
                place.fail(OffsetFields + 8 * axis,
                           std::string("the ") + axes[axis] + " offset is " + std::to_string(offset));
            first[axis] = readers::loadScalar<int32_t>(firstRecord + 4 * axis, false) * scale + offset;
            const double origin = chooseOrigin(header, axis, first[axis], _points > 0);
            _transform.scale[axis] = scale;
            _transform.shift[axis] = offset - origin;
            _origins[axis] = origin;
            if (!(std::fabs(scale) * 2147483648.0 + std::fabs(offset - origin) < FLT_MAX))
                place.fail(ScaleFields + 8 * axis, std::string("the ") + axes[axis] + " scale factor " +
                                                       std::to_string(scale) +
                                                       " puts coordinates out of the range of a float");
        }
        _transform.gpsOrigin = 0.0;
        if (_fields.gps && _points > 0)
        {
            const double time =
                readers::loadScalar<double>(firstRecord + (_fields.extended ? 22 : 20), false);
            if (std::isfinite(time))
                _transform.gpsOrigin = std::round(time);
        }
    }

    static double chooseOrigin(const char* header, int axis, double first, bool hasPoints)
    {
        const double max = readers::loadScalar<double>(header + BoundFields + 16 * axis, false);
        const double min = readers::loadScalar<double>(header + BoundFields + 16 * axis + 8, false);
        double centre = 0.5 * (min + max);
        if (hasPoints && !(min <= first && first <= max && std::isfinite(centre)))
            centre = first;
        return std::isfinite(centre) ? std::round(centre) : 0.0;
    }

    osg::ref_ptr<PointData> decodeFrame(std::size_t frame, const PointShare& share) const override
    {
        const FilePlace place{&_path, frame};
        if (frame != 0)
            place.fail(_file.getSize(), "no such frame (a LAS file holds one)");
        const PointRange range = getShareRange(share, _points);
        const std::size_t count = static_cast<std::size_t>(range.end - range.begin);
        std::vector<float> columns[ColumnCount];
        float* out[ColumnCount] = {};
        for (int column = 0; column < ColumnCount; ++column)
        {
            if (hasColumn(column))
            {
                columns[column].resize(count);
                out[column] = columns[column].data();
            }
        }
        const std::size_t perChunk = std::max<std::size_t>(1, ChunkBytes / _recordLength);
        std::vector<char> chunk(std::min(perChunk, std::max<std::size_t>(count, 1)) * _recordLength);
        for (std::size_t done = 0; done < count;)
        {
            const std::size_t n = std::min(perChunk, count - done);
            const uint64_t at = _pointsAt + (range.begin + done) * _recordLength;
            _file.read(at, chunk.data(), n * _recordLength, place, "the point records");
            _decoder(chunk.data(), n, _recordLength, _transform, out, done);
            if (_fields.gps)
                checkTimes(out[GpsTime], done, n, range.begin, place);
            done += n;
        }
        osg::ref_ptr<PointData> data = new PointData(count);
        for (int column = 0; column < ColumnCount; ++column)
        {
            if (hasColumn(column))
                data->addColumn(COLUMN_NAMES[column], std::move(columns[column]));
        }
        for (int axis = 0; axis < 3; ++axis)
            data->setColumnOrigin(COLUMN_NAMES[axis], _origins[axis]);
        if (_fields.gps)
            data->setColumnOrigin(COLUMN_NAMES[GpsTime], _transform.gpsOrigin);
        data->setTimestep(0);
        data->setFilePointCount(_points);
        return data;
    }

    /** GPS times are doubles: a NaN, an infinity or one beyond a float's range from the origin is an
     * error naming the point. */
    void checkTimes(const float* times, std::size_t from, std::size_t n, uint64_t first,
                    const FilePlace& place) const
    {
        for (std::size_t i = from; i < from + n; ++i)
        {
            if (!std::isfinite(times[i]))
            {
                const uint64_t point = first + i;
                place.fail(_pointsAt + point * _recordLength + (_fields.extended ? 22 : 20),
                           "the GPS time of point " + std::to_string(point + 1) +
                               " is not a finite number, or too far from the first point's for a float");
            }
        }
    }

    bool hasColumn(int column) const
    {
        switch (column)
        {
        case ScannerChannel:
            return _fields.extended;
        case GpsTime:
            return _fields.gps;
        case Red:
        case Green:
        case Blue:
            return _fields.rgb;
        case Nir:
            return _fields.nir;
        default:
            return true;
        }
    }

    uint64_t _pointsAt = 0;
    uint64_t _recordLength = 0;
    uint64_t _points = 0;
    FormatFields _fields = {};
    Decoder _decoder = nullptr;
    Transform _transform = {};
    double _origins[3] = {0.0, 0.0, 0.0};
};

}

osg::ref_ptr<FrameFile> formats::openLas(const std::string& path, const FrameFileOptions&, std::string& error)
{
    return openFormatFile<LasFile>(path, error);
}
