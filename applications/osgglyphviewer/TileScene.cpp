#include "TileScene.h"

#include "BuiltinScenes.h"

#include <osgGlyphsTiles/TileBuilder>
#include <osgGlyphsTiles/TileChecksum>
#include <osgGlyphsTiles/TileRoot>
#include <osgGlyphsTiles/TileSeriesPlayer>

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

/** The colour key of the tiles under root: the first cloud's colour map and range, which every
 * tile of a dataset shares. */
osgGlyphsData::ColorKey findColorKey(osg::Node& root, bool& hasGlyphs)
{
    FirstCloud first;
    root.accept(first);
    hasGlyphs = first.get() != nullptr;
    osgGlyphsData::ColorKey key;
    if (const osgGlyphs::GlyphCloud* cloud = first.get())
        if (cloud->getColorMode() == osgGlyphs::GlyphColorMode::Scalar)
        {
            key.kind = osgGlyphsData::ColorKey::Scalar;
            root.getUserValue(osgGlyphsTiles::COLOR_TITLE_USER_VALUE, key.title);
            key.colorMap = const_cast<osgGlyphs::ColorMap*>(cloud->getColorMap());
            key.min = cloud->getScalarRangeMin();
            key.max = cloud->getScalarRangeMax();
        }
    return key;
}

std::string describeBudget(std::size_t budget)
{
    return budget ? "at most " + std::to_string(budget) + " glyphs a frame" : "no glyph budget";
}

bool isSeriesIndex(const std::string& file)
{
    const std::string extension = osgDB::getLowerCaseFileExtension(file);
    return extension == "osgt" || extension == "osgb";
}

/** A series of tile archives (osgglyphconvert --frame-range ... out.osgt), played by a
 * TileSeriesPlayer. */
osg::ref_ptr<ViewerScene> createSeriesScene(const ViewerOptions& options, std::string& error)
{
    osg::ref_ptr<osgGlyphsTiles::TileSeries> series =
        dynamic_cast<osgGlyphsTiles::TileSeries*>(osgDB::readNodeFile(options.file));
    if (!series || series->getNumFrames() == 0)
    {
        error = options.file + (series ? ": a series of no frames"
                                       : ": not a series of tile archives (osgglyphconvert --frame-range ... "
                                         "out.osgt writes one)");
        return nullptr;
    }
    if (options.frame >= series->getNumFrames())
    {
        error = "--frame " + std::to_string(options.frame) + ": " + options.file + " has " +
                std::to_string(series->getNumFrames()) + " frames, counted from 0";
        return nullptr;
    }
    if (options.glyphBudget)
        series->setGlyphBudget(options.glyphBudget);
    osg::ref_ptr<osgGlyphsTiles::TileSeriesPlayer> player =
        new osgGlyphsTiles::TileSeriesPlayer(series.get());
    applyPlaybackOptions(options.playback, *player);
    series->setUpdateCallback(player.get());
    if (!player->showNow(static_cast<double>(options.frame), error))
        return nullptr;
    bool hasGlyphs = false;
    const osgGlyphsData::ColorKey key = findColorKey(*series->getShownRoot(), hasGlyphs);
    ViewerScene::FrameSource frames = [series, player](std::size_t frame, std::string& frameError)
    {
        if (!player->showNow(static_cast<double>(frame), frameError))
            return osg::ref_ptr<osg::Node>();
        return osg::ref_ptr<osg::Node>(series);
    };
    osg::ref_ptr<ViewerScene> scene = new ViewerScene(frames, series->getNumFrames(), key);
    scene->setPlayer(player.get());
    const std::size_t budget = series->getShownRoot()->getGlyphBudget();
    scene->setDescription(options.file + ": " + std::to_string(series->getNumFrames()) +
                          " frames of glyph tiles paged in by size on screen, " + describeBudget(budget) +
                          (hasGlyphs ? std::string() : " (no glyphs in the root tile)"));
    player->setPlaying(options.playback.play);
    return scene;
}

}

bool isTileArchive(const std::string& file)
{
    return osgDB::getLowerCaseFileExtension(file) == "osga" || isSeriesIndex(file);
}

osg::ref_ptr<ViewerScene> createTileScene(const ViewerOptions& options, std::string& error)
{
    if (!osgDB::fileExists(options.file))
    {
        error = options.file + ": no such file";
        return nullptr;
    }
    if (!osgGlyphsTiles::findTileSerializers(error))
        return nullptr;
    if (isSeriesIndex(options.file))
        return createSeriesScene(options, error);
    if (options.frame > 0)
    {
        error = "--frame " + std::to_string(options.frame) + ": a tile archive holds one frame (0)";
        return nullptr;
    }
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
    bool hasGlyphs = false;
    const osgGlyphsData::ColorKey key = findColorKey(*root, hasGlyphs);
    osg::ref_ptr<ViewerScene> scene = createFixedScene(root.get(), key);
    scene->setDescription(options.file + ": glyph tiles paged in by size on screen, " +
                          describeBudget(tileRoot->getGlyphBudget()) +
                          (hasGlyphs ? std::string() : " (no glyphs in the root tile)"));
    return scene;
}
