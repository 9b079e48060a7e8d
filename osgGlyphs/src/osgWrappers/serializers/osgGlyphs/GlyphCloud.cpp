#include <osgGlyphs/GlyphCloud>
#include <osgGlyphs/Version>

#include <osg/ValueObject>
#include <osgDB/InputStream>
#include <osgDB/ObjectWrapper>
#include <osgDB/OutputStream>
#include <osgDB/Registry>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

using osgGlyphs::GlyphCloud;

static std::ostream& exactFloats(std::ostream& out)
{
    out.precision(std::numeric_limits<float>::max_digits10);
    return out;
}

/** An enumerated property of the cloud, written by the name the viewer and the benchmark use
 * ("cone", "frustum"): its parse and name functions, accessors, and the word for it in errors. */
template <class Enum>
struct NamedEnum
{
    const char* what;
    bool (*parse)(const std::string&, Enum&);
    const char* (*name)(Enum);
    Enum (GlyphCloud::*get)() const;
    void (GlyphCloud::*set)(Enum);
};

static const NamedEnum<osgGlyphs::GlyphShape> shapeNames = {
    "shape", &osgGlyphs::parseShape, &osgGlyphs::getShapeName, &GlyphCloud::getShape, &GlyphCloud::setShape};
static const NamedEnum<osgGlyphs::GlyphAnchor> anchorNames = {"anchor", &osgGlyphs::parseAnchor,
                                                              &osgGlyphs::getAnchorName,
                                                              &GlyphCloud::getAnchor, &GlyphCloud::setAnchor};
static const NamedEnum<osgGlyphs::GlyphCulling> cullingNames = {
    "culling", &osgGlyphs::parseCulling, &osgGlyphs::getCullingName, &GlyphCloud::getCulling,
    &GlyphCloud::setCulling};

static bool alwaysWritten(const GlyphCloud&)
{
    return true;
}

template <const auto& names>
static bool readByName(osgDB::InputStream& is, GlyphCloud& cloud)
{
    std::string name;
    is >> name;
    auto value = (cloud.*names.get)();
    if (!names.parse(name, value))
    {
        is.throwException(std::string("osgGlyphs::GlyphCloud: unknown ") + names.what + " \"" + name + "\"");
        return false;
    }
    (cloud.*names.set)(value);
    return true;
}

template <const auto& names>
static bool writeByName(osgDB::OutputStream& os, const GlyphCloud& cloud)
{
    os << std::string(names.name((cloud.*names.get)())) << std::endl;
    return true;
}

static bool writeShape(osgDB::OutputStream& os, const GlyphCloud& cloud)
{
    if (osgGlyphs::isAxesShape(cloud.getShape()) && os.getFileVersion(OSGGLYPHS_SERIALIZER_DOMAIN) < 2)
        OSG_WARN << "osgGlyphs: GlyphCloud \"" << cloud.getName()
                 << "\" is written without its glyphs' semi-axes, orientations and exponents, which need "
                    "version 2 of "
                    "the osgGlyphs serializers: give the writer options whose plugin string data "
                    "\"CustomDomains\" is \""
                 << OSGGLYPHS_SERIALIZER_DOMAIN_ENTRY << "\"" << std::endl;
    // Shape is the cloud's first property. Text streams write floats with 6 significant digits
    // by default; from here on they get enough digits for every float to read back exactly.
    os << exactFloats;
    return writeByName<shapeNames>(os, cloud);
}

template <const auto& names>
static void addNamedEnumSerializer(osgDB::ObjectWrapper* wrapper, const char* property,
                                   osgDB::UserSerializer<GlyphCloud>::Writer writer = &writeByName<names>)
{
    wrapper->addSerializer(
        new osgDB::UserSerializer<GlyphCloud>(property, &alwaysWritten, &readByName<names>, writer),
        osgDB::BaseSerializer::RW_USER);
}

// Positions and scalars keep the format of object serializers (a flag, then the array; in text
// files within brackets), so files written before compressed positions read as before. A cloud with
// compressed positions writes their 16-bit integers instead, with their grid as the array's user value
// (GlyphCloud::POSITION_GRID_USER_VALUE).

