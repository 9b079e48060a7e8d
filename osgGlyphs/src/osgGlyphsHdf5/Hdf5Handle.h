/* osgGlyphs - private: HDF5 identifiers that close themselves, the library's lock, and failures as
 * one line naming the file, the frame and the dataset. */

#ifndef OSGGLYPHS_HDF5_HDF5HANDLE_H
#define OSGGLYPHS_HDF5_HDF5HANDLE_H 1

#include <hdf5.h>

#include <cstddef>
#include <cstdint>
#include <mutex>
#include <string>

namespace osgGlyphsHdf5
{
namespace detail
{

/** What the readers throw: one line naming the file, the frame (when there is one) and the
 * dataset. */
struct Hdf5Error
{
    std::string message;
    /** The dataset and what is wrong with it, so that a frame can name itself in a message about
     * what the opening found. */
    std::string dataset;
    std::string what;
};

/** Where a reader is, for messages: "<file>: frame <n>: dataset <path>: <what>". */
struct Place
{
    const std::string* file = nullptr;
    /** The frame (0-based); SIZE_MAX while the file is opened. */
    std::size_t frame = SIZE_MAX;

    std::string describe(const std::string& dataset, const std::string& what) const;
    [[noreturn]] void fail(const std::string& dataset, const std::string& what) const;
};

/** The innermost description on HDF5's error stack of this thread ("can't open object"), or
 * "HDF5 failed" when it is empty. */
std::string lastHdf5Error();

/** Holds the lock under which every HDF5 call of this library is made (the library may be built
 * without its own; recursive, since a reader that fails to open closes its handles under it), and keeps HDF5
 * from printing its error stack: failures become messages. */
class Hdf5Lock
{
public:
    Hdf5Lock();

private:
    std::lock_guard<std::recursive_mutex> _lock;
};

/** An HDF5 identifier closed by the function that matches its kind, under the lock. */
class Handle
{
public:
    using Close = herr_t (*)(hid_t);

    Handle() = default;
    Handle(hid_t id, Close close) : _id(id), _close(close) {}
    ~Handle() { reset(); }
    Handle(Handle&& other) noexcept : _id(other._id), _close(other._close) { other._id = H5I_INVALID_HID; }
    Handle& operator=(Handle&& other) noexcept;
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;

    hid_t get() const { return _id; }
    bool valid() const { return _id >= 0; }
    void reset();

private:
    hid_t _id = H5I_INVALID_HID;
    Close _close = nullptr;
};

/** Opens a file read-only; throws "<path>: cannot open as HDF5: <why>". */
Handle openFile(const std::string& path);
/** Opens a dataset; throws at place naming it when it is missing or is no dataset. */
Handle openDataset(hid_t file, const std::string& path, const Place& place);
Handle openGroup(hid_t file, const std::string& path, const Place& place);

/** What lies at path: H5O_TYPE_GROUP, H5O_TYPE_DATASET, or H5O_TYPE_UNKNOWN when nothing (or a
 * broken link) does. Every link on the way is checked first, as H5Oget_info_by_name needs. */
H5O_type_t objectType(hid_t file, const std::string& path);

/** The path of the parent of path and the last name in it. */
std::string parentPath(const std::string& path);
std::string baseName(const std::string& path);

}
}

#endif
