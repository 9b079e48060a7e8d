// osgglyphviewer: transparent glyphs (--opacity), blended in depth order by depth peeling.

#ifndef OSGGLYPHVIEWER_TRANSPARENCY_H
#define OSGGLYPHVIEWER_TRANSPARENCY_H 1

#include <osgGlyphs/DepthPeeling>

#include <osg/ApplicationUsage>
#include <osg/ArgumentParser>
#include <osg/Uniform>

#include <string>

/** What the command line says about transparency. */
struct TransparencyOptions
{
    bool on = false;      // --opacity given
    float opacity = 0.5f; // --opacity V; also what key x turns on without it
    unsigned int layers = osgGlyphs::DepthPeeling::DEFAULT_NUM_LAYERS;          // --peel-layers N
    osgGlyphs::DepthPeeling::Method method = osgGlyphs::DepthPeeling::K_BUFFER; // --transparency M
};

void describeTransparencyOptions(osg::ApplicationUsage& usage);

/** Reads --opacity, --peel-layers and --transparency; false with a one-line error on a bad value. */
bool readTransparencyOptions(osg::ArgumentParser& arguments, TransparencyOptions& options,
                             std::string& error);

/** The depth peeling node above the content, and the opacity it gives every glyph below it (which
 * overrides the clouds' own, and multiplies the alpha of their colours). */
class Transparency : public osg::Referenced
{
public:
    Transparency();

    /** The node to put above the glyphs. */
    osgGlyphs::DepthPeeling* getNode() { return _peeling.get(); }

    void setOptions(const TransparencyOptions& options);
    /** Transparent at the options' opacity, or opaque (key x). */
    void setOn(bool on);
    bool isOn() const { return _options.on; }
    float getOpacity() const { return _options.opacity; }

protected:
    ~Transparency() override = default;

    TransparencyOptions _options;
    osg::ref_ptr<osgGlyphs::DepthPeeling> _peeling;
    osg::ref_ptr<osg::Uniform> _opacity;
};

#endif
