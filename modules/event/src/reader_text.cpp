// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Text recordings: one event per line, columns separated by blanks, tabs or commas.
//  - RPG Event Camera Dataset: `t x y p`, t in seconds, p in {0, 1};
//  - E2VID-style: a first line `width height`, then `t x y p`;
//  - TUM stereo DVS128 (shared/data/stereo_dvs128_tum): `t_us x y p retina`, 1-based x and y;
// Lines starting with '#' or '%' are comments. Column order, time unit, 1-based coordinates and the camera
// column are options (EVENT_CAP_PROP_TEXT_*).

#include "event_reader.hpp"
#include "file_input.hpp"

#include <cstdlib>

namespace cv {
namespace event {
namespace detail {

namespace {

class TextReader CV_FINAL : public EventReader
{
public:
    TextReader(const String& path, const ReaderOptions& options) : in_(path), opt_(options)
    {
        // Skip comments; look at the first data line for a size header, the column count and the time unit.
        while (in_.readLine(line_))
        {
            lineNumber_++;
            if (isComment(line_))
                continue;
            lineOffset_ = in_.offset() - (int64)line_.size() - 1;
            std::vector<std::string> tokens = split(line_);
            if (tokens.size() == 2 && isInteger(tokens[0]) && isInteger(tokens[1]))
            {
                size_ = Size(std::atoi(tokens[0].c_str()), std::atoi(tokens[1].c_str()));
                continue;  // E2VID-style size line
            }
            columns_ = (int)tokens.size();
            const int needed = std::max(std::max(opt_.textColumnT, opt_.textColumnX),
                                        std::max(opt_.textColumnY, opt_.textColumnP)) + 1;
            if (columns_ < needed)
                formatError(in_.path(), lineOffset_, format("line %d has %d columns; a text recording needs at "
                                                            "least %d (t x y p)", lineNumber_, columns_, needed));
            camera_ = opt_.textColumnCamera == -2 ? (columns_ >= 5 ? 4 : -1) : opt_.textColumnCamera;
            if (camera_ >= columns_)
                formatError(in_.path(), lineOffset_, format("line %d has no camera column %d", lineNumber_, camera_));
            int unit = opt_.textTimeUnit;
            if (unit == EVENT_TIME_UNIT_AUTO)
            {
                const std::string& t = tokens[opt_.textColumnT];
                unit = t.find_first_of(".eE") != std::string::npos ? EVENT_TIME_UNIT_SECONDS
                                                                   : EVENT_TIME_UNIT_MICROSECONDS;
            }
            timeScale_ = unit == EVENT_TIME_UNIT_SECONDS ? 1e6 : unit == EVENT_TIME_UNIT_MILLISECONDS ? 1e3
                       : unit == EVENT_TIME_UNIT_NANOSECONDS ? 1e-3 : 1.0;
            integerTime_ = unit == EVENT_TIME_UNIT_MICROSECONDS;
            havePending_ = true;
            break;
        }
        if (!opt_.sensorSize.empty())
            size_ = opt_.sensorSize;
        if (opt_.textLeftCameraValue != 0 && opt_.textLeftCameraValue != 1)
            CV_Error_(Error::StsBadArg, ("%s: the left camera value must be 0 or 1, got %d", path.c_str(),
                                         opt_.textLeftCameraValue));
    }

    String name() const CV_OVERRIDE { return "TEXT"; }
    bool isStereo() const CV_OVERRIDE { return camera_ >= 0; }
    Size sensorSize() const CV_OVERRIDE { return size_; }
    double progress() const CV_OVERRIDE { return in_.progress(); }

