// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Text recordings: one event per line, columns separated by blanks, tabs or commas.
//  - RPG Event Camera Dataset: `t x y p`, t in seconds, p in {0, 1};
//  - E2VID-style: a first line `width height`, then `t x y p`;
//  - TUM stereo DVS128 recordings: `t_us x y p retina`, 1-based x and y;
// Lines starting with '#' or '%' are comments. Column order, time unit, 1-based coordinates and the camera
// column are options (EVENT_CAP_PROP_TEXT_*).

#include "precomp.hpp"
#include "io/event_reader.hpp"
#include "io/file_input.hpp"

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
    double ownShare() const CV_OVERRIDE
    {
        return opt_.cameraFilter >= 0 && in_.size() > 0 ? (double)ownBytes_ / (double)in_.size() : -1.0;
    }

    bool next(std::vector<Event>& out) CV_OVERRIDE
    {
        size_t produced = 0;
        out.reserve(out.size() + kReaderChunk);
        while (produced < kReaderChunk)
        {
            if (havePending_)
            {
                havePending_ = false;
                const size_t n = line_.size();
                line_.append(FileInput::kReadPadding, '\0');  // readable past the end, as the buffer's lines
                begin_ = line_.data();
                end_ = begin_ + n;
            }
            else
            {
                lineOffset_ = in_.offset();
                // The line stays in the file's buffer: no copy on the hot path.
                if (!in_.readLineView(begin_, end_, line_))
                    break;
                lineNumber_++;
                if (isComment(begin_, end_))
                    continue;
            }
            // Parsed straight into the output: an Event built on the stack in narrow stores and copied with one
            // wide load stalled on store forwarding (a fifth of the reader's time).
            out.emplace_back();
            try
            {
                parse(out.back());
            }
            catch (const cv::Exception&)
            {
                out.pop_back();  // what was parsed of the bad line is no event; the lines before it are delivered
                throw;
            }
            if (opt_.cameraFilter >= 0 && out.back().camera != opt_.cameraFilter)
            {
                out.pop_back();
                continue;
            }
            ownBytes_ += in_.offset() - lineOffset_;
            produced++;
        }
        return produced > 0;
    }

