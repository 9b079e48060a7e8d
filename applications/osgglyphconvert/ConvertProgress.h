/* osgglyphconvert: progress of a long conversion on stderr. */

#ifndef OSGGLYPHCONVERT_CONVERTPROGRESS_H
#define OSGGLYPHCONVERT_CONVERTPROGRESS_H 1

#include <chrono>
#include <string>

/** Prints "<program>: <stage> 42% (about 12 s left)" at most once a second (on one rewritten
 * line on a terminal), once a stage has run for a second. */
class ConvertProgress
{
public:
    explicit ConvertProgress(const std::string& program);

    /** Starts a stage ("reading data.ply"). */
    void start(const std::string& stage);
    /** The fraction of the stage done, 0 to 1. */
    void update(double fraction);
    /** Ends the stage's line. */
    void finish();

private:
    using Clock = std::chrono::steady_clock;
    std::string _program;
    std::string _stage;
    bool _terminal;
    Clock::time_point _start;
    Clock::time_point _lastShown;
    bool _lineOpen = false;
};

#endif
