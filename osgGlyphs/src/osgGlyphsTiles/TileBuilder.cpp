#include <osgGlyphsTiles/TileBuilder>
#include <osgGlyphsTiles/TileChecksum>
#include <osgGlyphsTiles/TileRoot>

#include "TileArchive.h"
#include "TileStream.h"

#include <osg/Version>
#include <osgDB/FileNameUtils>
#include <osgDB/FileUtils>
#include <osgDB/ObjectWrapper>
#include <osgDB/Registry>

#include <dlfcn.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <sstream>

using namespace osgGlyphsTiles;
using namespace osgGlyphsTiles::detail;
using osgGlyphs::GlyphCloud;
using osgGlyphs::GlyphColorMode;

namespace
{

/** The master file of a tile archive: its root node. */
const char* const ROOT_FILE = "root.osgb";

const char* const GLYPH_CLOUD_WRAPPER = "osgGlyphs::GlyphCloud";
const char* const TILE_ROOT_WRAPPER = "osgGlyphsTiles::TileRoot";

bool isPowerOfTwo(unsigned int value)
{
    return value && !(value & (value - 1));
}

/** A name for this process's next temporary files in directory (the system's when empty). */
std::string temporaryPrefix(const std::string& directory)
{
    static std::atomic<unsigned int> serial{0};
    std::error_code error;
    const std::filesystem::path folder =
        directory.empty() ? std::filesystem::temp_directory_path(error) : std::filesystem::path(directory);
    return (folder / ("osgglyphs-tiles-" + std::to_string(getpid()) + "-" + std::to_string(serial++)))
        .string();
}

/** Past the memory, the glyphs go into the temporary file in batches of this share of it (two at
 * a time in memory: one being sorted into buckets while the next fills). */
const std::size_t SPILL_BATCHES = 8;

/** The share of the progress of writing that sorting spilled glyphs into buckets takes (measured:
 * about a tenth of the time). */
const double SORTED_SHARE = 0.1;

/** Copies a cloud's settings with empty arrays of its kinds: a style, which costs nothing to
 * make whatever the cloud holds. */
class EmptyArraysCopy : public osg::CopyOp
{
public:
    osg::Array* operator()(const osg::Array* array) const override
    {
        return array ? static_cast<osg::Array*>(array->cloneType()) : nullptr;
    }
};

}

const char* const osgGlyphsTiles::COLOR_TITLE_USER_VALUE = "osgGlyphs_colorTitle";

bool osgGlyphsTiles::findTileSerializers(std::string& error)
{
    static std::mutex mutex;
    std::lock_guard<std::mutex> lock(mutex);
    osgDB::ObjectWrapperManager* wrappers = osgDB::Registry::instance()->getObjectWrapperManager();
    // The wrapper of each plugin's class, the first one missing.
    const auto missing = [wrappers]() -> const char*
    {
        if (!wrappers->findWrapper(GLYPH_CLOUD_WRAPPER))
            return "osgdb_serializers_osgglyphs";
        if (!wrappers->findWrapper(TILE_ROOT_WRAPPER))
            return "osgdb_serializers_osgglyphstiles";
        return nullptr;
    };
    if (!missing())
        return true;
    // The osgPlugins folder beside this library (installed), then the build tree's.
    Dl_info library;
    osgDB::FilePathList& paths = osgDB::Registry::instance()->getLibraryFilePathList();
    if (dladdr(reinterpret_cast<void*>(&findTileSerializers), &library) && library.dli_fname)
        paths.push_back(osgDB::getFilePath(osgDB::getRealPath(library.dli_fname)));
    paths.push_back(OSGGLYPHS_BUILD_LIBRARY_DIR);
    const char* plugin = missing();
    if (!plugin)
        return true;
    error = std::string("the osgGlyphs serializers (") + plugin +
            ") are not on OSG's plugin path: set OSG_LIBRARY_PATH to the folder that holds osgPlugins-" +
            osgGetVersion() + "/" + plugin + ".so";
    return false;
}

