// osgglyphviewer under mpirun: each process draws its share, IceT composites onto rank 0.

#ifndef OSGGLYPHVIEWER_DISTRIBUTED_H
#define OSGGLYPHVIEWER_DISTRIBUTED_H 1

#include "ViewerOptions.h"

#include <chrono>
#include <string>

/** Renders the options' scene split over the processes of MPI_COMM_WORLD: each reads (or, with
 * --random, generates) its share of the points, all agree on colour range, radius, framing and
 * near and far planes, each draws its share offscreen, and osgGlyphsComposite composites the
 * pictures by depth onto rank 0, which writes --output and --depth-output: the pictures one
 * process drawing everything writes. optionsRead false: the command line was bad (error). Any
 * failure in one process ends every process with that one error, printed by rank 0. Returns the
 * exit code. */
int renderDistributed(bool optionsRead, const ViewerOptions& options, std::string error,
                      std::chrono::steady_clock::time_point start);

#endif
