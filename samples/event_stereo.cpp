// event_stereo: per-event stereo disparity, depth and lifetime (StereoEventMatcher) on a stereo recording, a
// live stereo DAVIS pair, or the simulator's built-in scene; the main job of this project.
//
//   event_stereo [--input=FILE | --left=FILE --right=FILE | --live [--live-ms=MS]] [--record=FILE] [--calib=FILE] [--sensor=WxH]
//                [--left-camera-value=0|1] [--one-based] [--right-time-offset-ms=MS|auto] [--mode=coupled|decoupled|fixed|sgbm]
//                [--min-disparity=PX] [--max-disparity=PX] [--frame-ms=MS] [--threads=N] [--no-csv]
//                [--all-frames] [--output=DIR] [--set=NAME=VALUE,...] [--scene=NAME --duration-ms=MS]
//                [--filter=NAME [--filter-set=NAME=VALUE,...]]
//                (no input: simulate, with ground truth)
//
// Writes into DIR: events.csv (t,x,y,p,camera,disparity,depth,lifetime,flags,confidence per event, x/y rectified),
// disparity.avi with one frame per --frame-ms window when a video writer is available (left | right active
// events coloured by disparity, the paper's Figure 1; plus the ground truth below when simulated), the same
// picture as disparity_NNNNN.png (NNNNN: the window) for the first window and one per eighth of the run
// (--all-frames: every window),
// disparity_histogram.png and summary.md (events/s, share with disparity and with lifetime, dominant
// disparity, the quartiles of the left estimates' confidence, input events outside the sensor or going back
// in time, the right camera's clock against the left one's (estimated and applied by default), the pair
// check, and errors against the ground truth when simulated). Progress, and warnings when the pair's rows are
// off or its events line up outside the range or with the cameras exchanged, go to stderr.

#include <opencv2/event.hpp>
#include <opencv2/core/utils/filesystem.hpp>  // after a core header: it needs CV_EXPORTS
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "sample_command_line.hpp"
#include "sample_algorithm_settings.hpp"
#include "sample_pictures.hpp"
#include "sample_progress.hpp"
#include "sample_stereo_pair.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

using namespace cv;
using namespace cv::event;

