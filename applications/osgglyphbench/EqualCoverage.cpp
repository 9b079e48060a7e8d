#include "EqualCoverage.h"

#include "BenchText.h"

#include <osgGlyphsData/RandomCloud>

#include <algorithm>
#include <cmath>
#include <iostream>

namespace
{

/** The fraction of the view that n glyphs of this shape and radius cover in one untimed frame of
 * the default technique; negative with a one-line error when it cannot be measured. */
double measureCoverage(osgGlyphs::GlyphShape shape, unsigned int n, float radius,
                       const BenchSettings& settings, std::string& error)
{
    BenchSettings once = settings;
    once.frames = 1;
    BenchResult result;
    std::string renderer;
    if (!measureCase(BenchCase{osgGlyphs::DEFAULT_GLYPH_TECHNIQUE, shape, n}, radius, once, result, renderer,
                     error))
        return -1.0;
    return result.coverage;
}

/** Scales radius until glyphs of the case's shape cover target, as the spheres do. Coverage grows
 * as a power of the radius, close to 2; each step solves for the power through the last two
 * frames. Returns the radius, and in coverage what it covers; 0 when it cannot be measured (with
 * error set when a frame failed). */
double scaleToCoverage(const BenchCase& c, double radius, double target, const BenchSettings& settings,
                       double& coverage, std::string& error)
{
    double scaled = radius, power = 2.0;
    double lastScaled = 0.0, lastCoverage = 0.0;
    for (int step = 0; step < 5; ++step)
    {
        coverage = measureCoverage(c.shape, c.n, static_cast<float>(scaled), settings, error);
        if (target <= 0.0 || coverage <= 0.0)
            return 0.0;
        if (std::fabs(coverage / target - 1.0) < 0.02)
            break;
        if (lastCoverage > 0.0 && lastCoverage != coverage)
            power = std::clamp(std::log(coverage / lastCoverage) / std::log(scaled / lastScaled), 0.5, 4.0);
        lastScaled = scaled;
        lastCoverage = coverage;
        scaled *= std::pow(target / coverage, 1.0 / power);
    }
    return scaled;
}

}

float getCaseRadius(const BenchCase& c, const BenchSettings& settings, CaseRadii& found, std::string& error)
{
    const float radius = settings.radius > 0.0f          ? settings.radius
                         : settings.radiusSpacing > 0.0f ? settings.radiusSpacing / std::cbrt(float(c.n))
                                                         : osgGlyphsData::getDefaultRandomRadius(c.n);
    if (!settings.equalCoverage || c.shape == osgGlyphs::GlyphShape::Sphere)
        return radius;
    const std::pair<int, unsigned int> key(static_cast<int>(c.shape), c.n);
    if (found.count(key))
        return found[key];
    const double target = measureCoverage(osgGlyphs::GlyphShape::Sphere, c.n, radius, settings, error);
    double coverage = 0.0;
    const double scaled = target > 0.0 ? scaleToCoverage(c, radius, target, settings, coverage, error) : 0.0;
    if (scaled <= 0.0)
    {
        if (error.empty())
            error = "--equal-coverage: the spheres or the " + std::string(osgGlyphs::getShapeName(c.shape)) +
                    "s of n=" + std::to_string(c.n) + " cover nothing";
        return 0.0f;
    }
    std::cout << "[equal coverage] " << osgGlyphs::getShapeName(c.shape) << " n=" << c.n << ": radius "
              << format(scaled / radius, 3) << " x the spheres', covering " << format(100.0 * coverage, 1)
              << "% of the view (spheres: " << format(100.0 * target, 1) << "%)" << std::endl;
    return found[key] = static_cast<float>(scaled);
}
