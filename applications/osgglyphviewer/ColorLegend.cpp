#include "ColorLegend.h"

#include "ViewerText.h"

#include <osg/Geode>
#include <osg/Geometry>
#include <osg/NodeCallback>
#include <osg/observer_ptr>
#include <osgDB/FileUtils>
#include <osgText/Text>

#include <algorithm>
#include <cmath>

osgText::Font* getViewerFont()
{
    static osg::ref_ptr<osgText::Font> font = []
    {
        const char* const candidates[] = {"DejaVuSans.ttf", "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
                                          "/usr/share/fonts/truetype/liberation/LiberationSans-Regular.ttf",
                                          "fonts/arial.ttf"};
        for (const char* candidate : candidates)
        {
            if (!osgDB::findDataFile(candidate).empty() || osgDB::fileExists(candidate))
            {
                osg::ref_ptr<osgText::Font> found = osgText::readRefFontFile(candidate);
                if (found.valid())
                    return found;
            }
        }
        return osgText::Font::getDefaultFont();
    }();
    return font.get();
}

osg::ref_ptr<osg::Camera> createHudCamera(const std::string& name)
{
    osg::ref_ptr<osg::Camera> hud = new osg::Camera;
    hud->setName(name);
    hud->setReferenceFrame(osg::Transform::ABSOLUTE_RF);
    hud->setRenderOrder(osg::Camera::POST_RENDER);
    hud->setClearMask(0);
    hud->setAllowEventFocus(false);
    hud->setViewMatrix(osg::Matrix::identity());
    hud->setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
    osg::StateSet* stateSet = hud->getOrCreateStateSet();
    stateSet->setMode(GL_LIGHTING, osg::StateAttribute::OFF | osg::StateAttribute::PROTECTED);
    stateSet->setMode(GL_DEPTH_TEST, osg::StateAttribute::OFF | osg::StateAttribute::PROTECTED);
    return hud;
}

namespace
{

/** Lays out the legend in pixels of a viewport. */
class LegendLayout
{
public:
    LegendLayout(int width, int height, const osg::Vec4& background) : _geode(new osg::Geode)
    {
        _size = std::clamp(std::round(height / 36.0f), 11.0f, 20.0f);
        _right = width - _size;
        _top = height - 2.0f * _size;
        _barHeight = std::max(3.0f * _size, 0.4f * height);
        const float luminance =
            0.2126f * background.r() + 0.7152f * background.g() + 0.0722f * background.b();
        _textColor =
            luminance > 0.5f ? osg::Vec4(0.1f, 0.1f, 0.1f, 1.0f) : osg::Vec4(0.95f, 0.95f, 0.95f, 1.0f);
        _outlineColor = osg::Vec4(background.r(), background.g(), background.b(), 1.0f);
    }

    osg::ref_ptr<osg::Geode> build(const osgGlyphsData::ColorKey& key)
    {
        addText(key.title, osg::Vec3(_right, _top + 0.5f * _size, 0.0f), osgText::Text::RIGHT_BOTTOM);
        if (key.kind == osgGlyphsData::ColorKey::Scalar)
            addBar(key);
        else
            addCategories(key);
        return _geode;
    }

protected:
    void addText(const std::string& text, const osg::Vec3& position, osgText::Text::AlignmentType alignment)
    {
        osg::ref_ptr<osgText::Text> label = new osgText::Text;
        label->setFont(getViewerFont());
        label->setCharacterSize(_size);
        label->setFontResolution(32, 32);
        label->setColor(_textColor);
        label->setBackdropType(osgText::Text::OUTLINE);
        label->setBackdropColor(_outlineColor);
        label->setBackdropOffset(0.06f);
        label->setAlignment(alignment);
        label->setPosition(position);
        label->setText(text);
        _geode->addDrawable(label.get());
    }

