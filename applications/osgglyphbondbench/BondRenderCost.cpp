#include "BondRenderCost.h"

#include <osgGlyphs/GlyphCloud>
#include <osgGlyphs/GlyphCulling>
#include <osgGlyphsData/BondFinder>
#include <osgGlyphsData/BondGlyphs>
#include <osgGlyphsData/RandomCloud>
#include <osgGlyphsHeadless/OffscreenViewer>

#include <osg/Group>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

namespace
{

/** Median milliseconds of a frame of scene, after one untimed frame, the camera orbiting the unit
 * cube a degree a frame from where its bounding sphere fills the 30 degree view; appends to
 * submitted the share of each of clouds' glyphs that culling sent to the GPU in the last frame. */
double medianFrameMs(osg::Node* scene, unsigned int frames, int width, int height, std::string& renderer,
                     const std::vector<osgGlyphs::GlyphCloud*>& clouds, std::vector<double>& submitted)
{
    osg::ref_ptr<osgGlyphsHeadless::OffscreenViewer> viewer =
        new osgGlyphsHeadless::OffscreenViewer(width, height);
    if (!viewer->valid())
    {
        std::cerr << "osgglyphbondbench: " << viewer->getContextError() << "\n";
        return -1.0;
    }
    viewer->getFrameCapture()->setCaptureDepth(false);
    viewer->setSceneData(scene);
    viewer->realize();
    const osg::Vec3d centre(0.5, 0.5, 0.5);
    const double distance = std::sqrt(0.75) / std::sin(osg::DegreesToRadians(15.0));
    std::vector<double> times;
    for (unsigned int frame = 0; frame <= frames; ++frame)
    {
        const double angle = osg::DegreesToRadians(30.0 + frame);
        const osg::Vec3d eye =
            centre + osg::Vec3d(std::cos(angle), std::sin(angle), 0.45) * (distance / 1.0966);
        viewer->getCamera()->setViewMatrixAsLookAt(eye, centre, osg::Vec3d(0.0, 0.0, 1.0));
        const auto start = std::chrono::steady_clock::now();
        viewer->frame();
        if (frame > 0)
            times.push_back(
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    if (renderer.empty())
        renderer = viewer->getFrameCapture()->getGLRenderer();
    const unsigned int contextID = viewer->getCamera()->getGraphicsContext()->getState()->getContextID();
    for (osgGlyphs::GlyphCloud* cloud : clouds)
        submitted.push_back(double(cloud->getCullingStatistics(contextID).glyphsSubmitted) /
                            cloud->getNumGlyphs());
    std::sort(times.begin(), times.end());
    return times[times.size() / 2];
}

}

int measureBondRenderCost(std::size_t atoms, double bondsPerAtom, unsigned int frames, int width, int height)
{
    osgGlyphsData::RandomCloudOptions options;
    options.count = static_cast<unsigned int>(atoms);
    const double spacing = std::cbrt(1.0 / double(atoms));
    options.radius = static_cast<float>(0.4 * spacing);
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = osgGlyphsData::createRandomCloud(options);
    // 2 bondsPerAtom neighbours within the cutoff on average: n (4/3) pi c^3 = 2 bondsPerAtom.
    const double cutoff = std::cbrt(2.0 * bondsPerAtom * 3.0 / (4.0 * M_PI * double(atoms)));
    const std::vector<osg::Vec3f> positions(cloud->getPositions()->begin(), cloud->getPositions()->end());
    std::vector<osgGlyphsData::Bond> bonds;
    std::string error;
    if (!osgGlyphsData::findBonds(positions, {}, osgGlyphsData::BondCutoffs(cutoff), nullptr, bonds, error))
    {
        std::cerr << "osgglyphbondbench: " << error << "\n";
        return 1;
    }
    osg::ref_ptr<osgGlyphs::GlyphCloud> bondCloud =
        osgGlyphsData::makeBondCloud(*cloud, bonds, nullptr, osgGlyphsData::getDefaultBondRadius(*cloud),
                                     error, osgGlyphsData::BondEnds::AtAtomSurfaces);
    if (!bondCloud)
    {
        std::cerr << "osgglyphbondbench: " << error << "\n";
        return 1;
    }
    osg::ref_ptr<osg::Group> both = new osg::Group;
    both->addChild(cloud.get());
    both->addChild(bondCloud.get());
    std::string renderer;
    std::vector<double> submitted;
    const double alone =
        medianFrameMs(cloud.get(), frames, width, height, renderer, {cloud.get()}, submitted);
    const double bonded =
        medianFrameMs(both.get(), frames, width, height, renderer, {cloud.get(), bondCloud.get()}, submitted);
    // Culled together, nearest chunks of either first: atoms hide bonds and bonds atoms.
    both->getOrCreateStateSet()->setRenderBinDetails(0, osgGlyphs::FRONT_TO_BACK_BIN);
    const double together =
        medianFrameMs(both.get(), frames, width, height, renderer, {cloud.get(), bondCloud.get()}, submitted);
    if (alone < 0.0 || bonded < 0.0 || together < 0.0)
        return 1;
    std::cout << "osgglyphbondbench --render: " << atoms << " atoms of radius 0.4 x their mean spacing, "
              << bonds.size() << " bonds (cutoff " << std::setprecision(3) << cutoff / spacing
              << " x the spacing, " << bondCloud->getNumGlyphs() << " half-bonds), " << width << "x" << height
              << ", median of " << frames << " frames, " << renderer << "\n"
              << std::fixed << std::setprecision(1) << "  atoms alone                        " << alone
              << " ms, " << std::setprecision(0) << 100.0 * submitted[0] << "% of the atoms submitted\n"
              << std::setprecision(1) << "  atoms and bonds                    " << bonded << " ms ("
              << std::setprecision(2) << bonded / alone << " x), " << std::setprecision(0)
              << 100.0 * submitted[1] << "% of the atoms and " << 100.0 * submitted[2]
              << "% of the half-bonds submitted\n"
              << std::setprecision(1) << "  the same in one FRONT_TO_BACK_BIN  " << together << " ms ("
              << std::setprecision(2) << together / alone << " x), " << std::setprecision(0)
              << 100.0 * submitted[3] << "% and " << 100.0 * submitted[4] << "%\n";
    return 0;
}
