#include "Timeline.h"

#include "ColorLegend.h"

#include <osg/Geode>
#include <osg/Geometry>
#include <osgText/Text>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace
{

std::string formatRate(double framesPerSecond)
{
    char text[32];
    std::snprintf(text, sizeof(text), "%.3g", framesPerSecond);
    return text;
}

/** A quad of x0..x1 × y0..y1 in one colour. */
osg::ref_ptr<osg::Geometry> createQuad(const osg::Vec4& color)
{
    osg::ref_ptr<osg::Geometry> quad = new osg::Geometry;
    quad->setUseDisplayList(false);
    quad->setUseVertexBufferObjects(true);
    quad->setDataVariance(osg::Object::DYNAMIC);
    quad->setVertexArray(new osg::Vec3Array(4));
    osg::ref_ptr<osg::Vec4Array> colors = new osg::Vec4Array(1);
    (*colors)[0] = color;
    quad->setColorArray(colors.get(), osg::Array::BIND_OVERALL);
    quad->addPrimitiveSet(new osg::DrawArrays(GL_QUADS, 0, 4));
    return quad;
}

void placeQuad(osg::Geometry& quad, float x0, float y0, float x1, float y1)
{
    osg::Vec3Array& corners = static_cast<osg::Vec3Array&>(*quad.getVertexArray());
    corners[0].set(x0, y0, 0.0f);
    corners[1].set(x1, y0, 0.0f);
    corners[2].set(x1, y1, 0.0f);
    corners[3].set(x0, y1, 0.0f);
    corners.dirty();
    quad.dirtyBound();
}

/** Lays the timeline out for the reference's viewport and shows the player's state, every frame. */
class FollowPlayer : public osg::NodeCallback
{
public:
    FollowPlayer(osgGlyphsData::FramePlayer* player, osg::Camera* reference, const osg::Vec4& background)
        : _player(player), _reference(reference), _geode(new osg::Geode), _track(createQuad(osg::Vec4())),
          _played(createQuad(osg::Vec4())), _marker(createQuad(osg::Vec4())), _text(new osgText::Text)
    {
        const float luminance =
            0.2126f * background.r() + 0.7152f * background.g() + 0.0722f * background.b();
        const bool light = luminance > 0.5f;
        const osg::Vec4 ink =
            light ? osg::Vec4(0.1f, 0.1f, 0.1f, 1.0f) : osg::Vec4(0.95f, 0.95f, 0.95f, 1.0f);
        setColor(*_track, light ? osg::Vec4(0.8f, 0.8f, 0.8f, 1.0f) : osg::Vec4(0.3f, 0.3f, 0.3f, 1.0f));
        setColor(*_played, osg::Vec4(0.26f, 0.52f, 0.85f, 1.0f));
        setColor(*_marker, ink);
        _text->setFont(getViewerFont());
        _text->setFontResolution(32, 32);
        _text->setColor(ink);
        _text->setBackdropType(osgText::Text::OUTLINE);
        _text->setBackdropColor(osg::Vec4(background.r(), background.g(), background.b(), 1.0f));
        _text->setBackdropOffset(0.06f);
        _text->setAlignment(osgText::Text::LEFT_BOTTOM);
        _text->setDataVariance(osg::Object::DYNAMIC);
        for (osg::Drawable* drawable :
             {static_cast<osg::Drawable*>(_track.get()), static_cast<osg::Drawable*>(_played.get()),
              static_cast<osg::Drawable*>(_marker.get()), static_cast<osg::Drawable*>(_text.get())})
            _geode->addDrawable(drawable);
    }

    osg::Geode* getGeode() const { return _geode.get(); }

    void operator()(osg::Node* node, osg::NodeVisitor* nv) override
    {
        osg::Camera* hud = static_cast<osg::Camera*>(node);
        const osg::Viewport* viewport = _reference.valid() ? _reference->getViewport() : nullptr;
        if (viewport)
        {
            const int width = static_cast<int>(viewport->width()),
                      height = static_cast<int>(viewport->height());
            if (width != _width || height != _height)
            {
                _width = width;
                _height = height;
                hud->setProjectionMatrixAsOrtho2D(0.0, width, 0.0, height);
            }
        }
        show();
        traverse(node, nv);
    }

private:
    static void setColor(osg::Geometry& quad, const osg::Vec4& color)
    {
        (*static_cast<osg::Vec4Array*>(quad.getColorArray()))[0] = color;
    }

    void show()
    {
        const Timeline::Bar bar = Timeline::layoutBar(_width, _height);
        const std::size_t frames = std::max<std::size_t>(_player->getNumFrames(), 1);
        const double fraction =
            frames > 1 ? std::clamp(_player->getPosition() / double(frames - 1), 0.0, 1.0) : 1.0;
        const float x = bar.x0 + static_cast<float>(fraction) * (bar.x1 - bar.x0);
        const float half = std::max(1.5f, 0.2f * (bar.y1 - bar.y0));
        placeQuad(*_track, bar.x0, bar.y0, bar.x1, bar.y1);
        placeQuad(*_played, bar.x0, bar.y0, x, bar.y1);
        placeQuad(*_marker, x - half, bar.y0 - half, x + half, bar.y1 + half);
        const float size = std::clamp(std::round(_height / 36.0f), 11.0f, 20.0f);
        _text->setCharacterSize(size);
        _text->setPosition(osg::Vec3(bar.x0, bar.y1 + 0.5f * size, 0.0f));
        const std::string line = describePlayback(*_player);
        if (line != _line)
        {
            _line = line;
            _text->setText(line);
        }
    }

    osg::ref_ptr<osgGlyphsData::FramePlayer> _player;
    osg::observer_ptr<osg::Camera> _reference;
    osg::ref_ptr<osg::Geode> _geode;
    osg::ref_ptr<osg::Geometry> _track, _played, _marker;
    osg::ref_ptr<osgText::Text> _text;
    std::string _line;
    int _width = 0, _height = 0;
};

}

