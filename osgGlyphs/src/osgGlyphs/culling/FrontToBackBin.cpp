#include <osgGlyphs/GlyphCulling>

#include <osgUtil/RenderBin>

const char* const osgGlyphs::FRONT_TO_BACK_BIN = "osgGlyphsFrontToBack";

namespace
{

/** Registers the bin as the library loads: osgDB may read tiles that name it before any cloud is
 * made. */
struct FrontToBackBinRegistration
{
    FrontToBackBinRegistration()
    {
        osgUtil::RenderBin::addRenderBinPrototype(
            osgGlyphs::FRONT_TO_BACK_BIN, new osgUtil::RenderBin(osgUtil::RenderBin::SORT_FRONT_TO_BACK));
    }
};

const FrontToBackBinRegistration registration;

}
