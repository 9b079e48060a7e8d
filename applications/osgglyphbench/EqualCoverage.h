// osgglyphbench: --equal-coverage, the radius at which vector glyphs cover the view as spheres do.

#ifndef OSGGLYPHBENCH_EQUALCOVERAGE_H
#define OSGGLYPHBENCH_EQUALCOVERAGE_H 1

#include "BenchMeasurement.h"

#include <map>
#include <utility>

/** Radii found by --equal-coverage, by (shape, n). */
typedef std::map<std::pair<int, unsigned int>, float> CaseRadii;

/** The glyph radius of a case: --radius or getDefaultRandomRadius(n); with --equal-coverage, a
 * vector shape's is scaled until it covers the view as spheres of that radius do (within 2%,
 * at most 5 untimed frames), found once per shape and n and kept in found. Prints the radius
 * found. 0 with a one-line error when the frames cannot be measured. */
float getCaseRadius(const BenchCase& c, const BenchSettings& settings, CaseRadii& found, std::string& error);

#endif
