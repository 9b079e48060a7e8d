#include "ViewerScene.h"

#include "BuiltinScenes.h"
#include "ColorLegend.h"
#include "DatasetLoading.h"
#include "ShadowScene.h"
#include "TileScene.h"
#include "TrajectoryScene.h"
#include "ViewerCamera.h"
#include "ViewerText.h"

#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <osg/ComputeBoundsVisitor>
#include <osg/Geode>
#include <osg/NodeVisitor>
#include <osgGlyphs/GlyphStateCache>
#include <osgGlyphsData/SharedDataset>
#include <thread>

ViewerScene::ViewerScene(const FrameSource& source, std::size_t numFrames, const osgGlyphsData::ColorKey& key)
    : _source(source), _numFrames(numFrames), _key(key), _root(new osg::Group), _clipNode(new osg::ClipNode),
      _effects(new osgGlyphs::ScreenEffects), _transparency(new Transparency), _content(new osg::Group)
{
    _root->addChild(_clipNode.get());
    _clipNode->addChild(_effects.get());
    _effects->addChild(_transparency->getNode());
    _transparency->getNode()->addChild(_content.get());
    setLit(true);
}

std::size_t ViewerScene::getFrame() const
{
    return _player.valid() ? static_cast<std::size_t>(std::floor(_player->getPosition() + 1e-9)) : _frame;
}

std::size_t ViewerScene::getNumFrames() const
{
    return _player.valid() ? _player->getNumFrames() : _numFrames;
}

void ViewerScene::setPlayer(osgGlyphsData::FramePlayer* player)
{
    _player = player;
}

bool ViewerScene::setFrame(std::size_t frame, std::string& error)
{
    const std::size_t frames = getNumFrames();
    if (frame >= frames)
    {
        error = "no frame " + std::to_string(frame) + " (frames 0 to " + std::to_string(frames - 1) + ")";
        return false;
    }
    osg::ref_ptr<osg::Node> node = _source(frame, error);
    if (!node)
        return false;
    _content->removeChildren(0, _content->getNumChildren());
    _content->addChild(node.get());
    _frame = frame;
    if (_ambientOcclusion)
        computeOcclusion(*node);
    return true;
}

void ViewerScene::setAmbientOcclusion(bool on)
{
    _ambientOcclusion = on;
    if (on)
        computeOcclusion(*_content);
    osgGlyphs::setGlyphAmbientOcclusion(*_content->getOrCreateStateSet(), on);
}

