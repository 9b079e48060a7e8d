// osgglyphtrajbench: times the reading and the playback of trajectories (osgGlyphsData::FrameSource,
// FrameCache, TrajectoryPlayer), headless.
//
//   osgglyphtrajbench open   ONE_FRAME_FILE DUMP...   time to the first picture of each file
//   osgglyphtrajbench last   DUMP...                  time to the last frame, first and second open
//   osgglyphtrajbench decode ONE_FRAME_FILE DUMP...   readFrame over all frames, in order and at random
//   osgglyphtrajbench play   DUMP...                  playback against drawing and decoding alone
//   osgglyphtrajbench memory DUMP                     peak memory playing every frame once
//
// Every suite but memory runs its cases in turn, a round at a time (the first round only warms
// up), so that the noise of a shared machine falls on every case alike: compare the ratios
// within one run, not absolute times across runs. Results are printed and appended to --csv;
// share/bench/trajectory_bench.sh runs the whole benchmark.

#include <osgGlyphs/GlyphStateCache>
#include <osgGlyphs/ProgramErrorFilter>
#include <osgGlyphsData/FrameCache>
#include <osgGlyphsData/FrameSource>
#include <osgGlyphsData/GlyphMapping>
#include <osgGlyphsData/PointReader>
#include <osgGlyphsData/TrajectoryPlayer>
#include <osgGlyphsHeadless/OffscreenViewer>
#ifdef OSGGLYPHS_HAVE_HDF5
#include <osgGlyphsHdf5/Hdf5Formats>
#endif

#include <osg/ArgumentParser>
#include <osg/Group>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <numeric>
#include <random>
#include <set>
#include <string>
#include <vector>

#include <sys/resource.h>

namespace
{

const char* const PROGRAM = "osgglyphtrajbench";

double cpuSeconds(clockid_t clock)
{
    timespec now{};
    clock_gettime(clock, &now);
    return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

/** Wall time, and the CPU time of this thread and of the whole process (the index and cache
 * workers, llvmpipe's threads), since it was made. On a loaded machine, the CPU time of the
 * thread that decodes is what the decode would take alone. */
struct Stopwatch
{
    std::chrono::steady_clock::time_point wall = std::chrono::steady_clock::now();
    double thread = cpuSeconds(CLOCK_THREAD_CPUTIME_ID);
    double process = cpuSeconds(CLOCK_PROCESS_CPUTIME_ID);

    double seconds() const
    {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall).count();
    }
};

/** One run of a case: the times it took (its setup left out), the frames (pictures, jumps) and
 * the text bytes in them, and further figures of its own (the seconds of a phase). */
struct Sample
{
    double seconds = 0.0;
    double threadCpu = 0.0;
    double processCpu = 0.0;
    double count = 0.0;
    double bytes = 0.0;
    std::map<std::string, double> extra;

    /** Adds the times since the stopwatch was made: how every case times itself. */
    void add(const Stopwatch& watch)
    {
        seconds += watch.seconds();
        threadCpu += cpuSeconds(CLOCK_THREAD_CPUTIME_ID) - watch.thread;
        processCpu += cpuSeconds(CLOCK_PROCESS_CPUTIME_ID) - watch.process;
    }
};

struct Case
{
    std::string name;
    std::function<bool(unsigned int round, Sample& sample, std::string& error)> run;
};

/** A case's samples, summarised by their medians. */
struct Result
{
    std::string name;
    std::vector<Sample> samples;

    double median(const std::function<double(const Sample&)>& value) const
    {
        std::vector<double> values;
        for (const Sample& sample : samples)
            values.push_back(value(sample));
        std::sort(values.begin(), values.end());
        const std::size_t n = values.size();
        return n == 0 ? 0.0 : n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
    }
    double seconds() const
    {
        return median([](const Sample& s) { return s.seconds; });
    }
    double extra(const std::string& key) const
    {
        return median([&key](const Sample& s) { return s.extra.count(key) ? s.extra.at(key) : 0.0; });
    }
    double count() const { return samples.empty() ? 0.0 : samples.front().count; }
    double bytes() const { return samples.empty() ? 0.0 : samples.front().bytes; }
    double each() const { return seconds() / count(); }
};

/** What every suite shares: the settings, the viewer, the measurement and the report. */
struct Bench
{
    unsigned int rounds = 3;
    int width = 800;
    int height = 600;
    std::string csvPath;
    std::string machine = "unnamed machine";
    std::string date;
    std::string indexFolder = "/tmp/osgglyphtrajbench-index";
    osg::ref_ptr<osgGlyphsHeadless::OffscreenViewer> viewer;
    std::string suite;
    /** Runs only the cases whose names hold it (for a profiler); the figures of others are void. */
    std::string only;