    bool next(std::vector<Event>& out) CV_OVERRIDE
    {
        size_t produced = 0;
        out.reserve(out.size() + kReaderChunk);
        while (produced < kReaderChunk)
        {
            if (havePending_)
                havePending_ = false;
            else
            {
                lineOffset_ = in_.offset();
                if (!in_.readLine(line_))
                    break;
                lineNumber_++;
                if (isComment(line_))
                    continue;
            }
            const Event e = parse();
            if (opt_.cameraFilter >= 0 && e.camera != opt_.cameraFilter)
                continue;
            out.push_back(e);
            produced++;
        }
        return produced > 0;
    }

private:
    static bool isComment(const std::string& line)
    {
        size_t i = line.find_first_not_of(" \t");
        return i == std::string::npos || line[i] == '#' || line[i] == '%';
    }

    static bool isSeparator(char c) { return c == ' ' || c == '\t' || c == ',' || c == ';'; }

    static std::vector<std::string> split(const std::string& line)
    {
        std::vector<std::string> tokens;
        size_t i = 0;
        while (i < line.size())
        {
            while (i < line.size() && isSeparator(line[i]))
                i++;
            size_t j = i;
            while (j < line.size() && !isSeparator(line[j]))
                j++;
            if (j > i)
                tokens.push_back(line.substr(i, j - i));
            i = j;
        }
        return tokens;
    }

    static bool isInteger(const std::string& s)
    {
        char* end = nullptr;
        std::strtol(s.c_str(), &end, 10);
        return end && *end == '\0' && !s.empty();
    }

    // One column: exact integers and decimals without strtod on the common path (the reader's hot loop);
    // exponents and very long numbers fall back to strtod.
    struct Number
    {
        bool integral = true;  // no fraction and no exponent: `whole` is exact
        int64 whole = 0;       // integer part (signed)
        int64 frac = 0;        // fraction digits as an integer ...
        int fracDigits = 0;    // ... and their count
        double value = 0;
    };

    static const char* scanNumber(const char* p, Number& n)
    {
        const char* start = p;
        bool negative = false;
        if (*p == '-' || *p == '+')
            negative = *p++ == '-';
        int digits = 0;
        int64 whole = 0;
        while (*p >= '0' && *p <= '9' && digits < 18)
        {
            whole = whole * 10 + (*p++ - '0');
            digits++;
        }
        int64 frac = 0;
        int fracDigits = 0;
        if (*p == '.')
        {
            p++;
            while (*p >= '0' && *p <= '9' && fracDigits < 18)
            {
                frac = frac * 10 + (*p++ - '0');
                fracDigits++;
            }
        }
        if ((digits == 0 && fracDigits == 0) || (*p >= '0' && *p <= '9') || *p == 'e' || *p == 'E')
        {
            // Exponent, or more digits than the fast path keeps: let strtod decide.
            char* end = nullptr;
            n.value = std::strtod(start, &end);
            n.integral = false;
            n.fracDigits = -1;  // no exact decimal form
            return end == start ? start : end;
        }
        n.integral = fracDigits == 0 && p[-1] != '.';
        n.whole = negative ? -whole : whole;
        n.frac = negative ? -frac : frac;
        n.fracDigits = fracDigits;
        double f = (double)frac;
        for (int k = 0; k < fracDigits; k++)
            f *= 0.1;
        n.value = (double)whole + f;
        if (negative)
            n.value = -n.value;
        return p;
    }

    // A time column value to microseconds: exact decimal arithmetic when the number has a plain decimal form.
    int64 toMicroseconds(const Number& n) const
    {
        if (n.integral && timeScale_ == 1.0)
            return n.whole;
        // Beyond +-2^63 us (292,000 years) a time cannot be stored; refused rather than wrapped.
        if (!(std::abs(n.value * timeScale_) < 9.2e18))
            formatError(in_.path(), lineOffset_, format("line %d: timestamp %g is out of range: \"%s\"", lineNumber_,
                                                        n.value, line_.c_str()));
        if (n.fracDigits >= 0 && timeScale_ == 1e6 && n.fracDigits <= 12)
        {
            // seconds.fraction: whole * 10^6 + fraction scaled to 6 digits, rounded half away from zero.
            int64 scaled;
            if (n.fracDigits <= 6)
            {
                scaled = n.frac;
                for (int k = n.fracDigits; k < 6; k++)
                    scaled *= 10;
            }
            else
            {
                int64 div = 1;
                for (int k = 6; k < n.fracDigits; k++)
                    div *= 10;
                scaled = (n.frac + (n.frac >= 0 ? div / 2 : -div / 2)) / div;
            }
            return n.whole * 1000000 + scaled;
        }
        return (int64)std::llround(n.value * timeScale_);
    }

