// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"

namespace opencv_test { namespace {

// shared/data/README.md: ROS2 sqlite3 bag, EventPacket with libcaer encoding, 640x480, 334,331 events; the
// int32 microsecond timestamp wraps once: the stream must stay time-ordered across it.
TEST(Event_Capture_Real, rosbag2_libcaer_rollover)
{
    const std::string dir = requireSharedData("format_samples/ros2_libcaer_rollover");
    const std::string sources[] = { dir, dir + "/libcaer_rollover_0.db3" };  // the folder or the database
    for (const std::string& source : sources)
    {
        EXPECT_EQ("ROSBAG2", detectEventFileFormat(source));
        EventCapture cap(source);
        EXPECT_EQ("ROSBAG2", cap.getBackendName());
        EXPECT_EQ(Size(640, 480), cap.getSensorSize());
        cap.set(EVENT_CAP_PROP_BATCH_EVENTS, 100000);
        std::vector<Event> packet;
        size_t n = 0;
        int64 first = -1, last = -1, maxStep = 0;
        while (cap.read(packet))
            for (const Event& e : packet)
            {
                if (first < 0) first = e.t;
                if (last >= 0) maxStep = std::max(maxStep, e.t - last);
                last = e.t;
                n++;
            }
        EXPECT_EQ(334331u, n) << source;
        EXPECT_EQ(0.0, cap.get(EVENT_CAP_PROP_TIME_BACKWARDS)) << source;
        EXPECT_EQ(0.0, cap.get(EVENT_CAP_PROP_REJECTED_OUTSIDE)) << source;
        // The metadata gives 1.99 s between the first and last message; a mishandled wrap would show as a
        // jump of about 2^31 us (36 minutes) or as time going backwards.
        EXPECT_NEAR(2.0e6, (double)(last - first), 0.05e6) << source;
        EXPECT_LT(maxStep, 100000) << source;
    }
}

}} // namespace