    /** One line of the CSV (and of the console). */
    void report(const std::string& name, const std::string& metric, double value, const std::string& unit)
    {
        std::cout << "  " << std::left << std::setw(52) << name << " " << std::setw(22) << metric << " "
                  << std::right << std::setw(10) << std::setprecision(4) << value << " " << unit << std::endl;
        if (csvPath.empty())
            return;
        const bool fresh = !std::filesystem::exists(csvPath) || std::filesystem::file_size(csvPath) == 0;
        std::ofstream csv(csvPath, std::ios::app);
        if (fresh)
            csv << "date,machine,suite,case,metric,value,unit\n";
        csv << date << ",\"" << machine << "\"," << suite << ",\"" << name << "\",\"" << metric << "\","
            << std::setprecision(6) << value << "," << unit << "\n";
    }

    /** The figures of a result: median times, and the rates of its frames and bytes. */
    void reportRates(const Result& r)
    {
        report(r.name, "median_s", r.seconds(), "s");
        report(r.name, "thread_cpu_s", r.median([](const Sample& s) { return s.threadCpu; }), "s");
        report(r.name, "process_cpu_s", r.median([](const Sample& s) { return s.processCpu; }), "s");
        if (r.count() > 0.0)
        {
            report(r.name, "per_s", 1.0 / r.each(), "1/s");
            report(r.name, "ms_each", 1000.0 * r.each(), "ms");
        }
        if (r.bytes() > 0.0)
        {
            report(r.name, "MB_per_s", r.bytes() / 1e6 / r.seconds(), "MB/s");
            report(r.name, "MB_per_thread_cpu_s",
                   r.bytes() / 1e6 / r.median([](const Sample& s) { return s.threadCpu; }), "MB/s");
        }
    }

    /** Times against another case's, as measured in the same rounds. */
    void reportRatio(const Result& r, const Result& baseline)
    {
        report(r.name, "ratio_to:" + baseline.name, r.seconds() / baseline.seconds(), "x");
    }

    /** Runs the cases in turn, rounds + 1 times; the first round warms up and is not kept. */
    bool measure(std::vector<Case>& cases, std::vector<Result>& results)
    {
        results.assign(cases.size(), Result());
        std::ifstream load("/proc/loadavg");
        double loadAverage = 0.0;
        load >> loadAverage;
        report("(machine)", "loadavg_1min_before", loadAverage, "");
        for (unsigned int round = 0; round <= rounds; ++round)
        {
            std::cerr << PROGRAM << ": " << suite << ": round " << round << (round == 0 ? " (warm-up)" : "")
                      << " of " << rounds << std::endl;
            for (std::size_t i = 0; i < cases.size(); ++i)
            {
                if (cases[i].name.find(only) == std::string::npos)
                    continue;
                Sample sample;
                std::string error;
                if (!cases[i].run(round, sample, error))
                {
                    std::cerr << PROGRAM << ": " << cases[i].name << ": " << error << std::endl;
                    return false;
                }
                results[i].name = cases[i].name;
                if (round > 0)
                    results[i].samples.push_back(sample);
            }
        }
        return true;
    }
};

/** A figure of /proc/self/status in bytes: VmHWM (the peak resident memory), VmRSS. */
double readStatusBytes(const std::string& key)
{
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.compare(0, key.size() + 1, key + ":") == 0)
            return std::stod(line.substr(key.size() + 1)) * 1024.0;
    return 0.0;
}

std::string baseName(const std::string& path)
{
    return std::filesystem::path(path).filename().string();
}

/** A file opened as osgglyphviewer opens it: its first frame, the mapping prepared on it, its cloud. */
struct Scene
{
    osg::ref_ptr<osgGlyphsData::FrameSource> source;
    std::unique_ptr<osgGlyphsData::GlyphMapper> mapper;
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud;
    osg::ref_ptr<osg::Group> root;
    double openSeconds = 0.0;
    double mapSeconds = 0.0;
};

