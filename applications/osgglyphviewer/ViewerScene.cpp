#include "ViewerScene.h"

#include "BuiltinScenes.h"
#include "ColorLegend.h"
#include "DatasetLoading.h"
#include "ViewerCamera.h"

#include <osg/ComputeBoundsVisitor>
#include <osg/Geode>
#include <osgGlyphs/GlyphStateCache>

ViewerScene::ViewerScene(const FrameSource& source, std::size_t numFrames, const osgGlyphsData::ColorKey& key)
    : _source(source), _numFrames(numFrames), _key(key), _root(new osg::Group), _content(new osg::Group)
{
    _root->addChild(_content.get());
    setLit(true);
}

bool ViewerScene::setFrame(std::size_t frame, std::string& error)
{
    if (frame >= _numFrames)
    {
        error = "no frame " + std::to_string(frame) + " (frames 0 to " + std::to_string(_numFrames - 1) + ")";
        return false;
    }
    osg::ref_ptr<osg::Node> node = _source(frame, error);
    if (!node)
        return false;
    _content->removeChildren(0, _content->getNumChildren());
    _content->addChild(node.get());
    _frame = frame;
    return true;
}

void ViewerScene::setLit(bool lit)
{
    _lit = lit;
    osgGlyphs::setGlyphLighting(*_content->getOrCreateStateSet(), lit);
}

void ViewerScene::addLegend(osg::Camera* camera, const osg::Vec4& background)
{
    osg::ref_ptr<osg::Camera> legend = createColorLegend(_key, camera, background);
    if (legend.valid())
        _root->addChild(legend.get());
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

osg::ref_ptr<ViewerScene> createDatasetScene(const ViewerOptions& options, std::string& error)
{
    osg::ref_ptr<osgGlyphsData::PointDataset> dataset = loadDataset(options.file, options.format, error);
    if (!dataset)
        return nullptr;
    if (options.frame >= dataset->getNumFrames())
    {
        error = "--frame " + std::to_string(options.frame) + ": " + options.file + " has " +
                std::to_string(dataset->getNumFrames()) + " frame" +
                (dataset->getNumFrames() == 1 ? "" : "s") + ", counted from 0";
        return nullptr;
    }
    osgGlyphsData::GlyphMapper mapper(options.mapping);
    if (!mapper.prepare(*dataset, options.frame, error))
        return nullptr;
    ViewerScene::FrameSource source = [dataset, mapper](std::size_t frame, std::string& frameError)
    {
        osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = mapper.createCloud(*dataset->getFrame(frame), frameError);
        if (!cloud)
            return osg::ref_ptr<osg::Node>();
        osg::ref_ptr<osg::Geode> geode = new osg::Geode;
        geode->addDrawable(cloud.get());
        return osg::ref_ptr<osg::Node>(geode);
    };
    osg::ref_ptr<ViewerScene> scene = new ViewerScene(source, dataset->getNumFrames(), mapper.getColorKey());
    const osgGlyphsData::PointData* data = dataset->getFrame(options.frame);
    scene->setDescription(options.file + ": " + std::to_string(dataset->getNumFrames()) + " frame" +
                          (dataset->getNumFrames() == 1 ? "" : "s") + " (" + dataset->getFormat() + "), " +
                          std::to_string(data->getNumPoints()) + " points in frame " +
                          std::to_string(options.frame) + "; " + mapper.describe());
    return scene;
}

}

osg::ref_ptr<ViewerScene> createViewerScene(const ViewerOptions& options, std::string& error)
{
    if (options.file.empty() && options.frame > 0)
    {
        error = "--frame " + std::to_string(options.frame) + ": the " +
                (options.randomCount ? "random" : "built-in") + " scene has one frame (0)";
        return nullptr;
    }
    osg::ref_ptr<ViewerScene> scene;
    if (!options.file.empty())
        scene = createDatasetScene(options, error);
    else if (options.randomCount > 0)
        scene = createRandomScene(options, error);
    else
        scene = createDefaultScene(options, error);
    if (!scene || !scene->setFrame(options.frame, error))
        return nullptr;
    scene->setLit(options.mapping.lit);
    return scene;
}
