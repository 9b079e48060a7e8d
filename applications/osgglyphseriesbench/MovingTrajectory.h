// osgglyphseriesbench: a DCD trajectory of particles that move a little each frame, as in a
// simulation, of any size (the benchmark's input).

#ifndef OSGGLYPHSERIESBENCH_MOVINGTRAJECTORY_H
#define OSGGLYPHSERIESBENCH_MOVINGTRAJECTORY_H 1

#include <cstdint>
#include <string>

struct MovingTrajectoryOptions
{
    uint64_t particles = 1000000;
    unsigned int frames = 20;
    /** Each coordinate moves by up to this each frame; particles are 1 apart on average. */
    float step = 0.05f;
    unsigned int seed = 1;
};

/** Writes the trajectory (CHARMM DCD, little-endian, float32 coordinates, no unit cell): random
 * positions in a cube of side cbrt(particles), then a random walk; false with error. */
bool writeMovingTrajectory(const std::string& path, const MovingTrajectoryOptions& options,
                           std::string& error);

#endif
