#include "Transparency.h"

#include <osg/StateSet>

void describeTransparencyOptions(osg::ApplicationUsage& usage)
{
    usage.addCommandLineOption("--opacity <v>",
                               "Draw every glyph transparent with opacity v (0 < v <= 1, times the alpha of "
                               "the colours), blended in depth order by depth peeling; key x toggles it.");
    usage.addCommandLineOption("--peel-layers <n>",
                               "The layers depth peeling draws exactly (default 4); what lies behind them "
                               "is dropped.");
    usage.addCommandLineOption("--transparency <method>",
                               "How the layers are found: k-buffer (the default: one pass into per-pixel "
                               "lists of the nearest fragments) or peel (one pass per layer).");
}

bool readTransparencyOptions(osg::ArgumentParser& arguments, TransparencyOptions& options, std::string& error)
{
    float opacity = 0.0f;
    if (arguments.read("--opacity", opacity))
    {
        if (!(opacity > 0.0f && opacity <= 1.0f))
        {
            error = "--opacity: the opacity goes from 0 (excluded) to 1";
            return false;
        }
        options.on = true;
        options.opacity = opacity;
    }
    int layers = 0;
    if (arguments.read("--peel-layers", layers))
    {
        if (layers < 1 || layers > 64)
        {
            error = "--peel-layers: from 1 to 64 layers";
            return false;
        }
        options.layers = static_cast<unsigned int>(layers);
    }
    std::string method;
    if (arguments.read("--transparency", method))
    {
        if (method != "k-buffer" && method != "peel")
        {
            error = "--transparency: unknown method '" + method + "' (k-buffer, peel)";
            return false;
        }
        options.method =
            method == "peel" ? osgGlyphs::DepthPeeling::PEEL_PASSES : osgGlyphs::DepthPeeling::K_BUFFER;
    }
    return true;
}

Transparency::Transparency()
    : _peeling(new osgGlyphs::DepthPeeling), _opacity(new osg::Uniform("osgGlyphs_opacity", 1.0f))
{
    _peeling->setName("osgglyphviewer transparency");
    setOptions(_options);
}

void Transparency::setOptions(const TransparencyOptions& options)
{
    _options = options;
    _peeling->setNumLayers(options.layers);
    _peeling->setMethod(options.method);
    setOn(options.on);
}

void Transparency::setOn(bool on)
{
    _options.on = on;
    _peeling->setEnabled(on);
    if (on)
    {
        _opacity->set(_options.opacity);
        _peeling->getOrCreateStateSet()->addUniform(_opacity.get(),
                                                    osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE);
    }
    else if (_peeling->getStateSet())
        _peeling->getStateSet()->removeUniform(_opacity.get());
}
