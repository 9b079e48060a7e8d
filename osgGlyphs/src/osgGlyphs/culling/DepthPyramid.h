/* osgGlyphs - private: a hierarchical depth (Hi-Z) pyramid of the farthest depth. Not installed. */

#ifndef OSGGLYPHS_DEPTHPYRAMID_H
#define OSGGLYPHS_DEPTHPYRAMID_H 1

#include <vector>

namespace osgGlyphs
{
namespace detail
{

/** The farthest window depth over blocks of a depth image: level 0 is the image, each level
 * above halves it (rounding down, to 1x1, as GL's mipmap levels). A level's last column and
 * row also cover the pixels that rounding down leaves over, so that texel (x, y) of level k
 * holds every pixel (px, py) with min(px >> k, width(k) - 1) == x, and likewise for y. */
class DepthPyramid
{
public:
    /** Builds the pyramid over a width x height depth image, rows from the bottom up. */
    void build(std::vector<float> depth, int width, int height);
    /** The storage of a width x height image, rows from the bottom up, to fill and then build
     * the levels over (buildLevels()). The storage of every level is kept from one build to the
     * next. */
    float* resetImage(int width, int height);
    void buildLevels();
    /** No pyramid. */
    void clear();
    bool valid() const { return !_widths.empty(); }
    int getNumLevels() const { return static_cast<int>(_widths.size()); }
    int getWidth(int level) const { return _widths[level]; }
    int getHeight(int level) const { return _heights[level]; }
    const std::vector<float>& getLevel(int level) const { return _levels[level]; }

    /** The farthest depth over the pixels [x0, x1] x [y0, y1] (inclusive), read from at most
     * texels x texels texels of the finest level at which the rectangle spans that few: the
     * more texels, the closer the bound. The rectangle is clamped to the image; pixels outside
     * it count as not there. */
    float farthest(int x0, int y0, int x1, int y1, int texels = 2) const;

    /** The finest level at which the pixels [x0, x1] x [y0, y1] span at most texels x texels. */
    static int levelFor(int x0, int y0, int x1, int y1, int texels = 2);

private:
    std::vector<std::vector<float>> _levels;
    std::vector<int> _widths, _heights;
};

}
}

#endif
