#include <osgGlyphsHeadless/DepthImage>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <vector>

using namespace osgGlyphsHeadless;

namespace
{

bool isHostLittleEndian()
{
    const uint16_t one = 1;
    unsigned char first = 0;
    std::memcpy(&first, &one, 1);
    return first == 1;
}

void swapBytes(float& value)
{
    unsigned char bytes[4];
    std::memcpy(bytes, &value, 4);
    std::swap(bytes[0], bytes[3]);
    std::swap(bytes[1], bytes[2]);
    std::memcpy(&value, bytes, 4);
}

bool isSingleChannelFloat(const osg::Image& image)
{
    const GLenum format = image.getPixelFormat();
    return image.getDataType() == GL_FLOAT &&
           (format == GL_DEPTH_COMPONENT || format == GL_LUMINANCE || format == GL_RED || format == GL_ALPHA);
}

} // namespace

double osgGlyphsHeadless::windowDepthFromEyeZ(const osg::Matrixd& projection, double eyeZ)
{
    const osg::Vec4d clip = osg::Vec4d(0.0, 0.0, eyeZ, 1.0) * projection;
    return 0.5 * clip.z() / clip.w() + 0.5;
}

double osgGlyphsHeadless::eyeDistanceFromWindowDepth(const osg::Matrixd& projection, double windowDepth)
{
    if (windowDepth >= 1.0)
        return std::numeric_limits<double>::infinity();
    // Unproject (0, 0, ndcZ) and take its eye-space z; both matrix conventions of OSG are row vectors.
    const osg::Matrixd inverse = osg::Matrixd::inverse(projection);
    const osg::Vec4d eye = osg::Vec4d(0.0, 0.0, 2.0 * windowDepth - 1.0, 1.0) * inverse;
    return -eye.z() / eye.w();
}

osg::ref_ptr<osg::Image> osgGlyphsHeadless::createEyeDistanceImage(const osg::Image& windowDepth,
                                                                   const osg::Matrixd& projection)
{
    osg::ref_ptr<osg::Image> distance = new osg::Image;
    if (!isSingleChannelFloat(windowDepth))
        return nullptr;
    distance->allocateImage(windowDepth.s(), windowDepth.t(), 1, GL_LUMINANCE, GL_FLOAT);
    const int count = windowDepth.s() * windowDepth.t();
    const float* in = reinterpret_cast<const float*>(windowDepth.data());
    float* out = reinterpret_cast<float*>(distance->data());
    for (int i = 0; i < count; ++i)
        out[i] = static_cast<float>(eyeDistanceFromWindowDepth(projection, in[i]));
    return distance;
}

bool osgGlyphsHeadless::writePFM(const osg::Image& image, const std::string& path, std::string& error)
{
    if (!isSingleChannelFloat(image) || image.r() != 1)
    {
        error = path + ": PFM output needs a 2D single-channel float image";
        return false;
    }
    std::ofstream file(path, std::ios::binary);
    if (!file)
    {
        error = path + ": cannot open for writing";
        return false;
    }
    // A negative scale marks little-endian data. Rows go bottom to top, as in OpenGL.
    file << "Pf\n" << image.s() << ' ' << image.t() << "\n-1.0\n";
    std::vector<float> row(static_cast<size_t>(image.s()));
    for (int t = 0; t < image.t(); ++t)
    {
        std::memcpy(row.data(), image.data(0, t), row.size() * sizeof(float));
        if (!isHostLittleEndian())
            for (float& value : row)
                swapBytes(value);
        file.write(reinterpret_cast<const char*>(row.data()),
                   static_cast<std::streamsize>(row.size() * sizeof(float)));
    }
    if (!file)
    {
        error = path + ": write failed";
        return false;
    }
    return true;
}

osg::ref_ptr<osg::Image> osgGlyphsHeadless::readPFM(const std::string& path, std::string& error)
{
    std::ifstream file(path, std::ios::binary);
    if (!file)
    {
        error = path + ": cannot open";
        return nullptr;
    }
    auto fail = [&](const std::string& what) -> osg::ref_ptr<osg::Image>
    {
        std::ostringstream message;
        const std::streamoff offset = file ? static_cast<std::streamoff>(file.tellg()) : -1;
        message << path << ": " << what;
        if (offset >= 0)
            message << " (at byte " << offset << ")";
        error = message.str();
        return nullptr;
    };

    std::string magic;
    long long width = 0, height = 0;
    double scale = 0.0;
    if (!(file >> magic) || magic != "Pf")
        return fail("not a greyscale PFM file (magic must be 'Pf')");
    if (!(file >> width >> height) || width <= 0 || height <= 0 || width > 65536 || height > 65536)
        return fail("bad image size (1 to 65536 pixels per side)");
    if (!(file >> scale) || scale == 0.0 || !std::isfinite(scale))
        return fail("bad scale (a non-zero number)");
    const int separator = file.get();
    if (separator == std::char_traits<char>::eof() || !std::isspace(separator))
        return fail("the header must end with one whitespace character");

    const std::streamoff dataStart = file.tellg();
    file.seekg(0, std::ios::end);
    const std::streamoff available = file.tellg() - dataStart;
    const std::streamoff needed = static_cast<std::streamoff>(width * height * 4);
    if (available < needed)
        return fail("truncated: " + std::to_string(needed) + " bytes of pixels expected, " +
                    std::to_string(available) + " present");
    file.seekg(dataStart);

    osg::ref_ptr<osg::Image> image = new osg::Image;
    image->allocateImage(static_cast<int>(width), static_cast<int>(height), 1, GL_LUMINANCE, GL_FLOAT);
    file.read(reinterpret_cast<char*>(image->data()), needed);
    if ((scale < 0.0) != isHostLittleEndian())
    {
        float* values = reinterpret_cast<float*>(image->data());
        for (long long i = 0; i < width * height; ++i)
            swapBytes(values[i]);
    }
    return image;
}