TileBuilder::TileBuilder(const GlyphCloud& style, const TileOptions& options)
    : _style(new GlyphCloud(style, EmptyArraysCopy())), _options(options), _glyphs(new TileGlyphs)
{
    _options.maxGlyphsPerTile = std::max(_options.maxGlyphsPerTile, 1u);
    if (!isPowerOfTwo(_options.cellsPerAxis) || _options.cellsPerAxis < 2 || _options.cellsPerAxis > 256)
        _options.cellsPerAxis = TileOptions().cellsPerAxis;
    if (!(_options.pixelsPerCell > 0.0f))
        _options.pixelsPerCell = TileOptions().pixelsPerCell;
    _glyphs->origin = style.getOrigin();
    // The style keeps the settings, not the glyphs (the positions first: an empty cloud is
    // consistent whatever its other arrays).
    _style->setPositions(new osg::Vec3Array);
    _style->setRadii(nullptr);
    if (_style->getColorMode() == GlyphColorMode::Scalar)
        _style->setScalars(new osg::FloatArray);
    else if (_style->getColorMode() == GlyphColorMode::RGBA)
        _style->setColors(new osg::Vec4ubArray);
    _style->setVectors(!osgGlyphs::isVectorShape(_style->getShape()) ? nullptr : new osg::Vec3Array);
    const bool axes = osgGlyphs::isAxesShape(_style->getShape());
    _style->setSemiAxes(axes ? new osg::Vec3Array : nullptr);
    _style->setOrientations(axes ? new osg::Vec4Array : nullptr);
    _style->setExponents(_style->getShape() == osgGlyphs::GlyphShape::Superquadric ? new osg::Vec2Array
                                                                                   : nullptr);
    _style->setSelection({});
    _style->setOcclusion(nullptr);
    _style->setCulling(osgGlyphs::GlyphCulling::Occlusion); // the default, whatever the style's
}

TileBuilder::~TileBuilder()
{
    if (_spilled.valid())
        _spilled.wait();
}

std::size_t TileBuilder::getNumGlyphs() const
{
    return _glyphs->size() + _spilledGlyphs;
}

bool TileBuilder::setBounds(const osg::BoundingBoxd& box)
{
    if (getNumGlyphs() || !box.valid())
        return false;
    _bounds = box;
    return true;
}