namespace {

struct Options
{
    // Defaults: the keys below.
    std::string input, left, right, calib, output, scene, mode, settings, filter, filterSettings, record;
    bool live = false, csv = true, allFrames = false, oneBased = false;
    Size sensor;
    int leftCameraValue = 0, minDisparity = 0, maxDisparity = 0;
    // Row bands on their own threads (StereoEventMatcher::setNumThreads): the same results as one thread, but
    // little faster wherever the events crowd around the bands' boundary (a figure or an object in the middle
    // of the view, most real scenes), so one thread unless asked.
    int threads = 1;
    double frameMs = 0, durationMs = 0, rightTimeOffsetMs = 0, liveMs = 0;
    bool estimateClock = true;  // --right-time-offset-ms=auto: estimateClockOffset() on the first seconds
};

const char* const keys =
    "{help h            | false      | print this message}"
    "{input             |            | a recording (one file; stereo when it holds both cameras)}"
    "{left              |            | the left camera's recording (with --right)}"
    "{right             |            | the right camera's recording (with --left)}"
    "{live              | false      | a live stereo DAVIS pair (davis:0 left, davis:1 right)}"
    "{live-ms           | 0          | stop a live run after this much camera time [ms]; 0: until the cameras stop}"
    "{record            |            | also write the events as read (before --filter) to this file: .aedat4, else text with a camera column; a simulated scene with its ground truth in FILE.gt.csv}"
    "{calib             |            | stereo calibration (FileStorage: K1 D1 K2 D2 R T, image size)}"
    "{sensor            |            | sensor size WxH or a name (DVS128, DAVIS240, DAVIS346) when the format has none}"
    "{left-camera-value | 0          | the camera column's value that means left, in text recordings}"
    "{one-based         | false      | text recordings count pixels from 1}"
    "{right-time-offset-ms | auto    | added to the right camera's timestamps [ms]; auto: estimated from the first seconds of events (estimateClockOffset) and applied when the events are clear about it}"
    "{mode              | coupled    | coupled, decoupled, fixed or sgbm}"
    "{min-disparity     | 0          | smallest disparity searched [px]}"
    "{max-disparity     | 40         | largest disparity searched [px]}"
    "{frame-ms          | 33         | window of one video frame [ms]}"
    "{threads           | 1          | row bands on their own threads (the same results; on two cores little faster on realistic scenes: Threads in doc/stereo.md); 0: the CPUs, at most 4}"
    "{no-csv            | false      | do not write events.csv}"
    "{all-frames        | false      | a PNG for every window, not a handful}"
    "{output            | output/event_stereo | output folder}"
    "{scene             | boxes      | simulated scene when no input is given: boxes, boxes_fast, walking, walking_near, low_contrast (realistic), boxes_pair, boxes_fast_pair, walking_pair (as a real DAVIS240 pair records them), boxes_flicker (a flickering lamp); plane, two_planes, moving_line, faint_line, cluttered}"
    "{duration-ms       | 1000       | length of the simulated scene [ms]}"
    "{set               |            | matcher parameters NAME=VALUE, comma separated (e.g. uniquenessRatio=20,costWindow=11)}"
    "{filter            |            | a noise filter in front of the matcher: background_activity, trail, refractory, hot_pixels, anti_flicker}"
    "{filter-set        |            | filter parameters NAME=VALUE, comma separated (e.g. correlationTime=10000)}";

bool parse(int argc, char** argv, Options& o)
{
    SampleCommandLine cmd(argc, argv, keys,
                          "Per-event stereo disparity, depth and lifetime of a stereo recording, a live DAVIS pair "
                          "or a simulated scene.");
    if (cmd.helpShown())
        return false;
    o.input = cmd.get<std::string>("input");
    o.left = cmd.get<std::string>("left");
    o.right = cmd.get<std::string>("right");
    o.live = cmd.has("live");
    o.liveMs = cmd.get<double>("live-ms");
    o.record = cmd.get<std::string>("record");
    o.calib = cmd.get<std::string>("calib");
    if (cmd.has("sensor"))
        o.sensor = parseSensorSize(cmd.get<std::string>("sensor"));
    o.leftCameraValue = cmd.get<int>("left-camera-value");
    o.oneBased = cmd.has("one-based");
    const std::string clock = cmd.get<std::string>("right-time-offset-ms");
    o.estimateClock = clock == "auto";
    if (!o.estimateClock)
    {
        char* end = nullptr;
        o.rightTimeOffsetMs = std::strtod(clock.c_str(), &end);
        if (clock.empty() || *end != 0 || !std::isfinite(o.rightTimeOffsetMs))
            throw std::runtime_error("--right-time-offset-ms=" + clock + ": give milliseconds, or auto");
    }
    o.mode = cmd.get<std::string>("mode");
    o.minDisparity = cmd.get<int>("min-disparity");
    o.maxDisparity = cmd.get<int>("max-disparity");
    o.frameMs = cmd.get<double>("frame-ms");
    const int threads = cmd.get<int>("threads");
    if (threads < 0)
        throw std::runtime_error(format("--threads=%d: give 1 or more, or 0 for the CPUs", threads));
    o.threads = threads > 0 ? threads : std::min(4, std::max(1, getNumberOfCPUs()));
    o.csv = !cmd.has("no-csv");
    o.allFrames = cmd.has("all-frames");
    o.output = cmd.get<std::string>("output");
    o.scene = cmd.get<std::string>("scene");
    o.durationMs = cmd.get<double>("duration-ms");
    o.settings = cmd.get<std::string>("set");
    o.filter = cmd.get<std::string>("filter");
    o.filterSettings = cmd.get<std::string>("filter-set");
    if (findStereoMode(o.mode) < 0)
        throw std::runtime_error("--mode=" + o.mode + ": use coupled, decoupled, fixed or sgbm");
    if ((o.left.empty()) != (o.right.empty()))
        throw std::runtime_error("--left and --right go together");
    if (!(o.frameMs > 0))
        throw std::runtime_error("--frame-ms must be > 0");
    return true;
}

// Why a recording of this back-end holds one camera, in its own terms.
std::string oneCameraReason(const std::string& backend)
{
    if (backend == "TEXT")
        return "no camera column";
    if (backend == "ROSBAG1" || backend == "ROSBAG2")
        return "one event topic";
    if (backend == "AEDAT4")
        return "one event stream";
    if (backend == "HDF5_MVSEC")
        return "one camera's events";
    return "a " + backend + " file holds one camera";
}

// Where events come from: a capture (file, file pair, live pair) or the simulator with ground truth.
class Source
{
public:
    explicit Source(const Options& o)
    {
        if (o.input.empty() && o.left.empty() && !o.live)
        {
            sim_ = StereoEventSimulator::create(o.scene);
            if (o.rightTimeOffsetMs != 0)
            {
                // The simulated right camera restamped as a capture would do it.
                SimulatorSettings s = sim_->getSettings();
                s.rightClockOffsetUs += o.rightTimeOffsetMs * 1000;
                sim_ = StereoEventSimulator::create(sim_->getPlanes(), s);
            }
            durationUs_ = o.durationMs * 1000;
            windowUs_ = o.frameMs * 1000;
            name_ = "simulated scene \"" + o.scene + "\" (" + std::to_string((int)o.durationMs) + " ms)";
            return;
        }
        cap_.set(EVENT_CAP_PROP_TEXT_LEFT_CAMERA_VALUE, o.leftCameraValue);
        cap_.set(EVENT_CAP_PROP_TEXT_ONE_BASED, o.oneBased);
        cap_.set(EVENT_CAP_PROP_RIGHT_TIME_OFFSET_US, o.rightTimeOffsetMs * 1000);
        cap_.set(EVENT_CAP_PROP_SENSOR_WIDTH, o.sensor.width);
        cap_.set(EVENT_CAP_PROP_SENSOR_HEIGHT, o.sensor.height);
        cap_.set(EVENT_CAP_PROP_WINDOW_US, o.frameMs * 1000);
        if (o.live)
        {
            cap_.openStereo("davis:0", "davis:1");
            liveEndUs_ = o.liveMs * 1000;
        }
        else if (!o.left.empty())
            cap_.openStereo(o.left, o.right);
        else
            cap_.open(o.input);
        if (cap_.get(EVENT_CAP_PROP_STEREO) == 0)
            throw std::runtime_error(cap_.getSource() + ": not a stereo source (" + oneCameraReason(cap_.getBackendName()) +
                                     "); give each camera's recording with --left and --right");
        name_ = cap_.getSource() + " (" + cap_.getBackendName() + ")";
    }

