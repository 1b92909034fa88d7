// event_evaluate: runs a stereo method on a recording with per-event ground truth and writes a report.
//
//   event_evaluate [--scene=NAME [--sensor=DVS128] --duration-ms=MS | --input=REC [--gt=REC.gt.csv]] [--method=coupled]
//                  [--window-ms=33] [--output=DIR] [--set=PARAM=VALUE[,PARAM=VALUE...]] [--min-quality=Q]
//   methods: coupled (the default), decoupled, fixed (StereoEventMatcher modes), sgbm, lifetime, none
//
// Ground truth comes from the simulator (a named scene, simulated in memory) or from the side file that
// writeSimulatedRecording() writes (`t,x,y,p,camera,depth,disparity,flow_x,flow_y,lifetime,flags`).
// Methods: the StereoEventMatcher modes and `sgbm` (FrameStereoMatcher: what users do today, dv-processing's
// semi-dense matcher: edge frames per window + cv::StereoSGBM), with --set for their parameters (FileStorage names, e.g.
// --set=uniquenessRatio=20,costWindow=7, lifetimeEstimator.inlierDistance=0 for its lifetime estimator);
// `lifetime` = LifetimeEstimator per camera (lifetime and noise metrics, no disparity; --set takes its names;
// --min-quality drops the lifetimes of lower quality: those events count as without a lifetime).
//
// Writes DIR/report.md and DIR/metrics.csv (disparity density, share within 1 px, matching rate (left signal
// events within 1 px of the truth over all left signal events) and where the other left signal events went,
// precision at 50 / 75 % density and with no rejection (the per-event modes run a second matcher with
// minimum confidence 0 and rank its estimates by confidence), mean absolute disparity
// error, relative depth error, lifetime median relative error, noise precision / recall, events with a
// lifetime, time per event) and pictures: DIR/disparity_error_histogram.png, DIR/disparity_vs_truth.png and,
// for the per-event modes, DIR/density_precision.png.

#include <opencv2/calib3d.hpp>
#include <opencv2/event.hpp>
#include <opencv2/core/utils/filesystem.hpp>  // after a core header: it needs CV_EXPORTS
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "command_line.hpp"
#include "algorithm_settings.hpp"
#include "simulator_settings.hpp"
#include "sample_evaluation.hpp"
#include "sample_evaluation_pictures.hpp"
#include "sample_evaluation_report.hpp"

#include <array>
#include <chrono>
#include <memory>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

using namespace cv;
using namespace cv::event;
using namespace sample_evaluation;

namespace {

struct Options
{
    // Defaults: the keys below.
    std::string scene, input, gt, method, output;
    int sceneModel = SENSOR_DAVIS240;  // --sensor
    std::string settings;  // matcher parameters, --set as given
    std::string sensorSettings;  // --sensor-set, as given
    std::string filter, filterSettings;  // --filter, --filter-set
    double durationMs = 0, windowMs = 0;
    double minQuality = 0;  // --method=lifetime: lifetimes of lower quality dropped
};

const char* const keys =
    "{help h      | false      | print this message}"
    "{scene       | two_planes | simulated scene, when no --input is given}"
    "{duration-ms | 500        | length of the simulated scene [ms]}"
    "{sensor      | DAVIS240   | the sensor model --scene is simulated on: DVS128, DAVIS240 or DAVIS346}"
    "{input       |            | a recording with per-event ground truth beside it}"
    "{gt          |            | the ground truth file; default: the recording's name + .gt.csv}"
    "{method      | coupled    | coupled, decoupled, fixed (StereoEventMatcher modes), sgbm (frames + StereoSGBM, FrameStereoMatcher), lifetime, or none (evaluates --filter alone)}"
    "{filter      |            | a noise filter in front of the method: background_activity, trail, refractory, hot_pixels, anti_flicker}"
    "{filter-set  |            | filter parameters NAME=VALUE, comma separated (FileStorage names, e.g. correlationTime=5000)}"
    "{window-ms   | 33         | evaluation window (and SGBM frame) [ms]}"
    "{output      | evaluation | output folder}"
    "{set         |            | method parameters NAME=VALUE, comma separated (FileStorage names, e.g. uniquenessRatio=20; the matcher's lifetime estimator as lifetimeEstimator.NAME, e.g. lifetimeEstimator.inlierDistance=0; with --method=lifetime the estimator's own names)}"
    "{sensor-set  |            | simulator settings NAME=VALUE, comma separated (SimulatorSettings fields, e.g. jitterUs=300)}"
    "{min-quality | 0          | --method=lifetime: drop the lifetimes below this quality (0..1, LifetimeEstimator::process()); those events count as without a lifetime}";

}  // namespace

