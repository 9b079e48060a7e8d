#include "Hdf5Dataset.h"

#include <algorithm>

using namespace osgGlyphsHdf5::detail;

namespace
{

/** How many times the bytes HDF5 stores for a dataset its values may be: more than any of HDF5's
 * compression filters reaches (deflate stops near 1032). */
constexpr hsize_t MostExpansion = 4096;
/** Values read at once: a buffer that stays in the cache while it is spread into columns. */
constexpr hsize_t ValuesPerBlock = hsize_t(1) << 17;

bool multiply(hsize_t a, hsize_t b, hsize_t& product)
{
    return !__builtin_mul_overflow(a, b, &product);
}

std::string describeDims(const std::vector<hsize_t>& dims)
{
    if (dims.empty())
        return "a scalar";
    std::string text;
    for (hsize_t dim : dims)
        text += (text.empty() ? "" : " x ") + std::to_string(dim);
    return text;
}

template <typename T>
hid_t memoryType();
template <>
hid_t memoryType<float>()
{
    return H5T_NATIVE_FLOAT;
}
template <>
hid_t memoryType<double>()
{
    return H5T_NATIVE_DOUBLE;
}
template <>
hid_t memoryType<int64_t>()
{
    return H5T_NATIVE_INT64;
}

template <typename T>
void readBlocks(const DatasetInfo& info, const std::vector<hsize_t>& leading, hsize_t begin, hsize_t end,
                const Place& place, const RowSink<T>& sink)
{
    const std::size_t axis = leading.size();
    if (axis >= info.dims.size())
        place.fail(info.path, "has " + std::to_string(info.dims.size()) + " axes (" +
                                  describeDims(info.dims) + "), not the " + std::to_string(axis + 1) +
                                  " or more expected");
    for (std::size_t i = 0; i < axis; ++i)
    {
        if (leading[i] >= info.dims[i])
            place.fail(info.path, "has no index " + std::to_string(leading[i]) + " on axis " +
                                      std::to_string(i) + " (" + describeDims(info.dims) + ")");
    }
    if (begin > end || end > info.dims[axis])
        place.fail(info.path, "has no rows " + std::to_string(begin) + " to " + std::to_string(end) + " (" +
                                  describeDims(info.dims) + ")");
    const hsize_t width = info.countFrom(axis + 1);
    if (width == 0 || begin == end)
        return;
    const hsize_t rowsPerBlock = std::max<hsize_t>(1, ValuesPerBlock / width);
    // Reused by the thread's next reads: no allocation, no first touch of its pages each time.
    thread_local std::vector<T> buffer;
    buffer.resize(std::max<std::size_t>(buffer.size(), std::min(end - begin, rowsPerBlock) * width));
    Handle fileSpace(H5Dget_space(info.dataset.get()), H5Sclose);
    std::vector<hsize_t> start(info.dims.size(), 0), count(info.dims);
    for (std::size_t i = 0; i < axis; ++i)
    {
        start[i] = leading[i];
        count[i] = 1;
    }
    for (hsize_t row = begin; row < end; row += rowsPerBlock)
    {
        const hsize_t rows = std::min(rowsPerBlock, end - row);
        start[axis] = row;
        count[axis] = rows;
        const hsize_t values = rows * width;
        Handle memorySpace(H5Screate_simple(1, &values, nullptr), H5Sclose);
        if (!fileSpace.valid() || !memorySpace.valid() ||
            H5Sselect_hyperslab(fileSpace.get(), H5S_SELECT_SET, start.data(), nullptr, count.data(),
                                nullptr) < 0 ||
            H5Dread(info.dataset.get(), memoryType<T>(), memorySpace.get(), fileSpace.get(), H5P_DEFAULT,
                    buffer.data()) < 0)
            place.fail(info.path, "rows " + std::to_string(row) + " to " + std::to_string(row + rows) +
                                      " cannot be read: " + lastHdf5Error());
        sink(row, buffer.data(), rows);
    }
}

template <typename T>
std::vector<T> readAll(const DatasetInfo& info, hsize_t limit, const Place& place)
{
    requireNumbers(info, place);
    const hsize_t count = info.countFrom(0);
    if (count > limit)
        place.fail(info.path, "holds " + describeDims(info.dims) + " values, more than the " +
                                  std::to_string(limit) + " expected");
    std::vector<T> values(static_cast<std::size_t>(count));
    if (count > 0 &&
        H5Dread(info.dataset.get(), memoryType<T>(), H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
        place.fail(info.path, "cannot be read: " + lastHdf5Error());
    return values;
}

Handle openAttribute(hid_t file, const std::string& object, const std::string& name, const Place& place)
{
    Handle attribute(H5Aopen_by_name(file, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    if (!attribute.valid())
        place.fail(object + "@" + name, "cannot be opened: " + lastHdf5Error());
    return attribute;
}

hsize_t attributeCount(const Handle& attribute, const std::string& where, std::size_t limit,
                       const Place& place)
{
    Handle space(H5Aget_space(attribute.get()), H5Sclose);
    const hssize_t count = space.valid() ? H5Sget_simple_extent_npoints(space.get()) : -1;
    if (count < 0 || hsize_t(count) > limit)
        place.fail(where, "holds " + std::to_string(count) + " values, not 1 to " + std::to_string(limit));
    return hsize_t(count);
}

herr_t collectName(hid_t, const char* name, const H5L_info_t*, void* data)
{
    auto& names = *static_cast<std::vector<std::string>*>(data);
    names.emplace_back(name);
    return names.size() >= 100000 ? 1 : 0;
}

}

hsize_t DatasetInfo::countFrom(std::size_t axis) const
{
    hsize_t count = 1;
    for (std::size_t i = axis; i < dims.size(); ++i)
        count *= dims[i]; // checked against overflow by describeDataset()
    return count;
}

DatasetInfo osgGlyphsHdf5::detail::describeDataset(hid_t file, const std::string& path, const Place& place)
{
    DatasetInfo info;
    info.path = path;
    info.dataset = openDataset(file, path, place);
    Handle space(H5Dget_space(info.dataset.get()), H5Sclose);
    const int rank = space.valid() ? H5Sget_simple_extent_ndims(space.get()) : -1;
    if (rank < 0)
        place.fail(path, "has no readable dataspace: " + lastHdf5Error());
    if (H5Sget_simple_extent_type(space.get()) == H5S_NULL)
        place.fail(path, "holds no values (a null dataspace)");
    if (rank > 4)
        place.fail(path, "has " + std::to_string(rank) + " axes; at most 4 are read");
    info.dims.resize(static_cast<std::size_t>(rank));
    H5Sget_simple_extent_dims(space.get(), info.dims.data(), nullptr);
    Handle type(H5Dget_type(info.dataset.get()), H5Tclose);
    info.typeClass = type.valid() ? H5Tget_class(type.get()) : H5T_NO_CLASS;
    info.typeSize = type.valid() ? H5Tget_size(type.get()) : 0;
    hsize_t bytes = info.typeSize;
    for (hsize_t dim : info.dims)
    {
        if (!multiply(bytes, dim, bytes))
            place.fail(path, "has dims " + describeDims(info.dims) + " whose product overflows");
    }
    const hsize_t stored = H5Dget_storage_size(info.dataset.get());
    if (bytes > stored * MostExpansion + (hsize_t(1) << 20))
        place.fail(path, "has dims " + describeDims(info.dims) + " (" + std::to_string(bytes) +
                             " bytes) but the file stores " + std::to_string(stored) +
                             " bytes of it: dims that its data cannot fill");
    return info;
}

void osgGlyphsHdf5::detail::requireNumbers(const DatasetInfo& info, const Place& place)
{
    if (info.isNumbers())
        return;
    static const char* const names[] = {"integer",  "float",           "time",     "string",
                                        "bitfield", "opaque",          "compound", "reference",
                                        "enum",     "variable-length", "array"};
    const int index = static_cast<int>(info.typeClass);
    const std::string kind = index >= 0 && index < 11 ? names[index] : "unknown";
    place.fail(info.path, "holds " + kind + " values, not numbers");
}

void osgGlyphsHdf5::detail::readRows(const DatasetInfo& info, const std::vector<hsize_t>& leading,
                                     hsize_t begin, hsize_t end, const Place& place,
                                     const RowSink<float>& sink)
{
    requireNumbers(info, place);
    readBlocks(info, leading, begin, end, place, sink);
}

void osgGlyphsHdf5::detail::readRows(const DatasetInfo& info, const std::vector<hsize_t>& leading,
                                     hsize_t begin, hsize_t end, const Place& place,
                                     const RowSink<double>& sink)
{
    requireNumbers(info, place);
    readBlocks(info, leading, begin, end, place, sink);
}

std::vector<double> osgGlyphsHdf5::detail::readAllDoubles(const DatasetInfo& info, hsize_t limit,
                                                          const Place& place)
{
    return readAll<double>(info, limit, place);
}

std::vector<int64_t> osgGlyphsHdf5::detail::readAllIntegers(const DatasetInfo& info, hsize_t limit,
                                                            const Place& place)
{
    return readAll<int64_t>(info, limit, place);
}

bool osgGlyphsHdf5::detail::hasAttribute(hid_t file, const std::string& object, const std::string& name)
{
    if (objectType(file, object) == H5O_TYPE_UNKNOWN)
        return false;
    const htri_t exists = H5Aexists_by_name(file, object.c_str(), name.c_str(), H5P_DEFAULT);
    H5Eclear2(H5E_DEFAULT);
    return exists > 0;
}

std::vector<double> osgGlyphsHdf5::detail::readAttributeNumbers(hid_t file, const std::string& object,
                                                                const std::string& name, std::size_t limit,
                                                                const Place& place)
{
    const std::string where = object + "@" + name;
    Handle attribute = openAttribute(file, object, name, place);
    Handle type(H5Aget_type(attribute.get()), H5Tclose);
    const H5T_class_t kind = type.valid() ? H5Tget_class(type.get()) : H5T_NO_CLASS;
    if (kind != H5T_INTEGER && kind != H5T_FLOAT)
        place.fail(where, "is not a number");
    std::vector<double> values(attributeCount(attribute, where, limit, place));
    if (!values.empty() && H5Aread(attribute.get(), H5T_NATIVE_DOUBLE, values.data()) < 0)
        place.fail(where, "cannot be read: " + lastHdf5Error());
    return values;
}

std::string osgGlyphsHdf5::detail::readObjectReference(hid_t file, const std::string& object,
                                                       const std::string& name, const Place& place)
{
    const std::string where = object + "@" + name;
    Handle attribute = openAttribute(file, object, name, place);
    Handle type(H5Aget_type(attribute.get()), H5Tclose);
    if (!type.valid() || H5Tget_class(type.get()) != H5T_REFERENCE)
        place.fail(where, "is not an object reference");
    if (attributeCount(attribute, where, 1, place) != 1)
        place.fail(where, "holds more than one reference");
    hobj_ref_t reference{};
    if (H5Aread(attribute.get(), H5T_STD_REF_OBJ, &reference) < 0)
        place.fail(where, "cannot be read: " + lastHdf5Error());
    char path[1024] = {};
    const ssize_t length = H5Rget_name(file, H5R_OBJECT, &reference, path, sizeof(path));
    if (length <= 0 || length >= static_cast<ssize_t>(sizeof(path)))
        place.fail(where, "refers to no object of the file");
    return std::string(path, static_cast<std::size_t>(length));
}

bool osgGlyphsHdf5::detail::readIntegerFillValue(const DatasetInfo& info, int64_t& fill)
{
    Handle properties(H5Dget_create_plist(info.dataset.get()), H5Pclose);
    H5D_fill_value_t defined = H5D_FILL_VALUE_UNDEFINED;
    if (!properties.valid() || H5Pfill_value_defined(properties.get(), &defined) < 0 ||
        defined != H5D_FILL_VALUE_USER_DEFINED)
    {
        H5Eclear2(H5E_DEFAULT);
        return false;
    }
    return H5Pget_fill_value(properties.get(), H5T_NATIVE_INT64, &fill) >= 0;
}

std::vector<std::string> osgGlyphsHdf5::detail::readAttributeStrings(hid_t file, const std::string& object,
                                                                     const std::string& name,
                                                                     std::size_t limit, const Place& place)
{
    const std::string where = object + "@" + name;
    Handle attribute = openAttribute(file, object, name, place);
    Handle type(H5Aget_type(attribute.get()), H5Tclose);
    if (!type.valid() || H5Tget_class(type.get()) != H5T_STRING)
        place.fail(where, "is not a string");
    const std::size_t count = static_cast<std::size_t>(attributeCount(attribute, where, limit, place));
    std::vector<std::string> strings;
    Handle memory(H5Tcopy(H5T_C_S1), H5Tclose);
    if (H5Tis_variable_str(type.get()) > 0)
    {
        H5Tset_size(memory.get(), H5T_VARIABLE);
        std::vector<char*> pointers(count, nullptr);
        if (H5Aread(attribute.get(), memory.get(), pointers.data()) < 0)
            place.fail(where, "cannot be read: " + lastHdf5Error());
        for (char* text : pointers)
            strings.emplace_back(text ? text : "");
        Handle space(H5Aget_space(attribute.get()), H5Sclose);
        H5Dvlen_reclaim(memory.get(), space.get(), H5P_DEFAULT, pointers.data());
        return strings;
    }
    const std::size_t size = H5Tget_size(type.get());
    if (size == 0 || size > 4096)
        place.fail(where, "has strings of " + std::to_string(size) + " bytes");
    H5Tset_size(memory.get(), size);
    std::vector<char> bytes(count * size);
    if (H5Aread(attribute.get(), memory.get(), bytes.data()) < 0)
        place.fail(where, "cannot be read: " + lastHdf5Error());
    for (std::size_t i = 0; i < count; ++i)
    {
        const char* text = bytes.data() + i * size;
        strings.emplace_back(text, std::find(text, text + size, '\0'));
    }
    return strings;
}

std::vector<std::string> osgGlyphsHdf5::detail::listMembers(hid_t file, const std::string& group,
                                                            const Place& place)
{
    Handle handle = openGroup(file, group, place);
    std::vector<std::string> names;
    hsize_t index = 0;
    if (H5Literate(handle.get(), H5_INDEX_NAME, H5_ITER_INC, &index, collectName, &names) < 0)
        place.fail(group, "cannot list its members: " + lastHdf5Error());
    return names;
}
