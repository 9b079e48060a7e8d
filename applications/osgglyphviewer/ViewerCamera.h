// osgglyphviewer: where the camera looks from, and how long frames take.

#ifndef OSGGLYPHVIEWER_VIEWERCAMERA_H
#define OSGGLYPHVIEWER_VIEWERCAMERA_H 1

#include "ViewerOptions.h"

#include <osg/BoundingBox>
#include <osg/Camera>

#include <string>
#include <vector>

/** A view of a bounding box, z up: from the front, a little right and above, or mostly from
 * above when the box is flat in z; at the distance where every corner of the box is inside the
 * vertical and horizontal field of view, with a margin of 5%. */
CameraView frameBounds(const osg::BoundingBox& box, double fovY, double aspect);

/** The view turned by degrees about its centre, around its up vector: the camera path of --frames. */
CameraView orbit(const CameraView& view, double degrees);

/** Prints a warning line on stderr when the camera, looking from view, would show none or next to
 * none of the scene's glyphs (osgGlyphs::diagnoseGlyphView); the viewer draws on. */
void warnIfGlyphsHidden(osg::Node& content, const osg::Camera& camera, const CameraView& view);

/** The degrees --frames turns the camera per frame. */
const double ORBIT_DEGREES_PER_FRAME = 1.0;

/** The line --frames prints: "frame_ms median=... min=... max=...". */
std::string formatFrameTimes(std::vector<double> milliseconds);

#endif