std::string describePlayback(const osgGlyphsData::FramePlayer& player)
{
    const std::size_t frames = player.getNumFrames();
    const double position = player.getPosition();
    const bool between = std::abs(position - std::round(position)) > 1e-9;
    // Counted from 0, as --frame and the n and p keys count them.
    char frame[64];
    std::snprintf(frame, sizeof(frame), between ? "frame %.2f of 0..%zu" : "frame %.0f of 0..%zu", position,
                  frames > 0 ? frames - 1 : 0);
    std::string line = std::string(frame) + (player.isIndexComplete() ? "" : "+");
    line += "  timestep " + formatRate(player.getTimestep());
    if (player.isPlaying())
        line += "  playing at " + formatRate(player.getFramesPerSecond()) + "/s";
    else
        line += "  paused";
    if (std::abs(player.getStep()) != 1)
        line += ", every " + std::to_string(std::abs(player.getStep())) + " frames";
    if (player.getStep() < 0)
        line += ", backwards";
    if (player.getSubframes() > 0)
        line += ", " + std::to_string(player.getSubframes()) + " between";
    if (!player.getLoop())
        line += ", no loop";
    const osgGlyphsData::FramePlayerStatistics statistics = player.getStatistics();
    if (statistics.late > 0)
        line += "  (" + std::to_string(statistics.late) + " late)";
    return line;
}

Timeline::Timeline(osgGlyphsData::FramePlayer* player, osg::Camera* reference, const osg::Vec4& background)
    : _player(player), _hud(createHudCamera("osgglyphviewer timeline")), _reference(reference)
{
    osg::ref_ptr<FollowPlayer> follow = new FollowPlayer(player, reference, background);
    _hud->addChild(follow->getGeode());
    _hud->setUpdateCallback(follow.get());
}

Timeline::Bar Timeline::layoutBar(int width, int height)
{
    const float size = std::clamp(std::round(height / 36.0f), 11.0f, 20.0f);
    Bar bar;
    bar.x0 = size;
    bar.x1 = std::max(bar.x0 + 1.0f, width - 4.0f * size); // clear of the legend's labels
    bar.y0 = 0.8f * size;
    bar.y1 = bar.y0 + 0.5f * size;
    return bar;
}

bool Timeline::seekAt(float x, float y, bool dragging)
{
    const osg::Viewport* viewport = _reference.valid() ? _reference->getViewport() : nullptr;
    if (!viewport)
        return false;
    const Bar bar = layoutBar(static_cast<int>(viewport->width()), static_cast<int>(viewport->height()));
    const float reach = 0.5f * (bar.y1 - bar.y0) + 4.0f; // a forgiving target
    const float middle = 0.5f * (bar.y0 + bar.y1);
    if (!dragging && (x < bar.x0 - 4.0f || x > bar.x1 + 4.0f || std::abs(y - middle) > reach))
        return false;
    const std::size_t frames = _player->getNumFrames();
    if (frames == 0)
        return true;
    const double fraction = std::clamp((x - bar.x0) / (bar.x1 - bar.x0), 0.0f, 1.0f);
    _player->seek(std::round(fraction * double(frames - 1)));
    return true;
}

bool Timeline::handle(const osgGA::GUIEventAdapter& ea, osgGA::GUIActionAdapter& aa)
{
    if (ea.getHandled())
        return false;
    // Window pixels from the bottom left, whatever the event's own coordinate range.
    const float x = (ea.getXnormalized() + 1.0f) * 0.5f * (ea.getWindowWidth());
    const float y = (ea.getYnormalized() + 1.0f) * 0.5f * (ea.getWindowHeight());
    switch (ea.getEventType())
    {
    case osgGA::GUIEventAdapter::PUSH:
        if (ea.getButton() != osgGA::GUIEventAdapter::LEFT_MOUSE_BUTTON || !seekAt(x, y, false))
            return false;
        _dragging = true;
        aa.requestRedraw();
        return true;
    case osgGA::GUIEventAdapter::DRAG:
        if (!_dragging)
            return false;
        seekAt(x, y, true);
        aa.requestRedraw();
        return true;
    case osgGA::GUIEventAdapter::RELEASE:
        if (!_dragging)
            return false;
        _dragging = false;
        return true;
    default:
        return false;
    }
}
