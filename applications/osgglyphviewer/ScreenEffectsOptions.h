// osgglyphviewer: screen-space ambient occlusion and outlines (osgGlyphs::ScreenEffects).

#ifndef OSGGLYPHVIEWER_SCREENEFFECTSOPTIONS_H
#define OSGGLYPHVIEWER_SCREENEFFECTSOPTIONS_H 1

#include <osgGlyphs/ScreenEffects>

#include <osg/ApplicationUsage>
#include <osg/ArgumentParser>
#include <osgGA/GUIEventHandler>

#include <string>

class ViewerScene;

/** Which ambient occlusion --ao turns on. */
enum class AmbientOcclusionMode
{
    Glyph,  // per glyph, computed on the CPU once per frame of data (GlyphCloud::computeOcclusion)
    Screen, // in screen space every frame (ScreenEffects)
    Both
};

/** The options of the screen-space effects, and the kind of --ao. */
struct ScreenEffectsOptions
{
    AmbientOcclusionMode aoMode = AmbientOcclusionMode::Glyph;
    float occlusionRadius = 0.0f; // --ao-radius; 0: ScreenEffects' automatic radius
    bool outlines = false;        // --outline [PIXELS]
    float outlineWidth = 1.5f;
};

void describeScreenEffectsOptions(osg::ApplicationUsage& usage);

/** Reads --ao-mode (which turns ambientOcclusion on), --ao-radius and --outline [PIXELS];
 * false with a one-line error on a bad value. */
bool readScreenEffectsOptions(osg::ArgumentParser& arguments, ScreenEffectsOptions& options,
                              bool& ambientOcclusion, std::string& error);

/** Turns the scene's per-glyph occlusion and its screen effects on as the options say. */
void applyScreenEffectsOptions(ViewerScene& scene, const ScreenEffectsOptions& options,
                               bool ambientOcclusion);

/** Keys of the screen effects: a toggles the screen-space ambient occlusion, e the outlines. */
class ScreenEffectsKeys : public osgGA::GUIEventHandler
{
public:
    explicit ScreenEffectsKeys(osgGlyphs::ScreenEffects* effects) : _effects(effects) {}

    bool handle(const osgGA::GUIEventAdapter& ea, osgGA::GUIActionAdapter& aa) override;
    void getUsage(osg::ApplicationUsage& usage) const override;

protected:
    ~ScreenEffectsKeys() override = default;

    osg::ref_ptr<osgGlyphs::ScreenEffects> _effects;
};

#endif
