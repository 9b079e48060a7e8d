#include "TextLines.h"

#include "../readers/Fields.h"

#include <osgGlyphsData/Elements>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

using namespace osgGlyphsData;
using namespace osgGlyphsData::formats;
using readers::quote;

std::string TextPlace::describe(uint64_t line, const std::string& what) const
{
    std::string text = (path ? *path : std::string("file")) + ":" + std::to_string(line) + ": ";
    if (frame != SIZE_MAX)
        text += "frame " + std::to_string(frame) + ": ";
    return text + what;
}

void TextPlace::fail(uint64_t line, const std::string& what) const
{
    throw FormatError{describe(line, what)};
}

TextLines::TextLines(const BinaryFile& file, const TextPlace& place, uint64_t begin, uint64_t end,
                     uint64_t linesBefore)
    : _file(file), _place(place), _end(std::min(end, file.getSize())), _bufferOffset(begin),
      _lineNumber(linesBefore), _lineOffset(begin)
{
}

bool TextLines::fill()
{
    const uint64_t next = _bufferOffset + _filled;
    if (next >= _end)
        return false;
    // Keep the line begun, drop what was read before it.
    if (_begin > 0)
    {
        std::memmove(_buffer.data(), _buffer.data() + _begin, _filled - _begin);
        _filled -= _begin;
        _bufferOffset += _begin;
        _begin = 0;
    }
    if (_filled > MaxLineLength)
        _place.fail(_lineNumber + 1,
                    "a line longer than " + std::to_string(MaxLineLength) + " bytes: not a text file");
    const std::size_t bytes = static_cast<std::size_t>(std::min<uint64_t>(BlockSize, _end - next));
    _buffer.resize(_filled + bytes);
    FilePlace place{_place.path, _place.frame};
    _file.read(next, _buffer.data() + _filled, bytes, place, "the text");
    _filled += bytes;
    return true;
}

const char* TextLines::findLineEnd(std::size_t from) const
{
    if (from >= _filled)
        return nullptr;
    return static_cast<const char*>(std::memchr(_buffer.data() + from, '\n', _filled - from));
}

bool TextLines::next(std::string_view& line)
{
    std::size_t searched = _begin;
    for (;;)
    {
        const char* found = findLineEnd(searched);
        const std::size_t searchedBytes = _filled - _begin;
        if (found || !fill())
        {
            if (!found && _begin == _filled)
                return false;
            const std::size_t stop = found ? static_cast<std::size_t>(found - _buffer.data()) : _filled;
            std::size_t length = stop - _begin;
            if (length > 0 && _buffer[_begin + length - 1] == '\r')
                --length;
            line = std::string_view(_buffer.data() + _begin, length);
            _lineOffset = _bufferOffset + _begin;
            ++_lineNumber;
            _begin = found ? stop + 1 : stop;
            return true;
        }
        // fill() moved the line begun to the front of the buffer.
        searched = _begin + searchedBytes;
    }
}

uint64_t TextLines::skip(uint64_t count)
{
    uint64_t skipped = 0;
    uint64_t lineStart = getOffset();
    while (skipped < count)
    {
        if (const char* found = findLineEnd(_begin))
        {
            _lineOffset = lineStart;
            _begin = static_cast<std::size_t>(found - _buffer.data()) + 1;
            lineStart = getOffset();
            ++_lineNumber;
            ++skipped;
            continue;
        }
        // The rest of the buffer is the start of a line, not needed.
        _bufferOffset += _filled;
        _begin = _filled = 0;
        _buffer.clear();
        if (!fill())
        {
            if (lineStart < getOffset()) // a last line without its end
            {
                _lineOffset = lineStart;
                ++_lineNumber;
                ++skipped;
            }
            return skipped;
        }
    }
    return skipped;
}

std::string_view formats::columns(std::string_view line, std::size_t first, std::size_t last)
{
    if (first > line.size())
        return std::string_view();
    return readers::trim(line.substr(first - 1, last - first + 1));
}