bool TileBuilder::addGlyphs(const GlyphCloud& cloud, std::string& error)
{
    const osg::Vec3Array* positions = cloud.getPositions();
    const std::size_t count = positions ? positions->size() : 0;
    const GlyphColorMode mode = _style->getColorMode();
    const bool vectors = osgGlyphs::isVectorShape(_style->getShape());
    const osg::FloatArray* radii = cloud.getRadii();
    const osg::FloatArray* scalars = cloud.getScalars();
    const osg::Vec4ubArray* colors = cloud.getColors();
    const osg::Vec3Array* vectorArray = cloud.getVectors();
    const bool axes = osgGlyphs::isAxesShape(_style->getShape());
    const bool superquadrics = _style->getShape() == osgGlyphs::GlyphShape::Superquadric;
    const osg::Vec3Array* semiAxes = cloud.getSemiAxes();
    const osg::Vec4Array* orientations = cloud.getOrientations();
    const osg::Vec2Array* exponents = superquadrics ? cloud.getExponents() : nullptr;
    // Ellipsoids and superquadrics keep a turn each, exponents each for superquadrics: the cloud's
    // defaults where it has none.
    const auto orientationOf = [orientations](std::size_t i)
    { return orientations ? (*orientations)[i] : osg::Vec4(0.0f, 0.0f, 0.0f, 1.0f); };
    const auto exponentsOf = [exponents](std::size_t i)
    { return exponents ? (*exponents)[i] : osg::Vec2(1.0f, 1.0f); };
    const auto radiusOf = [&](std::size_t i)
    {
        if (axes)
            return GlyphCloud::getAxesShapeRadius((*semiAxes)[i], exponentsOf(i));
        return radii ? (*radii)[i] : cloud.getRadius();
    };
    if (cloud.getColorMode() != mode)
    {
        error = "the glyphs' colours are not of the kind of the tiles' style";
        return false;
    }
    if ((radii && radii->size() < count) ||
        (mode == GlyphColorMode::Scalar && (!scalars || scalars->size() < count)) ||
        (mode == GlyphColorMode::RGBA && (!colors || colors->size() < count)) ||
        (vectors && (!vectorArray || vectorArray->size() < count)) ||
        (axes && (!semiAxes || semiAxes->size() < count || (orientations && orientations->size() < count))) ||
        (exponents && exponents->size() < count))
    {
        error = "the glyphs' arrays are shorter than their positions";
        return false;
    }
    TileGlyphs& glyphs = *_glyphs;
    const osg::Vec3d shift = cloud.getOrigin() - glyphs.origin;
    for (std::size_t i = 0; i < count; ++i)
    {
        const float radius = radiusOf(i);
        const char* wrong = nullptr;
        if (!(*positions)[i].valid() || !std::isfinite(radius) || radius < 0.0f ||
            (vectors && !(*vectorArray)[i].valid()))
            wrong = " has a non-finite position, radius or vector";
        else if (axes && !(radius > 0.0f))
            wrong = " has semi-axes or exponents that are not finite and > 0";
        else if (axes && !(orientationOf(i).length() > 0.0f && orientationOf(i).valid()))
            wrong = " has a turn (quaternion) that is zero or not finite";
        else if (_bounds.valid() &&
                 !_bounds.contains(osg::Vec3d(osg::Vec3f(osg::Vec3d((*positions)[i]) + shift))))
            wrong = " lies outside the bounds given to the tile builder";
        if (wrong)
        {
            error = "glyph " + std::to_string(getNumGlyphs() + i) + wrong;
            return false;
        }
    }
    // In slices: once past the memory, a batch at a time goes into the temporary file.
    for (std::size_t begin = 0; begin < count;)
    {
        const std::size_t limit = _spilledGlyphs ? spillBatch() : _options.maxGlyphsInMemory;
        const std::size_t end =
            std::min(count, begin + std::max<std::size_t>(limit - std::min(limit, glyphs.size()), 1));
        for (std::size_t i = begin; i < end; ++i)
        {
            glyphs.positions.push_back(osg::Vec3f(osg::Vec3d((*positions)[i]) + shift));
            glyphs.radii.push_back(radiusOf(i));
            _box.expandBy(osg::Vec3d(glyphs.positions.back()));
        }
        for (std::size_t i = begin; axes && i < end; ++i)
        {
            glyphs.semiAxes.push_back((*semiAxes)[i]);
            glyphs.orientations.push_back(orientationOf(i));
            if (superquadrics)
                glyphs.exponents.push_back(exponentsOf(i));
        }
        if (mode == GlyphColorMode::Scalar)
            for (std::size_t i = begin; i < end; ++i)
            {
                const float value = (*scalars)[i];
                if (std::isfinite(value))
                {
                    const bool first = glyphs.scalarMin > glyphs.scalarMax;
                    glyphs.scalarMin = first ? value : std::min(glyphs.scalarMin, value);
                    glyphs.scalarMax = first ? value : std::max(glyphs.scalarMax, value);
                }
                glyphs.scalars.push_back(value);
            }
        if (mode == GlyphColorMode::RGBA)
            glyphs.colors.insert(glyphs.colors.end(), colors->begin() + begin, colors->begin() + end);
        if (vectors)
            glyphs.vectors.insert(glyphs.vectors.end(), vectorArray->begin() + begin,
                                  vectorArray->begin() + end);
        if (glyphs.size() >= limit && !spill(error))
            return false;
        begin = end;
    }
    return true;
}

std::size_t TileBuilder::spillBatch() const
{
    return std::max<std::size_t>(_options.maxGlyphsInMemory / SPILL_BATCHES, 1);
}

bool TileBuilder::spill(std::string& error)
{
    if (!_buckets && !_spill)
    {
        const TileRecordFormat format(*_glyphs);
        const std::string path = temporaryPrefix(_options.temporaryDirectory);
        if (_bounds.valid())
            _buckets = createStreamBuckets(path, format, cubeAround(_bounds), _options, _bucketCounts);
        else
            _spill.reset(new TileSpill(path, format));
        if ((_buckets && !_buckets->isOpen()) || (_spill && !_spill->isOpen()))
        {
            error = path + ": cannot create a temporary file (TileOptions::temporaryDirectory)";
            _buckets.reset();
            _spill.reset();
            return false;
        }
    }
    _spilledGlyphs += _glyphs->size();
    if (_spill)
    {
        if (!_spill->append(*_glyphs, 0, _glyphs->size(), error))
            return false;
        _glyphs->clear();
        return true;
    }
    // Sorted on another thread while the next glyphs come, in the arrays of the batch before.
    if (!finishSpill(error))
        return false;
    if (!_spilling)
        _spilling.reset(new TileGlyphs);
    TileGlyphs& batch = *_spilling;
    batch.swapGlyphs(*_glyphs);
    _glyphs->clear();
    _spilled = std::async(std::launch::async,
                          [this] { return _buckets->add(*_spilling, 0, _spilling->size(), _spillError); });
    return true;
}

