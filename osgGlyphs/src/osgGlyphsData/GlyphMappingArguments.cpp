#include <osgGlyphsData/GlyphMapping>

#include <osgGlyphs/GlyphTechnique>

namespace
{

std::string joinNames(const std::vector<std::string>& names)
{
    std::string joined;
    for (const std::string& name : names)
        joined += (joined.empty() ? "" : ", ") + name;
    return joined;
}

}

bool osgGlyphsData::readGlyphMappingArguments(osg::ArgumentParser& arguments, GlyphMappingOptions& options,
                                              std::string& error)
{
    options.optionPrefix = "--";
    for (const std::string& name : getGlyphMappingOptionNames())
    {
        const std::string option = "--" + name;
        std::string value, maximum;
        bool found = false;
        if (name == "unlit")
            found = arguments.read(option);
        else if (name == "range")
        {
            found = arguments.read(option, value, maximum);
            value += "," + maximum;
        }
        else if (name != "color" && name != "lit")
            found = arguments.read(option, value);
        if (found && !setGlyphMappingOption(options, name, value, error))
            return false;
    }
    return true;
}

void osgGlyphsData::describeGlyphMappingArguments(osg::ApplicationUsage& usage)
{
    usage.addCommandLineOption("--position <x,y,z>", "Position columns (default x,y,z, then xu,yu,zu, "
                                                     "then xs,ys,zs scaled by the simulation box).");
    usage.addCommandLineOption("--radius <r>", "One radius for every glyph (default: from the elements, else "
                                               "0.4 (spheres) or 0.2 (vectors) times the median "
                                               "nearest-neighbour distance). With --radius-by, a factor.");
    usage.addCommandLineOption("--radius-by <column>", "Radius of each glyph from a column. Without it, a "
                                                       "column named radius, or diameter (halved), gives "
                                                       "the radii (LAMMPS granular dumps, most CSV files).");
    usage.addCommandLineOption("--color-by <column|speed>",
                               "Colour by a column through the colour map, or by speed, the length of "
                               "the vectors (--vector). Default: element colours where the data has an "
                               "element column, else its red,green,blue columns, else speed where it has "
                               "vectors (a LAMMPS dump with vx,vy,vz), else a palette of LAMMPS types or "
                               "species, else one colour.");
    usage.addCommandLineOption("--colormap <name|file>",
                               "Colour map: " + joinNames(osgGlyphs::ColorMap::getBuiltinNames()) +
                                   " (default viridis), or a file of #rrggbb lines.");
    usage.addCommandLineOption("--range <min> <max>",
                               "Values mapped to the ends of the colour map (default: the data's range; of "
                               "a trajectory, over the frames --range-sample says).");
    usage.addCommandLineOption("--vector <vx,vy,vz>", "Vector columns for cones, arrows, cylinders and speed "
                                                      "(default vx,vy,vz, then velo_*, velocity_*).");
    usage.addCommandLineOption("--length-scale <s>", "Vector glyph length per unit of vector length "
                                                     "(default: the mean vector is 4 radii long).");
    usage.addCommandLineOption("--glyph <shape>",
                               "sphere (default), cone, arrow, cylinder, ellipsoid (the default "
                               "where the data has ellipsoids' shape columns) or superquadric (with "
                               "--tensor); cones, arrows and cylinders point along the vectors.");
    usage.addCommandLineOption("--tensor <xx,yy,zz,xy,xz,yz>",
                               "A symmetric tensor per point (6 columns in LAMMPS's stress/atom order, or 9 "
                               "row by row) drawn as an ellipsoid along its eigenvectors, semi-axes "
                               "|eigenvalue| x --tensor-scale, or with --glyph superquadric as Kindlmann's "
                               "superquadric glyph; --color-by trace (default), anisotropy or "
                               "eigenvalue1..3 (largest first, signed).");
    usage.addCommandLineOption("--tensor-scale <s>", "Semi-axis length per unit of eigenvalue (default: the "
                                                     "median largest |eigenvalue| is the default radius).");
    usage.addCommandLineOption("--unlit", "Flat colours instead of lit glyphs (key l toggles).");
    usage.addCommandLineOption("--technique <name>",
                               "How glyphs are drawn: " + joinNames(osgGlyphs::getTechniqueNames()) +
                                   " (default " + osgGlyphs::DEFAULT_GLYPH_TECHNIQUE + ").");
}