/** Indexes are kept (or not) in a folder of the benchmark's own, one folder a file. */
osgGlyphsData::FrameSourceOptions sourceOptions(const Bench& bench, const std::string& path, bool keepIndex)
{
    osgGlyphsData::FrameSourceOptions options;
    options.indexLocation =
        keepIndex ? osgGlyphsData::FrameIndexLocation::Cache : osgGlyphsData::FrameIndexLocation::None;
    options.cacheFolder = bench.indexFolder + "/" + baseName(path);
    options.warning = [](const std::string&) {}; // a concatenated dump repeats its timesteps
    return options;
}

/** The ids of this process's threads. */
std::set<int> threadIds()
{
    std::set<int> ids;
    for (const auto& entry : std::filesystem::directory_iterator("/proc/self/task"))
        ids.insert(std::stoi(entry.path().filename().string()));
    return ids;
}

/** niceIndex: an experiment, the lowest priority for the threads that open() started (the index
 * scan), as the library could give its index thread. */
bool openScene(const Bench& bench, const std::string& path, bool keepIndex, Scene& scene, std::string& error,
               bool niceIndex = false)
{
    const std::set<int> before = niceIndex ? threadIds() : std::set<int>();
    const Stopwatch open;
    scene.source = osgGlyphsData::FrameSource::open(path, sourceOptions(bench, path, keepIndex), error);
    if (!scene.source)
        return false;
    for (const int id : niceIndex ? threadIds() : std::set<int>())
        if (!before.count(id))
            setpriority(PRIO_PROCESS, static_cast<id_t>(id), 19);
    scene.openSeconds = open.seconds();
    const Stopwatch map;
    scene.mapper.reset(new osgGlyphsData::GlyphMapper(osgGlyphsData::GlyphMappingOptions()));
    scene.mapper->setMultiFrame(true);
    if (!scene.mapper->prepare(*osgGlyphsData::sampleFrames(*scene.source, 1), 0, error))
        return false;
    scene.cloud = scene.mapper->createCloud(*scene.source->getFirstFrame(), error);
    if (!scene.cloud)
        return false;
    scene.root = new osg::Group;
    scene.root->addChild(scene.cloud.get());
    scene.mapSeconds = map.seconds();
    return true;
}

/** Opens a file with its index complete and kept, for the suites that read its frames. */
bool openIndexed(const Bench& bench, const std::string& path, Scene& scene)
{
    std::string error;
    if (!openScene(bench, path, true, scene, error))
    {
        std::cerr << PROGRAM << ": " << error << std::endl;
        return false;
    }
    scene.source->waitForIndex();
    return true;
}

/** Draws one picture of a scene, seen whole from one side. */
bool draw(Bench& bench, osg::Node* root, std::string& error)
{
    osgViewer::Viewer& viewer = *bench.viewer;
    if (viewer.getSceneData() != root)
    {
        viewer.setSceneData(root);
        const osg::BoundingSphere bound = root->getBound();
        const double distance = 1.1 * bound.radius() / std::sin(osg::DegreesToRadians(15.0));
        if (bound.valid())
            viewer.getCamera()->setViewMatrixAsLookAt(bound.center() + osg::Vec3d(0.0, -distance, 0.0),
                                                      bound.center(), osg::Vec3d(0.0, 0.0, 1.0));
    }
    viewer.frame();
    error = osgGlyphs::GlyphStateCache::instance()->getProgramError();
    return error.empty();
}

/** The text bytes of frames [first, last] of a source, as its index has them. */
double frameBytes(const osgGlyphsData::FrameSource& source, std::size_t first, std::size_t last)
{
    double bytes = 0.0;
    for (std::size_t frame = first; frame <= last; ++frame)
    {
        const osgGlyphsData::FrameInfo info = source.getFrameInfo(frame);
        bytes += static_cast<double>(info.end - info.offset);
    }
    return bytes;
}

/** Decodes frames of a source in the order given. */
bool readFrames(const osgGlyphsData::FrameSource& source, const std::vector<std::size_t>& order,
                Sample& sample, std::string& error)
{
    const Stopwatch watch;
    for (std::size_t frame : order)
        if (!source.readFrame(frame, error))
            return false;
    sample.add(watch);
    sample.count = static_cast<double>(order.size());
    for (std::size_t frame : order)
        sample.bytes += frameBytes(source, frame, frame);
    return true;
}

