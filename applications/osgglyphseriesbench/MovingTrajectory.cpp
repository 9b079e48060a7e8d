#include "MovingTrajectory.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <random>
#include <vector>

namespace
{

/** A Fortran unformatted record: its length before and after it. */
bool writeRecord(std::FILE* file, const void* data, uint32_t bytes)
{
    return std::fwrite(&bytes, 4, 1, file) == 1 && (bytes == 0 || std::fwrite(data, bytes, 1, file) == 1) &&
           std::fwrite(&bytes, 4, 1, file) == 1;
}

bool writeHeader(std::FILE* file, const MovingTrajectoryOptions& options)
{
    char header[84] = {};
    std::memcpy(header, "CORD", 4);
    int32_t control[20] = {};
    control[0] = static_cast<int32_t>(options.frames); // frames
    control[1] = 0;                                    // first step
    control[2] = 1;                                    // steps between frames
    control[3] = static_cast<int32_t>(options.frames); // steps
    const float timestep = 1.0f;
    std::memcpy(&control[9], &timestep, 4);
    control[19] = 24; // CHARMM version
    std::memcpy(header + 4, control, sizeof(control));
    char title[4 + 80];
    const int32_t titles = 1;
    std::memcpy(title, &titles, 4);
    std::snprintf(title + 4, 80, "%-79s", "osgglyphseriesbench: particles on a random walk");
    const int32_t atoms = static_cast<int32_t>(options.particles);
    return writeRecord(file, header, sizeof(header)) && writeRecord(file, title, sizeof(title)) &&
           writeRecord(file, &atoms, 4);
}

}

bool writeMovingTrajectory(const std::string& path, const MovingTrajectoryOptions& options,
                           std::string& error)
{
    if (options.particles == 0 || options.particles > (uint64_t(1) << 30) / 4 || options.frames == 0)
    {
        error = "from 1 to 268,435,456 particles (a DCD record of 4 bytes each) and 1 frame or more";
        return false;
    }
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "wb"), &std::fclose);
    if (!file || !writeHeader(file.get(), options))
    {
        error = path + ": cannot be written";
        return false;
    }
    const std::size_t n = static_cast<std::size_t>(options.particles);
    const float side = static_cast<float>(std::cbrt(double(n)));
    std::mt19937 random(options.seed);
    std::uniform_real_distribution<float> inside(0.0f, side), move(-options.step, options.step);
    std::vector<float> axes[3];
    for (std::vector<float>& axis : axes)
    {
        axis.resize(n);
        for (float& value : axis)
            value = inside(random);
    }
    for (unsigned int frame = 0; frame < options.frames; ++frame)
    {
        if (frame > 0)
            for (std::vector<float>& axis : axes)
                for (float& value : axis)
                    value += move(random);
        for (const std::vector<float>& axis : axes)
            if (!writeRecord(file.get(), axis.data(), static_cast<uint32_t>(n * 4)))
            {
                error = path + ": cannot be written (disk full?)";
                return false;
            }
    }
    if (std::fclose(file.release()) != 0)
    {
        error = path + ": cannot be written";
        return false;
    }
    return true;
}
