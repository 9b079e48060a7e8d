#include "ViewerCamera.h"

#include <osgGlyphs/GlyphDiagnosis>

#include <osg/Matrixd>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

CameraView frameBounds(const osg::BoundingBox& box, double fovY, double aspect)
{
    CameraView view;
    if (!box.valid())
    {
        view.eye.set(0.0, -10.0, 0.0);
        return view;
    }
    const osg::Vec3d extent = box._max - box._min;
    const bool flat = extent.z() < 0.2 * std::max(extent.x(), extent.y());
    osg::Vec3d back = flat ? osg::Vec3d(0.15, -0.5, 0.85) : osg::Vec3d(0.25, -0.9, 0.4);
    back.normalize();
    osg::Vec3d right = osg::Vec3d(0.0, 0.0, 1.0) ^ back;
    right.normalize();
    const osg::Vec3d up = back ^ right;

    // Corner c at (x, y) across and z towards the eye is in view when the eye is at least
    // z + |x| / tan(halfX) and z + |y| / tan(halfY) from the centre.
    const double tanY = std::tan(osg::DegreesToRadians(fovY) / 2.0);
    const double tanX = tanY * aspect;
    view.center = box.center();
    double distance = 0.0;
    for (unsigned int corner = 0; corner < 8; ++corner)
    {
        const osg::Vec3d offset = osg::Vec3d(box.corner(corner)) - view.center;
        const double z = offset * back;
        distance = std::max(distance, z + std::fabs(offset * right) / tanX * 1.05);
        distance = std::max(distance, z + std::fabs(offset * up) / tanY * 1.05);
    }
    if (!(distance > 0.0))
        distance = 1.0;
    view.eye = view.center + back * distance;
    view.up.set(0.0, 0.0, 1.0);
    return view;
}

void warnIfGlyphsHidden(osg::Node& content, const osg::Camera& camera, const CameraView& view)
{
    const std::string reason =
        osgGlyphs::diagnoseGlyphView(content, camera, osg::Matrixd::lookAt(view.eye, view.center, view.up));
    if (!reason.empty())
        std::cerr << PROGRAM << ": warning: " << reason << std::endl;
}

CameraView orbit(const CameraView& view, double degrees)
{
    const osg::Matrixd rotation = osg::Matrixd::rotate(osg::DegreesToRadians(degrees), view.up);
    CameraView turned = view;
    turned.eye = view.center + rotation.preMult(view.eye - view.center);
    return turned;
}

std::string formatFrameTimes(std::vector<double> milliseconds)
{
    if (milliseconds.empty())
        return "frame_ms median=0 min=0 max=0";
    std::sort(milliseconds.begin(), milliseconds.end());
    const std::size_t n = milliseconds.size();
    const double median = n % 2 ? milliseconds[n / 2] : 0.5 * (milliseconds[n / 2 - 1] + milliseconds[n / 2]);
    char line[128];
    std::snprintf(line, sizeof(line), "frame_ms median=%.3f min=%.3f max=%.3f", median, milliseconds.front(),
                  milliseconds.back());
    return line;
}
