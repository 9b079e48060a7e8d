/* osgGlyphs - private: a share of a frame's rows, by their bytes (LAMMPS and XYZ frames). */

#ifndef OSGGLYPHS_READERS_ROWSHARE_H
#define OSGGLYPHS_READERS_ROWSHARE_H 1

#include "ColumnTable.h"
#include "TextScanner.h"

#include <osgGlyphsData/PointShare>

#include <optional>
#include <string>

namespace osgGlyphsData
{
namespace readers
{

/** Whether the share of a frame of count rows is the rows that start in the share's part of the
 * frame's bytes (readShareOfRows()), rather than a range of rows found by reading every row: for
 * a share of a stream that can seek. */
bool sharesRowsByBytes(const TextScanner& scanner, const PointShare& share, uint64_t count);

/** Reads the rows of a frame of count rows that start in this share's part of the rows' bytes
 * (getShareRange() of them), seeking there, and moves the scanner to the rows' end. body is the
 * offset of the first row; first, when given, is that row, read already. Row 0 gives the columns
 * their origins, as in every share.
 *
 * Where the rows end is counted when they fit in the first 64 KiB. Past that it is estimated:
 * count times the rows' mean length, measured in the first 64 KiB and in 16 KiB at a quarter,
 * half and three quarters of the frame; the end is the first line from 95% of the estimate on
 * (from where count rows of minBytes would end, at least) that passes endsRows (the next frame's
 * first line), or the file's end. A share so reads about a twentieth of each frame beyond its part,
 * instead of all of it. Rows whose length changes by more than that along the frame would make
 * the estimate pass the frame's end: the share that holds the end then meets the next frame's
 * first line among its rows and fails naming it, as when a frame is shorter than its count. */
void readShareOfRows(TextScanner& scanner, ColumnTable& table, uint64_t body, uint64_t count,
                     uint64_t minBytes, const PointShare& share, const TextScanner::LineTest& endsRows,
                     const std::string& section, const std::optional<std::string>& first = std::nullopt);

} // namespace readers
}

#endif
