// Not a test: measures what GlyphCloud's setters and dirtyGlyphs() cost on the CPU, the median
// of several runs each, and the peak resident memory of building one large cloud.
//
//   cloud_update_cost [N=1000000] [EDITED=100000] [RUNS=7]
//   cloud_update_cost --build-peak N     builds one cloud of N glyphs and prints peak RSS
#include <osgGlyphs/GlyphCloud>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <iostream>
#include <random>
#include <vector>

namespace
{

double milliseconds(const std::function<void()>& work)
{
    const auto start = std::chrono::steady_clock::now();
    work();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

double median(std::vector<double> values)
{
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

struct Arrays
{
    osg::ref_ptr<osg::Vec3Array> positions = new osg::Vec3Array;
    osg::ref_ptr<osg::FloatArray> radii = new osg::FloatArray;
    osg::ref_ptr<osg::FloatArray> scalars = new osg::FloatArray;
};

Arrays makeArrays(unsigned int n)
{
    Arrays arrays;
    std::mt19937 random(1);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    arrays.positions->reserve(n);
    arrays.radii->reserve(n);
    arrays.scalars->reserve(n);
    for (unsigned int i = 0; i < n; ++i)
    {
        arrays.positions->push_back(osg::Vec3(unit(random), unit(random), unit(random)));
        arrays.radii->push_back(0.001f + 0.001f * unit(random));
        arrays.scalars->push_back(unit(random));
    }
    return arrays;
}

osg::ref_ptr<osgGlyphs::GlyphCloud> build(const Arrays& arrays)
{
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = new osgGlyphs::GlyphCloud;
    cloud->setPositions(arrays.positions.get());
    cloud->setRadii(arrays.radii.get());
    cloud->setScalars(arrays.scalars.get());
    return cloud;
}

long peakRssMiB()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss / 1024;
}

}

int main(int argc, char** argv)
{
    if (argc == 3 && std::strcmp(argv[1], "--build-peak") == 0)
    {
        const unsigned int n = static_cast<unsigned int>(std::atol(argv[2]));
        Arrays arrays = makeArrays(n);
        const long dataMiB = peakRssMiB();
        const double ms = milliseconds([&] { build(arrays)->getBound(); });
        std::cout << "build_peak n=" << n << " build_ms=" << ms << " rss_before_build_mib=" << dataMiB
                  << " peak_rss_mib=" << peakRssMiB() << std::endl;
        return 0;
    }
    const unsigned int n = argc > 1 ? static_cast<unsigned int>(std::atol(argv[1])) : 1000000;
    const unsigned int edited = argc > 2 ? static_cast<unsigned int>(std::atol(argv[2])) : 100000;
    const int runs = argc > 3 ? std::atoi(argv[3]) : 7;
    Arrays arrays = makeArrays(n);
    std::vector<double> buildMs, editMs, rangeMs, radiiMs;
    for (int run = 0; run < runs; ++run)
    {
        osg::ref_ptr<osgGlyphs::GlyphCloud> cloud;
        buildMs.push_back(milliseconds([&] { cloud = build(arrays); }));
        cloud->getBound();
        editMs.push_back(milliseconds(
            [&]
            {
                for (unsigned int i = 0; i < edited; ++i)
                    (*arrays.positions)[i].x() += 1e-4f;
                arrays.positions->dirty();
                cloud->dirtyGlyphs();
                cloud->getBound();
            }));
        radiiMs.push_back(milliseconds([&] { cloud->setRadii(arrays.radii.get()); }));
        rangeMs.push_back(milliseconds([&] { cloud->setScalarRange(0.25f + 0.01f * run, 0.75f); }));
    }
    std::cout << "n=" << n << " edited=" << edited << " runs=" << runs
              << " median ms: build=" << median(buildMs) << " edit_positions_and_bound=" << median(editMs)
              << " set_radii_again=" << median(radiiMs) << " set_scalar_range=" << median(rangeMs)
              << std::endl;
    return 0;
}
