// The figures behind the manual's account of the matcher's and the lifetime estimator's design choices, each
// measured on the simulated experiment the manual describes (the unit tests assert the same properties with
// margins, and print nothing):
//   prior        boxes, 600 ms, rejection below 0.15: matching rate with and without the temporal prior, over
//                all left signal events and over those on horizontal edges
//   beyond_view  boxes, 600 ms: the left events the right camera does not see, within 1 px and further off
//   start_up     plane, 300 ms: COUPLED's median lifetime over the truth per 100 ms, one copy (the default)
//                and lifetimes passed on by every match without limit
//   bars         bars sliding over a wall on a 64 x 32 crop of the realistic sensor: the median lifetime over
//                the closed form 1 / speed, the default inlierDistance and 0, sharp and blurred bars;
//                bars that fire on about half the pixels, with the 100 ms time window and 8 px of travel
//   slowing      pendulum and pendulum_patterned on a DVS128, as built (3.5 s) and set as the TUM pendulum
//                recording fires (half the swing's speed, 0.8 px of blur, thresholds of 0.2; 7 s): the share
//                of events with a lifetime, our median lifetime, its median over the truth overall and per
//                quarter of the true lifetimes (fastest first) and at quality >= 0.75 and below, the arrival
//                check of ours and of the true ones
//
//   design_figures [--figures=prior,beyond_view,start_up,bars,slowing]

#include <opencv2/core/utility.hpp>
#include <opencv2/event.hpp>

#include "command_line.hpp"
#include "test_simulator_helpers.hpp"  // the bars experiment, shared with the unit tests
#include "test_stereo_scene_runs.hpp"   // the scene runs and their measures, shared with the unit tests

#include <algorithm>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

using namespace cv;
using namespace cv::event;
using opencv_test::barsLifetimeRatio;
using opencv_test::defaultInlierDistance;
using opencv_test::generateLeftCamera;
using opencv_test::LeftCameraEvents;
using opencv_test::pendulumAsTumFires;
using opencv_test::perfectLifetimes;

