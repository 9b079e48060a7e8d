#include "FrameScanner.h"

#include "../readers/Fields.h"

#include <cstring>

using namespace osgGlyphsData;
using namespace osgGlyphsData::frames;
using namespace osgGlyphsData::readers;

namespace
{

std::string_view withoutLineEnd(std::string_view line)
{
    return !line.empty() && line.back() == '\r' ? line.substr(0, line.size() - 1) : line;
}

bool isItem(std::string_view text)
{
    return startsWith(text, "ITEM:");
}

// A row that starts an item: the LAMMPS frame it belongs to was cut short by the next one.
bool rowIsItem(const char* begin, const char* end)
{
    while (begin < end && isBlank(*begin))
        ++begin;
    return end - begin >= 5 && std::memcmp(begin, "ITEM:", 5) == 0;
}

}

FrameScanner::FrameScanner(const std::string& format, const std::string& name, const ScanPosition& start,
                           const FrameHandler& onFrame, const WarningHandler& onWarning)
    : _lammps(format == "lammps"), _name(name), _onFrame(onFrame), _onWarning(onWarning),
      _offset(start.offset), _line(start.line), _fileFrame(start.fileFrame), _endOfFrames(start)
{
}

void FrameScanner::feed(const char* data, std::size_t size)
{
    const char* p = data;
    const char* const end = data + size;
    while (p < end)
    {
        // The rows of a frame, counted without parsing: the one loop that sees most bytes.
        if (_state == State::Rows && _carry.empty())
        {
            while (_rowsLeft > 0 && p < end)
            {
                const char* newline = static_cast<const char*>(std::memchr(p, '\n', end - p));
                if (!newline || (_lammps && rowIsItem(p, newline)))
                    break; // a line the next block ends, or an item that scanLine() reports
                ++_line;
                --_rowsLeft;
                _offset += newline + 1 - p;
                p = newline + 1;
            }
            if (_rowsLeft == 0)
            {
                endFrame(_offset);
                continue;
            }
            if (p >= end)
                break;
        }
        const char* newline = static_cast<const char*>(std::memchr(p, '\n', end - p));
        if (!newline)
        {
            if (_carry.empty())
                _carryOffset = _offset;
            _carry.append(p, end);
            _offset += end - p;
            break;
        }
        const uint64_t lineOffset = _carry.empty() ? _offset : _carryOffset;
        _offset += newline + 1 - p;
        ++_line;
        if (_carry.empty())
        {
            scanLine(std::string_view(p, newline - p), lineOffset, _offset);
        }
        else
        {
            _carry.append(p, newline);
            const std::string line = std::move(_carry);
            _carry.clear();
            scanLine(line, lineOffset, _offset);
        }
        _carryOffset = _offset;
        p = newline + 1;
    }
}

void FrameScanner::scanLine(std::string_view line, uint64_t lineOffset, uint64_t nextOffset)
{
    const std::string_view text = trim(withoutLineEnd(line));
    switch (_state)
    {
    case State::BetweenFrames:
        if (text.empty())
            return;
        if (startsFrame(text))
            startFrame(text, lineOffset);
        else
            beginGarbage(text, "after frame " + std::to_string(_fileFrame));
        return;
    case State::Garbage:
        if (!text.empty() && startsFrame(text))
        {
            warn(_garbageLine, std::to_string(_garbageLines) +
                                   (_garbageLines == 1 ? " line that belongs" : " lines that belong") +
                                   " to no frame, " + _garbageWhat + ", left out");
            startFrame(text, lineOffset);
        }
        else
            ++_garbageLines;
        return;
    case State::Header:
        headerLine(text);
        if (_state == State::Rows && _rowsLeft == 0)
            endFrame(nextOffset);
        return;
    case State::Comment:
        _state = State::Rows;
        if (_rowsLeft == 0)
            endFrame(nextOffset);
        return;
    case State::Rows:
        if (_lammps && isItem(text))
        {
            if (_hasCount)
                warn(_frame.line + 1, "frame " + std::to_string(_fileFrame + 1) + " has " +
                                          std::to_string(_frame.points - _rowsLeft) + " of its " +
                                          std::to_string(_frame.points) +
                                          " rows: the next frame starts at line " + std::to_string(_line));
            // The frame stays in the index, so that reading it names what is wrong.
            _frame.end = lineOffset;
            _onFrame(_frame);
            ++_fileFrame;
            _endOfFrames = {lineOffset, _line - 1, _fileFrame};
            startFrame(text, lineOffset);
            return;
        }
        if (--_rowsLeft == 0)
            endFrame(nextOffset);
        return;
    }
}

