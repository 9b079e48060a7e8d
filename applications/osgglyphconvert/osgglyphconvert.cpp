// osgglyphconvert: point data into a paged level-of-detail hierarchy of glyph tiles, in one OSG
// archive (.osga) whose master file is the root: `osgglyphviewer out.osga`, `osgviewer out.osga`;
// or each frame of a trajectory into an archive of its own (--frame-range, out%04d.osga).

#include "ConvertProgress.h"
#include "FrameRange.h"
#include "SequentialShares.h"
#include "SeriesIndex.h"

#include <osgGlyphsData/FrameSource>
#include <osgGlyphsData/GlyphMapping>
#include <osgGlyphsData/PointReader>
#include <osgGlyphsData/RandomCloud>
#include <osgGlyphsData/SharedDataset>
#include <osgGlyphsData/TrajectoryPlayer>
#include <osgGlyphsTiles/TileBuilder>
#ifdef OSGGLYPHS_HAVE_HDF5
#include <osgGlyphsHdf5/Hdf5Formats>
#endif

#include <osg/ArgumentParser>
#include <osgDB/FileNameUtils>
#include <osgDB/FileUtils>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
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

/** The frames of a trajectory spread over it that the colour range, the radius and the length
 * scale of its archives are taken over (see sampleFrames()). */
const std::size_t SAMPLE_FRAMES = 8;

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
    /** --dataset (repeatable): the HDF5 datasets to read, the positions first. */
    std::vector<std::string> datasets;
    /** --topology: the atoms' names, types and elements of a trajectory of coordinates. */
    std::string topology;
    unsigned int frame = 0;
    /** The frames converted: --frame's alone, or --frame-range's, each into an archive named by
     * output as a pattern (formatFramePath()). */
    FrameRange frames;
    bool hasFrameRange = false;
    /** Of --frame-range: the pattern of the frames' archives (the output itself, or beside the
     * output when that is a series index, .osgt or .osgb). */
    std::string framePattern;
    bool series = false;
    unsigned long long randomCount = 0;
    unsigned int seed = 1;
    osgGlyphsData::GlyphMappingOptions mapping;
    osgGlyphsTiles::TileOptions tiles;
};