namespace {

double median(std::vector<double> v)
{
    if (v.empty())
        return 0;
    std::nth_element(v.begin(), v.begin() + (std::ptrdiff_t)(v.size() / 2), v.end());
    return v[v.size() / 2];
}

// Calls visit(events, truth, disparity, lifetime) for each 20 ms packet of COUPLED over `ms` ms of `scene`.
void runCoupled(const std::string& scene, double ms, const std::function<void(StereoEventMatcher&)>& configure,
                const std::function<void(double, const std::vector<Event>&, const Mat&, const Mat&, const Mat&)>& visit)
{
    Ptr<StereoEventSimulator> sim = StereoEventSimulator::create(scene);
    Ptr<StereoEventMatcher> m = StereoEventMatcher::create(sim->getSensorSize(), STEREO_COUPLED);
    configure(*m);
    std::vector<Event> ev;
    Mat gt, disparity, lifetime;
    for (double t = 20000; t <= ms * 1000 + 1; t += 20000)
    {
        sim->generate(t, ev, gt);
        m->process(ev, disparity, lifetime);
        visit(t, ev, gt, disparity, lifetime);
    }
}

void printPrior()
{
    for (int tolerance : { 0, 30 })
    {
        const opencv_test::SceneRun run = opencv_test::runScene("boxes", 600, [&](StereoEventMatcher& m) {
            m.setMinConfidence(0.15);
            m.setPriorTolerance(tolerance);
        });
        std::printf("| boxes, 600 ms, minConfidence=0.15, priorTolerance=%d | %.1f %% | %.1f %% |\n", tolerance,
                    run.scores.matchingRate(), run.horizontalEdgeScores.matchingRate());
    }
}

void printBeyondView()
{
    const opencv_test::UnseenLeftEvents unseen =
        opencv_test::unseenLeftEvents(opencv_test::runScene("boxes", 600, [](StereoEventMatcher&) {}));
    std::printf("| boxes, 600 ms: left events the right camera does not see | %lld | %.1f %% within 1 px | %.1f %% "
                "further off |\n", (long long)unseen.count, unseen.withinShare, unseen.furtherShare);
}

void printStartUp()
{
    for (bool withoutLimit : { false, true })
    {
        std::vector<std::vector<double>> ratios(3);
        runCoupled("plane", 300,
                   [&](StereoEventMatcher& m) {
                       if (withoutLimit)
                       {
                           m.setMaxLifetimeCopies(255);
                           m.setLifetimeCopyConfidence(0);
                       }
                   },
                   [&](double t, const std::vector<Event>& ev, const Mat& gt, const Mat&, const Mat& lifetime) {
                       for (int i = 0; i < (int)ev.size(); i++)
                       {
                           const float truth = gt.at<float>(i, GT_LIFETIME), l = lifetime.at<float>(i);
                           if (l > 0 && truth > 0 && !((int)gt.at<float>(i, GT_FLAGS) & GT_FLAG_NOISE))
                               ratios[(size_t)((t - 20000) / 100000)].push_back(l / truth);
                       }
                   });
        std::printf("| plane, %s | %.2f | %.2f | %.2f |\n",
                    withoutLimit ? "maxLifetimeCopies=255,lifetimeCopyConfidence=0" : "defaults (one copy)",
                    median(ratios[0]), median(ratios[1]), median(ratios[2]));
    }
}

void printBars()
{
    struct Bars { const char* name; double logContrast, blurPx; } bars[] = { { "sharp, log contrast 0.5", 0.5, 0 },
                                                                            { "blurred 0.7 px, log contrast 1.0", 1.0, 0.7 } };
    for (const Bars& b : bars)
        for (double speed : { 3333.0, 1667.0, 1000.0, 300.0, 100.0 })
        {
            // The fixed threshold over every timestamp in the time window (skipEarlierEdges off), as published.
            const std::pair<double, double> fixed = barsLifetimeRatio(speed, b.logContrast, b.blurPx, 0, 100000, -1, false);
            const std::pair<double, double> scaled = barsLifetimeRatio(speed, b.logContrast, b.blurPx, defaultInlierDistance());
            std::printf("| %s | %.1f ms/px | %.2f | %.2f (%.1f %% with a lifetime) |\n", b.name, 1000 / speed,
                        fixed.first, scaled.first, 100 * scaled.second);
        }
    for (double speed : { 3333.0, 1000.0 })
    {
        const std::pair<double, double> whole = barsLifetimeRatio(speed, 0.35, 0, defaultInlierDistance());
        const std::pair<double, double> windowed = barsLifetimeRatio(speed, 0.35, 0, defaultInlierDistance(), 8 / speed * 1e6);
        std::printf("| half-firing, log contrast 0.35 | %.1f ms/px | timeWindow 100 ms: %.1f (%.1f %%) | 8 px of "
                    "travel: %.2f (%.1f %%) |\n", 1000 / speed, whole.first, 100 * whole.second, windowed.first,
                    100 * windowed.second);
    }
}

// The arrival check's median of the given lifetimes and flows of the left camera's events.
double arrivalMedian(const LeftCameraEvents& run, Size sensor, const Mat& lifetimes, const Mat& flow)
{
    Ptr<LifetimeArrivalCheck> check = LifetimeArrivalCheck::create(sensor);
    check->update(run.events, lifetimes, flow);
    return check->getRatioQuantile(0.5);
}

void printSlowing()
{
    for (const char* scene : { "pendulum", "pendulum_patterned" })
        for (bool recordingLike : { false, true })
        {
            const Ptr<StereoEventSimulator> sim =
                recordingLike ? pendulumAsTumFires(scene) : StereoEventSimulator::create(scene, SENSOR_DVS128);
            const SimulatorSettings s = sim->getSettings();
            const LeftCameraEvents run = generateLeftCamera(*sim, recordingLike ? 7e6 : 3.5e6);
            Mat lifetimes, flow, status, quality;
            LifetimeEstimator::create(s.resolution)->process(run.events, lifetimes, flow, status, quality);
            Mat trueLifetimes, trueFlow;
            perfectLifetimes(run.groundTruth, run.truthRows, trueLifetimes, trueFlow);
            std::vector<std::pair<float, double>> truthAndRatio;  // per event with both lifetimes
            std::vector<double> ours, trusted, doubtful;  // ours / truth at quality >= 0.75 and below
            for (int k = 0; k < (int)run.events.size(); k++)
            {
                const float l = lifetimes.at<float>(k), truth = trueLifetimes.at<float>(k);  // truth 0: noise
                if (l > 0)
                    ours.push_back(l);
                if (l > 0 && truth > 0)
                {
                    truthAndRatio.push_back(std::make_pair(truth, l / truth));
                    (quality.at<float>(k) >= 0.75f ? trusted : doubtful).push_back(l / truth);
                }
            }
            std::sort(truthAndRatio.begin(), truthAndRatio.end());
            std::vector<double> all, quarters[4];
            for (size_t i = 0; i < truthAndRatio.size(); i++)
            {
                all.push_back(truthAndRatio[i].second);
                quarters[i * 4 / truthAndRatio.size()].push_back(truthAndRatio[i].second);
            }
            std::printf("| `%s`, %s | %.0f %% | %.1f ms | %.2f | %.2f / %.2f / %.2f / %.2f | %.2f / %.2f | %.2f | "
                        "%.2f |\n", scene, recordingLike ? "as TUM pendulum fires" : "as built",
                        100.0 * ours.size() / run.events.size(), median(ours) / 1000, median(all),
                        median(quarters[0]), median(quarters[1]), median(quarters[2]), median(quarters[3]),
                        median(trusted), median(doubtful),
                        arrivalMedian(run, s.resolution, lifetimes, flow),
                        arrivalMedian(run, s.resolution, trueLifetimes, trueFlow));
            std::fflush(stdout);
        }
}

}  // namespace