std::vector<std::size_t> inOrder(std::size_t frames)
{
    std::vector<std::size_t> order(frames);
    std::iota(order.begin(), order.end(), std::size_t(0));
    return order;
}

std::vector<std::size_t> shuffled(std::size_t frames, unsigned int seed)
{
    std::vector<std::size_t> order = inOrder(frames);
    std::shuffle(order.begin(), order.end(), std::mt19937(seed));
    return order;
}

// --- open: the first picture of a trajectory against that of a one-frame file ----------------

bool runOpen(Bench& bench, const std::vector<std::string>& files)
{
    std::vector<Case> cases;
    const char* const modes[] = {
        "first picture, no index: ", "first picture, no index, scan niced: ", "first picture, index kept: "};
    for (const int mode : {0, 1, 2})
        for (const std::string& file : files)
            cases.push_back({modes[mode] + baseName(file),
                             [&bench, file, mode](unsigned int, Sample& sample, std::string& error)
                             {
                                 bench.viewer->setSceneData(nullptr);
                                 Scene scene;
                                 const Stopwatch watch;
                                 if (!openScene(bench, file, mode == 2, scene, error, mode == 1))
                                     return false;
                                 const Stopwatch drawing;
                                 if (!draw(bench, scene.root.get(), error))
                                     return false;
                                 sample.add(watch);
                                 sample.extra["open_s"] = scene.openSeconds;
                                 sample.extra["map_s"] = scene.mapSeconds;
                                 sample.extra["draw_s"] = drawing.seconds();
                                 bench.viewer->setSceneData(nullptr);
                                 return true; // the index thread stops as the scene goes, untimed
                             }});
    for (const std::string& file : files) // the index that "index kept" reuses
    {
        Scene scene;
        if (!openIndexed(bench, file, scene))
            return false;
    }
    std::vector<Result> results;
    if (!bench.measure(cases, results))
        return false;
    for (std::size_t i = 0; i < results.size(); ++i)
    {
        const Result& r = results[i];
        bench.report(r.name, "median_ms", 1000.0 * r.seconds(), "ms");
        for (const std::string phase : {"open", "map", "draw"})
            bench.report(r.name, phase + "_ms", 1000.0 * r.extra(phase + "_s"), "ms");
        if (i % files.size() != 0)
            bench.reportRatio(r, results[i - i % files.size()]); // the one-frame file, same index mode
    }
    return true;
}

// --- last: the last frame on a first open (index scan) and on a second (index reused) --------

/** Opens a file (its index removed first on a first open), waits for its index, then decodes and
 * draws its last frame (toLast), or its first again: the difference is what the jump costs. */
bool showFrame(Bench& bench, const std::string& file, bool firstOpen, bool toLast, Sample& sample,
               std::string& error)
{
    bench.viewer->setSceneData(nullptr);
    if (firstOpen)
        std::filesystem::remove_all(sourceOptions(bench, file, true).cacheFolder);
    Scene scene;
    const Stopwatch watch;
    if (!openScene(bench, file, true, scene, error))
        return false;
    if (firstOpen == scene.source->isIndexReused())
    {
        error = firstOpen ? "the index was reused on a first open" : "the index was not reused";
        return false;
    }
    scene.source->waitForIndex();
    const double indexSeconds = watch.seconds();
    const std::size_t frames = scene.source->getNumFrames();
    const Stopwatch decode;
    osg::ref_ptr<osgGlyphsData::PointData> frame = scene.source->readFrame(toLast ? frames - 1 : 0, error);
    if (!frame)
        return false;
    const double decodeSeconds = decode.seconds();
    if (!scene.mapper->updateCloud(*scene.cloud, *frame, error) || !draw(bench, scene.root.get(), error))
        return false;
    sample.add(watch);
    sample.bytes = static_cast<double>(scene.source->getFrameInfo(frames - 1).end);
    sample.extra["index_s"] = indexSeconds;
    sample.extra["decode_s"] = decodeSeconds;
    sample.extra["file_bytes"] = static_cast<double>(scene.source->getFileSize());
    sample.extra["frames"] = static_cast<double>(frames);
    bench.viewer->setSceneData(nullptr);
    return true;
}

