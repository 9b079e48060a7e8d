#include "GsdShapes.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>

using namespace osgGlyphsData::formats;

namespace
{

/** A reader of one JSON object whose values it keeps as text (strings unquoted, numbers as
 * written) and whose nested arrays and objects it skips. */
class FlatJsonObject
{
public:
    explicit FlatJsonObject(const std::string& text) : _text(text) {}

    bool parse(std::map<std::string, std::string>& values, std::string& error)
    {
        skipSpace();
        if (!take('{'))
            return fail("not a JSON object", error);
        skipSpace();
        if (take('}'))
            return atEnd(error);
        for (;;)
        {
            std::string key, value;
            skipSpace();
            if (!readString(key))
                return fail("a key that is not a string", error);
            skipSpace();
            if (!take(':'))
                return fail("no ':' after \"" + key + "\"", error);
            skipSpace();
            if (!readValue(value))
                return fail("the value of \"" + key + "\" is not JSON", error);
            values[key] = value;
            skipSpace();
            if (take('}'))
                return atEnd(error);
            if (!take(','))
                return fail("no ',' or '}' after the value of \"" + key + "\"", error);
        }
    }

private:
    bool fail(const std::string& what, std::string& error) const
    {
        error = what + " at character " + std::to_string(_at);
        return false;
    }

    bool atEnd(std::string& error)
    {
        skipSpace();
        return _at == _text.size() || fail("text after the object", error);
    }

    void skipSpace()
    {
        while (_at < _text.size() && std::isspace(static_cast<unsigned char>(_text[_at])))
            ++_at;
    }

    bool take(char c)
    {
        if (_at < _text.size() && _text[_at] == c)
        {
            ++_at;
            return true;
        }
        return false;
    }

    /** A string (escapes kept as the character after the backslash: names and numbers need no more). */
    bool readString(std::string& out)
    {
        if (!take('"'))
            return false;
        while (_at < _text.size() && _text[_at] != '"')
        {
            if (_text[_at] == '\\' && ++_at == _text.size())
                return false;
            out += _text[_at++];
        }
        return take('"');
    }

    bool readValue(std::string& out)
    {
        if (_at < _text.size() && _text[_at] == '"')
            return readString(out);
        if (_at < _text.size() && (_text[_at] == '[' || _text[_at] == '{'))
            return skipNested();
        const std::size_t start = _at;
        while (_at < _text.size() && _text[_at] != ',' && _text[_at] != '}' &&
               !std::isspace(static_cast<unsigned char>(_text[_at])))
            ++_at;
        out = _text.substr(start, _at - start);
        return !out.empty();
    }

    /** Skips an array or object, strings within included. */
    bool skipNested()
    {
        std::size_t depth = 0;
        while (_at < _text.size())
        {
            const char c = _text[_at];
            if (c == '"')
            {
                std::string ignored;
                if (!readString(ignored))
                    return false;
                continue;
            }
            ++_at;
            if (c == '[' || c == '{')
                ++depth;
            else if ((c == ']' || c == '}') && --depth == 0)
                return true;
        }
        return false;
    }

    const std::string& _text;
    std::size_t _at = 0;
};

/** A finite number > 0 written as the whole text. */
bool readPositive(const std::string& text, float& value)
{
    char* end = nullptr;
    const double number = std::strtod(text.c_str(), &end);
    value = static_cast<float>(number);
    return !text.empty() && end == text.c_str() + text.size() && std::isfinite(value) && value > 0.0f;
}

}

bool osgGlyphsData::formats::parseGsdShape(const std::string& json, GsdShapeKind& kind, osg::Vec3& semiAxes,
                                           std::string& error)
{
    kind = GsdShapeKind::Other;
    if (json.find_first_not_of(" \t\r\n") == std::string::npos)
        return true;
    std::map<std::string, std::string> values;
    if (!FlatJsonObject(json).parse(values, error))
        return false;
    if (values["type"] != "Ellipsoid")
        return true;
    for (int axis = 0; axis < 3; ++axis)
    {
        const std::string name(1, "abc"[axis]);
        if (!readPositive(values[name], semiAxes[axis]))
        {
            error = "an Ellipsoid's \"" + name + "\" is '" + values[name] + "', not a finite number > 0";
            return false;
        }
    }
    kind = GsdShapeKind::Ellipsoid;
    return true;
}
