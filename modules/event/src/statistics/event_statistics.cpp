// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"

#include <cmath>
#include <limits>

namespace cv {
namespace event {
namespace detail {
namespace {

const int64 kNoEvent = std::numeric_limits<int64>::min();

// Intervals in geometric bins 2 % wide from 1 us (bin 0 holds 0..1 us) up to about 10^4 s.
const double kIntervalBinRatio = 1.02;
const int kIntervalBins = 1200;

class EventStatisticsImpl CV_FINAL : public EventStatistics
{
public:
    explicit EventStatisticsImpl(Size size) : size_(size)
    {
        if (size.width <= 0 || size.height <= 0 || size.width > SHRT_MAX + 1 || size.height > SHRT_MAX + 1)
            CV_Error_(Error::StsBadArg, ("EventStatistics: sensor size %d x %d is not a valid pixel array",
                                         size.width, size.height));
        reset();
    }

    void update(InputArray events) CV_OVERRIDE
    {
        Mat_<Event> ev = getEventMat(events);
        const Event* e = ev.empty() ? nullptr : ev[0];
        const int n = (int)ev.total();
        // Validate first so that a bad packet leaves the statistics as they were.
        int64 previous = lastTime_;
        for (int i = 0; i < n; i++)
        {
            if ((unsigned)e[i].x >= (unsigned)size_.width || (unsigned)e[i].y >= (unsigned)size_.height)
                CV_Error_(Error::StsOutOfRange, ("EventStatistics: event #%d at (x=%d, y=%d), t=%lld us, is outside "
                                                 "the %d x %d sensor", i, e[i].x, e[i].y, (long long)e[i].t,
                                                 size_.width, size_.height));
            if (e[i].t == kNoEvent || (previous != kNoEvent && e[i].t < previous))
                CV_Error_(Error::StsBadArg, ("EventStatistics: event #%d at (x=%d, y=%d), t=%lld us, goes back in "
                                             "time (previous event at %lld us)", i, e[i].x, e[i].y,
                                             (long long)e[i].t, (long long)previous));
            previous = e[i].t;
        }
        for (int i = 0; i < n; i++)
            add(e[i]);
    }

    EventStreamStatistics getStatistics() const CV_OVERRIDE
    {
        EventStreamStatistics s;
        s.events = (double)events_;
        if (events_ == 0)
            return s;
        s.durationUs = (double)(lastTime_ - firstTime_);
        s.eventRate = s.durationUs > 0 ? s.events / (s.durationUs * 1e-6) : 0;
        s.onShare = (double)on_ / s.events;
        s.eventsPerCrossing = s.events / (double)runs_;
        s.intervalP10Us = intervalPercentile(0.10);
        s.intervalMedianUs = intervalPercentile(0.50);
        s.intervalP90Us = intervalPercentile(0.90);
        s.isolatedShare = (double)isolated_ / s.events;
        const double windows = (double)(window_ + 1);
        s.activePixelShare = ((double)activeSum_ + (double)activeInWindow_) / windows / (double)size_.area();
        return s;
    }

    void reset() CV_OVERRIDE
    {
        const size_t area = (size_t)size_.area();
        lastAt_.assign(area, kNoEvent);
        lastPolarity_.assign(area, 0);
        lastWindow_.assign(area, -1);
        intervals_.assign(kIntervalBins, 0);
        events_ = on_ = runs_ = isolated_ = intervalCount_ = 0;
        firstTime_ = lastTime_ = kNoEvent;
        window_ = 0;
        activeSum_ = activeInWindow_ = 0;
    }

    Size getSensorSize() const CV_OVERRIDE { return size_; }
    double getCrossingGap() const CV_OVERRIDE { return (double)crossingGap_; }
    void setCrossingGap(double us) CV_OVERRIDE { crossingGap_ = checkedWindow("crossing gap", us); reset(); }
    double getIsolationWindow() const CV_OVERRIDE { return (double)isolationWindow_; }
    void setIsolationWindow(double us) CV_OVERRIDE { isolationWindow_ = checkedWindow("isolation window", us); reset(); }
    double getActivityWindow() const CV_OVERRIDE { return (double)activityWindow_; }
    void setActivityWindow(double us) CV_OVERRIDE
    {
        activityWindow_ = checkedWindow("activity window", us);
        if (activityWindow_ == 0)
            CV_Error(Error::StsBadArg, "EventStatistics: the activity window must be at least 1 us");
        reset();
    }

