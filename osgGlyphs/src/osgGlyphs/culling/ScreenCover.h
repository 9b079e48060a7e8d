/* osgGlyphs - private: the chunks that lay down a cloud's front over the whole view. Not installed. */

#ifndef OSGGLYPHS_SCREENCOVER_H
#define OSGGLYPHS_SCREENCOVER_H 1

#include <cstddef>
#include <vector>

namespace osgGlyphs
{
namespace detail
{

/** A chunk in view: its pixel rectangle (inclusive, relative to the viewport) and the window
 * depth of its nearest point. */
struct ChunkInView
{
    unsigned int chunk;
    float nearest;
    int x0, y0, x1, y1;
};

/** The pixels a side of the cells of putScreenCoverFirst's grid. */
const int SCREEN_COVER_CELL_PIXELS = 8;

/** Moves to the front the chunks that cover a cell of a grid over the view first, when the
 * chunks (sorted nearest first) are laid down in turn; the rest follow. Both keep their order.
 * Returns how many cover. Drawn first, they lay down the cloud's front over the whole view, so
 * that the rounds after them are tested against it: the nearest chunks alone bunch around the
 * point nearest the eye. A chunk counts as covering the cells wholly inside its rectangle (a
 * box's projection does not fill its rectangle's corners; the cells that a view of width x
 * height pixels cuts short count as whole), or, when its rectangle holds no whole cell, the cell
 * of its rectangle's centre. */
std::size_t putScreenCoverFirst(std::vector<ChunkInView>& inView, int width, int height);

}
}

#endif
