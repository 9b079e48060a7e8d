#include "ScreenEffectsOptions.h"

#include "ViewerScene.h"

#include <cmath>
#include <iostream>

void describeScreenEffectsOptions(osg::ApplicationUsage& usage)
{
    usage.addCommandLineOption(
        "--ao-mode <glyph|screen|both>",
        "Which ambient occlusion --ao turns on (given alone, it turns it on too). glyph (the default): per "
        "glyph, exact for the glyphs' true shapes, the same from every view, free per frame once computed, "
        "and the same in headless renders; screen: screen-space occlusion from the depth of each frame "
        "(osgGlyphs::ScreenEffects), which needs no precomputation and includes other geometry, at a cost "
        "per frame and with a result that depends on the view; both.");
    usage.addCommandLineOption("--ao-radius <r>",
                               "How far occluders reach in screen-space ambient occlusion, "
                               "in data units (default twice the glyphs' mean radius).");
    usage.addCommandLineOption("--outline [pixels]",
                               "Dark outlines at silhouettes and where glyphs meet, "
                               "so many pixels wide (default 1.5); key e toggles them.");
}

namespace
{

bool parseMode(const std::string& name, AmbientOcclusionMode& mode)
{
    if (name == "glyph")
        mode = AmbientOcclusionMode::Glyph;
    else if (name == "screen")
        mode = AmbientOcclusionMode::Screen;
    else if (name == "both")
        mode = AmbientOcclusionMode::Both;
    else
        return false;
    return true;
}

}

bool readScreenEffectsOptions(osg::ArgumentParser& arguments, ScreenEffectsOptions& options,
                              bool& ambientOcclusion, std::string& error)
{
    std::string mode;
    if (arguments.read("--ao-mode", mode))
    {
        if (!parseMode(mode, options.aoMode))
        {
            error = "--ao-mode '" + mode + "': unknown mode (glyph, screen, both)";
            return false;
        }
        ambientOcclusion = true;
    }
    if (arguments.read("--ao-radius", options.occlusionRadius) &&
        !(std::isfinite(options.occlusionRadius) && options.occlusionRadius > 0.0f))
    {
        error = "--ao-radius needs a positive distance";
        return false;
    }
    const int position = arguments.find("--outline");
    if (position >= 0)
    {
        options.outlines = true;
        const bool hasWidth = position + 1 < arguments.argc() && arguments.isNumber(position + 1);
        if (hasWidth)
        {
            options.outlineWidth = std::stof(arguments[position + 1]);
            if (!(options.outlineWidth >= 1.0f && options.outlineWidth <= 32.0f))
            {
                error = "--outline " + std::string(arguments[position + 1]) +
                        ": the width goes from 1 to 32 pixels";
                return false;
            }
        }
        arguments.remove(position, hasWidth ? 2 : 1);
    }
    return true;
}

void applyScreenEffectsOptions(ViewerScene& scene, const ScreenEffectsOptions& options, bool ambientOcclusion)
{
    scene.setAmbientOcclusion(ambientOcclusion && options.aoMode != AmbientOcclusionMode::Screen);
    osgGlyphs::ScreenEffects* effects = scene.getScreenEffects();
    effects->setAmbientOcclusion(ambientOcclusion && options.aoMode != AmbientOcclusionMode::Glyph);
    effects->setOcclusionRadius(options.occlusionRadius);
    effects->setOutlines(options.outlines);
    effects->setOutlineWidth(options.outlineWidth);
}

bool ScreenEffectsKeys::handle(const osgGA::GUIEventAdapter& ea, osgGA::GUIActionAdapter& aa)
{
    if (ea.getHandled() || ea.getEventType() != osgGA::GUIEventAdapter::KEYDOWN)
        return false;
    if (ea.getKey() == 'a')
    {
        _effects->setAmbientOcclusion(!_effects->getAmbientOcclusion());
        std::cout << PROGRAM << ": screen-space ambient occlusion "
                  << (_effects->getAmbientOcclusion() ? "on" : "off") << std::endl;
    }
    else if (ea.getKey() == 'e')
    {
        _effects->setOutlines(!_effects->getOutlines());
        std::cout << PROGRAM << ": outlines " << (_effects->getOutlines() ? "on" : "off") << std::endl;
    }
    else
        return false;
    aa.requestRedraw();
    return true;
}

void ScreenEffectsKeys::getUsage(osg::ApplicationUsage& usage) const
{
    usage.addKeyboardMouseBinding("a", "Toggle screen-space ambient occlusion (--ao-mode screen)");
    usage.addKeyboardMouseBinding("e", "Toggle outlines at silhouettes and creases (--outline)");
}