int main(int argc, char** argv)
{
    CommandLineParser parser(argc, argv,
                             "{help h||print this message}"
                             "{figures|prior,beyond_view,start_up,bars,slowing|which figures, comma separated}");
    parser.about("The figures behind the manual's account of the matcher's and the lifetime estimator's design "
                 "choices, each on its simulated experiment.");
    if (parser.has("help"))
    {
        parser.printMessage();
        return 0;
    }
    const std::string figures = parser.get<std::string>("figures");
    for (const std::string& name : commaList(figures))
    {
        if (name == "prior")
        {
            std::printf("\n| temporal prior | matching rate | on horizontal edges |\n|---|---|---|\n");
            printPrior();
        }
        else if (name == "beyond_view")
        {
            std::printf("\n| past the other camera's view | events | | |\n|---|---|---|---|\n");
            printBeyondView();
        }
        else if (name == "start_up")
        {
            std::printf("\n| COUPLED lifetime / truth, median | 0-100 ms | 100-200 ms | 200-300 ms |\n|---|---|---|---|\n");
            printStartUp();
        }
        else if (name == "bars")
        {
            std::printf("\n| bars | speed | lifetime / closed form, inlierDistance=0 | the default inlierDistance |\n"
                        "|---|---|---|---|\n");
            printBars();
        }
        else if (name == "slowing")
        {
            std::printf("\n| on a DVS128 | events with a lifetime | our median lifetime | ours / truth, median "
                        "| by quarter of the true lifetimes, fastest first | at quality >= 0.75 / below "
                        "| arrival check, ours | of the true lifetimes |\n|---|---|---|---|---|---|---|---|\n");
            printSlowing();
        }
        else
        {
            std::fprintf(stderr, "design_figures: unknown figure \"%s\" (prior, beyond_view, start_up, bars, "
                         "slowing)\n", name.c_str());
            return 2;
        }
        std::fflush(stdout);
    }
    return 0;
}
