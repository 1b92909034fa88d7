// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"
#include "common/timestamp_math.hpp"
#include "common/sensor_bounds.hpp"

#include <limits>

namespace cv {
namespace event {

const int64 EventSurface::NO_EVENT;

namespace detail {
namespace {

class EventSurfaceImpl CV_FINAL : public EventSurface
{
public:
    explicit EventSurfaceImpl(Size size) { setSensorSize(size); }

    Size getSensorSize() const CV_OVERRIDE { return size_; }

    void setSensorSize(Size size) CV_OVERRIDE
    {
        if (size.width <= 0 || size.height <= 0 || size.width > SHRT_MAX + 1 || size.height > SHRT_MAX + 1)
            CV_Error_(Error::StsBadArg, ("EventSurface: sensor size %d x %d is not a valid pixel array",
                                         size.width, size.height));
        size_ = size;
        const size_t plane = (size_t)size.area();
        times_.assign(2 * plane, NO_EVENT);
        counts_.assign(2 * plane, 0);
        total_ = 0;
    }

    void update(InputArray events) CV_OVERRIDE
    {
        Mat_<Event> ev = getEventMat(events);
        const Event* e = ev.empty() ? nullptr : ev[0];
        const int n = (int)ev.total();
        // Validate first so that a bad packet leaves the surface as it was.
        for (int i = 0; i < n; i++)
            if (!inside(e[i]))
                outOfRange(e[i], i);
        for (int i = 0; i < n; i++)
            store(e[i]);
        total_ += n;
    }

    void update(const Event& e) CV_OVERRIDE
    {
        if (!inside(e))
            outOfRange(e, -1);
        store(e);
        total_++;
    }

    void reset() CV_OVERRIDE
    {
        std::fill(times_.begin(), times_.end(), NO_EVENT);
        clearCounts();
        total_ = 0;
    }

    void clearCounts() CV_OVERRIDE { std::fill(counts_.begin(), counts_.end(), 0); }

    int64 at(int x, int y, int polarity) const CV_OVERRIDE
    {
        checkPixel(x, y);
        return times_[index(x, y, polarity ? 1 : 0)];
    }

    int64 latest(int x, int y) const CV_OVERRIDE
    {
        checkPixel(x, y);
        return std::max(times_[index(x, y, 0)], times_[index(x, y, 1)]);
    }

    const int64* ptr(int polarity, int y) const CV_OVERRIDE
    {
        CV_CheckGE(y, 0, "EventSurface::ptr: row outside the sensor");
        CV_CheckLT(y, size_.height, "EventSurface::ptr: row outside the sensor");
        return &times_[index(0, y, checkPolarity(polarity, false))];
    }

    void getSurface(int polarity, OutputArray surface, int ddepth, double originUs) const CV_OVERRIDE
    {
        // Clamped into int64 before the conversion (out of range it would be undefined); the differences are
        // then taken in int64 where they fit, so that timestamps near 2^63 keep their microseconds.
        const int64 origin = (int64)std::llround(std::max(-9.2233720368547748e18, std::min(9.2233720368547748e18, originUs)));
        CV_CheckType(ddepth, ddepth == CV_64F || ddepth == CV_32S, "EventSurface::getSurface: CV_64F or CV_32S");
        const int p = checkPolarity(polarity, true);
        surface.create(size_, ddepth);
        Mat out = surface.getMat();
        for (int y = 0; y < size_.height; y++)
        {
            for (int x = 0; x < size_.width; x++)
            {
                const int64 t = p < 0 ? std::max(times_[index(x, y, 0)], times_[index(x, y, 1)])
                                      : times_[index(x, y, p)];
                if (ddepth == CV_64F)
                    out.at<double>(y, x) = t == NO_EVENT ? -std::numeric_limits<double>::infinity()
                                                         : timeDifference(t, origin);
                else
                    out.at<int>(y, x) = t == NO_EVENT ? INT_MIN
                                                      : (int)std::max<double>(INT_MIN + 1, std::min<double>(INT_MAX, timeDifference(t, origin)));
            }
        }
    }

