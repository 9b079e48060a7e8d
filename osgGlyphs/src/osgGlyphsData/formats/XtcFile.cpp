// XTC: not read yet (being written).

#include "Formats.h"

using namespace osgGlyphsData;

osg::ref_ptr<FrameFile> formats::openXtc(const std::string& path, const FrameFileOptions&, std::string& error)
{
    error = path + ": XTC files are not read yet";
    return nullptr;
}

osg::ref_ptr<FrameFile> formats::openTrr(const std::string& path, const FrameFileOptions&, std::string& error)
{
    error = path + ": TRR files are not read yet";
    return nullptr;
}
