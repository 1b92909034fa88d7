// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"
#include "filters/event_filter_engine.hpp"

namespace cv {
namespace event {
namespace detail {
namespace {

const char* const CAMERA_MASK_NAMES[2] = { "maskLeft", "maskRight" };

class HotPixelFilterImpl CV_FINAL : public EventFilterEngine<HotPixelFilter>
{
public:
    HotPixelFilterImpl(Size size, double minRateHz, double relativeRate)
    {
        setMinRate(minRateHz);
        setRelativeRate(relativeRate);
        setSensorSize(size);
    }

    void setSensorSize(Size size) CV_OVERRIDE
    {
        EventFilterEngine<HotPixelFilter>::setSensorSize(size);
        // The masks are per pixel: a new sensor size makes them meaningless.
        for (int c = 0; c < 2; c++)
        {
            masks_[c].assign((size_t)pixelCount(), (uchar)0);
            counts_[c].assign((size_t)pixelCount(), 0u);
        }
        learning_ = true;
    }

    void learn(InputArray events) CV_OVERRIDE
    {
        Mat_<Event> ev = getEventMat(events);
        const int n = (int)ev.total();
        const Event* e = n ? ev[0] : nullptr;
        int64 last[2] = { learnLast_[0], learnLast_[1] };
        validate(e, n, last);
        count(e, n);
    }

    int detect() CV_OVERRIDE
    {
        int hot = 0;
        for (int c = 0; c < 2; c++)
        {
            std::fill(masks_[c].begin(), masks_[c].end(), (uchar)0);
            if (learnFirst_[c] == NEVER)
                continue;
            const std::vector<uint32_t>& k = counts_[c];
            // A span of at least 1 ms: a rate needs time, and a packet of one instant has none.
            const double seconds = std::max(1e-3, timeDifference(learnLast_[c], learnFirst_[c]) * 1e-6);
            const double least = minRate_ * seconds;
            const int w = size_.width, h = size_.height;
            for (int y = 0; y < h; y++)
                for (int x = 0; x < w; x++)
                {
                    const uint32_t v = k[(size_t)y * w + x];
                    if (v == 0 || (double)v < least)
                        continue;
                    // The scene makes neighbours fire together; a hot pixel stands out from its own
                    // neighbourhood. The mean is floored at one event, so that a few chance events among
                    // silent neighbours do not make a pixel hot.
                    double sum = 0;
                    int neighbours = 0;
                    for (int dy = -1; dy <= 1; dy++)
                        for (int dx = -1; dx <= 1; dx++)
                        {
                            const int xx = x + dx, yy = y + dy;
                            if ((dx == 0 && dy == 0) || xx < 0 || yy < 0 || xx >= w || yy >= h)
                                continue;
                            sum += k[(size_t)yy * w + xx];
                            neighbours++;
                        }
                    const double neighbourMean = std::max(1.0, sum / std::max(1, neighbours));
                    if ((double)v >= relativeRate_ * neighbourMean)
                    {
                        masks_[c][(size_t)y * w + x] = 255;
                        hot++;
                    }
                }
        }
        return hot;
    }

    void getMask(OutputArray mask, int camera) const CV_OVERRIDE
    {
        checkCamera(camera);
        Mat(size_, CV_8U, (void*)masks_[camera].data()).copyTo(mask);
    }

    void setMask(InputArray mask, int camera) CV_OVERRIDE
    {
        checkCamera(camera);
        Mat m = mask.getMat();
        if (m.size() != size_ || m.type() != CV_8UC1)
            CV_Error_(Error::StsBadArg, ("HotPixelFilter: a mask must be %d x %d CV_8UC1 (the sensor); got %d x %d of "
                                         "type %s", size_.width, size_.height, m.cols, m.rows,
                                         typeToString(m.type()).c_str()));
        Mat target(size_, CV_8U, masks_[camera].data());
        compare(m, 0, target, CMP_NE);
    }

    void clearMasks() CV_OVERRIDE
    {
        for (std::vector<uchar>& m : masks_)
            std::fill(m.begin(), m.end(), (uchar)0);
    }

    int getHotPixelCount() const CV_OVERRIDE
    {
        int hot = 0;
        for (const std::vector<uchar>& m : masks_)
            for (uchar v : m)
                hot += v != 0;
        return hot;
    }

    double getMinRate() const CV_OVERRIDE { return minRate_; }
    void setMinRate(double hz) CV_OVERRIDE
    {
        if (!(hz >= 0) || hz > 1e9)
            CV_Error_(Error::StsBadArg, ("HotPixelFilter: minimum rate %g Hz; must be >= 0", hz));
        minRate_ = hz;
    }

