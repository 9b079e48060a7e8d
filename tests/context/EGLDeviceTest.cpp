// The choice of an EGL device: by request, by OSGGLYPHS_EGL_DEVICE, by an MPI launcher's local
// rank, and the errors for a device that does not exist. Then the same through real contexts on
// Mesa's software device, the one device this machine has.

#include "RenderHarness.h"

#include <osgGlyphsHeadless/EGLDevices>
#include <osgGlyphsHeadless/HeadlessContext>

#include <cstdlib>
#include <map>

using namespace osgGlyphsHeadless;

namespace
{

/** An environment of the given variables only. */
EnvironmentLookup environmentOf(std::map<std::string, std::string> variables)
{
    return [variables = std::move(variables)](const char* name) -> const char*
    {
        auto found = variables.find(name);
        return found == variables.end() ? nullptr : found->second.c_str();
    };
}

/** Sets an environment variable for the lifetime of the object. */
class ScopedVariable
{
public:
    ScopedVariable(const char* name, const char* value) : _name(name) { setenv(name, value, 1); }
    ~ScopedVariable() { unsetenv(_name); }

private:
    const char* _name;
};

} // namespace

TEST(EGLDeviceChoice, FirstDeviceWithoutAnyHint)
{
    const EGLDeviceChoice choice = chooseEGLDevice(3, -1, environmentOf({}));
    EXPECT_EQ(choice.index, 0);
    EXPECT_EQ(choice.reason, "the first of 3 EGL devices");
}

TEST(EGLDeviceChoice, RequestWinsOverEnvironmentAndRank)
{
    const EGLDeviceChoice choice = chooseEGLDevice(
        4, 2, environmentOf({{"OSGGLYPHS_EGL_DEVICE", "1"}, {"OMPI_COMM_WORLD_LOCAL_RANK", "3"}}));
    EXPECT_EQ(choice.index, 2);
}

TEST(EGLDeviceChoice, EnvironmentVariableWinsOverRank)
{
    const EGLDeviceChoice choice = chooseEGLDevice(
        4, -1, environmentOf({{"OSGGLYPHS_EGL_DEVICE", "1"}, {"OMPI_COMM_WORLD_LOCAL_RANK", "3"}}));
    EXPECT_EQ(choice.index, 1);
    EXPECT_EQ(choice.reason, "OSGGLYPHS_EGL_DEVICE=1");
}

TEST(EGLDeviceChoice, LocalRankSpreadsRanksOverDevices)
{
    for (const std::string& variable : getLocalRankVariables())
    {
        for (int rank = 0; rank < 7; ++rank)
        {
            const EGLDeviceChoice choice =
                chooseEGLDevice(3, -1, environmentOf({{variable, std::to_string(rank)}}));
            EXPECT_EQ(choice.index, rank % 3) << variable << "=" << rank;
            EXPECT_NE(choice.reason.find(variable), std::string::npos) << choice.reason;
        }
    }
}

TEST(EGLDeviceChoice, OpenMPIsRankIsConsultedFirst)
{
    const EGLDeviceChoice choice =
        chooseEGLDevice(8, -1, environmentOf({{"SLURM_LOCALID", "5"}, {"OMPI_COMM_WORLD_LOCAL_RANK", "2"}}));
    EXPECT_EQ(choice.index, 2);
}

TEST(EGLDeviceChoice, RequestOutOfRangeIsAnError)
{
    const EGLDeviceChoice choice = chooseEGLDevice(2, 2, environmentOf({}));
    EXPECT_FALSE(choice.valid());
    EXPECT_EQ(choice.error, "device 2 (requested) is not a device: there are 2 EGL devices");
}

