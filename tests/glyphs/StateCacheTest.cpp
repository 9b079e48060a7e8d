// The lifetime of the shared state: GlyphStateCache holds one StateSet per technique and
// variant, keys scalar colouring by the colour map's serial number, and only observes its
// StateSets, which go with the last cloud that uses them. Colour maps and clouds that come and go must not
// accumulate StateSets, textures or GL objects; a new map must never be drawn with a freed one's texture; and
// releaseGLObjects() must reach every program and texture of the shared state, also when a
// viewer closes and the next one reuses its context ID.

#include "GlyphTestScenes.h"

#include <osgGlyphs/ColorMap>
#include <osgGlyphs/GlyphCloud>
#include <osgGlyphs/GlyphStateCache>
#include <osgGlyphsPaper/Techniques>

#include <osg/ContextData>
#include <osg/GraphicsContext>
#include <osg/Texture>
#include <osg/observer_ptr>

#include <algorithm>
#include <cmath>

using namespace osgGlyphsTest;
using osgGlyphs::ColorMap;
using osgGlyphs::GlyphCloud;
using osgGlyphs::GlyphStateCache;

namespace
{

/** The paper's techniques, by name, beside osgGlyphs' own. */
const bool PAPER_TECHNIQUES_REGISTERED = (osgGlyphsPaper::registerTechniques(), true);

/** StateSets go with the last cloud that uses them: with a cloud or two alive, a few are. The
 * tests allow 8; a thousand maps pass through. */
const unsigned int MAX_CACHED_STATESETS = 8;

/** A two-colour map of its own for each i, from red to a colour that changes with i. */
osg::ref_ptr<ColorMap> createColorMap(int i)
{
    const float f = static_cast<float>(i % 97) / 96.0f;
    return new ColorMap("map " + std::to_string(i),
                        {osg::Vec4(1.0f, 0.0f, 0.0f, 1.0f), osg::Vec4(0.0f, f, 1.0f - f, 1.0f)});
}

/** The two spheres of a scalar cloud: scalar 0 at the left, 1 at the right, about a centre. */
const float SPHERE_RADIUS = 0.5f;
const osg::Vec3 SPHERE_OFFSETS[2] = {osg::Vec3(-0.55f, 0.0f, 0.0f), osg::Vec3(0.55f, 0.0f, 0.0f)};

/** Two unlit spheres coloured by the ends of the colour map, drawn by the technique. */
osg::ref_ptr<GlyphCloud> createScalarCloud(ColorMap* colorMap,
                                           const std::string& technique = "geometry-shader",
                                           const osg::Vec3& center = osg::Vec3())
{
    osg::ref_ptr<osg::Vec3Array> positions = new osg::Vec3Array;
    osg::ref_ptr<osg::FloatArray> scalars = new osg::FloatArray;
    for (int i = 0; i < 2; ++i)
    {
        positions->push_back(center + SPHERE_OFFSETS[i]);
        scalars->push_back(static_cast<float>(i));
    }
    osg::ref_ptr<GlyphCloud> cloud = new GlyphCloud;
    cloud->setPositions(positions.get());
    cloud->setRadius(SPHERE_RADIUS);
    cloud->setScalars(scalars.get());
    cloud->setScalarRange(0.0f, 1.0f);
    cloud->setColorMap(colorMap);
    cloud->setLit(false);
    cloud->setTechnique(osgGlyphs::createTechnique(technique).get());
    return cloud;
}

/** Every texture of a StateSet, on every unit. */
std::vector<const osg::Texture*> getTextures(const osg::StateSet& stateSet)
{
    std::vector<const osg::Texture*> textures;
    for (const osg::StateSet::AttributeList& unit : stateSet.getTextureAttributeList())
        for (const auto& attribute : unit)
            if (const osg::Texture* texture = attribute.second.first->asTexture())
                textures.push_back(texture);
    return textures;
}

template <class T>
int countAlive(const std::vector<osg::observer_ptr<T>>& objects)
{
    return static_cast<int>(std::count_if(objects.begin(), objects.end(),
                                          [](const osg::observer_ptr<T>& object) { return object.valid(); }));
}

/** Whether a program has GL objects (its compiled variants) in a context. osg::Program keeps them
 * in a protected per-context list, which its releaseGLObjects() clears for the context. */
struct ProgramObjectsOf : osg::Program
{
    static bool exist(const osg::Program& program, unsigned int contextID)
    {
        const auto list = &ProgramObjectsOf::_pcpList;
        return (program.*list)[contextID].valid();
    }
};

unsigned int getContextID(Renderer& renderer)
{
    return renderer.getViewer()->getCamera()->getGraphicsContext()->getState()->getContextID();
}

/** Renders nothing, so that the viewer lets go of the clouds it drew. */
void renderNothing(Renderer& renderer)
{
    renderer.render(new osg::Group);
}

osg::Vec4ub toColor(const osg::Vec4& color)
{
    auto channel = [](float value) { return static_cast<unsigned char>(std::lround(value * 255.0f)); };
    return osg::Vec4ub(channel(color.r()), channel(color.g()), channel(color.b()), 255);
}

/** The colour under a sphere's centre: an unlit sphere shows its colour-map colour. */
::testing::AssertionResult sphereColorNear(const Frame& frame, const osg::Vec3& center,
                                           const osg::Vec4& color)
{
    const osg::Vec3d window = frame.project(center);
    return colorNear(frame, static_cast<int>(window.x()), static_cast<int>(window.y()), toColor(color), 2);
}

}