    Size sensorSize() const { return sim_ ? sim_->getSensorSize() : cap_.getSensorSize(); }
    const std::string& name() const { return name_; }
    bool isText() const { return !sim_ && cap_.getBackendName() == "TEXT"; }
    bool hasTruth() const { return !sim_.empty(); }
    const Ptr<StereoEventSimulator>& simulator() const { return sim_; }

    bool next(std::vector<Event>& events, Mat& truth, double& windowEnd)
    {
        if (sim_)
        {
            if (sim_->getTime() >= durationUs_)
                return false;
            windowEnd = std::min(durationUs_, sim_->getTime() + windowUs_);
            sim_->generate(windowEnd, events, truth);
            return true;
        }
        if (liveEndUs_ > 0 && lastWindowEnd_ >= liveEndUs_)
            return false;
        if (!cap_.read(events))
            return false;
        windowEnd = lastWindowEnd_ = cap_.get(EVENT_CAP_PROP_POS_US);
        touchesZero_ = touchesZero_ || touchesColumnOrRowZero(events);
        return true;
    }

    // Input events the capture did not deliver (outside the sensor) and events that went back in time
    // (delivered with the previous timestamp): both are counted, never silent.
    double rejectedOutside() const { return sim_ ? 0 : cap_.get(EVENT_CAP_PROP_REJECTED_OUTSIDE); }
    double timeBackwards() const { return sim_ ? 0 : cap_.get(EVENT_CAP_PROP_TIME_BACKWARDS); }
    // Whether a delivered event lay in column or row 0 (a file counted from 1 never has one).
    bool eventsTouchZero() const { return touchesZero_; }