    double getRelativeRate() const CV_OVERRIDE { return relativeRate_; }
    void setRelativeRate(double ratio) CV_OVERRIDE
    {
        if (!(ratio >= 1) || ratio > 1e9)
            CV_Error_(Error::StsBadArg, ("HotPixelFilter: relative rate %g; must be >= 1 (a hot pixel fires more "
                                         "than its neighbours)", ratio));
        relativeRate_ = ratio;
    }

    double getLearningTime() const CV_OVERRIDE { return (double)learningTime_; }
    void setLearningTime(double us) CV_OVERRIDE
    {
        learningTime_ = us == 0 ? 0 : positiveMicroseconds(us, "learning time");
        learning_ = true;
    }

    void write(FileStorage& fs) const CV_OVERRIDE
    {
        writeSensorSize(fs);
        fs << "minRate" << minRate_
           << "relativeRate" << relativeRate_ << "learningTime" << (double)learningTime_;
        for (int c = 0; c < 2; c++)
            fs << CAMERA_MASK_NAMES[c] << Mat(size_, CV_8U, (void*)masks_[c].data());
    }

    void read(const FileNode& fn) CV_OVERRIDE
    {
        if (!fn["minRate"].empty())
            setMinRate((double)fn["minRate"]);
        if (!fn["relativeRate"].empty())
            setRelativeRate((double)fn["relativeRate"]);
        if (!fn["learningTime"].empty())
            setLearningTime((double)fn["learningTime"]);
        readSensorSize(fn);
        for (int c = 0; c < 2; c++)
        {
            if (fn[CAMERA_MASK_NAMES[c]].empty())
                continue;
            Mat m;
            fn[CAMERA_MASK_NAMES[c]] >> m;
            setMask(m, c);
        }
    }

    String getDefaultName() const CV_OVERRIDE { return "HotPixelFilter"; }

protected:
    void resetState() CV_OVERRIDE
    {
        for (std::vector<uint32_t>& k : counts_)
            std::fill(k.begin(), k.end(), 0u);
        learnFirst_[0] = learnFirst_[1] = learnLast_[0] = learnLast_[1] = NEVER;
        streamStart_ = NEVER;
        learning_ = true;
    }

    void addCamera(int) CV_OVERRIDE {}  // the masks and counts of both cameras come with the sensor size

    int decide(const Event* e, int n, uchar* keep) CV_OVERRIDE
    {
        int i = 0;
        if (learningTime_ > 0 && learning_)
        {
            if (streamStart_ == NEVER)
                streamStart_ = e[0].t;
            const int64 end = timeAfter(streamStart_, learningTime_);
            int m = 0;
            while (m < n && e[m].t < end)
                m++;
            count(e, m);
            std::fill(keep, keep + m, (uchar)255);
            i = m;
            if (m < n)
            {
                detect();
                learning_ = false;
            }
        }
        int kept = i;
        const int w = size_.width;
        for (; i < n; i++)
        {
            const bool cold = masks_[e[i].camera][(size_t)e[i].y * w + e[i].x] == 0;
            keep[i] = cold ? 255 : 0;
            kept += cold;
        }
        return kept;
    }

private:
    void count(const Event* e, int n)
    {
        const int w = size_.width;
        for (int i = 0; i < n; i++)
        {
            const int c = e[i].camera;
            uint32_t& k = counts_[c][(size_t)e[i].y * w + e[i].x];
            k += k != UINT32_MAX;
            if (learnFirst_[c] == NEVER)
                learnFirst_[c] = e[i].t;
            learnLast_[c] = e[i].t;
        }
    }

    void checkCamera(int camera) const
    {
        if (camera != CAMERA_LEFT && camera != CAMERA_RIGHT)
            CV_Error_(Error::StsBadArg, ("HotPixelFilter: camera %d; expected CAMERA_LEFT (0) or CAMERA_RIGHT (1)",
                                         camera));
    }

    double minRate_ = 5, relativeRate_ = 10;
    int64 learningTime_ = 0;
    bool learning_ = true;
    int64 streamStart_ = NEVER;
    int64 learnFirst_[2] = { NEVER, NEVER }, learnLast_[2] = { NEVER, NEVER };
    std::vector<uchar> masks_[2];
    std::vector<uint32_t> counts_[2];
};

}  // namespace
}  // namespace detail

Ptr<HotPixelFilter> HotPixelFilter::create(Size sensorSize, double minRateHz, double relativeRate)
{
    return makePtr<detail::HotPixelFilterImpl>(sensorSize, minRateHz, relativeRate);
}

}  // namespace event
}  // namespace cv
