#include "RowShare.h"

#include "Fields.h"

#include <algorithm>
#include <cstring>

using namespace osgGlyphsData;
using namespace osgGlyphsData::readers;

namespace
{

// The bytes of a frame's first rows that tell where the rows end, or how long they are.
const std::size_t HeadBytes = 64 * 1024;
// The bytes of each sample of the rows' length further on.
const std::size_t SampleBytes = 16 * 1024;

/** The whole rows at the start of text (which starts a line), up to maxRows or a line that passes
 * endsRows: how many, and their bytes. */
struct RowCount
{
    uint64_t rows = 0;
    uint64_t bytes = 0;
    bool ended = false; // a line passed endsRows
};

RowCount countRows(std::string_view text, uint64_t maxRows, const TextScanner::LineTest& endsRows)
{
    RowCount count;
    while (count.rows < maxRows)
    {
        const std::size_t lineEnd = text.find('\n', count.bytes);
        if (lineEnd == std::string_view::npos)
            break;
        std::string_view line = text.substr(count.bytes, lineEnd - count.bytes);
        if (!line.empty() && line.back() == '\r')
            line.remove_suffix(1);
        if ((count.ended = endsRows(line)))
            break;
        count.bytes = lineEnd + 1;
        ++count.rows;
    }
    return count;
}

/** Where the rows from body end: see readShareOfRows(). */
uint64_t findEndOfRows(TextScanner& scanner, uint64_t body, uint64_t count, uint64_t minBytes,
                       const TextScanner::LineTest& endsRows)
{
    const uint64_t fileEnd = scanner.getEndOffset();
    const uint64_t headOffset = scanner.getOffset();
    const std::size_t size = static_cast<std::size_t>(std::min<uint64_t>(HeadBytes, fileEnd - headOffset));
    const char* head = scanner.peekBytes(size);
    uint64_t rows = headOffset > body ? 1 : 0; // the first row, read already
    const RowCount first =
        countRows(std::string_view(head ? head : "", head ? size : 0), count - rows, endsRows);
    rows += first.rows;
    if (first.ended || rows == count)
        return headOffset + first.bytes;
    if (rows == 0)
        return fileEnd;
    // The frame's bytes: the rows' mean length in the middle of each quarter of the size the head
    // makes it (the head's where a sample cannot be taken), times count.
    const double headRowBytes =
        static_cast<double>(headOffset + first.bytes - body) / static_cast<double>(rows);
    const double headGuess = headRowBytes * static_cast<double>(count);
    const double least = static_cast<double>(minBytes) * static_cast<double>(count);
    double rowBytes = 0.0;
    for (double fraction : {0.125, 0.375, 0.625, 0.875})
    {
        const uint64_t at = body + static_cast<uint64_t>(fraction * headGuess);
        const std::string text = at < fileEnd ? scanner.readAt(at - 1, SampleBytes) : std::string();
        const std::size_t lineStart = text.find('\n');
        const RowCount sample =
            lineStart == std::string::npos
                ? RowCount()
                : countRows(std::string_view(text).substr(lineStart + 1), UINT64_MAX, endsRows);
        if (sample.ended) // shorter than its head made it: look from the least it can be
            return scanner.findLine(
                std::max(body + static_cast<uint64_t>(std::min(least, double(fileEnd - body))),
                         headOffset + first.bytes),
                endsRows);
        rowBytes += sample.rows > 0 ? static_cast<double>(sample.bytes) / static_cast<double>(sample.rows)
                                    : headRowBytes;
    }
    const double estimate = rowBytes / 4.0 * static_cast<double>(count);
    const double from = std::max(0.95 * estimate, least);
    if (from >= static_cast<double>(fileEnd - body))
        return fileEnd;
    return scanner.findLine(body + static_cast<uint64_t>(from), endsRows);
}

}

bool osgGlyphsData::readers::sharesRowsByBytes(const TextScanner& scanner, const PointShare& share,
                                               uint64_t count)
{
    return !share.isWhole() && scanner.canSeek() && count > 0;
}

void osgGlyphsData::readers::readShareOfRows(TextScanner& scanner, ColumnTable& table, uint64_t body,
                                             uint64_t count, uint64_t minBytes, const PointShare& share,
                                             const TextScanner::LineTest& endsRows,
                                             const std::string& section,
                                             const std::optional<std::string>& first)
{
    const uint64_t end = findEndOfRows(scanner, body, count, minBytes, endsRows);
    const PointRange part = getShareRange(share, end - body);
    std::string_view line;
    std::vector<std::string_view> fields;
    if (part.begin > 0)
    {
        // Row 0 chooses the origins; a bad row 0 is the failure of the share that holds it.
        if (first || scanner.nextLine(line))
        {
            splitBlanks(first ? std::string_view(*first) : line, fields);
            if (fields.size() == table.getNumColumns())
                table.chooseOrigins(fields);
        }
        scanner.skipToLineStart(body + part.begin);
    }
    else if (first && part.end > 0)
    {
        table.appendRow(*first);
    }
    // The share's part of the rows, and at most as many as its bytes can hold.
    const double fraction =
        static_cast<double>(part.end - part.begin) / static_cast<double>(std::max<uint64_t>(end - body, 1));
    const uint64_t expected = static_cast<uint64_t>(1.02 * fraction * static_cast<double>(count)) + 16;
    table.reserve(static_cast<std::size_t>(std::min(expected, (part.end - part.begin) / minBytes + 1)));
    while (scanner.getOffset() < body + part.end && scanner.nextLine(line))
    {
        if (endsRows(line))
            scanner.fail(quote(trim(line)) + " among the " + std::to_string(count) + " rows of " + section +
                         " (the frame has fewer rows than its count)");
        table.appendRow(line);
    }
    scanner.skipToLineStart(end);
}
