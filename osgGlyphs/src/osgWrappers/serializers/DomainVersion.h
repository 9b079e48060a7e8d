#ifndef OSGGLYPHS_WRAPPERS_DOMAINVERSION_H
#define OSGGLYPHS_WRAPPERS_DOMAINVERSION_H

// Every wrapper of osgGlyphs, osgGlyphsPaper and osgGlyphsTiles is registered in the osgDB wrapper
// domain "osgGlyphs" (REGISTER_CUSTOM_OBJECT_WRAPPER(osgGlyphs, ...): the macro quotes the word, so
// each wrapper spells it out). The domain versions properties only: files name classes as before
// ("osgGlyphs::GlyphCloud"), and osgDB finds a wrapper by its class name alone.
//
// The versions, as osgDB::InputStream::getFileVersion("osgGlyphs") gives them while reading:
// - 0: a file that does not mention the domain. Every file written before the domain was, and every
//   file whose writer does not ask for a version: osgDB writes a custom domain's version only when
//   asked, and writes for version 0 otherwise.
// - 1 (DOMAIN_VERSION): the same properties as 0, in a file that says so in its header
//   ("#CustomDomain osgGlyphs 1" in .osgt); a writer asks through its osgDB::Options
//   (domainVersionEntry(), OSGGLYPHS_SERIALIZER_DOMAIN_ENTRY in <osgGlyphs/Version>). Tile
//   archives ask. Not for .osgx: OSG 3.6.5 writes the domain into XML files but cannot
//   read such a file back.
// - 2: GlyphCloud's SemiAxes, Orientations and Exponents (ellipsoids, superquadrics), after
//   UPDATE_TO_VERSION_SCOPED(2).
// The properties of version 0 and 1 are outside any UPDATE_TO_VERSION_SCOPED, so files of every
// version hold them. A property added later goes after UPDATE_TO_VERSION_SCOPED(3),
// OSGGLYPHS_SERIALIZER_VERSION (and its entry) becomes 3, and the writers that should store it ask
// for 3: osgDB reads it only from files that declare 2 or more and writes it only when
// asked. A file declaring a version this code does not know yet is read as far as this code knows it; what a
// later release appends is skipped.

#include <osgGlyphs/Version>

#include <string>

namespace osgGlyphsWrappers
{

constexpr const char* DOMAIN_NAME = OSGGLYPHS_SERIALIZER_DOMAIN;
constexpr int DOMAIN_VERSION = OSGGLYPHS_SERIALIZER_VERSION;

/** "osgGlyphs:<version>": the entry of osgDB::Options' plugin string data "CustomDomains"
 * ("name:version;name:version") that has osgDB write .osgt and .osgb files in that version. */
inline std::string domainVersionEntry(int version = DOMAIN_VERSION)
{
    return std::string(DOMAIN_NAME) + ":" + std::to_string(version);
}

}

#endif
