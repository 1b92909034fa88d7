// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"
#include "test_stereo_scene_runs.hpp"

namespace opencv_test { namespace {

// A vertical edge of 21 pixels fires in the left sensor at column 30 and, `delay` us later, in the right one at
// column 20 (disparity 10), after the cold start (an event at t = 0 in a corner starts it). The events get no
// lifetime (one instant, no plane): they are visible to matching only while they wait for their decision. The
// left events' estimates.
std::vector<StereoEventEstimate> delayedEdge(double lookAhead, int64 delay)
{
    const int64 t0 = 300000;
    std::vector<Event> ev;
    ev.push_back(Event(0, 63, 47, POLARITY_ON, CAMERA_LEFT));
    for (int y = 10; y <= 30; y++)
        ev.push_back(Event(t0, 30, y, POLARITY_ON, CAMERA_LEFT));
    for (int y = 10; y <= 30; y++)
        ev.push_back(Event(t0 + delay, 20, y, POLARITY_ON, CAMERA_RIGHT));
    Ptr<StereoEventMatcher> m = StereoEventMatcher::create(Size(64, 48), STEREO_COUPLED);
    m->setLookAhead(lookAhead);
    Mat d, flags, confidence;
    m->process(ev, d, noArray(), flags, noArray(), noArray(), confidence);
    return estimatesOf(d, flags, confidence, 1, 21);
}

TEST(StereoEventMatcher_LookAhead, a_counterpart_that_fires_later_is_matched_only_within_the_look_ahead)
{
    const int64 delay = 500;
    // Decided on arrival, or with a look-ahead shorter than the delay: the right edge is not there yet.
    for (double lookAhead : { 0.0, 400.0 })
        for (const StereoEventEstimate& e : delayedEdge(lookAhead, delay))
        {
            EXPECT_LT(e.disparity, 0) << "look-ahead " << lookAhead;
            EXPECT_TRUE(e.flags & STEREO_NO_COUNTERPART) << "look-ahead " << lookAhead;
        }
    // A look-ahead at least as long as the delay: the right edge has arrived when the left events are decided.
    for (double lookAhead : { 500.0, 10000.0 })
        for (const StereoEventEstimate& e : delayedEdge(lookAhead, delay))
        {
            EXPECT_NEAR(e.disparity, 10.0, 0.5) << "look-ahead " << lookAhead;
            EXPECT_GT(e.confidence, 0.5f) << "look-ahead " << lookAhead;
        }
}

// Low contrast: pixels near their threshold fire late and unevenly, so an event's counterpart often comes a
// few milliseconds after it. Measured with rejection at 0.15, so that the rate counts only estimates the
// matcher stands by (without rejection, an event decided too early keeps a guess that is sometimes right),
// and with the paper's inactive noise events: events kept active without a lifetime (noiseActiveTime) also
// leave structure behind for later events, which takes part of the look-ahead's gain (at the default 25 ms:
// 88.3 -> 89.4 %), and without the filling, which gives the surface's disparity to the events decided too
// early (with it the look-ahead gains nothing here).
TEST(StereoEventMatcher_LookAhead, raises_the_matching_rate_on_low_contrast)
{
    const SceneRun onArrival = runScene("low_contrast", 600, [](StereoEventMatcher& m) {
        m.setMinConfidence(0.15);
        m.setNoiseActiveTime(0);
        m.setFillRadius(0);
        m.setLookAhead(0);
    });
    const SceneRun ahead = runScene("low_contrast", 600, [](StereoEventMatcher& m) {
        m.setMinConfidence(0.15);
        m.setNoiseActiveTime(0);
        m.setFillRadius(0);
        EXPECT_EQ(m.getLookAhead(), 10000.0);
    });
    EXPECT_GT(matchingRate(ahead), matchingRate(onArrival) + 2);
    EXPECT_GT(within1(ahead), 96);
}
}}  // namespace