TEST(EGLDeviceChoice, EnvironmentOutOfRangeOrGarbageIsAnError)
{
    EGLDeviceChoice choice = chooseEGLDevice(1, -1, environmentOf({{"OSGGLYPHS_EGL_DEVICE", "1"}}));
    EXPECT_FALSE(choice.valid());
    EXPECT_EQ(choice.error, "OSGGLYPHS_EGL_DEVICE=1 is not a device: there is 1 EGL device");
    for (const char* garbage : {"", "-1", "one", "1x", "99999999999999999999"})
    {
        choice = chooseEGLDevice(4, -1, environmentOf({{"OSGGLYPHS_EGL_DEVICE", garbage}}));
        EXPECT_FALSE(choice.valid()) << garbage;
        EXPECT_NE(choice.error.find("is not a device index"), std::string::npos) << choice.error;
    }
}

TEST(EGLDeviceChoice, NoDeviceIsAnError)
{
    const EGLDeviceChoice choice = chooseEGLDevice(0, -1, environmentOf({}));
    EXPECT_FALSE(choice.valid());
    EXPECT_EQ(choice.error, "EGL offers no device");
}

TEST(EGLDeviceChoice, UnparsableRankFallsThroughToTheNextVariable)
{
    const EGLDeviceChoice choice =
        chooseEGLDevice(4, -1, environmentOf({{"OMPI_COMM_WORLD_LOCAL_RANK", "x"}, {"SLURM_LOCALID", "3"}}));
    EXPECT_EQ(choice.index, 3);
}

TEST(EGLDevices, MesaOffersItsSoftwareDevice)
{
    const std::vector<EGLDeviceDescription> devices = listEGLDevices();
    ASSERT_FALSE(devices.empty());
    EXPECT_NE(devices[0].extensions.find("EGL_MESA_device_software"), std::string::npos)
        << devices[0].extensions;
    EXPECT_EQ(devices[0].describe(), "0: Mesa's software renderer");
}

TEST(EGLDevices, ContextOnTheChosenDevice)
{
    ScopedVariable rank("OMPI_COMM_WORLD_LOCAL_RANK", "2");
    osg::ref_ptr<HeadlessContext> context = HeadlessContext::create(8, 8, HeadlessBackend::EGL);
    ASSERT_TRUE(context.valid());
    EXPECT_TRUE(context->isRealized());
    const HeadlessRendererInfo& info = context->getRendererInfo();
    EXPECT_EQ(info.platform.rfind("EGL device 0: Mesa's software renderer of 1", 0), 0u) << info.platform;
    EXPECT_NE(info.platform.find("OMPI_COMM_WORLD_LOCAL_RANK=2"), std::string::npos) << info.platform;
    EXPECT_FALSE(info.vendor.empty());
}

TEST(EGLDevices, RequestedDeviceThatDoesNotExistFailsWithoutFallingBack)
{
    for (HeadlessBackend backend : {HeadlessBackend::EGL, HeadlessBackend::Default})
    {
        std::string error;
        EXPECT_FALSE(HeadlessContext::create(8, 8, backend, 7, &error).valid());
        EXPECT_EQ(error, "device 7 (requested) is not a device: there is 1 EGL device");
    }
}

TEST(EGLDevices, EnvironmentVariableThatNamesNoDeviceFails)
{
    ScopedVariable device("OSGGLYPHS_EGL_DEVICE", "3");
    std::string error;
    EXPECT_FALSE(HeadlessContext::create(8, 8, HeadlessBackend::Default, -1, &error).valid());
    EXPECT_EQ(error, "OSGGLYPHS_EGL_DEVICE=3 is not a device: there is 1 EGL device");
}

TEST(EGLDevices, EnvironmentVariableChoosesTheDevice)
{
    ScopedVariable device("OSGGLYPHS_EGL_DEVICE", "0");
    osgGlyphsTest::Renderer renderer(8, 8);
    ASSERT_TRUE(renderer.getViewer()->valid());
    EXPECT_NE(renderer.getViewer()->getContext()->getRendererInfo().platform.find("OSGGLYPHS_EGL_DEVICE=0"),
              std::string::npos);
}
