// osgglyphviewer: how the columns of point data become glyphs.

#ifndef OSGGLYPHVIEWER_GLYPHMAPPING_H
#define OSGGLYPHVIEWER_GLYPHMAPPING_H 1

#include <osgGlyphs/GlyphCloud>
#include <osgGlyphs/PointData>

#include <string>
#include <utility>
#include <vector>

/** What the command line says about turning columns into glyphs. Empty names and values <= 0
 * mean "choose from the data". */
struct GlyphMappingOptions
{
    /** --position: three columns, or empty for osgGlyphs::getPositions' defaults. */
    std::vector<std::string> positionColumns;
    /** --radius: one radius for all glyphs, or the factor of --radius-by. */
    float radius = 0.0f;
    /** --radius-by: a column of radii. */
    std::string radiusColumn;
    /** --color-by: a column name or "speed". */
    std::string colorBy;
    /** --colormap, resolved (never null). */
    osg::ref_ptr<osgGlyphs::ColorMap> colorMap;
    /** --range. */
    bool hasRange = false;
    float rangeMin = 0.0f;
    float rangeMax = 1.0f;
    /** --vector: three columns, or empty for vx,vy,vz (then velo_*, velocity_*). */
    std::vector<std::string> vectorColumns;
    /** --length-scale. */
    float lengthScale = 0.0f;
    osgGlyphs::GlyphShape shape = osgGlyphs::GlyphShape::Sphere;
    osgGlyphs::GlyphTechnique technique = osgGlyphs::DEFAULT_GLYPH_TECHNIQUE;
};

/** What the colours of a cloud stand for: a colour map over a range of a scalar, a few labelled
 * categories, or nothing (one colour). */
struct ColorKey
{
    enum Kind
    {
        None,
        Scalar,
        Categories
    };
    Kind kind = None;
    std::string title;
    osg::ref_ptr<osgGlyphs::ColorMap> colorMap;
    float min = 0.0f;
    float max = 1.0f;
    std::vector<std::pair<std::string, osg::Vec4>> categories;
};

/** Sets what every cloud of the viewer shares: shape, technique, colour map and range. */
void applyGlyphStyle(osgGlyphs::GlyphCloud& cloud, const GlyphMappingOptions& options);

/** Turns frames of a dataset into GlyphClouds under one mapping.
 *
 * prepare() resolves the column names once and fixes what must stay the same from frame to
 * frame: the radius, the vector length scale and the colour range (over every frame). Defaults:
 * - colour: the --color-by column or speed; else the element colours where the data has an
 *   "element" column; else the colours of "red", "green", "blue" columns (0..1, or 0..255 when
 *   a value exceeds 1); else speed where it has velocity columns; else a categorical palette
 *   over a "type" (LAMMPS) or "species" column; else one colour;
 * - radius: the element's covalent radius where the data has elements; else 0.4 (spheres) or
 *   0.2 (vector glyphs) times the median nearest-neighbour distance, at least 1/250 (1/500) of
 *   the diagonal of the points' bounding box;
 * - length scale: the mean vector is 4 radii long. */
class GlyphMapper
{
public:
    explicit GlyphMapper(const GlyphMappingOptions& options) : _options(options) {}

    /** Resolves the mapping on a dataset, from its frame startFrame. On failure error is one
     * line naming the option and, for a missing column, the columns the data has. */
    bool prepare(const osgGlyphs::PointDataset& dataset, std::size_t startFrame, std::string& error);

    /** The glyphs of one frame. nullptr, with error set, when the frame lacks a column. */
    osg::ref_ptr<osgGlyphs::GlyphCloud> createCloud(const osgGlyphs::PointData& data,
                                                    std::string& error) const;

    const ColorKey& getColorKey() const { return _key; }

    /** One line saying how the data is drawn, for the console. */
    std::string describe() const;

protected:
    enum class ColorSource
    {
        Uniform,
        Column,
        Speed,
        Element,
        RGB,
        Category
    };

    bool resolveVectors(const osgGlyphs::PointData& data, bool required, std::string& error);
    bool resolveColor(const osgGlyphs::PointData& data, std::string& error);
    bool computeScalars(const osgGlyphs::PointData& data, std::vector<float>& scalars,
                        std::string& error) const;
    bool computeRange(const osgGlyphs::PointDataset& dataset, std::string& error);
    void computeSizes(const osgGlyphs::PointData& data, const std::vector<osg::Vec3f>& positions);
    void buildCategoryKey(const osgGlyphs::PointData& data);
    osg::Vec4 getCategoryColor(float value) const;

    GlyphMappingOptions _options;
    ColorSource _colorSource = ColorSource::Uniform;
    std::string _colorColumn;
    std::vector<std::string> _vectorColumns; // empty: no vectors
    std::string _radiusColumn;               // radii from a column (times _radius)
    bool _elementRadii = false;              // radii from the element table
    float _radius = 1.0f;
    float _lengthScale = 1.0f;
    float _rgbScale = 1.0f; // 1/255 for colour columns of bytes
    ColorKey _key;
};

#endif
