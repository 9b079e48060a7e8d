#include "ViewerOptions.h"

#include "ViewerText.h"

#include <osgGlyphsData/PointReader>

#include <osgGlyphsData/FrameSource>

#include <osgDB/FileUtils>

#include <cstdlib>
#include <iostream>
#include <sstream>

const char* const PROGRAM = "osgglyphviewer";

const unsigned int MAX_CLIP_PLANES = 8;

namespace
{

/** Reads "option v1 .. vn" of n numbers, which osg::ArgumentParser cannot do beyond eight. */
bool readNumbers(osg::ArgumentParser& arguments, const std::string& option, std::vector<double>& values,
                 bool& found, std::string& error)
{
    found = false;
    const int pos = arguments.find(option);
    if (pos < 0)
        return true;
    found = true;
    const int count = static_cast<int>(values.size());
    for (int i = 0; i < count; ++i)
    {
        if (pos + 1 + i >= arguments.argc() || !arguments.isNumber(pos + 1 + i))
        {
            error = option + " needs " + std::to_string(count) + " numbers";
            return false;
        }
        values[i] = std::atof(arguments[pos + 1 + i]);
    }
    arguments.remove(pos, count + 1);
    return true;
}

/** The errors osg::ArgumentParser collected, on one line, without its program-name prefix. */
std::string collectParserErrors(osg::ArgumentParser& arguments)
{
    const std::string prefix = arguments.getApplicationName() + ": ";
    std::string message;
    for (const auto& entry : arguments.getErrorMessageMap())
    {
        std::string text = entry.first;
        if (text.compare(0, prefix.size(), prefix) == 0)
            text.erase(0, prefix.size());
        message += (message.empty() ? "" : "; ") + text;
    }
    return message + " (see --help)";
}

bool readMappingOptions(osg::ArgumentParser& arguments, ViewerOptions& options, std::string& error)
{
    osgGlyphsData::GlyphMappingOptions& mapping = options.mapping;
    if (!osgGlyphsData::readGlyphMappingArguments(arguments, mapping, error))
        return false;
    const osg::ref_ptr<osgGlyphs::GlyphTechnique> technique = osgGlyphs::createTechnique(mapping.technique);
    if (!technique->supportsShape(mapping.shape))
        std::cerr << PROGRAM << ": warning: the " << technique->getTechniqueName()
                  << " technique cannot draw " << osgGlyphs::getShapeName(mapping.shape)
                  << "s; they are drawn with " << osgGlyphs::DEFAULT_GLYPH_TECHNIQUE << std::endl;
    return true;
}

bool readInputOptions(osg::ArgumentParser& arguments, ViewerOptions& options, std::string& error)
{
    arguments.read("--format", options.format);
    arguments.read("--topology", options.topology);
    for (std::string dataset; arguments.read("--dataset", dataset);)
        options.datasets.push_back(dataset);
    int value = 0;
    if (arguments.read("--frame", value))
    {
        if (value < 0)
        {
            error = "--frame counts from 0";
            return false;
        }
        options.frame = static_cast<unsigned int>(value);
    }
    if (arguments.read("--random", value))
    {
        if (value <= 0)
        {
            error = "--random needs a positive number of glyphs";
            return false;
        }
        options.randomCount = static_cast<unsigned int>(value);
    }
    if (arguments.read("--seed", value))
        options.seed = static_cast<unsigned int>(value);
    while (arguments.read("--follow"))
        options.follow = true;
    if (arguments.read("--follow-timeout", options.followTimeout) && !(options.followTimeout > 0.0))
    {
        error = "--follow-timeout needs a positive number of seconds";
        return false;
    }
    double budget = 0.0;
    if (arguments.read("--glyph-budget", budget))
    {
        if (!(budget >= 1.0 && budget <= 1e12))
        {
            error = "--glyph-budget needs a number of glyphs from 1 to 1e12";
            return false;
        }
        options.glyphBudget = static_cast<std::size_t>(budget);
    }
    return true;
}

bool readViewOptions(osg::ArgumentParser& arguments, ViewerOptions& options, std::string& error)
{
    if (arguments.read("--size", options.width, options.height) &&
        (options.width <= 0 || options.height <= 0 || options.width > 16384 || options.height > 16384))
    {
        error = "--size: width and height must be between 1 and 16384";
        return false;
    }
    std::vector<double> camera(9);
    if (!readNumbers(arguments, "--camera", camera, options.hasCamera, error))
        return false;
    if (options.hasCamera)
    {
        options.camera.eye.set(camera[0], camera[1], camera[2]);
        options.camera.center.set(camera[3], camera[4], camera[5]);
        options.camera.up.set(camera[6], camera[7], camera[8]);
        if ((options.camera.center - options.camera.eye).length2() == 0.0 ||
            options.camera.up.length2() == 0.0)
        {
            error = "--camera: the eye must differ from the centre and the up vector must not be zero";
            return false;
        }
    }
    if (arguments.read("--fov", options.fov) && !(options.fov > 0.0 && options.fov < 180.0))
    {
        error = "--fov: the vertical field of view must be between 0 and 180 degrees";
        return false;
    }
    for (bool found = true; found;)
    {
        std::vector<double> plane(4);
        if (!readNumbers(arguments, "--clip", plane, found, error))
            return false;
        if (!found)
            break;
        if (plane[0] == 0.0 && plane[1] == 0.0 && plane[2] == 0.0)
        {
            error = "--clip: the plane's normal (A B C) must not be zero";
            return false;
        }
        if (options.clipPlanes.size() == MAX_CLIP_PLANES)
        {
            error = "--clip: at most " + std::to_string(MAX_CLIP_PLANES) + " planes";
            return false;
        }
        options.clipPlanes.emplace_back(plane[0], plane[1], plane[2], plane[3]);
    }
    while (arguments.read("--clip-cap"))
        options.clipCaps = true;
    while (arguments.read("--shadows"))
        options.shadows = true;
    while (arguments.read("--ao"))
        options.ambientOcclusion = true;
    if (!readScreenEffectsOptions(arguments, options.effects, options.ambientOcclusion, error) ||
        !readTransparencyOptions(arguments, options.transparency, error))
        return false;
    float r = 0.0f, g = 0.0f, b = 0.0f;
    if (arguments.read("--background", r, g, b))
    {
        if (r < 0.0f || r > 1.0f || g < 0.0f || g > 1.0f || b < 0.0f || b > 1.0f)
        {
            error = "--background: red, green and blue go from 0 to 1";
            return false;
        }
        options.background.set(r, g, b, 1.0f);
    }
    return true;
}

bool readOutputOptions(osg::ArgumentParser& arguments, ViewerOptions& options, std::string& error)
{
    while (arguments.read("--offscreen"))
        options.offscreen = true;
    std::string backend;
    if (arguments.read("--headless", backend))
    {
        if (!osgGlyphsHeadless::parseHeadlessBackend(backend, options.backend))
        {
            error = "--headless '" + backend + "': unknown backend (egl, osmesa, default)";
            return false;
        }
        options.offscreen = true;
    }
    std::string device;
    if (arguments.read("--egl-device", device))
    {
        char* end = nullptr;
        const long index = std::strtol(device.c_str(), &end, 10);
        if (device.empty() || *end != '\0' || index < 0 || index > 4096)
        {
            error = "--egl-device '" + device + "': not a device index (0, 1, ...)";
            return false;
        }
        options.eglDevice = static_cast<int>(index);
        options.offscreen = true;
    }
    if (arguments.read("--output", options.output))
        options.offscreen = true;
    if (arguments.read("--depth-output", options.depthOutput))
        options.offscreen = true;
    int frames = 0;
    if (arguments.read("--frames", frames))
    {
        if (frames <= 0)
        {
            error = "--frames needs a positive number of frames";
            return false;
        }
        options.frames = static_cast<unsigned int>(frames);
    }
    if (arguments.read("--pick", options.pickX, options.pickY))
    {
        options.hasPick = true;
        if (options.pickX < 0 || options.pickY < 0 || options.pickX >= options.width ||
            options.pickY >= options.height)
        {
            error = "--pick " + std::to_string(options.pickX) + " " + std::to_string(options.pickY) +
                    ": not a pixel of the " + std::to_string(options.width) + "x" +
                    std::to_string(options.height) + " image";
            return false;
        }
    }
    return true;
}

}