bool runLast(Bench& bench, const std::vector<std::string>& files)
{
    std::vector<Case> cases;
    for (const std::string& file : files)
        for (const int kind : {0, 1, 2})
            cases.push_back({std::string(kind == 0   ? "last frame, first open: "
                                         : kind == 1 ? "last frame, index reused: "
                                                     : "first frame, index reused: ") +
                                 baseName(file),
                             [&bench, file, kind](unsigned int, Sample& sample, std::string& error)
                             { return showFrame(bench, file, kind == 0, kind < 2, sample, error); }});
    std::vector<Result> results;
    if (!bench.measure(cases, results))
        return false;
    for (std::size_t i = 0; i < results.size(); ++i)
    {
        const Result& r = results[i];
        bench.report(r.name, "frames", r.extra("frames"), "");
        bench.report(r.name, "median_ms", 1000.0 * r.seconds(), "ms");
        bench.report(r.name, "index_ms", 1000.0 * r.extra("index_s"), "ms");
        bench.report(r.name, "decode_ms", 1000.0 * r.extra("decode_s"), "ms");
        if (i % 3 == 0) // the scan: text (and file) bytes over the time to a complete index
        {
            bench.report(r.name, "scan_MB_per_s", r.bytes() / 1e6 / r.extra("index_s"), "MB/s");
            bench.report(r.name, "scan_file_MB_per_s", r.extra("file_bytes") / 1e6 / r.extra("index_s"),
                         "MB/s");
        }
        if (i % 3 == 1)
        {
            bench.reportRatio(r, results[i + 1]);
            bench.report(r.name, "jump_minus_first_ms", 1000.0 * (r.seconds() - results[i + 1].seconds()),
                         "ms");
        }
        if (i % 3 == 0)
            bench.reportRatio(r, results[i + 1]);
    }
    return true;
}

// --- decode: readFrame over every frame, against readPointFile of a one-frame file ------------

bool runDecode(Bench& bench, const std::vector<std::string>& files)
{
    std::vector<Scene> scenes(files.size() - 1);
    for (std::size_t i = 1; i < files.size(); ++i)
        if (!openIndexed(bench, files[i], scenes[i - 1]))
            return false;
    std::vector<Case> cases;
    const std::string oneFrame = files[0];
    cases.push_back(
        {"readPointFile: " + baseName(oneFrame), [oneFrame](unsigned int, Sample& sample, std::string& error)
         {
             const Stopwatch watch;
             if (!osgGlyphsData::readPointFile(oneFrame, osgGlyphsData::PointReadOptions(), error))
                 return false;
             sample.add(watch);
             sample.count = 1.0;
             sample.bytes = static_cast<double>(std::filesystem::file_size(oneFrame));
             return true;
         }});
    for (const Scene& scene : scenes)
    {
        const osgGlyphsData::FrameSource* source = scene.source.get();
        const std::string name = baseName(source->getSource());
        const std::size_t frames = source->getNumFrames();
        cases.push_back({"readFrame 0: " + name, [source](unsigned int, Sample& sample, std::string& error)
                         { return readFrames(*source, {0}, sample, error); }});
        cases.push_back({"readFrame in order: " + name,
                         [source, frames](unsigned int, Sample& sample, std::string& error)
                         { return readFrames(*source, inOrder(frames), sample, error); }});
        cases.push_back({"readFrame at random: " + name,
                         [source, frames](unsigned int round, Sample& sample, std::string& error)
                         { return readFrames(*source, shuffled(frames, round), sample, error); }});
    }
    std::vector<Result> results;
    if (!bench.measure(cases, results))
        return false;
    const Result& parser = results[0];
    for (const Result& r : results)
    {
        bench.reportRates(r);
        if (&r != &parser)
            bench.report(r.name, "MB_per_s_ratio_to:" + parser.name,
                         (r.bytes() / r.seconds()) / (parser.bytes() / parser.seconds()), "x");
    }
    return true;
}

// --- play: playback against drawing alone and decoding alone ----------------------------------

/** Plays every frame once, as fast as drawing and decoding allow, with a cache of the default
 * budget decoding ahead on its worker. */