bool FrameScanner::startsFrame(std::string_view text) const
{
    uint64_t count = 0;
    return _lammps ? isItem(text) : parseUInt64(text, count);
}

void FrameScanner::startFrame(std::string_view text, uint64_t lineOffset)
{
    _frame = FrameInfo();
    _frame.offset = lineOffset;
    _frame.line = _line - 1;
    _frame.fileFrame = _fileFrame;
    _frame.timestep = static_cast<int64_t>(_fileFrame);
    _hasCount = false;
    _pendingItem.clear();
    if (_lammps)
    {
        _state = State::Header;
        headerLine(text);
        return;
    }
    parseUInt64(text, _frame.points);
    _hasCount = true;
    _rowsLeft = _frame.points;
    _state = State::Comment;
}

void FrameScanner::headerLine(std::string_view text)
{
    if (!isItem(text))
    {
        const std::string item = std::move(_pendingItem);
        _pendingItem.clear();
        if (item == "TIMESTEP")
            parseInt64(text, _frame.timestep);
        else if (item == "NUMBER OF ATOMS")
            _hasCount = parseUInt64(text, _frame.points);
        else if (item == "TIME")
            _frame.hasTime = parseDouble(text, _frame.time);
        return; // box bounds and values the reader checks
    }
    const std::string_view item = trim(text.substr(5));
    if (item == "ATOMS" || startsWith(item, "ATOMS "))
    {
        // Without a count the reader fails on the frame; its rows end at the next item.
        _rowsLeft = _hasCount ? _frame.points : UINT64_MAX;
        _state = State::Rows;
        return;
    }
    _pendingItem = std::string(item);
}

void FrameScanner::endFrame(uint64_t nextOffset)
{
    _frame.end = nextOffset;
    ++_fileFrame;
    _endOfFrames = {nextOffset, _line, _fileFrame};
    _state = State::BetweenFrames;
    if (_frame.points > 0)
        _onFrame(_frame);
    else
        ++_emptyFrames;
}

void FrameScanner::beginGarbage(std::string_view text, const std::string& what)
{
    _state = State::Garbage;
    _garbageLine = _line;
    _garbageLines = 1;
    _garbageWhat = what + " (" + quote(text) + ")";
}

void FrameScanner::warn(uint64_t line, const std::string& what)
{
    if (_onWarning)
        _onWarning(_name + ":" + std::to_string(line) + ": " + what);
}

void FrameScanner::finish(bool growing)
{
    if (_state == State::Garbage)
        warn(_garbageLine, std::to_string(_garbageLines) +
                               (_garbageLines == 1 ? " line that belongs" : " lines that belong") +
                               " to no frame, " + _garbageWhat + ", left out");
    const bool inFrame = _state == State::Header || _state == State::Comment || _state == State::Rows;
    if (inFrame && !growing)
        warn(_frame.line + 1,
             "frame " + std::to_string(_fileFrame + 1) + " is cut short by the end of the file and left out");
    if (_emptyFrames > 0)
        warn(_endOfFrames.line, std::to_string(_emptyFrames) + " frame" + (_emptyFrames == 1 ? "" : "s") +
                                    " without points left out");
    _emptyFrames = 0;
}
