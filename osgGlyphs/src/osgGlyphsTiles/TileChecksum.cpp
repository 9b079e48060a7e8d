#include <osgGlyphsTiles/TileChecksum>
#include <osgGlyphsTiles/TileRoot>

#include <osgGlyphs/GlyphCloud>

#include <osg/NodeVisitor>
#include <osg/ValueObject>
#include <osgDB/Registry>

#include <cstdio>
#include <vector>

using namespace osgGlyphsTiles;

const char* const osgGlyphsTiles::TILE_CHECKSUM_USER_VALUE = "osgGlyphs_tileChecksum";

namespace
{

/** FNV-1a over the glyphs of the clouds a traversal meets. */
class GlyphHasher : public osg::NodeVisitor
{
public:
    GlyphHasher() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}

    void apply(osg::Drawable& drawable) override
    {
        const osgGlyphs::GlyphCloud* cloud = dynamic_cast<const osgGlyphs::GlyphCloud*>(&drawable);
        if (!cloud)
            return;
        const osg::Vec3d origin = cloud->getOrigin();
        add(&origin, sizeof(origin));
        const float radius = cloud->getRadius();
        add(&radius, sizeof(radius));
        const osg::Vec4 color = cloud->getColor();
        add(&color, sizeof(color));
        // The positions as drawn: compressed positions are stored, and read back, as grid points.
        osg::ref_ptr<const osg::Vec3Array> positions = cloud->getPositions();
        if (cloud->getCompressedPositions())
            positions = cloud->computeDrawnPositions();
        std::vector<const osg::Array*> arrays = {positions.get(), cloud->getRadii(), cloud->getScalars(),
                                                 cloud->getColors(), cloud->getVectors()};
        // Only theirs: the checksums of archives of other shapes stay as they were.
        if (osgGlyphs::isAxesShape(cloud->getShape()))
            arrays.insert(arrays.end(),
                          {cloud->getSemiAxes(), cloud->getOrientations(), cloud->getExponents()});
        for (const osg::Array* array : arrays)
        {
            const uint64_t size = array ? array->getTotalDataSize() : 0;
            add(&size, sizeof(size));
            if (array)
                add(array->getDataPointer(), array->getTotalDataSize());
        }
    }

    uint64_t hash = 14695981039346656037ULL;

private:
    void add(const void* data, std::size_t size)
    {
        const unsigned char* bytes = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < size; ++i)
            hash = (hash ^ bytes[i]) * 1099511628211ULL;
    }
};

std::string toHex(uint64_t value)
{
    char text[17];
    std::snprintf(text, sizeof(text), "%016llx", static_cast<unsigned long long>(value));
    return text;
}

/** Whether the file lies inside an OSG archive ("data.osga/n1-3.osgb"). */
bool isInsideTileArchive(const std::string& file)
{
    return file.find(".osga/") != std::string::npos || file.find(".osga\\") != std::string::npos;
}

}

uint64_t osgGlyphsTiles::computeTileChecksum(osg::Node& node)
{
    GlyphHasher hasher;
    node.accept(hasher);
    return hasher.hash;
}

void osgGlyphsTiles::setTileChecksum(osg::Node& node)
{
    node.setUserValue(TILE_CHECKSUM_USER_VALUE, toHex(computeTileChecksum(node)));
}

bool osgGlyphsTiles::checkTileChecksum(osg::Node& node, std::string& error)
{
    std::string stored;
    if (!node.getUserValue(TILE_CHECKSUM_USER_VALUE, stored))
    {
        error = "the tile has no checksum";
        return false;
    }
    const std::string computed = toHex(computeTileChecksum(node));
    if (stored != computed)
    {
        error = "the tile's glyphs do not match its checksum (" + computed + " instead of " + stored +
                "): the archive is corrupt";
        return false;
    }
    return true;
}

osgDB::ReaderWriter::ReadResult TileCheckingReadCallback::readNode(const std::string& file,
                                                                   const osgDB::Options* options)
{
    const bool tile = isInsideTileArchive(file);
    if (tile)
    {
        std::lock_guard<std::mutex> lock(_mutex);
        if (_refused.count(file))
            return osgDB::ReaderWriter::ReadResult("refused earlier");
    }
    // The next callback: the one given, else the Registry's (an application's own).
    osgDB::ReadFileCallback* next = _next.get();
    if (!next && osgDB::Registry::instance()->getReadFileCallback() != this)
        next = osgDB::Registry::instance()->getReadFileCallback();
    osgDB::ReaderWriter::ReadResult result =
        next ? next->readNode(file, options)
             : osgDB::Registry::instance()->readNodeImplementation(file, options);
    if (!tile)
        return result;
    std::string error;
    if (!result.validNode())
        error = "cannot be read" + (result.message().empty() ? std::string() : ": " + result.message());
    else if (checkTileChecksum(*result.getNode(), error))
    {
        // The tile's own PagedLODs read their children through this callback too.
        if (options && options->getReadFileCallback() == this)
        {
            osg::ref_ptr<osgDB::Options> inherited = options->cloneOptions();
            setTileDatabaseOptions(*result.getNode(), inherited.get());
        }
        return result;
    }
    {
        std::lock_guard<std::mutex> lock(_mutex);
        if (!_refused.insert(file).second)
            return osgDB::ReaderWriter::ReadResult(error);
    }
    OSG_WARN << "osgGlyphs: " << file << ": " << error
             << "; the tile is left out and its parent drawn in its place" << std::endl;
    return osgDB::ReaderWriter::ReadResult(error);
}

std::set<std::string> TileCheckingReadCallback::getRefusedTiles() const
{
    std::lock_guard<std::mutex> lock(_mutex);
    return _refused;
}
