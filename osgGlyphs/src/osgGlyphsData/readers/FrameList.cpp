#include "FrameList.h"

#include "Readers.h"

using namespace osgGlyphsData;
using namespace osgGlyphsData::readers;

FrameList::FrameList(TextScanner& scanner, PointDataset& dataset, const PointReadOptions& options)
    : _scanner(scanner), _dataset(dataset), _options(options), _fileFrame(options.start.frame)
{
    _dataset.setEndOfCompleteFrames(options.start);
}

void FrameList::add(PointData* frame, uint64_t firstLine, uint64_t filePoints)
{
    const uint64_t number = _fileFrame + 1;
    if (_options.growing && !_scanner.isLineTerminated() && _scanner.atEnd())
    {
        _dataset.setIncompleteFrame(_scanner.getName() + ":" + std::to_string(_scanner.getLineNumber()) +
                                    ": the last line has no end yet: frame " + std::to_string(number) +
                                    " is incomplete and left out");
        return;
    }
    ++_fileFrame;
    _dataset.setEndOfCompleteFrames({_scanner.getOffset(), _scanner.getLineNumber(), _fileFrame});
    if (filePoints > 0)
    {
        frame->setFilePointCount(filePoints);
        _dataset.addFrame(frame);
        return;
    }
    if (_emptyFrames++ == 0)
    {
        _firstEmptyFrame = number;
        _firstEmptyLine = firstLine;
    }
}

bool FrameList::leavesOutCutFrame(const ReadError& error)
{
    const bool cut = error.endOfInput || (!_scanner.isLineTerminated() && _scanner.atEnd());
    if (!cut || (_dataset.getNumFrames() == 0 && _emptyFrames == 0 && !mayReadNothing(_options)))
        return false;
    const std::string leftOut =
        error.message + "; frame " + std::to_string(_fileFrame + 1) + " is incomplete and left out";
    if (_options.growing)
        _dataset.setIncompleteFrame(leftOut);
    else
        _dataset.addWarning(leftOut);
    return true;
}

void FrameList::finish(const std::string& noFrames)
{
    const std::string where = _scanner.getName() + ":" + std::to_string(_firstEmptyLine) + ": ";
    const std::string first = "frame " + std::to_string(_firstEmptyFrame);
    if (_dataset.getNumFrames() == 0 && !mayReadNothing(_options))
    {
        if (_emptyFrames == 0)
            _scanner.fail(noFrames);
        throw ReadError{where + "no atoms: " +
                        (_emptyFrames == 1 ? first + " is empty"
                                           : "all " + std::to_string(_emptyFrames) + " frames are empty")};
    }
    if (_emptyFrames == 1)
        _dataset.addWarning(where + first + " has no atoms and is left out");
    else if (_emptyFrames > 1)
        _dataset.addWarning(where + std::to_string(_emptyFrames) +
                            " frames without atoms left out, the first " + first);
}
