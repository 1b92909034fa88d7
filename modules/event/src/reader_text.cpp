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

    Event parse()
    {
        // Parse the columns in place: no allocation per line.
        double values[16];
        const int want = std::min(columns_, 16);
        const char* p = line_.c_str();
        int n = 0;
        int64 tInteger = 0;
        while (n < want)
        {
            while (*p && isSeparator(*p))
                p++;
            if (!*p)
                break;
            char* end = nullptr;
            if (n == opt_.textColumnT && integerTime_)
            {
                tInteger = std::strtoll(p, &end, 10);
                values[n] = (double)tInteger;
            }
            else
                values[n] = std::strtod(p, &end);
            if (end == p || (*end && !isSeparator(*end)))
                formatError(in_.path(), lineOffset_, format("line %d: column %d is not a number: \"%s\"",
                                                            lineNumber_, n + 1, line_.c_str()));
            p = end;
            n++;
        }
        if (n < want)
            formatError(in_.path(), lineOffset_, format("line %d: %d columns, expected %d: \"%s\"", lineNumber_, n,
                                                        columns_, line_.c_str()));
        const int64 t = integerTime_ ? tInteger : (int64)std::llround(values[opt_.textColumnT] * timeScale_);
        const int base = opt_.textOneBased ? 1 : 0;
        const double x = values[opt_.textColumnX] - base, y = values[opt_.textColumnY] - base;
        if (!(std::abs(x) < 32768 && std::abs(y) < 32768) || x != std::floor(x) || y != std::floor(y))
            formatError(in_.path(), lineOffset_, format("line %d: coordinates (%g, %g) are not pixel indices",
                                                        lineNumber_, values[opt_.textColumnX],
                                                        values[opt_.textColumnY]));
        int camera = CAMERA_LEFT;
        if (camera_ >= 0)
        {
            const int c = (int)values[camera_];
            const int other = opt_.textLeftCameraValue == 0 ? 1 : 0;
            if (c == opt_.textLeftCameraValue)
                camera = CAMERA_LEFT;
            else if (c == other)
                camera = CAMERA_RIGHT;
            else
                formatError(in_.path(), lineOffset_, format("line %d: camera value %d; expected %d (left) or %d (right)",
                                                            lineNumber_, c, opt_.textLeftCameraValue, other));
        }
        return Event(t, (int)x, (int)y, values[opt_.textColumnP] > 0 ? POLARITY_ON : POLARITY_OFF, camera);
    }

    FileInput in_;
    ReaderOptions opt_;
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