TEST(StateCache, AThousandColourMapsPassThroughABoundedCache)
{
    // Every cloud has a map of its own; one in twenty is drawn, so that its StateSet's colour-map
    // texture has a texture object in the context when the cache drops it.
    Renderer renderer(64, 48);
    GlyphStateCache* cache = GlyphStateCache::instance();
    std::vector<osg::observer_ptr<ColorMap>> maps;
    std::vector<osg::observer_ptr<osg::Texture>> textures;
    unsigned int mostStateSets = 0, mostTextureObjects = 0;
    for (int i = 0; i < 1000; ++i)
    {
        osg::ref_ptr<ColorMap> colorMap = createColorMap(i);
        osg::ref_ptr<GlyphCloud> cloud = createScalarCloud(colorMap.get());
        maps.push_back(colorMap.get());
        textures.push_back(colorMap->getTexture());
        if (i % 20 == 0)
        {
            renderer.render(group({cloud.get()}).get());
            const osg::TextureObjectManager* manager =
                osg::get<osg::TextureObjectManager>(getContextID(renderer));
            mostTextureObjects = std::max(mostTextureObjects, manager->getNumberActiveTextureObjects());
        }
        mostStateSets = std::max(mostStateSets, cache->getNumStateSets());
    }
    EXPECT_LE(mostStateSets, MAX_CACHED_STATESETS);
    EXPECT_LE(mostTextureObjects, MAX_CACHED_STATESETS);
    // The maps go with their clouds; their textures as the cache drops their StateSets.
    EXPECT_EQ(countAlive(maps), 1) << "only the last map, which the last drawn cloud holds";
    EXPECT_LE(countAlive(textures), static_cast<int>(MAX_CACHED_STATESETS));

    renderNothing(renderer);
    cache->prune();
    EXPECT_EQ(countAlive(maps), 0);
    EXPECT_EQ(countAlive(textures), 0);
    EXPECT_EQ(cache->getNumStateSets(), 0u);
}

