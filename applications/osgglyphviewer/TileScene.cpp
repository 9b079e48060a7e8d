#include "TileScene.h"

#include "BuiltinScenes.h"

#include <osgGlyphsTiles/TileBuilder>
#include <osgGlyphsTiles/TileChecksum>
#include <osgGlyphsTiles/TileRoot>

#include <osg/NodeVisitor>
#include <osgDB/FileNameUtils>
#include <osgDB/FileUtils>
#include <osgDB/ReadFile>
#include <osgDB/Registry>

namespace
{

/** The first glyph cloud in a graph (the root tile's). */
class FirstCloud : public osg::NodeVisitor
{
public:
    FirstCloud() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
    void apply(osg::Drawable& drawable) override
    {
        if (!_cloud)
            _cloud = dynamic_cast<osgGlyphs::GlyphCloud*>(&drawable);
    }
    void apply(osg::Node& node) override
    {
        if (!_cloud)
            traverse(node);
    }
    osgGlyphs::GlyphCloud* get() const { return _cloud; }

private:
    osgGlyphs::GlyphCloud* _cloud = nullptr;
};

}

bool isTileArchive(const std::string& file)
{
    return osgDB::getLowerCaseFileExtension(file) == "osga";
}

osg::ref_ptr<ViewerScene> createTileScene(const ViewerOptions& options, std::string& error)
{
    if (options.frame > 0)
    {
        error = "--frame " + std::to_string(options.frame) + ": a tile archive holds one frame (0)";
        return nullptr;
    }
    if (!osgDB::fileExists(options.file))
    {
        error = options.file + ": no such file";
        return nullptr;
    }
    if (!osgGlyphsTiles::findTileSerializers(error))
        return nullptr;
    osg::ref_ptr<osg::Node> root = osgDB::readNodeFile(options.file);
    if (!root)
    {
        error = options.file + ": not an OSG archive of glyph tiles (osgDB cannot read it)";
        return nullptr;
    }
    std::string checksumError;
    if (!osgGlyphsTiles::checkTileChecksum(*root, checksumError))
    {
        error = options.file + ": root tile: " + checksumError;
        return nullptr;
    }
    // The root's TileRoot checks the tiles paged in below it (a corrupt one is left out) and
    // keeps the budget; an archive of an earlier osgglyphconvert gets one here.
    osg::ref_ptr<osgGlyphsTiles::TileRoot> tileRoot = dynamic_cast<osgGlyphsTiles::TileRoot*>(root.get());
    if (!tileRoot)
    {
        tileRoot = new osgGlyphsTiles::TileRoot;
        std::string title;
        if (root->getUserValue(osgGlyphsTiles::COLOR_TITLE_USER_VALUE, title))
            tileRoot->setUserValue(osgGlyphsTiles::COLOR_TITLE_USER_VALUE, title);
        tileRoot->addChild(root.get());
        root = tileRoot;
    }
    if (options.glyphBudget)
        tileRoot->setGlyphBudget(options.glyphBudget);
    FirstCloud first;
    root->accept(first);
    osgGlyphsData::ColorKey key;
    if (const osgGlyphs::GlyphCloud* cloud = first.get())
        if (cloud->getColorMode() == osgGlyphs::GlyphColorMode::Scalar)
        {
            key.kind = osgGlyphsData::ColorKey::Scalar;
            root->getUserValue(osgGlyphsTiles::COLOR_TITLE_USER_VALUE, key.title);
            key.colorMap = const_cast<osgGlyphs::ColorMap*>(cloud->getColorMap());
            key.min = cloud->getScalarRangeMin();
            key.max = cloud->getScalarRangeMax();
        }
    osg::ref_ptr<ViewerScene> scene = createFixedScene(root.get(), key);
    const std::size_t budget = tileRoot->getGlyphBudget();
    scene->setDescription(
        options.file + ": glyph tiles paged in by size on screen, " +
        (budget ? "at most " + std::to_string(budget) + " glyphs a frame" : "no glyph budget") +
        (first.get() ? std::string() : " (no glyphs in the root tile)"));
    return scene;
}
