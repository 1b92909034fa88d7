// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"
#include "filters/event_filter_engine.hpp"

namespace cv {
namespace event {
namespace detail {
namespace {

class RefractoryFilterImpl CV_FINAL : public EventFilterEngine<RefractoryFilter>
{
public:
    RefractoryFilterImpl(Size size, double periodUs)
    {
        setPeriod(periodUs);
        setSensorSize(size);
    }

    double getPeriod() const CV_OVERRIDE { return (double)period_; }
    void setPeriod(double us) CV_OVERRIDE { period_ = positiveMicroseconds(us, "period"); }

    void write(FileStorage& fs) const CV_OVERRIDE
    {
        writeSensorSize(fs);
        fs << "period" << (double)period_;
    }

    void read(const FileNode& fn) CV_OVERRIDE
    {
        if (!fn["period"].empty())
            setPeriod((double)fn["period"]);
        readSensorSize(fn);
    }

    String getDefaultName() const CV_OVERRIDE { return "RefractoryFilter"; }

protected:
    void resetState() CV_OVERRIDE
    {
        for (std::vector<int64>& t : lastKept_)
            std::fill(t.begin(), t.end(), NEVER);
    }

    void addCamera(int camera) CV_OVERRIDE { lastKept_[camera].assign((size_t)pixelCount(), NEVER); }

    int decide(const Event* e, int n, uchar* keep) CV_OVERRIDE
    {
        const int w = size_.width;
        int kept = 0;
        for (int i = 0; i < n; i++)
        {
            int64& last = lastKept_[e[i].camera][(size_t)e[i].y * w + e[i].x];
            const bool alive = last <= timeBefore(e[i].t, period_);
            keep[i] = alive ? 255 : 0;
            kept += alive;
            if (alive)
                last = e[i].t;
        }
        return kept;
    }

private:
    int64 period_ = 1000;
    std::vector<int64> lastKept_[2];
};

}  // namespace
}  // namespace detail

Ptr<RefractoryFilter> RefractoryFilter::create(Size sensorSize, double periodUs)
{
    return makePtr<detail::RefractoryFilterImpl>(sensorSize, periodUs);
}

}  // namespace event
}  // namespace cv
