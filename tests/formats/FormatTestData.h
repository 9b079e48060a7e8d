/* The format tests' data (tests/data/formats, make_formats.sh) and their comparisons. */

#ifndef OSGGLYPHS_TESTS_FORMATTESTDATA_H
#define OSGGLYPHS_TESTS_FORMATTESTDATA_H 1

#include <osgGlyphsData/FrameSource>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <string>

#include <unistd.h>

namespace formattest
{

inline std::string dataPath(const std::string& name)
{
    return std::string(OSGGLYPHS_FORMAT_DATA_DIR) + "/" + name;
}

/** Opens a test file as a trajectory, with no index file left behind; fails the test if it cannot. */
inline osg::ref_ptr<osgGlyphsData::FrameSource> openFrames(const std::string& path,
                                                           osgGlyphsData::FrameSourceOptions options = {})
{
    options.indexLocation = osgGlyphsData::FrameIndexLocation::None;
    std::string error;
    osg::ref_ptr<osgGlyphsData::FrameSource> source = osgGlyphsData::FrameSource::open(path, options, error);
    EXPECT_TRUE(source.valid()) << error;
    if (source)
        source->waitForIndex();
    return source;
}

inline osg::ref_ptr<osgGlyphsData::PointData> frameOf(const osgGlyphsData::FrameSource& source,
                                                      std::size_t frame)
{
    std::string error;
    osg::ref_ptr<osgGlyphsData::PointData> data = source.readFrame(frame, error);
    EXPECT_TRUE(data.valid()) << error;
    return data;
}

/** Expects column name of actual to hold expected's values, point by point in the same order,
 * within tolerance (absolute), scaled by factor (a unit conversion: 0.1 for Angstrom to nm). */
inline void expectColumnMatches(const osgGlyphsData::PointData& expected,
                                const osgGlyphsData::PointData& actual, const std::string& name,
                                double tolerance, double factor = 1.0,
                                const std::string& actualName = std::string())
{
    const std::string other = actualName.empty() ? name : actualName;
    ASSERT_TRUE(expected.hasColumn(name)) << name;
    ASSERT_TRUE(actual.hasColumn(other)) << other;
    ASSERT_EQ(expected.getNumPoints(), actual.getNumPoints());
    const int e = expected.findColumn(name);
    const int a = actual.findColumn(other);
    std::size_t wrong = 0;
    for (std::size_t i = 0; i < expected.getNumPoints(); ++i)
    {
        const double want = expected.getValue(std::size_t(e), i) * factor;
        const double got = actual.getValue(std::size_t(a), i);
        if (!(std::fabs(want - got) <= tolerance) && wrong++ < 3)
            ADD_FAILURE() << other << " of point " << i << ": " << got << ", expected " << want;
    }
    EXPECT_EQ(wrong, 0u) << other << ": values outside " << tolerance;
}

/** Expects every frame of actual to have the positions of the same frame of expected. */
inline void expectPositionsMatch(const osgGlyphsData::FrameSource& expected,
                                 const osgGlyphsData::FrameSource& actual, double tolerance,
                                 double factor = 1.0)
{
    ASSERT_EQ(expected.getNumFrames(), actual.getNumFrames());
    for (std::size_t frame = 0; frame < expected.getNumFrames(); ++frame)
    {
        SCOPED_TRACE("frame " + std::to_string(frame));
        osg::ref_ptr<osgGlyphsData::PointData> want = frameOf(expected, frame);
        osg::ref_ptr<osgGlyphsData::PointData> got = frameOf(actual, frame);
        ASSERT_TRUE(want && got);
        for (const char* axis : {"x", "y", "z"})
            expectColumnMatches(*want, *got, axis, tolerance, factor);
    }
}

/** Writes bytes to a scratch file of this process in the temporary folder and returns its path. */
inline std::string writeScratchFile(const std::string& name, const std::string& bytes)
{
    // The process's own: ctest runs each test as a process, side by side.
    const std::string path =
        ::testing::TempDir() + "osgglyphs_format_" + std::to_string(getpid()) + "_" + name;
    std::ofstream(path, std::ios::binary | std::ios::trunc)
        .write(bytes.data(), std::streamsize(bytes.size()));
    return path;
}

/** The bytes of a file. */
inline std::string readBytes(const std::string& path)
{
    std::ifstream stream(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>());
}

/** The error of opening a file and reading every frame: empty when all went well. */
inline std::string firstError(const std::string& path, const std::string& format = std::string())
{
    osgGlyphsData::FrameSourceOptions options;
    options.format = format;
    options.indexLocation = osgGlyphsData::FrameIndexLocation::None;
    options.warning = [](const std::string&) {};
    std::string error;
    osg::ref_ptr<osgGlyphsData::FrameSource> source = osgGlyphsData::FrameSource::open(path, options, error);
    if (!source)
        return error;
    source->waitForIndex();
    for (std::size_t frame = 0; frame < source->getNumFrames(); ++frame)
    {
        if (!source->readFrame(frame, error))
            return error;
    }
    return std::string();
}

}

#endif
