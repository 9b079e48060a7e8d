// CSV: a header row of column names, then one point a row; comma, semicolon, tab or blank separated.

#include "ColumnTable.h"
#include "Fields.h"
#include "Readers.h"

#include <cstring>
#include <limits>

using namespace osgGlyphsData;
using namespace osgGlyphsData::readers;

namespace
{

// A separator of 0 means runs of blanks.
char detectSeparator(std::string_view header)
{
    for (char candidate : {',', ';', '\t'})
    {
        if (header.find(candidate) != std::string_view::npos)
            return candidate;
    }
    return 0;
}

// A field without surrounding blanks and double quotes.
std::string_view unquote(std::string_view field)
{
    field = trim(field);
    if (field.size() >= 2 && field.front() == '"' && field.back() == '"')
        field = field.substr(1, field.size() - 2);
    return field;
}

void splitSeparated(std::string_view line, char separator, std::vector<std::string_view>& fields)
{
    if (separator == 0)
    {
        splitBlanks(line, fields);
        return;
    }
    fields.clear();
    std::size_t start = 0;
    for (;;)
    {
        const std::size_t stop = line.find(separator, start);
        fields.push_back(
            unquote(line.substr(start, stop == std::string_view::npos ? line.npos : stop - start)));
        if (stop == std::string_view::npos)
            return;
        start = stop + 1;
    }
}

bool isSkipped(std::string_view line)
{
    const std::string_view text = trim(line);
    return text.empty() || text.front() == '#';
}

} // namespace

void osgGlyphsData::readers::readCsv(TextScanner& scanner, PointDataset& dataset,
                                     const PointReadOptions& options)
{
    std::string_view line;
    bool found = false;
    while (!found && scanner.nextLine(line))
    {
        // A UTF-8 byte order mark: at the start of the file, or of a file appended to comments.
        if (startsWith(line, "\xEF\xBB\xBF"))
            line.remove_prefix(3);
        found = !isSkipped(line);
    }
    if (!found)
        scanner.fail("no header line: the file has only comments and blank lines");

    const char separator = detectSeparator(line);
    std::vector<std::string_view> fields;
    splitSeparated(line, separator, fields);
    bool allNumbers = true;
    for (std::string_view field : fields)
    {
        double value = 0.0;
        allNumbers = allNumbers && parseDouble(field, value);
    }
    if (allNumbers)
        scanner.fail("the first line must name the columns, found " + quote(trim(line)));
    // A share of a file of known size holds the lines that start in its part of the body's bytes
    // (getShareRange() of the bytes after the header): it seeks there and stops at the next part.
    const bool byBytes = !options.share.isWhole() && scanner.getEndOffset() > 0;
    ColumnTable table(scanner, byBytes ? PointShare() : options.share);
    for (std::string_view field : fields)
    {
        for (char c : field)
        {
            if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F)
                scanner.fail("the column name " + quote(field) +
                             " has control characters (is this binary data?)");
        }
        table.addColumn(std::string(field));
    }

    uint64_t stop = std::numeric_limits<uint64_t>::max();
    bool pending = false; // line holds a row still to append
    if (byBytes)
    {
        const uint64_t body = scanner.getOffset();
        const PointRange part = getShareRange(options.share, scanner.getEndOffset() - body);
        stop = body + part.end;
        if (part.begin > 0)
        {
            // Row 0, before the share, gives the columns their origins as in every share.
            while ((pending = scanner.nextLine(line)) && isSkipped(line))
            {
            }
            if (pending && scanner.getLineOffset() < body + part.begin)
            {
                splitSeparated(line, separator, fields);
                table.chooseOrigins(fields);
                pending = false;
                scanner.skipToLineStart(body + part.begin);
            }
        }
    }
    while ((pending || scanner.nextLine(line)) && scanner.getLineOffset() < stop)
    {
        pending = false;
        if (isSkipped(line))
            continue;
        if (separator == 0)
        {
            table.appendRow(line);
            continue;
        }
        splitSeparated(line, separator, fields);
        if (fields.size() != table.getNumColumns())
            table.failFieldCount(fields.size());
        for (std::size_t c = 0; c < fields.size(); ++c)
            table.appendField(c, fields[c]);
    }
    addOnlyFrame(scanner, dataset, options, table.finish().get());
}