namespace
{

std::string describeColumns(std::size_t first, std::size_t last, const char* what)
{
    return "columns " + std::to_string(first) + "-" + std::to_string(last) + " (" + what + "): ";
}

/** The value of a hybrid-36 digit (0-9 then the letters of one case), or -1. */
int hybridDigit(char c, bool upper)
{
    if (c >= '0' && c <= '9')
        return c - '0';
    if (upper && c >= 'A' && c <= 'Z')
        return c - 'A' + 10;
    if (!upper && c >= 'a' && c <= 'z')
        return c - 'a' + 10;
    return -1;
}

/** Hybrid-36 of width digits: decimal up to 10^width - 1, then A000.. in base 36 (upper case) from
 * 10^width, then a000.. (lower case) after those. */
bool parseHybrid36(std::string_view field, std::size_t width, int64_t& value)
{
    if (field.size() != width || field.empty())
        return false;
    const char first = field[0];
    const bool upper = first >= 'A' && first <= 'Z';
    if (!upper && !(first >= 'a' && first <= 'z'))
        return false;
    int64_t number = 0, power = 1, decimal = 1;
    for (char c : field)
    {
        const int digit = hybridDigit(c, upper);
        if (digit < 0)
            return false;
        number = number * 36 + digit;
    }
    for (std::size_t i = 1; i < width; ++i)
        power *= 36;
    for (std::size_t i = 0; i < width; ++i)
        decimal *= 10;
    // The upper case range starts at A000..: 10 * 36^(width-1) stands for 10^width.
    value = upper ? number - 10 * power + decimal : number + 16 * power + decimal;
    return true;
}

}

double formats::parseFixedNumber(const TextLines& lines, std::string_view field, std::size_t first,
                                 std::size_t last, const char* what)
{
    double value = 0.0;
    if (!readers::parseDouble(field, value))
        lines.fail(describeColumns(first, last, what) + (field.empty()
                                                             ? std::string("blank, expected a number")
                                                             : quote(field) + " is not a number"));
    if (!std::isfinite(value))
        lines.fail(describeColumns(first, last, what) + quote(field) + " is not a finite number");
    if (std::abs(value) > std::numeric_limits<float>::max())
        lines.fail(describeColumns(first, last, what) + quote(field) + " is out of the range of a float");
    return value;
}

int64_t formats::parseFixedInteger(const TextLines& lines, std::string_view field, std::size_t first,
                                   std::size_t last, const char* what)
{
    int64_t value = 0;
    if (!readers::parseInt64(field, value) && !parseHybrid36(field, last - first + 1, value))
        lines.fail(describeColumns(first, last, what) + (field.empty()
                                                             ? std::string("blank, expected an integer")
                                                             : quote(field) + " is not an integer"));
    return value;
}

void LabelColumn::append(std::string_view label)
{
    auto found = _indices.find(label);
    if (found == _indices.end())
    {
        found = _indices.emplace(std::string(label), static_cast<float>(_labels.size())).first;
        _labels.emplace_back(label);
    }
    _values.push_back(found->second);
}

void LabelColumn::addTo(PointData& frame, const std::string& name)
{
    frame.addColumn(name, std::move(_values));
    frame.setColumnLabels(name, std::move(_labels));
}

namespace
{

bool isLetter(char c)
{
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
}

bool isLower(char c)
{
    return c >= 'a' && c <= 'z';
}

unsigned int elementOf(std::string_view symbol)
{
    const Element* element = findElement(std::string(symbol));
    return element ? element->number : 0;
}

}

unsigned int formats::guessElement(std::string_view element, std::string_view name, bool pdbField,
                                   std::string_view residue)
{
    if (!readers::trim(element).empty())
        return elementOf(readers::trim(element));
    std::size_t start = 0;
    while (start < name.size() && !isLetter(name[start]))
        ++start;
    std::size_t letters = 0;
    while (start + letters < name.size() && isLetter(name[start + letters]))
        ++letters;
    if (letters == 0)
        return 0;
    const std::string_view one = name.substr(start, 1);
    const std::string_view two = name.substr(start, std::min<std::size_t>(letters, 2));
    if (two.size() == 2 && isLower(two[1]) && elementOf(two))
        return elementOf(two);
    if (pdbField && start == 0)
    {
        // A name starting in column 13: a two-letter element, or a 4-character name (hydrogens).
        if (readers::trim(name).size() == 4 && (name[0] == 'H' || name[0] == 'h'))
            return 1;
        if (two.size() == 2 && elementOf(two))
            return elementOf(two);
        return elementOf(one);
    }
    const bool ion =
        !residue.empty() && readers::equalsIgnoreCase(readers::trim(name), readers::trim(residue));
    if (ion && two.size() == 2 && elementOf(two))
        return elementOf(two);
    if (elementOf(one))
        return elementOf(one);
    return two.size() == 2 ? elementOf(two) : 0;
}

void ElementColumns::reserve(std::size_t count)
{
    _elements.reserve(count);
    _species.reserve(count);
}

void ElementColumns::append(unsigned int element, std::string_view name)
{
    _elements.push_back(static_cast<float>(element));
    _species.append(element > 0 ? std::string_view(getElement(element).symbol) : name);
}

void ElementColumns::addTo(PointData& frame)
{
    frame.addColumn("element", std::move(_elements));
    _species.addTo(frame, "species");
}