namespace
{

/** Computes the ambient occlusion of the clouds that have none, with progress on the console
 * once it has taken a second. */
class OcclusionVisitor : public osg::NodeVisitor
{
public:
    OcclusionVisitor() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
    void apply(osg::Drawable& drawable) override
    {
        auto* cloud = dynamic_cast<osgGlyphs::GlyphCloud*>(&drawable);
        if (!cloud || cloud->getOcclusion())
            return;
        const auto start = std::chrono::steady_clock::now();
        auto seconds = [start]
        { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
        double nextReport = 1.0;
        osgGlyphs::GlyphOcclusionSettings settings;
        settings.progress = [&](float done)
        {
            if (seconds() < nextReport)
                return;
            nextReport = seconds() + 1.0;
            std::cerr << PROGRAM << ": ambient occlusion of " << cloud->getNumGlyphs()
                      << " glyphs: " << int(100.0f * done) << "%" << std::endl;
        };
        cloud->setOcclusion(cloud->computeOcclusion(settings).get());
        if (seconds() >= 1.0)
            std::cerr << PROGRAM << ": ambient occlusion computed in " << std::fixed << std::setprecision(1)
                      << seconds() << " s" << std::defaultfloat << std::endl;
    }
};

}

void ViewerScene::computeOcclusion(osg::Node& node)
{
    OcclusionVisitor visitor;
    node.accept(visitor);
}

bool ViewerScene::followFile(std::size_t& added, std::string& error)
{
    added = 0;
    if (!_follower || !_follower(added, error))
        return !_follower;
    _numFrames += added;
    return true;
}

void ViewerScene::setLit(bool lit)
{
    _lit = lit;
    osgGlyphs::setGlyphLighting(*_content->getOrCreateStateSet(), lit);
}

void ViewerScene::setClipPlanes(const std::vector<osg::Plane>& planes, bool capped)
{
    while (_clipNode->getNumClipPlanes() > 0)
        _clipNode->removeClipPlane(0u);
    for (unsigned int i = 0; i < planes.size(); ++i)
        _clipNode->addClipPlane(new osg::ClipPlane(i, planes[i]));
    osgGlyphs::setClipCaps(*_clipNode->getOrCreateStateSet(), capped);
}

void ViewerScene::setShadows(bool shadows)
{
    if (shadows == _shadowedScene.valid())
        return;
    if (shadows)
    {
        osg::ComputeBoundsVisitor bounds;
        _content->accept(bounds);
        _shadowedScene = createShadowScene(bounds.getBoundingBox());
        _root->replaceChild(_clipNode.get(), _shadowedScene.get());
        _shadowedScene->addChild(_clipNode.get());
    }
    else
    {
        _root->replaceChild(_shadowedScene.get(), _clipNode.get());
        _shadowedScene = nullptr;
    }
}

void ViewerScene::addLegend(osg::Camera* camera, const osg::Vec4& background)
{
    osg::ref_ptr<osg::Camera> legend = createColorLegend(_key, camera, background);
    if (legend.valid())
        _root->addChild(legend.get());
}

std::string ViewerScene::describePoint(unsigned int index) const
{
    if (_describer)
        return _describer(_frame, index);
    const osgGlyphs::GlyphCloud* cloud = getCloud();
    if (!cloud || !cloud->getPositions() || index >= cloud->getPositions()->size())
        return std::string();
    const osg::Vec3d p = cloud->getOrigin() + osg::Vec3d((*cloud->getPositions())[index]);
    return "x = " + formatFullValue(p.x()) + "\ny = " + formatFullValue(p.y()) +
           "\nz = " + formatFullValue(p.z()) + "\n";
}

osgGlyphs::GlyphCloud* ViewerScene::getCloud() const
{
    for (unsigned int i = 0; i < _content->getNumChildren(); ++i)
    {
        osg::Group* group = _content->getChild(i)->asGroup();
        osg::Node* nodes[] = {_content->getChild(i),
                              group && group->getNumChildren() ? group->getChild(0) : nullptr};
        for (osg::Node* node : nodes)
            if (auto* cloud = dynamic_cast<osgGlyphs::GlyphCloud*>(node))
                return cloud;
    }
    return nullptr;
}

void ViewerScene::setHomeView(const CameraView& view)
{
    _hasHomeView = true;
    _homeView = view;
}

void setProjectionForView(osg::Camera& camera, double fovY, double aspect, const CameraView& view)
{
    const double distance = (view.eye - view.center).length();
    camera.setProjectionMatrixAsPerspective(fovY, aspect, distance * 1e-3, distance * 1e3);
}

CameraView ViewerScene::getHomeView(double fovY, double aspect)
{
    if (_hasHomeView)
        return _homeView;
    osg::ComputeBoundsVisitor bounds;
    _content->accept(bounds);
    return frameBounds(bounds.getBoundingBox(), fovY, aspect);
}

namespace
{

/** Waits until a followed file has count frames, reading it again every POLL_SECONDS. */
bool waitForFrames(DatasetFollower& follower, const osgGlyphsData::PointDataset& dataset, std::size_t count,
                   double timeout, std::string& error)
{
    const auto start = std::chrono::steady_clock::now();
    if (dataset.getNumFrames() < count)
        std::cerr << PROGRAM << ": waiting for frame " << count - 1 << " of " << dataset.getSource()
                  << std::endl;
    while (dataset.getNumFrames() < count)
    {
        if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > timeout)
        {
            error = dataset.getSource() + ": no frame " + std::to_string(count - 1) + " after " +
                    std::to_string(static_cast<int>(timeout)) + " s of --follow";
            return false;
        }
        std::this_thread::sleep_for(std::chrono::duration<double>(FOLLOW_POLL_SECONDS));
        std::size_t added = 0;
        if (!follower.poll(added, error))
            return false;
    }
    return true;
}

/** Whether every process succeeded; alone, whether this one did. */
bool agree(const SceneSharing& sharing, bool ok, std::string& error)
{
    return sharing.agree ? sharing.agree(ok, error) : ok;
}

/** A file split over processes (mpirun): each reads its share of every frame at once. */
osg::ref_ptr<ViewerScene> createDatasetScene(const ViewerOptions& options, const SceneSharing& sharing,
                                             std::string& error)
{
    osg::ref_ptr<osgGlyphsData::PointDataset> dataset =
        loadDataset(options.file, options.format, options.follow, sharing.share, error, options.datasets);
    if (!agree(sharing, dataset.valid(), error))
        return nullptr;
    // The same in every process: no need to agree on it.
    if (sharing.reduction.valid() && !osgGlyphsData::unifyShares(*dataset, *sharing.reduction, error))
    {
        error = options.file + ": " + error;
        return nullptr;
    }
    std::shared_ptr<DatasetFollower> follower;
    if (options.follow)
    {
        follower = std::make_shared<DatasetFollower>(options.file, options.format, dataset.get());
        if (!waitForFrames(*follower, *dataset, options.frame + 1, options.followTimeout, error))
            return nullptr;
    }
    if (options.frame >= dataset->getNumFrames())
    {
        error = "--frame " + std::to_string(options.frame) + ": " + options.file + " has " +
                std::to_string(dataset->getNumFrames()) + " frame" +
                (dataset->getNumFrames() == 1 ? "" : "s") + ", counted from 0";
        return nullptr;
    }
    osgGlyphsData::GlyphMapper mapper(options.mapping);
    mapper.setReduction(sharing.reduction.get());
    if (!agree(sharing, mapper.prepare(*dataset, options.frame, error), error))
        return nullptr;
    ViewerScene::FrameSource source = [dataset, mapper, sharing](std::size_t frame, std::string& frameError)
    {
        osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = mapper.createCloud(*dataset->getFrame(frame), frameError);
        if (!agree(sharing, cloud.valid(), frameError))
            return osg::ref_ptr<osg::Node>();
        if (sharing.shareCloud)
            sharing.shareCloud(*cloud);
        return osg::ref_ptr<osg::Node>(cloud); // not in a Geode: see BuiltinScenes.cpp
    };
    osg::ref_ptr<ViewerScene> scene = new ViewerScene(source, dataset->getNumFrames(), mapper.getColorKey());
    if (follower)
        scene->setFollower([follower](std::size_t& added, std::string& pollError)
                           { return follower->poll(added, pollError); });
    scene->setPointDescriber(
        [dataset](std::size_t frame, unsigned int index)
        {
            const osgGlyphsData::PointData* points = dataset->getFrame(frame);
            std::string text;
            for (std::size_t column = 0;
                 points && index < points->getNumPoints() && column < points->getNumColumns(); ++column)
            {
                const std::string& name = points->getColumnNames()[column];
                const double value = points->getValue(column, index);
                const std::vector<std::string>& labels = points->getColumnLabels(name);
                const bool label = !labels.empty() && value >= 0.0 && value < double(labels.size());
                text += name + " = " + (label ? labels[std::size_t(value)] : formatFullValue(value)) + "\n";
            }
            return text;
        });
    const osgGlyphsData::PointData* data = dataset->getFrame(options.frame);
    scene->setDescription(options.file + ": " + std::to_string(dataset->getNumFrames()) + " frame" +
                          (dataset->getNumFrames() == 1 ? "" : "s") + " (" + dataset->getFormat() + "), " +
                          std::to_string(data->getNumPoints()) + " points in frame " +
                          std::to_string(options.frame) + "; " + mapper.describe());
    return scene;
}

}

