// Not a test: measures GlyphCloud::computeOcclusion() on a dense random cloud (radius 0.4 times
// the mean spacing, as osgglyphbench --radius-spacing 0.4): wall time and the process's CPU time,
// which on a shared machine says what the computation needs.
//
//   occlusion_cost [N=1000000] [THREADS=0 (every core)]
#include <osgGlyphs/GlyphCloud>
#include <osgGlyphsData/RandomCloud>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <iostream>

int main(int argc, char** argv)
{
    osgGlyphsData::RandomCloudOptions options;
    options.count = argc > 1 ? unsigned(std::strtoul(argv[1], nullptr, 10)) : 1000000u;
    options.radius = 0.4f / std::cbrt(float(options.count));
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = osgGlyphsData::createRandomCloud(options);
    osgGlyphs::GlyphOcclusionSettings settings;
    settings.threads = argc > 2 ? unsigned(std::strtoul(argv[2], nullptr, 10)) : 0u;

    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpuStart = std::clock();
    osg::ref_ptr<osg::Vec4ubArray> occlusion = cloud->computeOcclusion(settings);
    const double cpu = double(std::clock() - cpuStart) / CLOCKS_PER_SEC;
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    double open = 0.0;
    for (const osg::Vec4ub& value : *occlusion)
        open += value.a() / 255.0;
    std::cout << "computeOcclusion: " << cloud->getNumGlyphs() << " glyphs, " << wall << " s wall, " << cpu
              << " s CPU (all threads); mean open fraction " << open / occlusion->size() << std::endl;
    return 0;
}