    void write(FileStorage& fs) const CV_OVERRIDE
    {
        writeFormat(fs);
        fs << "crossingGap" << (double)crossingGap_ << "isolationWindow" << (double)isolationWindow_
           << "activityWindow" << (double)activityWindow_;
    }

    void read(const FileNode& fn) CV_OVERRIDE
    {
        if (!fn["crossingGap"].empty())
            setCrossingGap((double)fn["crossingGap"]);
        if (!fn["isolationWindow"].empty())
            setIsolationWindow((double)fn["isolationWindow"]);
        if (!fn["activityWindow"].empty())
            setActivityWindow((double)fn["activityWindow"]);
    }

    String getDefaultName() const CV_OVERRIDE { return "EventStatistics"; }

private:
    static int64 checkedWindow(const char* what, double us)
    {
        if (!(us >= 0 && us <= 1e12))
            CV_Error_(Error::StsBadArg, ("EventStatistics: %s of %g us; expected 0 .. 1e12 us", what, us));
        return (int64)std::llround(us);
    }

    void add(const Event& e)
    {
        const size_t i = (size_t)e.y * (size_t)size_.width + (size_t)e.x;
        if (events_ == 0)
            firstTime_ = e.t;
        lastTime_ = e.t;
        events_++;
        on_ += e.p ? 1 : 0;

        // Edge crossings: a new run unless the pixel's last event has this polarity and is recent enough.
        const int64 last = lastAt_[i];
        if (last == kNoEvent || lastPolarity_[i] != e.p || e.t - last > crossingGap_)
            runs_++;
        if (last != kNoEvent)
            addInterval(e.t - last);

        // Isolated: no event at any of the 8 neighbours within the isolation window before this one.
        bool supported = false;
        for (int dy = -1; dy <= 1 && !supported; dy++)
        {
            const int y = e.y + dy;
            if (y < 0 || y >= size_.height)
                continue;
            for (int dx = -1; dx <= 1; dx++)
            {
                const int x = e.x + dx;
                if ((dx == 0 && dy == 0) || x < 0 || x >= size_.width)
                    continue;
                const int64 t = lastAt_[(size_t)y * (size_t)size_.width + (size_t)x];
                if (t != kNoEvent && e.t - t <= isolationWindow_)
                {
                    supported = true;
                    break;
                }
            }
        }
        isolated_ += supported ? 0 : 1;

        // Active pixels per window: windows counted from the first event; empty windows count as 0.
        const int64 window = (e.t - firstTime_) / activityWindow_;
        if (window != window_)
        {
            activeSum_ += activeInWindow_;
            activeInWindow_ = 0;
            window_ = window;
        }
        if (lastWindow_[i] != window)
        {
            lastWindow_[i] = window;
            activeInWindow_++;
        }

        lastAt_[i] = e.t;
        lastPolarity_[i] = e.p;
    }

    void addInterval(int64 dt)
    {
        int bin = 0;
        if (dt >= 1)
            bin = std::min(kIntervalBins - 1, 1 + (int)std::floor(std::log((double)dt) / std::log(kIntervalBinRatio)));
        intervals_[(size_t)bin]++;
        intervalCount_++;
    }

    // The geometric middle of the bin holding the share @p q of the intervals (0 for the 0..1 us bin).
    double intervalPercentile(double q) const
    {
        if (intervalCount_ == 0)
            return 0;
        const double target = q * (double)intervalCount_;
        double seen = 0;
        for (int b = 0; b < kIntervalBins; b++)
        {
            seen += (double)intervals_[(size_t)b];
            if (seen >= target && intervals_[(size_t)b] > 0)
                return b == 0 ? 0.5 : std::pow(kIntervalBinRatio, (double)(b - 1) + 0.5);
        }
        return std::pow(kIntervalBinRatio, (double)(kIntervalBins - 1));
    }

    Size size_;
    int64 crossingGap_ = 5000, isolationWindow_ = 10000, activityWindow_ = 10000;
    std::vector<int64> lastAt_, lastWindow_;
    std::vector<uchar> lastPolarity_;
    std::vector<int64> intervals_;
    int64 events_ = 0, on_ = 0, runs_ = 0, isolated_ = 0, intervalCount_ = 0;
    int64 firstTime_ = kNoEvent, lastTime_ = kNoEvent;
    int64 window_ = 0, activeSum_ = 0, activeInWindow_ = 0;
};

}  // namespace
}  // namespace detail

Ptr<EventStatistics> EventStatistics::create(Size sensorSize)
{
    return makePtr<detail::EventStatisticsImpl>(sensorSize);
}

}  // namespace event
}  // namespace cv