    // 0..1, or -1 when unknown (live).
    double progress() const
    {
        if (sim_)
            return sim_->getTime() / durationUs_;
        return cap_.get(EVENT_CAP_PROP_PROGRESS);
    }

private:
    Ptr<StereoEventSimulator> sim_;
    EventCapture cap_;
    double durationUs_ = 0, windowUs_ = 0;
    double liveEndUs_ = 0, lastWindowEnd_ = 0;
    std::string name_;
    bool touchesZero_ = false;
};

// Pictures written by default: the first window and one each time the run passes another eighth (live, where
// the length is unknown: windows 1, 2, 4, 8, ...). --all-frames writes every window; the video has them all.
std::string progressText(int64 events, double seconds)
{
    char text[96];
    std::snprintf(text, sizeof(text), "%lld events, %.2f Mev/s", (long long)events, (double)events / std::max(1e-9, seconds) / 1e6);
    return text;
}

bool isPictureWindow(int64 window, double fraction, int& lastEighth)
{
    if (window == 0)
        return true;
    if (fraction < 0)
        return (window & (window - 1)) == 0;
    const int eighth = (int)std::floor(fraction * 8);
    if (eighth <= lastEighth)
        return false;
    lastEighth = eighth;
    return true;
}

Mat histogramPicture(const std::vector<int64>& h, int minDisparity)
{
    const int bar = 8, height = 200;
    Mat img(height + 50, bar * (int)h.size() + 20, CV_8UC3, Scalar::all(255));
    const int64 peak = std::max<int64>(1, *std::max_element(h.begin(), h.end()));
    for (size_t k = 0; k < h.size(); k++)
    {
        const int len = (int)std::lround((double)h[k] / (double)peak * height);
        rectangle(img, Point(10 + bar * (int)k, height + 20 - len), Point(10 + bar * (int)k + bar - 2, height + 20),
                  Scalar(180, 90, 30), FILLED);
    }
    putText(img, "events per disparity [px]", Point(10, 14), FONT_HERSHEY_SIMPLEX, 0.45, Scalar::all(0), 1);
    putText(img, std::to_string(minDisparity), Point(10, height + 40), FONT_HERSHEY_SIMPLEX, 0.4, Scalar::all(0), 1);
    putText(img, std::to_string(minDisparity + (int)h.size() - 1), Point(img.cols - 30, height + 40),
            FONT_HERSHEY_SIMPLEX, 0.4, Scalar::all(0), 1);
    return img;
}

// The quartiles of the left estimates' confidence, from a histogram of confidence 0..1 in equal bins, and the
// share below 0.15 (the threshold doc/benchmarks.md's rejection examples use): how clear-cut the matches of this
// recording are (a scene with few, alike edges along the rows gives low values, whatever the matcher).
std::string confidenceQuartiles(const std::vector<int64>& h)
{
    const double lowConfidence = 0.15;
    const double binsPerUnit = (double)(h.size() - 1);
    int64 n = 0;
    for (int64 c : h)
        n += c;
    if (n == 0)
        return "none (no left estimate)";
    auto quantile = [&](double q) {
        int64 seen = 0;
        for (size_t k = 0; k < h.size(); k++)
            if ((seen += h[k]) > (int64)(q * (double)(n - 1)))
                return (double)k / binsPerUnit;
        return 1.0;
    };
    int64 low = 0;
    for (size_t k = 0; k < (size_t)std::lround(lowConfidence * binsPerUnit); k++)
        low += h[k];
    return cv::format("%.2f / %.2f / %.2f (%.1f %% below %.2f)", quantile(0.25), quantile(0.5), quantile(0.75),
                      100.0 * (double)low / (double)n, lowConfidence);
}

// Moves each event to its rectified pixel (the check looks at rows and columns as the matcher will).
void rectifyEvents(const StereoCalibration& calibration, std::vector<Event>& events)
{
    for (int camera = 0; camera < 2; camera++)
    {
        std::vector<Point2f> raw;
        for (const Event& e : events)
            if (e.camera == camera)
                raw.push_back(Point2f(e.x, e.y));
        if (raw.empty())
            continue;
        Mat rectified;
        calibration.rectifyPoints(raw, rectified, camera);
        size_t k = 0;
        for (Event& e : events)
            if (e.camera == camera)
            {
                const Point2f q = rectified.at<Point2f>((int)k++);
                e.x = (short)cvRound(q.x);
                e.y = (short)cvRound(q.y);
            }
    }
}

// --right-time-offset-ms=auto: the right camera's clock against the left one's (estimateClockOffset()) from the
// first three seconds of events (longer while there are fewer than 20,000, up to 20 s; at most 300,000, as the
// events are matched several times), read by a capture of its own before the run. Applied when its
// uncertainty is below kSampleMaxClockUncertaintyUs; otherwise the events cannot tell an offset from a
// disparity (one object at one speed) and the clocks are left as they are.
struct ClockCheck
{
    std::string result = "not estimated";
    double appliedMs = 0;
};

ClockCheck checkClocks(Options o)
{
    ClockCheck check;
    if (!o.estimateClock)
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
    Source probe(o);
    const Size size = probe.sensorSize();
    if (size.empty())
        return check;  // the run itself says what is missing
    // The events the matcher will see: through the run's noise filter, if any.
    Ptr<EventFilter> filter = createSampleFilter(o.filter, o.filterSettings, size);
    std::vector<Event> events, packet;
    Mat truth, keepMask;
    double windowEnd = 0;
    while (probe.next(packet, truth, windowEnd))
    {
        if (filter)
            filter->filter(packet, packet, keepMask);
        events.insert(events.end(), packet.begin(), packet.end());
        const int64 span = events.empty() ? 0 : events.back().t - events.front().t;
        if ((span > 3000000 && events.size() >= 20000) || span > 20000000 || events.size() >= 300000)
            break;
    }
    const double seconds = events.empty() ? 0 : (double)(events.back().t - events.front().t) * 1e-6;
    size_t count[2] = { 0, 0 };
    for (const Event& e : events)
        count[e.camera ? 1 : 0]++;
    if (std::min(count[0], count[1]) < 1000)
    {
        check.result = cv::format("not estimated (left %zu events, right %zu in the first %.1f s)", count[0], count[1], seconds);
        return check;
    }
    if (!o.calib.empty())
        rectifyEvents(readStereoCalibration(o.calib), events);
    double uncertainty = 0;
    const double offset = estimateClockOffset(events, size, o.minDisparity, o.maxDisparity, &uncertainty);
    check.result = cv::format("%+.2f ms +- %.2f ms (estimateClockOffset, first %.1f s)", offset * 1e-3, uncertainty * 1e-3, seconds);
    if (uncertainty <= kSampleMaxClockUncertaintyUs)
    {
        check.appliedMs = std::round(offset / 10) * 0.01;  // to 10 us: the summary shows what was applied
        check.result += ": applied";
    }
    else
        check.result += cv::format(": not applied, the events do not pin it down (uncertainty above %.1f ms: one object at one speed along the rows, or surfaces whose speeds follow their depth)", kSampleMaxClockUncertaintyUs * 1e-3);
    return check;
}

// Whether the pair is set up as the matcher assumes: its rows line up (estimateRowAlignment()) and its events
// line up at a disparity inside the searched range, with the cameras the right way round
// (estimateDominantDisparity()). Both look once at the first two seconds of events (longer while there are
// fewer than 20,000, up to 20 s; at most 2 million), rectified first when there is a calibration. A pair that
// fails either loses matches: the user hears of it on stderr and in the summary.
class PairCheck
{
public:
    // `swapAdvice`: how this source's cameras are exchanged (an option to give).
    PairCheck(Size size, int minDisparity, int maxDisparity, const std::string& swapAdvice, const std::string& calib)
        : size_(size), minDisparity_(minDisparity), maxDisparity_(maxDisparity), swapAdvice_(swapAdvice)
    {
        if (!calib.empty())
            calibration_ = readStereoCalibration(calib);
    }

