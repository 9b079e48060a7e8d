// PDB: not read yet (being written).

#include "Formats.h"

using namespace osgGlyphsData;

osg::ref_ptr<FrameFile> formats::openPdb(const std::string& path, const FrameFileOptions&, std::string& error)
{
    error = path + ": PDB files are not read yet";
    return nullptr;
}

osg::ref_ptr<FrameFile> formats::openGro(const std::string& path, const FrameFileOptions&, std::string& error)
{
    error = path + ": GRO files are not read yet";
    return nullptr;
}
