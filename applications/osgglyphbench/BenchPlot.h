// osgglyphbench: --plot, frames per second against n drawn by gnuplot.

#ifndef OSGGLYPHBENCH_BENCHPLOT_H
#define OSGGLYPHBENCH_BENCHPLOT_H 1

#include "BenchMeasurement.h"

#include <string>
#include <vector>

/** Writes settings.plotFile with gnuplot from a script and data in a temporary folder: one log-log
 * panel per shape, one line per technique. False, with a message, when gnuplot is missing or
 * fails. */
bool writePlot(const std::vector<BenchResult>& results, const BenchSettings& settings,
               const std::string& renderer);

#endif