TEST(StateCache, ANewColourMapIsNeverDrawnWithAFreedOnesColours)
{
    Renderer renderer(160, 120);
    const osg::Vec4 oldLow(1.0f, 0.0f, 0.0f, 1.0f), oldHigh(0.0f, 1.0f, 0.0f, 1.0f);
    const osg::Vec4 newLow(0.0f, 0.0f, 1.0f, 1.0f), newHigh(1.0f, 1.0f, 0.0f, 1.0f);

    osg::ref_ptr<ColorMap> oldMap = new ColorMap("map", {oldLow, oldHigh});
    osg::ref_ptr<GlyphCloud> cloud = createScalarCloud(oldMap.get());
    const Frame before = renderer.render(group({cloud.get()}).get());
    ASSERT_TRUE(sphereColorNear(before, SPHERE_OFFSETS[0], oldLow));
    ASSERT_TRUE(sphereColorNear(before, SPHERE_OFFSETS[1], oldHigh));

    // The old map's StateSet, and with it the old texture, outlives the map (held here as
    // another cloud or a render graph could hold it).
    const unsigned long long oldSerial = oldMap->getSerialNumber();
    const osg::observer_ptr<ColorMap> oldObserver = oldMap.get();
    const osg::ref_ptr<const osg::StateSet> oldStateSet = cloud->getVariantStateSet();
    renderNothing(renderer);
    cloud = nullptr;
    oldMap = nullptr;
    ASSERT_FALSE(oldObserver.valid()) << "the old map is freed";
    ASSERT_EQ(osgGlyphs::GlyphStateCache::instance()->getNumStateSets(), 1u)
        << "its StateSet is still cached";

    // Allocated right after the old one was freed, the new map often takes its address.
    osg::ref_ptr<ColorMap> newMap = new ColorMap("map", {newLow, newHigh});
    EXPECT_GT(newMap->getSerialNumber(), oldSerial);
    cloud = createScalarCloud(newMap.get());
    EXPECT_NE(cloud->getVariantStateSet(), oldStateSet.get());
    const Frame after = renderer.render(group({cloud.get()}).get());
    EXPECT_TRUE(sphereColorNear(after, SPHERE_OFFSETS[0], newLow));
    EXPECT_TRUE(sphereColorNear(after, SPHERE_OFFSETS[1], newHigh));
}

TEST(StateCache, EachViewerAfterAClosedOneLinksItsProgramsInItsOwnContext)
{
    // Viewers made and closed one after another reuse context ID 0, and often their cull visitor's
    // address and, in their first frame, its traversal number: each must register its new
    // context, so that closing it releases the programs linked there and the next viewer links its
    // own. A program left linked for a closed context names nothing in the next: glyphs vanish.
    // (A scene still holding the cloud when its viewer closes would release them itself.)
    const osg::Vec4 low(1.0f, 0.0f, 0.0f, 1.0f), high(0.0f, 0.0f, 1.0f, 1.0f);
    osg::ref_ptr<ColorMap> colorMap = new ColorMap("map", {low, high});
    for (int i = 0; i < 4; ++i)
    {
        Renderer renderer(160, 120);
        ASSERT_EQ(getContextID(renderer), 0u);
        osg::ref_ptr<GlyphCloud> cloud = createScalarCloud(colorMap.get());
        const Frame frame = renderer.render(group({cloud.get()}).get());
        EXPECT_TRUE(sphereColorNear(frame, SPHERE_OFFSETS[0], low)) << "viewer " << i;
        EXPECT_TRUE(sphereColorNear(frame, SPHERE_OFFSETS[1], high)) << "viewer " << i;
        // Closed with a scene that no longer holds the cloud: only the context's observer can
        // release the programs.
        renderNothing(renderer);
    }
}

TEST(StateCache, TextureMultiSpritesGoWithTheirStateSets)
{
    // Each texture-multi StateSet of a colour map holds 64 lit sprites of 256 x 256 (16 MB); 80
    // maps pass through, one in ten drawn.
    const int numMaps = 80;
    Renderer renderer(64, 48);
    std::vector<osg::observer_ptr<const osg::StateSet>> stateSets;
    std::vector<osg::observer_ptr<const osg::StateAttribute>> sprites;
    std::vector<osg::observer_ptr<ColorMap>> maps;
    int mostSprites = 0;
    for (int i = 0; i < numMaps; ++i)
    {
        osg::ref_ptr<ColorMap> colorMap = createColorMap(i);
        osg::ref_ptr<GlyphCloud> cloud = createScalarCloud(colorMap.get(), "texture-multi");
        const osg::StateSet* stateSet = cloud->getVariantStateSet();
        const osg::StateAttribute* sprite = stateSet->getTextureAttribute(
            osgGlyphsPaper::LIT_SPRITES_TEXTURE_UNIT, osg::StateAttribute::TEXTURE);
        ASSERT_NE(sprite, nullptr);
        stateSets.push_back(stateSet);
        sprites.push_back(sprite);
        maps.push_back(colorMap.get());
        if (i % 10 == 0)
        {
            const Frame frame = renderer.render(group({cloud.get()}).get());
            ASSERT_TRUE(sphereColorNear(frame, SPHERE_OFFSETS[1], colorMap->getColor(1.0f)));
        }
        // Sprites live exactly as long as their StateSets.
        for (size_t j = 0; j < sprites.size(); ++j)
            ASSERT_EQ(sprites[j].valid(), stateSets[j].valid()) << "map " << j << " after map " << i;
        mostSprites = std::max(mostSprites, countAlive(sprites));
    }
    // A map's sprites went with its cloud: at most the current map's and those of the last one
    // drawn (the viewer still holds its scene) were alive at once.
    EXPECT_LE(mostSprites, 2);

    renderNothing(renderer);
    GlyphStateCache::instance()->prune();
    EXPECT_EQ(countAlive(stateSets), 0);
    EXPECT_EQ(countAlive(sprites), 0);
    EXPECT_EQ(countAlive(maps), 0) << "the sprites follow their map, and let go of it with the StateSet";
}

