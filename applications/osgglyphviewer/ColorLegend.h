// osgglyphviewer: the colour legend over the view.

#ifndef OSGGLYPHVIEWER_COLORLEGEND_H
#define OSGGLYPHVIEWER_COLORLEGEND_H 1

#include <osgGlyphsData/GlyphMapping>

#include <osg/Camera>
#include <osgText/Font>

#include <string>

/** A sans-serif TrueType font if the system has one, else osgText's built-in font. */
osgText::Font* getViewerFont();

/** An orthographic HUD camera drawn after the scene (absolute reference frame, POST_RENDER,
 * clearing nothing, no lighting and no depth test, so the scene's depth buffer stays intact);
 * the caller sets its projection. */
osg::ref_ptr<osg::Camera> createHudCamera(const std::string& name);

/** Creates the heads-up display of a colour key: for a scalar, a vertical bar of the colour map
 * at the right of the view with the range's maximum and minimum beside its ends and the column
 * name above it; for categories, a swatch and a label per category.
 *
 * The HUD is a createHudCamera() in pixels. Its update
 * callback lays it out again whenever the viewport of reference changes size. Text is dark on a
 * light background and light on a dark one, outlined in the background colour. Returns nullptr
 * for osgGlyphsData::ColorKey::None. */
osg::ref_ptr<osg::Camera> createColorLegend(const osgGlyphsData::ColorKey& key, osg::Camera* reference,
                                            const osg::Vec4& background);

#endif
