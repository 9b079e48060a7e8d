/* Helpers of the point reader tests: data from strings, files under the build tree, error checks. */

#ifndef OSGGLYPHS_TESTS_READERTESTUTIL_H
#define OSGGLYPHS_TESTS_READERTESTUTIL_H 1

#include <osgGlyphsData/PointReader>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <streambuf>
#include <string>
#include <vector>

namespace readertest
{

/** Reads text (or bytes) in a format through readPointStream, named name in messages. */
inline osg::ref_ptr<osgGlyphsData::PointDataset> readString(const std::string& text,
                                                            const std::string& format, std::string& error,
                                                            const std::string& name = "data")
{
    std::istringstream stream(text);
    return osgGlyphsData::readPointStream(stream, format, name, osgGlyphsData::PointReadOptions(), error);
}

/** Reads text with options, keeping the warnings in warnings rather than printing them. */
inline osg::ref_ptr<osgGlyphsData::PointDataset>
readWithOptions(const std::string& text, const std::string& format, osgGlyphsData::PointReadOptions options,
                std::vector<std::string>& warnings, std::string& error, const std::string& name = "data")
{
    std::istringstream stream(text);
    options.warning = [&warnings](const std::string& warning) { warnings.push_back(warning); };
    return osgGlyphsData::readPointStream(stream, format, name, options, error);
}

/** Reads what must be malformed; returns the error, failing the test when the read succeeds or
 * the message is not exactly one line. */
inline std::string readError(const std::string& text, const std::string& format, const std::string& name)
{
    std::string error;
    osg::ref_ptr<osgGlyphsData::PointDataset> dataset = readString(text, format, error, name);
    EXPECT_FALSE(dataset.valid()) << "read succeeded: " << name;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    EXPECT_FALSE(error.empty());
    return error;
}

/** True when text starts with prefix and contains part, for EXPECT_TRUE with a readable message. */
inline ::testing::AssertionResult hasError(const std::string& error, const std::string& prefix,
                                           const std::string& part)
{
    if (error.compare(0, prefix.size(), prefix) == 0 && error.find(part) != std::string::npos)
        return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "error \"" << error << "\" does not start with \"" << prefix
                                         << "\" and contain \"" << part << "\"";
}

/** A folder for test files under the build tree. */
inline std::string testFile(const std::string& name)
{
    std::filesystem::create_directories(OSGGLYPHS_READER_TEST_DIR);
    return std::string(OSGGLYPHS_READER_TEST_DIR) + "/" + name;
}

/** Writes bytes into a test file; returns its path. */
inline std::string writeFile(const std::string& name, const std::string& bytes)
{
    const std::string path = testFile(name);
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
}

/** A column's file values (origin added, as floats), empty (with a failure) when it is missing. */
inline std::vector<float> column(const osgGlyphsData::PointData& data, const std::string& name)
{
    const int index = data.findColumn(name);
    EXPECT_GE(index, 0) << "no column " << name;
    std::vector<float> values(index < 0 ? 0 : data.getNumPoints());
    for (std::size_t i = 0; i < values.size(); ++i)
        values[i] = static_cast<float>(data.getValue(static_cast<std::size_t>(index), i));
    return values;
}

/** A stream that cannot seek, as a pipe: its size is unknown to the reader. */
class PipeBuffer : public std::streambuf
{
public:
    explicit PipeBuffer(const std::string& data) : _data(data), _at(0) {}

protected:
    int_type underflow() override
    {
        if (_at >= _data.size())
            return traits_type::eof();
        const std::size_t piece = std::min<std::size_t>(_data.size() - _at, 7);
        char* begin = &_data[_at];
        setg(begin, begin, begin + piece);
        _at += piece;
        return traits_type::to_int_type(*begin);
    }

private:
    std::string _data;
    std::size_t _at;
};

/** Binary data in either byte order. */
class Bytes
{
public:
    explicit Bytes(bool bigEndian) : _bigEndian(bigEndian) {}

    template <typename T>
    Bytes& put(T value)
    {
        unsigned char raw[sizeof(T)];
        std::memcpy(raw, &value, sizeof(T));
        const uint16_t one = 1;
        const bool hostLittle = *reinterpret_cast<const unsigned char*>(&one) == 1;
        if (hostLittle == _bigEndian)
        {
            for (std::size_t i = 0; i < sizeof(T) / 2; ++i)
                std::swap(raw[i], raw[sizeof(T) - 1 - i]);
        }
        _data.append(reinterpret_cast<const char*>(raw), sizeof(T));
        return *this;
    }

    Bytes& text(const std::string& text)
    {
        _data += text;
        return *this;
    }

    const std::string& str() const { return _data; }

private:
    bool _bigEndian;
    std::string _data;
};

} // namespace readertest

#endif