private:
    static bool isComment(const std::string& line)
    {
        return isComment(line.data(), line.data() + line.size());
    }

    static bool isComment(const char* p, const char* end)
    {
        while (p < end && (*p == ' ' || *p == '\t'))
            p++;
        return p == end || *p == '#' || *p == '%';
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

    // Up to 8 leading decimal digits of the 8 bytes at p, read as one word (the line is followed by
    // FileInput::kReadPadding readable bytes): their count (clamped to `end`, -1 when the clamp cuts a digit
    // run, so that the caller takes the byte-wise path) and their value.
    static int wordDigits(const char* p, const char* end, int64& value)
    {
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__ && defined(__GNUC__)
        uint64 v;
        std::memcpy(&v, p, 8);
        const uint64 x = v ^ 0x3030303030303030ULL;  // digits become 0..9
        // A byte is not a digit when its high nibble is set or it is 10..15. Carries of the addition start
        // only at non-digits and move to later bytes, so the first non-digit is found exactly.
        const uint64 nonDigit = (x & 0xF0F0F0F0F0F0F0F0ULL) | ((x + 0x0606060606060606ULL) & 0x1010101010101010ULL);
        const int k = nonDigit ? __builtin_ctzll(nonDigit) / 8 : 8;
        if (k > end - p)
            return -1;
        if (k == 0)
        {
            value = 0;
            return 0;
        }
        uint64 d = x << (8 * (8 - k));  // right-aligned: leading zero digits
        d = d * 10 + (d >> 8);
        d = (((d & 0x000000FF000000FFULL) * (100 + (1000000ULL << 32))) +
             (((d >> 16) & 0x000000FF000000FFULL) * (1 + (10000ULL << 32)))) >> 32;
        value = (int64)d;
        return k;
#else
        (void)p; (void)end; (void)value;
        return -1;
#endif
    }

    // Digits at p into `acc` (at most `limit` of them in all, counted in `count`); returns the stop.
    static const char* scanDigits(const char* p, const char* end, int64& acc, int& count, int limit)
    {
        static const int64 pow10[9] = { 1, 10, 100, 1000, 10000, 100000, 1000000, 10000000, 100000000 };
        while (count + 8 <= limit)
        {
            int64 v;
            const int k = wordDigits(p, end, v);
            if (k < 0)
                break;
            acc = acc * pow10[k] + v;
            count += k;
            p += k;
            if (k < 8)
                return p;
        }
        while (p < end && *p >= '0' && *p <= '9' && count < limit)
        {
            acc = acc * 10 + (*p++ - '0');
            count++;
        }
        return p;
    }

    // Scans one number in [p, end); returns where it stops (p itself when there is none).
    static const char* scanNumber(const char* p, const char* end, Number& n)
    {
        const char* start = p;
        bool negative = false;
        if (p < end && (*p == '-' || *p == '+'))
            negative = *p++ == '-';
        int digits = 0;
        int64 whole = 0;
        p = scanDigits(p, end, whole, digits, 18);
        int64 frac = 0;
        int fracDigits = 0;
        const bool point = p < end && *p == '.';
        if (point)
            p = scanDigits(p + 1, end, frac, fracDigits, 18);
        if ((digits == 0 && fracDigits == 0) || (p < end && ((*p >= '0' && *p <= '9') || *p == 'e' || *p == 'E')))
        {
            // Exponent, or more digits than the fast path keeps: let strtod decide, on a terminated copy.
            char token[64];
            const size_t len = std::min<size_t>(sizeof(token) - 1, (size_t)(end - start));
            std::memcpy(token, start, len);
            token[len] = '\0';
            char* stop = nullptr;
            n.value = std::strtod(token, &stop);
            n.integral = false;
            n.fracDigits = -1;  // no exact decimal form
            return start + (stop - token);
        }
        n.integral = !point;
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
                                                        n.value, lineText().c_str()));
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

    // The camera a camera-column value names (the left camera's value is 0 or 1, the right one's the other), or
    // -1 when it names neither.
    int cameraOf(int64 value) const
    {
        return value == opt_.textLeftCameraValue ? CAMERA_LEFT : value == 1 - opt_.textLeftCameraValue ? CAMERA_RIGHT : -1;
    }

    // The common layout, every column a plain unsigned integer and the time in microseconds, read straight
    // into integers (no Number, no double). Anything else on the line (a sign, a fraction, an exponent, more
    // than 18 digits, a coordinate below the base, a malformed column) returns false, and parseGeneral() reads
    // the line again and decides, with its error messages: the two agree on every line this path accepts.
    bool parseIntegers(Event& e) const
    {
        int64 v[16];
        const int want = std::min(columns_, 16);
        const char* p = begin_;
        for (int n = 0; n < want; n++)
        {
            while (p < end_ && isSeparator(*p))
                p++;
            int64 acc = 0;
            // Most columns fit one word: read it directly (scanDigits alone costs 8 % more instructions here).
            int digits = wordDigits(p, end_, acc);
            const char* stop = p + digits;
            if (digits == 8 || digits < 0)
            {
                acc = 0;
                digits = 0;
                stop = scanDigits(p, end_, acc, digits, 18);
            }
            if (digits == 0 || (stop < end_ && !isSeparator(*stop)))
                return false;
            v[n] = acc;
            p = stop;
        }
        const int base = opt_.textOneBased ? 1 : 0;
        const int64 x = v[opt_.textColumnX] - base, y = v[opt_.textColumnY] - base;
        if (x < 0 || y < 0 || x >= 32768 || y >= 32768)
            return false;
        int camera = CAMERA_LEFT;
        if (camera_ >= 0)
        {
            camera = cameraOf(v[camera_]);
            if (camera < 0)
                return false;
        }
        e.t = v[opt_.textColumnT];
        e.x = (short)x;
        e.y = (short)y;
        e.p = v[opt_.textColumnP] > 0 ? POLARITY_ON : POLARITY_OFF;
        e.camera = (uchar)camera;
        return true;
    }

    void parse(Event& e)
    {
        if (!integerTime_ || !parseIntegers(e))
            e = parseGeneral();
    }

    Event parseGeneral()
    {
        // Parse the columns in place: no allocation per line (and the columns are a member: constructing 16 of
        // them per line took 40 % of the reader's time).
        Number* values = columns16_;
        const int want = std::min(columns_, 16);
        const char* p = begin_;
        int n = 0;
        while (n < want)
        {
            while (p < end_ && isSeparator(*p))
                p++;
            if (p == end_)
                break;
            const char* end = scanNumber(p, end_, values[n]);
            if (end == p || (end < end_ && !isSeparator(*end)))
                formatError(in_.path(), lineOffset_, format("line %d: column %d is not a number: \"%s\"",
                                                            lineNumber_, n + 1, lineText().c_str()));
            p = end;
            n++;
        }
        if (n < want)
            formatError(in_.path(), lineOffset_, format("line %d: %d columns, expected %d: \"%s\"", lineNumber_, n,
                                                        columns_, lineText().c_str()));
        const Number& tn = values[opt_.textColumnT];
        if (integerTime_ && !tn.integral)
            formatError(in_.path(), lineOffset_, format("line %d: timestamp \"%s\" is not an integer number of "
                                                        "microseconds, as the first line's was", lineNumber_, lineText().c_str()));
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
                                                            cn.value, lineText().c_str()));
            const int c = (int)cn.value;
            camera = cameraOf(c);
            if (camera < 0)
                formatError(in_.path(), lineOffset_, format("line %d: camera value %d; expected %d (left) or %d (right)",
                                                            lineNumber_, c, opt_.textLeftCameraValue,
                                                            1 - opt_.textLeftCameraValue));
        }
        return Event(t, (int)x, (int)y, values[opt_.textColumnP].value > 0 ? POLARITY_ON : POLARITY_OFF, camera);
    }

    FileInput in_;
    ReaderOptions opt_;
    Number columns16_[16];
    Size size_;
    std::string line_;                            // header lines, and lines that cross a buffer refill
    const char* begin_ = nullptr, *end_ = nullptr;  // the line being parsed
    std::string lineText() const { return std::string(begin_, end_); }  // for messages
    int64 lineOffset_ = 0;
    int64 ownBytes_ = 0;  // bytes of the lines delivered (of this reader's camera, with a camera filter)
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