TEST(StateCache, ReleaseGLObjectsReachesEveryProgramAndTexture)
{
    // Every registered technique, the paper's included, draws a scalar cloud of its own.
    Renderer renderer(320, 240);
    osg::ref_ptr<ColorMap> colorMap = createColorMap(40);
    const std::vector<std::string> techniques = osgGlyphs::getTechniqueNames();
    ASSERT_GE(techniques.size(), 8u);
    osg::ref_ptr<osg::Geode> scene = new osg::Geode;
    std::vector<const osg::Program*> programs;
    std::vector<const osg::Texture*> textures;
    for (size_t i = 0; i < techniques.size(); ++i)
    {
        const osg::Vec3 center(-3.6f + 2.4f * (i % 4), 0.0f, 1.2f - 2.4f * (i / 4));
        osg::ref_ptr<GlyphCloud> cloud = createScalarCloud(colorMap.get(), techniques[i], center);
        ASSERT_STREQ(cloud->getEffectiveTechnique()->getTechniqueName(), techniques[i].c_str());
        scene->addDrawable(cloud.get());
        programs.push_back(GlyphStateCache::instance()->getProgram(*cloud->getEffectiveTechnique()));
        for (const osg::Texture* texture : getTextures(*cloud->getVariantStateSet()))
            if (std::find(textures.begin(), textures.end(), texture) == textures.end())
                textures.push_back(texture);
    }
    // The colour map's; texture-blend's mask and lighting; texture-multi's sprites.
    EXPECT_GE(textures.size(), 4u);

    const Frame before = renderer.render(scene.get());
    saveFrame(before, "state_cache_release_before");
    const unsigned int contextID = getContextID(renderer);
    for (size_t i = 0; i < programs.size(); ++i)
        EXPECT_TRUE(ProgramObjectsOf::exist(*programs[i], contextID)) << techniques[i];
    for (const osg::Texture* texture : textures)
        EXPECT_NE(texture->getTextureObject(contextID), nullptr) << texture->className();

    osg::State* state = renderer.getViewer()->getCamera()->getGraphicsContext()->getState();
    GlyphStateCache::instance()->releaseGLObjects(state);
    for (size_t i = 0; i < programs.size(); ++i)
        EXPECT_FALSE(ProgramObjectsOf::exist(*programs[i], contextID)) << techniques[i];
    for (const osg::Texture* texture : textures)
        EXPECT_EQ(texture->getTextureObject(contextID), nullptr) << texture->className();

    // Compiled and loaded again, as into a new context that reuses the ID: the same picture.
    const Frame after = renderer.render(scene.get());
    saveFrame(after, "state_cache_release_after");
    int covered = 0, differing = 0;
    for (int y = 0; y < before.height(); ++y)
    {
        for (int x = 0; x < before.width(); ++x)
        {
            covered += before.isCovered(x, y) ? 1 : 0;
            differing +=
                colorNear(after, x, y, before.colorAt(x, y), 0) && after.depthAt(x, y) == before.depthAt(x, y)
                    ? 0
                    : 1;
        }
    }
    EXPECT_GT(covered, 5000);
    EXPECT_EQ(differing, 0) << "of " << covered << " covered pixels";
    for (size_t i = 0; i < programs.size(); ++i)
        EXPECT_TRUE(ProgramObjectsOf::exist(*programs[i], contextID)) << techniques[i];
}
