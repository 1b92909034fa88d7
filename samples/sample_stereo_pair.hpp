// Checks the stereo samples make of a pair of cameras: whether its clocks agree, its rows and its events line up,
// and which option exchanges the cameras when they look exchanged.

#ifndef OPENCV_EVENT_SAMPLES_SAMPLE_STEREO_PAIR_HPP
#define OPENCV_EVENT_SAMPLES_SAMPLE_STEREO_PAIR_HPP

#include <opencv2/event.hpp>

#include "algorithm_settings.hpp"
#include "clock_offset_policy.hpp"
#include "sample_stereo_source.hpp"

#include <cmath>
#include <cstdint>
#include <iostream>
#include <string>
#include <vector>

/** Below this correlation (cv::event::estimateDominantDisparity()) the events do not say where they line up:
    the threshold cv::event::checkStereoPair() uses, for the samples that look at one window at a time. */
constexpr double kSampleMinLineUpScore = 0.1;

/** The option that exchanges the cameras: of two files (--left/--right), of a text file's camera column, or of
    any other recording of both cameras. */
inline std::string sampleCameraSwapAdvice(bool twoFiles, bool textFile, int leftCameraValue)
{
    if (twoFiles)
        return "exchange --left and --right";
    if (textFile)
        return cv::format("give --left-camera-value=%d", 1 - leftCameraValue);
    return "exchange the left and right cameras";
}

// --right-time-offset-ms=auto: the right camera's clock against the left one's (estimateClockOffset()) from the
// first three seconds of events (longer while there are fewer than 20,000, up to 20 s; at most 300,000, as the
// events are matched several times), read by a capture of its own before the run. Applied when its
// uncertainty is below kSampleMaxClockUncertaintyUs and it lies kSampleClockSignificance of them clear of zero;
// otherwise the events cannot tell an offset from a disparity (one object at one speed), or do not show the
// clocks apart, and the clocks are left as they are.
struct ClockCheck
{
    std::string result = "not estimated";
    double appliedMs = 0;
};

inline ClockCheck checkClocks(StereoSourceOptions o, bool estimate, const std::string& filterName,
                              const std::string& filterSettings, const std::string& calib, int minDisparity,
                              int maxDisparity)
{
    ClockCheck check;
    if (!estimate)
    {
        check.result = cv::format("%+.2f ms, as given (--right-time-offset-ms)", o.rightTimeOffsetMs);
        check.appliedMs = o.rightTimeOffsetMs;
        return check;
    }
    if (o.live)
    {
        check.result = "not estimated (live; give --right-time-offset-ms)";
        return check;
    }
    o.rightTimeOffsetMs = 0;
    o.durationMs = std::min(o.durationMs, 3000.0);
    SampleStereoSource probe(o);
    const cv::Size size = probe.sensorSize();
    if (size.empty())
        return check;  // the run itself says what is missing
    // The events the matcher will see: through the run's noise filter, if any.
    cv::Ptr<cv::event::EventFilter> filter = createSampleFilter(filterName, filterSettings, size);
    std::vector<cv::event::Event> events, packet;
    cv::Mat truth, keepMask;
    double windowEnd = 0;
    while (probe.next(packet, truth, windowEnd))
    {
        if (filter)
            filter->filter(packet, packet, keepMask);
        events.insert(events.end(), packet.begin(), packet.end());
        const int64_t span = events.empty() ? 0 : events.back().t - events.front().t;
        if ((span > 3000000 && events.size() >= 20000) || span > 20000000 || events.size() >= 300000)
            break;
    }
    const double seconds = events.empty() ? 0 : (double)(events.back().t - events.front().t) * 1e-6;
    size_t count[2] = { 0, 0 };
    for (const cv::event::Event& e : events)
        count[e.camera ? 1 : 0]++;
    if (std::min(count[0], count[1]) < 1000)
    {
        check.result = cv::format("not estimated (left %zu events, right %zu in the first %.1f s)", count[0], count[1], seconds);
        return check;
    }
    if (!calib.empty())
        cv::event::readStereoCalibration(calib).rectifyEvents(events, events);
    double uncertainty = 0;
    const double offset = cv::event::estimateClockOffset(events, size, minDisparity, maxDisparity, &uncertainty);
    check.result = cv::format("%+.2f ms +- %.2f ms (estimateClockOffset, first %.1f s)", offset * 1e-3, uncertainty * 1e-3, seconds);
    if (sampleAppliesClockOffset(offset, uncertainty))
    {
        check.appliedMs = std::round(offset / 10) * 0.01;  // to 10 us: the summary shows what was applied
        check.result += ": applied";
    }
    else if (uncertainty <= kSampleMaxClockUncertaintyUs)
        check.result += cv::format(": not applied, within %g of its uncertainties of none: the events do not show the clocks apart", kSampleClockSignificance);
    else
        check.result += cv::format(": not applied, the events do not pin it down (uncertainty above %.1f ms: one object at one speed along the rows, or surfaces whose speeds follow their depth)", kSampleMaxClockUncertaintyUs * 1e-3);
    return check;
}

