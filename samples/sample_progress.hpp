// Progress of a long run on stderr, for the sample programs.
//
// On a terminal one line is redrawn in place, at most five times a second; into a log (stderr not a terminal)
// a line is printed at most every five seconds, so that a long recording does not fill the log.

#ifndef OPENCV_EVENT_SAMPLES_SAMPLE_PROGRESS_HPP
#define OPENCV_EVENT_SAMPLES_SAMPLE_PROGRESS_HPP

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <string>
#include <unistd.h>

class SampleProgress
{
public:
    SampleProgress() : terminal_(isatty(STDERR_FILENO) != 0), last_(std::chrono::steady_clock::now()) {}

    /** Reports @p fraction done (0..1; negative: unknown, e.g. a live camera) and a short @p text. */
    void update(double fraction, const std::string& text)
    {
        const auto now = std::chrono::steady_clock::now();
        const double since = std::chrono::duration<double>(now - last_).count();
        if (shown_ && since < (terminal_ ? 0.2 : 5.0))
            return;
        last_ = now;
        shown_ = true;
        print(fraction, text);
    }

    /** Prints the final state, whatever the time since the last line, and ends the line. */
    void finish(double fraction, const std::string& text)
    {
        print(fraction, text);
        if (terminal_)
            std::cerr << "\n";
    }

private:
    void print(double fraction, const std::string& text) const
    {
        std::string bar;
        if (fraction >= 0)
        {
            const int width = 30, filled = (int)std::lround(std::min(1.0, fraction) * width);
            bar = "[" + std::string((size_t)filled, '#') + std::string((size_t)(width - filled), '.') + "] " +
                  std::to_string((int)std::lround(std::min(1.0, fraction) * 100)) + " %, ";
        }
        if (terminal_)
            std::cerr << "\r" << bar << text << "   " << std::flush;
        else
            std::cerr << bar << text << "\n";
    }

    bool terminal_, shown_ = false;
    std::chrono::steady_clock::time_point last_;
};

#endif  // OPENCV_EVENT_SAMPLES_SAMPLE_PROGRESS_HPP