// Written as the cloud holds them: a temporary array could share the address of one written
// before it in the same file, which the stream would then refer to instead.
static const osg::Array* positionsToWrite(const GlyphCloud& cloud)
{
    const osg::Vec3Array& positions = *cloud.getPositions();
    const auto* quantised = dynamic_cast<const osg::Vec3sArray*>(cloud.getGlyphArrays().positions);
    // Non-finite positions (glyphs that are skipped) have no 16-bit value: write the floats.
    if (!cloud.getCompressedPositions() || !quantised ||
        !std::all_of(positions.begin(), positions.end(),
                     [](const osg::Vec3& p) { return std::isfinite(p.length2()); }))
        return &positions;
    return quantised;
}

static bool checkPositions(const GlyphCloud& cloud)
{
    return cloud.getPositions() != nullptr;
}

/** Reads a property written by writeObjectProperty; false when the text says there is no object. */
static bool readObjectProperty(osgDB::InputStream& is, osg::ref_ptr<osg::Object>& object)
{
    if (!is.isBinary())
    {
        bool hasObject = false;
        is >> hasObject;
        if (!hasObject)
            return false;
        is >> is.BEGIN_BRACKET;
    }
    object = is.readObject();
    if (!is.isBinary())
        is >> is.END_BRACKET;
    return true;
}

/** Writes an object as an object serializer does after its flag (the user serializer writes the
 * flag in binary files): in text files the flag, then the object within brackets. */
static bool writeObjectProperty(osgDB::OutputStream& os, const osg::Object* object)
{
    if (!os.isBinary())
        os << true << os.BEGIN_BRACKET << std::endl;
    os.writeObject(object);
    if (!os.isBinary())
        os << os.END_BRACKET << std::endl;
    return true;
}

static bool readPositions(osgDB::InputStream& is, GlyphCloud& cloud)
{
    osg::ref_ptr<osg::Object> array;
    if (!readObjectProperty(is, array))
        return true;
    osg::Vec4 grid;
    if (osg::Vec3sArray* quantised = dynamic_cast<osg::Vec3sArray*>(array.get()))
    {
        if (quantised->getUserValue(GlyphCloud::POSITION_GRID_USER_VALUE, grid))
            cloud.setCompressedPositions(*quantised, grid);
        else
            is.throwException("osgGlyphs::GlyphCloud: 16-bit positions without their grid");
    }
    else if (osg::Vec3Array* positions = dynamic_cast<osg::Vec3Array*>(array.get()))
        cloud.setPositions(positions);
    else
        is.throwException("osgGlyphs::GlyphCloud: the positions are neither floats nor 16-bit integers");
    return true;
}

static bool writePositions(osgDB::OutputStream& os, const GlyphCloud& cloud)
{
    return writeObjectProperty(os, positionsToWrite(cloud));
}

// Scalars that are exactly the values of their 16-bit steps (as tiles store them) are written as the
// steps (ScalarSteps, 2 bytes a glyph), other scalars as floats (Scalars): never both.

static bool scalarsAreSteps(const GlyphCloud& cloud)
{
    const osg::FloatArray* scalars = cloud.getScalars();
    const osg::Vec2 range = cloud.getScalarQuantisationRange();
    return scalars && !scalars->empty() &&
           std::all_of(scalars->begin(), scalars->end(),
                       [&](float s)
                       {
                           const float value =
                               GlyphCloud::dequantiseScalar(GlyphCloud::quantiseScalar(s, range), range);
                           return std::memcmp(&value, &s, sizeof(s)) == 0;
                       });
}

/** What checkScalars() found, for checkScalarSteps() right after it on the same cloud: each
 * looks at every scalar. */
struct StepsCheck
{
    const GlyphCloud* cloud = nullptr;
    const osg::FloatArray* scalars = nullptr;
    unsigned int modified = 0;
    bool steps = false;
};
static thread_local StepsCheck lastStepsCheck;

static bool checkScalars(const GlyphCloud& cloud)
{
    const osg::FloatArray* scalars = cloud.getScalars();
    const bool steps = scalarsAreSteps(cloud);
    lastStepsCheck = {&cloud, scalars, scalars ? scalars->getModifiedCount() : 0u, steps};
    return scalars && !steps;
}

static bool readScalars(osgDB::InputStream& is, GlyphCloud& cloud)
{
    osg::ref_ptr<osg::Object> scalars;
    if (readObjectProperty(is, scalars))
        cloud.setScalars(dynamic_cast<osg::FloatArray*>(scalars.get()));
    return true;
}

