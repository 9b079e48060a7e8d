/* osgGlyphs - private: the frame file of a format reader: its file, readFrame() and opener, once. */

#ifndef OSGGLYPHS_FORMATS_FORMATFRAMEFILE_H
#define OSGGLYPHS_FORMATS_FORMATFRAMEFILE_H 1

#include "BinaryFile.h"

#include <osgGlyphsData/FrameFile>

#include <new>
#include <string>
#include <utility>

namespace osgGlyphsData
{
namespace formats
{

/** A FrameFile read from a BinaryFile by a format reader that throws FormatError: findFrames()
 * when it opens, decodeFrame() for each frame. The reader keeps only its format's logic. */
class FormatFrameFile : public FrameFile
{
public:
    /** What readFrame() does when decoding runs out of memory. */
    enum class OutOfMemory
    {
        /** std::bad_alloc goes on to the caller. */
        Thrown,
        /** "<file>: frame <n>: out of memory" as the frame's error. */
        Reported
    };

    /** Opens the file and finds its frames; false with the one-line error. */
    bool open(std::string& error)
    {
        if (!_file.open(_path, error))
            return false;
        try
        {
            findFrames();
        }
        catch (const FormatError& failure)
        {
            error = failure.message;
            return false;
        }
        return true;
    }

    osg::ref_ptr<PointData> readFrame(std::size_t frame, const PointShare& share,
                                      std::string& error) const final
    {
        try
        {
            return decodeFrame(frame, share);
        }
        catch (const FormatError& failure)
        {
            error = failure.message;
        }
        catch (const std::bad_alloc&)
        {
            if (_outOfMemory == OutOfMemory::Thrown)
                throw;
            error = _path + ": frame " + std::to_string(frame) + ": out of memory";
        }
        return nullptr;
    }

protected:
    FormatFrameFile(const std::string& path, const std::string& format,
                    OutOfMemory outOfMemory = OutOfMemory::Thrown)
        : FrameFile(path, format), _outOfMemory(outOfMemory)
    {
    }

    /** Reads the header and finds the frames (their fixed size, an index or a scan), once, at
     * opening; throws FormatError when the file is malformed. */
    virtual void findFrames() = 0;

    /** Decodes share of a frame's points; throws FormatError when it is malformed. Thread-safe. */
    virtual osg::ref_ptr<PointData> decodeFrame(std::size_t frame, const PointShare& share) const = 0;

    BinaryFile _file;

private:
    OutOfMemory _outOfMemory;
};

/** Opens path as a T (a FormatFrameFile made from path and args); nullptr with the one-line error. */
template <typename T, typename... Args>
osg::ref_ptr<FrameFile> openFormatFile(const std::string& path, std::string& error, Args&&... args)
{
    osg::ref_ptr<T> file = new T(path, std::forward<Args>(args)...);
    if (!file->open(error))
        return nullptr;
    return file;
}

} // namespace formats
}

#endif