    /** A rectangle of x0..x1 × y0..y1 with the colour of each row from colorAt(t), t from 0 at y0
     * to 1 at y1, and an outline in the text colour. */
    template <class ColorAt>
    void addRectangle(float x0, float y0, float x1, float y1, unsigned int rows, ColorAt colorAt)
    {
        osg::ref_ptr<osg::Vec3Array> vertices = new osg::Vec3Array;
        osg::ref_ptr<osg::Vec4Array> colors = new osg::Vec4Array;
        for (unsigned int row = 0; row <= rows; ++row)
        {
            const float t = static_cast<float>(row) / rows;
            const float y = y0 + t * (y1 - y0);
            vertices->push_back(osg::Vec3(x0, y, 0.0f));
            vertices->push_back(osg::Vec3(x1, y, 0.0f));
            colors->push_back(colorAt(t));
            colors->push_back(colorAt(t));
        }
        const unsigned int fillCount = static_cast<unsigned int>(vertices->size());
        for (const osg::Vec3& corner : {osg::Vec3(x0, y0, 0.0f), osg::Vec3(x1, y0, 0.0f),
                                        osg::Vec3(x1, y1, 0.0f), osg::Vec3(x0, y1, 0.0f)})
        {
            vertices->push_back(corner);
            colors->push_back(_textColor);
        }
        osg::ref_ptr<osg::Geometry> geometry = new osg::Geometry;
        geometry->setVertexArray(vertices.get());
        geometry->setColorArray(colors.get(), osg::Array::BIND_PER_VERTEX);
        geometry->addPrimitiveSet(new osg::DrawArrays(GL_QUAD_STRIP, 0, fillCount));
        geometry->addPrimitiveSet(new osg::DrawArrays(GL_LINE_LOOP, fillCount, 4));
        _geode->addDrawable(geometry.get());
    }

    void addBar(const osgGlyphsData::ColorKey& key)
    {
        const float x1 = _right, x0 = _right - _size;
        const float y1 = _top, y0 = _top - _barHeight;
        const osgGlyphs::ColorMap* colorMap = key.colorMap.get();
        addRectangle(x0, y0, x1, y1, 64, [colorMap](float t) { return colorMap->getColor(t); });
        addText(formatValue(key.max), osg::Vec3(x0 - 0.4f * _size, y1, 0.0f), osgText::Text::RIGHT_CENTER);
        addText(formatValue(key.min), osg::Vec3(x0 - 0.4f * _size, y0, 0.0f), osgText::Text::RIGHT_CENTER);
    }

    void addCategories(const osgGlyphsData::ColorKey& key)
    {
        float y = _top - _size;
        for (const auto& category : key.categories)
        {
            const osg::Vec4 color = category.second;
            if (color.a() > 0.0f)
                addRectangle(_right - _size, y, _right, y + _size, 1, [color](float) { return color; });
            addText(category.first, osg::Vec3(_right - 1.4f * _size, y + 0.5f * _size, 0.0f),
                    osgText::Text::RIGHT_CENTER);
            y -= 1.5f * _size;
        }
    }

    osg::ref_ptr<osg::Geode> _geode;
    float _size;
    float _right;
    float _top;
    float _barHeight;
    osg::Vec4 _textColor;
    osg::Vec4 _outlineColor;
};

/** Lays the legend out again when the reference camera's viewport changes size. */
class FollowViewport : public osg::NodeCallback
{
public:
    FollowViewport(const osgGlyphsData::ColorKey& key, osg::Camera* reference, const osg::Vec4& background)
        : _key(key), _reference(reference), _background(background)
    {
    }

    void operator()(osg::Node* node, osg::NodeVisitor* nv) override
    {
        osg::ref_ptr<osg::Camera> reference;
        osg::Camera* hud = node->asCamera();
        if (hud && _reference.lock(reference) && reference->getViewport())
        {
            const int width = static_cast<int>(reference->getViewport()->width());
            const int height = static_cast<int>(reference->getViewport()->height());
            if (width != _width || height != _height)
            {
                _width = width;
                _height = height;
                hud->setProjectionMatrixAsOrtho2D(0.0, width, 0.0, height);
                hud->removeChildren(0, hud->getNumChildren());
                hud->addChild(LegendLayout(width, height, _background).build(_key));
            }
        }
        traverse(node, nv);
    }

private:
    osgGlyphsData::ColorKey _key;
    osg::observer_ptr<osg::Camera> _reference;
    osg::Vec4 _background;
    int _width = 0;
    int _height = 0;
};

}

osg::ref_ptr<osg::Camera> createColorLegend(const osgGlyphsData::ColorKey& key, osg::Camera* reference,
                                            const osg::Vec4& background)
{
    if (key.kind == osgGlyphsData::ColorKey::None)
        return nullptr;
    osg::ref_ptr<osg::Camera> hud = createHudCamera("osgglyphviewer colour legend");
    hud->setUpdateCallback(new FollowViewport(key, reference, background));
    return hud;
}
