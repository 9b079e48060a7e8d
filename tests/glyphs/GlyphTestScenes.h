// Small scenes of glyph clouds and fixed-function geometry shared by the glyph tests.

#ifndef OSGGLYPHS_TESTS_GLYPHTESTSCENES_H
#define OSGGLYPHS_TESTS_GLYPHTESTSCENES_H

#include "AnalyticScene.h"

#include <osgGlyphs/GlyphCloud>

#include <osg/Geode>
#include <osg/Light>
#include <osg/LightSource>
#include <osg/Notify>

#include <functional>
#include <mutex>
#include <sstream>
#include <vector>

namespace osgGlyphsTest
{

/** An OSG array from a list of values (OSG's arrays have no initializer-list constructor). */
template <class ArrayType>
osg::ref_ptr<ArrayType> makeArray(std::initializer_list<typename ArrayType::ElementDataType> values)
{
    return new ArrayType(values.begin(), values.end());
}

struct SphereSpec
{
    osg::Vec3 center;
    float radius;
    osg::Vec4ub color;
};

/** A cloud of spheres with per-glyph radii and RGBA colours, unlit unless asked. */
osg::ref_ptr<osgGlyphs::GlyphCloud> createSphereCloud(const std::vector<SphereSpec>& spheres,
                                                      bool lit = false);

/** The same spheres as analytic primitives; labels follow the spheres' order. */
void addSpheres(AnalyticScene& scene, const std::vector<SphereSpec>& spheres);

/** An unlit, flat-coloured square in the plane through center with the given normal. */
osg::ref_ptr<osg::Geometry> createFlatQuad(const osg::Vec3& center, const osg::Vec3& u, const osg::Vec3& v,
                                           const osg::Vec4& color);

osg::ref_ptr<osg::Geode> group(std::initializer_list<osg::Drawable*> drawables);

/** Which of the given unlit colours a pixel shows, -1 for none of them. */
int labelOfColor(const osg::Vec4ub& color, const std::vector<osg::Vec4ub>& palette, int tolerance = 2);

/** Counts, over the pixels whose analytic label is certain, wrong labels (the palette colour
 * shown against the analytic nearest primitive) and wrong depths. */
struct Agreement
{
    int certain = 0;
    int covered = 0;
    int wrongLabel = 0;
    int wrongDepth = 0;
    double worstDepthError = 0.0;
};

/** Compares an unlit frame with the analytic scene whose labels index the palette. Depth is
 * checked against depthTolerance except where the ray meets the surface at a grazing angle
 * (|cos| below grazingCosine), where the hit distance is ill-conditioned. */
Agreement compareWithTruth(const Frame& frame, const AnalyticScene& truth,
                           const std::vector<osg::Vec4ub>& palette, double depthTolerance,
                           double grazingCosine = 0.0);

/** Every pixel centre's ray against the frame, for glyphs too small for certain labels: how
 * many centres hit the analytic scene, and how many are covered when they should not be (or
 * not when they should), show the wrong colour, or have a depth beyond depthTolerance. */
struct CentreAgreement
{
    int hits = 0;
    int wrongCoverage = 0;
    int wrongLabel = 0;
    int wrongDepth = 0;
};

CentreAgreement compareEveryPixelCentre(const Frame& frame, const AnalyticScene& truth,
                                        const std::vector<osg::Vec4ub>& palette, double depthTolerance);

/** Light 0, directional from the upper left front (towards (-0.45, -0.65, 0.6)), with coloured
 * ambient, diffuse and specular parts: for a Renderer whose view has NO_LIGHT, so that every part
 * of a normal changes the shade. */
/** The pixel centres covered, against the truth's, and the depth error of those both cover. */
struct CoverageComparison
{
    int truthCentres = 0;
    int intersection = 0;
    int unionCentres = 0;
    std::vector<double> depthErrors; // |t - t_truth| / the glyphs' size

    double iou() const { return unionCentres ? double(intersection) / unionCentres : 0.0; }
    /** The error below which a fraction of the depth errors lie (sorts them). */
    double depthPercentile(double fraction);
};

/** Every pixel centre of frame against truth's ray through it; depth errors over size. */
CoverageComparison compareCoveredCentres(const Frame& frame, const AnalyticScene& truth, double size);

/** Picks along 400 rays through a scene (a 20 x 20 grid from y = -10 toward +y, slightly tilted)
 * against the truth's nearest hits: rays whose hit or miss disagrees, hits on another glyph, the
 * farthest point and the least aligned normal. */
struct PickingAgreement
{
    int hits = 0;
    int wrongHit = 0;
    int wrongLabel = 0;
    double worstDistance = 0.0;
    double worstNormalCosine = 1.0;
};

PickingAgreement comparePicksWithTruth(osg::Node& scene, const AnalyticScene& truth);

osg::ref_ptr<osg::LightSource> createColouredLight();

/** A directional osg::Light (position w = 0, in world coordinates, under no transform) as the glyph
 * shaders see it in the frame's view. */
EyeLight eyeLightOf(const osg::Light& light, const Frame& frame);

/** Lit colours against the truth: over the pixels whose label is certain (and that keep accepts,
 * given a hit), the colour of the label lit at the analytic hit with the analytic normal
 * (shadeLikeGlyphs) against the frame, to tolerance levels per channel. */
struct LitAgreement
{
    int checked = 0;
    int wrong = 0;
};

LitAgreement compareLitWithTruth(const Frame& frame, const AnalyticScene& truth,
                                 const std::vector<osg::Vec4ub>& labelColors, const EyeLight& light,
                                 const osg::Vec3d& material, int tolerance,
                                 const std::function<bool(const RayHit&)>& keep = nullptr);

/** Writes a shader file that OSG's data path finds before the embedded copy: name (such as
 * "lighting.glsl") under outputPath(folder)/osgGlyphs. Returns outputPath(folder), the folder to put
 * on the data path. */
std::string writeShaderOverride(const std::string& folder, const std::string& name, const std::string& text);

/** Renders the scene with the shader files of folder (see writeShaderOverride) first on OSG's data
 * path, then takes the folder off the path again; the programs are reloaded on both sides. */
Frame renderWithShaderFolder(Renderer& renderer, osg::Node* scene, const std::string& folder);

/** Collects OSG's warnings from construction until stop(). Create it with new. */
class NotifyCapture : public osg::NotifyHandler
{
public:
    NotifyCapture();
    void notify(osg::NotifySeverity severity, const char* message) override;
    /** Restores the previous handler and returns what was captured. */
    std::string stop();

private:
    osg::ref_ptr<osg::NotifyHandler> _previous;
    mutable std::mutex _mutex;
    std::ostringstream _text;
};

}

#endif
