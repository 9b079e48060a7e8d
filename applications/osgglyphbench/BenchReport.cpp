#include "BenchReport.h"

#include "BenchText.h"

#include <iomanip>
#include <iostream>

const char* const CSV_HEADER =
    "technique,shape,n,width,height,frames,ms_median,ms_min,ms_max,first_frame_ms,"
    "gpu_bytes_per_glyph,data_path,coverage,radius,attributes,culling,overdraw,"
    "submitted,ao,ao_seconds,screen_effects,opacity,transparency,positions,smallest_axis";

namespace
{

/** " ssao", " outline" or " ssao+outline" for a case's screen effects; nothing without. */
std::string describeScreenEffects(ScreenEffectsChoice choice)
{
    switch (choice)
    {
    case ScreenEffectsChoice::AmbientOcclusion:
        return " ssao";
    case ScreenEffectsChoice::Outlines:
        return " outline";
    case ScreenEffectsChoice::Both:
        return " ssao+outline";
    default:
        return "";
    }
}

std::string formatOverdraw(double overdraw)
{
    return overdraw < 0.0 ? "-" : format(overdraw, 2);
}

void printSummaryRow(const BenchResult& result, const BenchResult* floor, const BenchResult* polygons)
{
    std::cout << std::left << std::setw(14) << osgGlyphs::getShapeName(result.shape) << std::setw(10)
              << result.n << std::setw(18) << result.technique << std::setw(11)
              << (std::string(osgGlyphs::getCullingName(result.culling)) +
                  (result.ambientOcclusion ? " ao" : "") + describeScreenEffects(result.screenEffects) +
                  (result.opacity < 1.0f ? std::string(" a ") + getTransparencyName(result.transparency)
                                         : ""))
              << std::right << std::setw(10) << formatMs(result.msMedian) << std::setw(12)
              << formatRatio(result, floor) << std::setw(12) << formatRatio(result, polygons) << std::setw(10)
              << formatOverdraw(result.overdraw) << "\n";
}

}

std::string formatRatio(const BenchResult& result, const BenchResult* reference)
{
    if (!reference)
        return "-";
    const double ratio = result.msMedian / reference->msMedian;
    return format(ratio, ratio >= 10.0 ? 1 : ratio >= 1.0 ? 2 : 3) + "x";
}

std::string getProgressPrefix(std::size_t index, std::size_t total, const BenchCase& c)
{
    const std::string culling = c.culling == osgGlyphs::GlyphCulling::Off
                                    ? ""
                                    : std::string(" culling=") + osgGlyphs::getCullingName(c.culling);
    return "[" + std::to_string(index) + "/" + std::to_string(total) + "] " + c.technique + " " +
           osgGlyphs::getShapeName(c.shape) + " n=" + std::to_string(c.n) + culling +
           (c.ambientOcclusion ? " ao" : "") + describeScreenEffects(c.screenEffects) +
           (c.opacity < 1.0f ? " opacity=" + format(c.opacity, 2) + " " + getTransparencyName(c.transparency)
                             : std::string()) +
           ": ";
}

void printProgress(const BenchResult& result, std::size_t index, std::size_t total)
{
    std::cout << getProgressPrefix(index, total,
                                   BenchCase{result.technique, result.shape, result.n, result.culling,
                                             result.ambientOcclusion, result.screenEffects, result.opacity,
                                             result.transparency})
              << "median " << formatMs(result.msMedian) << " ms (min " << formatMs(result.msMin) << ", max "
              << formatMs(result.msMax) << "), first frame " << formatMs(result.firstFrameMs) << " ms, "
              << format(result.bytesPerGlyph, 1) << " B/glyph, covers " << format(100.0 * result.coverage, 1)
              << "% of the view, " << formatOverdraw(result.overdraw) << " fragments per pixel, "
              << format(100.0 * result.submitted, 1) << "% of the glyphs submitted"
              << (result.ambientOcclusion
                      ? ", ambient occlusion computed in " + format(result.occlusionSeconds, 2) + " s"
                      : std::string())
              << (result.coverage > 0.0 ? "" : " (WARNING: it drew nothing)") << std::endl;
}

void writeCsvRow(std::ostream& csv, const BenchResult& result, const BenchSettings& settings)
{
    csv << result.technique << ',' << osgGlyphs::getShapeName(result.shape) << ',' << result.n << ','
        << settings.width << ',' << settings.height << ',' << settings.frames << ','
        << format(result.msMedian, 4) << ',' << format(result.msMin, 4) << ',' << format(result.msMax, 4)
        << ',' << format(result.firstFrameMs, 4) << ',' << format(result.bytesPerGlyph, 2) << ','
        << getDataPathName(settings.dataPath) << ',' << format(result.coverage, 4) << ','
        << format(result.radius, 7) << ',' << (settings.compressedAttributes ? "compressed" : "float") << ','
        << osgGlyphs::getCullingName(result.culling) << ','
        << (result.overdraw < 0.0 ? "" : format(result.overdraw, 3)) << ',' << format(result.submitted, 4)
        << ',' << (result.ambientOcclusion ? "on" : "off") << ',' << format(result.occlusionSeconds, 3) << ','
        << getScreenEffectsName(result.screenEffects) << ',' << format(result.opacity, 3) << ','
        << (result.opacity < 1.0f ? getTransparencyName(result.transparency) : "") << ','
        << (settings.compressedPositions ? "16" : "float") << ','
        << (osgGlyphs::isAxesShape(result.shape) ? format(settings.smallestAxis, 3) : "") << '\n'
        << std::flush;
}

std::vector<const BenchResult*> findResults(const std::vector<BenchResult>& results,
                                            const std::string& technique, osgGlyphs::GlyphShape shape,
                                            unsigned int n)
{
    std::vector<const BenchResult*> found;
    for (const BenchResult& result : results)
    {
        if (result.technique == technique && result.shape == shape && result.n == n)
            found.push_back(&result);
    }
    return found;
}

const BenchResult* findResult(const std::vector<BenchResult>& results, std::string technique,
                              osgGlyphs::GlyphShape shape, unsigned int n)
{
    const std::vector<const BenchResult*> found = findResults(results, technique, shape, n);
    return found.empty() ? nullptr : found.front();
}

void printSummary(const std::vector<BenchResult>& results, const BenchSettings& settings)
{
    std::cout << "\nSummary: median ms per frame, and relative to points-floor and to polygons (same "
                 "shape and n, this run)\n";
    std::cout << std::left << std::setw(14) << "shape" << std::setw(10) << "n" << std::setw(18) << "technique"
              << std::setw(11) << "culling" << std::right << std::setw(10) << "ms" << std::setw(12)
              << "/floor" << std::setw(12) << "/polygons" << std::setw(10) << "overdraw"
              << "\n";
    for (osgGlyphs::GlyphShape shape : settings.shapes)
    {
        for (unsigned int n : settings.counts)
        {
            const BenchResult* floor = findResult(results, "points-floor", shape, n);
            const BenchResult* polygons = findResult(results, "polygons", shape, n);
            for (const std::string& technique : settings.techniques)
            {
                for (const BenchResult* result : findResults(results, technique, shape, n))
                    printSummaryRow(*result, floor, polygons);
            }
        }
    }
    std::cout << std::flush;
}
