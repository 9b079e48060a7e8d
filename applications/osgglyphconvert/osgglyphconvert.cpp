// osgglyphconvert: point data into a paged level-of-detail hierarchy of glyph tiles, in one OSG
// archive (.osga) whose master file is the root: `osgglyphviewer out.osga`, `osgviewer out.osga`.

#include "ConvertProgress.h"
#include "SequentialShares.h"

#include <osgGlyphsData/GlyphMapping>
#include <osgGlyphsData/PointReader>
#include <osgGlyphsData/RandomCloud>
#include <osgGlyphsData/SharedDataset>
#include <osgGlyphsTiles/TileBuilder>

#include <osg/ArgumentParser>
#include <osgDB/FileNameUtils>
#include <osgDB/FileUtils>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <future>
#include <iostream>
#include <limits>

#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace
{

const char* const PROGRAM = "osgglyphconvert";

/** Glyphs of a --random dataset generated at a time. */
const unsigned int RANDOM_BATCH = 1u << 20;

/** Passes over the parts of a file larger than memory before giving up on its mapping settling. */
const unsigned int MAX_SHARE_PASSES = 8;

/** Free memory the allocator keeps for reuse instead of giving it back to the system. */
const int KEPT_FREE_BYTES = 128 << 20;

/** Lets the allocator reuse the memory of each part's and each partition's arrays (tens of MB
 * each, made and freed over and over) instead of mapping fresh pages for every one, which the
 * system then zeroes: a tenth of a large conversion's time went into page faults. */
void keepFreedMemory()
{
#ifdef __GLIBC__
    mallopt(M_MMAP_THRESHOLD, std::numeric_limits<int>::max());
    mallopt(M_TRIM_THRESHOLD, KEPT_FREE_BYTES);
#endif
}

struct ConvertOptions
{
    std::string input;
    std::string output;
    std::string format;
    unsigned int frame = 0;
    unsigned long long randomCount = 0;
    unsigned int seed = 1;
    osgGlyphsData::GlyphMappingOptions mapping;
    osgGlyphsTiles::TileOptions tiles;
};

void describeOptions(osg::ApplicationUsage& usage)
{
    usage.setCommandLineUsage(std::string(PROGRAM) + " [options] <input> <output.osga>\n       " + PROGRAM +
                              " --random <n> [--seed <s>] [options] <output.osga>");
    usage.setDescription(std::string(PROGRAM) +
                         " cuts point data into a paged level-of-detail hierarchy of glyph tiles, in one "
                         "OSG archive that osgglyphviewer, osgviewer and osgDB::readNodeFile open.");
    usage.addCommandLineOption(
        "<input>", "A point file: " +
                       []
                       {
                           std::string names;
                           for (const std::string& name : osgGlyphsData::getSupportedPointFormats())
                               names += (names.empty() ? "" : ", ") + name;
                           return names;
                       }() +
                       " (by extension).");
    usage.addCommandLineOption("--format <name>", "Read the input as this format whatever its extension.");
    usage.addCommandLineOption("--frame <n>",
                               "The frame of a multi-frame input, counted from 0 (default 0).");
    usage.addCommandLineOption("--random <n>", "Instead of a file, n random glyphs in the unit cube with "
                                               "scalars in [0,1) (as osgglyphviewer --random).");
    usage.addCommandLineOption("--seed <s>", "The seed of --random (default 1).");
    osgGlyphsData::describeGlyphMappingArguments(usage);
    usage.addCommandLineOption("--tile-glyphs <n>", "The most glyphs in a leaf tile (default 32768).");
    usage.addCommandLineOption("--tile-cells <n>", "Cells per axis of an inner tile's grid, one glyph "
                                                   "per occupied cell: 2, 4, .., 256 (default 32).");
    usage.addCommandLineOption("--pixels-per-cell <p>", "A tile gives way to its children when a cell of "
                                                        "its grid would span p pixels (default 1.5).");
    usage.addCommandLineOption("--memory-glyphs <n>",
                               "The most glyphs held in memory at a time (default 6000000, about 80 bytes "
                               "each at peak); larger datasets are sorted through temporary files.");
    usage.addCommandLineOption("--temp-dir <dir>", "Where those temporary files go (default: the output's "
                                                   "folder).");
    usage.addCommandLineOption("--float-positions", "Store positions as floats (12 bytes a glyph), exactly "
                                                    "as given, instead of 16-bit integers on a grid over "
                                                    "each tile (6 bytes, within 1/131,064 of the tile).");
    usage.addCommandLineOption("--threads <n>", "Threads cutting tiles (default: one per core).");
    usage.addCommandLineOption("--glyph-budget <n>",
                               "The most glyphs a view of the archive draws, kept in its root for every "
                               "viewer, stock osgviewer included (default 2000000; 0: no budget).");
    usage.addCommandLineOption("-h or --help", "Display this help.");
}

bool readOptions(osg::ArgumentParser& arguments, ConvertOptions& options, std::string& error)
{
    if (!osgGlyphsData::readGlyphMappingArguments(arguments, options.mapping, error))
        return false;
    arguments.read("--format", options.format);
    int frame = 0;
    if (arguments.read("--frame", frame) && frame < 0)
    {
        error = "--frame counts from 0";
        return false;
    }
    options.frame = static_cast<unsigned int>(frame);
    double count = 0.0;
    if (arguments.read("--random", count) && !(count >= 1.0 && count <= 1e12))
    {
        error = "--random needs a number of glyphs from 1 to 1e12";
        return false;
    }
    options.randomCount = static_cast<unsigned long long>(count);
    arguments.read("--seed", options.seed);
    int tileGlyphs = 0, tileCells = 0, threads = 0;
    if (arguments.read("--threads", threads))
    {
        if (threads < 1 || threads > 1024)
        {
            error = "--threads needs a number from 1 to 1024";
            return false;
        }
        options.tiles.threads = static_cast<unsigned int>(threads);
    }
    if (arguments.read("--tile-glyphs", tileGlyphs))
    {
        if (tileGlyphs < 1)
        {
            error = "--tile-glyphs needs a positive number";
            return false;
        }
        options.tiles.maxGlyphsPerTile = static_cast<unsigned int>(tileGlyphs);
    }
    if (arguments.read("--tile-cells", tileCells))
    {
        if (tileCells < 2 || tileCells > 256 || (tileCells & (tileCells - 1)))
        {
            error = "--tile-cells needs a power of two from 2 to 256";
            return false;
        }
        options.tiles.cellsPerAxis = static_cast<unsigned int>(tileCells);
    }
    if (arguments.read("--pixels-per-cell", options.tiles.pixelsPerCell) &&
        !(options.tiles.pixelsPerCell > 0.0f))
    {
        error = "--pixels-per-cell needs a positive number";
        return false;
    }
    double memoryGlyphs = 0.0;
    if (arguments.read("--memory-glyphs", memoryGlyphs))
    {
        if (!(memoryGlyphs >= 1.0 && memoryGlyphs <= 1e12))
        {
            error = "--memory-glyphs needs a number of glyphs from 1 to 1e12";
            return false;
        }
        options.tiles.maxGlyphsInMemory = static_cast<std::size_t>(memoryGlyphs);
    }
    arguments.read("--temp-dir", options.tiles.temporaryDirectory);
    double budget = 0.0;
    if (arguments.read("--glyph-budget", budget))
    {
        if (!(budget >= 0.0 && budget <= 1e12) || budget != std::floor(budget))
        {
            error = "--glyph-budget needs a whole number of glyphs from 0 (no budget) to 1e12";
            return false;
        }
        options.tiles.glyphBudget = static_cast<std::size_t>(budget);
    }
    if (arguments.read("--float-positions"))
        options.tiles.compressedPositions = false;
    for (int i = 1; i < arguments.argc(); ++i)
        if (arguments.isOption(i))
        {
            error = std::string("unknown option ") + arguments[i] + " (see --help)";
            return false;
        }
    const int files = arguments.argc() - 1;
    const int expected = options.randomCount ? 1 : 2;
    if (files != expected)
    {
        error = options.randomCount ? "--random needs one output file and no input (see --help)"
                                    : "needs an input file and an output file (see --help)";
        return false;
    }
    if (!options.randomCount)
        options.input = arguments[1];
    options.output = arguments[files];
    if (options.tiles.temporaryDirectory.empty())
    {
        const std::string folder = osgDB::getFilePath(options.output);
        options.tiles.temporaryDirectory = folder.empty() ? "." : folder;
    }
    if (osgDB::getLowerCaseFileExtension(options.output) != "osga")
    {
        error = options.output + ": the output is an OSG archive, named *.osga";
        return false;
    }
    return true;
}

/** The tiles of a --random dataset, generated a batch at a time. */
osg::ref_ptr<osgGlyphsTiles::TileBuilder> buildRandom(const ConvertOptions& options,
                                                      ConvertProgress& progress, std::string& error)
{
    osgGlyphsData::RandomCloudOptions random;
    random.shape = options.mapping.shape;
    random.lengthScale = options.mapping.lengthScale;
    random.culling = osgGlyphs::GlyphCulling::Off; // the clouds only carry the glyphs to the builder
    random.radius = options.mapping.radius > 0.0f
                        ? options.mapping.radius
                        : osgGlyphsData::getDefaultRandomRadius(static_cast<unsigned int>(
                              std::min<unsigned long long>(options.randomCount, 0xffffffffu)));
    const auto createBatch = [&options, random](unsigned long long first)
    {
        osgGlyphsData::RandomCloudOptions batch = random;
        batch.count = static_cast<unsigned int>(
            std::min<unsigned long long>(RANDOM_BATCH, options.randomCount - first));
        // One seed per batch: the first batch is osgglyphviewer's --random of the same seed.
        batch.seed = options.seed + static_cast<unsigned int>(first / RANDOM_BATCH) * 7919u;
        osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = osgGlyphsData::createRandomCloud(batch);
        osgGlyphsData::applyGlyphStyle(*cloud, options.mapping);
        return cloud;
    };
    progress.start("generating " + std::to_string(options.randomCount) + " random glyphs");
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = createBatch(0);
    osg::ref_ptr<osgGlyphsTiles::TileBuilder> builder =
        new osgGlyphsTiles::TileBuilder(*cloud, options.tiles);
    builder->setColorTitle("random value");
    // Every random position lies in the unit cube: the glyphs past the memory are sorted into
    // octree nodes as they come.
    builder->setBounds(osg::BoundingBoxd(0.0, 0.0, 0.0, 1.0, 1.0, 1.0));
    for (unsigned long long first = 0; first < options.randomCount; first += RANDOM_BATCH)
    {
        // The next batch is made while this one is added.
        const unsigned long long next = first + RANDOM_BATCH;
        std::future<osg::ref_ptr<osgGlyphs::GlyphCloud>> nextCloud;
        if (next < options.randomCount)
            nextCloud = std::async(std::launch::async, createBatch, next);
        if (!builder->addGlyphs(*cloud, error))
            return nullptr;
        progress.update(double(first + cloud->getNumGlyphs()) / options.randomCount);
        if (nextCloud.valid())
            cloud = nextCloud.get();
    }
    return builder;
}

/** Shares a file is read in so that each holds at most about maxGlyphs points: its size over 12
 * bytes, the least a point takes in a binary file (three floats). */
unsigned int sharesOf(const std::string& path, std::size_t maxGlyphs)
{
    std::error_code error;
    const double bytes = static_cast<double>(std::filesystem::file_size(path, error));
    if (error)
        return 1;
    return static_cast<unsigned int>(std::clamp(std::ceil(bytes / 12.0 / double(maxGlyphs)), 1.0, 65536.0));
}

/** A point file, or one share of it, as read. */
struct ReadPoints
{
    osg::ref_ptr<osgGlyphsData::PointDataset> dataset;
    std::string error;
};

ReadPoints readPoints(const ConvertOptions& options, const osgGlyphsData::PointShare& share,
                      ConvertProgress* progress)
{
    osgGlyphsData::PointReadOptions read;
    read.format = options.format;
    if (progress)
        read.progress = [progress](uint64_t done, uint64_t total)
        { progress->update(total ? double(done) / total : 0.0); };
    read.warning = [](const std::string& warning)
    { std::cerr << PROGRAM << ": warning: " << warning << std::endl; };
    read.share = share;
    ReadPoints points;
    points.dataset = osgGlyphsData::readPointFile(options.input, read, points.error);
    return points;
}

/** The box of a file's positions, gathered share by share over a pass: the previous pass's is the
 * whole file's. Invalid when the shares' positions have different origins. */
struct PassBounds
{
    osg::BoundingBoxd previous, current;
    osg::Vec3d previousOrigin, currentOrigin;
    bool sharedOrigin = true;

    void add(const osg::Vec3d& origin, const osg::BoundingBoxd& box)
    {
        if (!current.valid() && sharedOrigin)
            currentOrigin = origin;
        sharedOrigin = sharedOrigin && origin == currentOrigin;
        current.expandBy(box);
    }

    void endPass()
    {
        previous = sharedOrigin ? current : osg::BoundingBoxd();
        previousOrigin = currentOrigin;
        current.init();
        sharedOrigin = true;
    }
};

/** Adds the glyphs of one frame of points read from a file, or from one share of it under
 * shares (which must then be given beginShare() for it), to builder, which is made from the
 * first. */
bool addPoints(const ConvertOptions& options, const ReadPoints& points, SequentialShares* shares,
               PassBounds* bounds, osg::ref_ptr<osgGlyphsTiles::TileBuilder>& builder, std::string& error)
{
    osgGlyphsData::PointDataset* dataset = points.dataset.get();
    error = points.error;
    if (!dataset || (shares && !osgGlyphsData::unifyShares(*dataset, *shares, error)))
        return false;
    if (options.frame >= dataset->getNumFrames())
    {
        error = options.input + ": --frame " + std::to_string(options.frame) + ": the file has " +
                std::to_string(dataset->getNumFrames()) + " frame(s) with points";
        return false;
    }
    osgGlyphsData::GlyphMapper mapper(options.mapping);
    mapper.setReduction(shares);
    mapper.setCulling(osgGlyphs::GlyphCulling::Off); // its clouds only carry the glyphs to the builder
    if (!mapper.prepare(*dataset, options.frame, error))
        return false;
    if (bounds)
        bounds->add(mapper.getPositionOrigin(), mapper.getPositionBounds());
    // Under shares, a pass that has already given the mapping other values than the previous pass
    // is not the last, and its glyphs are not kept.
    if (shares && !shares->isSettled())
        return true;
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = mapper.createCloud(*dataset->getFrame(options.frame), error);
    if (!cloud)
        return false;
    if (!builder)
    {
        std::cerr << PROGRAM << ": " << mapper.describe() << std::endl;
        builder = new osgGlyphsTiles::TileBuilder(*cloud, options.tiles);
        builder->setColorTitle(mapper.getColorKey().title);
        // The whole file's box from the previous pass: the glyphs past the memory are sorted
        // into octree nodes as they come.
        if (bounds && bounds->previous.valid() && bounds->previousOrigin == mapper.getPositionOrigin())
            builder->setBounds(bounds->previous);
    }
    if (!builder->addGlyphs(*cloud, error))
    {
        error = options.input + ": " + error;
        return false;
    }
    return true;
}

/** The tiles of one frame of a point file, read whole or, when larger than the glyphs held in
 * memory, in shares over a few passes (see SequentialShares), each share read while the one
 * before is added. */
osg::ref_ptr<osgGlyphsTiles::TileBuilder> buildFromFile(const ConvertOptions& options,
                                                        ConvertProgress& progress, std::string& error)
{
    osg::ref_ptr<osgGlyphsTiles::TileBuilder> builder;
    const unsigned int count = sharesOf(options.input, options.tiles.maxGlyphsInMemory);
    osgGlyphsData::PointShare share;
    share.count = count;
    if (count == 1)
    {
        progress.start("reading " + options.input);
        return addPoints(options, readPoints(options, share, &progress), nullptr, nullptr, builder, error)
                   ? builder
                   : nullptr;
    }
    const auto readShare = [&options, share](unsigned int index)
    {
        osgGlyphsData::PointShare part = share;
        part.index = index;
        return std::async(std::launch::async, readPoints, std::cref(options), part, nullptr);
    };
    osg::ref_ptr<SequentialShares> shares = new SequentialShares(count);
    PassBounds bounds;
    std::future<ReadPoints> next = readShare(0);
    for (unsigned int pass = 1; pass <= MAX_SHARE_PASSES; ++pass)
    {
        builder = nullptr;
        progress.start("reading " + options.input + ", pass " + std::to_string(pass));
        for (unsigned int index = 0; index < count; ++index)
        {
            const ReadPoints points = next.get();
            // The next share is read meanwhile; after the last, the first again when this pass
            // is already known not to be the last.
            if (index + 1 < count)
                next = readShare(index + 1);
            else if (!shares->isSettled())
                next = readShare(0);
            shares->beginShare(index);
            if (!addPoints(options, points, shares.get(), &bounds, builder, error))
                return nullptr;
            progress.update(double(index + 1) / count);
        }
        if (shares->endPass() && builder)
        {
            progress.finish();
            std::cerr << PROGRAM << ": read " << options.input << " in " << count << " parts, " << pass
                      << (pass == 1 ? " pass" : " passes") << std::endl;
            return builder;
        }
        bounds.endPass();
        if (!next.valid())
            next = readShare(0);
    }
    error = options.input + ": the mapping of its " + std::to_string(count) + " parts did not settle in " +
            std::to_string(MAX_SHARE_PASSES) + " passes (try --radius and --range)";
    return nullptr;
}

}

