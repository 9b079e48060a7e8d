// osgglyphbench: a run: every case of the settings, measured in turn and reported.

#ifndef OSGGLYPHBENCH_BENCHRUN_H
#define OSGGLYPHBENCH_BENCHRUN_H 1

#include "BenchOptions.h"

/** Measures every case of the settings, by shape, then n, then technique, printing each as it
 * goes, then the summary; writes --csv as it goes and --plot at the end. Returns the exit code. */
int runBenchmark(const BenchSettings& settings);

#endif
