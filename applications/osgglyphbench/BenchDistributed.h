// osgglyphbench under mpirun: sort-last rendering of random clouds split over the processes.

#ifndef OSGGLYPHBENCH_BENCHDISTRIBUTED_H
#define OSGGLYPHBENCH_BENCHDISTRIBUTED_H 1

#include "BenchOptions.h"

/** For every shape and count of the settings (technique and culling: the first given), each
 * process generates its share of the random cloud and draws it offscreen at --size, and
 * osgGlyphsComposite composites the pictures onto rank 0, --frames times after a first frame
 * that is not counted. Rank 0 prints, per case, the median over the frames of each phase's time in
 * the slowest process: render (the draw up to glFinish), read-back, composite (IceT, including
 * the wait) and write-back; with --csv, also as CSV. Returns the exit code. */
int runDistributedBenchmark(const BenchSettings& settings);

#endif