static bool writeScalars(osgDB::OutputStream& os, const GlyphCloud& cloud)
{
    return writeObjectProperty(os, cloud.getScalars()); // checkScalars() chose the floats
}

static bool checkScalarSteps(const GlyphCloud& cloud)
{
    const osg::FloatArray* scalars = cloud.getScalars();
    const StepsCheck last = lastStepsCheck;
    lastStepsCheck = StepsCheck();
    if (last.cloud == &cloud && last.scalars == scalars && scalars &&
        last.modified == scalars->getModifiedCount())
        return last.steps;
    return scalarsAreSteps(cloud);
}

static bool readScalarSteps(osgDB::InputStream& is, GlyphCloud& cloud)
{
    osg::Vec2 range;
    is >> range;
    const unsigned int count = is.readSize();
    is >> is.BEGIN_BRACKET;
    // No allocation trusts the count: a truncated stream fails before it runs out of memory.
    osg::ref_ptr<osg::FloatArray> scalars = new osg::FloatArray;
    for (unsigned int i = 0; i < count && !is.getException(); ++i)
    {
        unsigned short step = 0;
        is >> step;
        scalars->push_back(GlyphCloud::dequantiseScalar(step, range));
    }
    is >> is.END_BRACKET;
    if (is.getException())
        return false;
    cloud.setScalars(scalars.get());
    return true;
}

static bool writeScalarSteps(osgDB::OutputStream& os, const GlyphCloud& cloud)
{
    const osg::FloatArray& scalars = *cloud.getScalars();
    const osg::Vec2 range = cloud.getScalarQuantisationRange();
    os << range;
    os.writeSize(static_cast<unsigned int>(scalars.size()));
    os << os.BEGIN_BRACKET << std::endl;
    if (os.isBinary())
    {
        // The bytes of one unsigned short at a time, in one call.
        std::vector<unsigned short> steps(scalars.size());
        for (std::size_t i = 0; i < steps.size(); ++i)
            steps[i] = static_cast<unsigned short>(GlyphCloud::quantiseScalar(scalars[i], range));
        os.writeCharArray(reinterpret_cast<const char*>(steps.data()),
                          static_cast<unsigned int>(steps.size() * sizeof(unsigned short)));
    }
    else
        for (float s : scalars)
            os << static_cast<unsigned short>(GlyphCloud::quantiseScalar(s, range));
    os << os.END_BRACKET << std::endl;
    return true;
}

static bool checkScalarRange(const GlyphCloud& cloud)
{
    return !cloud.getScalarRangeIsAutomatic();
}

static bool readScalarRange(osgDB::InputStream& is, GlyphCloud& cloud)
{
    float min = 0.0f, max = 1.0f;
    is >> min >> max;
    cloud.setScalarRange(min, max);
    return true;
}

static bool writeScalarRange(osgDB::OutputStream& os, const GlyphCloud& cloud)
{
    os << cloud.getScalarRangeMin() << cloud.getScalarRangeMax() << std::endl;
    return true;
}

static bool checkMaterial(const GlyphCloud&)
{
    return true;
}

static bool readMaterial(osgDB::InputStream& is, GlyphCloud& cloud)
{
    float ambient = 0.0f, specular = 0.0f, shininess = 0.0f;
    is >> ambient >> specular >> shininess;
    cloud.setMaterial(ambient, specular, shininess);
    return true;
}

static bool writeMaterial(osgDB::OutputStream& os, const GlyphCloud& cloud)
{
    os << cloud.getAmbient() << cloud.getSpecular() << cloud.getShininess() << std::endl;
    return true;
}

static bool checkArrowHead(const GlyphCloud&)
{
    return true;
}

static bool readArrowHead(osgDB::InputStream& is, GlyphCloud& cloud)
{
    float length = 0.0f, radius = 0.0f;
    is >> length >> radius;
    cloud.setArrowHead(length, radius);
    return true;
}

static bool writeArrowHead(osgDB::OutputStream& os, const GlyphCloud& cloud)
{
    os << cloud.getArrowHeadLengthRatio() << cloud.getArrowHeadRadiusRatio() << std::endl;
    return true;
}

/** Computes a cloud's bounds once it is read. Nothing else may before cull threads share it: the
 * PagedLODs of a tile archive have user-defined centres, so neither osgDB's DatabasePager nor a
 * viewer's home position computes the bounds of the clouds below them, and the cull threads of
 * two cameras would compute them together. */
