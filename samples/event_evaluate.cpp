// event_evaluate: runs a stereo method on a recording with per-event ground truth and writes a report.
//
//   event_evaluate [--scene=NAME --duration-ms=MS | --input=REC [--gt=REC.gt.csv]] [--method=coupled]
//                  [--window-ms=33] [--output=DIR] [--set=PARAM=VALUE[,PARAM=VALUE...]]
//   methods: coupled (the default), decoupled, fixed, sgbm (StereoEventMatcher modes), lifetime, none
//
// Ground truth comes from the simulator (a named scene, simulated in memory) or from the side file that
// writeSimulatedRecording() writes (`t,x,y,p,camera,depth,disparity,flow_x,flow_y,lifetime,flags`).
// Methods: the StereoEventMatcher modes (`sgbm` = what users do today, dv-processing's semi-dense matcher:
// edge frames per window + cv::StereoSGBM), with --set for matcher parameters (FileStorage names, e.g.
// --set=uniquenessRatio=20,costWindow=7, lifetimeEstimator.inlierDistance=0 for its lifetime estimator);
// `lifetime` = LifetimeEstimator per camera (lifetime and noise metrics, no disparity; --set takes its names).
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

#include "sample_command_line.hpp"
#include "sample_algorithm_settings.hpp"

#include <array>
#include <chrono>
#include <memory>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

using namespace cv;
using namespace cv::event;

