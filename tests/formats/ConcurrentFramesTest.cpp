/* Frame files decoded from several threads at once (FrameFile::readFrame is const and
 * thread-safe): every thread gets the frames one thread reads alone. Run under ThreadSanitizer
 * (label threads). */

#include "FormatTestData.h"

#include <atomic>
#include <thread>

using namespace formattest;
using namespace osgGlyphsData;

namespace
{

bool sameColumns(const PointData& a, const PointData& b)
{
    if (a.getColumnNames() != b.getColumnNames() || a.getNumPoints() != b.getNumPoints())
        return false;
    for (std::size_t c = 0; c < a.getNumColumns(); ++c)
    {
        if (*a.getColumn(c) != *b.getColumn(c))
            return false;
    }
    return true;
}

}

TEST(ConcurrentFrames, EveryThreadReadsTheFramesOneThreadReads)
{
    const char* files[] = {"melt.dcd",     "xtc/melt.xtc", "xtc/melt.trr",    "gsd/melt.gsd",
                           "pdb/melt.pdb", "pdb/melt.gro", "las/las14_f8.las"};
    for (const char* name : files)
    {
        SCOPED_TRACE(name);
        osg::ref_ptr<FrameSource> source = openFrames(dataPath(name));
        ASSERT_TRUE(source);
        const std::size_t frames = source->getNumFrames();
        std::vector<osg::ref_ptr<PointData>> alone;
        for (std::size_t frame = 0; frame < frames; ++frame)
            alone.push_back(frameOf(*source, frame));
        std::atomic<int> mismatches{0};
        std::vector<std::thread> threads;
        for (unsigned int t = 0; t < 4; ++t)
            threads.emplace_back(
                [&, t]
                {
                    for (std::size_t i = 0; i < 3 * frames; ++i)
                    {
                        const std::size_t frame = (i * (t + 1) + t) % frames;
                        std::string error;
                        osg::ref_ptr<PointData> data = source->readFrame(frame, error);
                        if (!data || !alone[frame] || !sameColumns(*data, *alone[frame]))
                            ++mismatches;
                    }
                });
        for (std::thread& thread : threads)
            thread.join();
        EXPECT_EQ(mismatches.load(), 0);
    }
}
