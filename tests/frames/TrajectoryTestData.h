/* Analytic trajectories written as LAMMPS dumps and XYZ files, plain and compressed, for the frame tests. */

#ifndef OSGGLYPHS_TESTS_TRAJECTORYTESTDATA_H
#define OSGGLYPHS_TESTS_TRAJECTORYTESTDATA_H 1

#include <zlib.h>
#include <zstd.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace trajectorytest
{

/** A folder of its own under the test's temporary directory, emptied. */
inline std::string scratchFolder(const std::string& name)
{
    const std::filesystem::path folder =
        std::filesystem::path(::testing::TempDir()) / ("osgglyphs_frames_" + name);
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder.string();
}

/** Atom id's position at frame f: linear motion x0 + v f, inside a box [0, 10)^3 without wrapping. */
inline double analyticX(int id, int frame)
{
    return 1.0 + 0.01 * id + 0.05 * frame;
}
inline double analyticY(int id, int frame)
{
    return 2.0 + 0.02 * id - 0.03 * frame;
}
inline double analyticZ(int id, int /*frame*/)
{
    return 3.0 + 0.001 * id;
}

/** One LAMMPS frame of atoms 1..atoms in a scrambled order (differently per frame), timestep 100 f. */
inline std::string lammpsFrame(int frame, int atoms)
{
    std::ostringstream out;
    out.precision(9);
    out << "ITEM: TIMESTEP\n" << 100 * frame << "\nITEM: NUMBER OF ATOMS\n" << atoms << "\n";
    out << "ITEM: BOX BOUNDS pp pp pp\n0 10\n0 10\n0 10\nITEM: ATOMS id type x y z vx\n";
    for (int k = 0; k < atoms; ++k)
    {
        const int id = 1 + (k * 7 + frame * 3) % atoms;
        out << id << " " << 1 + id % 2 << " " << analyticX(id, frame) << " " << analyticY(id, frame) << " "
            << analyticZ(id, frame) << " " << 0.5 * frame + id << "\n";
    }
    return out.str();
}

inline std::string lammpsDump(int frames, int atoms)
{
    std::string text;
    for (int f = 0; f < frames; ++f)
        text += lammpsFrame(f, atoms);
    return text;
}

/** An extended XYZ frame of the same motion, in id order. */
inline std::string xyzFrame(int frame, int atoms)
{
    std::ostringstream out;
    out.precision(9);
    out << atoms << "\nProperties=species:S:1:pos:R:3:id:I:1 step=" << 100 * frame << "\n";
    for (int id = 1; id <= atoms; ++id)
        out << (id % 2 ? "C" : "O") << " " << analyticX(id, frame) << " " << analyticY(id, frame) << " "
            << analyticZ(id, frame) << " " << id << "\n";
    return out.str();
}

inline void writeFile(const std::string& path, const std::string& bytes)
{
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    ASSERT_TRUE(out.good()) << path;
}

inline void appendFile(const std::string& path, const std::string& bytes)
{
    std::ofstream out(path, std::ios::binary | std::ios::app);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    ASSERT_TRUE(out.good()) << path;
}

inline std::string readFile(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/** bytes as one gzip member. */
inline std::string gzipBytes(const std::string& bytes)
{
    z_stream stream{};
    EXPECT_EQ(deflateInit2(&stream, 6, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY), Z_OK);
    std::string out(deflateBound(&stream, bytes.size()) + 64, '\0');
    stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
    stream.avail_in = static_cast<uInt>(bytes.size());
    stream.next_out = reinterpret_cast<Bytef*>(out.data());
    stream.avail_out = static_cast<uInt>(out.size());
    EXPECT_EQ(deflate(&stream, Z_FINISH), Z_STREAM_END);
    out.resize(stream.total_out);
    deflateEnd(&stream);
    return out;
}

/** bytes as one zstd frame. */
inline std::string zstdBytes(const std::string& bytes)
{
    std::string out(ZSTD_compressBound(bytes.size()), '\0');
    const std::size_t size = ZSTD_compress(out.data(), out.size(), bytes.data(), bytes.size(), 3);
    EXPECT_FALSE(ZSTD_isError(size));
    out.resize(size);
    return out;
}

}

#endif