void describeViewerOptions(osg::ApplicationUsage& usage)
{
    const std::string formats = joinNames(osgGlyphsData::getSupportedPointFormats());
    usage.addCommandLineOption("<file>",
                               "A point file: " + formats +
                                   " (by extension). Without a file or --random, a built-in scene.");
    usage.addCommandLineOption("--format <name>",
                               "Read the file as this format (" + formats + ") whatever its extension.");
    usage.addCommandLineOption(
        "--topology <file>",
        "The atoms of a trajectory that holds only coordinates (DCD, XTC, TRR): a PDB, GRO or LAMMPS data "
        "file (write_data, its atoms sorted by id), or any point file, whose first frame gives every frame "
        "the columns it lacks (id, name, residue, type, species, element, mass, charge, ...), atom by atom "
        "in file order. Its atom count must be the trajectory's.");
    usage.addCommandLineOption(
        "--dataset <path>", "Of an HDF5 file, a dataset to read (repeatable): the positions first (N x 3), "
                            "then columns (N or N x k). Without it, H5MD and snapshots are read whole.");
    usage.addCommandLineOption("--frame <n>", "The frame of a multi-frame file to show, counted from 0 "
                                              "(default 0). Keys n and p step through the others.");
    usage.addCommandLineOption("--random <n>", "Instead of a file, the random dataset of Aguirre et al. "
                                               "(TPCG 2010): n glyphs in the unit cube, scalars in [0,1).");
    usage.addCommandLineOption("--seed <s>", "The seed of --random (default 1).");
    usage.addCommandLineOption("--glyph-budget <n>",
                               "A tile archive of osgglyphconvert (.osga): the most glyphs a frame draws; "
                               "tiles refine, largest on screen first, within it (default: the archive's, "
                               "2000000 unless osgglyphconvert --glyph-budget set another).");

    osgGlyphsData::describeGlyphMappingArguments(usage);
    describePlaybackOptions(usage);
    describeBondOptions(usage);

    usage.addCommandLineOption("--size <w> <h>", "Window or image size in pixels (default 800 600).");
    usage.addCommandLineOption("--camera <ex> <ey> <ez> <cx> <cy> <cz> <ux> <uy> <uz>",
                               "Look from eye e at centre c with up vector u (default: frame the data).");
    usage.addCommandLineOption("--fov <degrees>", "Vertical field of view (default 30).");
    usage.addCommandLineOption("--background <r> <g> <b>", "Background colour, 0..1 (default 1 1 1).");
    usage.addCommandLineOption("--clip <A> <B> <C> <D>",
                               "Cut the glyphs, keeping A*x + B*y + C*z + D >= 0 in data coordinates "
                               "(osg::ClipPlane's convention); repeat for up to 8 planes.");
    usage.addCommandLineOption("--clip-cap", "Cap the cuts of --clip: cut glyphs show a solid face in the "
                                             "plane, as a sliced solid does.");
    usage.addCommandLineOption(
        "--ao", "Ambient occlusion per glyph: each glyph darkened by the neighbours around it, "
                "computed once per frame of data on the CPU (GlyphCloud::computeOcclusion); "
                "key o toggles it. See --ao-mode for screen-space occlusion.");
    describeScreenEffectsOptions(usage);
    describeTransparencyOptions(usage);
    usage.addCommandLineOption("--shadows",
                               "Cast shadows (osgShadow's ViewDependentShadowMap) from a light above "
                               "(+z) onto a ground plane under the data and onto the glyphs.");

    usage.addCommandLineOption("--offscreen", "Render without a display, through EGL (a GPU, else Mesa's "
                                              "software renderer) unless --headless says otherwise, instead "
                                              "of opening a window. Prints the renderer used.");
    usage.addCommandLineOption("--headless <egl|osmesa|default>",
                               "The GL backend of --offscreen; implies --offscreen. default: "
                               "OSGGLYPHS_HEADLESS, else EGL, else OSMesa (which needs "
                               "LD_PRELOAD=libOSMesa.so.8).");
    usage.addCommandLineOption("--egl-device <n>",
                               "The EGL device (GPU) to render on; implies --offscreen. Default: "
                               "OSGGLYPHS_EGL_DEVICE, else under mpirun the rank's local index modulo "
                               "the devices, else the first.");
    usage.addCommandLineOption("--output <file.png>", "Write the rendered image; implies --offscreen. With "
                                                      "--frame-range, a pattern such as out%04d.png.");
    usage.addCommandLineOption("--depth-output <file.pfm>",
                               "Write eye-space depth (distance from the eye plane along the view "
                               "direction) as float PFM, rows bottom to top, background +inf; implies "
                               "--offscreen.");
    usage.addCommandLineOption("--frames <k>", "Render k frames, turning the camera 1 degree about the "
                                               "centre each frame, print 'frame_ms median=.. min=.. max=..' "
                                               "and exit (in a window too).");
    usage.addCommandLineOption(
        "--follow", "Watch a dump that is still being written: a last frame half written is "
                    "left out, and frames are added as they complete (the file is read again "
                    "four times a second). In a window, the newest frame is shown while you are on the last "
                    "one. Offscreen, each new frame is rendered (and --output rewritten) until "
                    "--frames k pictures are made.");
    usage.addCommandLineOption("--follow-timeout <s>",
                               "Offscreen --follow: give up when no new frame completes for s seconds "
                               "(default 60).");
    usage.addCommandLineOption("--pick <px> <py>",
                               "With --offscreen: after rendering, print 'pick glyph=<index> x=<x> y=<y> "
                               "z=<z>', the glyph under pixel (px, py) of the image counted from its top "
                               "left corner (its index in the file's frame) and the world point of its "
                               "surface there, or 'pick none'. In a window, a click (without a drag) picks.");
    usage.addCommandLineOption("-h or --help", "Display this help: options and keys.");
}

