// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"
#include "filters/event_filter_engine.hpp"

namespace cv {
namespace event {
namespace detail {
namespace {

// A pixel's flicker state: when its last burst of each polarity started, the polarity of its last event,
// and how many periods in a row fell inside the band.
struct FlickerPixel
{
    int64 burstStart[2];
    uchar lastPolarity;  // 2 before the first event
    uchar cycles;
};

class AntiFlickerFilterImpl CV_FINAL : public EventFilterEngine<AntiFlickerFilter>
{
public:
    AntiFlickerFilterImpl(Size size, double minHz, double maxHz)
    {
        setFrequencyBand(minHz, maxHz);
        setSensorSize(size);
    }

    double getMinFrequency() const CV_OVERRIDE { return minHz_; }
    double getMaxFrequency() const CV_OVERRIDE { return maxHz_; }

    void setFrequencyBand(double minHz, double maxHz) CV_OVERRIDE
    {
        if (!(minHz > 0) || !(maxHz > minHz) || maxHz > 1e6)
            CV_Error_(Error::StsBadArg, ("AntiFlickerFilter: band %g..%g Hz; needs 0 < min < max <= 1 MHz", minHz, maxHz));
        minHz_ = minHz;
        maxHz_ = maxHz;
        shortestPeriod_ = (int64)std::ceil(1e6 / maxHz);
        longestPeriod_ = (int64)std::floor(1e6 / minHz);
    }

    int getMinCycles() const CV_OVERRIDE { return minCycles_; }
    void setMinCycles(int cycles) CV_OVERRIDE
    {
        if (cycles < 1 || cycles > 255)
            CV_Error_(Error::StsBadArg, ("AntiFlickerFilter: minimum cycles %d; must be 1..255", cycles));
        minCycles_ = cycles;
    }

    void write(FileStorage& fs) const CV_OVERRIDE
    {
        writeSensorSize(fs);
        fs << "minFrequency" << minHz_
           << "maxFrequency" << maxHz_ << "minCycles" << minCycles_;
    }

    void read(const FileNode& fn) CV_OVERRIDE
    {
        setFrequencyBand(fn["minFrequency"].empty() ? minHz_ : (double)fn["minFrequency"],
                         fn["maxFrequency"].empty() ? maxHz_ : (double)fn["maxFrequency"]);
        if (!fn["minCycles"].empty())
            setMinCycles((int)fn["minCycles"]);
        readSensorSize(fn);
    }

    String getDefaultName() const CV_OVERRIDE { return "AntiFlickerFilter"; }

protected:
    static FlickerPixel emptyPixel() { return FlickerPixel{ { NEVER, NEVER }, 2, 0 }; }

    void resetState() CV_OVERRIDE
    {
        for (std::vector<FlickerPixel>& p : pixels_)
            std::fill(p.begin(), p.end(), emptyPixel());
    }

    void addCamera(int camera) CV_OVERRIDE { pixels_[camera].assign((size_t)pixelCount(), emptyPixel()); }

    int decide(const Event* e, int n, uchar* keep) CV_OVERRIDE
    {
        const int w = size_.width;
        int kept = 0;
        for (int i = 0; i < n; i++)
        {
            FlickerPixel& px = pixels_[e[i].camera][(size_t)e[i].y * w + e[i].x];
            const int p = e[i].p ? 1 : 0;
            const int64 t = e[i].t;
            if (px.lastPolarity != p)
            {
                // A burst starts: one period since the last burst of this polarity started.
                const int64 previous = px.burstStart[p];
                if (previous != NEVER)
                {
                    const double period = timeDifference(t, previous);
                    const bool inBand = period >= (double)shortestPeriod_ && period <= (double)longestPeriod_;
                    px.cycles = inBand ? (uchar)std::min(255, px.cycles + 1) : (uchar)0;
                }
                px.burstStart[p] = t;
                px.lastPolarity = (uchar)p;
            }
            // Still flickering only while bursts keep coming within the longest period.
            const int64 latestStart = std::max(px.burstStart[0], px.burstStart[1]);
            const bool flickering = px.cycles >= minCycles_ && latestStart >= timeBefore(t, longestPeriod_);
            keep[i] = flickering ? 0 : 255;
            kept += !flickering;
        }
        return kept;
    }

private:
    double minHz_ = 80, maxHz_ = 150;
    int64 shortestPeriod_ = 1, longestPeriod_ = 1;
    int minCycles_ = 3;
    std::vector<FlickerPixel> pixels_[2];
};

}  // namespace
}  // namespace detail

Ptr<AntiFlickerFilter> AntiFlickerFilter::create(Size sensorSize, double minFrequencyHz, double maxFrequencyHz)
{
    return makePtr<detail::AntiFlickerFilterImpl>(sensorSize, minFrequencyHz, maxFrequencyHz);
}

}  // namespace event
}  // namespace cv