struct ComputeBoundsOnRead : public osgDB::FinishedObjectReadCallback
{
    void objectRead(osgDB::InputStream&, osg::Object& object) override
    {
        static_cast<GlyphCloud&>(object).getBoundingBox();
    }
};

// osg::Geometry is left out of the chain: its arrays and primitive sets are derived from the
// cloud's own, which are written here. The technique is an object with a wrapper of its own
// (Techniques.cpp; osgdb_serializers_osgglyphspaper for the paper's). The versions of the osgGlyphs
// domain are in DomainVersion.h: a new property goes last, after UPDATE_TO_VERSION_SCOPED(3).
REGISTER_CUSTOM_OBJECT_WRAPPER(osgGlyphs, osgGlyphs_GlyphCloud, new osgGlyphs::GlyphCloud,
                               osgGlyphs::GlyphCloud,
                               "osg::Object osg::Node osg::Drawable osgGlyphs::GlyphCloud")
{
    wrapper->addFinishedObjectReadCallback(new ComputeBoundsOnRead);
    addNamedEnumSerializer<shapeNames>(wrapper, "Shape", &writeShape);
    // The single colour comes before the arrays: setting it later would drop per-glyph colours.
    ADD_VEC4_SERIALIZER(Color, osg::Vec4(0.8f, 0.8f, 0.8f, 1.0f));
    ADD_OBJECT_SERIALIZER(Technique, osgGlyphs::GlyphTechnique, NULL);
    ADD_USER_SERIALIZER(Positions);
    ADD_FLOAT_SERIALIZER(Radius, 1.0f);
    ADD_OBJECT_SERIALIZER(Radii, osg::FloatArray, NULL);
    ADD_OBJECT_SERIALIZER(Colors, osg::Vec4ubArray, NULL);
    ADD_USER_SERIALIZER(Scalars);
    ADD_OBJECT_SERIALIZER(Vectors, osg::Vec3Array, NULL);
    ADD_OBJECT_SERIALIZER(ColorMap, osgGlyphs::ColorMap, NULL);
    ADD_USER_SERIALIZER(ScalarRange);
    ADD_BOOL_SERIALIZER(Lit, true);
    ADD_USER_SERIALIZER(Material);
    ADD_FLOAT_SERIALIZER(LengthScale, 1.0f);
    ADD_BOOL_SERIALIZER(UniformLength, false);
    addNamedEnumSerializer<anchorNames>(wrapper, "Anchor");
    ADD_USER_SERIALIZER(ArrowHead);
    ADD_BOOL_SERIALIZER(CompressedAttributes, true);
    // Appended after the first files were written, before the domain: text files without them
    // read as before, binary ones without them do not.
    ADD_VEC3D_SERIALIZER(Origin, osg::Vec3d());
    addNamedEnumSerializer<cullingNames>(wrapper, "Culling");
    ADD_UINT_SERIALIZER(CullingChunkSize, 512u);
    ADD_OBJECT_SERIALIZER(Occlusion, osg::Vec4ubArray, NULL);
    ADD_FLOAT_SERIALIZER(Opacity, 1.0f);
    ADD_BOOL_SERIALIZER(CompressedPositions, false);
    ADD_USER_SERIALIZER(ScalarSteps);
    {
        UPDATE_TO_VERSION_SCOPED(2)
        ADD_OBJECT_SERIALIZER(SemiAxes, osg::Vec3Array, NULL);
        ADD_OBJECT_SERIALIZER(Orientations, osg::Vec4Array, NULL);
        ADD_OBJECT_SERIALIZER(Exponents, osg::Vec2Array, NULL);
    }
}

// osgDB narrows a wrapper's associates to the versions their own wrappers give them, in OSG's numbers
// (osg::Drawable's adds osg::Node from 154), and compares them with the version of the class's own
// domain: in the osgGlyphs domain that would skip osg::Node's properties, which every file holds.
// Narrowed here once, before osgDB would, then osg::Node is put back in every version.
static const bool nodeInEveryVersion = []
{
    osgDB::ObjectWrapper* wrapper =
        osgDB::Registry::instance()->getObjectWrapperManager()->findWrapper("osgGlyphs::GlyphCloud");
    wrapper->setupAssociatesRevisionsInheritanceIfRequired();
    wrapper->markAssociateAsAdded("osg::Node");
    return true;
}();