bool TileBuilder::finishSpill(std::string& error) const
{
    if (_spilled.valid())
        _spillFailed = !_spilled.get() || _spillFailed;
    if (_spillFailed)
        error = _spillError;
    return !_spillFailed;
}

osg::ref_ptr<osg::Node> TileBuilder::buildTree(TileWriter& writer, std::string& error) const
{
    const std::size_t budget = _options.maxGlyphsInMemory;
    if (!finishSpill(error))
        return nullptr;
    if (_buckets)
        return buildStreamedTree(*_buckets, _bucketCounts, *_glyphs, writer, budget,
                                 _buckets->getPath() + "-split", error);
    if (_spill)
    {
        // Without bounds, the cube was known only now: one more pass sorts the glyphs.
        std::vector<std::size_t> counts;
        const std::unique_ptr<TileBuckets> buckets = createStreamBuckets(
            _spill->getPath() + "-sorted", _spill->getFormat(), writer.getCube(), _options, counts);
        if (!buckets->isOpen())
        {
            error = buckets->getPath() + ": cannot create a temporary file";
            return nullptr;
        }
        bool added = true;
        if (!_spill->read(
                [&](const TileGlyphs& block)
                {
                    added = buckets->add(block, 0, block.size(), error);
                    writer.setProgress(SORTED_SHARE * double(buckets->size()) / double(_spill->size()));
                    return added;
                },
                error) ||
            !added)
            return nullptr;
        return buildStreamedTree(*buckets, std::move(counts), *_glyphs, writer, budget,
                                 _spill->getPath() + "-split", error);
    }
    TileTree tree(*_glyphs, writer);
    if (!tree.size())
        return new osg::Group;
    osg::ref_ptr<osg::Node> root = tree.buildNode(0, 0, 0, tree.size());
    if (!root)
        error = writer.getError();
    return root;
}

osg::ref_ptr<osg::Node> TileBuilder::createTree() const
{
    std::string error;
    TileWriter writer(*_style, _options, cubeAround(getOctreeBox()), *_glyphs, nullptr, getNumGlyphs(), {});
    osg::ref_ptr<osg::Node> tree = buildTree(writer, error);
    return tree ? createRoot(*tree) : nullptr;
}

osg::ref_ptr<TileRoot> TileBuilder::createRoot(osg::Node& tree) const
{
    osg::ref_ptr<TileRoot> root = new TileRoot;
    root->setGlyphBudget(_options.glyphBudget);
    if (!_colorTitle.empty())
        root->setUserValue(COLOR_TITLE_USER_VALUE, _colorTitle);
    root->addChild(&tree);
    setTileChecksum(*root);
    return root;
}

bool TileBuilder::write(const std::string& path, std::string& error, const ProgressFunction& progress)
{
    if (!findTileSerializers(error))
        return false;
    if ((_spill || _buckets) && !_glyphs->positions.empty())
    {
        if (!spill(error) || !finishSpill(error))
            return false;
        _glyphs->release();
        _spilling.reset();
    }
    if (osgDB::fileExists(path) && std::remove(path.c_str()) != 0)
    {
        error = path + ": cannot replace the file";
        return false;
    }
    TileArchive archive;
    if (!archive.create(path, error))
    {
        error = path + ": " + error;
        return false;
    }
    // The first file written is the archive's master file: a place holder until the root is
    // made, after its descendants, and written again under the same name.
    osg::ref_ptr<osg::Group> placeHolder = new osg::Group;
    std::string archiveError;
    bool written = archive.writeNode(*placeHolder, ROOT_FILE, archiveError);
    std::string treeError;
    osg::ref_ptr<osg::Node> root;
    TileWriter writer(*_style, _options, cubeAround(getOctreeBox()), *_glyphs, &archive, getNumGlyphs(),
                      progress);
    if (written)
        root = buildTree(writer, treeError);
    if (root)
        root = createRoot(*root);
    written = written && root.valid() && archive.writeNode(*root, ROOT_FILE, archiveError);
    written = archive.close(archiveError) && written;
    if (!written)
    {
        error = path + ": " +
                (!treeError.empty()      ? treeError
                 : !archiveError.empty() ? archiveError
                                         : "cannot write the tiles");
        return false;
    }
    return true;
}
