#include "Distributed.h"

#include "Headless.h"
#include "TileScene.h"
#include "ViewerScene.h"

#include <osgGlyphsComposite/ImageCompositor>
#include <osgGlyphsComposite/MPIShare>
#include <osgGlyphsComposite/SharedCloud>

#include <cstdio>
#include <iostream>

namespace
{

/** What a distributed rendering cannot do, with why. */
bool checkDistributable(const ViewerOptions& options, std::string& error)
{
    if (!options.offscreen)
        error = "under mpirun the viewer renders --offscreen only";
    else if (options.file.empty() && options.randomCount == 0)
        error = "under mpirun give a point file or --random N: the built-in scene is not split";
    else if (!options.file.empty() && isTileArchive(options.file))
        error = "tile archives are not split under mpirun: give the point file";
    else if (options.follow)
        error = "--follow is not available under mpirun";
    else if (!options.topology.empty())
        error = "--topology is not available under mpirun";
    else if (options.shadows)
        error = "--shadows is not available under mpirun (the shadow map would see one share)";
    else if (options.hasPick)
        error = "--pick is not available under mpirun";
    else
        return true;
    return false;
}

/** "render 41.2 ms, read-back 3.1 ms, composite 5.0 ms, write-back 0.9 ms": each phase of the slowest
 * process. */
std::string describePhases(const osgGlyphsComposite::MPIShare& mpi,
                           const osgGlyphsComposite::ImageCompositor& compositor, double frameMilliseconds)
{
    const osgGlyphsComposite::ImageCompositor::Timing& t = compositor.getLastTiming();
    const double others = 1e3 * (t.readBack + t.wait + t.composite + t.writeBack);
    const double phases[] = {mpi.getMaximum(frameMilliseconds - others), mpi.getMaximum(1e3 * t.readBack),
                             mpi.getMaximum(1e3 * t.wait), mpi.getMaximum(1e3 * t.composite),
                             mpi.getMaximum(1e3 * t.writeBack)};
    char line[240];
    std::snprintf(line, sizeof(line),
                  "render %.1f ms, read-back %.1f ms, waiting %.1f ms, composite %.1f ms, write-back %.1f ms "
                  "(the slowest of %d processes in each)",
                  phases[0], phases[1], phases[2], phases[3], phases[4], mpi.getSize());
    return line;
}

}

int renderDistributed(bool optionsRead, const ViewerOptions& options, std::string error,
                      std::chrono::steady_clock::time_point start)
{
    const osg::ref_ptr<osgGlyphsComposite::MPIShare> mpi = new osgGlyphsComposite::MPIShare;
    const bool output = mpi->getRank() == 0;
    const auto fail = [output](const std::string& message)
    {
        if (output)
            std::cerr << PROGRAM << ": " << message << std::endl;
        return 1;
    };
    // The command line is the same in every process, and so is what is wrong with it.
    if (!optionsRead || !checkDistributable(options, error))
        return fail(error);

    SceneSharing sharing;
    sharing.share = mpi->getShare();
    sharing.reduction = mpi;
    sharing.agree = [mpi](bool ok, std::string& agreedError) { return mpi->agree(ok, agreedError); };
    sharing.shareCloud = [mpi](osgGlyphs::GlyphCloud& cloud) { osgGlyphsComposite::shareCloud(cloud, *mpi); };
    osg::ref_ptr<ViewerScene> scene = createViewerScene(options, error, sharing);
    if (!mpi->agree(scene.valid(), error))
        return fail(error);
    if (output)
        std::cout << PROGRAM << ": " << scene->getDescription() << " (in rank 0 of " << mpi->getSize()
                  << " processes)" << std::endl;

    const osg::ref_ptr<osgGlyphsComposite::ImageCompositor> compositor =
        new osgGlyphsComposite::ImageCompositor(mpi.get());
    OffscreenSharing offscreen;
    offscreen.compositor = compositor;
    offscreen.output = output;
    offscreen.processName =
        "rank " + std::to_string(mpi->getRank()) + " of " + std::to_string(mpi->getSize());
    offscreen.agree = sharing.agree;
    offscreen.describeFrame = [mpi, compositor](double frameMilliseconds)
    { return describePhases(*mpi, *compositor, frameMilliseconds); };
    return renderOffscreen(*scene, options, start, offscreen);
}
