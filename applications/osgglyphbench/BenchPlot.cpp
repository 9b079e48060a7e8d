#include "BenchPlot.h"

#include "BenchReport.h"

#include <osgGlyphs/GlyphCloud>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include <unistd.h>

namespace
{

std::string findExecutable(const std::string& name)
{
    const char* path = std::getenv("PATH");
    std::istringstream folders(path ? path : "");
    std::string folder;
    while (std::getline(folders, folder, ':'))
    {
        const std::string candidate = (folder.empty() ? std::string(".") : folder) + "/" + name;
        if (access(candidate.c_str(), X_OK) == 0)
            return candidate;
    }
    return std::string();
}

/** A string literal in gnuplot's single quotes. */
std::string quoteGnuplot(const std::string& text)
{
    std::string quoted = "'";
    for (char c : text)
        quoted += c == '\'' ? std::string("''") : std::string(1, c);
    return quoted + "'";
}

/** A word for sh, in single quotes. */
std::string quoteShell(const std::string& text)
{
    std::string quoted = "'";
    for (char c : text)
        quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

/** The same colour for a technique in every panel; the floor is a dashed black reference. A
 * culling other than the default is dotted. */
std::string getLineStyle(std::string technique, osgGlyphs::GlyphCulling culling)
{
    if (technique == "points-floor")
        return "lc rgb '#000000' dt 2 lw 2 pt 7 ps 0.8";
    static const char* const colors[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728",
                                         "#9467bd", "#8c564b", "#e377c2", "#17becf"};
    const std::vector<std::string> all = osgGlyphs::getTechniqueNames();
    const size_t index = std::find(all.begin(), all.end(), technique) - all.begin();
    static const osgGlyphs::GlyphCulling defaultCulling =
        osg::ref_ptr<osgGlyphs::GlyphCloud>(new osgGlyphs::GlyphCloud)->getCulling();
    const bool byDefault = culling == defaultCulling;
    return std::string("lc rgb '") + colors[index % 8] + "' lw 2 pt " + (byDefault ? "7" : "6") + " ps 0.8" +
           (byDefault ? "" : " dt 3");
}

/** One data file per (shape, technique, culling measured): n, fps at the median, at the slowest
 * and the fastest frame. Returns the plot command of the shape's panel, or an empty string
 * without data. A line is named by its culling too when more than one culling was measured. */
std::string writePanelData(const std::filesystem::path& folder, const std::vector<BenchResult>& results,
                           const BenchSettings& settings, osgGlyphs::GlyphShape shape)
{
    std::string plot;
    for (const std::string& technique : settings.techniques)
    {
        for (osgGlyphs::GlyphCulling culling : settings.cullings)
        {
            const std::string title = settings.cullings.size() > 1
                                          ? technique + ", culling " + osgGlyphs::getCullingName(culling)
                                          : technique;
            const std::string name = std::string(osgGlyphs::getShapeName(shape)) + "-" + technique + "-" +
                                     osgGlyphs::getCullingName(culling) + ".dat";
            std::ofstream data(folder / name);
            bool any = false;
            for (unsigned int n : settings.counts)
            {
                for (const BenchResult* result : findResults(results, technique, shape, n))
                {
                    // Techniques that cannot cull are measured once, with culling off.
                    const bool once = findResults(results, technique, shape, n).size() == 1;
                    if (result->culling != culling && !(once && culling == settings.cullings.front()))
                        continue;
                    data << n << ' ' << 1000.0 / result->msMedian << ' ' << 1000.0 / result->msMax << ' '
                         << 1000.0 / result->msMin << '\n';
                    any = true;
                }
            }
            if (!any)
                continue;
            plot += std::string(plot.empty() ? "plot " : ", \\\n     ") +
                    quoteGnuplot((folder / name).string()) + " using 1:2:3:4 with yerrorlines " +
                    getLineStyle(technique, culling) + " title " + quoteGnuplot(title);
        }
    }
    return plot;
}

/** The gnuplot script: a multiplot of one log-log panel per shape. */
std::string writePlotScript(const std::filesystem::path& folder, const std::vector<BenchResult>& results,
                            const BenchSettings& settings, const std::string& renderer)
{
    const unsigned int panels = static_cast<unsigned int>(settings.shapes.size());
    const unsigned int columns = std::min(panels, 2u), rows = (panels + 1) / 2;
    std::ostringstream script;
    script
        << "set terminal pngcairo size " << 720 * columns << "," << 540 * rows << " font 'sans,11'\n"
        << "set output " << quoteGnuplot(settings.plotFile) << "\n"
        << "set multiplot layout " << rows << "," << columns << " title "
        << quoteGnuplot("osgGlyphs, " + renderer + ", " + std::to_string(settings.width) + "x" +
                        std::to_string(settings.height) + ", " + getDataPathName(settings.dataPath))
        << "\n"
        << "set logscale xy\nset offsets graph 0.03, graph 0.03, 0, 0\nset grid xtics ytics mxtics mytics\n"
        << "set format x '10^{%L}'\n"
        << "set xlabel 'glyphs (N)'\nset ylabel 'frames per second'\nset key bottom left box opaque\n";
    for (osgGlyphs::GlyphShape shape : settings.shapes)
    {
        const std::string plot = writePanelData(folder, results, settings, shape);
        script << "set title "
               << quoteGnuplot(std::string(osgGlyphs::getShapeName(shape)) +
                               "s: median, bars from the slowest to the fastest frame")
               << "\n"
               << (plot.empty() ? std::string("plot 1/0 notitle") : plot) << "\n";
    }
    script << "unset multiplot\n";
    const std::filesystem::path file = folder / "plot.gp";
    std::ofstream(file) << script.str();
    return file.string();
}

}

bool writePlot(const std::vector<BenchResult>& results, const BenchSettings& settings,
               const std::string& renderer)
{
    const std::string gnuplot = findExecutable("gnuplot");
    if (gnuplot.empty())
    {
        std::cerr << PROGRAM << ": error: --plot needs gnuplot, which is not on PATH: install the Debian "
                  << "package gnuplot-nox (apt-get install gnuplot-nox). No plot written"
                  << (settings.csvFile.empty() ? "." : "; the CSV is in " + settings.csvFile + ".")
                  << std::endl;
        return false;
    }
    std::string folder = (std::filesystem::temp_directory_path() / "osgglyphbench-XXXXXX").string();
    if (!mkdtemp(&folder[0]))
    {
        std::cerr << PROGRAM << ": error: cannot create a temporary folder for the plot" << std::endl;
        return false;
    }
    const std::string script = writePlotScript(folder, results, settings, renderer);
    if (std::system((quoteShell(gnuplot) + " " + quoteShell(script)).c_str()) != 0)
    {
        std::cerr << PROGRAM << ": error: gnuplot failed on " << script << std::endl;
        return false;
    }
    std::filesystem::remove_all(folder);
    std::cout << PROGRAM << ": wrote " << settings.plotFile << std::endl;
    return true;
}