    Event parse()
    {
        // Parse the columns in place: no allocation per line (and the columns are a member: constructing 16 of
        // them per line took 40 % of the reader's time).
        Number* values = columns16_;
        const int want = std::min(columns_, 16);
        const char* p = line_.c_str();
        int n = 0;
        while (n < want)
        {
            while (*p && isSeparator(*p))
                p++;
            if (!*p)
                break;
            const char* end = scanNumber(p, values[n]);
            if (end == p || (*end && !isSeparator(*end)))
                formatError(in_.path(), lineOffset_, format("line %d: column %d is not a number: \"%s\"",
                                                            lineNumber_, n + 1, line_.c_str()));
            p = end;
            n++;
        }
        if (n < want)
            formatError(in_.path(), lineOffset_, format("line %d: %d columns, expected %d: \"%s\"", lineNumber_, n,
                                                        columns_, line_.c_str()));
        const Number& tn = values[opt_.textColumnT];
        if (integerTime_ && !tn.integral)
            formatError(in_.path(), lineOffset_, format("line %d: timestamp \"%s\" is not an integer number of "
                                                        "microseconds, as the first line's was", lineNumber_, line_.c_str()));
        const int64 t = toMicroseconds(tn);
        const int base = opt_.textOneBased ? 1 : 0;
        const Number& xn = values[opt_.textColumnX];
        const Number& yn = values[opt_.textColumnY];
        const double x = xn.value - base, y = yn.value - base;
        if (!xn.integral || !yn.integral || !(std::abs(x) < 32768 && std::abs(y) < 32768))
            formatError(in_.path(), lineOffset_, format("line %d: coordinates (%g, %g) are not pixel indices",
                                                        lineNumber_, xn.value, yn.value));
        int camera = CAMERA_LEFT;
        if (camera_ >= 0)
        {
            const Number& cn = values[camera_];
            if (!cn.integral || !(std::abs(cn.value) < 1e9))
                formatError(in_.path(), lineOffset_, format("line %d: camera value %g is not 0 or 1: \"%s\"", lineNumber_,
                                                            cn.value, line_.c_str()));
            const int c = (int)cn.value;
            const int other = opt_.textLeftCameraValue == 0 ? 1 : 0;
            if (c == opt_.textLeftCameraValue)
                camera = CAMERA_LEFT;
            else if (c == other)
                camera = CAMERA_RIGHT;
            else
                formatError(in_.path(), lineOffset_, format("line %d: camera value %d; expected %d (left) or %d (right)",
                                                            lineNumber_, c, opt_.textLeftCameraValue, other));
        }
        return Event(t, (int)x, (int)y, values[opt_.textColumnP].value > 0 ? POLARITY_ON : POLARITY_OFF, camera);
    }

    FileInput in_;
    ReaderOptions opt_;
    Number columns16_[16];
    Size size_;
    std::string line_;
    int64 lineOffset_ = 0;
    int lineNumber_ = 0;
    int columns_ = 0;
    int camera_ = -1;
    double timeScale_ = 1.0;
    bool integerTime_ = true;
    bool havePending_ = false;
};

}  // namespace

Ptr<EventReader> openTextReader(const String& path, const ReaderOptions& options)
{
    return makePtr<TextReader>(path, options);
}

}  // namespace detail
}  // namespace event
}  // namespace cv
