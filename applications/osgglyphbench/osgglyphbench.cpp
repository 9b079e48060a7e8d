// osgglyphbench: the performance comparison of "Rendering Large Point Datasets with GPU Shaders"
// (Aguirre, Gutierrez, Perrin, TPCG 2010), reproduced and extended on osgGlyphs: frames per
// second of every glyph technique for random clouds of 100 to 1,000,000 glyphs, headless.
//
// The parts: BenchOptions (the command line), BenchRun (the cases, in turn), BenchMeasurement
// (a case's scene, frames, times and coverage), EqualCoverage (--equal-coverage radii),
// BenchReport (progress, CSV, summary) and BenchPlot (--plot, through gnuplot).

#ifdef OSGGLYPHBENCH_MPI
#include "BenchDistributed.h"

#include <osgGlyphsComposite/MPIShare>
#endif
#include "BenchOptions.h"
#include "BenchRun.h"

#include <osgGlyphs/ProgramErrorFilter>
#include <osgGlyphsPaper/Techniques>

#include <osg/ArgumentParser>

#include <iostream>

int main(int argc, char** argv)
{
    osgGlyphsPaper::registerTechniques(); // the paper's techniques are the benchmark's references
    // A glyph program that fails is reported in one line, by measureCases.
    osg::setNotifyHandler(new osgGlyphs::ProgramErrorFilter(osg::getNotifyHandler()));
    osg::ArgumentParser arguments(&argc, argv);
    osg::ApplicationUsage* usage = arguments.getApplicationUsage();
    usage->setApplicationName(PROGRAM);
    describeBenchOptions(*usage);
    if (arguments.read("-h") || arguments.read("--help"))
    {
        printBenchHelp(*usage);
        return 0;
    }
    BenchSettings settings;
    if (!readBenchSettings(arguments, settings))
    {
        arguments.writeErrorMessages(std::cerr);
        std::cerr << "(" << PROGRAM << " --help lists the options)" << std::endl;
        return 1;
    }
#ifdef OSGGLYPHBENCH_MPI
    if (osgGlyphsComposite::isLaunchedByMPI())
        return runDistributedBenchmark(settings);
#endif
    return runBenchmark(settings);
}
