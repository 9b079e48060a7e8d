/* HDF5 files of a given structure, written through HDF5's C library: the H5MD test's malformed
 * files and the HDF5 fuzz target's (tests/fuzz/FuzzHdf5.cpp). */

#ifndef OSGGLYPHS_TESTS_HDF5LAYOUT_H
#define OSGGLYPHS_TESTS_HDF5LAYOUT_H 1

#include <hdf5.h>

#include <map>
#include <string>
#include <vector>

namespace hdf5layout
{

enum class Kind
{
    Float,
    Double,
    Int,
    /** Fixed-length strings. */
    String,
    /** Chunked, no value written: what the dims announce is not in the file. */
    Unwritten,
    /** Values that are not numbers (float NaN). */
    NotANumber
};

struct Spec
{
    std::vector<hsize_t> dims;
    Kind kind = Kind::Float;
    /** Values are start + step * (flat index). */
    double start = 0.0;
    double step = 0.5;
    /** Chunked and gzip-compressed. */
    bool gzip = false;
};

/** Dataset paths and what each holds. */
using Layout = std::map<std::string, Spec>;

/** An H5MD file of frames x particles: time-dependent position and id, fixed species, a fixed
 * box vector; steps 0, 10, 20, ... */
inline Layout smallH5md(hsize_t frames = 3, hsize_t particles = 4)
{
    Layout layout;
    for (const char* element : {"position", "id"})
    {
        const std::string path = std::string("/particles/all/") + element;
        layout[path + "/value"] = element == std::string("position")
                                      ? Spec{{frames, particles, 3}, Kind::Float, 0.0, 0.5}
                                      : Spec{{frames, particles}, Kind::Int, 1.0, 1.0};
        layout[path + "/step"] = {{frames}, Kind::Int, 0.0, 10.0};
        layout[path + "/time"] = {{frames}, Kind::Double, 0.0, 0.05};
    }
    layout["/particles/all/species"] = {{particles}, Kind::Int, 1.0, 0.0};
    layout["/particles/all/box/edges"] = {{3}, Kind::Double, 10.0, 0.0};
    return layout;
}

inline hid_t fileType(Kind kind)
{
    switch (kind)
    {
    case Kind::Double:
        return H5T_IEEE_F64LE;
    case Kind::Int:
        return H5T_STD_I64LE;
    default:
        return H5T_IEEE_F32LE;
    }
}

inline void writeDataset(hid_t file, const std::string& path, const Spec& spec)
{
    hid_t links = H5Pcreate(H5P_LINK_CREATE);
    H5Pset_create_intermediate_group(links, 1);
    hid_t space = spec.dims.empty() ? H5Screate(H5S_SCALAR)
                                    : H5Screate_simple(int(spec.dims.size()), spec.dims.data(), nullptr);
    hid_t create = H5Pcreate(H5P_DATASET_CREATE);
    if ((spec.gzip || spec.kind == Kind::Unwritten) && !spec.dims.empty())
    {
        std::vector<hsize_t> chunk(spec.dims);
        for (hsize_t& dim : chunk)
            dim = dim == 0 ? 1 : (dim > 64 ? 64 : dim);
        H5Pset_chunk(create, int(chunk.size()), chunk.data());
        if (spec.gzip)
            H5Pset_deflate(create, 6);
    }
    hid_t type = spec.kind == Kind::String ? H5Tcopy(H5T_C_S1) : H5Tcopy(fileType(spec.kind));
    if (spec.kind == Kind::String)
        H5Tset_size(type, 8);
    hid_t dataset = H5Dcreate2(file, path.c_str(), type, space, links, create, H5P_DEFAULT);
    hsize_t count = 1;
    for (hsize_t dim : spec.dims)
        count *= dim;
    if (dataset >= 0 && spec.kind != Kind::Unwritten && count < (hsize_t(1) << 24))
    {
        if (spec.kind == Kind::String)
        {
            std::vector<char> text(count * 8, 'a');
            H5Dwrite(dataset, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, text.data());
        }
        else
        {
            std::vector<double> values(count);
            for (hsize_t i = 0; i < count; ++i)
                values[i] = spec.kind == Kind::NotANumber ? 0.0 / 0.0 : spec.start + spec.step * double(i);
            H5Dwrite(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
        }
    }
    if (dataset >= 0)
        H5Dclose(dataset);
    H5Tclose(type);
    H5Pclose(create);
    H5Sclose(space);
    H5Pclose(links);
}

/** Writes the layout to path (replacing the file); false when HDF5 cannot create it. */
inline bool writeLayout(const std::string& path, const Layout& layout)
{
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    if (file < 0)
        return false;
    for (const auto& [dataset, spec] : layout)
        writeDataset(file, dataset, spec);
    H5Fclose(file);
    return true;
}

}

#endif
