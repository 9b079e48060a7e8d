// The scenes of tests/data/osgdb: every property that osgGlyphs' wrappers serialize, set to a value
// other than its default. make-fixtures.sh wrote them with the release before the wrappers had a
// version; SerializerVersionTest.cpp reads those files and compares what it reads with these scenes.

#ifndef OSGGLYPHS_TESTS_SERIALIZERFIXTURES_H
#define OSGGLYPHS_TESTS_SERIALIZERFIXTURES_H

#include <osgGlyphs/DepthPeeling>
#include <osgGlyphs/GlyphCloud>
#include <osgGlyphs/ScreenEffects>
#include <osgGlyphsTiles/TileRoot>

#include <osg/Group>

#include <cstddef>

namespace osgGlyphsFixtures
{

/** Clouds of every shape, one for each technique (the paper's included), that together write every
 * property of GlyphCloud: float and 16-bit positions, float scalars, scalars written as their
 * 16-bit steps, and RGBA colours. */
osg::ref_ptr<osg::Group> createClouds();

/** A ScreenEffects with every setting off its default, and no children. */
osg::ref_ptr<osgGlyphs::ScreenEffects> createScreenEffects();

/** A DepthPeeling of 3 layers peeled in passes, enabled. */
osg::ref_ptr<osgGlyphs::DepthPeeling> createDepthPeeling();

/** createScreenEffects() above createDepthPeeling() disabled: every setting of both off its
 * default. */
osg::ref_ptr<osg::Group> createEffects();

/** A TileRoot with a glyph budget beyond 32 bits. */
osg::ref_ptr<osgGlyphsTiles::TileRoot> createTileRoot();

/** The tile archive tiles.osga, as make-fixtures.sh has osgglyphconvert write it. */
constexpr unsigned int ARCHIVE_GLYPHS = 120;
constexpr std::size_t ARCHIVE_GLYPH_BUDGET = 12345;

}

#endif
