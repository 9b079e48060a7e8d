// osgglyphbench: what a run reports: its progress, the CSV rows and the summary of ratios.

#ifndef OSGGLYPHBENCH_BENCHREPORT_H
#define OSGGLYPHBENCH_BENCHREPORT_H 1

#include "BenchMeasurement.h"

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

/** The first line of the CSV: its columns. */
extern const char* const CSV_HEADER;

/** "[index/total] technique shape n=N: " */
/** result's median over reference's, as "1.23x"; "-" without a reference. */
std::string formatRatio(const BenchResult& result, const BenchResult* reference);

std::string getProgressPrefix(std::size_t index, std::size_t total, const BenchCase& c);

/** Prints a measured case, prefixed with its progress. */
void printProgress(const BenchResult& result, std::size_t index, std::size_t total);

/** Writes the CSV row of a case and flushes it, so that an interrupted run keeps its rows. */
void writeCsvRow(std::ostream& csv, const BenchResult& result, const BenchSettings& settings);

/** The results of a technique, shape and n, one per culling measured. */
std::vector<const BenchResult*> findResults(const std::vector<BenchResult>& results,
                                            const std::string& technique, osgGlyphs::GlyphShape shape,
                                            unsigned int n);

/** The first result of a technique, shape and n, or null if it was not measured. */
const BenchResult* findResult(const std::vector<BenchResult>& results, std::string technique,
                              osgGlyphs::GlyphShape shape, unsigned int n);

/** Prints ms_median of every case relative to points-floor and to polygons at the same shape and n. */
void printSummary(const std::vector<BenchResult>& results, const BenchSettings& settings);

#endif
