/* osgGlyphs - private: an HDF5 dataset's shape and type, checked against what the file stores,
 * read in blocks of rows through hyperslabs; attributes as numbers and strings. */

#ifndef OSGGLYPHS_HDF5_HDF5DATASET_H
#define OSGGLYPHS_HDF5_HDF5DATASET_H 1

#include "Hdf5Handle.h"

#include <functional>
#include <vector>

namespace osgGlyphsHdf5
{
namespace detail
{

/** The most values per particle that an element may have (a 3x3 tensor, a few more). */
constexpr hsize_t MaxWidth = 16;

struct DatasetInfo
{
    std::string path;
    Handle dataset;
    std::vector<hsize_t> dims;
    H5T_class_t typeClass = H5T_NO_CLASS;
    std::size_t typeSize = 0;

    bool isNumbers() const { return typeClass == H5T_INTEGER || typeClass == H5T_FLOAT; }
    bool isFloat32() const { return typeClass == H5T_FLOAT && typeSize == 4; }
    /** Double precision or 64-bit integers: values that floats cannot keep far from zero. */
    bool isWide() const { return typeSize >= 8 && isNumbers(); }
    /** The product of the dims from axis on (1 past the last). */
    hsize_t countFrom(std::size_t axis) const;
};

/** Opens a dataset and reads its shape and type. Throws at place naming it when it is missing,
 * of rank over 4, or announces more values than the bytes HDF5 stores for it could hold (even
 * compressed): dims that no allocation may trust. */
DatasetInfo describeDataset(hid_t file, const std::string& path, const Place& place);

/** Throws at place unless the dataset holds integers or floating-point numbers. */
void requireNumbers(const DatasetInfo& info, const Place& place);

/** A block of rows: the values of rows [row, row + rows), width values each, row after row. */
template <typename T>
using RowSink = std::function<void(hsize_t row, const T* values, hsize_t rows)>;

/** Reads rows [begin, end) along axis leading.size() of the dataset, with the axes before it at
 * the indices of leading and the axes after it whole (width values a row), in blocks of about a
 * million values, converted to T by HDF5. */
void readRows(const DatasetInfo& info, const std::vector<hsize_t>& leading, hsize_t begin, hsize_t end,
              const Place& place, const RowSink<float>& sink);
void readRows(const DatasetInfo& info, const std::vector<hsize_t>& leading, hsize_t begin, hsize_t end,
              const Place& place, const RowSink<double>& sink);

/** Every value of a small dataset (at most limit values) as doubles, or as integers. */
std::vector<double> readAllDoubles(const DatasetInfo& info, hsize_t limit, const Place& place);
std::vector<int64_t> readAllIntegers(const DatasetInfo& info, hsize_t limit, const Place& place);

/** Whether object (a group or dataset path) has the attribute. */
bool hasAttribute(hid_t file, const std::string& object, const std::string& name);
/** A numeric attribute's values (at most limit); throws at place naming object/@name. */
std::vector<double> readAttributeNumbers(hid_t file, const std::string& object, const std::string& name,
                                         std::size_t limit, const Place& place);
/** A string attribute's strings (fixed or variable length, at most limit). */
std::vector<std::string> readAttributeStrings(hid_t file, const std::string& object, const std::string& name,
                                              std::size_t limit, const Place& place);

/** The path of the object an object reference attribute refers to (H5MD's particles_group);
 * throws at place naming object/@name when it is not one. */
std::string readObjectReference(hid_t file, const std::string& object, const std::string& name,
                                const Place& place);

/** The dataset's fill value as an integer, where its creator defined one; false where not. */
bool readIntegerFillValue(const DatasetInfo& info, int64_t& fill);

/** The names of a group's members, in HDF5's name order. */
std::vector<std::string> listMembers(hid_t file, const std::string& group, const Place& place);

}
}

#endif