int main(int argc, char** argv)
{
    keepFreedMemory();
    osg::ArgumentParser arguments(&argc, argv);
    osg::ApplicationUsage* usage = arguments.getApplicationUsage();
    usage->setApplicationName(PROGRAM);
    describeOptions(*usage);
    if (arguments.read("-h") || arguments.read("--help"))
    {
        usage->write(std::cout, osg::ApplicationUsage::COMMAND_LINE_OPTION);
        return 0;
    }
    ConvertOptions options;
    std::string error;
    if (!readOptions(arguments, options, error))
    {
        std::cerr << PROGRAM << ": " << error << std::endl;
        return 2;
    }
    const auto start = std::chrono::steady_clock::now();
    ConvertProgress progress(PROGRAM);
    osg::ref_ptr<osgGlyphsTiles::TileBuilder> builder =
        options.randomCount ? buildRandom(options, progress, error) : buildFromFile(options, progress, error);
    if (builder)
    {
        progress.start("writing " + options.output);
        if (!builder->write(options.output, error, [&progress](double done) { progress.update(done); }))
            builder = nullptr;
    }
    progress.finish();
    if (!builder)
    {
        std::cerr << PROGRAM << ": " << error << std::endl;
        return 1;
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::error_code sizeError;
    const double bytes = static_cast<double>(std::filesystem::file_size(options.output, sizeError));
    const double glyphs = static_cast<double>(builder->getNumGlyphs());
    std::fprintf(stderr,
                 "%s: wrote %s: %.0f glyphs, %.1f MB (%.1f bytes per glyph) in %.2f s (%.2f M glyphs/s)\n",
                 PROGRAM, options.output.c_str(), glyphs, bytes / 1e6, glyphs > 0 ? bytes / glyphs : 0.0,
                 seconds, seconds > 0 ? glyphs / seconds / 1e6 : 0.0);
    return 0;
}
