// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"

namespace opencv_test { namespace {

// The baseline works as users run it: on a textured scene of two fronto-parallel planes, matched in its own
// 33 ms windows, the disparities SGBM gives are within a pixel of the simulator's truth for at least 95 % of
// the non-occluded signal events that get one, and most such events get one.
TEST(FrameStereoMatcher, estimates_the_truth_on_two_textured_planes)
{
    Ptr<StereoEventSimulator> sim = StereoEventSimulator::create("two_planes");
    Ptr<FrameStereoMatcher> m = FrameStereoMatcher::create(sim->getSensorSize());
    StereoEventScores scores;
    std::vector<Event> ev;
    Mat truth, disparity;
    for (double t = 33000; t <= 264000 + 1; t += 33000)
    {
        sim->generate(t, ev, truth);
        m->process(ev, disparity);
        scoreStereoEvents(ev, disparity, truth, scores);
    }
    EXPECT_GE(scores.precision(), 95.0);
    EXPECT_GE(scores.density(), 50.0);
}

// Each event's disparity is shown at its pixel for one frame window after it, no longer, and the map and the
// picture agree.
TEST(FrameStereoMatcher, shows_each_estimate_for_one_frame_window)
{
    Ptr<StereoEventSimulator> sim = StereoEventSimulator::create("two_planes");
    Ptr<FrameStereoMatcher> m = FrameStereoMatcher::create(sim->getSensorSize());
    std::vector<Event> ev;
    Mat truth, disparity;
    sim->generate(33000, ev, truth);
    sim->generate(66000, ev, truth);
    m->process(ev, disparity);
    ASSERT_FALSE(ev.empty());
    const int64 last = ev.back().t;
    Mat_<float> shown;
    m->getActiveDisparity((double)last, shown, CAMERA_LEFT);
    // The last left event of each pixel decides what it shows.
    Mat_<float> expected(sim->getSensorSize(), (float)StereoEventMatcher::NO_DISPARITY);
    for (size_t i = 0; i < ev.size(); i++)
        if (ev[i].camera == CAMERA_LEFT)
            expected(ev[i].y, ev[i].x) = ev[i].t + 33000 > last ? disparity.at<float>((int)i)
                                                               : (float)StereoEventMatcher::NO_DISPARITY;
    EXPECT_EQ(cvtest::norm(shown, expected, NORM_INF), 0.0);
    EXPECT_GT(countNonZero(shown >= 0), 100);
    // The colour scale spans the disparities present: two_planes' planes at 10 and 20 px, not the whole
    // 0-64 px search.
    const Vec2i range = m->getDisparityDisplayRange((double)last, CAMERA_LEFT);
    EXPECT_GE(range[0], 8);
    EXPECT_LE(range[0], 10);
    EXPECT_GE(range[1], 20);
    EXPECT_LE(range[1], 22);
    Mat picture;
    m->renderDisparity((double)last, picture, CAMERA_LEFT, false);
    Mat lit;
    cv::transform(picture, lit, Matx13f(1, 1, 1));
    EXPECT_EQ(countNonZero(lit > 0), countNonZero(shown >= 0));
    m->getActiveDisparity((double)last + 33000, shown, CAMERA_LEFT);
    EXPECT_EQ(countNonZero(shown >= 0), 0) << "one window later nothing is shown";
}

// With a calibration, an event outside the rectified image is flagged and gets nothing; the others get the
// depth f B / d of their disparity.
TEST(FrameStereoMatcher, outputs_depth_and_flags_like_the_event_matcher)
{
    Ptr<StereoEventSimulator> sim = StereoEventSimulator::create("two_planes");
    const Size size = sim->getSensorSize();
    StereoCalibration calibration = StereoCalibration::fromRectified(size, 200, 0.1);
    calibration.D1 = (Mat_<double>(1, 5) << -0.3, 0, 0, 0, 0);  // pulls the left image's corners outside
    Ptr<FrameStereoMatcher> m = FrameStereoMatcher::create(size);
    m->setCalibration(calibration);
    std::vector<Event> ev;
    Mat truth, disparity, flags, depth;
    sim->generate(66000, ev, truth);
    m->process(ev, disparity, flags, depth);
    int outside = 0, estimated = 0;
    for (int i = 0; i < disparity.rows; i++)
    {
        const float d = disparity.at<float>(i);
        const int f = flags.at<int>(i);
        if (f == STEREO_OUTSIDE)
        {
            outside++;
            EXPECT_EQ(d, (float)StereoEventMatcher::NO_DISPARITY);
            continue;
        }
        ASSERT_EQ(f, d >= 0 ? (int)STEREO_HAS_DISPARITY : 0) << "event " << i;
        if (d > 0)
        {
            estimated++;
            ASSERT_NEAR(depth.at<float>(i), 200 * 0.1 / d, 1e-4 * depth.at<float>(i)) << "event " << i;
        }
    }
    EXPECT_GT(outside, 0);
    EXPECT_GT(estimated, 0);
}

TEST(FrameStereoMatcher, refuses_bad_input_and_parameters_naming_them)
{
    StereoMethod method(Size(64, 48), FRAME_BASELINE);
    const Ptr<FrameStereoMatcher> m = method.frames;
    auto message = [&](const std::vector<Event>& ev) { return processingError(method, ev); };
    const std::string back = message({ Event(2000, 1, 1, 1, 0), Event(1000, 2, 2, 1, 1) });
    EXPECT_NE(back.find("FrameStereoMatcher"), std::string::npos) << back;
    EXPECT_NE(back.find("t=1000"), std::string::npos) << back;
    const std::string outside = message({ Event(1000, 64, 1, 1, 0) });
    EXPECT_NE(outside.find("64 x 48"), std::string::npos) << outside;
    const std::string camera = message({ Event(1000, 1, 1, 1, 2) });
    EXPECT_NE(camera.find("camera 2"), std::string::npos) << camera;
    EXPECT_THROW(m->setMaxDisparity(-1), cv::Exception);
    EXPECT_THROW(m->setMinDisparity(41), cv::Exception);
    EXPECT_THROW(m->setFrameWindow(0), cv::Exception);
    EXPECT_THROW(m->setFrameWindow(std::numeric_limits<double>::quiet_NaN()), cv::Exception);
    EXPECT_THROW(m->setSensorSize(Size(0, 10)), cv::Exception);
    EXPECT_THROW(m->setCalibration(StereoCalibration::fromRectified(Size(240, 180), 200, 0.1)), cv::Exception);
    Mat image;
    EXPECT_THROW(m->renderDisparity(0, image, 2), cv::Exception);
    EXPECT_EQ(m->getMaxDisparity(), 40);
    EXPECT_EQ(m->getFrameWindow(), 33000.0);
}

// write() and read() carry every parameter and the calibration; a node with one value out of range changes
// nothing.
TEST(FrameStereoMatcher, parameters_round_trip_through_FileStorage)
{
    Ptr<FrameStereoMatcher> m = FrameStereoMatcher::create(Size(128, 128));
    m->setMinDisparity(2);
    m->setMaxDisparity(30);
    m->setFrameWindow(20000);
    m->setCalibration(StereoCalibration::fromRectified(Size(128, 128), 150, 0.2));
    FileStorage out(".yml", FileStorage::WRITE | FileStorage::MEMORY);
    m->write(out);
    const std::string yaml = out.releaseAndGetString();
    Ptr<FrameStereoMatcher> r = FrameStereoMatcher::create();
    FileStorage in(yaml, FileStorage::READ | FileStorage::MEMORY);
    r->read(in.root());
    EXPECT_EQ(r->getSensorSize(), Size(128, 128));
    EXPECT_EQ(r->getMinDisparity(), 2);
    EXPECT_EQ(r->getMaxDisparity(), 30);
    EXPECT_EQ(r->getFrameWindow(), 20000.0);
    EXPECT_NEAR(r->getCalibration().focalLength() * r->getCalibration().baseline(), 150 * 0.2, 1e-9);

    FileStorage bad("%YAML:1.0\nminDisparity: 5\nframeWindow: -3\n", FileStorage::READ | FileStorage::MEMORY);
    EXPECT_THROW(r->read(bad.root()), cv::Exception);
    EXPECT_EQ(r->getMinDisparity(), 2);
    EXPECT_EQ(r->getFrameWindow(), 20000.0);
}

}}  // namespace
