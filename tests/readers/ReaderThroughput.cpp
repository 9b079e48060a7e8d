// Throughput of readPointFile on a large LAMMPS dump (not a ctest test: numbers depend on the machine).
//
//   reader_throughput generate <file> [atoms]   writes a dump "id type xu yu zu vx vy vz c_pe" (262144 atoms)
//   reader_throughput read <file> [repeats]     reads it, prints MB/s of the best run and the array size
//   reader_throughput [atoms]                    both, in a temporary file
//
// Peak memory: /usr/bin/time -v reader_throughput read <file> 1

#include <osgGlyphsData/PointReader>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>

namespace
{

bool generate(const std::string& path, unsigned long atoms)
{
    std::FILE* file = std::fopen(path.c_str(), "w");
    if (!file)
        return false;
    const double length = std::cbrt(atoms / 0.8442);
    std::fprintf(file, "ITEM: TIMESTEP\n1000\nITEM: NUMBER OF ATOMS\n%lu\nITEM: BOX BOUNDS pp pp pp\n",
                 atoms);
    for (int axis = 0; axis < 3; ++axis)
        std::fprintf(file, "%.16e %.16e\n", 0.0, length);
    std::fprintf(file, "ITEM: ATOMS id type xu yu zu vx vy vz c_pe\n");
    std::mt19937_64 random(42);
    std::uniform_real_distribution<double> position(0.0, length);
    std::normal_distribution<double> velocity(0.0, 1.1);
    std::normal_distribution<double> energy(-6.7, 0.4);
    for (unsigned long id = 1; id <= atoms; ++id)
    {
        std::fprintf(file, "%lu %lu %.10g %.10g %.10g %.10g %.10g %.10g %.10g\n", id, 1 + id % 3,
                     position(random), position(random), position(random), velocity(random), velocity(random),
                     velocity(random), energy(random));
    }
    return std::fclose(file) == 0;
}

int read(const std::string& path, int repeats)
{
    const double megabytes = static_cast<double>(std::filesystem::file_size(path)) / 1e6;
    double best = 1e30;
    std::size_t arrayBytes = 0;
    for (int run = 0; run < repeats; ++run)
    {
        const auto start = std::chrono::steady_clock::now();
        std::string error;
        osg::ref_ptr<osgGlyphsData::PointDataset> dataset =
            osgGlyphsData::readPointFile(path, osgGlyphsData::PointReadOptions(), error);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (!dataset.valid())
        {
            std::fprintf(stderr, "%s\n", error.c_str());
            return 1;
        }
        best = std::min(best, seconds);
        arrayBytes = 0;
        for (const auto& frame : dataset->getFrames())
            arrayBytes += frame->getNumPoints() * frame->getNumColumns() * sizeof(float);
    }
    std::printf("%s: %.1f MB in %.3f s: %.0f MB/s (best of %d); arrays %.1f MB\n", path.c_str(), megabytes,
                best, megabytes / best, repeats, arrayBytes / 1e6);
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    const std::string mode = argc > 1 ? argv[1] : "";
    if (mode == "generate" && argc > 2)
    {
        const unsigned long atoms = argc > 3 ? std::strtoul(argv[3], nullptr, 10) : 262144ul;
        return generate(argv[2], atoms) ? 0 : 1;
    }
    if (mode == "read" && argc > 2)
        return read(argv[2], argc > 3 ? std::atoi(argv[3]) : 5);
    const unsigned long atoms = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 262144ul;
    const std::string path =
        (std::filesystem::temp_directory_path() / "osgglyphs_throughput.lammpstrj").string();
    if (!generate(path, atoms == 0 ? 262144ul : atoms))
    {
        std::fprintf(stderr, "cannot write %s\n", path.c_str());
        return 1;
    }
    const int result = read(path, 5);
    std::filesystem::remove(path);
    return result;
}