namespace {

struct Options
{
    // Defaults: the keys below.
    std::string scene, input, gt, method, output;
    std::string settings;  // matcher parameters, --set as given
    std::string sensorSettings;  // --sensor-set, as given
    std::string filter, filterSettings;  // --filter, --filter-set
    double durationMs = 0, windowMs = 0;
};

// Ground truth for the events, from the simulator or from a .gt.csv side file read in step.
class TruthSource
{
public:
    explicit TruthSource(const std::string& csv) : in_(csv)
    {
        if (!in_)
            throw std::runtime_error(csv + ": cannot open the ground-truth file");
        std::string header;
        std::getline(in_, header);
        path_ = csv;
    }
    // Ground truth of the next event, checked against it.
    std::array<float, 6> next(const Event& e)
    {
        std::string line;
        if (!std::getline(in_, line))
            throw std::runtime_error(path_ + ": fewer ground-truth lines than events");
        long long t;
        int x, y, p, c, flags;
        float v[5];
        if (std::sscanf(line.c_str(), "%lld,%d,%d,%d,%d,%f,%f,%f,%f,%f,%d", &t, &x, &y, &p, &c, &v[0], &v[1], &v[2], &v[3],
                        &v[4], &flags) != 11 || t != e.t || x != e.x || y != e.y || c != e.camera)
            throw std::runtime_error(path_ + ": ground-truth line \"" + line + "\" does not describe the next event");
        return { { v[0], v[1], v[2], v[3], v[4], (float)flags } };
    }

private:
    std::ifstream in_;
    std::string path_;
};

struct EvaluationTotals
{
    int64 events = 0, signal = 0, withLifetime = 0;
    // The disparities scored (scoreStereoEvents): over every event; over the left signal events the right camera
    // sees (not flagged occluded: what a matcher can reach); over the events motion caused (flicker left out:
    // with a flickering lamp in view, what a user's moving scene gets).
    StereoEventScores scores, visible, motion;
    // Left signal events without a disparity: rejected (STEREO_AMBIGUOUS), no candidate (STEREO_NO_COUNTERPART);
    // the rest had neither (outside the rectified image).
    int64 leftAmbiguous = 0, leftNoCounterpart = 0;
    int64 withLifetimeCamera[2] = { 0, 0 };
    int64 noiseTrue = 0, noiseFlagged = 0, noiseCorrect = 0;
    std::vector<int> errorHistogram = std::vector<int>(41, 0);  // |error| in 0.25 px bins up to 10 px
    std::vector<double> lifetimeRelErrors;
    // Signal events a flickering plane caused (GT_FLAG_FLICKER); signal - flicker are the motion's.
    int64 flicker = 0;
    // --filter: what it kept of the motion's events, of the noise and of the flicker, and its own time.
    int64 filterSignalKept = 0, filterNoiseKept = 0, filterFlickerKept = 0;
    double filterSeconds = 0;
    // Non-occluded signal events with a best estimate (no rejection): its confidence, and whether it is within 1 px.
    std::vector<std::pair<float, bool>> ranked;
};

// Precision (share within 1 px) of the most confident estimates that make up `density` % of the
// non-occluded signal events; -1 when the estimates do not reach that density. `ranked` is sorted.
double precisionAtDensity(const std::vector<std::pair<float, bool>>& ranked, int64 candidates, double density)
{
    const size_t n = (size_t)std::llround(density / 100.0 * (double)candidates);
    if (n == 0 || n > ranked.size())
        return -1;
    size_t good = 0;
    for (size_t i = 0; i < n; i++)
        good += ranked[i].second;
    return 100.0 * (double)good / (double)n;
}

// The density-precision curve of the ranked estimates, with the method's own operating point (its
// rejection threshold) marked.
void drawDensityPrecision(const std::vector<std::pair<float, bool>>& ranked, int64 candidates, double density,
                          double precision, const std::string& path, const std::string& title)
{
    const int w = 500, h = 300, left = 50, top = 40;
    Mat img(h + top + 50, w + left + 20, CV_8UC3, Scalar::all(255));
    const double lowest = 50;  // precision axis from 50 to 100 %
    auto at = [&](double d, double p) {
        return Point(left + (int)std::lround(d / 100 * w), top + (int)std::lround((100 - std::max(lowest, p)) / (100 - lowest) * h));
    };
    rectangle(img, at(0, 100), at(100, lowest), Scalar(200, 200, 200));
    for (int p = 60; p < 100; p += 10)
        line(img, at(0, p), at(100, p), Scalar(235, 235, 235));
    size_t good = 0;
    Point previous(-1, -1);
    const size_t step = std::max<size_t>(1, ranked.size() / 500);
    for (size_t i = 0; i < ranked.size(); i++)
    {
        good += ranked[i].second;
        if ((i + 1) % step != 0 && i + 1 != ranked.size())
            continue;
        const Point q = at(100.0 * (double)(i + 1) / (double)candidates, 100.0 * (double)good / (double)(i + 1));
        if (previous.x >= 0)
            line(img, previous, q, Scalar(180, 90, 30), 2, LINE_AA);
        previous = q;
    }
    circle(img, at(density, precision), 5, Scalar(0, 0, 220), FILLED, LINE_AA);
    putText(img, title, Point(10, 22), FONT_HERSHEY_SIMPLEX, 0.5, Scalar(0, 0, 0), 1, LINE_AA);
    putText(img, "100 %", Point(5, top + 5), FONT_HERSHEY_SIMPLEX, 0.35, Scalar(0, 0, 0), 1, LINE_AA);
    putText(img, "50 %", Point(10, top + h), FONT_HERSHEY_SIMPLEX, 0.35, Scalar(0, 0, 0), 1, LINE_AA);
    putText(img, "density (estimates / non-occluded signal events), 0 .. 100 %", Point(left, top + h + 20),
            FONT_HERSHEY_SIMPLEX, 0.38, Scalar(0, 0, 0), 1, LINE_AA);
    putText(img, "up: precision (within 1 px); red dot: the rejection threshold", Point(left, top + h + 38),
            FONT_HERSHEY_SIMPLEX, 0.38, Scalar(0, 0, 0), 1, LINE_AA);
    imwrite(path, img);
}

// What a method says about each event of a window: disparity (-1: none), lifetime [us] (0: noise), and
// which of the two it estimates at all.
struct MethodOutput
{
    std::vector<float> disparity, lifetime, confidence;
    std::vector<int> flags;
    // The same method with no rejection (minimum confidence 0): every event's best estimate and its confidence,
    // for the density-precision curve; empty for methods without a confidence.
    std::vector<float> bestDisparity, bestConfidence;
    bool hasDisparity = false, hasLifetime = false;
};

class Method
{
public:
    virtual ~Method() {}
    virtual void process(const std::vector<Event>& window, MethodOutput& out) = 0;
    // Fills out.bestDisparity / bestConfidence (not timed); nothing for methods without a confidence.
    virtual void processUnfiltered(const std::vector<Event>& window, MethodOutput& out)
    {
        (void)window;
        out.bestDisparity.clear();
        out.bestConfidence.clear();
    }
};

// A StereoEventMatcher mode: COUPLED / DECOUPLED / FIXED_INTERVAL per event, FRAME_SGBM per window (the
// windows here are the matcher's frame windows, so each frame gets exactly one window of events).
class Matcher CV_FINAL : public Method
{
public:
    Matcher(Size size, int mode, double windowUs, const std::string& settings) : matcher_(StereoEventMatcher::create(size, mode))
    {
        matcher_->setFrameWindow(windowUs);
        applyMatcherSettings(matcher_, settings);
        // Without rejection (the default) the run itself gives every event's best estimate.
        if (mode != STEREO_FRAME_SGBM && matcher_->getMinConfidence() > 0)
        {
            unfiltered_ = StereoEventMatcher::create(size, mode);
            applyMatcherSettings(unfiltered_, settings);
            unfiltered_->setMinConfidence(0);
        }
    }

    void process(const std::vector<Event>& window, MethodOutput& out) CV_OVERRIDE
    {
        Mat disparity, lifetime, flags, confidence;
        matcher_->process(window, disparity, lifetime, flags, noArray(), noArray(), confidence);
        out.hasDisparity = true;
        out.hasLifetime = matcher_->getMode() == STEREO_COUPLED || matcher_->getMode() == STEREO_DECOUPLED;
        out.disparity.assign(disparity.begin<float>(), disparity.end<float>());
        out.lifetime.assign(lifetime.begin<float>(), lifetime.end<float>());
        out.flags.assign(flags.begin<int>(), flags.end<int>());
        out.confidence.assign(confidence.begin<float>(), confidence.end<float>());
    }

