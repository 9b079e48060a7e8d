/* osgGlyphs - private: finds the frames of a multi-frame text file in one pass, without parsing rows. */

#ifndef OSGGLYPHS_FRAMES_FRAMESCANNER_H
#define OSGGLYPHS_FRAMES_FRAMESCANNER_H 1

#include <osgGlyphsData/FrameSource>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

namespace osgGlyphsData
{
namespace frames
{

/** Where a scan stands between two frames: it can resume there. */
struct ScanPosition
{
    uint64_t offset = 0;
    uint64_t line = 0;      // lines before offset
    uint64_t fileFrame = 0; // frames before offset, without points included
};

/** Scans the bytes of a LAMMPS dump or an XYZ file for its frames: the header lines of each are
 * read (timestep, count, time), its rows only counted, checking that a LAMMPS row is not an
 * "ITEM:" line (a frame cut short by the next one). Bytes are fed in blocks of any size.
 *
 * A frame is reported once its last row has its line end; frames without points are counted
 * but not reported. What is not a frame (garbage between frames, a frame cut short) is a
 * warning naming the file and line; the scan resumes at the next frame. */
class FrameScanner
{
public:
    typedef std::function<void(const FrameInfo& frame)> FrameHandler;
    typedef std::function<void(const std::string& warning)> WarningHandler;

    static bool supportsFormat(const std::string& format) { return format == "lammps" || format == "xyz"; }

    FrameScanner(const std::string& format, const std::string& name, const ScanPosition& start,
                 const FrameHandler& onFrame, const WarningHandler& onWarning);

    /** Scans the next bytes of the file. */
    void feed(const char* data, std::size_t size);

    /** The end of the bytes fed: a last frame not complete is a warning unless growing. */
    void finish(bool growing);

    /** The end of the last complete frame (where a later scan of a grown file resumes). */
    const ScanPosition& getEndOfFrames() const { return _endOfFrames; }

    /** The offset of the next byte to feed. */
    uint64_t getOffset() const { return _offset; }

private:
    enum class State
    {
        BetweenFrames, // blank lines, then a frame's first line
        Header,        // LAMMPS items before ITEM: ATOMS
        Comment,       // XYZ: the comment line after the count
        Rows,
        Garbage // lines after a frame that start none, until one does
    };

    void scanLine(std::string_view line, uint64_t lineOffset, uint64_t nextOffset);
    void startFrame(std::string_view text, uint64_t lineOffset);
    bool startsFrame(std::string_view text) const;
    void headerLine(std::string_view text);
    void endFrame(uint64_t nextOffset);
    void beginGarbage(std::string_view text, const std::string& what);
    void warn(uint64_t line, const std::string& what);

    bool _lammps;
    std::string _name;
    FrameHandler _onFrame;
    WarningHandler _onWarning;
    State _state = State::BetweenFrames;
    std::string _carry; // a line that the last block cut
    uint64_t _carryOffset = 0;
    uint64_t _offset;
    uint64_t _line;
    uint64_t _fileFrame;
    ScanPosition _endOfFrames;
    FrameInfo _frame;
    std::string _pendingItem; // the LAMMPS item whose value line comes next
    bool _hasCount = false;
    uint64_t _rowsLeft = 0;
    uint64_t _garbageLine = 0;
    uint64_t _garbageLines = 0;
    std::string _garbageWhat;
    uint64_t _emptyFrames = 0;
};

}
}

#endif
