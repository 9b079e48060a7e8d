#include "BenchRun.h"

#include "BenchPlot.h"
#include "BenchReport.h"
#include "BenchText.h"
#include "EqualCoverage.h"

#include <cstdlib>
#include <fstream>
#include <iostream>

namespace
{

/** Why a technique cannot be measured for a shape on the data path, or nothing. */
std::string whyNotMeasured(const std::string& name, osgGlyphs::GlyphShape shape,
                           const BenchSettings& settings)
{
    const osg::ref_ptr<osgGlyphs::GlyphTechnique> technique = osgGlyphs::createTechnique(name);
    if (!technique->supportsShape(shape))
        return "the library cannot draw it yet";
    if (settings.dataPath == DataPath::DisplayList && !technique->supportsDisplayLists())
        return "GL compiles no instanced draw into a display list";
    return std::string();
}

/** The cullings a technique is measured with: --culling where it can cull, else off (display
 * lists keep one frame's choice of chunks, so clouds drawn from them do not cull). */
std::vector<osgGlyphs::GlyphCulling> getCullings(const std::string& name, const BenchSettings& settings)
{
    if (osgGlyphs::createTechnique(name)->supportsCulling() && settings.dataPath != DataPath::DisplayList)
        return settings.cullings;
    return {osgGlyphs::GlyphCulling::Off};
}

/** Every case to measure, by shape, then n, then technique, so that an interrupted run has
 * every technique at the smaller n. Prints the (technique, shape) pairs skipped. */
std::vector<BenchCase> listCases(const BenchSettings& settings)
{
    std::vector<BenchCase> cases;
    for (osgGlyphs::GlyphShape shape : settings.shapes)
    {
        std::vector<std::string> measured;
        for (const std::string& technique : settings.techniques)
        {
            const std::string why = whyNotMeasured(technique, shape, settings);
            if (why.empty())
                measured.push_back(technique);
            else
                std::cout << "[skipped] " << technique << " " << osgGlyphs::getShapeName(shape) << ": " << why
                          << std::endl;
        }
        for (unsigned int n : settings.counts)
            for (const std::string& technique : measured)
                for (osgGlyphs::GlyphCulling culling : getCullings(technique, settings))
                    for (bool ambientOcclusion : settings.ambientOcclusion)
                        for (ScreenEffectsChoice effects : settings.screenEffects)
                            for (float opacity : settings.opacities)
                                for (osgGlyphs::DepthPeeling::Method transparency :
                                     settings.transparencyMethods)
                                {
                                    if (opacity < 1.0f ||
                                        transparency == settings.transparencyMethods.front())
                                        cases.push_back(BenchCase{technique, shape, n, culling,
                                                                  ambientOcclusion, effects, opacity,
                                                                  transparency});
                                }
    }
    return cases;
}

/** Whether an earlier n of the same technique and shape went over --max-ms. */
bool isOverBudget(const std::vector<BenchResult>& results, const BenchCase& c, const BenchSettings& settings)
{
    if (settings.maxMs <= 0.0)
        return false;
    for (const BenchResult& result : results)
    {
        if (result.technique == c.technique && result.shape == c.shape && result.culling == c.culling &&
            result.ambientOcclusion == c.ambientOcclusion && result.screenEffects == c.screenEffects &&
            result.opacity == c.opacity && result.transparency == c.transparency &&
            result.msMedian > settings.maxMs)
            return true;
    }
    return false;
}

/** Prints the system's 1-minute load average, where /proc/loadavg has it: other processes on
 * the machine make every time noisier. */
void printLoad(const char* when)
{
    std::ifstream file("/proc/loadavg");
    std::string load;
    if (file >> load)
        std::cout << "Load average " << when << ": " << load << std::endl;
}

/** Sets MESA_SHADER_CACHE_DISABLE=true unless the user set it; says which. */
void disableShaderCache()
{
    const bool userSet = std::getenv("MESA_SHADER_CACHE_DISABLE") != nullptr;
    if (!userSet)
        setenv("MESA_SHADER_CACHE_DISABLE", "true", 0);
    std::cout << "MESA_SHADER_CACHE_DISABLE=" << std::getenv("MESA_SHADER_CACHE_DISABLE")
              << (userSet ? " (set by the user)" : "") << std::endl;
}

/** Opens --csv, if given, and writes its header; false when it cannot be written. */
bool openCsv(const BenchSettings& settings, std::ofstream& csv)
{
    if (settings.csvFile.empty())
        return true;
    csv.open(settings.csvFile);
    if (!csv)
    {
        std::cerr << PROGRAM << ": error: cannot write " << settings.csvFile << std::endl;
        return false;
    }
    csv << CSV_HEADER << '\n' << std::flush;
    return true;
}

/** Measures the cases in turn, skipping those over --max-ms, into results and the cases measured,
 * and writes each row to the CSV where there is one; false, with the error printed, when a case
 * cannot be measured (no headless context, a glyph program that fails). */
bool measureCases(const std::vector<BenchCase>& cases, const BenchSettings& settings, CaseRadii& radii,
                  std::ofstream* csv, std::vector<BenchResult>& results, std::vector<BenchCase>& measured,
                  std::string& renderer)
{
    for (size_t i = 0; i < cases.size(); ++i)
    {
        const BenchCase& c = cases[i];
        if (isOverBudget(results, c, settings))
        {
            std::cout << getProgressPrefix(i + 1, cases.size(), c) << "skipped (over --max-ms)" << std::endl;
            continue;
        }
        BenchResult result;
        std::string error;
        const float radius = getCaseRadius(c, settings, radii, error);
        if (radius <= 0.0f || !measureCase(c, radius, settings, result, renderer, error))
        {
            std::cerr << PROGRAM << ": error: " << error << std::endl;
            return false;
        }
        printProgress(result, i + 1, cases.size());
        if (csv && csv->is_open())
            writeCsvRow(*csv, result, settings);
        results.push_back(result);
        measured.push_back(c);
    }
    return true;
}

/** Measures the cases of the first pass settings.repeat - 1 times more, in the same order, and
 * keeps for each the median of its passes' medians, the least minimum and the greatest maximum;
 * the rest (coverage, fragments, glyphs sent) is the first pass's. */
bool repeatCases(const std::vector<BenchCase>& measured, const BenchSettings& settings, CaseRadii& radii,
                 std::vector<BenchResult>& results, std::string& renderer)
{
    std::vector<std::vector<double>> medians(results.size());
    for (size_t i = 0; i < results.size(); ++i)
        medians[i].push_back(results[i].msMedian);
    for (unsigned int pass = 2; pass <= settings.repeat; ++pass)
    {
        std::cout << "[pass " << pass << " of " << settings.repeat << "]" << std::endl;
        std::vector<BenchResult> passResults;
        std::vector<BenchCase> passCases;
        BenchSettings unbounded = settings;
        unbounded.maxMs = 0.0;
        if (!measureCases(measured, unbounded, radii, nullptr, passResults, passCases, renderer))
            return false;
        for (size_t i = 0; i < results.size(); ++i)
        {
            medians[i].push_back(passResults[i].msMedian);
            results[i].msMin = std::min(results[i].msMin, passResults[i].msMin);
            results[i].msMax = std::max(results[i].msMax, passResults[i].msMax);
        }
    }
    for (size_t i = 0; i < results.size(); ++i)
        results[i].msMedian = median(medians[i]);
    return true;
}

}