// Whether the pair is set up as the matcher assumes (checkStereoPair()), looked at once over the first two
// seconds of events (longer while there are fewer than 20,000, up to 20 s; at most 2 million), rectified first
// when there is a calibration. A pair that fails loses matches: the user hears of it on stderr and in the summary.
class SamplePairCheck
{
public:
    // `swapAdvice`: how this source's cameras are exchanged (an option to give).
    SamplePairCheck(cv::Size size, int minDisparity, int maxDisparity, const std::string& swapAdvice, const std::string& calib)
        : size_(size), minDisparity_(minDisparity), maxDisparity_(maxDisparity), swapAdvice_(swapAdvice)
    {
        if (!calib.empty())
            calibration_ = cv::event::readStereoCalibration(calib);
    }

    /** A simulated pair whose right camera is misaligned on purpose (SimulatorSettings::rightRowOffset,
    rightRollRad): the summary says so next to the estimate, and nothing is warned (nothing to act on). */
    void setDesignedMisalignment(double rowOffset, double rollRad)
    {
        designed_ = true;
        designedOffset_ = rowOffset;
        designedRoll_ = rollRad;
    }

    void add(const std::vector<cv::event::Event>& packet)
    {
        if (done_)
            return;
        for (const cv::event::Event& e : packet)
        {
            if (events_.empty())
                first_ = e.t;
            const int64_t span = e.t - first_;
            if ((span > 2000000 && events_.size() >= 20000) || span > 20000000 || events_.size() >= 2000000)
            {
                estimate();
                return;
            }
            events_.push_back(e);
        }
    }

    /** The summary lines' text (estimated now if the stream was shorter). */
    std::string rowResult()
    {
        estimate();
        return rowResult_;
    }
    std::string disparityResult()
    {
        estimate();
        return disparityResult_;
    }
    /** How much of the stream the check looked at, for the summary's labels. */
    std::string span()
    {
        estimate();
        return cv::format("first %.1f s", spanUs_ * 1e-6);
    }

private:
    void estimate()
    {
        if (done_)
            return;
        done_ = true;
        if (!calibration_.empty())
            calibration_.rectifyEvents(events_, events_);
        const cv::event::StereoPairCheck c = cv::event::checkStereoPair(events_, size_, minDisparity_, maxDisparity_);
        events_.clear();
        events_.shrink_to_fit();
        spanUs_ = c.spanUs;
        const size_t n = (size_t)(c.leftEvents + c.rightEvents);
        if (n < 2000)
            rowResult_ = disparityResult_ = "not estimated (too few events)";
        else if (!c.overlap)
        {
            rowResult_ = disparityResult_ = cv::format("not estimated (left %.0f events, right %.0f)", c.leftEvents, c.rightEvents);
            std::cerr << "\nevent_stereo: warning: over the " << span() << " the left camera has " << (long long)c.leftEvents
                      << " events and the right one " << (long long)c.rightEvents << ": the two streams do not overlap in time (a "
                      << "camera that fires nothing, or two recordings whose clocks are apart; --right-time-offset-ms "
                      << "shifts the right camera's clock)\n";
        }
        else
        {
            describeLineUp(c, n);
            describeRows(c, n);
        }
    }

    void describeRows(const cv::event::StereoPairCheck& c, size_t n)
    {
        if (!c.rowsEstimated)
        {
            rowResult_ = "not estimated (too narrow a sensor for the disparity range)";
            return;
        }
        const std::string text = cv::format("offset %+.2f px, roll %+.4f rad: up to %.2f px at the sides (score %.2f, %zu events)",
                                            c.rowOffset, c.roll, c.rowsOffAtSides, c.rowScore, n);
        rowResult_ = text;
        if (!c.rowsTrusted)
            rowResult_ += "; a score below 0.4: too uncertain to act on";
        if (designed_)
            rowResult_ += cv::format("; the simulated right camera is misaligned on purpose: offset %+.2f px, roll "
                                     "%+.4f rad, up to %.2f px at the sides", designedOffset_, designedRoll_,
                                     std::abs(designedOffset_) + std::abs(std::sin(designedRoll_)) * 0.5 * size_.width);
        else if (c.rowsOff)
            std::cerr << "\nevent_stereo: warning: the right camera's rows are off the left's by " << text
                      << "; check the rectification (matches are searched along the rows)\n";
    }

    void describeLineUp(const cv::event::StereoPairCheck& c, size_t n)
    {
        const int d = c.lineUpDisparity;
        disparityResult_ = cv::format("%d px (correlation %.2f, %zu events)", d, c.lineUpScore, n);
        std::string advice;
        if (c.camerasExchanged)
            advice = cv::format("the right camera sees the scene to the right of the left one (the events line up "
                                "at %d px): the cameras look exchanged; %s", d, swapAdvice_.c_str());
        else if (c.beyondRange)
            advice = cv::format("most of the scene lines up at %d px, beyond --max-disparity=%d: widen the range",
                                d, maxDisparity_);
        else if (c.belowRange)
            advice = cv::format("most of the scene lines up at %d px, below --min-disparity=%d: lower it", d,
                                minDisparity_);
        if (!advice.empty())
        {
            disparityResult_ += "; " + advice;
            std::cerr << "\nevent_stereo: warning: " << advice << "\n";
        }
    }

    cv::Size size_;
    int minDisparity_, maxDisparity_;
    std::string swapAdvice_;
    cv::event::StereoCalibration calibration_;
    std::vector<cv::event::Event> events_;
    int64_t first_ = 0;
    double spanUs_ = 0;
    bool done_ = false;
    std::string rowResult_, disparityResult_;
    bool designed_ = false;
    double designedOffset_ = 0, designedRoll_ = 0;
};

#endif  // OPENCV_EVENT_SAMPLES_SAMPLE_STEREO_PAIR_HPP
