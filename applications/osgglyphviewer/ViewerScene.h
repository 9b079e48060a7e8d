// osgglyphviewer: what the viewer shows.

#ifndef OSGGLYPHVIEWER_VIEWERSCENE_H
#define OSGGLYPHVIEWER_VIEWERSCENE_H 1

#include "ViewerOptions.h"

#include <osgGlyphs/GlyphCloud>
#include <osgGlyphsData/FramePlayer>
#include <osgGlyphsData/GlyphMapping>

#include <osg/Camera>
#include <osg/ClipNode>
#include <osg/Group>

#include <functional>
#include <string>

/** The scene of the viewer: the content of one frame (the glyphs, and other geometry of the
 * built-in scene) under a group that switches glyph lighting, and a colour legend.
 *
 * The frames come from a FrameSource; setFrame() replaces the content. The colour key, and so
 * the legend, is the same for every frame. */
class ViewerScene : public osg::Referenced
{
public:
    /** Makes the content of a frame, or returns nullptr with a one-line error. */
    typedef std::function<osg::ref_ptr<osg::Node>(std::size_t frame, std::string& error)> FrameSource;

    ViewerScene(const FrameSource& source, std::size_t numFrames, const osgGlyphsData::ColorKey& key);

    /** The scene graph: content and, once addLegend() is called, the legend. */
    osg::Group* getRoot() { return _root.get(); }

    /** The content of the current frame, which the camera frames. */
    osg::Group* getContent() { return _content.get(); }

    /** Shows the frame; on failure keeps the current one and returns false with error set. */
    bool setFrame(std::size_t frame, std::string& error);
    /** The frame shown (the stored frame before it, for an interpolated picture). */
    std::size_t getFrame() const;
    /** The frames known (of a trajectory whose index is being built: so far). */
    std::size_t getNumFrames() const;

    /** The player of a trajectory, which then makes the frames (setFrame() shows them through
     * it): its cloud is the content, its update callback on the content's group. */
    void setPlayer(osgGlyphsData::FramePlayer* player);
    osgGlyphsData::FramePlayer* getPlayer() const { return _player.get(); }

    /** Reads the frames its file completed since the last call; added: how many (--follow). */
    typedef std::function<bool(std::size_t& added, std::string& error)> FrameFollower;
    void setFollower(const FrameFollower& follower) { _follower = follower; }
    bool isFollowing() const { return static_cast<bool>(_follower); }

    /** Counts in the frames that the file completed since the last call (none without a
     * follower); false with a one-line error when they cannot be read. */
    bool followFile(std::size_t& added, std::string& error);

    /** Keeps only the half-spaces plane(p) >= 0 of the content (data coordinates); capped, cut
     * glyphs show solid faces in the planes. */
    void setClipPlanes(const std::vector<osg::Plane>& planes, bool capped);

    /** Puts the content under a shadowed scene with its own light and a ground plane just below
     * the current frame (--shadows; createShadowScene), or takes it out. */
    void setShadows(bool shadows);
    /** Whether the scene has its own light, with which the view's headlight must be off. */
    bool hasOwnLight() const { return _shadowedScene.valid(); }

    /** Ambient occlusion per glyph (--ao): computed for every cloud of a frame when it is first
     * shown with it on, with progress on the console when it takes long. */
    void setAmbientOcclusion(bool on);
    bool getAmbientOcclusion() const { return _ambientOcclusion; }

    /** The screen-space ambient occlusion and outlines of the content (off by default). */
    osgGlyphs::ScreenEffects* getScreenEffects() { return _effects.get(); }
    /** The transparency of the content (--opacity; key x). */
    Transparency* getTransparency() { return _transparency.get(); }

    /** Lit or flat glyphs, for every glyph of the scene. */
    void setLit(bool lit);
    bool getLit() const { return _lit; }

    const osgGlyphsData::ColorKey& getColorKey() const { return _key; }

    /** Adds the HUD of the colour key, laid out for the viewport of camera. */
    void addLegend(osg::Camera* camera, const osg::Vec4& background);

    /** A view chosen for the scene (the built-in scene has one); otherwise views frame the content. */
    void setHomeView(const CameraView& view);
    /** The scene's own view, or the content framed for a field of view and aspect ratio. */
    CameraView getHomeView(double fovY, double aspect);

    /** Describes point index of a frame: a "name = value" line per column of the file. */
    typedef std::function<std::string(std::size_t frame, unsigned int index)> PointDescriber;
    void setPointDescriber(const PointDescriber& describer) { _describer = describer; }
    /** The point's columns in the current frame; without a file, its glyph's position. */
    std::string describePoint(unsigned int index) const;

    /** The glyphs of the current frame: the content's cloud, where it is one. */
    osgGlyphs::GlyphCloud* getCloud() const;

    /** One line about the data and how it is drawn, for the console. */
    void setDescription(const std::string& description) { _description = description; }
    const std::string& getDescription() const { return _description; }

protected:
    ~ViewerScene() override = default;

    /** Gives the clouds under node that have no ambient occlusion theirs. */
    static void computeOcclusion(osg::Node& node);

    FrameSource _source;
    osg::ref_ptr<osgGlyphsData::FramePlayer> _player;
    FrameFollower _follower;
    std::size_t _numFrames;
    std::size_t _frame = 0;
    bool _lit = true;
    bool _ambientOcclusion = false;
    osgGlyphsData::ColorKey _key;
    osg::ref_ptr<osg::Group> _root;
    osg::ref_ptr<osg::ClipNode> _clipNode;   // between the root (or the shadowed scene) and the content
    osg::ref_ptr<osg::Group> _shadowedScene; // between the root and the clip node, with --shadows
    osg::ref_ptr<osgGlyphs::ScreenEffects> _effects; // below the clip node
    osg::ref_ptr<Transparency> _transparency;        // its node between the effects and the content
    osg::ref_ptr<osg::Group> _content;
    bool _hasHomeView = false;
    CameraView _homeView;
    std::string _description;
    PointDescriber _describer;
};

/** A perspective projection for a view: near and far planes at a thousandth and a thousand times
 * the viewing distance, from which OSG fits them to the scene each frame. A fixed starting pair
 * would leave scenes far larger or smaller than it to rounding (points 1e17 apart come out blank
 * from 1 and 1000). */
void setProjectionForView(osg::Camera& camera, double fovY, double aspect, const CameraView& view);

/** How a process that draws one share of a scene split over processes (mpirun) makes its part:
 * by default the whole scene, alone. */
struct SceneSharing
{
    /** The share of the points this process reads or generates. */
    osgGlyphsData::PointShare share;
    /** Combines over the processes what depends on the whole dataset (colour range, radius). */
    osg::ref_ptr<const osgGlyphsData::ShareReduction> reduction;
    /** Collective: whether every process succeeded, else the first failure's error in all. */
    std::function<bool(bool ok, std::string& error)> agree;
    /** Collective: called with the cloud of each frame in every process (shared bounds). */
    std::function<void(osgGlyphs::GlyphCloud& cloud)> shareCloud;

    bool isShared() const { return static_cast<bool>(agree); }
};

/** The scene the options ask for: the built-in scene, --random, or a file (read with progress)
 * mapped to glyphs, at --frame. Returns nullptr with a one-line error. With sharing, a file or
 * --random, of which this process holds sharing.share; every process must call it. */
osg::ref_ptr<ViewerScene> createViewerScene(const ViewerOptions& options, std::string& error,
                                            const SceneSharing& sharing = SceneSharing());

#endif
