// osgGlyphsMovie::MovieWriter: movies of synthetic frames, read back by FFmpeg's command-line tools
// (ffprobe for the stream, ffmpeg for the pixels). Each frame's top half has another colour than its
// bottom half, and both change from frame to frame: the decoded pixels prove the row order and the
// frame order. The checks through the tools are skipped where ffprobe or ffmpeg is not installed.

#include <osgGlyphsMovie/MovieWriter>

#include <gtest/gtest.h>

#include <osg/Image>
#include <osg/ref_ptr>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#ifndef OSGGLYPHS_MOVIE_TEST_DIR
#define OSGGLYPHS_MOVIE_TEST_DIR "movie_test_output"
#endif

using osgGlyphsMovie::MovieOptions;
using osgGlyphsMovie::MovieWriter;

namespace
{

using Colour = std::array<int, 3>;

const int NumFrames = 12;
// Lossy YUV 4:2:0 of flat colours stays well within this; the colours of neighbouring frames differ
// by 15 in one channel and those of the two halves by far more.
const int ColourTolerance = 7;

Colour topColour(int frame)
{
    return {220, 20 + 15 * frame, 40};
}
Colour bottomColour(int frame)
{
    return {30, 200 - 15 * frame, 210};
}

/** A frame as osgGlyphsHeadless reads it back: row 0 at the bottom (unless topLeft). */
osg::ref_ptr<osg::Image> makeFrame(int width, int height, int frame, GLenum pixelFormat = GL_RGBA,
                                   int packing = 1, bool topLeft = false)
{
    osg::ref_ptr<osg::Image> image = new osg::Image;
    image->allocateImage(width, height, 1, pixelFormat, GL_UNSIGNED_BYTE, packing);
    if (topLeft)
        image->setOrigin(osg::Image::TOP_LEFT);
    const int components = osg::Image::computeNumComponents(pixelFormat);
    for (int row = 0; row < height; ++row)
    {
        const int pictureRow = topLeft ? row : height - 1 - row;
        const Colour colour = pictureRow < (height + 1) / 2 ? topColour(frame) : bottomColour(frame);
        unsigned char* pixel = image->data(0, row);
        for (int x = 0; x < width; ++x, pixel += components)
        {
            for (int c = 0; c < 3; ++c)
                pixel[pixelFormat == GL_BGRA || pixelFormat == GL_BGR ? 2 - c : c] =
                    static_cast<unsigned char>(colour[c]);
            if (components == 4)
                pixel[3] = 255;
        }
    }
    return image;
}

/** A frame of noise, which the encoder's quality shows on. */
osg::ref_ptr<osg::Image> makeNoise(int width, int height, unsigned int seed)
{
    osg::ref_ptr<osg::Image> image = new osg::Image;
    image->allocateImage(width, height, 1, GL_RGB, GL_UNSIGNED_BYTE);
    for (unsigned int i = 0; i < image->getTotalSizeInBytes(); ++i)
    {
        seed = seed * 1664525u + 1013904223u;
        image->data()[i] = static_cast<unsigned char>(seed >> 24);
    }
    return image;
}

std::string outputPath(const std::string& name)
{
    std::filesystem::create_directories(OSGGLYPHS_MOVIE_TEST_DIR);
    const std::string path = std::string(OSGGLYPHS_MOVIE_TEST_DIR) + "/" + name;
    std::filesystem::remove(path);
    return path;
}

bool haveTools()
{
    static const bool present = std::system("ffprobe -version > /dev/null 2>&1") == 0 &&
                                std::system("ffmpeg -version > /dev/null 2>&1") == 0;
    return present;
}

std::string runCommand(const std::string& command)
{
    std::string output;
    if (FILE* pipe = popen(command.c_str(), "r"))
    {
        char buffer[256];
        while (std::size_t read = std::fread(buffer, 1, sizeof(buffer), pipe))
            output.append(buffer, read);
        pclose(pipe);
    }
    return output;
}

/** The video stream's entries as ffprobe prints them, key=value per line. */
std::map<std::string, std::string> probe(const std::string& path)
{
    const std::string output =
        runCommand("ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                   "stream=nb_read_frames,width,height,codec_name,pix_fmt,avg_frame_rate,color_space "
                   "-of default=noprint_wrappers=1 '" +
                   path + "'");
    std::map<std::string, std::string> entries;
    std::istringstream lines(output);
    for (std::string line; std::getline(lines, line);)
    {
        const std::string::size_type equals = line.find('=');
        if (equals != std::string::npos)
            entries[line.substr(0, equals)] = line.substr(equals + 1);
    }
    return entries;
}

/** Frame number frame of the movie, decoded by ffmpeg to RGB, top row first. */
std::vector<unsigned char> decodeFrame(const std::string& path, int frame)
{
    const std::string raw = path + ".frame" + std::to_string(frame) + ".rgb";
    std::filesystem::remove(raw);
    runCommand("ffmpeg -v error -y -i '" + path + "' -vf 'select=eq(n\\," + std::to_string(frame) +
               ")' -frames:v 1 -f rawvideo -pix_fmt rgb24 '" + raw + "'");
    std::ifstream file(raw, std::ios::binary);
    return std::vector<unsigned char>(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
}

Colour pixelAt(const std::vector<unsigned char>& rgb, int width, int x, int y)
{
    const std::size_t offset = (static_cast<std::size_t>(y) * width + x) * 3;
    return {rgb[offset], rgb[offset + 1], rgb[offset + 2]};
}

void expectColour(const Colour& actual, const Colour& expected, const std::string& where)
{
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(actual[c], expected[c], ColourTolerance)
            << where << ": channel " << c << " of (" << actual[0] << ", " << actual[1] << ", " << actual[2]
            << ")";
}

/** Frames 0, 5 and 11 decoded: the top half on top, each with its frame's colours. */
void expectFrameColours(const std::string& path, int width, int height)
{
    for (int frame : {0, 5, NumFrames - 1})
    {
        const std::vector<unsigned char> rgb = decodeFrame(path, frame);
        ASSERT_EQ(rgb.size(), static_cast<std::size_t>(width) * height * 3) << path << " frame " << frame;
        const std::string where = path + " frame " + std::to_string(frame);
        expectColour(pixelAt(rgb, width, width / 2, height / 4), topColour(frame), where + " top");
        expectColour(pixelAt(rgb, width, width / 2, height * 3 / 4), bottomColour(frame), where + " bottom");
    }
}

void writeFrames(MovieWriter& writer, GLenum pixelFormat = GL_RGBA, int packing = 1, bool topLeft = false)
{
    for (int frame = 0; frame < NumFrames; ++frame)
    {
        std::string error;
        ASSERT_TRUE(writer.writeFrame(
            *makeFrame(writer.getWidth(), writer.getHeight(), frame, pixelFormat, packing, topLeft), error))
            << error;
    }
    EXPECT_EQ(writer.getFramesWritten(), static_cast<unsigned int>(NumFrames));
}

/** Writes the 12 frames to a new movie and closes it; the writer for its names. */
osg::ref_ptr<MovieWriter> writeMovie(const std::string& name, int width, int height,
                                     const MovieOptions& options = MovieOptions(),
                                     GLenum pixelFormat = GL_RGBA, int packing = 1)
{
    osg::ref_ptr<MovieWriter> writer = new MovieWriter;
    std::string error;
    EXPECT_TRUE(writer->open(outputPath(name), width, height, options, error)) << error;
    if (writer->isOpen())
    {
        writeFrames(*writer, pixelFormat, packing);
        EXPECT_TRUE(writer->close(error)) << error;
    }
    return writer;
}

/** The default encoder for .mp4, .mkv and .mov: libx264 where it is, else MPEG-4 part 2. */
void expectH264OrMpeg4(const MovieWriter& writer)
{
    if (writer.getEncoderName() == "libx264")
        EXPECT_EQ(writer.getCodecName(), "h264");
    else
        EXPECT_EQ(writer.getCodecName(), "mpeg4") << writer.getEncoderName();
}

void expectStream(const std::string& path, int width, int height, const std::string& codec,
                  const std::string& pixelFormat = "yuv420p")
{
    std::map<std::string, std::string> stream = probe(path);
    EXPECT_EQ(stream["nb_read_frames"], std::to_string(NumFrames)) << path;
    EXPECT_EQ(stream["width"], std::to_string(width)) << path;
    EXPECT_EQ(stream["height"], std::to_string(height)) << path;
    EXPECT_EQ(stream["codec_name"], codec) << path;
    EXPECT_EQ(stream["pix_fmt"], pixelFormat) << path;
}

bool contains(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

}

TEST(MovieWriter, WritesTwelveFramesOfMp4)
{
    osg::ref_ptr<MovieWriter> writer = writeMovie("colours.mp4", 64, 48);
    EXPECT_EQ(writer->getEncodedWidth(), 64);
    EXPECT_EQ(writer->getEncodedHeight(), 48);
    EXPECT_EQ(writer->getPixelFormat(), "yuv420p");
    expectH264OrMpeg4(*writer);
    std::cout << "[          ] .mp4 written by " << writer->getEncoderName() << " (" << writer->getCodecName()
              << ")" << std::endl;
    if (!haveTools())
        GTEST_SKIP() << "ffprobe or ffmpeg is not installed";

    expectStream(writer->getPath(), 64, 48, writer->getCodecName());
    std::map<std::string, std::string> stream = probe(writer->getPath());
    EXPECT_EQ(stream["avg_frame_rate"], "30/1");
    EXPECT_EQ(stream["color_space"], "smpte170m");
    expectFrameColours(writer->getPath(), 64, 48);
}

TEST(MovieWriter, TagsTheHighDefinitionMatrix)
{
    osg::ref_ptr<MovieWriter> writer = writeMovie("hd.mp4", 1280, 720);
    if (!haveTools())
        GTEST_SKIP() << "ffprobe or ffmpeg is not installed";

    expectStream(writer->getPath(), 1280, 720, writer->getCodecName());
    EXPECT_EQ(probe(writer->getPath())["color_space"], "bt709");
    expectFrameColours(writer->getPath(), 1280, 720);
}

TEST(MovieWriter, PadsAnOddSizeByOnePixel)
{
    // RGB rows of 195 bytes, aligned to 4: the writer follows osg::Image's row step.
    osg::ref_ptr<MovieWriter> writer = writeMovie("odd.mp4", 65, 49, MovieOptions(), GL_RGB, 4);
    EXPECT_EQ(writer->getWidth(), 65);
    EXPECT_EQ(writer->getHeight(), 49);
    EXPECT_EQ(writer->getEncodedWidth(), 66);
    EXPECT_EQ(writer->getEncodedHeight(), 50);
    if (!haveTools())
        GTEST_SKIP() << "ffprobe or ffmpeg is not installed";

    expectStream(writer->getPath(), 66, 50, writer->getCodecName());
    expectFrameColours(writer->getPath(), 66, 50);
    // The padding repeats the last column and row.
    const std::vector<unsigned char> rgb = decodeFrame(writer->getPath(), 3);
    ASSERT_EQ(rgb.size(), 66u * 50u * 3u);
    expectColour(pixelAt(rgb, 66, 65, 10), topColour(3), "padded column");
    expectColour(pixelAt(rgb, 66, 30, 49), bottomColour(3), "padded row");
}

TEST(MovieWriter, KeepsAnOddSizeWithoutSubsampledChroma)
{
    MovieOptions options;
    options.codec = "libx264";
    options.pixelFormat = "yuv444p";
    osg::ref_ptr<MovieWriter> writer = new MovieWriter;
    std::string error;
    if (!writer->open(outputPath("odd444.mkv"), 65, 49, options, error))
    {
        ASSERT_TRUE(contains(error, "no video encoder")) << error;
        GTEST_SKIP() << "libx264 is not available: " << error;
    }
    EXPECT_EQ(writer->getEncodedWidth(), 65);
    EXPECT_EQ(writer->getEncodedHeight(), 49);
    writeFrames(*writer, GL_BGRA);
    ASSERT_TRUE(writer->close(error)) << error;
    if (!haveTools())
        GTEST_SKIP() << "ffprobe or ffmpeg is not installed";

    expectStream(writer->getPath(), 65, 49, "h264", "yuv444p");
    expectFrameColours(writer->getPath(), 65, 49);
}

TEST(MovieWriter, TakesTopLeftImagesTopRowFirst)
{
    osg::ref_ptr<MovieWriter> writer = new MovieWriter;
    std::string error;
    ASSERT_TRUE(writer->open(outputPath("topleft.mp4"), 64, 48, MovieOptions(), error)) << error;
    writeFrames(*writer, GL_RGBA, 1, true);
    ASSERT_TRUE(writer->close(error)) << error;
    if (!haveTools())
        GTEST_SKIP() << "ffprobe or ffmpeg is not installed";
    expectFrameColours(writer->getPath(), 64, 48);
}

class MovieContainer : public ::testing::TestWithParam<const char*>
{
};

TEST_P(MovieContainer, WritesTheContainersDefaultCodec)
{
    const std::string extension = GetParam();
    osg::ref_ptr<MovieWriter> writer = writeMovie("colours" + extension, 64, 48);
    if (extension == ".avi")
        EXPECT_EQ(writer->getCodecName(), "mpeg4");
    else if (extension == ".webm")
        EXPECT_TRUE(writer->getCodecName() == "vp9" || writer->getCodecName() == "vp8")
            << writer->getCodecName();
    else
        expectH264OrMpeg4(*writer);
    std::cout << "[          ] " << extension << " written by " << writer->getEncoderName() << " ("
              << writer->getCodecName() << ")" << std::endl;
    if (!haveTools())
        GTEST_SKIP() << "ffprobe or ffmpeg is not installed";

    expectStream(writer->getPath(), 64, 48, writer->getCodecName());
    expectFrameColours(writer->getPath(), 64, 48);
}

INSTANTIATE_TEST_SUITE_P(Extensions, MovieContainer, ::testing::Values(".mkv", ".mov", ".avi", ".webm"),
                         [](const ::testing::TestParamInfo<const char*>& extension)
                         { return std::string(extension.param + 1); });

TEST(MovieWriter, WritesANamedCodec)
{
    MovieOptions options;
    options.codec = "mpeg4";
    options.quality = 10;
    osg::ref_ptr<MovieWriter> writer = writeMovie("named.mp4", 64, 48, options);
    EXPECT_EQ(writer->getEncoderName(), "mpeg4");
    if (!haveTools())
        GTEST_SKIP() << "ffprobe or ffmpeg is not installed";
    expectStream(writer->getPath(), 64, 48, "mpeg4");
    expectFrameColours(writer->getPath(), 64, 48);
}

TEST(MovieWriter, LowerQualityValuesMakeLargerFiles)
{
    for (const char* codec : {"", "mpeg4"})
    {
        std::uintmax_t sizes[2] = {};
        const int qualities[2] = {5, 40};
        for (int i = 0; i < 2; ++i)
        {
            MovieOptions options;
            options.codec = codec;
            options.quality = qualities[i];
            osg::ref_ptr<MovieWriter> writer = new MovieWriter;
            std::string error;
            const std::string path = outputPath("noise" + std::string(codec) + std::to_string(i) + ".mp4");
            ASSERT_TRUE(writer->open(path, 64, 48, options, error)) << error;
            for (unsigned int frame = 0; frame < NumFrames; ++frame)
                ASSERT_TRUE(writer->writeFrame(*makeNoise(64, 48, frame), error)) << error;
            ASSERT_TRUE(writer->close(error)) << error;
            sizes[i] = std::filesystem::file_size(path);
        }
        EXPECT_GT(sizes[0], sizes[1] * 2) << "codec '" << codec << "'";
    }
}

TEST(MovieWriter, KeepsTheFrameRate)
{
    MovieOptions options;
    options.framesPerSecond = 30000.0 / 1001.0;
    osg::ref_ptr<MovieWriter> ntsc = writeMovie("ntsc.mp4", 64, 48, options);
    options.framesPerSecond = 24.0;
    osg::ref_ptr<MovieWriter> film = writeMovie("film.mkv", 64, 48, options);
    if (!haveTools())
        GTEST_SKIP() << "ffprobe or ffmpeg is not installed";
    EXPECT_EQ(probe(ntsc->getPath())["avg_frame_rate"], "30000/1001");
    EXPECT_EQ(probe(film->getPath())["avg_frame_rate"], "24/1");
}

TEST(MovieWriter, TheDestructorClosesTheMovie)
{
    const std::string path = outputPath("unclosed.mp4");
    {
        osg::ref_ptr<MovieWriter> writer = new MovieWriter;
        std::string error;
        ASSERT_TRUE(writer->open(path, 64, 48, MovieOptions(), error)) << error;
        writeFrames(*writer);
    }
    if (!haveTools())
        GTEST_SKIP() << "ffprobe or ffmpeg is not installed";
    EXPECT_EQ(probe(path)["nb_read_frames"], std::to_string(NumFrames));
}

TEST(MovieWriter, OpensAgainAfterClose)
{
    osg::ref_ptr<MovieWriter> writer = new MovieWriter;
    std::string error;
    const std::string first = outputPath("first.mkv");
    ASSERT_TRUE(writer->open(first, 64, 48, MovieOptions(), error)) << error;
    ASSERT_TRUE(writer->writeFrame(*makeFrame(64, 48, 0), error)) << error;
    EXPECT_FALSE(writer->open(outputPath("second.mkv"), 64, 48, MovieOptions(), error));
    EXPECT_TRUE(contains(error, "first.mkv")) << error;
    EXPECT_TRUE(contains(error, "second.mkv")) << error;
    ASSERT_TRUE(writer->close(error)) << error;
    EXPECT_TRUE(writer->close(error)) << "closing twice: " << error;
    EXPECT_FALSE(writer->isOpen());

    ASSERT_TRUE(writer->open(outputPath("second.mkv"), 32, 16, MovieOptions(), error)) << error;
    EXPECT_EQ(writer->getFramesWritten(), 0u);
    writeFrames(*writer);
    ASSERT_TRUE(writer->close(error)) << error;
    if (!haveTools())
        GTEST_SKIP() << "ffprobe or ffmpeg is not installed";
    EXPECT_EQ(probe(first)["nb_read_frames"], "1");
    std::map<std::string, std::string> second = probe(writer->getPath());
    EXPECT_EQ(second["nb_read_frames"], std::to_string(NumFrames));
    EXPECT_EQ(second["width"], "32");
}

TEST(MovieWriter, RefusesAnImageOfAnotherSize)
{
    osg::ref_ptr<MovieWriter> writer = new MovieWriter;
    std::string error;
    const std::string path = outputPath("sizes.mp4");
    ASSERT_TRUE(writer->open(path, 64, 48, MovieOptions(), error)) << error;
    ASSERT_TRUE(writer->writeFrame(*makeFrame(64, 48, 0), error)) << error;
    EXPECT_FALSE(writer->writeFrame(*makeFrame(32, 24, 1), error));
    EXPECT_TRUE(contains(error, path)) << error;
    EXPECT_TRUE(contains(error, "32x24")) << error;
    EXPECT_TRUE(contains(error, "64x48")) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    EXPECT_EQ(writer->getFramesWritten(), 1u);
    // The movie goes on.
    EXPECT_TRUE(writer->writeFrame(*makeFrame(64, 48, 1), error)) << error;
    EXPECT_TRUE(writer->close(error)) << error;
    EXPECT_EQ(writer->getFramesWritten(), 2u);
}

TEST(MovieWriter, RefusesImagesItCannotRead)
{
    osg::ref_ptr<MovieWriter> writer = new MovieWriter;
    std::string error;
    EXPECT_FALSE(writer->writeFrame(*makeFrame(64, 48, 0), error));
    EXPECT_TRUE(contains(error, "no movie is open")) << error;

    ASSERT_TRUE(writer->open(outputPath("formats.mp4"), 64, 48, MovieOptions(), error)) << error;
    osg::ref_ptr<osg::Image> floats = new osg::Image;
    floats->allocateImage(64, 48, 1, GL_RGBA, GL_FLOAT);
    EXPECT_FALSE(writer->writeFrame(*floats, error));
    EXPECT_TRUE(contains(error, "not 8-bit")) << error;
    osg::ref_ptr<osg::Image> grey = new osg::Image;
    grey->allocateImage(64, 48, 1, GL_LUMINANCE, GL_UNSIGNED_BYTE);
    EXPECT_FALSE(writer->writeFrame(*grey, error));
    EXPECT_TRUE(contains(error, "not 8-bit")) << error;
    osg::ref_ptr<osg::Image> empty = new osg::Image;
    EXPECT_FALSE(writer->writeFrame(*empty, error));
    EXPECT_TRUE(contains(error, "0x0")) << error;
    EXPECT_EQ(writer->getFramesWritten(), 0u);
    EXPECT_TRUE(writer->close(error)) << error;
}

TEST(MovieWriter, RefusesAnUnwritablePath)
{
    const std::string path = "/nonexistent-osgglyphs-directory/movie.mp4";
    osg::ref_ptr<MovieWriter> writer = new MovieWriter;
    std::string error;
    EXPECT_FALSE(writer->open(path, 64, 48, MovieOptions(), error));
    EXPECT_FALSE(writer->isOpen());
    EXPECT_TRUE(contains(error, path)) << error;
    EXPECT_TRUE(contains(error, "No such file or directory")) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    EXPECT_FALSE(writer->writeFrame(*makeFrame(64, 48, 0), error));
}

TEST(MovieWriter, ReportsAFullDisk)
{
    if (!std::filesystem::exists("/dev/full"))
        GTEST_SKIP() << "no /dev/full";
    const std::string path = outputPath("full.mkv");
    std::filesystem::create_symlink("/dev/full", path);
    osg::ref_ptr<MovieWriter> writer = new MovieWriter;
    std::string error;
    bool written = writer->open(path, 64, 48, MovieOptions(), error);
    for (int frame = 0; written && frame < NumFrames; ++frame)
        written = writer->writeFrame(*makeNoise(64, 48, frame), error);
    if (written)
        written = writer->close(error);
    EXPECT_FALSE(written);
    EXPECT_TRUE(contains(error, path)) << error;
    EXPECT_TRUE(contains(error, "No space left on device")) << error;
    EXPECT_TRUE(writer->close(error)) << "closing after the failure: " << error;
    std::filesystem::remove(path);
}

TEST(MovieWriter, RemovesTheFileWhenTheHeaderFails)
{
    // libavformat's MXF muxer takes no MPEG-4 part 2 (FFmpeg 5.1), which it finds out in its header.
    const std::string path = outputPath("refused.mxf");
    MovieOptions options;
    options.codec = "mpeg4";
    osg::ref_ptr<MovieWriter> writer = new MovieWriter;
    std::string error;
    if (writer->open(path, 64, 48, options, error))
        GTEST_SKIP() << "this libavformat writes MPEG-4 part 2 into MXF";
    EXPECT_TRUE(contains(error, path)) << error;
    EXPECT_TRUE(contains(error, "header")) << error;
    EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(MovieWriter, RefusesAnUnknownExtension)
{
    const std::string path = outputPath("movie.notavideo");
    osg::ref_ptr<MovieWriter> writer = new MovieWriter;
    std::string error;
    EXPECT_FALSE(writer->open(path, 64, 48, MovieOptions(), error));
    EXPECT_TRUE(contains(error, path)) << error;
    EXPECT_TRUE(contains(error, "\".notavideo\"")) << error;
    EXPECT_FALSE(std::filesystem::exists(path));

    EXPECT_FALSE(writer->open(outputPath("movie.wav"), 64, 48, MovieOptions(), error));
    EXPECT_TRUE(contains(error, "holds no video")) << error;
}

TEST(MovieWriter, RefusesOptionsBeforeCreatingTheFile)
{
    struct Case
    {
        const char* what;
        std::string name;
        int width, height;
        MovieOptions options;
        const char* expected;
    };
    MovieOptions unknownCodec, audioCodec, wrongContainer, unknownFormat, refusedFormat, noRate, badQuality;
    unknownCodec.codec = "nosuchcodec";
    audioCodec.codec = "aac";
    wrongContainer.codec = "mpeg4";
    unknownFormat.pixelFormat = "nosuchformat";
    refusedFormat.codec = "mpeg4";
    refusedFormat.pixelFormat = "yuv444p";
    noRate.framesPerSecond = 0.0;
    badQuality.quality = -1;
    const Case cases[] = {
        {"an unknown codec", "a.mp4", 64, 48, unknownCodec, "\"nosuchcodec\""},
        {"an audio codec", "b.mp4", 64, 48, audioCodec, "no video encoder \"aac\""},
        {"a codec the container refuses", "c.webm", 64, 48, wrongContainer, "cannot hold mpeg4"},
        {"an unknown pixel format", "d.mp4", 64, 48, unknownFormat, "\"nosuchformat\""},
        {"a pixel format the encoder refuses", "e.mp4", 64, 48, refusedFormat, "cannot encode yuv444p"},
        {"no frame rate", "f.mp4", 64, 48, noRate, "frame rate"},
        {"a negative quality", "g.mp4", 64, 48, badQuality, "quality -1"},
        {"no pixels", "h.mp4", 0, 48, MovieOptions(), "0x48"},
    };
    for (const Case& refused : cases)
    {
        const std::string path = outputPath(refused.name);
        osg::ref_ptr<MovieWriter> writer = new MovieWriter;
        std::string error;
        EXPECT_FALSE(writer->open(path, refused.width, refused.height, refused.options, error))
            << refused.what;
        EXPECT_TRUE(contains(error, path)) << refused.what << ": " << error;
        EXPECT_TRUE(contains(error, refused.expected)) << refused.what << ": " << error;
        EXPECT_FALSE(std::filesystem::exists(path)) << refused.what;
        EXPECT_FALSE(writer->isOpen()) << refused.what;
    }
}
