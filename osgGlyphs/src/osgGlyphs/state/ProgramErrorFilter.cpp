#include <osgGlyphs/ProgramErrorFilter>

#include "GlyphProgram.h"

#include <string>

using namespace osgGlyphs;

namespace
{

/** OSG's report of a glyph shader or program that failed (WARN for a shader, NOTICE for a
 * program): its FAILED line or its info log, naming "osgGlyphs..." in quotes. */
bool isOsgFailureReport(osg::NotifySeverity severity, const std::string& message)
{
    return severity <= osg::NOTICE && message.find("\"osgGlyphs") != std::string::npos &&
           (message.find("\" FAILED") != std::string::npos ||
            message.find("\" infolog:") != std::string::npos);
}

}

ProgramErrorFilter::ProgramErrorFilter(osg::NotifyHandler* next) : _next(next) {}

void ProgramErrorFilter::notify(osg::NotifySeverity severity, const char* message)
{
    const std::string text = message ? message : "";
    if (text.rfind(detail::PROGRAM_ERROR_NOTIFY_PREFIX, 0) == 0 || isOsgFailureReport(severity, text))
        return;
    if (_next.valid())
        _next->notify(severity, message);
}
