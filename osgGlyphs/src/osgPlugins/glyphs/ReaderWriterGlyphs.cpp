// osgdb_glyphs: point data files (LAMMPS dumps, XYZ, CSV, PLY, VTK) read as glyph scenes by
// any osgDB application, through the library's readers and its column-to-glyph mapping.

#include <osgGlyphs/GlyphDiagnosis>
#include <osgGlyphsData/GlyphMapping>
#include <osgGlyphsData/PointReader>
#include <osgGlyphsPaper/Techniques>
#ifdef OSGGLYPHS_HAVE_HDF5
#include <osgGlyphsHdf5/Hdf5Formats>
#endif

#include <osg/Notify>
#include <osg/Sequence>
#include <osgDB/FileNameUtils>
#include <osgDB/FileUtils>
#include <osgDB/Registry>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <sstream>

namespace
{

/** The pseudo-extension: data.ply.glyphs reads data.ply with this plugin. */
const char* const PSEUDO_EXTENSION = "glyphs";

/** Seconds each frame of a multi-frame file is shown. */
const double FRAME_SECONDS = 0.1;

/** Without a frame option, files of at most this many frames play them all; longer ones show the
 * first: every frame is a cloud, and a dump of 200,000 small frames would take gigabytes. */
const std::size_t MAX_DEFAULT_SEQUENCE_FRAMES = 1000;

/** Which frames become the scene. */
enum class FrameChoice
{
    Default, ///< all, up to MAX_DEFAULT_SEQUENCE_FRAMES; else the first
    All,     ///< frame=all
    One      ///< frame=<n>
};

/** What an option string asks for beyond the column mapping. */
struct ReadSettings
{
    osgGlyphsData::GlyphMappingOptions mapping;
    std::string format;
    FrameChoice frames = FrameChoice::Default;
    unsigned long frame = 0;
};

bool parseFrame(const std::string& value, ReadSettings& settings)
{
    if (value == "all")
    {
        settings.frames = FrameChoice::All;
        return true;
    }
    char* end = nullptr;
    errno = 0;
    settings.frame = std::strtoul(value.c_str(), &end, 10);
    settings.frames = FrameChoice::One;
    return !value.empty() && value[0] != '-' && end == value.c_str() + value.size() && errno == 0;
}

/** The reading of as many frames as the settings need. */
osgGlyphsData::PointReadOptions readOptionsFor(const ReadSettings& settings)
{
    osgGlyphsData::PointReadOptions options;
    options.format = settings.format;
    if (settings.frames == FrameChoice::Default)
        options.maxFrames = MAX_DEFAULT_SEQUENCE_FRAMES + 1; // one more tells a longer file
    else if (settings.frames == FrameChoice::One)
        options.maxFrames = static_cast<uint64_t>(settings.frame) + 1;
    return options;
}

/** Reads "key=value key flag ..."; keys of other plugins are left to them. */
bool parseOptionString(const std::string& text, ReadSettings& settings, std::string& error)
{
    const std::vector<std::string>& mappingNames = osgGlyphsData::getGlyphMappingOptionNames();
    std::istringstream tokens(text);
    std::string token;
    while (tokens >> token)
    {
        const std::string::size_type equals = token.find('=');
        const std::string key = token.substr(0, equals);
        const std::string value = equals == std::string::npos ? std::string() : token.substr(equals + 1);
        if (key == "format")
            settings.format = value;
        else if (key == "frame")
        {
            if (!parseFrame(value, settings))
            {
                error = "frame '" + value + "': a frame number from 0, or all";
                return false;
            }
        }
        else if (std::find(mappingNames.begin(), mappingNames.end(), key) != mappingNames.end())
        {
            if (!osgGlyphsData::setGlyphMappingOption(settings.mapping, key, value, error))
                return false;
        }
    }
    return true;
}

osg::ref_ptr<osg::Node> createScene(const osgGlyphsData::PointDataset& dataset, const ReadSettings& settings,
                                    std::string& error)
{
    const std::size_t first = settings.frames == FrameChoice::One ? settings.frame : 0;
    if (first >= dataset.getNumFrames())
    {
        error = dataset.getSource() + ": frame " + std::to_string(first) + " asked for, the file has " +
                std::to_string(dataset.getNumFrames());
        return nullptr;
    }
    std::size_t last = settings.frames == FrameChoice::One ? first + 1 : dataset.getNumFrames();
    if (settings.frames == FrameChoice::Default && last > MAX_DEFAULT_SEQUENCE_FRAMES)
    {
        OSG_WARN << "osgdb_glyphs: " << dataset.getSource() << " has more than "
                 << MAX_DEFAULT_SEQUENCE_FRAMES
                 << " frames: showing frame 0 (frame=all plays them all, frame=<n> shows another)"
                 << std::endl;
        last = 1;
    }
    osgGlyphsData::GlyphMapper mapper(settings.mapping);
    if (!mapper.prepare(dataset, first, error))
        return nullptr;
    if (last - first == 1)
        return mapper.createCloud(*dataset.getFrame(first), error);

    // Every frame, played in a loop.
    osg::ref_ptr<osg::Sequence> sequence = new osg::Sequence;
    sequence->setName(dataset.getSource());
    for (std::size_t index = first; index < last; ++index)
    {
        osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = mapper.createCloud(*dataset.getFrame(index), error);
        if (!cloud)
            return nullptr;
        sequence->addChild(cloud.get(), FRAME_SECONDS);
    }
    sequence->setInterval(osg::Sequence::LOOP, 0, -1);
    sequence->setDuration(1.0f, -1);
    sequence->setMode(osg::Sequence::START);
    return sequence;
}

}