int main(int argc, char** argv)
{
    Options o;
    try
    {
        ProgramCommandLine cmd(argc, argv, keys,
                              "Runs a stereo method on a recording with per-event ground truth and writes a report.");
        if (cmd.helpShown())
            return 0;
        o.scene = cmd.get<std::string>("scene");
        o.durationMs = cmd.get<double>("duration-ms");
        o.sceneModel = sceneSensorModel(cmd.get<std::string>("sensor"));
        o.input = cmd.get<std::string>("input");
        o.gt = cmd.get<std::string>("gt");
        o.method = cmd.get<std::string>("method");
        o.windowMs = cmd.get<double>("window-ms");
        o.output = cmd.get<std::string>("output");
        o.settings = cmd.get<std::string>("set");
        o.sensorSettings = cmd.get<std::string>("sensor-set");
        o.filter = cmd.get<std::string>("filter");
        o.filterSettings = cmd.get<std::string>("filter-set");
        o.minQuality = cmd.get<double>("min-quality");
        if (!(o.minQuality >= 0 && o.minQuality <= 1))
            throw std::runtime_error(cv::format("--min-quality=%g: must be 0..1", o.minQuality));
        if (o.minQuality > 0 && o.method != "lifetime")
            throw std::runtime_error("--min-quality: only with --method=lifetime (the matchers' lifetimes have no quality)");
        if (o.method != "lifetime" && o.method != "none" && !StereoMethod::known(o.method))
            throw std::runtime_error("--method=" + o.method + ": available methods: coupled, decoupled, fixed, sgbm, lifetime, none");
        if (!utils::fs::createDirectories(o.output))
            throw std::runtime_error(o.output + ": cannot create the output folder");

        Ptr<StereoEventSimulator> sim;
        EventCapture cap;
        SimulatedGroundTruthReader truthFile;
        Size size;
        if (o.input.empty())
        {
            sim = simulatorWithSettings(o.scene, o.sceneModel, o.sensorSettings);
            size = sim->getSensorSize();
        }
        else
        {
            cap.set(EVENT_CAP_PROP_WINDOW_US, o.windowMs * 1000);
            cap.open(o.input);
            cap.set(EVENT_CAP_PROP_POS_US, 0);  // windows start at t = 0, as for the simulator (simulated files start there)
            size = cap.getSensorSize();
            truthFile.open(o.gt.empty() ? o.input + ".gt.csv" : o.gt);
        }
        std::unique_ptr<Method> method;
        Ptr<EventFilter> filter = createSampleFilter(o.filter, o.filterSettings, size);
        std::vector<uchar> keepMask;
        std::vector<Event> keptEvents;
        MethodOutput keptEstimate;
        Mat filterPicture;
        if (o.method == "none")
        {
            if (!o.settings.empty())
                throw std::runtime_error("--set: --method=none has no parameters (--filter-set sets the filter's)");
            method.reset(new NoEstimate());
        }
        else if (o.method == "lifetime")
            method.reset(new Lifetime(size, o.settings, o.minQuality));
        else
            method.reset(new Matcher(size, o.method, o.windowMs * 1000, o.settings));
        MethodOutput estimate;
        EvaluationTotals acc;
        std::vector<Event> window;
        std::vector<std::array<float, 6>> truth;
        double seconds = 0;
        double t = 0;
        for (;;)
        {
            // Next window of events and their ground truth.
            truth.clear();
            Mat g;
            if (sim)
            {
                if (t >= o.durationMs * 1000)
                    break;
                t += o.windowMs * 1000;
                sim->generate(std::min(t, o.durationMs * 1000), window, g);
            }
            else
            {
                if (!cap.read(window))
                    break;
                truthFile.read(window, g);
            }
            for (int r = 0; r < g.rows; r++)
                truth.push_back({ { g.at<float>(r, 0), g.at<float>(r, 1), g.at<float>(r, 2), g.at<float>(r, 3),
                                    g.at<float>(r, 4), g.at<float>(r, 5) } });
            if (filter)
            {
                // The method sees the kept events only; every event still counts (a removed signal event is
                // one the method did not match).
                const auto f0 = std::chrono::steady_clock::now();
                Mat mask;
                filter->filter(window, keptEvents, mask);
                acc.filterSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - f0).count();
                keepMask.assign(mask.begin<uchar>(), mask.end<uchar>());
                const auto t0 = std::chrono::steady_clock::now();
                method->process(keptEvents, keptEstimate);
                seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
                method->processUnfiltered(keptEvents, keptEstimate);
                spreadOverWindow(keptEstimate, keepMask, estimate);
                acc.addFiltered(truth, keepMask);
                if (!window.empty())
                    filterPicture = drawFilterBeforeAfter(window, truth, keepMask, size);
            }
            else
            {
                const auto t0 = std::chrono::steady_clock::now();
                method->process(window, estimate);
                seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
                method->processUnfiltered(window, estimate);
            }

            acc.add(window, truth, estimate, size);
        }

        EvaluationReport report;
        report.method = o.method;
        report.source = !sim ? o.input
                      : o.sceneModel == SENSOR_DAVIS240 ? "simulated scene " + o.scene
                      : "simulated scene " + o.scene + " on a " + getSensorModelName(o.sceneModel);
        report.output = o.output;
        report.filter = filter ? o.filter : std::string();
        report.windowMs = o.windowMs;
        report.seconds = seconds;
        report.disparities = estimate.hasDisparity;
        report.lifetimes = estimate.hasLifetime;
        writeEvaluationReport(report, acc, filterPicture);
        return 0;
    }
    catch (const std::exception& e)
    {
        std::cerr << "event_evaluate: " << errorText(e) << "\n";
        return 1;
    }
}
