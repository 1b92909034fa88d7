// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_FILTERS_EVENT_FILTER_ENGINE_HPP
#define OPENCV_EVENT_SRC_FILTERS_EVENT_FILTER_ENGINE_HPP

#include "opencv2/event/event_filter.hpp"
#include "common/timestamp_math.hpp"
#include "common/sensor_bounds.hpp"

#include <limits>
#include <vector>

namespace cv {
namespace event {
namespace detail {

/** What every filter shares: the packet's checks, the per-camera time order, the counts and the kept / mask
outputs. A filter implements decide(), which sees only valid events and writes one keep flag per event. */
template<class Interface>
class EventFilterEngine : public Interface
{
public:
    static const int64 NEVER = std::numeric_limits<int64>::min();

    Size getSensorSize() const CV_OVERRIDE { return size_; }

    void setSensorSize(Size size) CV_OVERRIDE
    {
        if (size.width <= 0 || size.height <= 0 || size.width > SHRT_MAX + 1 || size.height > SHRT_MAX + 1)
            CV_Error_(Error::StsBadArg, ("%s: sensor size %d x %d is not a valid pixel array", this->getDefaultName().c_str(),
                                         size.width, size.height));
        size_ = size;
        cameras_ = 0;
        reset();
    }

    void reset() CV_OVERRIDE
    {
        lastTime_[0] = lastTime_[1] = NEVER;
        processed_ = kept_ = 0;
        resetState();
    }

    double getProcessedCount() const CV_OVERRIDE { return processed_; }
    double getKeptCount() const CV_OVERRIDE { return kept_; }

    void filter(InputArray events, OutputArray kept, OutputArray mask) CV_OVERRIDE
    {
        Mat_<Event> ev = getEventMat(events);
        const int n = (int)ev.total();
        const Event* e = n ? ev[0] : nullptr;
        int64 last[2] = { lastTime_[0], lastTime_[1] };
        const int cameras = validate(e, n, last);
        while (cameras_ < cameras)
            addCamera(cameras_++);
        keep_.resize((size_t)n);
        const int nKept = n ? decide(e, n, keep_.data()) : 0;
        lastTime_[0] = last[0];
        lastTime_[1] = last[1];
        processed_ += n;
        kept_ += nKept;

        if (mask.needed())
        {
            mask.create(n, 1, CV_8U);
            if (n)
                std::memcpy(mask.getMat().ptr(), keep_.data(), (size_t)n);
        }
        if (kept.needed())
        {
            // kept may be events itself: a std::vector would move under e when resized, so compact first.
            compact_.resize((size_t)nKept);
            for (int i = 0, k = 0; i < n; i++)
                if (keep_[i])
                    compact_[k++] = e[i];
            Mat(nKept, 1, EVENT_MAT_TYPE, nKept ? (void*)compact_.data() : (void*)&dummy_).copyTo(kept);
        }
    }

protected:
    EventFilterEngine() : size_(0, 0), cameras_(0), processed_(0), kept_(0) { lastTime_[0] = lastTime_[1] = NEVER; }

    /** Empties the per-pixel state of the cameras allocated so far. */
    virtual void resetState() = 0;
    /** Allocates the empty per-pixel state of camera @p camera (0, then 1 when a right event first comes). */
    virtual void addCamera(int camera) = 0;
    /** Writes keep[i] = 255 or 0 for the n valid events and returns how many are kept. */
    virtual int decide(const Event* e, int n, uchar* keep) = 0;

    /** Writes the format header and the sensor size; a filter writes its own parameters after them. */
    void writeSensorSize(FileStorage& fs) const
    {
        this->writeFormat(fs);
        fs << "sensorWidth" << size_.width << "sensorHeight" << size_.height;
    }

    /** Takes the sensor size from @p fn where stored (a change resets the filter). */
    void readSensorSize(const FileNode& fn)
    {
        const Size s(fn["sensorWidth"].empty() ? size_.width : (int)fn["sensorWidth"],
                     fn["sensorHeight"].empty() ? size_.height : (int)fn["sensorHeight"]);
        if (s != size_)
            setSensorSize(s);
    }

    int pixelCount() const { return size_.area(); }
    int cameraCount() const { return cameras_; }

    /** Checks every event before anything changes; advances @p last (per camera) as the events do and returns
    1 + the highest camera id seen (0 for an empty packet). */
    int validate(const Event* e, int n, int64* last) const
    {
        int cameras = 0;
        for (int i = 0; i < n; i++)
        {
            const Event& ev = e[i];
            if (ev.camera > 1)
                CV_Error_(Error::StsBadArg, ("%s: event #%d (t=%lld us, x=%d, y=%d) has camera %d; expected "
                                             "CAMERA_LEFT (0) or CAMERA_RIGHT (1)", this->getDefaultName().c_str(), i,
                                             (long long)ev.t, ev.x, ev.y, ev.camera));
            if (!onSensor(ev.x, ev.y, size_))
                CV_Error_(Error::StsOutOfRange, ("%s: event #%d at (x=%d, y=%d), t=%lld us, camera %d, is outside "
                                                 "the %d x %d sensor", this->getDefaultName().c_str(), i, ev.x, ev.y, (long long)ev.t,
                                                 ev.camera, size_.width, size_.height));
            if (ev.t == NEVER)
                CV_Error_(Error::StsOutOfRange, ("%s: event #%d (x=%d, y=%d) has t = INT64_MIN, which is reserved "
                                                 "for EventSurface::NO_EVENT", this->getDefaultName().c_str(), i, ev.x, ev.y));
            if (ev.t < last[ev.camera])
                CV_Error_(Error::StsBadArg, ("%s: event #%d at t=%lld us (x=%d, y=%d, camera %d) is earlier than the "
                                             "previous event of its camera (t=%lld us): events must come in time "
                                             "order", this->getDefaultName().c_str(), i, (long long)ev.t, ev.x, ev.y, ev.camera,
                                             (long long)last[ev.camera]));
            last[ev.camera] = ev.t;
            cameras = std::max(cameras, ev.camera + 1);
        }
        return cameras;
    }

    /** A time parameter in microseconds, checked > 0 and rounded to a whole microsecond (at least 1). */
    int64 positiveMicroseconds(double us, const char* what) const
    {
        if (!(us > 0) || us > 1e15)
            CV_Error_(Error::StsBadArg, ("%s: %s %g us; must be > 0 (and below 1e15)", this->getDefaultName().c_str(), what, us));
        return std::max<int64>(1, (int64)std::llround(us));
    }

    Size size_;

private:
    int cameras_;
    int64 lastTime_[2];
    double processed_, kept_;
    std::vector<uchar> keep_;
    std::vector<Event> compact_;
    Event dummy_;
};

template<class Interface> const int64 EventFilterEngine<Interface>::NEVER;

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_FILTERS_EVENT_FILTER_ENGINE_HPP