osg::ref_ptr<ViewerScene> createViewerScene(const ViewerOptions& options, std::string& error,
                                            const SceneSharing& sharing)
{
    if (options.file.empty() && options.frame > 0)
    {
        error = "--frame " + std::to_string(options.frame) + ": the " +
                (options.randomCount ? "random" : "built-in") + " scene has one frame (0)";
        return nullptr;
    }
    if (!options.topology.empty() && isTileArchive(options.file))
    {
        error = "--topology: " + options.file + " is a tile archive, whose glyphs are made already";
        return nullptr;
    }
    const bool tiles = !options.file.empty() && isTileArchive(options.file);
    if ((options.bonds.enabled() || options.bonds.required) && (tiles || sharing.isShared()))
    {
        error = std::string(options.bonds.required ? "--bonds" : "--bond-cutoff") +
                ": bonds are drawn for a file of atoms on one process, not " +
                (tiles ? "for a tile archive" : "under mpirun");
        return nullptr;
    }
    osg::ref_ptr<ViewerScene> scene;
    if (tiles)
        scene = createTileScene(options, error);
    else if (!options.file.empty() && !sharing.isShared())
        scene = createTrajectoryScene(options, error);
    else if (!options.file.empty())
        scene = createDatasetScene(options, sharing, error);
    else if (options.randomCount > 0)
        scene = createRandomScene(options, sharing, error);
    else
        scene = createDefaultScene(options, error);
    if (!scene || !scene->setFrame(options.frame, error))
        return nullptr;
    scene->setLit(options.mapping.lit);
    scene->setClipPlanes(options.clipPlanes, options.clipCaps);
    scene->setShadows(options.shadows);
    applyScreenEffectsOptions(*scene, options.effects, options.ambientOcclusion);
    scene->getTransparency()->setOptions(options.transparency);
    return scene;
}
