#include <osgGlyphsData/RandomCloud>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>

using namespace osgGlyphs;
using namespace osgGlyphsData;

namespace
{

/** The independent random streams of one seed. */
enum class Stream : unsigned int
{
    Positions = 1,
    Scalars = 2,
    Vectors = 3,
    Ellipsoids = 4,
    Exponents = 5
};

/** Uniform floats in [0, 1) from a std::mt19937 seeded by (seed, stream), converted without
 * std::uniform_real_distribution, whose results differ between standard libraries. */
class UniformFloats
{
public:
    /** Starts after the first skipped values of the stream. */
    UniformFloats(unsigned int seed, Stream stream, uint64_t skipped)
    {
        std::seed_seq sequence{seed, static_cast<unsigned int>(stream)};
        _engine.seed(sequence);
        _engine.discard(skipped);
    }

    /** 24 random bits: every float in [0, 1) of that resolution, equally likely. */
    float operator()() { return static_cast<float>(_engine() >> 8) * (1.0f / 16777216.0f); }

private:
    std::mt19937 _engine;
};

osg::ref_ptr<osg::Vec3Array> createPositions(PointRange range, unsigned int seed)
{
    const uint64_t count = range.end - range.begin;
    UniformFloats uniform(seed, Stream::Positions, 3 * range.begin);
    osg::ref_ptr<osg::Vec3Array> positions = new osg::Vec3Array;
    positions->reserve(count);
    for (uint64_t i = 0; i < count; ++i)
    {
        const float x = uniform(), y = uniform(), z = uniform();
        positions->push_back(osg::Vec3(x, y, z));
    }
    return positions;
}

osg::ref_ptr<osg::FloatArray> createScalars(PointRange range, unsigned int seed)
{
    const uint64_t count = range.end - range.begin;
    UniformFloats uniform(seed, Stream::Scalars, range.begin);
    osg::ref_ptr<osg::FloatArray> scalars = new osg::FloatArray;
    scalars->reserve(count);
    for (uint64_t i = 0; i < count; ++i)
        scalars->push_back(uniform());
    return scalars;
}

/** Directions uniform on the unit sphere (uniform height and azimuth, Archimedes), times a
 * magnitude uniform in [0.5, 1]. */
osg::ref_ptr<osg::Vec3Array> createVectors(PointRange range, unsigned int seed)
{
    const uint64_t count = range.end - range.begin;
    UniformFloats uniform(seed, Stream::Vectors, 3 * range.begin);
    osg::ref_ptr<osg::Vec3Array> vectors = new osg::Vec3Array;
    vectors->reserve(count);
    for (uint64_t i = 0; i < count; ++i)
    {
        const float z = 2.0f * uniform() - 1.0f;
        const float azimuth = 2.0f * osg::PIf * uniform();
        const float magnitude = 0.5f + 0.5f * uniform();
        const float ring = std::sqrt(std::max(0.0f, 1.0f - z * z));
        vectors->push_back(osg::Vec3(ring * std::cos(azimuth), ring * std::sin(azimuth), z) * magnitude);
    }
    return vectors;
}

/** Semi-axes (radius, and two uniform in [smallest, 1] of it) and rotations uniform over SO(3)
 * (Shoemake's quaternions from three uniform numbers). */
void setEllipsoids(GlyphCloud& cloud, PointRange range, unsigned int seed, float radius, float smallest)
{
    const uint64_t count = range.end - range.begin;
    UniformFloats uniform(seed, Stream::Ellipsoids, 5 * range.begin);
    osg::ref_ptr<osg::Vec3Array> semiAxes = new osg::Vec3Array;
    osg::ref_ptr<osg::Vec4Array> rotations = new osg::Vec4Array;
    semiAxes->reserve(count);
    rotations->reserve(count);
    smallest = smallest >= 0.01f ? std::min(smallest, 1.0f) : 0.01f; // NaN too
    const float spread = 1.0f - smallest;
    for (uint64_t i = 0; i < count; ++i)
    {
        semiAxes->push_back(osg::Vec3(1.0f, smallest + spread * uniform(), smallest + spread * uniform()) *
                            radius);
        const float u = uniform(), a = 2.0f * osg::PIf * uniform(), b = 2.0f * osg::PIf * uniform();
        const float s = std::sqrt(1.0f - u), t = std::sqrt(u);
        rotations->push_back(osg::Vec4(s * std::sin(a), s * std::cos(a), t * std::sin(b), t * std::cos(b)));
    }
    cloud.setSemiAxes(semiAxes.get());
    cloud.setOrientations(rotations.get());
}

/** Superquadrics' exponents, each uniform in [0.1, 1]: from rounded boxes to ellipsoids. */
void setExponents(GlyphCloud& cloud, PointRange range, unsigned int seed)
{
    const uint64_t count = range.end - range.begin;
    UniformFloats uniform(seed, Stream::Exponents, 2 * range.begin);
    osg::ref_ptr<osg::Vec2Array> exponents = new osg::Vec2Array;
    exponents->reserve(count);
    for (uint64_t i = 0; i < count; ++i)
    {
        const float e1 = 0.1f + 0.9f * uniform();
        exponents->push_back(osg::Vec2(e1, 0.1f + 0.9f * uniform()));
    }
    cloud.setExponents(exponents.get());
}

}

float osgGlyphsData::getDefaultRandomRadius(unsigned int count)
{
    const float radius = 0.5f / std::sqrt(static_cast<float>(std::max(count, 1u)));
    return std::min(radius, 0.1f);
}

osg::ref_ptr<GlyphCloud> osgGlyphsData::createRandomCloud(const RandomCloudOptions& options)
{
    const float radius = options.radius > 0.0f ? options.radius : getDefaultRandomRadius(options.count);
    const PointRange range = getShareRange(options.share, options.count);
    osg::ref_ptr<GlyphCloud> cloud = new GlyphCloud;
    cloud->setCulling(options.culling);
    cloud->setRadius(radius);
    cloud->setScalars(createScalars(range, options.seed).get());
    cloud->setScalarRange(0.0f, 1.0f);
    if (isVectorShape(options.shape))
    {
        cloud->setVectors(createVectors(range, options.seed).get());
        cloud->setLengthScale(options.lengthScale > 0.0f ? options.lengthScale : 4.0f * radius);
    }
    if (isAxesShape(options.shape))
        setEllipsoids(*cloud, range, options.seed, radius, options.smallestAxis);
    if (options.shape == GlyphShape::Superquadric)
        setExponents(*cloud, range, options.seed);
    cloud->setShape(options.shape);
    // The positions last: the setters before them work on an empty cloud, and the culling chunks
    // are built once.
    cloud->setPositions(createPositions(range, options.seed).get());
    return cloud;
}

osg::ref_ptr<GlyphCloud> osgGlyphsData::createRandomCloud(const RandomCloudOptions& options,
                                                          std::string& error)
{
    if (!checkPointShare(options.share, error))
    {
        error = "random cloud: " + error;
        return nullptr;
    }
    if (!(options.smallestAxis > 0.0f && options.smallestAxis <= 1.0f))
    {
        error = "random cloud: the smallest semi-axis share " + std::to_string(options.smallestAxis) +
                " is not in (0, 1]";
        return nullptr;
    }
    return createRandomCloud(options);
}