bool readViewerOptions(osg::ArgumentParser& arguments, ViewerOptions& options, std::string& error)
{
    if (!readInputOptions(arguments, options, error) || !readMappingOptions(arguments, options, error) ||
        !readViewOptions(arguments, options, error) || !readOutputOptions(arguments, options, error) ||
        !readPlaybackOptions(arguments, options.playback, error) ||
        !readBondOptions(arguments, options.bonds, error))
        return false;
    if (options.playback.hasFrameRange || !options.playback.movie.empty())
        options.offscreen = true;

    arguments.reportRemainingOptionsAsUnrecognized();
    if (arguments.errors())
    {
        error = collectParserErrors(arguments);
        return false;
    }
    std::vector<std::string> files;
    for (int pos = 1; pos < arguments.argc(); ++pos)
    {
        if (!arguments.isOption(pos))
            files.push_back(arguments[pos]);
    }
    if (files.size() > 1)
    {
        error = "one file at a time, not " + joinNames(files, " ");
        return false;
    }
    if (!files.empty())
        options.file = files.front();
    if (!options.file.empty() && options.randomCount > 0)
    {
        error = "give a file or --random, not both";
        return false;
    }
    if (!options.topology.empty() && options.file.empty())
    {
        error = "--topology needs a file of frames";
        return false;
    }
    if (options.follow && options.file.empty())
    {
        error = "--follow needs a file";
        return false;
    }
    if ((options.bonds.enabled() || options.bonds.required) && options.file.empty())
    {
        error = std::string(options.bonds.required ? "--bonds" : "--bond-cutoff") + " needs a file of atoms";
        return false;
    }
    const PlaybackOptions& playback = options.playback;
    if ((playback.hasFrameRange || !playback.movie.empty()) && options.file.empty())
    {
        error = std::string(playback.movie.empty() ? "--frame-range" : "--movie") + " needs a file of frames";
        return false;
    }
    if (playback.hasFrameRange && playback.movie.empty() && options.output.find('%') == std::string::npos)
    {
        error = "--frame-range writes a picture per frame: give --output a pattern such as out%04d.png, or "
                "--movie";
        return false;
    }
    if (!playback.movie.empty() && !options.output.empty() && options.output.find('%') == std::string::npos)
    {
        error = "--output with --movie writes every picture too: give it a pattern such as out%04d.png";
        return false;
    }
    std::string name;
    if (!osgGlyphsData::formatFramePath(options.output, 0, name))
    {
        error = "--output '" + options.output + "': a pattern holds one integer conversion, such as %04d";
        return false;
    }
    if ((playback.hasFrameRange || !playback.movie.empty()) && (options.follow || options.frames > 0))
    {
        error = "--frame-range and --movie render the frames of the file; they do not combine with " +
                std::string(options.follow ? "--follow" : "--frames");
        return false;
    }
    if (options.hasPick && !options.offscreen)
    {
        error = "--pick needs --offscreen (in a window, click to pick)";
        return false;
    }
    return true;
}
