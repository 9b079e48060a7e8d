// Files of many frames: what a reading holds is bounded by the data it returns, measured by the
// bytes operator new hands out (AllocationMeter), not by timing or RSS.

#include "AllocationMeter.h"

#include <osgGlyphsData/PointReader>

#include <gtest/gtest.h>

#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using hostiletest::AllocationMeter;
using hostiletest::MiB;

// 100,000 frames without atoms hold no memory: they are left out (with one warning).
TEST(FrameMemory, EmptyFramesHoldNothing)
{
    std::string xyz = "1\n\nH 0 0 0\n";
    for (int i = 0; i < 100000; ++i)
        xyz += "0\n\n";
    std::string lammps = "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n1\nITEM: ATOMS id x y z\n1 0 0 0\n";
    for (int i = 0; i < 20000; ++i)
        lammps +=
            "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n0\nITEM: BOX BOUNDS pp pp pp\n0 1\n0 1\n0 1\nITEM: "
            "ATOMS id x y z\n";
    for (const auto& file :
         {std::make_pair(std::string("xyz"), &xyz), std::make_pair(std::string("lammps"), &lammps)})
    {
        std::istringstream stream(*file.second);
        std::vector<std::string> warnings;
        osgGlyphsData::PointReadOptions options;
        options.warning = [&warnings](const std::string& warning) { warnings.push_back(warning); };
        std::string error;
        AllocationMeter meter(256 * MiB);
        osg::ref_ptr<osgGlyphsData::PointDataset> dataset =
            osgGlyphsData::readPointStream(stream, file.first, "empty", options, error);
        ASSERT_TRUE(dataset.valid()) << error;
        EXPECT_EQ(dataset->getNumFrames(), 1u);
        EXPECT_EQ(warnings.size(), 1u);
        EXPECT_LT(meter.getBytesInUse(), 64 << 10) << file.first; // the one frame and the warning
        EXPECT_LT(meter.getPeakBytes(), 4 * MiB) << file.first;   // and a block of the file
    }
}

// Many small frames: the reading at most holds a small multiple of what it returns.
TEST(FrameMemory, PeakStaysNearWhatTheDatasetHolds)
{
    std::string lammps;
    for (int i = 0; i < 20000; ++i)
        lammps +=
            "ITEM: TIMESTEP\n" + std::to_string(i) +
            "\nITEM: NUMBER OF ATOMS\n1\nITEM: BOX BOUNDS pp pp pp\n0 1\n0 1\n0 1\nITEM: ATOMS id type x y "
            "z\n1 1 0.5 0.5 0.5\n";
    std::istringstream stream(lammps);
    std::string error;
    AllocationMeter meter(1024 * MiB);
    osg::ref_ptr<osgGlyphsData::PointDataset> dataset =
        osgGlyphsData::readPointStream(stream, "lammps", "small", osgGlyphsData::PointReadOptions(), error);
    ASSERT_TRUE(dataset.valid()) << error;
    ASSERT_EQ(dataset->getNumFrames(), 20000u);
    const std::ptrdiff_t held = meter.getBytesInUse();
    EXPECT_LT(meter.getPeakBytes(), 2 * held + 4 * static_cast<std::ptrdiff_t>(MiB));
    std::cout << "20000 frames of one atom: " << held / 20000 << " bytes a frame held, peak "
              << meter.getPeakBytes() / 1024 << " KiB, file " << lammps.size() / 1024 << " KiB" << std::endl;
}
