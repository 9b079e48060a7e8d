// osgglyphviewer: views point data files as GPU shader glyphs, in a window or headless.
//
// The parts: ViewerOptions (the command line), DatasetLoading (files, with progress),
// GlyphMapping (columns to glyphs), BuiltinScenes (no file, --random), ViewerScene (frames,
// lighting, legend), ColorLegend (the HUD), ViewerCamera (framing, --frames), Headless
// (--offscreen, --output, --depth-output), Interactive and ViewerEventHandler (the window).

#ifdef OSGGLYPHVIEWER_MPI
#include "Distributed.h"

#include <osgGlyphsComposite/MPIShare>
#endif
#include "Headless.h"
#include "Interactive.h"
#include "ViewerOptions.h"
#include "ViewerScene.h"

#include <osgGlyphs/ProgramErrorFilter>
#include <osgGlyphs/Version>
#include <osgGlyphsPaper/Techniques>
#ifdef OSGGLYPHS_HAVE_HDF5
#include <osgGlyphsHdf5/Hdf5Formats>
#endif

#include <osg/ArgumentParser>

#include <chrono>
#include <iostream>

int main(int argc, char** argv)
{
    const auto start = std::chrono::steady_clock::now();
    osgGlyphsPaper::registerTechniques(); // --technique offers the paper's techniques too
#ifdef OSGGLYPHS_HAVE_HDF5
    osgGlyphsHdf5::registerFormats(); // H5MD, snapshots and --dataset
#endif
    // A glyph program that fails is reported in one line, by the headless and the window loops.
    osg::setNotifyHandler(new osgGlyphs::ProgramErrorFilter(osg::getNotifyHandler()));
    osg::ArgumentParser arguments(&argc, argv);
    osg::ApplicationUsage* usage = arguments.getApplicationUsage();
    usage->setApplicationName(PROGRAM);
    usage->setDescription(std::string(PROGRAM) + " shows point data as GPU shader glyphs (osgGlyphs " +
                          osgGlyphsGetVersion() + "), in a window or headless.");
    usage->setCommandLineUsage(std::string(PROGRAM) + " [options] [file]");
    const bool help = arguments.readHelpType() != osg::ApplicationUsage::NO_HELP;
    describeViewerOptions(*usage);
    describeViewerKeys(*usage);
    if (help)
    {
        std::cout << usage->getDescription() << "\n\n";
        usage->write(std::cout, osg::ApplicationUsage::COMMAND_LINE_OPTION |
                                    osg::ApplicationUsage::KEYBOARD_MOUSE_BINDING);
        return 0;
    }

    ViewerOptions options;
    std::string error;
    const bool optionsRead = readViewerOptions(arguments, options, error);
#ifdef OSGGLYPHVIEWER_MPI
    if (osgGlyphsComposite::isLaunchedByMPI())
        return renderDistributed(optionsRead, options, error, start);
#endif
    osg::ref_ptr<ViewerScene> scene;
    if (optionsRead)
        scene = createViewerScene(options, error);
    if (!scene)
    {
        std::cerr << PROGRAM << ": " << error << std::endl;
        return 1;
    }
    std::cout << PROGRAM << ": " << scene->getDescription() << std::endl;
    return options.offscreen ? renderOffscreen(*scene, options, start)
                             : runInteractive(*scene, options, usage);
}