bool play(Bench& bench, Scene& scene, unsigned int subframes, Sample& sample, std::string& error)
{
    if (!scene.mapper->updateCloud(*scene.cloud, *scene.source->getFirstFrame(), error) ||
        !draw(bench, scene.root.get(), error))
        return false;
    const Stopwatch watch;
    osg::ref_ptr<osgGlyphsData::TrajectoryPlayer> player = new osgGlyphsData::TrajectoryPlayer(
        new osgGlyphsData::FrameCache(scene.source.get()), *scene.mapper, scene.cloud.get());
    player->setFramesPerSecond(1e6); // a picture every draw, when its frames are decoded
    player->setLoop(false);
    player->setSubframes(subframes);
    player->setErrorHandler([](const std::string&) {});
    scene.root->setUpdateCallback(player.get());
    player->setPlaying(true);
    unsigned int draws = 0;
    while (player->isPlaying() || player->getPosition() != player->getWantedPosition())
    {
        if (!draw(bench, scene.root.get(), error))
            return false;
        ++draws;
    }
    sample.add(watch);
    scene.root->setUpdateCallback(nullptr);
    const osgGlyphsData::TrajectoryPlayerStatistics statistics = player->getStatistics();
    if (statistics.failed > 0)
    {
        error = statistics.lastError;
        return false;
    }
    sample.count = static_cast<double>(statistics.shown);
    sample.bytes = frameBytes(*scene.source, 0, scene.source->getNumFrames() - 1);
    sample.extra["late"] = static_cast<double>(statistics.late);
    sample.extra["draws"] = draws;
    return true;
}

/** Times showNow() at every pair of frames, all of them in the cache: at a stored frame, between
 * two (offset), after showing the middle of the pair first (its interpolator made) or not. */
bool showEvery(osgGlyphsData::TrajectoryPlayer& player, double offset, bool pairFirst, Sample& sample,
               std::string& error)
{
    const uint64_t decoded = player.getCache()->getStatistics().decoded;
    const std::size_t frames = player.getNumFrames();
    for (std::size_t k = 0; k + 1 < frames; ++k)
    {
        if (pairFirst && !player.showNow(k + 0.5, error))
            return false;
        const Stopwatch watch;
        if (!player.showNow(k + offset, error))
            return false;
        sample.add(watch);
    }
    sample.count = static_cast<double>(frames - 1);
    sample.extra["decoded"] = static_cast<double>(player.getCache()->getStatistics().decoded - decoded);
    return true;
}

