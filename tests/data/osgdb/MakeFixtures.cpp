// Writes the scenes of tests/osgdb/SerializerFixtures.h into a folder as .osgt and .osgb files,
// with osgDB's defaults (no options), as a program using osgGlyphs writes them.
//   make_osgdb_fixtures <folder>

#include "SerializerFixtures.h"

#include <osgDB/WriteFile>

#include <iostream>
#include <string>

namespace
{

bool writeBoth(const osg::Node& scene, const std::string& folder, const std::string& name)
{
    for (const char* extension : {".osgt", ".osgb"})
    {
        const std::string path = folder + "/" + name + extension;
        if (!osgDB::writeNodeFile(scene, path))
        {
            std::cerr << "make_osgdb_fixtures: could not write " << path << std::endl;
            return false;
        }
    }
    return true;
}

}

int main(int argc, char** argv)
{
    if (argc != 2)
    {
        std::cerr << "usage: make_osgdb_fixtures <folder>" << std::endl;
        return 2;
    }
    const std::string folder = argv[1];
    const bool written = writeBoth(*osgGlyphsFixtures::createClouds(), folder, "clouds") &&
                         writeBoth(*osgGlyphsFixtures::createEffects(), folder, "effects") &&
                         writeBoth(*osgGlyphsFixtures::createTileRoot(), folder, "tileroot");
    return written ? 0 : 1;
}