    /** A simulated pair whose right camera is misaligned on purpose (SimulatorSettings::rightRowOffset,
    rightRollRad): the summary says so next to the estimate, and nothing is warned (nothing to act on). */
    void setDesignedMisalignment(double rowOffset, double rollRad)
    {
        designed_ = true;
        designedOffset_ = rowOffset;
        designedRoll_ = rollRad;
    }

    void add(const std::vector<Event>& packet)
    {
        if (done_)
            return;
        for (const Event& e : packet)
        {
            if (events_.empty())
                first_ = e.t;
            const int64 span = e.t - first_;
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
        return spanText();
    }

private:
    void estimate()
    {
        if (done_)
            return;
        done_ = true;
        if (!events_.empty())
            spanUs_ = events_.back().t - events_.front().t;
        if (events_.size() < 2000)
            rowResult_ = disparityResult_ = "not estimated (too few events)";
        else if (camerasOverlap())
        {
            if (!calibration_.imageSize.empty())
                rectifyEvents(calibration_, events_);
            estimateDisparity();
            if (size_.width < 3 * maxDisparity_ / 2 + 12)
                rowResult_ = "not estimated (too narrow a sensor for the disparity range)";
            else
                estimateRows();
        }
        events_.clear();
        events_.shrink_to_fit();
    }

    std::string spanText() const
    {
        return cv::format("first %.1f s", (double)spanUs_ * 1e-6);
    }

    // A pair whose cameras' streams do not overlap in time has nothing to match: one camera fired nothing, or
    // two recordings' clocks are apart (each started its own).
    bool camerasOverlap()
    {
        size_t count[2] = { 0, 0 };
        for (const Event& e : events_)
            count[e.camera ? 1 : 0]++;
        if (std::min(count[0], count[1]) * 100 >= std::max(count[0], count[1]))
            return true;
        rowResult_ = disparityResult_ = cv::format("not estimated (left %zu events, right %zu)", count[0], count[1]);
        std::cerr << "\nevent_stereo: warning: over the " << spanText() << " the left camera has " << count[0]
                  << " events and the right one " << count[1] << ": the two streams do not overlap in time (a camera "
                  << "that fires nothing, or two recordings whose clocks are apart; --right-time-offset-ms shifts the "
                  << "right camera's clock)\n";
        return false;
    }

    /** How far apart the two cameras' rows are at the image's sides, for a row offset and a roll. */
    double rowsOffAtSides(double rowOffset, double rollRad) const
    {
        return std::abs(rowOffset) + std::abs(std::sin(rollRad)) * 0.5 * size_.width;
    }

    void estimateRows()
    {
        double score = 0;
        const Vec2d a = estimateRowAlignment(events_, size_, minDisparity_, maxDisparity_, &score);
        const double sides = rowsOffAtSides(a[0], a[1]);
        char text[200];
        std::snprintf(text, sizeof(text), "offset %+.2f px, roll %+.4f rad: up to %.2f px at the sides (score %.2f, %zu events)",
                      a[0], a[1], sides, score, events_.size());
        rowResult_ = text;
        if (score < kSampleMinRowScore)
            rowResult_ += cv::format("; a score below %.1f: too uncertain to act on", kSampleMinRowScore);
        if (designed_)
            rowResult_ += cv::format("; the simulated right camera is misaligned on purpose: offset %+.2f px, roll "
                                     "%+.4f rad, up to %.2f px at the sides", designedOffset_, designedRoll_,
                                     rowsOffAtSides(designedOffset_, designedRoll_));
        else if (score >= kSampleMinRowScore && sides > 0.5)
            std::cerr << "\nevent_stereo: warning: the right camera's rows are off the left's by " << text
                      << "; check the rectification (matches are searched along the rows)\n";
    }

    // Looks twice as far as the searched range (at most half the sensor), so that a scene beyond the range, or
    // a swapped pair's negative disparity, shows.
    void estimateDisparity()
    {
        const int reach = std::min(size_.width / 2, std::max(20, 2 * std::max(maxDisparity_, -minDisparity_)));
        double score = 0;
        const int d = estimateDominantDisparity(events_, size_, reach, noArray(), &score);
        disparityResult_ = cv::format("%d px (correlation %.2f, %zu events)", d, score, events_.size());
        if (score < kSampleMinLineUpScore)
            return;  // the events do not say enough to warn on
        std::string advice;
        if (d < 0 && d < minDisparity_ - 1)
        {
            advice = cv::format("the right camera sees the scene to the right of the left one (the events line up "
                                "at %d px): the cameras look exchanged; %s", d, swapAdvice_.c_str());
        }
        else if (d > maxDisparity_)
            advice = cv::format("most of the scene lines up at %d px, beyond --max-disparity=%d: widen the range",
                                d, maxDisparity_);
        else if (d < minDisparity_ - 1)
            advice = cv::format("most of the scene lines up at %d px, below --min-disparity=%d: lower it", d,
                                minDisparity_);
        if (!advice.empty())
        {
            disparityResult_ += "; " + advice;
            std::cerr << "\nevent_stereo: warning: " << advice << "\n";
        }
    }

    Size size_;
    int minDisparity_, maxDisparity_;
    std::string swapAdvice_;
    StereoCalibration calibration_;
    std::vector<Event> events_;
    int64 first_ = 0, spanUs_ = 0;
    bool done_ = false;
    std::string rowResult_, disparityResult_;
    bool designed_ = false;
    double designedOffset_ = 0, designedRoll_ = 0;
};

}  // namespace

int main(int argc, char** argv)
{
    Options opt;
    try
    {
        if (!parse(argc, argv, opt))
            return 0;
        if (!utils::fs::createDirectories(opt.output))
            throw std::runtime_error(opt.output + ": cannot create the output folder");
        const ClockCheck clocks = checkClocks(opt);
        opt.rightTimeOffsetMs = clocks.appliedMs;
        Source source(opt);
        const Size size = source.sensorSize();
        if (size.empty())
            throw sensorSizeMissing(source.name());

        Ptr<StereoEventMatcher> matcher = StereoEventMatcher::create(size, findStereoMode(opt.mode));
        matcher->setMinDisparity(opt.minDisparity);
        matcher->setMaxDisparity(opt.maxDisparity);
        matcher->setNumThreads(opt.threads);
        applyMatcherSettings(matcher, opt.settings);
        Ptr<EventFilter> filter = createSampleFilter(opt.filter, opt.filterSettings, size);
        if (!opt.calib.empty())
            matcher->loadCalibration(opt.calib);
        else if (source.hasTruth())
        {
            const SimulatorSettings& s = source.simulator()->getSettings();
            matcher->setCalibration(StereoCalibration::fromRectified(size, s.focalLength, s.baseline));
        }

        std::ofstream csv;
        if (opt.csv)
        {
            csv.open(opt.output + "/events.csv");
            csv << "t,x,y,p,camera,disparity,depth,lifetime,flags,confidence\n";
        }
        const int zoom = samplePictureZoom(size);
        VideoWriter video;
        std::vector<int64> histogram((size_t)(opt.maxDisparity - opt.minDisparity + 1), 0);
        std::vector<int64> confidences(101, 0);  // the left estimates', bins of 0.01
        int64 events = 0, withDisparity[2] = { 0, 0 }, withLifetime[2] = { 0, 0 }, perCamera[2] = { 0, 0 };
        int64 pictures = 0, windows = 0;
        StereoEventScores scores;
        int lastEighth = 0;
        SampleProgress progress;
        double seconds = 0, filterSeconds = 0;
        int64 filtered = 0;
        std::vector<Event> packet;
        Mat keepMask;
        Mat truth, disparity, lifetime, flags, depth, confidence, truthDisparity;
        double windowEnd = 0;
        char line[160];
        const std::string swapAdvice = sampleCameraSwapAdvice(!opt.left.empty(), source.isText(), opt.leftCameraValue);
        PairCheck pairCheck(size, opt.minDisparity, opt.maxDisparity, swapAdvice, opt.calib);
        if (source.hasTruth())
            pairCheck.setDesignedMisalignment(source.simulator()->getSettings().rightRowOffset,
                                              source.simulator()->getSettings().rightRollRad);
        EventWriter recorder;
        if (!opt.record.empty() && source.hasTruth())
        {
            // A simulated scene is written with its ground truth beside (FILE.gt.csv), for event_evaluate: the
            // same scene simulated again from the start gives the same events.
            const Ptr<StereoEventSimulator>& sim = source.simulator();
            writeSimulatedRecording(StereoEventSimulator::create(sim->getPlanes(), sim->getSettings()), opt.record,
                                    opt.durationMs * 1000);
        }
        else if (!opt.record.empty())
        {
            recorder.set(EVENT_WRITER_PROP_STEREO, 1);
            recorder.open(opt.record, size);
        }
        while (source.next(packet, truth, windowEnd))
        {
            if (recorder.isOpened())
                recorder.write(packet);
            if (filter)
            {
                // The matcher sees the kept events; the ground truth follows them.
                filtered += (int64)packet.size();
                const int64 f0 = getTickCount();
                filter->filter(packet, packet, keepMask);
                filterSeconds += (double)(getTickCount() - f0) / getTickFrequency();
                if (source.hasTruth())
                {
                    Mat keptTruth;
                    for (int i = 0; i < keepMask.rows; i++)
                        if (keepMask.at<uchar>(i))
                            keptTruth.push_back(truth.row(i));
                    truth = keptTruth;
                }
            }
            pairCheck.add(packet);
            const int64 t0 = getTickCount();
            matcher->process(packet, disparity, lifetime, flags, depth, noArray(), confidence);
            seconds += (double)(getTickCount() - t0) / getTickFrequency();
            if (source.hasTruth())
            {
                scoreStereoEvents(packet, disparity, truth, scores);
                truthDisparity = Mat::zeros(size, CV_32F);
            }
            for (size_t i = 0; i < packet.size(); i++)
            {
                const Event& e = packet[i];
                const float d = disparity.at<float>((int)i);
                const int f = flags.at<int>((int)i);
                perCamera[e.camera]++;
                withDisparity[e.camera] += d >= 0;
                withLifetime[e.camera] += (f & STEREO_HAS_LIFETIME) != 0;
                if (d >= 0 && e.camera == CAMERA_LEFT)
                    confidences[(size_t)std::min(100, std::max(0, (int)(confidence.at<float>((int)i) * 100.f)))]++;
                if (d >= 0)
                    histogram[(size_t)std::min<int>((int)histogram.size() - 1, std::max(0, (int)std::lround(d) - opt.minDisparity))]++;
                if (source.hasTruth() && e.camera == CAMERA_LEFT && !((int)truth.at<float>((int)i, GT_FLAGS) & GT_FLAG_NOISE))
                    truthDisparity.at<float>(e.y, e.x) = truth.at<float>((int)i, GT_DISPARITY);
                if (csv.is_open())
                {
                    std::snprintf(line, sizeof(line), "%lld,%d,%d,%d,%d,%.2f,%.4f,%.0f,%d,%.3f\n", (long long)e.t, e.x, e.y,
                                  e.p, e.camera, d, depth.at<float>((int)i), lifetime.at<float>((int)i), f,
                                  confidence.at<float>((int)i));
                    csv << line;
                }
            }
            events += (int64)packet.size();

            // Picture of this window: left | right active events by disparity (+ ground truth when simulated).
            Mat left, right, row;
            matcher->renderDisparity(windowEnd - 1, left, CAMERA_LEFT, false);
            matcher->renderDisparity(windowEnd - 1, right, CAMERA_RIGHT, true);
            hconcat(left, right, row);
            if (source.hasTruth())
            {
                Mat scaled, colour, below = Mat::zeros(size.height, row.cols, CV_8UC3);
                truthDisparity.convertTo(scaled, CV_8U, 255.0 / std::max(1, opt.maxDisparity - opt.minDisparity),
                                         -255.0 * opt.minDisparity / std::max(1, opt.maxDisparity - opt.minDisparity));
                applyColorMap(scaled, colour, COLORMAP_JET);
                colour.setTo(Scalar::all(0), truthDisparity <= 0);
                colour.copyTo(below(Rect(0, 0, size.width, size.height)));
                putText(below, "ground truth (left events of this window)", Point(size.width + 4, 14),
                        FONT_HERSHEY_PLAIN, 0.8, Scalar::all(255), 1);
                vconcat(row, below, row);
            }
            row = sampleEnlarge(row, zoom);
            if (opt.allFrames || isPictureWindow(windows, source.progress(), lastEighth))
            {
                std::snprintf(line, sizeof(line), "/disparity_%05lld.png", (long long)windows);
                imwrite(opt.output + line, row);
                pictures++;
            }
            if (windows++ == 0)
                video.open(opt.output + "/disparity.avi", VideoWriter::fourcc('M', 'J', 'P', 'G'),
                           std::max(1.0, 1000.0 / opt.frameMs), row.size());
            if (video.isOpened())
                video.write(row);
            progress.update(source.progress(), progressText(events, seconds));
        }
        progress.finish(source.progress(), progressText(events, seconds));

        int dominant = -1;
        int64 votes = 0;
        for (size_t k = 0; k < histogram.size(); k++)
            if (histogram[k] > votes)
            {
                votes = histogram[k];
                dominant = opt.minDisparity + (int)k;
            }
        imwrite(opt.output + "/disparity_histogram.png", histogramPicture(histogram, opt.minDisparity));
        const int64 outside = (int64)source.rejectedOutside(), backwards = (int64)source.timeBackwards();
        if (outside > 0)
            std::cerr << "event_stereo: warning: "
                      << outsideEventsWarning(outside, size.width, size.height, source.isText(), opt.oneBased,
                                              source.eventsTouchZero()) << "\n";
        auto pct = [](double a, double b) { return b != 0 ? 100.0 * a / b : 0.0; };
        std::ostringstream text;
        text << "# event_stereo summary\n\n| | |\n|---|---|\n"
             << "| source | " << source.name() << " |\n"
             << "| sensor | " << size.width << " x " << size.height << (opt.calib.empty() ? "" : ", calibration " + opt.calib) << " |\n"
             << "| mode | " << opt.mode << ", disparities " << opt.minDisparity << ".." << opt.maxDisparity << " px |\n"
             << (filter ? "| filter | " + opt.filter + ": kept " + cv::format("%lld of %lld events (%.1f %%), %.1f Mev/s", (long long)events,
                                    (long long)filtered, pct(events, filtered), (double)filtered / std::max(1e-9, filterSeconds) / 1e6) + " |\n" : std::string())
             << "| events | " << events << " (left " << perCamera[0] << ", right " << perCamera[1] << ") |\n"
             << "| input events outside the sensor (not processed) / going back in time (clamped) | "
             << outside << " / " << backwards << " |\n"
             << "| processing | " << seconds << " s, " << (double)events / std::max(1e-9, seconds) / 1e6 << " Mev/s ("
             << opt.threads << (opt.threads == 1 ? " thread" : " threads") << ") |\n"
             << "| events with a disparity | " << pct(withDisparity[0] + withDisparity[1], events) << " % (left "
             << pct(withDisparity[0], perCamera[0]) << " %, right " << pct(withDisparity[1], perCamera[1]) << " %) |\n"
             << "| events with a lifetime | " << pct(withLifetime[0] + withLifetime[1], events) << " % (left "
             << withLifetime[0] << ", right " << withLifetime[1] << ") |\n"
             << "| right camera's clock against the left one's | " << clocks.result << " |\n"
             << "| row alignment of the pair (estimateRowAlignment, " << pairCheck.span() << ") | " << pairCheck.rowResult() << " |\n"
             << "| disparity the pair's events line up at (estimateDominantDisparity, " << pairCheck.span() << ") | "
             << pairCheck.disparityResult() << " |\n"
             << "| dominant disparity | " << dominant << " px (" << pct(votes, withDisparity[0] + withDisparity[1])
             << " % of estimates) |\n"
             << "| confidence of the left estimates (quartiles) | "
             << (opt.mode == "sgbm" ? std::string("none (frames + SGBM give no confidence)") : confidenceQuartiles(confidences)) << " |\n";
        if (source.hasTruth())
            text << "| ground truth: density (estimated / non-occluded signal) | " << scores.density() << " % |\n"
                 << "| ground truth: estimates within 1 px | " << scores.precision() << " % |\n"
                 << "| ground truth: matching rate (left signal events within 1 px, over all of them) | "
                 << scores.matchingRate() << " % |\n"
                 << "| ground truth: left signal events 1-2 px off / over 2 px off / without a disparity | "
                 << cv::format("%.1f / %.1f / %.1f", pct(scores.leftWithin2 - scores.leftWithin1, scores.leftSignal),
                               pct(scores.leftEstimated - scores.leftWithin2, scores.leftSignal),
                               pct(scores.leftSignal - scores.leftEstimated, scores.leftSignal))
                 << " % |\n"
                 << "| ground truth: mean absolute disparity error | " << scores.meanAbsError() << " px |\n";
        text << "| outputs | " << (opt.csv ? "events.csv, " : "") << pictures << " of " << windows
             << " windows as disparity_NNNNN.png" << (video.isOpened() ? ", disparity.avi" : "")
             << ", disparity_histogram.png"
             << (opt.record.empty() ? std::string()
                                    : ", the events read in " + opt.record + (source.hasTruth() ? " (+ .gt.csv)" : ""))
             << " |\n";
        std::ofstream(opt.output + "/summary.md") << text.str();
        std::cout << text.str();
        return 0;
    }
    catch (const std::exception& e)
    {
        std::cerr << "event_stereo: " << errorText(e) << "\n";
        return 1;
    }
}
