// event_stereo: per-event stereo disparity, depth and lifetime (StereoEventMatcher, or FrameStereoMatcher with
// --mode=sgbm) on a stereo recording, a live stereo DAVIS pair, or a simulated scene; this project's main job.
//
//   event_stereo [--input=FILE | --left=FILE --right=FILE | --live [--live-ms=MS]] [--record=FILE] [--calib=FILE] [--sensor=WxH]
//                [--left-camera-value=0|1] [--one-based] [--right-time-offset-ms=MS|auto] [--mode=coupled|decoupled|fixed|sgbm]
//                [--min-disparity=PX] [--max-disparity=PX] [--frame-ms=MS] [--threads=N] [--no-csv]
//                [--all-frames] [--output=DIR] [--set=NAME=VALUE,...] [--scene=NAME --duration-ms=MS [--sensor-set=NAME=VALUE,...]]
//                [--filter=NAME [--filter-set=NAME=VALUE,...]]        (no input: simulate, with ground truth)
//
// Writes into DIR: events.csv (t,x,y,p,camera,disparity,depth,lifetime,flags,confidence per event, x/y rectified),
// disparity.avi with one frame per --frame-ms window when a video writer is available (left | right active
// events coloured by disparity, the paper's Figure 1; plus the ground truth below when simulated), the same
// picture as disparity_NNNNN.png (NNNNN: the window) for the first window and one per eighth of the run
// (--all-frames: every window), disparity_histogram.png and summary.md (events/s, share with disparity and with lifetime, dominant
// disparity, the quartiles of the left estimates' confidence, input events outside the sensor or going back
// in time, the right camera's clock against the left one's (estimated and applied by default), the pair
// check, and errors against the ground truth when simulated). Progress, and warnings when the pair's rows are
// off or its events line up outside the range or with the cameras exchanged, go to stderr.

#include <opencv2/event.hpp>
#include <opencv2/core/utils/filesystem.hpp>  // after a core header: it needs CV_EXPORTS
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "command_line.hpp"
#include "algorithm_settings.hpp"
#include "sample_pictures.hpp"
#include "sample_progress.hpp"
#include "sample_stereo_pair.hpp"
#include "sample_stereo_pictures.hpp"
#include "sample_stereo_source.hpp"
#include "sample_stereo_tally.hpp"
#include "stereo_method.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>

using namespace cv;
using namespace cv::event;

