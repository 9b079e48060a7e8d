// osgglyphviewer: the command line.

#ifndef OSGGLYPHVIEWER_VIEWEROPTIONS_H
#define OSGGLYPHVIEWER_VIEWEROPTIONS_H 1

#include "BondOptions.h"
#include "PlaybackOptions.h"
#include "ScreenEffectsOptions.h"
#include "Transparency.h"

#include <osgGlyphsData/GlyphMapping>
#include <osgGlyphsHeadless/HeadlessContext>

#include <osg/ApplicationUsage>
#include <osg/ArgumentParser>
#include <osg/Plane>
#include <osg/Vec3d>
#include <osg/Vec4>

#include <string>
#include <vector>

/** The program's name in messages. */
extern const char* const PROGRAM;

/** The longest wait for paged tiles before a picture is written anyway. */
const double PAGING_TIMEOUT_SECONDS = 120.0;

/** The clip planes --clip may give: OSG's and every GL implementation's (GL_MAX_CLIP_PLANES >= 8). */
extern const unsigned int MAX_CLIP_PLANES;

/** A camera placed by eye, centre and up vector. */
struct CameraView
{
    osg::Vec3d eye;
    osg::Vec3d center;
    osg::Vec3d up = osg::Vec3d(0.0, 0.0, 1.0);
};

/** Everything the command line sets. */
struct ViewerOptions
{
    // Input
    std::string file;
    std::string format;
    std::vector<std::string> datasets; // --dataset PATH (repeatable): HDF5 datasets, positions first
    std::string topology;              // --topology FILE: the atoms' names, types, elements of a trajectory
    unsigned int frame = 0;
    unsigned int randomCount = 0; // --random N; 0: no random dataset
    unsigned int seed = 1;
    bool follow = false;         // --follow: re-read the growing file, show frames as they complete
    double followTimeout = 60.0; // --follow-timeout S: offscreen, the longest wait for a frame
    std::size_t glyphBudget = 0; // tile archives; 0: the archive's own

    osgGlyphsData::GlyphMappingOptions mapping;
    PlaybackOptions playback; // trajectories: --play, --fps, --interpolate, --frame-range, --movie
    BondOptions bonds;        // --bond-cutoff, --bond-radius

    // View
    int width = 800;
    int height = 600;
    bool hasCamera = false;
    CameraView camera;
    double fov = 30.0;
    osg::Vec4 background = osg::Vec4(1.0f, 1.0f, 1.0f, 1.0f);
    std::vector<osg::Plane> clipPlanes; // --clip A B C D: keep A x + B y + C z + D >= 0
    bool clipCaps = false;
    bool shadows = false;             // --shadows: a shadowed scene with a ground plane
    bool ambientOcclusion = false;    // --ao: ambient occlusion, of the kind effects.aoMode says
    ScreenEffectsOptions effects;     // --ao-mode, --ao-radius, --outline
    TransparencyOptions transparency; // --opacity, --peel-layers

    // Output
    bool offscreen = false;
    osgGlyphsHeadless::HeadlessBackend backend = osgGlyphsHeadless::HeadlessBackend::Default;
    /** --egl-device; -1: OSGGLYPHS_EGL_DEVICE, else the MPI local rank, else the first device. */
    int eglDevice = -1;
    std::string output;
    std::string depthOutput;
    unsigned int frames = 0; // --frames K; 0: one frame headless, run until closed in a window
    bool hasPick = false;    // --pick PX PY: the glyph under that pixel, counted from the top left
    int pickX = 0;
    int pickY = 0;
};

/** Lists every option and the keys of the window in usage. */
void describeViewerOptions(osg::ApplicationUsage& usage);

/** Reads every option from arguments, then the file name. Returns false with a one-line error
 * on a bad value, an unknown option or a contradiction. */
bool readViewerOptions(osg::ArgumentParser& arguments, ViewerOptions& options, std::string& error);

#endif
