// LAS: not read yet (being written).

#include "Formats.h"

using namespace osgGlyphsData;

osg::ref_ptr<FrameFile> formats::openLas(const std::string& path, const FrameFileOptions&, std::string& error)
{
    error = path + ": LAS files are not read yet";
    return nullptr;
}
