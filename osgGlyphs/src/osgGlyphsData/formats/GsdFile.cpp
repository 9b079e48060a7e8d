// GSD: not read yet (being written).

#include "Formats.h"

using namespace osgGlyphsData;

osg::ref_ptr<FrameFile> formats::openGsd(const std::string& path, const FrameFileOptions&, std::string& error)
{
    error = path + ": GSD files are not read yet";
    return nullptr;
}
