// The hostile corpus of tests/fuzz/corpus, the fuzz targets' seeds, read as a user would.

#include "AllocationMeter.h"

#include <osgGlyphsData/GlyphMapping>
#include <osgGlyphsData/PointReader>

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

using hostiletest::AllocationMeter;
using hostiletest::MiB;

// Every file of the hostile corpus (the fuzz targets' seeds) reads, or fails in one line naming
// it, within the memory cap, and the frames it gives map to glyphs or fail in one line.
TEST(HostileCorpus, EveryFileReadsOrFailsInOneLine)
{
    std::size_t files = 0;
    for (const auto& folder : std::filesystem::directory_iterator(OSGGLYPHS_HOSTILE_CORPUS_DIR))
    {
        if (!folder.is_directory())
            continue;
        for (const auto& entry : std::filesystem::directory_iterator(folder.path()))
        {
            const std::string path = entry.path().string();
            SCOPED_TRACE(path);
            ++files;
            osgGlyphsData::PointReadOptions options;
            options.format = folder.path().filename().string();
            std::vector<std::string> warnings;
            options.warning = [&warnings](const std::string& warning) { warnings.push_back(warning); };
            std::string error;
            AllocationMeter meter(256 * MiB);
            osg::ref_ptr<osgGlyphsData::PointDataset> dataset =
                osgGlyphsData::readPointFile(path, options, error);
            EXPECT_FALSE(meter.wasCapReached());
            for (const std::string& message : warnings)
                EXPECT_TRUE(message.find('\n') == std::string::npos &&
                            message.compare(0, path.size(), path) == 0)
                    << message;
            if (dataset.valid())
            {
                ASSERT_GT(dataset->getNumFrames(), 0u);
                osgGlyphsData::GlyphMapper mapper{osgGlyphsData::GlyphMappingOptions()};
                if (mapper.prepare(*dataset, 0, error))
                {
                    for (const auto& frame : dataset->getFrames())
                        mapper.createCloud(*frame, error);
                }
            }
            EXPECT_EQ(error.find('\n'), std::string::npos) << error;
            EXPECT_TRUE(error.empty() || error.find(path) != std::string::npos) << error;
        }
    }
    EXPECT_GE(files, 20u);
}
