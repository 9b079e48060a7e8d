/* osgGlyphs - private: the binary formats read as frame files, one opener per format. */

#ifndef OSGGLYPHS_FORMATS_FORMATS_H
#define OSGGLYPHS_FORMATS_FORMATS_H 1

#include <osgGlyphsData/FrameFile>

namespace osgGlyphsData
{
namespace formats
{

/** Each opener reads what it needs of the file's header and structure and returns the FrameFile,
 * or nullptr with a one-line error naming the file and the byte. */
osg::ref_ptr<FrameFile> openDcd(const std::string& path, const FrameFileOptions& options, std::string& error);
osg::ref_ptr<FrameFile> openXtc(const std::string& path, const FrameFileOptions& options, std::string& error);
osg::ref_ptr<FrameFile> openTrr(const std::string& path, const FrameFileOptions& options, std::string& error);
osg::ref_ptr<FrameFile> openGsd(const std::string& path, const FrameFileOptions& options, std::string& error);
osg::ref_ptr<FrameFile> openLas(const std::string& path, const FrameFileOptions& options, std::string& error);
osg::ref_ptr<FrameFile> openPdb(const std::string& path, const FrameFileOptions& options, std::string& error);
osg::ref_ptr<FrameFile> openGro(const std::string& path, const FrameFileOptions& options, std::string& error);

} // namespace formats
}

#endif