void describeOptions(osg::ApplicationUsage& usage)
{
    usage.setCommandLineUsage(std::string(PROGRAM) + " [options] <input> <output.osga>\n       " + PROGRAM +
                              " --frame-range <a:b[:step]> [options] <input> <output%04d.osga>\n       " +
                              PROGRAM + " --random <n> [--seed <s>] [options] <output.osga>");
    usage.setDescription(std::string(PROGRAM) +
                         " cuts point data into a paged level-of-detail hierarchy of glyph tiles, in one "
                         "OSG archive that osgglyphviewer, osgviewer and osgDB::readNodeFile open; or "
                         "each frame of a trajectory into an archive of its own.");
    usage.addCommandLineOption(
        "<input>", "A point file: " +
                       []
                       {
                           std::string names;
                           for (const std::string& name : osgGlyphsData::getSupportedPointFormats())
                               names += (names.empty() ? "" : ", ") + name;
                           return names;
                       }() +
                       " (by extension), also compressed by gzip or zstd (traj.lammpstrj.gz, "
                       "data.csv.zst). The frames of compressed files and of --frame-range are read "
                       "through an index of the file's frames, kept beside it (<input>.glyphindex) for "
                       "the next run.");
    usage.addCommandLineOption("--format <name>", "Read the input as this format whatever its extension.");
    usage.addCommandLineOption(
        "--topology <file>",
        "The atoms of an input that holds only coordinates (DCD, XTC, TRR): a PDB, GRO or LAMMPS data file "
        "(write_data, its atoms sorted by id), or any point file, whose first frame gives every frame the "
        "columns it lacks (id, name, residue, type, species, element, mass, charge, ...), atom by atom in "
        "file order. Its atom count must be the input's. The input is then read as by --frame-range.");
    usage.addCommandLineOption(
        "--dataset <path>", "Of an HDF5 input, a dataset to read (repeatable): the positions first (N x 3), "
                            "then columns (N or N x k). Without it, H5MD and snapshots are read whole.");
    usage.addCommandLineOption(
        "--frame <n>", "The frame of a multi-frame input, counted from 0 (default 0), with the colour "
                       "range of every frame of a plain file; a compressed file's is mapped as by "
                       "--frame-range.");
    usage.addCommandLineOption(
        "--frame-range <a:b[:step]>",
        "Frames a to b (a: to the last), every step-th, each into an archive named by the output as a "
        "pattern with the frame's number (out%04d.osga: out0000.osga, out0010.osga, ..): the archive "
        "--frame would write of it, except that the colour range (over 8 frames spread over the file, fewer "
        "when their points pass --memory-glyphs), "
        "radius and length scale (of its first frame) are the same in every archive, so that one colour "
        "means one value throughout; --range, --radius and --length-scale fix them. A frame larger than "
        "--memory-glyphs is sorted through temporary files, as a large file is. A frame that fails is "
        "reported and skipped, the others converted, and the "
        "exit code is 1.");
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

/** Reads --frame and --frame-range. */
bool readFrameOptions(osg::ArgumentParser& arguments, ConvertOptions& options, std::string& error)
{
    int frame = 0;
    const bool hasFrame = arguments.read("--frame", frame);
    if (hasFrame && frame < 0)
    {
        error = "--frame counts from 0";
        return false;
    }
    options.frame = static_cast<unsigned int>(frame);
    options.frames.first = options.frames.last = options.frame;
    options.frames.option = "--frame " + std::to_string(frame);
    std::string range;
    options.hasFrameRange = arguments.read("--frame-range", range);
    if (options.hasFrameRange && hasFrame)
    {
        error = "--frame and --frame-range do not combine: --frame-range f:f converts frame f alone";
        return false;
    }
    if (options.hasFrameRange && !parseFrameRange(range, options.frames))
    {
        error = "--frame-range '" + range +
                "': expected first:last or first:last:step (first: to the last frame), frames counted from 0";
        return false;
    }
    return true;
}

/** With --frame-range, the output is a pattern that names each frame's archive. */
bool checkOutputPattern(const ConvertOptions& options, std::string& error)
{
    std::string name;
    if (options.series && options.output.find('%') != std::string::npos)
    {
        error = options.output + ": a series' index is one file: name it without a pattern (its frames are " +
                seriesFramePattern("name.osgt") + ")";
        return false;
    }
    if (!osgGlyphsData::formatFramePath(options.framePattern, 0, name))
    {
        error = options.output + ": the output's pattern takes one integer conversion, such as %04d";
        return false;
    }
    if (options.frames.mayHoldSeveral() && options.framePattern.find('%') == std::string::npos)
    {
        error = options.frames.option +
                " writes an archive per frame: name the output with a pattern such as "
                "out%04d.osga, which the frame's number fills in";
        return false;
    }
    return true;
}

bool readOptions(osg::ArgumentParser& arguments, ConvertOptions& options, std::string& error)
{
    if (!osgGlyphsData::readGlyphMappingArguments(arguments, options.mapping, error))
        return false;
    arguments.read("--format", options.format);
    arguments.read("--topology", options.topology);
    for (std::string dataset; arguments.read("--dataset", dataset);)
        options.datasets.push_back(dataset);
    if (!readFrameOptions(arguments, options, error))
        return false;
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
    options.series = options.hasFrameRange && isSeriesIndex(options.output);
    options.framePattern = options.series ? seriesFramePattern(options.output) : options.output;
    if (osgDB::getLowerCaseFileExtension(options.output) != "osga" && !options.series)
    {
        error = options.output + ": the output is an OSG archive, named *.osga" +
                (options.hasFrameRange ? ", or with --frame-range a series' index, *.osgt or *.osgb" : "");
        return false;
    }
    if (!options.topology.empty() && options.randomCount)
    {
        error = "--topology needs a file of frames, not --random";
        return false;
    }
    if (options.hasFrameRange && options.randomCount)
    {
        error = "--frame-range needs a file of frames, not --random";
        return false;
    }
    return !options.hasFrameRange || checkOutputPattern(options, error);
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

void printWarning(const std::string& warning)
{
    std::cerr << PROGRAM << ": warning: " << warning << std::endl;
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
    read.datasets = options.datasets;
    if (progress)
        read.progress = [progress](uint64_t done, uint64_t total)
        { progress->update(total ? double(done) / total : 0.0); };
    read.warning = printWarning;
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

/** Adds the glyphs of a frame, through a prepared mapper, to builder, which is made from the
 * first frame added; bounds, where known, holds every glyph that will be added. */
bool addFrame(const ConvertOptions& options, const osgGlyphsData::GlyphMapper& mapper,
              const osgGlyphsData::PointData& frame, const osg::BoundingBoxd* bounds,
              osg::ref_ptr<osgGlyphsTiles::TileBuilder>& builder, std::string& error)
{
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = mapper.createCloud(frame, error);
    if (!cloud)
        return false;
    if (!builder)
    {
        builder = new osgGlyphsTiles::TileBuilder(*cloud, options.tiles);
        builder->setColorTitle(mapper.getColorKey().title);
        // The glyphs past the memory are sorted into octree nodes as they come.
        if (bounds)
            builder->setBounds(*bounds);
    }
    if (!builder->addGlyphs(*cloud, error))
    {
        error = options.input + ": " + error;
        return false;
    }
    return true;
}

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
    // The whole file's box from the previous pass.
    const bool knownBounds =
        bounds && bounds->previous.valid() && bounds->previousOrigin == mapper.getPositionOrigin();
    const bool first = !builder;
    if (!addFrame(options, mapper, *dataset->getFrame(options.frame),
                  knownBounds ? &bounds->previous : nullptr, builder, error))
        return false;
    if (first)
        std::cerr << PROGRAM << ": " << mapper.describe() << std::endl;
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

/** Whether a file is gzip or zstd compressed, by its name or its first bytes: readPointFile()
 * reads plain files only, a FrameSource these too. */
bool isCompressed(const std::string& path)
{
    const std::string extension = osgDB::getLowerCaseFileExtension(path);
    if (extension == "gz" || extension == "zst")
        return true;
    unsigned char magic[4] = {0, 0, 0, 0};
    std::ifstream file(path, std::ios::binary);
    file.read(reinterpret_cast<char*>(magic), sizeof(magic));
    const std::streamsize size = file.gcount();
    return (size >= 2 && magic[0] == 0x1f && magic[1] == 0x8b) ||
           (size == 4 && magic[0] == 0x28 && magic[1] == 0xb5 && magic[2] == 0x2f && magic[3] == 0xfd);
}

/** A frame of a trajectory as decoded: a frame malformed fails alone. */
struct DecodedFrame
{
    osg::ref_ptr<osgGlyphsData::PointData> data;
    std::string error;
};

DecodedFrame decodeFrame(const osgGlyphsData::FrameSource& source, std::size_t frame)
{
    DecodedFrame decoded;
    decoded.data = frame == 0 ? osg::ref_ptr<osgGlyphsData::PointData>(source.getFirstFrame())
                              : source.readFrame(frame, decoded.error);
    return decoded;
}

std::future<DecodedFrame> decodeLater(const osgGlyphsData::FrameSource& source, std::size_t frame)
{
    return std::async(std::launch::async, decodeFrame, std::cref(source), frame);
}

/** A trajectory opened for conversion: its frames, those converted, and the mapping of them all. */
struct Trajectory
{
    explicit Trajectory(const ConvertOptions& options) : mapper(options.mapping) {}

    osg::ref_ptr<osgGlyphsData::FrameSource> source;
    std::vector<std::size_t> frames;
    osgGlyphsData::GlyphMapper mapper;
    /** The first frame converted, decoded while the mapping is prepared. */
    std::future<DecodedFrame> first;
};

/** The frames the mapping is prepared over: SAMPLE_FRAMES, fewer where their points together would
 * pass --memory-glyphs (at least one). */
std::size_t countSampleFrames(const ConvertOptions& options, const osgGlyphsData::FrameSource& source)
{
    const uint64_t points = std::max<uint64_t>(source.getFrameInfo(0).points, 1);
    return static_cast<std::size_t>(
        std::clamp<uint64_t>(options.tiles.maxGlyphsInMemory / points, 1, SAMPLE_FRAMES));
}

/** Opens the input as a trajectory, indexes its frames, lists those converted, starts decoding the
 * first of them and prepares the mapping of them all over countSampleFrames() frames spread over
 * the file (sampleFrames()), so that colour range, radius and length scale are the same in every
 * frame's archive. */
bool openTrajectory(const ConvertOptions& options, ConvertProgress& progress, Trajectory& trajectory,
                    std::string& error)
{
    osgGlyphsData::FrameSourceOptions sourceOptions;
    sourceOptions.format = options.format;
    sourceOptions.datasets = options.datasets;
    sourceOptions.topology = options.topology;
    sourceOptions.warning = printWarning;
    sourceOptions.progress = [&progress](uint64_t done, uint64_t total)
    { progress.update(total ? double(done) / total : 0.0); };
    progress.start("reading " + options.input);
    trajectory.source = osgGlyphsData::FrameSource::open(options.input, sourceOptions, error);
    if (!trajectory.source)
        return false;
    progress.start("indexing the frames of " + options.input);
    trajectory.source->waitForIndex();
    progress.finish();
    trajectory.frames = listFrames(options.frames, options.input, trajectory.source->getNumFrames(), error);
    if (trajectory.frames.empty())
        return false;
    trajectory.first = decodeLater(*trajectory.source, trajectory.frames[0]);
    trajectory.mapper.setCulling(osgGlyphs::GlyphCulling::Off); // its clouds only carry the glyphs
    const std::size_t samples = countSampleFrames(options, *trajectory.source);
    if (!trajectory.mapper.prepare(*osgGlyphsData::sampleFrames(*trajectory.source, samples), 0, error))
        return false;
    std::cerr << PROGRAM << ": " << trajectory.mapper.describe() << std::endl;
    if (samples < SAMPLE_FRAMES && trajectory.source->getNumFrames() > samples &&
        trajectory.mapper.getColorKey().kind == osgGlyphsData::ColorKey::Scalar && !options.mapping.hasRange)
        std::cerr << PROGRAM << ": the colour range is taken over " << samples << " frame"
                  << (samples == 1 ? "" : "s") << ", all that --memory-glyphs "
                  << options.tiles.maxGlyphsInMemory << " holds of frames of "
                  << trajectory.source->getFrameInfo(0).points << " points; --range fixes it" << std::endl;
    return true;
}

/** The tiles of one frame of a compressed file, read through the index of its frames. */
osg::ref_ptr<osgGlyphsTiles::TileBuilder> buildFromSource(const ConvertOptions& options,
                                                          ConvertProgress& progress, std::string& error)
{
    Trajectory trajectory(options);
    if (!openTrajectory(options, progress, trajectory, error))
        return nullptr;
    const DecodedFrame decoded = trajectory.first.get();
    error = decoded.error;
    osg::ref_ptr<osgGlyphsTiles::TileBuilder> builder;
    return decoded.data && addFrame(options, trajectory.mapper, *decoded.data, nullptr, builder, error)
               ? builder
               : nullptr;
}

osg::ref_ptr<osgGlyphsTiles::TileBuilder> build(const ConvertOptions& options, ConvertProgress& progress,
                                                std::string& error)
{
    if (options.randomCount)
        return buildRandom(options, progress, error);
    if (isCompressed(options.input) || !options.topology.empty())
        return buildFromSource(options, progress, error);
    return buildFromFile(options, progress, error);
}

/** The size of a file written; 0 when it cannot be told. */
double fileBytes(const std::string& path)
{
    std::error_code error;
    const std::uintmax_t bytes = std::filesystem::file_size(path, error);
    return error ? 0.0 : static_cast<double>(bytes);
}

/** What the archives of a frame range hold, for the last line. */
struct SeriesSummary
{
    std::size_t written = 0;
    std::size_t failed = 0;
    double glyphs = 0.0;
    double bytes = 0.0;
};

/** Converts one decoded frame of a trajectory into the archive at path. */
bool writeFrame(const ConvertOptions& options, const Trajectory& trajectory, const DecodedFrame& decoded,
                const std::string& path, const osgGlyphsTiles::TileBuilder::ProgressFunction& progress,
                SeriesSummary& summary, std::string& error)
{
    osg::ref_ptr<osgGlyphsTiles::TileBuilder> builder;
    error = decoded.error;
    if (!decoded.data || !addFrame(options, trajectory.mapper, *decoded.data, nullptr, builder, error) ||
        !builder->write(path, error, progress))
        return false;
    ++summary.written;
    summary.glyphs += static_cast<double>(builder->getNumGlyphs());
    summary.bytes += fileBytes(path);
    return true;
}

void printSeriesSummary(const ConvertOptions& options, const SeriesSummary& summary, double seconds)
{
    std::fprintf(
        stderr,
        "%s: wrote %zu frame%s to %s: %.0f glyph-frames, %.1f MB (%.2f bytes per glyph-frame) in %.2f s "
        "(%.3g M glyph-frames/s)\n",
        PROGRAM, summary.written, summary.written == 1 ? "" : "s", options.output.c_str(), summary.glyphs,
        summary.bytes / 1e6, summary.glyphs > 0 ? summary.bytes / summary.glyphs : 0.0, seconds,
        seconds > 0 ? summary.glyphs / seconds / 1e6 : 0.0);
    if (summary.failed)
        std::fprintf(stderr, "%s: %zu of %zu frames failed\n", PROGRAM, summary.failed,
                     summary.failed + summary.written);
}

/** Converts each frame of --frame-range into its archive, decoding the next frame meanwhile, and
 * returns the exit code: 1 when any frame failed (each says why in a line), the others converted. */
int convertFrameRange(const ConvertOptions& options)
{
    const auto start = std::chrono::steady_clock::now();
    ConvertProgress progress(PROGRAM);
    Trajectory trajectory(options);
    std::string error;
    if (!openTrajectory(options, progress, trajectory, error))
    {
        progress.finish();
        std::cerr << PROGRAM << ": " << error << std::endl;
        return 1;
    }
    const std::vector<std::size_t>& frames = trajectory.frames;
    progress.start("converting " + std::to_string(frames.size()) + " frames");
    SeriesSummary summary;
    osg::ref_ptr<osgGlyphsTiles::TileSeries> series = new osgGlyphsTiles::TileSeries;
    std::future<DecodedFrame> next = std::move(trajectory.first);
    for (std::size_t i = 0; i < frames.size(); ++i)
    {
        const DecodedFrame decoded = next.get();
        if (i + 1 < frames.size())
            next = decodeLater(*trajectory.source, frames[i + 1]);
        std::string path;
        osgGlyphsData::formatFramePath(options.framePattern, frames[i], path);
        const auto update = [&progress, i, &frames](double done)
        { progress.update((i + done) / frames.size()); };
        if (!writeFrame(options, trajectory, decoded, path, update, summary, error))
        {
            progress.finish();
            std::cerr << PROGRAM << ": frame " << frames[i] << " (timestep "
                      << trajectory.source->getFrameInfo(frames[i]).timestep << "): " << error << std::endl;
            ++summary.failed;
        }
        else
            series->addFrame(osgDB::getSimpleFileName(path),
                             static_cast<double>(trajectory.source->getFrameInfo(frames[i]).timestep));
    }
    progress.finish();
    if (options.series && !writeSeriesIndex(*series, options.output, error))
    {
        std::cerr << PROGRAM << ": " << error << std::endl;
        return 1;
    }
    printSeriesSummary(options, summary,
                       std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    return summary.failed ? 1 : 0;
}

}

int main(int argc, char** argv)
{
    keepFreedMemory();
#ifdef OSGGLYPHS_HAVE_HDF5
    osgGlyphsHdf5::registerFormats();
#endif
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
    if (options.hasFrameRange)
        return convertFrameRange(options);
    const auto start = std::chrono::steady_clock::now();
    ConvertProgress progress(PROGRAM);
    osg::ref_ptr<osgGlyphsTiles::TileBuilder> builder = build(options, progress, error);
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
    const double bytes = fileBytes(options.output);
    const double glyphs = static_cast<double>(builder->getNumGlyphs());
    std::fprintf(stderr,
                 "%s: wrote %s: %.0f glyphs, %.1f MB (%.1f bytes per glyph) in %.2f s (%.2f M glyphs/s)\n",
                 PROGRAM, options.output.c_str(), glyphs, bytes / 1e6, glyphs > 0 ? bytes / glyphs : 0.0,
                 seconds, seconds > 0 ? glyphs / seconds / 1e6 : 0.0);
    return 0;
}
