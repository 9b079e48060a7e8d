// The HDF5 formats' registration with osgGlyphsData, and the openers that tell H5MD, snapshots
// and named datasets apart.

#include <osgGlyphsHdf5/Hdf5Formats>

#include "Hdf5Readers.h"

using namespace osgGlyphsData;
using namespace osgGlyphsHdf5::detail;

namespace
{

bool namesH5mdElement(hid_t file, const std::string& dataset)
{
    return objectType(file, dataset) == H5O_TYPE_GROUP || dataset.rfind("/particles/", 0) == 0 ||
           dataset.rfind("particles/", 0) == 0;
}

osg::ref_ptr<FrameFile> open(const std::string& path, const FrameFileOptions& options, bool h5md,
                             std::string& error)
{
    Hdf5Lock lock;
    try
    {
        Handle file = openFile(path);
        const std::string format = h5md ? "h5md" : "hdf5";
        const std::vector<std::string>& datasets = options.datasets;
        if (h5md ||
            (datasets.empty() ? looksLikeH5md(file.get()) : namesH5mdElement(file.get(), datasets[0])))
            return openH5md(std::move(file), path, format, datasets);
        if (!datasets.empty())
            return openDatasets(std::move(file), path, format, datasets);
        if (looksLikeSnapshot(file.get()))
            return openSnapshot(std::move(file), path, format);
        error = path + ": neither H5MD (/particles) nor a snapshot (/PartType<N>/Coordinates): name the "
                       "datasets to read, the positions first";
    }
    catch (const Hdf5Error& failure)
    {
        error = failure.message;
    }
    return nullptr;
}

/** Registers the formats when the library is loaded, where the linker keeps it. */
const bool registeredAtLoading = (osgGlyphsHdf5::registerFormats(), true);

}

void osgGlyphsHdf5::registerFormats()
{
    static std::once_flag once;
    std::call_once(
        once,
        []
        {
            registerFrameFileFormat({"h5md", "H5MD particle trajectory (HDF5)", {"h5md"}, {}},
                                    [](const std::string& path, const FrameFileOptions& options,
                                       std::string& error) { return open(path, options, true, error); });
            registerFrameFileFormat({"hdf5",
                                     "HDF5 particles: H5MD, SWIFT or Gadget snapshot, or the datasets named",
                                     {"h5", "hdf5", "hdf"},
                                     {}},
                                    [](const std::string& path, const FrameFileOptions& options,
                                       std::string& error) { return open(path, options, false, error); });
        });
}
