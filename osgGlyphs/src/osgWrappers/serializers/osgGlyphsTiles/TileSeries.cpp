#include "GlyphCount.h"

#include <osgGlyphsTiles/TileSeries>

#include <osgDB/InputStream>
#include <osgDB/ObjectWrapper>
#include <osgDB/OutputStream>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

using osgGlyphsTiles::TileSeries;

namespace
{

/** More frames than this in an index is a corrupt file, not a series. */
const unsigned int MAX_FRAMES = 100000000u;

}

/** A frame's timestep: in text files a word read whole (osgDB's text reader takes a word that is
 * not a number, "nan" among them, for 0). */
static bool readTimestep(osgDB::InputStream& is, double& timestep)
{
    if (is.isBinary())
        is >> timestep;
    else
    {
        std::string word;
        is >> word;
        char* end = nullptr;
        timestep = std::strtod(word.c_str(), &end);
        if (word.empty() || *end != '\0')
            timestep = std::numeric_limits<double>::quiet_NaN();
    }
    return !is.getException();
}

static bool checkFrames(const TileSeries&)
{
    return true;
}

// The frames' files are relative to the index file's folder, which reading makes the series'
// database path (as osg::PagedLOD's serializer does).
static bool readFrames(osgDB::InputStream& is, TileSeries& series)
{
    unsigned int count = 0;
    is >> count;
    if (count > MAX_FRAMES)
    {
        is.throwException("osgGlyphs: TileSeries: " + std::to_string(count) +
                          " frames: the index is corrupt");
        return false;
    }
    is >> is.BEGIN_BRACKET;
    std::vector<TileSeries::Frame> frames;
    for (unsigned int i = 0; i < count && !is.getException(); ++i)
    {
        TileSeries::Frame frame;
        is.readWrappedString(frame.file);
        if (!readTimestep(is, frame.timestep))
            return false;
        if (frame.file.empty() || !std::isfinite(frame.timestep))
        {
            is.throwException("osgGlyphs: TileSeries: frame " + std::to_string(i) +
                              ": no file, or a timestep that is not a number");
            return false;
        }
        frames.push_back(frame);
    }
    is >> is.END_BRACKET;
    if (is.getException())
        return false;
    series.setFrames(frames);
    const osgDB::Options* options = is.getOptions();
    if (series.getDatabasePath().empty() && options && !options->getDatabasePathList().empty())
        series.setDatabasePath(options->getDatabasePathList().front());
    // Read with its first frame shown, as an archive is read with its root tile: a viewer frames
    // the series by its bound before the first update traversal.
    std::string error;
    if (!frames.empty() && series.showFrameNow(0, error) == TileSeries::FRAME_FAILED)
        OSG_WARN << "osgGlyphs: " << error << std::endl;
    return true;
}

static bool writeFrames(osgDB::OutputStream& os, const TileSeries& series)
{
    const std::vector<TileSeries::Frame>& frames = series.getFrames();
    os << static_cast<unsigned int>(frames.size()) << os.BEGIN_BRACKET << std::endl;
    for (const TileSeries::Frame& frame : frames)
    {
        os.writeWrappedString(frame.file);
        // Text streams write doubles with 6 significant digits: timesteps go as all of theirs.
        if (os.isBinary())
            os << frame.timestep;
        else
        {
            char digits[32];
            std::snprintf(digits, sizeof(digits), "%.17g", frame.timestep);
            os << std::string(digits);
        }
        os << std::endl;
    }
    os << os.END_BRACKET << std::endl;
    return true;
}

static bool checkGlyphBudget(const TileSeries&)
{
    return true;
}

static bool readGlyphBudget(osgDB::InputStream& is, TileSeries& series)
{
    std::size_t budget = 0;
    osgGlyphsWrappers::readGlyphCount(is, budget);
    series.setGlyphBudget(budget);
    return true;
}

static bool writeGlyphBudget(osgDB::OutputStream& os, const TileSeries& series)
{
    osgGlyphsWrappers::writeGlyphCount(os, series.getGlyphBudget());
    return true;
}

// Not an osg::Group in the file: the child is the frame shown, read from its archive.
REGISTER_CUSTOM_OBJECT_WRAPPER(osgGlyphs, osgGlyphsTiles_TileSeries, new osgGlyphsTiles::TileSeries,
                               osgGlyphsTiles::TileSeries, "osg::Object osg::Node osgGlyphsTiles::TileSeries")
{
    ADD_USER_SERIALIZER(Frames);
    ADD_USER_SERIALIZER(GlyphBudget);
}
