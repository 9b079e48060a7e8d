#include "SeriesIndex.h"

#include <osgGlyphsTiles/TileBuilder>

#include <osgDB/FileNameUtils>
#include <osgDB/WriteFile>

bool isSeriesIndex(const std::string& output)
{
    const std::string extension = osgDB::getLowerCaseFileExtension(output);
    return extension == "osgt" || extension == "osgb";
}

std::string seriesFramePattern(const std::string& output)
{
    return osgDB::getNameLessExtension(output) + "_%06d.osga";
}

bool writeSeriesIndex(const osgGlyphsTiles::TileSeries& series, const std::string& output, std::string& error)
{
    if (!osgGlyphsTiles::findTileSerializers(error))
        return false;
    if (!osgDB::writeNodeFile(series, output))
    {
        error = output + ": cannot write the series' index";
        return false;
    }
    return true;
}