    void renderTimeSurface(double tUs, double tau, OutputArray dst, int ddepth, int polarity) const CV_OVERRIDE
    {
        const double t = tUs;
        CV_CheckType(ddepth, ddepth == CV_8U || ddepth == CV_32F, "EventSurface::renderTimeSurface: CV_8U or CV_32F");
        if (!(tau > 0))
            CV_Error_(Error::StsBadArg, ("EventSurface::renderTimeSurface: tau must be > 0 us, got %g", tau));
        const int p = checkPolarity(polarity, true);
        Mat_<float> values(size_);
        const double invTau = 1.0 / tau;
        for (int y = 0; y < size_.height; y++)
        {
            float* row = values[y];
            for (int x = 0; x < size_.width; x++)
            {
                const int64 last = p < 0 ? std::max(times_[index(x, y, 0)], times_[index(x, y, 1)])
                                         : times_[index(x, y, p)];
                row[x] = (last == NO_EVENT || (double)last > t) ? 0.f : (float)std::exp(-(t - (double)last) * invTau);
            }
        }
        if (ddepth == CV_32F)
            values.copyTo(dst);
        else
            values.convertTo(dst, CV_8U, 255.0);
    }

    void renderEventCount(OutputArray dst, int polarity) const CV_OVERRIDE
    {
        if (polarity < -2 || polarity > 1)
            CV_Error_(Error::StsBadArg, ("EventSurface::renderEventCount: polarity %d; expected 0, 1, -1 (sum) "
                                         "or -2 (ON - OFF)", polarity));
        dst.create(size_, CV_32S);
        Mat_<int> out = dst.getMat();
        const size_t plane = (size_t)size_.area();
        int* o = out[0];
        for (size_t i = 0; i < plane; i++)
        {
            const int off = counts_[i], on = counts_[plane + i];
            o[i] = polarity == POLARITY_OFF ? off : polarity == POLARITY_ON ? on : polarity == -1 ? on + off : on - off;
        }
    }

    double getEventCount() const CV_OVERRIDE { return (double)total_; }

    void write(FileStorage& fs) const CV_OVERRIDE
    {
        writeFormat(fs);
        fs << "sensorWidth" << size_.width << "sensorHeight" << size_.height;
    }

    void read(const FileNode& fn) CV_OVERRIDE
    {
        const int w = fn["sensorWidth"].empty() ? size_.width : (int)fn["sensorWidth"];
        const int h = fn["sensorHeight"].empty() ? size_.height : (int)fn["sensorHeight"];
        if (w != size_.width || h != size_.height)
            setSensorSize(Size(w, h));
    }

    String getDefaultName() const CV_OVERRIDE { return "EventSurface"; }

private:
    // Inside the sensor, and not at INT64_MIN, which is NO_EVENT: stored, it would make the pixel look empty.
    bool inside(const Event& e) const
    {
        return onSensor(e.x, e.y, size_) && e.t != NO_EVENT;
    }

    void outOfRange(const Event& e, int index) const
    {
        CV_Error_(Error::StsOutOfRange,
                  ("EventSurface: event%s%s at (x=%d, y=%d), t=%lld us, is %s", index >= 0 ? " #" : "",
                   index >= 0 ? std::to_string(index).c_str() : "", e.x, e.y, (long long)e.t,
                   e.t == NO_EVENT ? "at INT64_MIN, the reserved NO_EVENT time"
                                   : cv::format("outside the %d x %d sensor", size_.width, size_.height).c_str()));
    }

    void checkPixel(int x, int y) const
    {
        if (!onSensor(x, y, size_))
            CV_Error_(Error::StsOutOfRange, ("EventSurface: pixel (%d, %d) is outside the %d x %d sensor", x, y,
                                             size_.width, size_.height));
    }

    static int checkPolarity(int polarity, bool allowBoth)
    {
        if (polarity == POLARITY_OFF || polarity == POLARITY_ON || (allowBoth && polarity == -1))
            return polarity;
        CV_Error_(Error::StsBadArg, ("EventSurface: polarity %d; expected 0 (OFF), 1 (ON)%s", polarity,
                                     allowBoth ? " or -1 (both)" : ""));
    }

    size_t index(int x, int y, int p) const
    {
        return (size_t)p * size_.area() + (size_t)y * size_.width + x;
    }

    void store(const Event& e)
    {
        const size_t i = index(e.x, e.y, e.p ? 1 : 0);
        times_[i] = e.t;
        counts_[i]++;
    }

    Size size_;
    std::vector<int64> times_;   // [polarity][y][x]
    std::vector<int> counts_;    // [polarity][y][x], since clearCounts()
    int64 total_ = 0;
};

}  // namespace
}  // namespace detail

Ptr<EventSurface> EventSurface::create(Size sensorSize)
{
    return makePtr<detail::EventSurfaceImpl>(sensorSize);
}

}  // namespace event
}  // namespace cv