bool runPlay(Bench& bench, const std::vector<std::string>& files)
{
    std::vector<Scene> scenes(files.size());
    for (std::size_t i = 0; i < files.size(); ++i)
        if (!openIndexed(bench, files[i], scenes[i]))
            return false;
    Scene& first = scenes[0];
    const std::size_t frames = first.source->getNumFrames();
    std::vector<Case> cases;
    cases.push_back({"draw only", [&bench, &first, frames](unsigned int, Sample& sample, std::string& error)
                     {
                         if (!draw(bench, first.root.get(), error))
                             return false;
                         const Stopwatch watch;
                         for (std::size_t i = 0; i < frames; ++i)
                             if (!draw(bench, first.root.get(), error))
                                 return false;
                         sample.add(watch);
                         sample.count = static_cast<double>(frames);
                         return true;
                     }});
    // Stored and interpolated pictures, the frames cached (a budget for every frame).
    osg::ref_ptr<osgGlyphsData::TrajectoryPlayer> still = new osgGlyphsData::TrajectoryPlayer(
        new osgGlyphsData::FrameCache(first.source.get(), uint64_t(4) << 30), *first.mapper,
        first.cloud.get());
    std::string error;
    for (std::size_t k = 0; k < frames; ++k)
        if (!still->getCache()->getFrame(k, error))
        {
            std::cerr << PROGRAM << ": " << error << std::endl;
            return false;
        }
    const struct
    {
        const char* name;
        double offset;
        bool pairFirst;
    } shows[] = {{"showNow(k), stored", 0.0, false},
                 {"showNow(k+0.5), new pair", 0.5, false},
                 {"showNow(k+0.25), pair made", 0.25, true}};
    // The same in a cloud without occlusion culling, which a new frame does not sort into chunks.
    osgGlyphsData::GlyphMapper unculled = *first.mapper;
    unculled.setCulling(osgGlyphs::GlyphCulling::Off);
    osg::ref_ptr<osgGlyphs::GlyphCloud> unculledCloud =
        unculled.createCloud(*first.source->getFirstFrame(), error);
    if (!unculledCloud)
    {
        std::cerr << PROGRAM << ": " << error << std::endl;
        return false;
    }
    osg::ref_ptr<osgGlyphsData::TrajectoryPlayer> stillUnculled =
        new osgGlyphsData::TrajectoryPlayer(still->getCache(), unculled, unculledCloud.get());
    for (const bool culling : {true, false})
        for (const auto& show : shows)
        {
            osg::ref_ptr<osgGlyphsData::TrajectoryPlayer> player = culling ? still : stillUnculled;
            cases.push_back({show.name + std::string(culling ? "" : ", culling off"),
                             [player, show](unsigned int, Sample& sample, std::string& caseError)
                             { return showEvery(*player, show.offset, show.pairFirst, sample, caseError); }});
        }
    for (Scene& scene : scenes)
    {
        const osgGlyphsData::FrameSource* source = scene.source.get();
        cases.push_back({"decode only: " + baseName(source->getSource()),
                         [source](unsigned int, Sample& sample, std::string& caseError) {
                             return readFrames(*source, inOrder(source->getNumFrames()), sample, caseError);
                         }});
        for (const unsigned int subframes : {0u, 3u})
            cases.push_back(
                {"play, subframes " + std::to_string(subframes) + ": " + baseName(source->getSource()),
                 [&bench, &scene, subframes](unsigned int, Sample& sample, std::string& caseError)
                 { return play(bench, scene, subframes, sample, caseError); }});
    }
    std::vector<Result> results;
    if (!bench.measure(cases, results))
        return false;
    for (std::size_t i = 0; i < 7; ++i)
    {
        bench.reportRates(results[i]);
        if (i > 1)
            bench.reportRatio(results[i], results[1]);
        if (i > 4)
            bench.reportRatio(results[i], results[4]);
    }
    // What a picture costs the drawing thread: the draw, and showing its frame in the cloud (a
    // stored one, or one of three interpolated ones, the first of which matches the pair).
    const double draw = results[0].each(), stored = results[1].each();
    const double interpolated = (results[2].each() + 2.0 * results[3].each()) / 3.0;
    for (std::size_t i = 7; i < results.size(); i += 3)
    {
        const Result& decode = results[i];
        bench.reportRates(decode);
        for (std::size_t s = 0; s < 2; ++s)
        {
            const Result& p = results[i + 1 + s];
            const double pictures = s == 0 ? 1.0 : 4.0; // per decoded frame
            const double decodeEach = decode.each() / pictures;
            const double drawEach = draw + (s == 0 ? stored : (stored + 3.0 * interpolated) / 4.0);
            bench.reportRates(p);
            bench.report(p.name, "late", p.extra("late"), "");
            bench.report(p.name, "draws", p.extra("draws"), "");
            bench.report(p.name, "cores_busy",
                         p.median([](const Sample& x) { return x.processCpu; }) / p.seconds(), "");
            bench.report(p.name, "naive_min_per_s", 1.0 / std::max(draw, decodeEach), "1/s");
            bench.report(p.name, "naive_serial_per_s", 1.0 / (draw + decodeEach), "1/s");
            bench.report(p.name, "min_per_s", 1.0 / std::max(drawEach, decodeEach), "1/s");
            bench.report(p.name, "serial_per_s", 1.0 / (drawEach + decodeEach), "1/s");
            bench.report(p.name, "rate_to_min", std::max(drawEach, decodeEach) / p.each(), "x");
            bench.report(p.name, "rate_to_serial", (drawEach + decodeEach) / p.each(), "x");
        }
    }
    return true;
}

// --- memory: peak resident memory playing every frame once, default cache budget -------------