    void processUnfiltered(const std::vector<Event>& window, MethodOutput& out) CV_OVERRIDE
    {
        if (!unfiltered_ && matcher_->getMode() != STEREO_FRAME_SGBM)
        {
            out.bestDisparity = out.disparity;
            out.bestConfidence = out.confidence;
            return;
        }
        if (!unfiltered_)
            return Method::processUnfiltered(window, out);
        Mat disparity, confidence;
        unfiltered_->process(window, disparity, noArray(), noArray(), noArray(), noArray(), confidence);
        out.bestDisparity.assign(disparity.begin<float>(), disparity.end<float>());
        out.bestConfidence.assign(confidence.begin<float>(), confidence.end<float>());
    }

private:
    Ptr<StereoEventMatcher> matcher_, unfiltered_;
};

// Lifetime per camera (LifetimeEstimator, plane fitting); no disparity.
class Lifetime CV_FINAL : public Method
{
public:
    Lifetime(Size size, const std::string& settings)
        : est_{ LifetimeEstimator::create(size), LifetimeEstimator::create(size) }
    {
        for (const Ptr<LifetimeEstimator>& est : est_)
            applyAlgorithmSettings(est, settings, "--set", "lifetime estimator");
    }

    void process(const std::vector<Event>& window, MethodOutput& out) CV_OVERRIDE
    {
        out.hasLifetime = true;
        out.lifetime.resize(window.size());
        for (size_t i = 0; i < window.size(); i++)
        {
            Vec2f flow;
            int status;
            out.lifetime[i] = est_[window[i].camera]->processEvent(window[i], flow, status);
        }
    }

private:
    Ptr<LifetimeEstimator> est_[2];
};

// No estimate at all: --method=none evaluates a --filter alone.
class NoEstimate CV_FINAL : public Method
{
public:
    void process(const std::vector<Event>&, MethodOutput& out) CV_OVERRIDE { out = MethodOutput(); }
};

// The method's output for the kept events of a window, spread back over the whole window: a removed event has
// no disparity, no lifetime (the filter calls it noise) and no best estimate.
void spreadOverWindow(const MethodOutput& kept, const std::vector<uchar>& keepMask, MethodOutput& out)
{
    const size_t n = keepMask.size();
    MethodOutput all;
    all.hasDisparity = kept.hasDisparity;
    all.hasLifetime = kept.hasLifetime;
    auto spread = [&](const std::vector<float>& from, std::vector<float>& to, float none) {
        if (from.empty())
            return;
        to.assign(n, none);
        for (size_t i = 0, k = 0; i < n; i++)
            if (keepMask[i])
                to[i] = from[k++];
    };
    spread(kept.disparity, all.disparity, -1.f);
    spread(kept.lifetime, all.lifetime, 0.f);
    spread(kept.confidence, all.confidence, 0.f);
    spread(kept.bestDisparity, all.bestDisparity, -1.f);
    spread(kept.bestConfidence, all.bestConfidence, 0.f);
    if (!kept.flags.empty())
    {
        all.flags.assign(n, 0);
        for (size_t i = 0, k = 0; i < n; i++)
            if (keepMask[i])
                all.flags[i] = kept.flags[k++];
    }
    out = all;
}

// Left camera's events of a window as a picture: signal ON white, signal OFF grey, noise red, flicker blue; and
// the same for the events a filter kept, side by side.
Mat drawFilterBeforeAfter(const std::vector<Event>& window, const std::vector<std::array<float, 6>>& truth,
                          const std::vector<uchar>& keepMask, Size size)
{
    Mat before(size, CV_8UC3, Scalar::all(0)), after(size, CV_8UC3, Scalar::all(0));
    for (size_t i = 0; i < window.size(); i++)
    {
        const Event& e = window[i];
        if (e.camera != CAMERA_LEFT)
            continue;
        const int flags = (int)truth[i][GT_FLAGS];
        const Vec3b colour = (flags & GT_FLAG_NOISE) ? Vec3b(40, 40, 255)
                           : (flags & GT_FLAG_FLICKER) ? Vec3b(255, 120, 0)
                           : e.p ? Vec3b(255, 255, 255) : Vec3b(150, 150, 150);
        before.at<Vec3b>(e.y, e.x) = colour;
        if (keepMask[i])
            after.at<Vec3b>(e.y, e.x) = colour;
    }
    Mat pair;
    hconcat(std::vector<Mat>{ before, Mat(size.height, 4, CV_8UC3, Scalar(80, 80, 80)), after }, pair);
    resize(pair, pair, Size(), 2, 2, INTER_NEAREST);
    return pair;
}

Mat colourDisparity(const Mat& d, float maxDisparity)
{
    Mat scaled, colour;
    d.convertTo(scaled, CV_8U, 255.0 / maxDisparity);
    applyColorMap(scaled, colour, COLORMAP_JET);
    colour.setTo(Scalar::all(0), d <= 0);
    return colour;
}

// Bars with the first and last bin labelled "0" and the range end.
void drawHistogram(const std::vector<int>& h, const std::string& path, const std::string& title,
                   const std::string& endLabel = "10 px")
{
    const int w = 20 * (int)h.size(), height = 300;
    Mat img(height + 70, w + 20, CV_8UC3, Scalar::all(255));  // title above the bars, labels below
    const int peak = std::max(1, *std::max_element(h.begin(), h.end()));
    for (size_t k = 0; k < h.size(); k++)
    {
        const int bar = (int)std::lround((double)h[k] / peak * height);
        rectangle(img, Point(10 + 20 * (int)k, height + 40 - bar), Point(10 + 20 * (int)k + 17, height + 40), Scalar(180, 90, 30), FILLED);
    }
    putText(img, title, Point(10, 25), FONT_HERSHEY_SIMPLEX, 0.5, Scalar(0, 0, 0), 1);
    putText(img, "0", Point(10, height + 60), FONT_HERSHEY_SIMPLEX, 0.4, Scalar(0, 0, 0), 1);
    putText(img, endLabel, Point(w - 30, height + 60), FONT_HERSHEY_SIMPLEX, 0.4, Scalar(0, 0, 0), 1);
    imwrite(path, img);
}

const char* const keys =
    "{help h      | false      | print this message}"
    "{scene       | two_planes | simulated scene, when no --input is given}"
    "{duration-ms | 500        | length of the simulated scene [ms]}"
    "{input       |            | a recording with per-event ground truth beside it}"
    "{gt          |            | the ground truth file; default: the recording's name + .gt.csv}"
    "{method      | coupled    | coupled, decoupled, fixed, sgbm (StereoEventMatcher modes), lifetime, or none (evaluates --filter alone)}"
    "{filter      |            | a noise filter in front of the method: background_activity, trail, refractory, hot_pixels, anti_flicker}"
    "{filter-set  |            | filter parameters NAME=VALUE, comma separated (FileStorage names, e.g. correlationTime=5000)}"
    "{window-ms   | 33         | evaluation window (and SGBM frame) [ms]}"
    "{output      | evaluation | output folder}"
    "{set         |            | method parameters NAME=VALUE, comma separated (FileStorage names, e.g. uniquenessRatio=20; the matcher's lifetime estimator as lifetimeEstimator.NAME, e.g. lifetimeEstimator.inlierDistance=0; with --method=lifetime the estimator's own names)}"
    "{sensor-set  |            | simulator settings NAME=VALUE, comma separated (SimulatorSettings fields, e.g. jitterUs=300)}";

// --sensor-set: the numeric SimulatorSettings fields by name.
void applySimulatorSetting(SimulatorSettings& s, const std::string& name, double value)
{
    const std::pair<const char*, double*> fields[] = {
        { "thresholdOn", &s.thresholdOn }, { "thresholdOff", &s.thresholdOff }, { "thresholdSigma", &s.thresholdSigma }, { "thresholdNoise", &s.thresholdNoise }, { "blurSigmaPx", &s.blurSigmaPx },
        { "rightThresholdScale", &s.rightThresholdScale }, { "refractoryUs", &s.refractoryUs },
        { "noiseRateHz", &s.noiseRateHz }, { "latencyUs", &s.latencyUs }, { "latencySigmaUs", &s.latencySigmaUs },
        { "jitterUs", &s.jitterUs }, { "hotPixelShare", &s.hotPixelShare }, { "hotPixelRateHz", &s.hotPixelRateHz },
        { "leakRateHz", &s.leakRateHz }, { "rightRowOffset", &s.rightRowOffset }, { "rightRollRad", &s.rightRollRad },
        { "maxPixelStep", &s.maxPixelStep }, { "flickerFrequencyHz", &s.flickerFrequencyHz }
    };
    for (const auto& f : fields)
        if (name == f.first)
        {
            *f.second = value;
            return;
        }
    if (name == "seed")
    {
        s.seed = (int)value;
        return;
    }
    std::string known;
    for (const auto& f : fields)
        known += std::string(known.empty() ? "" : ", ") + f.first;
    throw std::runtime_error("--sensor-set: no simulator setting \"" + name + "\" (" + known + ", seed)");
}

}  // namespace

