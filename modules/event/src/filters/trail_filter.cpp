// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"
#include "filters/event_filter_engine.hpp"

namespace cv {
namespace event {
namespace detail {
namespace {

class TrailFilterImpl CV_FINAL : public EventFilterEngine<TrailFilter>
{
public:
    TrailFilterImpl(Size size, double thresholdUs)
    {
        setThreshold(thresholdUs);
        setSensorSize(size);
    }

    double getThreshold() const CV_OVERRIDE { return (double)threshold_; }
    void setThreshold(double us) CV_OVERRIDE { threshold_ = positiveMicroseconds(us, "threshold"); }

    void write(FileStorage& fs) const CV_OVERRIDE
    {
        writeSensorSize(fs);
        fs << "threshold" << (double)threshold_;
    }

    void read(const FileNode& fn) CV_OVERRIDE
    {
        if (!fn["threshold"].empty())
            setThreshold((double)fn["threshold"]);
        readSensorSize(fn);
    }

    String getDefaultName() const CV_OVERRIDE { return "TrailFilter"; }

protected:
    void resetState() CV_OVERRIDE
    {
        for (int c = 0; c < 2; c++)
        {
            std::fill(times_[c].begin(), times_[c].end(), NEVER);
            std::fill(polarities_[c].begin(), polarities_[c].end(), (uchar)0);
        }
    }

    void addCamera(int camera) CV_OVERRIDE
    {
        times_[camera].assign((size_t)pixelCount(), NEVER);
        polarities_[camera].assign((size_t)pixelCount(), (uchar)0);
    }

    int decide(const Event* e, int n, uchar* keep) CV_OVERRIDE
    {
        const int w = size_.width;
        int kept = 0;
        for (int i = 0; i < n; i++)
        {
            const size_t k = (size_t)e[i].y * w + e[i].x;
            int64& last = times_[e[i].camera][k];
            uchar& polarity = polarities_[e[i].camera][k];
            // NEVER lies before any "since", so a pixel's first event starts a burst.
            const bool starts = last < timeBefore(e[i].t, threshold_) || polarity != e[i].p;
            keep[i] = starts ? 255 : 0;
            kept += starts;
            last = e[i].t;
            polarity = e[i].p;
        }
        return kept;
    }

private:
    int64 threshold_ = 5000;
    std::vector<int64> times_[2];
    std::vector<uchar> polarities_[2];
};

}  // namespace
}  // namespace detail

Ptr<TrailFilter> TrailFilter::create(Size sensorSize, double thresholdUs)
{
    return makePtr<detail::TrailFilterImpl>(sensorSize, thresholdUs);
}

}  // namespace event
}  // namespace cv
