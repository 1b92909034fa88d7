// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_TEST_STEREO_SCENE_RUNS_HPP
#define OPENCV_EVENT_TEST_STEREO_SCENE_RUNS_HPP

// COUPLED runs over a simulated scene with the outputs and the ground truth per event, and the measures the
// stereo tests (and perf/design_figures, which quotes them) take of them; the estimates of a run of events from
// process()'s outputs.

#include "opencv2/event.hpp"

#include <functional>
#include <string>
#include <vector>

namespace opencv_test {
using namespace cv;
using namespace cv::event;

// One COUPLED run over a simulated scene, per event: the outputs and the ground truth.
struct SceneRun
{
    std::vector<float> disparity, confidence, truth, lifetime, truthLifetime;
    std::vector<int> flags, truthFlags, camera;
    std::vector<uchar> horizontalEdge;  // the truth's normal flow is more vertical than horizontal
    StereoEventScores scores, horizontalEdgeScores;  // over all events, and over those on horizontal edges
};

inline SceneRun runScene(const std::string& scene, double ms, const std::function<void(StereoEventMatcher&)>& configure)
{
    Ptr<StereoEventSimulator> sim = StereoEventSimulator::create(scene);
    Ptr<StereoEventMatcher> m = StereoEventMatcher::create(sim->getSensorSize(), STEREO_COUPLED);
    configure(*m);
    SceneRun run;
    std::vector<Event> ev;
    Mat gt, d, lt, fl, conf;
    for (double t = 20000; t <= ms * 1000 + 1; t += 20000)
    {
        sim->generate(t, ev, gt);
        m->process(ev, d, lt, fl, noArray(), noArray(), conf);
        const size_t first = run.horizontalEdge.size();
        for (int i = 0; i < (int)ev.size(); i++)
        {
            run.disparity.push_back(d.at<float>(i));
            run.confidence.push_back(conf.at<float>(i));
            run.lifetime.push_back(lt.at<float>(i));
            run.truthLifetime.push_back(gt.at<float>(i, GT_LIFETIME));
            run.flags.push_back(fl.at<int>(i));
            run.truth.push_back(gt.at<float>(i, GT_DISPARITY));
            run.truthFlags.push_back((int)gt.at<float>(i, GT_FLAGS));
            run.camera.push_back(ev[(size_t)i].camera);
            run.horizontalEdge.push_back(std::abs(gt.at<float>(i, GT_FLOW_Y)) > std::abs(gt.at<float>(i, GT_FLOW_X)));
        }
        scoreStereoEvents(ev, d, gt, run.scores);
        scoreStereoEvents(ev, d, gt, run.horizontalEdgeScores, noArray(),
                          Mat((int)ev.size(), 1, CV_8U, run.horizontalEdge.data() + first));
    }
    return run;
}

// The estimates of events [first, first + count) of one process() call, from its disparity, flags and
// confidence outputs.
inline std::vector<StereoEventEstimate> estimatesOf(const Mat& disparity, const Mat& flags, const Mat& confidence,
                                                    int first, int count)
{
    std::vector<StereoEventEstimate> estimates;
    for (int i = first; i < first + count; i++)
    {
        StereoEventEstimate e;
        e.disparity = disparity.at<float>(i);
        e.flags = flags.at<int>(i);
        e.confidence = confidence.at<float>(i);
        estimates.push_back(e);
    }
    return estimates;
}

// Event i is a left signal event: one of those the matching rate counts.
inline bool isLeftSignal(const SceneRun& r, size_t i)
{
    return r.camera[i] == CAMERA_LEFT && !(r.truthFlags[i] & GT_FLAG_NOISE);
}

// Event i has a disparity within 1 px of the truth.
inline bool matchedWithin1(const SceneRun& r, size_t i)
{
    return r.disparity[i] >= 0 && std::abs(r.disparity[i] - r.truth[i]) <= 1;
}

// Left signal events within 1 px of the truth, over all left signal events [%]; onlyHorizontalEdges: over
// those on horizontal edges.
inline double matchingRate(const SceneRun& r, bool onlyHorizontalEdges = false)
{
    return (onlyHorizontalEdges ? r.horizontalEdgeScores : r.scores).matchingRate();
}

// Estimates of non-occluded signal events within 1 px of the truth [%].
inline double within1(const SceneRun& r)
{
    return r.scores.precision();
}

// The left events the right camera does not see (flagged occluded, nothing else): how many, and the shares [%]
// of them with a disparity within 1 px of the truth and further off.
struct UnseenLeftEvents
{
    int64 count = 0;
    double withinShare = 0, furtherShare = 0;
};

inline UnseenLeftEvents unseenLeftEvents(const SceneRun& r)
{
    UnseenLeftEvents u;
    int64 within = 0, further = 0;
    for (size_t i = 0; i < r.disparity.size(); i++)
        if (r.camera[i] == CAMERA_LEFT && r.truthFlags[i] == GT_FLAG_OCCLUDED)
        {
            u.count++;
            if (r.disparity[i] >= 0)
                (std::abs(r.disparity[i] - r.truth[i]) <= 1 ? within : further)++;
        }
    u.withinShare = 100.0 * (double)within / (double)std::max<int64>(1, u.count);
    u.furtherShare = 100.0 * (double)further / (double)std::max<int64>(1, u.count);
    return u;
}

}  // namespace opencv_test

#endif  // OPENCV_EVENT_TEST_STEREO_SCENE_RUNS_HPP
