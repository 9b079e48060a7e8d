#include "EGLDeviceList.h"

#include <algorithm>
#include <cerrno>
#include <cstdlib>

using namespace osgGlyphsHeadless;

namespace
{

/** Parses a whole non-negative decimal integer; false for anything else. */
bool parseIndex(const char* text, int& index)
{
    if (!text || *text == '\0')
        return false;
    char* end = nullptr;
    errno = 0;
    const long value = std::strtol(text, &end, 10);
    if (*end != '\0' || errno != 0 || value < 0 || value > 1 << 20)
        return false;
    index = static_cast<int>(value);
    return true;
}

std::string countOfDevices(int deviceCount)
{
    return std::to_string(deviceCount) + (deviceCount == 1 ? " EGL device" : " EGL devices");
}

EGLDeviceChoice explicitChoice(int index, int deviceCount, const std::string& reason)
{
    EGLDeviceChoice choice;
    if (index >= deviceCount)
        choice.error = reason + " is not a device: there " + (deviceCount == 1 ? "is " : "are ") +
                       countOfDevices(deviceCount);
    else
        choice.index = index, choice.reason = reason;
    return choice;
}

} // namespace

std::string EGLDeviceDescription::describe() const
{
    std::string text = std::to_string(index) + ": ";
    if (!drmDeviceFile.empty())
        text += drmDeviceFile;
    else if (extensions.find("EGL_MESA_device_software") != std::string::npos)
        text += "Mesa's software renderer";
    else
        text += extensions.substr(0, extensions.find(' '));
    if (!renderer.empty())
        text += " (" + renderer + ")";
    return text;
}

const char* osgGlyphsHeadless::getEGLDeviceVariable()
{
    return "OSGGLYPHS_EGL_DEVICE";
}

const std::vector<std::string>& osgGlyphsHeadless::getLocalRankVariables()
{
    static const std::vector<std::string> variables = {"OMPI_COMM_WORLD_LOCAL_RANK", "MPI_LOCALRANKID",
                                                       "MV2_COMM_WORLD_LOCAL_RANK",  "SLURM_LOCALID",
                                                       "PALS_LOCAL_RANKID",          "FLUX_TASK_LOCAL_ID"};
    return variables;
}

EGLDeviceChoice osgGlyphsHeadless::chooseEGLDevice(int deviceCount, int requested,
                                                   const EnvironmentLookup& environment)
{
    const EnvironmentLookup lookup =
        environment ? environment : [](const char* name) { return std::getenv(name); };
    if (deviceCount <= 0)
    {
        EGLDeviceChoice none;
        none.error = "EGL offers no device";
        return none;
    }
    if (requested >= 0)
        return explicitChoice(requested, deviceCount, "device " + std::to_string(requested) + " (requested)");

    if (const char* value = lookup(getEGLDeviceVariable()))
    {
        const std::string reason = std::string(getEGLDeviceVariable()) + "=" + value;
        int index = 0;
        if (!parseIndex(value, index))
        {
            EGLDeviceChoice choice;
            choice.error = reason + " is not a device index (0, 1, ...)";
            return choice;
        }
        return explicitChoice(index, deviceCount, reason);
    }

    for (const std::string& variable : getLocalRankVariables())
    {
        int rank = 0;
        if (parseIndex(lookup(variable.c_str()), rank))
        {
            EGLDeviceChoice choice;
            choice.index = rank % deviceCount;
            choice.reason =
                "local rank " + variable + "=" + std::to_string(rank) + " of " + countOfDevices(deviceCount);
            return choice;
        }
    }

    EGLDeviceChoice first;
    first.index = 0;
    first.reason = "the first of " + countOfDevices(deviceCount);
    return first;
}

bool detail::hasEGLClientExtension(const char* extension)
{
    const char* extensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!extensions)
        return false;
    const std::string list = std::string(" ") + extensions + " ";
    return list.find(std::string(" ") + extension + " ") != std::string::npos;
}

std::vector<EGLDeviceEXT> detail::queryEGLDevices()
{
    if (!hasEGLClientExtension("EGL_EXT_device_enumeration") && !hasEGLClientExtension("EGL_EXT_device_base"))
        return {};
    auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    EGLint count = 0;
    if (!queryDevices || !queryDevices(0, nullptr, &count) || count <= 0)
        return {};
    std::vector<EGLDeviceEXT> devices(static_cast<size_t>(std::min<EGLint>(count, 256)));
    if (!queryDevices(static_cast<EGLint>(devices.size()), devices.data(), &count))
        return {};
    devices.resize(static_cast<size_t>(std::max<EGLint>(0, std::min<EGLint>(count, devices.size()))));
    return devices;
}

std::vector<EGLDeviceDescription> osgGlyphsHeadless::listEGLDevices()
{
    auto queryString =
        reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(eglGetProcAddress("eglQueryDeviceStringEXT"));
    auto text = [queryString](EGLDeviceEXT device, EGLint name) -> std::string
    {
        const char* value = queryString ? queryString(device, name) : nullptr;
        eglGetError(); // A name the driver does not know leaves EGL_BAD_PARAMETER behind.
        return value ? value : "";
    };
    std::vector<EGLDeviceDescription> descriptions;
    const std::vector<EGLDeviceEXT> devices = detail::queryEGLDevices();
    for (size_t i = 0; i < devices.size(); ++i)
    {
        EGLDeviceDescription description;
        description.index = static_cast<int>(i);
        description.extensions = text(devices[i], EGL_EXTENSIONS);
        if (description.extensions.find("EGL_EXT_device_drm") != std::string::npos)
            description.drmDeviceFile = text(devices[i], EGL_DRM_DEVICE_FILE_EXT);
        if (description.extensions.find("EGL_EXT_device_query_name") != std::string::npos)
            description.renderer = text(devices[i], EGL_RENDERER_EXT);
        descriptions.push_back(description);
    }
    return descriptions;
}
