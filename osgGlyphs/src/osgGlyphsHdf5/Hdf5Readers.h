/* osgGlyphs - private: the HDF5 readers, each opening a file that Hdf5Formats.cpp has recognised. */

#ifndef OSGGLYPHS_HDF5_HDF5READERS_H
#define OSGGLYPHS_HDF5_HDF5READERS_H 1

#include "Hdf5Particles.h"

#include <osgGlyphsData/FrameFile>

namespace osgGlyphsHdf5
{
namespace detail
{

/** Each is called under Hdf5Lock with the opened file, and throws Hdf5Error (one line naming the
 * file and the dataset) when the file is malformed. */

/** H5MD: every particle group of /particles, or, with datasets, the group of the first (the
 * position element) and only the elements named. */
osg::ref_ptr<osgGlyphsData::FrameFile> openH5md(Handle file, const std::string& path,
                                                const std::string& format,
                                                const std::vector<std::string>& datasets);

/** Whether the file is laid out as H5MD (a /particles group). */
bool looksLikeH5md(hid_t file);

/** SWIFT and Gadget snapshots: every /PartTypeN group with Coordinates, one frame. */
osg::ref_ptr<osgGlyphsData::FrameFile> openSnapshot(Handle file, const std::string& path,
                                                    const std::string& format);

/** Whether the file has a /PartTypeN/Coordinates dataset. */
bool looksLikeSnapshot(hid_t file);

/** The datasets named: positions (N x 2 or N x 3) first, then columns (N or N x k), one frame. */
osg::ref_ptr<osgGlyphsData::FrameFile> openDatasets(Handle file, const std::string& path,
                                                    const std::string& format,
                                                    const std::vector<std::string>& datasets);

}
}

#endif