bool runMemory(Bench& bench, const std::vector<std::string>& files)
{
    Scene scene;
    std::string error;
    Sample sample;
    if (!openIndexed(bench, files[0], scene))
        return false;
    if (!draw(bench, scene.root.get(), error))
    {
        std::cerr << PROGRAM << ": " << error << std::endl;
        return false;
    }
    const double openPeak = readStatusBytes("VmHWM");
    if (!play(bench, scene, 0, sample, error))
    {
        std::cerr << PROGRAM << ": " << error << std::endl;
        return false;
    }
    const double peak = readStatusBytes("VmHWM");
    const std::string name = "play every frame: " + baseName(files[0]);
    const double frame =
        static_cast<double>(osgGlyphsData::FrameCache::getFrameBytes(*scene.source->getFirstFrame()));
    bench.report(name, "frames", static_cast<double>(scene.source->getNumFrames()), "");
    bench.report(name, "pictures", sample.count, "");
    bench.report(name, "frame_columns_MB", frame / 1e6, "MB");
    bench.report(name, "data_MB", frame * scene.source->getNumFrames() / 1e6, "MB");
    bench.report(name, "cache_budget_MB", osgGlyphsData::FrameCache::DEFAULT_BUDGET_BYTES / 1e6, "MB");
    bench.report(name, "peak_rss_opened_MB", openPeak / 1e6, "MB");
    bench.report(name, "peak_rss_MB", peak / 1e6, "MB");
    bench.report(name, "peak_rss_growth_MB", (peak - openPeak) / 1e6, "MB");
    bench.report(name, "pictures_per_s", sample.count / sample.seconds, "1/s");
    return true;
}

std::string today()
{
    const std::time_t now = std::time(nullptr);
    char text[32];
    std::strftime(text, sizeof(text), "%Y-%m-%d", std::localtime(&now));
    return text;
}

}

int main(int argc, char** argv)
{
#ifdef OSGGLYPHS_HAVE_HDF5
    osgGlyphsHdf5::registerFormats(); // H5MD and snapshots
#endif
    // A glyph program that fails is reported by draw(), in one line.
    osg::setNotifyHandler(new osgGlyphs::ProgramErrorFilter(osg::getNotifyHandler()));
    osg::ArgumentParser arguments(&argc, argv);
    Bench bench;
    bench.date = today();
    arguments.read("--rounds", bench.rounds);
    arguments.read("--csv", bench.csvPath);
    arguments.read("--machine", bench.machine);
    arguments.read("--index-folder", bench.indexFolder);
    arguments.read("--size", bench.width, bench.height);
    arguments.read("--only", bench.only);
    using Suite = std::function<bool(Bench&, const std::vector<std::string>&)>;
    const std::map<std::string, std::pair<std::size_t, Suite>> suites = {{"open", {2, runOpen}},
                                                                         {"last", {1, runLast}},
                                                                         {"decode", {2, runDecode}},
                                                                         {"play", {1, runPlay}},
                                                                         {"memory", {1, runMemory}}};
    std::vector<std::string> files;
    for (int i = 2; i < arguments.argc(); ++i)
        files.push_back(arguments[i]);
    const auto suite = arguments.argc() > 1 ? suites.find(arguments[1]) : suites.end();
    if (suite == suites.end() || files.size() < suite->second.first || arguments.errors())
    {
        std::cerr << "usage: " << PROGRAM
                  << " open|last|decode|play|memory [--rounds N] [--csv FILE] [--machine TEXT]"
                     " [--index-folder DIR] [--size W H] [--only CASE_TEXT] FILE...\n"
                     "  open   ONE_FRAME_FILE DUMP...  first picture of each, against the one-frame file\n"
                     "  last   DUMP...                 last frame on a first open (index scan) and a second\n"
                     "  decode ONE_FRAME_FILE DUMP...  readFrame in order and at random, and readPointFile\n"
                     "  play   DUMP [DUMP.gz]          playback against drawing alone and decoding alone\n"
                     "  memory DUMP                    peak memory playing every frame once"
                  << std::endl;
        return 1;
    }
    bench.suite = suite->first;
    bench.viewer = new osgGlyphsHeadless::OffscreenViewer(bench.width, bench.height);
    std::string error;
    osg::ref_ptr<osg::Group> empty = new osg::Group;
    error = bench.viewer->getContextError();
    if (!bench.viewer->valid() || !draw(bench, empty.get(), error))
    {
        std::cerr << PROGRAM << ": cannot draw headless: " << error << std::endl;
        return 1;
    }
    bench.viewer->getFrameCapture()->setCaptureDepth(false);
    bench.machine += ", " + bench.viewer->getFrameCapture()->getGLRenderer();
    std::cout << PROGRAM << " " << bench.suite << ": " << bench.machine << ", " << bench.date << ", "
              << bench.width << "x" << bench.height << ", medians of " << bench.rounds << " rounds"
              << std::endl;
    const bool ok = suite->second.second(bench, files);
    bench.viewer = nullptr;
    return ok ? 0 : 1;
}
