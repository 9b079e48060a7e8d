#include "Hdf5Handle.h"

using namespace osgGlyphsHdf5::detail;

namespace
{

std::recursive_mutex& hdf5Mutex()
{
    static std::recursive_mutex mutex;
    return mutex;
}

herr_t keepInnermost(unsigned int, const H5E_error2_t* error, void* data)
{
    std::string& description = *static_cast<std::string*>(data);
    if (description.empty() && error->desc && error->desc[0])
        description = error->desc;
    return 0;
}

}

std::string Place::describe(const std::string& dataset, const std::string& what) const
{
    std::string text = file ? *file : std::string("(unnamed)");
    if (frame != SIZE_MAX)
        text += ": frame " + std::to_string(frame);
    if (!dataset.empty())
        text += ": dataset " + dataset;
    return text + ": " + what;
}

void Place::fail(const std::string& dataset, const std::string& what) const
{
    throw Hdf5Error{describe(dataset, what), dataset, what};
}

std::string osgGlyphsHdf5::detail::lastHdf5Error()
{
    std::string description;
    H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, keepInnermost, &description);
    H5Eclear2(H5E_DEFAULT);
    for (char& c : description)
    {
        if (c == '\n' || c == '\r')
            c = ' ';
    }
    return description.empty() ? std::string("HDF5 failed") : description;
}

Hdf5Lock::Hdf5Lock() : _lock(hdf5Mutex())
{
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

Handle& Handle::operator=(Handle&& other) noexcept
{
    if (this != &other)
    {
        reset();
        _id = other._id;
        _close = other._close;
        other._id = H5I_INVALID_HID;
    }
    return *this;
}

void Handle::reset()
{
    if (_id >= 0 && _close)
        _close(_id);
    _id = H5I_INVALID_HID;
}

Handle osgGlyphsHdf5::detail::openFile(const std::string& path)
{
    const htri_t isHdf5 = H5Fis_hdf5(path.c_str());
    if (isHdf5 == 0)
        throw Hdf5Error{path + ": not an HDF5 file (no HDF5 signature)", "", ""};
    Handle file(isHdf5 > 0 ? H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT) : H5I_INVALID_HID, H5Fclose);
    if (!file.valid())
        throw Hdf5Error{path + ": cannot open as HDF5: " + lastHdf5Error(), "", ""};
    return file;
}

H5O_type_t osgGlyphsHdf5::detail::objectType(hid_t file, const std::string& path)
{
    std::size_t at = path.find_first_not_of('/');
    while (at != std::string::npos && at < path.size())
    {
        const std::size_t end = path.find('/', at);
        const std::string prefix = path.substr(0, end);
        if (H5Lexists(file, prefix.c_str(), H5P_DEFAULT) <= 0 ||
            H5Oexists_by_name(file, prefix.c_str(), H5P_DEFAULT) <= 0)
        {
            H5Eclear2(H5E_DEFAULT);
            return H5O_TYPE_UNKNOWN;
        }
        at = end == std::string::npos ? end : path.find_first_not_of('/', end);
    }
    H5O_info_t info;
    if (H5Oget_info_by_name(file, path.c_str(), &info, H5P_DEFAULT) < 0)
    {
        H5Eclear2(H5E_DEFAULT);
        return H5O_TYPE_UNKNOWN;
    }
    return info.type;
}

Handle osgGlyphsHdf5::detail::openDataset(hid_t file, const std::string& path, const Place& place)
{
    const H5O_type_t type = objectType(file, path);
    if (type == H5O_TYPE_UNKNOWN)
        place.fail(path, "missing");
    if (type != H5O_TYPE_DATASET)
        place.fail(path, "is a group, not a dataset");
    Handle dataset(H5Dopen2(file, path.c_str(), H5P_DEFAULT), H5Dclose);
    if (!dataset.valid())
        place.fail(path, "cannot be opened: " + lastHdf5Error());
    return dataset;
}

Handle osgGlyphsHdf5::detail::openGroup(hid_t file, const std::string& path, const Place& place)
{
    const H5O_type_t type = objectType(file, path);
    if (type == H5O_TYPE_UNKNOWN)
        place.fail(path, "missing");
    if (type != H5O_TYPE_GROUP)
        place.fail(path, "is a dataset, not a group");
    Handle group(H5Gopen2(file, path.c_str(), H5P_DEFAULT), H5Gclose);
    if (!group.valid())
        place.fail(path, "cannot be opened: " + lastHdf5Error());
    return group;
}

std::string osgGlyphsHdf5::detail::parentPath(const std::string& path)
{
    const std::size_t slash = path.find_last_of('/');
    if (slash == std::string::npos)
        return "/";
    return slash == 0 ? "/" : path.substr(0, slash);
}

std::string osgGlyphsHdf5::detail::baseName(const std::string& path)
{
    const std::size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}