namespace {

struct Options : StereoSourceOptions
{
    // Defaults: the keys below.
    std::string calib, output, mode, settings, filter, filterSettings, record;
    bool csv = true, allFrames = false;
    int minDisparity = 0, maxDisparity = 0;
    // Row bands (setNumThreads): one thread unless asked, as they gain little where events crowd mid-view.
    int threads = 1;
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
    "{sensor            |            | sensor size WxH or a name (DVS128, DAVIS240, DAVIS346) when the format has none; the model --scene is simulated on (default DAVIS240)}"
    "{left-camera-value | 0          | the camera column's value that means left, in text recordings}"
    "{one-based         | false      | text recordings count pixels from 1}"
    "{right-time-offset-ms | auto    | added to the right camera's timestamps [ms]; auto: estimated from the first seconds of events (estimateClockOffset) and applied when the events are clear about it}"
    "{mode              | coupled    | coupled, decoupled, fixed (StereoEventMatcher) or sgbm (frames + StereoSGBM, FrameStereoMatcher)}"
    "{min-disparity     | 0          | smallest disparity searched [px]}"
    "{max-disparity     | 40         | largest disparity searched [px]}"
    "{frame-ms          | 33         | window of one video frame (and of one frame of sgbm) [ms]}"
    "{threads           | 1          | row bands on their own threads (the same results; on two cores little faster on realistic scenes: Threads in doc/stereo.md); 0: the CPUs, at most 4}"
    "{no-csv            | false      | do not write events.csv}"
    "{all-frames        | false      | a PNG for every window, not a handful}"
    "{output            | output/event_stereo | output folder}"
    "{scene             | boxes      | simulated scene when no input is given: boxes, boxes_fast, walking, walking_near, low_contrast (realistic), boxes_pair, boxes_fast_pair, walking_pair (as a real DAVIS240 pair records them), boxes_flicker (a flickering lamp), fan, pendulum, pendulum_patterned (the TUM pairs' scenes, with --sensor=DVS128); plane, two_planes, moving_line, faint_line, cluttered}"
    "{duration-ms       | 1000       | length of the simulated scene [ms]}"
    "{sensor-set        |            | the simulated scene's sensor and rig settings NAME=VALUE, comma separated (SimulatorSettings fields, e.g. rightScale=0.0075,jitterUs=300)}"
    "{set               |            | matcher parameters NAME=VALUE, comma separated (e.g. uniquenessRatio=20,costWindow=11)}"
    "{filter            |            | a noise filter in front of the matcher: background_activity, trail, refractory, hot_pixels, anti_flicker}"
    "{filter-set        |            | filter parameters NAME=VALUE, comma separated (e.g. correlationTime=10000)}";

bool parse(int argc, char** argv, Options& o)
{
    ProgramCommandLine cmd(argc, argv, keys,
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
    o.sensorSettings = cmd.get<std::string>("sensor-set");
    if (o.simulated() && cmd.has("sensor"))
        o.sceneModel = sceneSensorModel(cmd.get<std::string>("sensor"));
    o.durationMs = cmd.get<double>("duration-ms");
    o.settings = cmd.get<std::string>("set");
    o.filter = cmd.get<std::string>("filter");
    o.filterSettings = cmd.get<std::string>("filter-set");
    if (!StereoMethod::known(o.mode))
        throw std::runtime_error("--mode=" + o.mode + ": use " + StereoMethod::names());
    if ((o.left.empty()) != (o.right.empty()))
        throw std::runtime_error("--left and --right go together");
    if (!(o.frameMs > 0))
        throw std::runtime_error("--frame-ms must be > 0");
    return true;
}

std::string progressText(int64 events, double seconds)
{
    return cv::format("%lld events, %.2f Mev/s", (long long)events, (double)events / std::max(1e-9, seconds) / 1e6);
}

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
        const ClockCheck clocks = checkClocks(opt, opt.estimateClock, opt.filter, opt.filterSettings, opt.calib,
                                             opt.minDisparity, opt.maxDisparity);
        opt.rightTimeOffsetMs = clocks.appliedMs;
        SampleStereoSource source(opt);
        const Size size = source.sensorSize();
        if (size.empty())
            throw sensorSizeMissing(source.name());

        StereoMethod method(opt.mode, size);
        method.setDisparityRange(opt.minDisparity, opt.maxDisparity);
        if (method.matcher)
            method.matcher->setNumThreads(opt.threads);
        else
            method.frames->setFrameWindow(opt.frameMs * 1000);
        method.applySettings(opt.settings);
        Ptr<EventFilter> filter = createSampleFilter(opt.filter, opt.filterSettings, size);
        if (!opt.calib.empty())
            method.setCalibration(readStereoCalibration(opt.calib));
        else if (source.hasTruth())
        {
            const SimulatorSettings& s = source.simulator()->getSettings();
            method.setCalibration(StereoCalibration::fromRectified(size, s.focalLength, s.baseline));
        }

        std::ofstream csv;
        if (opt.csv)
        {
            csv.open(opt.output + "/events.csv");
            csv << "t,x,y,p,camera,disparity,depth,lifetime,flags,confidence\n";
        }
        const int zoom = samplePictureZoom(size);
        VideoWriter video;
        SampleStereoTally tally(opt.minDisparity, opt.maxDisparity, size.width);
        int64 pictures = 0, windows = 0, filtered = 0;
        int lastEighth = 0;
        SampleProgress progress;
        double seconds = 0, filterSeconds = 0, windowEnd = 0;
        std::vector<Event> packet;
        Mat keepMask, truth, disparity, lifetime, flags, depth, confidence, truthDisparity;
        SamplePairCheck pairCheck(size, opt.minDisparity, opt.maxDisparity,
                                  sampleCameraSwapAdvice(!opt.left.empty(), source.isText(), opt.leftCameraValue), opt.calib);
        if (source.hasTruth())
            pairCheck.setDesignedMisalignment(source.simulator()->getSettings().rightRowOffset,
                                              source.simulator()->getSettings().rightRollRad);
        if (!opt.record.empty())
            source.record(opt.record);
        while (source.next(packet, truth, windowEnd))
        {
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
            method.process(packet, disparity, lifetime, flags, depth, confidence);
            seconds += (double)(getTickCount() - t0) / getTickFrequency();
            tally.add(packet, disparity, flags, confidence, source.hasTruth() ? truth : Mat());
            if (source.hasTruth())
                truthDisparity = Mat::zeros(size, CV_32F);
            for (size_t i = 0; i < packet.size(); i++)
            {
                const Event& e = packet[i];
                if (source.hasTruth() && e.camera == CAMERA_LEFT && !((int)truth.at<float>((int)i, GT_FLAGS) & GT_FLAG_NOISE))
                    truthDisparity.at<float>(e.y, e.x) = truth.at<float>((int)i, GT_DISPARITY);
                if (csv.is_open())
                {
                    char line[160];  // one per event: no allocation
                    std::snprintf(line, sizeof(line), "%lld,%d,%d,%d,%d,%.2f,%.4f,%.0f,%d,%.3f\n", (long long)e.t, e.x,
                                  e.y, e.p, e.camera, disparity.at<float>((int)i), depth.at<float>((int)i),
                                  lifetime.at<float>((int)i), flags.at<int>((int)i), confidence.at<float>((int)i));
                    csv << line;
                }
            }

            const Mat picture = sampleEnlarge(stereoWindowPicture(method, windowEnd - 1, truthDisparity), zoom);
            if (opt.allFrames || sampleIsPictureWindow(windows, source.progress(), lastEighth))
            {
                imwrite(opt.output + cv::format("/disparity_%05lld.png", (long long)windows), picture);
                pictures++;
            }
            if (windows++ == 0)
                video.open(opt.output + "/disparity.avi", VideoWriter::fourcc('M', 'J', 'P', 'G'),
                           std::max(1.0, 1000.0 / opt.frameMs), picture.size());
            if (video.isOpened())
                video.write(picture);
            progress.update(source.progress(), progressText(tally.events(), seconds));
        }
        progress.finish(source.progress(), progressText(tally.events(), seconds));

        imwrite(opt.output + "/disparity_histogram.png", tally.histogramPicture());
        const int64 events = tally.events();
        const int64 outside = (int64)source.rejectedOutside(), backwards = (int64)source.timeBackwards();
        if (outside > 0)
            std::cerr << "event_stereo: warning: "
                      << outsideEventsWarning(outside, size.width, size.height, source.isText(), opt.oneBased,
                                              source.eventsTouchZero()) << "\n";
        std::ostringstream text;
        text << "# event_stereo summary\n\n| | |\n|---|---|\n"
             << "| source | " << source.name() << " |\n"
             << "| sensor | " << size.width << " x " << size.height << (opt.calib.empty() ? "" : ", calibration " + opt.calib) << " |\n"
             << "| mode | " << opt.mode << ", disparities " << opt.minDisparity << ".." << opt.maxDisparity << " px |\n"
             << (filter ? cv::format("| filter | %s: kept %lld of %lld events (%.1f %%), %.1f Mev/s |\n", opt.filter.c_str(),
                                     (long long)events, (long long)filtered, filtered ? 100.0 * events / filtered : 0.0,
                                     (double)filtered / std::max(1e-9, filterSeconds) / 1e6) : std::string())
             << tally.eventRows()
             << "| input events outside the sensor (not processed) / going back in time (clamped) | "
             << outside << " / " << backwards << " |\n"
             << "| processing | " << seconds << " s, " << (double)events / std::max(1e-9, seconds) / 1e6 << " Mev/s ("
             << opt.threads << (opt.threads == 1 ? " thread" : " threads") << ") |\n"
             << tally.estimateRows()
             << "| right camera's clock against the left one's | " << clocks.result << " |\n"
             << "| row alignment of the pair (estimateRowAlignment, " << pairCheck.span() << ") | " << pairCheck.rowResult() << " |\n"
             << "| disparity the pair's events line up at (estimateDominantDisparity, " << pairCheck.span() << ") | "
             << pairCheck.disparityResult() << " |\n"
             << tally.disparityRows(method.hasConfidence());
        if (source.hasTruth())
            text << tally.truthRows();
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
