#include <osgGlyphs/ColorMap>

#include "state/Resources.h"

#include <atomic>

#include <osgDB/fstream>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <sstream>

using namespace osgGlyphs;

namespace
{

unsigned long long nextSerialNumber()
{
    static std::atomic<unsigned long long> s_next{1};
    return s_next++;
}

const char* const BUILTIN_NAMES[] = {"viridis", "magma", "cividis", "coolwarm", "grayscale"};

/** Texels in the GPU copy: enough that linear filtering between them is invisible. */
const int TEXTURE_SIZE = 256;

bool parseHex(const std::string& digits, osg::Vec4& color)
{
    if (digits.size() != 6 && digits.size() != 8)
        return false;
    float channels[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    for (size_t c = 0; c < digits.size() / 2; ++c)
    {
        unsigned int value = 0;
        for (size_t i = 0; i < 2; ++i)
        {
            const char ch = digits[2 * c + i];
            const int nibble = std::isdigit(static_cast<unsigned char>(ch)) ? ch - '0'
                               : (ch >= 'a' && ch <= 'f')                   ? ch - 'a' + 10
                               : (ch >= 'A' && ch <= 'F')                   ? ch - 'A' + 10
                                                                            : -1;
            if (nibble < 0)
                return false;
            value = value * 16 + static_cast<unsigned int>(nibble);
        }
        channels[c] = static_cast<float>(value) / 255.0f;
    }
    color.set(channels[0], channels[1], channels[2], channels[3]);
    return true;
}

/** A token in double quotes for a message: at most 40 characters, other bytes than printable
 * ASCII as \\xNN. */
std::string quoteForMessage(const std::string& token)
{
    static const char hex[] = "0123456789abcdef";
    const size_t limit = 40;
    std::string text = "\"";
    for (size_t i = 0; i < token.size() && i < limit; ++i)
    {
        const unsigned char c = static_cast<unsigned char>(token[i]);
        if (c >= 0x20 && c < 0x7F && c != '\\' && c != '"')
            text += static_cast<char>(c);
        else
            text += std::string("\\x") + hex[c >> 4] + hex[c & 0xF];
    }
    return text + (token.size() > limit ? "...\"" : "\"");
}

}

ColorMap::ColorMap()
    : _colors{osg::Vec4(0, 0, 0, 1), osg::Vec4(1, 1, 1, 1)}, _serialNumber(nextSerialNumber())
{
}

ColorMap::ColorMap(const std::string& name, const std::vector<osg::Vec4>& colors)
    : _colors(colors), _serialNumber(nextSerialNumber())
{
    setName(name);
}

ColorMap::ColorMap(const ColorMap& other, const osg::CopyOp& copyop)
    : osg::Object(other, copyop), _colors(other._colors), _serialNumber(nextSerialNumber())
{
}

ColorMap* ColorMap::getBuiltin(const std::string& name)
{
    static std::mutex mutex;
    static std::map<std::string, osg::ref_ptr<ColorMap>> cache;
    std::lock_guard<std::mutex> lock(mutex);
    auto found = cache.find(name);
    if (found != cache.end())
        return found->second.get();
    if (std::find(std::begin(BUILTIN_NAMES), std::end(BUILTIN_NAMES), name) == std::end(BUILTIN_NAMES))
        return nullptr;
    std::string error;
    osg::ref_ptr<ColorMap> map =
        parse(name, detail::readResource("osgGlyphs/colormaps/" + name + ".txt"), error);
    if (!map)
    {
        OSG_WARN << "osgGlyphs: colour map " << name << ": " << error << std::endl;
        return nullptr;
    }
    cache[name] = map;
    return map.get();
}

std::vector<std::string> ColorMap::getBuiltinNames()
{
    return std::vector<std::string>(std::begin(BUILTIN_NAMES), std::end(BUILTIN_NAMES));
}

osg::ref_ptr<ColorMap> ColorMap::parse(const std::string& name, const std::string& text, std::string& error)
{
    std::vector<osg::Vec4> colors;
    std::istringstream lines(text);
    std::string line;
    for (int number = 1; std::getline(lines, line); ++number)
    {
        const size_t begin = line.find_first_not_of(" \t\r");
        if (begin == std::string::npos)
            continue;
        const size_t end = line.find_last_not_of(" \t\r");
        const std::string token = line.substr(begin, end - begin + 1);
        osg::Vec4 color;
        if (token[0] == '#' && parseHex(token.substr(1), color))
            colors.push_back(color);
        else if (token[0] != '#')
        {
            error = name + ":" + std::to_string(number) + ": expected a colour \"#rrggbb\", found " +
                    quoteForMessage(token);
            return nullptr;
        }
    }
    if (colors.size() < 2)
    {
        error = name + ": a colour map needs at least two colours";
        return nullptr;
    }
    return new ColorMap(name, colors);
}

osg::ref_ptr<ColorMap> ColorMap::readFile(const std::string& path, std::string& error)
{
    osgDB::ifstream file(path.c_str(), std::ios::binary);
    if (!file)
    {
        error = path + ": cannot open";
        return nullptr;
    }
    // Never more than the largest colour map: the path may name a device or a huge file.
    std::string text(MaxFileBytes + 1, '\0');
    file.read(&text[0], static_cast<std::streamsize>(text.size()));
    if (file.bad())
    {
        error = path + ": cannot read";
        return nullptr;
    }
    text.resize(static_cast<std::size_t>(file.gcount()));
    if (text.size() > MaxFileBytes)
    {
        error = path + ": more than " + std::to_string(MaxFileBytes >> 10) +
                " KiB, not a colour map (one #rrggbb a line)";
        return nullptr;
    }
    return parse(path, text, error);
}

void ColorMap::setColors(const std::vector<osg::Vec4>& colors)
{
    _colors = colors;
    ++_modifiedCount;
    if (_texture.valid())
        fillImage(*_texture->getImage());
}

osg::Vec4 ColorMap::getColor(float t) const
{
    if (_colors.empty())
        return osg::Vec4(1, 1, 1, 1);
    if (_colors.size() == 1 || !(t > 0.0f))
        return _colors.front();
    if (t >= 1.0f)
        return _colors.back();
    const float position = t * static_cast<float>(_colors.size() - 1);
    const size_t index = static_cast<size_t>(position);
    const float fraction = position - static_cast<float>(index);
    return _colors[index] * (1.0f - fraction) + _colors[index + 1] * fraction;
}

void ColorMap::fillImage(osg::Image& image) const
{
    image.allocateImage(TEXTURE_SIZE, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE);
    for (int i = 0; i < TEXTURE_SIZE; ++i)
    {
        // Texel i holds the map at i / (size - 1); the shader samples at the matching
        // coordinate, so that GPU colours agree with getColor().
        const osg::Vec4 color = getColor(static_cast<float>(i) / static_cast<float>(TEXTURE_SIZE - 1));
        unsigned char* texel = image.data(i);
        for (int c = 0; c < 4; ++c)
            texel[c] = static_cast<unsigned char>(std::lround(std::clamp(color[c], 0.0f, 1.0f) * 255.0f));
    }
    image.dirty();
}

osg::Texture1D* ColorMap::getTexture() const
{
    if (_texture.valid())
        return _texture.get();
    osg::ref_ptr<osg::Image> image = new osg::Image;
    fillImage(*image);
    // Textures drop STATIC images after loading them where unref-after-apply is set (the
    // Optimizer's OPTIMIZE_TEXTURE_SETTINGS sets it on every texture it finds): a shared colour
    // map must keep its image for every context that comes later, and setColors() refills it.
    image->setDataVariance(osg::Object::DYNAMIC);
    _texture = new osg::Texture1D(image.get());
    _texture->setFilter(osg::Texture::MIN_FILTER, osg::Texture::LINEAR);
    _texture->setFilter(osg::Texture::MAG_FILTER, osg::Texture::LINEAR);
    _texture->setWrap(osg::Texture::WRAP_S, osg::Texture::CLAMP_TO_EDGE);
    _texture->setResizeNonPowerOfTwoHint(false);
    return _texture.get();
}

void ColorMap::releaseGLObjects(osg::State* state) const
{
    if (_texture.valid())
        _texture->releaseGLObjects(state);
}

void ColorMap::resizeGLObjectBuffers(unsigned int maxSize)
{
    if (_texture.valid())
        _texture->resizeGLObjectBuffers(maxSize);
}
