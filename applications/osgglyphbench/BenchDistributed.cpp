#include "BenchDistributed.h"
#include "BenchMeasurement.h"

#include <osgGlyphsComposite/ImageCompositor>
#include <osgGlyphsComposite/MPIShare>
#include <osgGlyphsComposite/SharedCloud>
#include <osgGlyphsData/RandomCloud>
#include <osgGlyphsHeadless/OffscreenViewer>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>

namespace
{

using osgGlyphsComposite::ImageCompositor;
using osgGlyphsComposite::MPIShare;

/** The phases of one frame, in ms, each of the slowest process. */
struct Phases
{
    double render = 0.0, readBack = 0.0, wait = 0.0, composite = 0.0, writeBack = 0.0, total = 0.0;
};

double median(std::vector<double> values)
{
    std::sort(values.begin(), values.end());
    const std::size_t middle = values.size() / 2;
    return values.size() % 2 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

bool measure(const MPIShare& mpi, const BenchSettings& settings, osgGlyphs::GlyphShape shape,
             unsigned int count, Phases& result, std::string& error)
{
    osgGlyphsData::RandomCloudOptions options;
    options.count = count;
    options.seed = settings.seed;
    options.shape = shape;
    options.radius = settings.radius;
    options.share = mpi.getShare();
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = osgGlyphsData::createRandomCloud(options);
    cloud->setTechnique(osgGlyphs::createTechnique(settings.techniques.front()).get());
    cloud->setCulling(settings.cullings.front());
    osgGlyphsComposite::shareCloud(*cloud, mpi);

    osg::ref_ptr<osgGlyphsHeadless::OffscreenViewer> viewer =
        new osgGlyphsHeadless::OffscreenViewer(settings.width, settings.height, settings.backend);
    error = viewer->getContextError();
    if (!mpi.agree(viewer->valid(), error))
        return false;
    const osg::ref_ptr<ImageCompositor> compositor = new ImageCompositor(&mpi);
    viewer->getCamera()->setPostDrawCallback(compositor.get());
    viewer->getFrameCapture()->setCaptureDepth(false);
    viewer->setSceneData(cloud.get());

    std::vector<double> render, readBack, wait, composite, writeBack, total;
    for (unsigned int frame = 0; frame <= settings.frames; ++frame)
    {
        placeBenchCamera(*viewer->getCamera(), frame);
        const auto start = std::chrono::steady_clock::now();
        viewer->frame();
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        if (frame == 0)
            continue; // shader compilation, buffer uploads
        const ImageCompositor::Timing& t = compositor->getLastTiming();
        const double others = 1e3 * (t.readBack + t.wait + t.composite + t.writeBack);
        render.push_back(mpi.getMaximum(ms - others));
        readBack.push_back(mpi.getMaximum(1e3 * t.readBack));
        wait.push_back(mpi.getMaximum(1e3 * t.wait));
        composite.push_back(mpi.getMaximum(1e3 * t.composite));
        writeBack.push_back(mpi.getMaximum(1e3 * t.writeBack));
        total.push_back(mpi.getMaximum(ms));
    }
    result = Phases{median(render),    median(readBack),  median(wait),
                    median(composite), median(writeBack), median(total)};
    return true;
}

}

int runDistributedBenchmark(const BenchSettings& settings)
{
    const osg::ref_ptr<MPIShare> mpi = new MPIShare;
    const bool output = mpi->getRank() == 0;
    std::ofstream csv;
    if (output && !settings.csvFile.empty())
    {
        csv.open(settings.csvFile);
        csv << "processes,shape,glyphs,width,height,render_ms,readback_ms,wait_ms,composite_ms,writeback_ms,"
               "frame_ms\n";
    }
    if (output)
        std::printf("%s: sort-last over %d processes, %dx%d, median of %u frames, slowest process per phase\n"
                    "%-8s %10s %10s %10s %10s %10s %10s %10s\n",
                    PROGRAM, mpi->getSize(), settings.width, settings.height, settings.frames, "shape",
                    "glyphs", "render ms", "read ms", "wait ms", "compos. ms", "write ms", "frame ms");
    for (osgGlyphs::GlyphShape shape : settings.shapes)
    {
        for (unsigned int count : settings.counts)
        {
            Phases phases;
            std::string error;
            if (!measure(*mpi, settings, shape, count, phases, error))
            {
                if (output)
                    std::cerr << PROGRAM << ": " << error << std::endl;
                return 1;
            }
            if (!output)
                continue;
            const char* name = osgGlyphs::getShapeName(shape);
            std::printf("%-8s %10u %10.1f %10.1f %10.1f %10.1f %10.1f %10.1f\n", name, count, phases.render,
                        phases.readBack, phases.wait, phases.composite, phases.writeBack, phases.total);
            std::fflush(stdout);
            if (csv.is_open())
                csv << mpi->getSize() << "," << name << "," << count << "," << settings.width << ","
                    << settings.height << "," << phases.render << "," << phases.readBack << "," << phases.wait
                    << "," << phases.composite << "," << phases.writeBack << "," << phases.total << "\n";
        }
    }
    return 0;
}
