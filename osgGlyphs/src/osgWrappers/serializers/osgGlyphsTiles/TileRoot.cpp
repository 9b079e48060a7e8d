#include "GlyphCount.h"

#include <osgGlyphsTiles/TileRoot>

#include <osgDB/InputStream>
#include <osgDB/ObjectWrapper>
#include <osgDB/OutputStream>

#include <cmath>
#include <sstream>
#include <string>

using osgGlyphsTiles::TileRoot;

namespace
{

/** The budget the reading options ask for ("glyphBudget=N" in the option string), if any. */
bool budgetFromOptions(const osgDB::Options* options, double& budget)
{
    if (!options)
        return false;
    std::istringstream words(options->getOptionString());
    const std::string key = std::string(osgGlyphsTiles::GLYPH_BUDGET_OPTION) + "=";
    for (std::string word; words >> word;)
        if (word.compare(0, key.size(), key) == 0)
        {
            std::istringstream value(word.substr(key.size()));
            double asked = -1.0;
            if (value >> asked && value.eof() && asked >= 0.0 &&
                asked <= osgGlyphsWrappers::MAX_GLYPH_COUNT && asked == std::floor(asked))
            {
                budget = asked;
                return true;
            }
            OSG_WARN << "osgGlyphs: option " << word << ": the glyph budget must be a whole number of glyphs "
                     << "from 0 (no budget) to 1e15; the archive's is kept" << std::endl;
        }
    return false;
}

}

static bool checkGlyphBudget(const TileRoot&)
{
    return true;
}

static bool readGlyphBudget(osgDB::InputStream& is, TileRoot& root)
{
    std::size_t stored = osgGlyphsTiles::TileBudget::DEFAULT_MAX_GLYPHS;
    osgGlyphsWrappers::readGlyphCount(is, stored);
    double budget = static_cast<double>(stored);
    if (budgetFromOptions(is.getOptions(), budget))
        OSG_NOTICE << "osgGlyphs: glyph budget " << budget << " glyphs, from the options" << std::endl;
    root.setGlyphBudget(static_cast<std::size_t>(budget));
    return true;
}

static bool writeGlyphBudget(osgDB::OutputStream& os, const TileRoot& root)
{
    osgGlyphsWrappers::writeGlyphCount(os, root.getGlyphBudget());
    return true;
}

REGISTER_CUSTOM_OBJECT_WRAPPER(osgGlyphs, osgGlyphsTiles_TileRoot, new osgGlyphsTiles::TileRoot,
                               osgGlyphsTiles::TileRoot,
                               "osg::Object osg::Node osg::Group osgGlyphsTiles::TileRoot")
{
    ADD_USER_SERIALIZER(GlyphBudget);
}