int main(int argc, char** argv)
{
    Options o;
    try
    {
        SampleCommandLine cmd(argc, argv, keys,
                              "Runs a stereo method on a recording with per-event ground truth and writes a report.");
        if (cmd.helpShown())
            return 0;
        o.scene = cmd.get<std::string>("scene");
        o.durationMs = cmd.get<double>("duration-ms");
        o.input = cmd.get<std::string>("input");
        o.gt = cmd.get<std::string>("gt");
        o.method = cmd.get<std::string>("method");
        o.windowMs = cmd.get<double>("window-ms");
        o.output = cmd.get<std::string>("output");
        o.settings = cmd.get<std::string>("set");
        o.sensorSettings = cmd.get<std::string>("sensor-set");
        o.filter = cmd.get<std::string>("filter");
        o.filterSettings = cmd.get<std::string>("filter-set");
        if (o.method != "lifetime" && o.method != "none" && findStereoMode(o.method) < 0)
            throw std::runtime_error("--method=" + o.method + ": available methods: coupled, decoupled, fixed, sgbm, lifetime, none");
        if (!utils::fs::createDirectories(o.output))
            throw std::runtime_error(o.output + ": cannot create the output folder");

        Ptr<StereoEventSimulator> sim;
        EventCapture cap;
        std::unique_ptr<TruthSource> truthFile;
        Size size;
        if (o.input.empty())
        {
            sim = StereoEventSimulator::create(o.scene);
            if (!o.sensorSettings.empty())
            {
                SimulatorSettings settings = sim->getSettings();
                for (const std::pair<std::string, std::string>& item : parseNameValueList("--sensor-set", o.sensorSettings))
                    applySimulatorSetting(settings, item.first, std::stod(item.second));
                sim = StereoEventSimulator::create(sim->getPlanes(), settings);
            }
            size = sim->getSensorSize();
        }
        else
        {
            cap.set(EVENT_CAP_PROP_WINDOW_US, o.windowMs * 1000);
            cap.open(o.input);
            cap.set(EVENT_CAP_PROP_POS_US, 0);  // windows start at t = 0, as for the simulator (simulated files start there)
            size = cap.getSensorSize();
            truthFile.reset(new TruthSource(o.gt.empty() ? o.input + ".gt.csv" : o.gt));
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
            method.reset(new Lifetime(size, o.settings));
        else
            method.reset(new Matcher(size, findStereoMode(o.method), o.windowMs * 1000, o.settings));
        MethodOutput estimate;
        EvaluationTotals acc;
        std::vector<Event> window;
        std::vector<std::array<float, 6>> truth;
        Mat lastEstimate, lastTruth;
        std::vector<uchar> visibleMask, motionMask;
        std::vector<float> depth;
        double seconds = 0;
        double t = 0;
        for (;;)
        {
            // Next window of events and their ground truth.
            truth.clear();
            if (sim)
            {
                if (t >= o.durationMs * 1000)
                    break;
                t += o.windowMs * 1000;
                Mat g;
                sim->generate(std::min(t, o.durationMs * 1000), window, g);
                for (int r = 0; r < g.rows; r++)
                    truth.push_back({ { g.at<float>(r, 0), g.at<float>(r, 1), g.at<float>(r, 2), g.at<float>(r, 3),
                                        g.at<float>(r, 4), g.at<float>(r, 5) } });
            }
            else
            {
                if (!cap.read(window))
                    break;
                for (const Event& e : window)
                    truth.push_back(truthFile->next(e));
            }
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
                for (size_t i = 0; i < window.size(); i++)
                {
                    const int flags = (int)truth[i][GT_FLAGS];
                    const bool noise = (flags & GT_FLAG_NOISE) != 0, flicker = (flags & GT_FLAG_FLICKER) != 0;
                    acc.filterSignalKept += keepMask[i] && !noise && !flicker;
                    acc.filterNoiseKept += keepMask[i] && noise;
                    acc.filterFlickerKept += keepMask[i] && flicker;
                }
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

            lastEstimate = Mat::zeros(size, CV_32F);
            lastTruth = Mat::zeros(size, CV_32F);
            visibleMask.assign(window.size(), 0);
            motionMask.assign(window.size(), 0);
            depth.assign(window.size(), 0.f);
            for (size_t i = 0; i < window.size(); i++)
            {
                const std::array<float, 6>& g = truth[i];
                const int flags = (int)g[GT_FLAGS];
                acc.events++;
                const bool isNoise = (flags & GT_FLAG_NOISE) != 0;
                acc.noiseTrue += isNoise;
                if (estimate.hasLifetime)
                {
                    const bool flagged = estimate.lifetime[i] <= 0;  // no lifetime = classified as noise
                    acc.noiseFlagged += flagged;
                    acc.noiseCorrect += flagged && isNoise;
                    if (!isNoise && !flagged)
                    {
                        acc.withLifetime++;
                        acc.withLifetimeCamera[window[i].camera]++;
                        if (g[GT_LIFETIME] > 0)
                            acc.lifetimeRelErrors.push_back(std::abs(estimate.lifetime[i] - g[GT_LIFETIME]) / g[GT_LIFETIME]);
                    }
                }
                if (isNoise)
                    continue;
                acc.signal++;
                acc.flicker += (flags & GT_FLAG_FLICKER) != 0;
                motionMask[i] = !(flags & GT_FLAG_FLICKER);
                const bool estimated = estimate.hasDisparity && estimate.disparity[i] >= 0;
                if (window[i].camera == CAMERA_LEFT && !estimated && !estimate.flags.empty())
                {
                    acc.leftAmbiguous += (estimate.flags[i] & STEREO_AMBIGUOUS) != 0;
                    acc.leftNoCounterpart += (estimate.flags[i] & STEREO_NO_COUNTERPART) != 0;
                }
                if (flags & GT_FLAG_OCCLUDED)
                    continue;
                visibleMask[i] = 1;
                if (!estimate.bestDisparity.empty() && estimate.bestDisparity[i] >= 0)
                    acc.ranked.push_back(std::make_pair(estimate.bestConfidence[i],
                                                        std::abs(estimate.bestDisparity[i] - g[GT_DISPARITY]) <= 1.0));
                if (window[i].camera == CAMERA_LEFT)
                    lastTruth.at<float>(window[i].y, window[i].x) = g[GT_DISPARITY];
                if (!estimated)
                    continue;
                const float d = estimate.disparity[i];
                const double err = std::abs(d - g[GT_DISPARITY]);
                acc.errorHistogram[std::min<size_t>(acc.errorHistogram.size() - 1, (size_t)(err / 0.25))]++;
                // The depth the pair's own f B gives (true depth x true disparity), whatever f and B are.
                if (d > 0)
                    depth[i] = g[GT_DEPTH] * g[GT_DISPARITY] / d;
                if (window[i].camera == CAMERA_LEFT)
                    lastEstimate.at<float>(window[i].y, window[i].x) = d;
            }
            if (!window.empty())
            {
                // A method without disparities scores as one that estimates none (the counts of events stay).
                if (!estimate.hasDisparity)
                    estimate.disparity.assign(window.size(), -1.f);
                const Mat truthRows((int)truth.size(), 6, CV_32F, truth.data());
                const Mat disparity((int)window.size(), 1, CV_32F, estimate.disparity.data());
                scoreStereoEvents(window, disparity, truthRows, acc.scores, depth);
                scoreStereoEvents(window, disparity, truthRows, acc.visible, noArray(), visibleMask);
                scoreStereoEvents(window, disparity, truthRows, acc.motion, noArray(), motionMask);
            }
        }

        // Report.
        auto share = [](int64 a, int64 b) { return b > 0 ? 100.0 * (double)a / (double)b : 0.0; };
        const StereoEventScores& scores = acc.scores;
        const int64 candidates = (int64)scores.visibleSignal, estimated = (int64)scores.estimated;
        const int64 leftSignal = (int64)scores.leftSignal, leftVisible = (int64)acc.visible.leftSignal;
        const int64 leftMotion = (int64)acc.motion.leftSignal;
        const double density = scores.density(), within1 = scores.precision(), matchingRate = scores.matchingRate();
        const double mae = scores.meanAbsError(), relDepth = 100 * scores.meanDepthError();
        const double leftWrong = share((int64)(scores.leftEstimated - scores.leftWithin1), leftSignal);
        const double usPerEvent = acc.events ? seconds * 1e6 / (double)acc.events : 0;
        std::string lifetimeError = "n/a", precision = "n/a", recall = "n/a";
        if (estimate.hasLifetime)
        {
            if (!acc.lifetimeRelErrors.empty())
            {
                std::vector<double>& r = acc.lifetimeRelErrors;
                std::nth_element(r.begin(), r.begin() + r.size() / 2, r.end());
                lifetimeError = std::to_string(100.0 * r[r.size() / 2]);
            }
            precision = acc.noiseFlagged ? std::to_string(share(acc.noiseCorrect, acc.noiseFlagged)) : "n/a";
            recall = acc.noiseTrue ? std::to_string(share(acc.noiseCorrect, acc.noiseTrue)) : "n/a (no noise)";
        }
        // Precision at fixed densities, from the ranking by confidence (the most confident first).
        std::stable_sort(acc.ranked.begin(), acc.ranked.end(),
                         [](const std::pair<float, bool>& a, const std::pair<float, bool>& b) { return a.first > b.first; });
        const double fullDensity = share((int64)acc.ranked.size(), candidates);
        const double at50 = precisionAtDensity(acc.ranked, candidates, 50);
        const double at75 = precisionAtDensity(acc.ranked, candidates, 75);
        const double atFull = precisionAtDensity(acc.ranked, candidates, fullDensity);
        auto percent = [](double v) { return v < 0 ? std::string("n/a") : cv::format("%.1f %%", v); };
        // Every key for every method, "n/a" where the method estimates no disparities (as for lifetimes).
        auto disparityValue = [&](auto value) {
            std::ostringstream text;
            if (estimate.hasDisparity)
                text << value;
            else
                text << "n/a";
            return text.str();
        };
        std::ofstream csv(o.output + "/metrics.csv");
        csv << "metric,value\n"
            << "events," << acc.events << "\n"
            << "signal_events," << acc.signal << "\n"
            << "non_occluded_signal_events," << candidates << "\n"
            << "events_with_disparity," << disparityValue(estimated) << "\n"
            << "disparity_density_percent," << disparityValue(density) << "\n"
            << "within_1px_percent," << disparityValue(within1) << "\n"
            << "matching_rate_percent," << disparityValue(matchingRate) << "\n"
            << "left_occluded_percent," << disparityValue(share(leftSignal - leftVisible, leftSignal)) << "\n"
            << "matching_rate_visible_percent," << disparityValue(acc.visible.matchingRate()) << "\n"
            << "matching_rate_motion_percent," << disparityValue(acc.motion.matchingRate()) << "\n"
            << "left_wrong_percent," << disparityValue(leftWrong) << "\n"
            << "left_ambiguous_percent," << disparityValue(share(acc.leftAmbiguous, leftSignal)) << "\n"
            << "left_no_counterpart_percent," << disparityValue(share(acc.leftNoCounterpart, leftSignal)) << "\n"
            << "precision_at_50_percent_density," << disparityValue(at50) << "\n"
            << "precision_at_75_percent_density," << disparityValue(at75) << "\n"
            << "unfiltered_density_percent," << disparityValue(fullDensity) << "\n"
            << "precision_at_unfiltered_density," << disparityValue(atFull) << "\n"
            << "mean_abs_disparity_error_px," << disparityValue(mae) << "\n"
            << "relative_depth_error_percent," << disparityValue(relDepth) << "\n"
            << "lifetime_median_relative_error_percent," << lifetimeError << "\n"
            << "noise_precision_percent," << precision << "\n"
            << "noise_recall_percent," << recall << "\n"
            << "events_with_lifetime," << acc.withLifetime << "\n"
            << "events_with_lifetime_left," << acc.withLifetimeCamera[0] << "\n"
            << "events_with_lifetime_right," << acc.withLifetimeCamera[1] << "\n"
            << "time_per_event_us," << usPerEvent << "\n";
        // The filter's figures: signal kept (recall of the motion's events), noise and flicker removed, and the
        // share of signal among the kept events (precision).
        const int64 noiseEvents = acc.noiseTrue;
        const double signalKept = share(acc.filterSignalKept, acc.signal - acc.flicker);
        const double noiseRemoved = share(noiseEvents - acc.filterNoiseKept, noiseEvents);
        const double flickerRemoved = share(acc.flicker - acc.filterFlickerKept, acc.flicker);
        const double keptPrecision = share(acc.filterSignalKept, acc.filterSignalKept + acc.filterNoiseKept + acc.filterFlickerKept);
        const double filterMevPerS = acc.filterSeconds > 0 ? (double)acc.events / acc.filterSeconds * 1e-6 : 0;
        if (filter)
            csv << "filter," << o.filter << "\n"
                << "filter_signal_kept_percent," << signalKept << "\n"
                << "filter_noise_removed_percent," << noiseRemoved << "\n"
                << "flicker_events," << acc.flicker << "\n"
                << "filter_flicker_removed_percent," << (acc.flicker ? std::to_string(flickerRemoved) : "n/a") << "\n"
                << "filter_kept_signal_share_percent," << keptPrecision << "\n"
                << "filter_mev_per_s," << filterMevPerS << "\n";
        // The report shows what the method estimates: disparities, lifetimes (with noise), both, or neither
        // (--method=none, for a filter).
        const bool disparities = estimate.hasDisparity, lifetimes = estimate.hasLifetime;
        const std::string noiseText = !acc.noiseFlagged && !acc.noiseTrue ? std::string("n/a (no noise, none classified as noise)")
            : (acc.noiseFlagged ? percent(share(acc.noiseCorrect, acc.noiseFlagged)) : std::string("n/a (none classified as noise)"))
              + " / " + (acc.noiseTrue ? percent(share(acc.noiseCorrect, acc.noiseTrue)) : std::string("n/a (no noise)"));
        std::ofstream md(o.output + "/report.md");
        md << "# Evaluation: " << o.method << " on " << (sim ? "simulated scene " + o.scene : o.input) << "\n\n"
           << "Windows of " << o.windowMs << " ms, both cameras. "
           << (disparities ? "Disparity metrics over the non-occluded signal events (ground-truth flags)."
                           : "`" + o.method + "` estimates no disparities.")
           << (lifetimes ? " Lifetimes over the signal events, noise over all." : "") << "\n\n"
           << "| metric | value |\n|---|---|\n"
           << "| events (signal / noise) | " << acc.events << " (" << acc.signal << " / " << acc.noiseTrue << ") |\n";
        if (disparities)
            md << "| disparity density (estimated / non-occluded signal) | " << density << " % (" << estimated << " / " << candidates << ") |\n"
               << "| estimated events within 1 px | " << within1 << " % |\n"
               << "| matching rate (left signal events within 1 px of the truth / all left signal events) | " << matchingRate
               << " % (" << (int64)scores.leftWithin1 << " / " << leftSignal << ") |\n"
               << "| ... over the left signal events the right camera sees (" << share(leftSignal - leftVisible, leftSignal)
               << " % are occluded: no matcher can match them) | " << acc.visible.matchingRate() << " % ("
               << (int64)acc.visible.leftWithin1 << " / " << leftVisible << ") |\n"
               << "| ... over the left signal events motion caused (" << share(leftSignal - leftMotion, leftSignal)
               << " % are the flicker's) | " << acc.motion.matchingRate() << " % (" << (int64)acc.motion.leftWithin1
               << " / " << leftMotion << ") |\n"
               << "| left signal events more than 1 px off / rejected (ambiguous) / without a candidate | "
               << leftWrong << " / " << share(acc.leftAmbiguous, leftSignal) << " / "
               << share(acc.leftNoCounterpart, leftSignal) << " % |\n"
               << "| precision (within 1 px) of the most confident estimates at 50 / 75 % density | "
               << (acc.ranked.empty() ? std::string("n/a (" + o.method + " has no confidence)") : percent(at50) + " / " + percent(at75)) << " |\n"
               << "| ... with no rejection (every event's best estimate): density, precision | "
               << (acc.ranked.empty() ? std::string("n/a") : percent(fullDensity) + ", " + percent(atFull)) << " |\n"
               << "| mean absolute disparity error | " << mae << " px |\n"
               << "| mean relative depth error | " << relDepth << " % |\n";
        if (lifetimes)
            md << "| lifetime median relative error | " << lifetimeError << (acc.lifetimeRelErrors.empty() ? "" : " %") << " |\n"
               << "| noise precision / recall | " << noiseText << " |\n"
               << "| events with a lifetime (left / right) | " << acc.withLifetime << " (" << acc.withLifetimeCamera[0]
               << " / " << acc.withLifetimeCamera[1] << ") |\n";
        if (disparities || lifetimes)  // --method=none times nothing
            md << "| time per event | " << usPerEvent << " us |\n";
        if (filter)
            md << "| filter " << o.filter << ": signal kept / noise removed / signal share of the kept events | "
               << signalKept << " / " << noiseRemoved << " / " << keptPrecision << " % (" << noiseEvents << " noise events) |\n"
               << "| filter " << o.filter << ": flicker removed | "
               << (acc.flicker ? cv::format("%.2f %% of %lld flicker events", flickerRemoved, (long long)acc.flicker) : std::string("n/a (no flicker)")) << " |\n"
               << "| filter speed | " << filterMevPerS << " Mev/s |\n";
        if (disparities)
        {
            md << "\n"
               << "![error histogram](disparity_error_histogram.png)\n\n"
               << "![estimate | ground truth](disparity_vs_truth.png)\n";
            if (!acc.ranked.empty())
            {
                drawDensityPrecision(acc.ranked, candidates, density, within1, o.output + "/density_precision.png",
                                     "precision against density, ranked by confidence (" + o.method + ")");
                md << "\n![density-precision curve](density_precision.png)\n";
            }
            drawHistogram(acc.errorHistogram, o.output + "/disparity_error_histogram.png",
                          "|disparity error| histogram, 0.25 px bins (" + o.method + ")");
        }
        if (lifetimes)
        {
            std::vector<int> h(41, 0);  // relative lifetime error in 2.5 % bins up to 100 %
            for (double r : acc.lifetimeRelErrors)
                h[std::min<size_t>(h.size() - 1, (size_t)(r / 0.025))]++;
            drawHistogram(h, o.output + "/lifetime_error_histogram.png",
                          "|lifetime error| / true lifetime, 2.5 % bins, last bin >= 100 % (" + o.method + ")", "100 %");
            md << "\n![lifetime error histogram](lifetime_error_histogram.png)\n";
        }
        if (disparities)
        {
            const float maxDisparity = 48;
            Mat pair;
            hconcat(colourDisparity(lastEstimate, maxDisparity), colourDisparity(lastTruth, maxDisparity), pair);
            resize(pair, pair, Size(), 2, 2, INTER_NEAREST);
            imwrite(o.output + "/disparity_vs_truth.png", pair);
        }
        if (!filterPicture.empty())
        {
            imwrite(o.output + "/filter_before_after.png", filterPicture);
            md << "\n![left events of the last window: all | kept by " << o.filter << " (signal ON white, OFF grey, noise red, flicker blue)](filter_before_after.png)\n";
            std::cout << "filter " << o.filter << ": signal kept " << signalKept << " %, noise removed " << noiseRemoved
                      << " % of " << noiseEvents;
            if (acc.flicker)
                std::cout << ", flicker removed " << flickerRemoved << " % of " << acc.flicker;
            std::cout << ", signal share of kept " << keptPrecision << " %, "
                      << filterMevPerS << " Mev/s\n";
        }
        if (disparities)
            std::cout << "density " << density << " %, within 1 px " << within1 << " %, matching rate " << matchingRate
                      << " %, MAE " << mae << " px, ";
        if (lifetimes)
            std::cout << "lifetime median relative error " << lifetimeError << (acc.lifetimeRelErrors.empty() ? "" : " %")
                      << ", " << acc.withLifetime << " of " << acc.events << " events with a lifetime, ";
        if (disparities || lifetimes)
            std::cout << usPerEvent << " us/event; ";
        std::cout << "report in " << o.output << "/report.md\n";
        return 0;
    }
    catch (const std::exception& e)
    {
        std::cerr << "event_evaluate: " << errorText(e) << "\n";
        return 1;
    }
}
