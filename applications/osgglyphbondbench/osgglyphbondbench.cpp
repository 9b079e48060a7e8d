// osgglyphbondbench: times osgGlyphsData::findBonds, bonds by a distance cutoff per pair of types,
// over random uniform atoms at a typical bonding density (five neighbours within the cutoff on
// average): open, in a periodic box, in a periodic triclinic box, with three types.
//
//   osgglyphbondbench [--atoms N] [--rounds R] [--neighbours K]
//   osgglyphbondbench --render [--atoms N] [--frames F] [--size W H]
//
// Each case runs R rounds (after one that warms up) and prints the median time, the bonds found
// and the ratio to copying the positions once (a std::vector copy of the same atoms): a baseline
// that any pass over the atoms costs, whatever the machine. The CPU time (all threads) beside the
// time says how much the machine's other work slowed the run.
//
// With --render it draws the atoms (dense: radius 0.4 x their mean spacing) alone and with about
// two bonds each, and prints the frame times' ratio (BondRenderCost.h).

#include "BondRenderCost.h"

#include <osgGlyphsData/BondFinder>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <functional>
#include <iomanip>
#include <iostream>
#include <random>
#include <string>
#include <vector>

namespace
{

double seconds()
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

/** The CPU time of the process, all its threads, in seconds. */
double cpuSeconds()
{
    timespec now{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
    return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

/** The median of rounds timings of run (and of the CPU time it took), after one that warms up. */
double medianTime(int rounds, const std::function<void()>& run, double* cpu = nullptr)
{
    run();
    std::vector<double> times, cpus;
    for (int r = 0; r < rounds; ++r)
    {
        const double start = seconds(), cpuStart = cpuSeconds();
        run();
        times.push_back(seconds() - start);
        cpus.push_back(cpuSeconds() - cpuStart);
    }
    std::sort(times.begin(), times.end());
    std::sort(cpus.begin(), cpus.end());
    if (cpu)
        *cpu = cpus[cpus.size() / 2];
    return times[times.size() / 2];
}

}

int main(int argc, char** argv)
{
    std::size_t atoms = 1000000;
    int rounds = 5;
    double neighbours = 5.0;
    bool render = false;
    unsigned int frames = 10;
    int width = 800, height = 600;
    for (int a = 1; a < argc; ++a)
    {
        const std::string arg = argv[a];
        if (arg == "--atoms" && a + 1 < argc)
            atoms = std::strtoull(argv[++a], nullptr, 10);
        else if (arg == "--render")
            render = true;
        else if (arg == "--frames" && a + 1 < argc)
            frames = static_cast<unsigned int>(std::max(1, std::atoi(argv[++a])));
        else if (arg == "--size" && a + 2 < argc)
        {
            width = std::max(1, std::atoi(argv[++a]));
            height = std::max(1, std::atoi(argv[++a]));
        }
        else if (arg == "--rounds" && a + 1 < argc)
            rounds = std::max(1, std::atoi(argv[++a]));
        else if (arg == "--neighbours" && a + 1 < argc)
            neighbours = std::atof(argv[++a]);
        else
        {
            std::cerr << "usage: osgglyphbondbench [--atoms N] [--rounds R] [--neighbours K]\n"
                         "       osgglyphbondbench --render [--atoms N] [--frames F] [--size W H]\n";
            return 2;
        }
    }
    if (render)
        return measureBondRenderCost(atoms, 2.0, frames, width, height);

    // A cutoff of 1.6 with `neighbours` atoms within it on average: the box's volume follows.
    const double cutoff = 1.6;
    const double density = neighbours / (4.0 / 3.0 * M_PI * cutoff * cutoff * cutoff);
    const double side = std::cbrt(static_cast<double>(atoms) / density);
    std::mt19937 random(1);
    std::uniform_real_distribution<double> along(0.0, side);
    std::vector<osg::Vec3f> positions(atoms);
    for (osg::Vec3f& p : positions)
        p.set(float(along(random)), float(along(random)), float(along(random)));
    // The triclinic box has the same volume; its atoms are the same fractional coordinates.
    const osg::Vec3d tilt(0.3 * side, 0.2 * side, -0.25 * side);
    std::vector<osg::Vec3f> tilted(atoms);
    for (std::size_t i = 0; i < atoms; ++i)
    {
        const osg::Vec3f& p = positions[i];
        tilted[i].set(float(p.x() + tilt.x() * p.y() / side + tilt.y() * p.z() / side),
                      float(p.y() + tilt.z() * p.z() / side), p.z());
    }
    std::vector<int> types(atoms);
    std::uniform_int_distribution<int> type(1, 3);
    for (int& t : types)
        t = type(random);
    osgGlyphsData::BondCutoffs typed(cutoff);
    typed.setPairCutoff(1, 1, 1.2);
    typed.setPairCutoff(2, 3, 1.4);
    typed.setPairCutoff(3, 3, 0.0);

    const osgGlyphsData::PeriodicBox box(osg::BoundingBoxd(0, 0, 0, side, side, side));
    const osgGlyphsData::PeriodicBox triclinic(osg::BoundingBoxd(0, 0, 0, side, side, side), tilt);

    std::vector<osg::Vec3f> copy;
    const double copyTime = medianTime(rounds,
                                       [&]
                                       {
                                           copy = positions;
                                           copy.back().x() += 1.0f; // kept
                                       });
    std::cout << "osgglyphbondbench: " << atoms << " atoms in a box of " << std::setprecision(4) << side
              << ", cutoff " << cutoff << ", " << neighbours << " neighbours within it on average; median of "
              << rounds << " rounds\n";
    std::cout << "  copy the positions once   " << std::fixed << std::setprecision(2) << 1e3 * copyTime
              << " ms\n";

    struct Case
    {
        const char* name;
        const std::vector<osg::Vec3f>* positions;
        const std::vector<int>* types;
        const osgGlyphsData::BondCutoffs* cutoffs;
        const osgGlyphsData::PeriodicBox* box;
    };
    const std::vector<int> oneType;
    const osgGlyphsData::BondCutoffs plain(cutoff);
    const Case cases[] = {{"open, one type", &positions, &oneType, &plain, nullptr},
                          {"periodic, one type", &positions, &oneType, &plain, &box},
                          {"periodic, three types", &positions, &types, &typed, &box},
                          {"triclinic periodic, one type", &tilted, &oneType, &plain, &triclinic}};
    int status = 0;
    for (const Case& c : cases)
    {
        std::vector<osgGlyphsData::Bond> bonds;
        std::string error;
        bool ok = true;
        double cpu = 0.0;
        auto find = [&]
        { ok = osgGlyphsData::findBonds(*c.positions, *c.types, *c.cutoffs, c.box, bonds, error) && ok; };
        const double time = medianTime(rounds, find, &cpu);
        if (!ok)
        {
            std::cerr << "osgglyphbondbench: " << c.name << ": " << error << "\n";
            status = 1;
            continue;
        }
        std::cout << "  " << std::left << std::setw(30) << c.name << std::right << std::setw(8) << 1e3 * time
                  << " ms (CPU " << std::setw(7) << 1e3 * cpu << " ms)  " << std::setw(9) << bonds.size()
                  << " bonds (" << std::setprecision(2)
                  << 2.0 * bonds.size() / std::max<std::size_t>(1, atoms) << " per atom)  "
                  << std::setprecision(1) << time / copyTime << " x the copy\n"
                  << std::setprecision(2);
    }
    return status;
}