/** Reads point data as glyphs; the option string is in docs/user-guide.md ("Stock OSG tools").
 *
 * Once loaded, the plugin owns the extensions of the point formats: osgDB's Registry, after the
 * loaded plugins fail to read a file, loads the plugin named after its extension and takes what
 * that one reads, so a .ply file this plugin rejects would become OSG's empty mesh, without a
 * word. Aliasing the extensions to "glyphs" points that step at this plugin, and its error is
 * what the reading program reports. */
class ReaderWriterGlyphs : public osgDB::ReaderWriter
{
public:
    ReaderWriterGlyphs()
    {
        osgGlyphsPaper::registerTechniques(); // the technique option offers the paper's too
#ifdef OSGGLYPHS_HAVE_HDF5
        osgGlyphsHdf5::registerFormats(); // before the extensions are listed
#endif
        supportsExtension(PSEUDO_EXTENSION, "Pseudo-loader: <file>.glyphs reads <file> as glyphs");
        std::string formats;
        for (const osgGlyphsData::PointFormat& format : osgGlyphsData::getPointFormats())
        {
            for (const std::string& extension : format.extensions)
            {
                supportsExtension(extension, format.description);
                osgDB::Registry::instance()->addFileExtensionAlias(extension, PSEUDO_EXTENSION);
            }
            formats += (formats.empty() ? "" : ", ") + format.name;
        }
        supportsOption("format=<name>", "Read as " + formats + ", whatever the extension");
        supportsOption("frame=<n>|all",
                       "One frame of a multi-frame file, or all of them in a loop (default: all "
                       "of a file of at most " +
                           std::to_string(MAX_DEFAULT_SEQUENCE_FRAMES) + " frames, else frame 0)");
        supportsOption("glyph=<shape>",
                       "sphere (default), cone, arrow, cylinder or ellipsoid (default for ellipsoid data)");
        supportsOption("color=<column>|speed", "Colour through the colour map by a column (also color-by)");
        supportsOption("colormap=<name>|<file>", "viridis (default), magma, cividis, coolwarm, grayscale");
        supportsOption("range=<min>,<max>", "Colour range instead of the data's");
        supportsOption("radius=<r>", "Glyph radius, or the factor of radius-by");
        supportsOption("radius-by=<column>",
                       "Radii from a column (default: a radius column, else diameter halved)");
        supportsOption("position=<x>,<y>,<z>", "Position columns");
        supportsOption("vector=<x>,<y>,<z>", "Vector columns of cones, arrows and cylinders");
        supportsOption("length-scale=<s>", "Vector length per unit of magnitude");
        supportsOption(
            "tensor=<xx>,<yy>,<zz>,<xy>,<xz>,<yz>",
            "Symmetric tensors (6 columns, or 9 row by row) as ellipsoids along their eigenvectors");
        supportsOption("tensor-scale=<s>", "Ellipsoid semi-axis per unit of eigenvalue");
        supportsOption("technique=<name>", "How glyphs are drawn (default: the library's)");
        supportsOption("unlit", "No lighting");
    }

    const char* className() const override
    {
        return "osgGlyphs point data reader";
    }

    ReadResult readObject(const std::string& file, const Options* options) const override
    {
        return readNode(file, options);
    }

    ReadResult readNode(const std::string& file, const Options* options) const override
    {
        const std::string extension = osgDB::getLowerCaseFileExtension(file);
        if (!acceptsExtension(extension))
            return ReadResult::FILE_NOT_HANDLED;
        const std::string dataFile = extension == PSEUDO_EXTENSION ? osgDB::getNameLessExtension(file) : file;
        const std::string path = osgDB::findDataFile(dataFile, options);
        if (path.empty())
            return ReadResult::FILE_NOT_FOUND;

        ReadSettings settings;
        std::string error;
        if (!parseOptionString(getOptionString(options), settings, error))
            return failure(error);
        const osgGlyphsData::PointReadOptions readOptions = readOptionsFor(settings);
        if (readOptions.format.empty() && osgGlyphsData::formatFromExtension(path).empty())
            return failure(path + ": no point format for this extension; give one with format=<name>");
        return toScene(osgGlyphsData::readPointFile(path, readOptions, error), settings, error);
    }

    ReadResult readNode(std::istream& stream, const Options* options) const override
    {
        ReadSettings settings;
        std::string error;
        if (!parseOptionString(getOptionString(options), settings, error))
            return failure(error);
        if (settings.format.empty())
            return ReadResult::FILE_NOT_HANDLED; // a stream has no extension to tell its format
        return toScene(osgGlyphsData::readPointStream(stream, settings.format, "stream",
                                                      readOptionsFor(settings), error),
                       settings, error);
    }

private:
    static std::string getOptionString(const Options* options)
    {
        return options ? options->getOptionString() : std::string();
    }

    static ReadResult failure(const std::string& message)
    {
        return ReadResult("osgdb_glyphs: " + message);
    }

    /** The glyphs of a dataset, or the error of its reading or mapping. A scene in which a viewer
     * would see no glyph is read with a warning that says why. */
    static ReadResult toScene(const osg::ref_ptr<osgGlyphsData::PointDataset>& dataset,
                              const ReadSettings& settings, std::string& error)
    {
        osg::ref_ptr<osg::Node> scene = dataset ? createScene(*dataset, settings, error) : nullptr;
        if (!scene)
            return failure(error);
        const std::string hidden = osgGlyphs::diagnoseGlyphScene(*scene);
        if (!hidden.empty())
            OSG_WARN << "osgdb_glyphs: " << dataset->getSource() << ": warning: " << hidden << std::endl;
        return ReadResult(scene.get());
    }
};

REGISTER_OSGPLUGIN(glyphs, ReaderWriterGlyphs)
