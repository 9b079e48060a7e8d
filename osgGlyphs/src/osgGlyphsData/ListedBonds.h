/* osgGlyphs - private: the bonds a file lists (a LAMMPS data file's Bonds, PDB CONECT) turned into
 * a frame's bond list (PointData::getBonds()). */

#ifndef OSGGLYPHS_LISTEDBONDS_H
#define OSGGLYPHS_LISTEDBONDS_H 1

#include <osgGlyphsData/PointData>

#include <cstdint>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

namespace osgGlyphsData
{

/** A frame's index for each atom of a file, NOT_IN_FRAME where the frame (a share) lacks it. */
constexpr uint32_t NOT_IN_FRAME = std::numeric_limits<uint32_t>::max();

/** The bonds between a file's atoms, given by their rows in the file (in any order, either way
 * round, repeated as PDB lists each bond from both atoms), as the frame holds them: by the frame's
 * index of each row (frameIndexOfRow), each pair once, sorted, with zero images. Bonds with an atom
 * the frame lacks are left out; the rows must be below frameIndexOfRow.size() and not equal. */
std::shared_ptr<const PointData::BondList>
makeListedBonds(const std::vector<std::pair<uint32_t, uint32_t>>& rows,
                const std::vector<uint32_t>& frameIndexOfRow);

}

#endif
