#include <osgGlyphs/Version>

extern "C"
{
    const char* osgGlyphsGetVersion()
    {
        return OSGGLYPHS_VERSION_STRING;
    }
    const char* osgGlyphsGetLibraryName()
    {
        return "osgGlyphs Library";
    }
}