namespace
{

/** Measures the archive and prints its frame against each case of the run. */
bool measureAndCompareArchive(const BenchSettings& settings, const std::vector<BenchResult>& results)
{
    BenchResult archive;
    unsigned int pagingFrames = 0;
    std::string error;
    if (!measureArchive(settings, archive, pagingFrames, error))
    {
        std::cerr << PROGRAM << ": error: " << error << std::endl;
        return false;
    }
    std::cout << "archive " << settings.archive << ": paged in over " << pagingFrames << " frames; median "
              << formatMs(archive.msMedian) << " ms (min " << formatMs(archive.msMin) << ", max "
              << formatMs(archive.msMax) << ")\n";
    for (const BenchResult& result : results)
        std::cout << "  " << formatRatio(archive, &result) << " the " << result.technique << " "
                  << osgGlyphs::getShapeName(result.shape) << " n=" << result.n << " of this run ("
                  << formatMs(result.msMedian) << " ms)\n";
    return true;
}

}

int runBenchmark(const BenchSettings& settings)
{
    std::ofstream csv;
    if (!openCsv(settings, csv))
        return 1;
    disableShaderCache();
    printLoad("at the start");
    printFrameOverhead(settings);
    const std::vector<BenchCase> cases = listCases(settings);
    std::vector<BenchResult> results;
    std::vector<BenchCase> measured;
    std::string renderer;
    CaseRadii radii;
    // One pass writes its rows as it goes; several, the medians once all have run.
    if (!measureCases(cases, settings, radii, settings.repeat == 1 ? &csv : nullptr, results, measured,
                      renderer) ||
        !repeatCases(measured, settings, radii, results, renderer))
        return 1;
    for (const BenchResult& result : results)
        if (settings.repeat > 1 && csv.is_open())
            writeCsvRow(csv, result, settings);
    if (!settings.archive.empty() && !measureAndCompareArchive(settings, results))
        return 1;
    printLoad("at the end");
    printSummary(results, settings);
    if (csv.is_open())
        std::cout << PROGRAM << ": wrote " << settings.csvFile << std::endl;
    if (!settings.plotFile.empty() && !writePlot(results, settings, renderer))
        return 1;
    return 0;
}
