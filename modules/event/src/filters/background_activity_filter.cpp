// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"
#include "filters/event_filter_engine.hpp"

namespace cv {
namespace event {
namespace detail {
namespace {

class BackgroundActivityFilterImpl CV_FINAL : public EventFilterEngine<BackgroundActivityFilter>
{
public:
    BackgroundActivityFilterImpl(Size size, double correlationTimeUs)
    {
        setCorrelationTime(correlationTimeUs);
        setSensorSize(size);
    }

    double getCorrelationTime() const CV_OVERRIDE { return (double)correlationTime_; }
    void setCorrelationTime(double us) CV_OVERRIDE { correlationTime_ = positiveMicroseconds(us, "correlation time"); }

    void write(FileStorage& fs) const CV_OVERRIDE
    {
        writeSensorSize(fs);
        fs << "correlationTime" << (double)correlationTime_;
    }

    void read(const FileNode& fn) CV_OVERRIDE
    {
        if (!fn["correlationTime"].empty())
            setCorrelationTime((double)fn["correlationTime"]);
        readSensorSize(fn);
    }

    String getDefaultName() const CV_OVERRIDE { return "BackgroundActivityFilter"; }

protected:
    // One border pixel all round, never written, so that the 8 neighbours need no bounds checks.
    int stride() const { return size_.width + 2; }

    void resetState() CV_OVERRIDE
    {
        for (std::vector<int64>& t : times_)
            std::fill(t.begin(), t.end(), NEVER);
    }

    void addCamera(int camera) CV_OVERRIDE
    {
        times_[camera].assign((size_t)stride() * (size_.height + 2), NEVER);
    }

    int decide(const Event* e, int n, uchar* keep) CV_OVERRIDE
    {
        const int w = stride();
        int kept = 0;
        for (int i = 0; i < n; i++)
        {
            int64* c = &times_[e[i].camera][(size_t)(e[i].y + 1) * w + e[i].x + 1];
            const int64 since = timeBefore(e[i].t, correlationTime_);
            const int64* up = c - w;
            const int64* down = c + w;
            const int64 newest = std::max(std::max(std::max(up[-1], up[0]), std::max(up[1], c[-1])),
                                          std::max(std::max(c[1], down[-1]), std::max(down[0], down[1])));
            const bool supported = newest >= since;
            keep[i] = supported ? 255 : 0;
            kept += supported;
            *c = e[i].t;
        }
        return kept;
    }

private:
    int64 correlationTime_ = 10000;
    std::vector<int64> times_[2];
};

}  // namespace
}  // namespace detail

Ptr<BackgroundActivityFilter> BackgroundActivityFilter::create(Size sensorSize, double correlationTimeUs)
{
    return makePtr<detail::BackgroundActivityFilterImpl>(sensorSize, correlationTimeUs);
}

}  // namespace event
}  // namespace cv
