#include "ConvertProgress.h"

#include <cstdio>

#include <unistd.h>

ConvertProgress::ConvertProgress(const std::string& program)
    : _program(program), _terminal(isatty(fileno(stderr)) != 0)
{
}

void ConvertProgress::start(const std::string& stage)
{
    finish();
    _stage = stage;
    _start = _lastShown = Clock::now();
}

void ConvertProgress::update(double fraction)
{
    const Clock::time_point now = Clock::now();
    const double elapsed = std::chrono::duration<double>(now - _start).count();
    if (elapsed < 1.0 || std::chrono::duration<double>(now - _lastShown).count() < 1.0)
        return;
    _lastShown = now;
    // No estimate from the first percent: it would mostly be the stage's start-up.
    char left[64] = "";
    if (fraction >= 0.01)
        std::snprintf(left, sizeof(left), " (about %.0f s left)", elapsed * (1.0 - fraction) / fraction);
    std::fprintf(stderr, "%s%s: %s %3d%%%s%s", _terminal ? "\r" : "", _program.c_str(), _stage.c_str(),
                 static_cast<int>(100.0 * fraction), left, _terminal ? "   " : "\n");
    std::fflush(stderr);
    _lineOpen = _terminal;
}

void ConvertProgress::finish()
{
    if (_lineOpen)
        std::fputc('\n', stderr);
    _lineOpen = false;
}
