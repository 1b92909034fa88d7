// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"

namespace opencv_test { namespace {

// One ground-truth row: depth, disparity, flow, lifetime, flags.
void addTruth(Mat& gt, float depth, float disparity, int flags)
{
    Mat row = (Mat_<float>(1, 6) << depth, disparity, 0.f, 0.f, 0.f, (float)flags);
    gt.push_back(row);
}

// Eight events whose counts are known by construction: left signal within / beyond 1 px / without an
// estimate, a left occluded one within 1 px, left noise, right signal within 1 px and beyond, right occluded.
struct HandMadePacket
{
    std::vector<Event> events;
    Mat disparity, truth, depth;
    HandMadePacket()
    {
        const struct { int camera; float estimate, truth; int flags; float depth; } rows[] = {
            { CAMERA_LEFT, 10.5f, 10.f, 0, 2.2f },    // within 1 px: |0.5|, depth error 0.2 / 2
            { CAMERA_LEFT, 13.f, 10.f, 0, 2.f },      // 3 px off
            { CAMERA_LEFT, -1.f, 10.f, 0, -1.f },     // no estimate
            { CAMERA_LEFT, 20.f, 20.f, GT_FLAG_OCCLUDED, 1.f },
            { CAMERA_LEFT, 5.f, 0.f, GT_FLAG_NOISE, 4.f },
            { CAMERA_RIGHT, 9.f, 10.f, 0, 2.f },      // within 1 px: exactly 1
            { CAMERA_RIGHT, 7.f, 10.f, 0, 3.f },      // 3 px off, depth error 1 / 2
            { CAMERA_RIGHT, 4.f, 20.f, GT_FLAG_OCCLUDED, 1.f },
        };
        for (const auto& r : rows)
        {
            events.push_back(Event((int64)events.size(), 5, 5, 1, r.camera));
            disparity.push_back(r.estimate);
            addTruth(truth, r.truth > 0 ? 0.1f * 200.f / r.truth : 0.f, r.truth, r.flags);
            depth.push_back(r.depth);
        }
    }
};

TEST(Event_StereoEvaluation, counts_a_hand_made_packet_as_constructed)
{
    const HandMadePacket p;
    StereoEventScores s;
    scoreStereoEvents(p.events, p.disparity, p.truth, s, p.depth);
    EXPECT_EQ(5, s.visibleSignal);  // rows 0, 1, 2, 5, 6
    EXPECT_EQ(4, s.estimated);      // rows 0, 1, 5, 6
    EXPECT_EQ(2, s.within1);        // rows 0, 5
    EXPECT_NEAR(0.5 + 3 + 1 + 3, s.absErrorSum, 1e-6);
    EXPECT_EQ(4, s.leftSignal);     // rows 0-3: the occluded one counts
    EXPECT_EQ(3, s.leftEstimated);  // rows 0, 1, 3
    EXPECT_EQ(2, s.leftWithin1);    // rows 0, 3
    EXPECT_EQ(2, s.leftWithin2) << "row 1 is 3 px off";
    EXPECT_EQ(4, s.depthEstimated);
    EXPECT_NEAR(0.2 / 2 + 0 + 0 + 1.0 / 2, s.depthErrorSum, 1e-5);
    EXPECT_DOUBLE_EQ(80.0, s.density());
    EXPECT_DOUBLE_EQ(50.0, s.precision());
    EXPECT_DOUBLE_EQ(50.0, s.matchingRate());
    EXPECT_DOUBLE_EQ(7.5 / 4, s.meanAbsError());
    EXPECT_NEAR(0.6 / 4, s.meanDepthError(), 1e-6);

    // Row 0's disparity at infinity: a depth of 0 or an infinite one is none.
    for (float none : { 0.f, std::numeric_limits<float>::infinity() })
    {
        Mat depth = p.depth.clone();
        depth.at<float>(0) = none;
        StereoEventScores withoutRow0;
        scoreStereoEvents(p.events, p.disparity, p.truth, withoutRow0, depth);
        EXPECT_EQ(3, withoutRow0.depthEstimated) << none;
        EXPECT_NEAR(1.0 / 2, withoutRow0.depthErrorSum, 1e-5) << none;
    }
}

TEST(Event_StereoEvaluation, adds_packets_and_counts_only_the_masked_events)
{
    const HandMadePacket p;
    StereoEventScores twice;
    scoreStereoEvents(p.events, p.disparity, p.truth, twice);
    scoreStereoEvents(p.events, p.disparity, p.truth, twice);
    EXPECT_EQ(10, twice.visibleSignal);
    EXPECT_EQ(4, twice.leftWithin1);
    EXPECT_EQ(0, twice.depthEstimated) << "no depths given";

    Mat rightOnly(8, 1, CV_8U, Scalar(0));
    rightOnly.rowRange(5, 8).setTo(1);
    StereoEventScores right;
    scoreStereoEvents(p.events, p.disparity, p.truth, right, noArray(), rightOnly);
    EXPECT_EQ(2, right.visibleSignal);
    EXPECT_EQ(1, right.within1);
    EXPECT_EQ(0, right.leftSignal);
    EXPECT_DOUBLE_EQ(0.0, right.matchingRate()) << "no left events: 0, not a division by zero";

    StereoEventScores none;
    scoreStereoEvents(std::vector<Event>(), Mat(), Mat(), none);
    EXPECT_EQ(0, none.visibleSignal);
}

TEST(Event_StereoEvaluation, refuses_outputs_that_do_not_fit_the_packet)
{
    const HandMadePacket p;
    StereoEventScores s;
    EXPECT_THROW(scoreStereoEvents(p.events, p.disparity.rowRange(0, 7), p.truth, s), cv::Exception);
    EXPECT_THROW(scoreStereoEvents(p.events, p.disparity, p.truth.rowRange(0, 7), s), cv::Exception);
    EXPECT_THROW(scoreStereoEvents(p.events, p.disparity, p.truth.colRange(0, 5), s), cv::Exception);
    Mat disparity64;
    p.disparity.convertTo(disparity64, CV_64F);
    EXPECT_THROW(scoreStereoEvents(p.events, disparity64, p.truth, s), cv::Exception);
    EXPECT_THROW(scoreStereoEvents(p.events, p.disparity, p.truth, s, p.depth.rowRange(0, 3)), cv::Exception);
    EXPECT_EQ(0, s.visibleSignal) << "nothing counted from a refused packet";
}

TEST(Event_StereoEvaluation, precision_at_a_density_ranks_the_estimates_by_confidence)
{
    const HandMadePacket p;
    // The estimated visible rows by confidence: 5 (1, within 1 px), 0 (0.9, within), 1 (0.8, 3 px off), 6 (0.2,
    // 3 px off). Rows 2, 3, 4 and 7 are not estimated, occluded or noise: their confidences do not count.
    const Mat confidence = (Mat_<float>(8, 1) << 0.9f, 0.8f, 0.f, 1.f, 1.f, 1.f, 0.2f, 1.f);
    StereoEventScores s;
    EXPECT_EQ(-1, s.precisionAtDensity(50)) << "no confidences given";
    scoreStereoEvents(p.events, p.disparity, p.truth, s, noArray(), noArray(), confidence);
    ASSERT_EQ((size_t)StereoEventScores::CONFIDENCE_BINS, s.confidenceEstimated.size());
    EXPECT_EQ(1, s.confidenceEstimated[StereoEventScores::CONFIDENCE_BINS - 1]) << "a confidence of 1: the last bin";
    EXPECT_EQ(1, s.confidenceWithin1[900]);
    EXPECT_DOUBLE_EQ(100.0, s.precisionAtDensity(20));  // 1 of the 5 visible signal events: row 5
    EXPECT_DOUBLE_EQ(100.0, s.precisionAtDensity(40));  // rows 5, 0
    EXPECT_DOUBLE_EQ(200.0 / 3, s.precisionAtDensity(60));
    EXPECT_DOUBLE_EQ(s.precision(), s.precisionAtDensity(80));  // all four estimates
    EXPECT_EQ(-1, s.precisionAtDensity(100)) << "only 4 of the 5 have an estimate";
    EXPECT_EQ(-1, s.precisionAtDensity(0));

    // Rows 0 and 1 alike in confidence: the second of the two taken is half of that bin's, 1 of its 2 right ones.
    Mat tied = confidence.clone();
    tied.at<float>(0) = tied.at<float>(1) = 0.5f;
    StereoEventScores t;
    scoreStereoEvents(p.events, p.disparity, p.truth, t, noArray(), noArray(), tied);
    EXPECT_DOUBLE_EQ(75.0, t.precisionAtDensity(40));
    // A second packet adds to the bins.
    scoreStereoEvents(p.events, p.disparity, p.truth, t, noArray(), noArray(), tied);
    EXPECT_EQ(4, t.confidenceEstimated[500]);
    EXPECT_DOUBLE_EQ(100.0, t.precisionAtDensity(20));  // 2 of 10: both row 5s

    for (float bad : { 1.5f, -0.1f, std::numeric_limits<float>::quiet_NaN() })
    {
        Mat wrong = confidence.clone();
        wrong.at<float>(6) = bad;
        StereoEventScores before = s;
        EXPECT_THROW(scoreStereoEvents(p.events, p.disparity, p.truth, s, noArray(), noArray(), wrong), cv::Exception)
            << bad;
        EXPECT_EQ(before.visibleSignal, s.visibleSignal) << "nothing counted from a refused packet";
        EXPECT_EQ(before.confidenceEstimated, s.confidenceEstimated);
    }
    StereoEventScores odd;
    odd.confidenceEstimated.assign(10, 0.0);
    odd.confidenceWithin1.assign(10, 0.0);
    EXPECT_THROW(scoreStereoEvents(p.events, p.disparity, p.truth, odd, noArray(), noArray(), confidence), cv::Exception);
}

}}  // namespace
