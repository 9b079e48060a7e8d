#include "BinRounds.h"

#include <osgGlyphs/GlyphCulling>

#include <osgUtil/RenderBin>

const char* const osgGlyphs::FRONT_TO_BACK_BIN = "osgGlyphsFrontToBack";

namespace
{

/** Sorts its leaves nearest first and culls the chunks of the clouds among them together
 * (drawBinInRounds). */
class FrontToBackBin : public osgUtil::RenderBin
{
public:
    FrontToBackBin() : osgUtil::RenderBin(SORT_FRONT_TO_BACK) {}
    FrontToBackBin(const FrontToBackBin& other, const osg::CopyOp& copyop = osg::CopyOp::SHALLOW_COPY)
        : osgUtil::RenderBin(other, copyop)
    {
    }
    META_Object(osgGlyphs, FrontToBackBin);

    void drawImplementation(osg::RenderInfo& renderInfo, osgUtil::RenderLeaf*& previous) override
    {
        // Sorting moved every leaf into the leaf list; anything else is drawn as RenderBin does.
        if (!_bins.empty() || !_stateGraphList.empty() || _stateset.valid())
            osgUtil::RenderBin::drawImplementation(renderInfo, previous);
        else
            osgGlyphs::detail::drawBinInRounds(renderInfo, previous, _renderLeafList);
    }
};

/** Registers the bin as the library loads: osgDB may read tiles that name it before any cloud is
 * made. */
struct FrontToBackBinRegistration
{
    FrontToBackBinRegistration()
    {
        osgUtil::RenderBin::addRenderBinPrototype(osgGlyphs::FRONT_TO_BACK_BIN, new FrontToBackBin);
    }
};

const FrontToBackBinRegistration registration;

}
