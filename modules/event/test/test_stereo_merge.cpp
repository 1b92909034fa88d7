// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// No loss in the stereo merge: two recorded streams (bursts, shared timestamps, one camera silent for long
// stretches) opened as a pair come out as one time-ordered stream holding every input event exactly once,
// left first on equal timestamps, whatever the batch size or window length of the reads.

#include "test_precomp.hpp"

namespace opencv_test { namespace {

std::vector<Event> burstyStream(int n, int camera, uint64 seed)
{
    RNG rng(seed);
    std::vector<Event> ev;
    int64 t = 1000;
    for (int i = 0; i < n; i++)
    {
        const int r = rng.uniform(0, 100);
        if (r < 40)
            t += 0;                         // same timestamp as the previous event
        else if (r < 98)
            t += rng.uniform(1, 50);
        else
            t += rng.uniform(50000, 300000);  // the camera is silent for a while
        ev.push_back(Event(t, rng.uniform(0, 128), rng.uniform(0, 128), rng.uniform(0, 2), camera));
    }
    return ev;
}

// The expected merge, independently: both streams in one list, stable-sorted by time with left first.
std::vector<Event> expectedMerge(const std::vector<Event>& left, const std::vector<Event>& right)
{
    std::vector<Event> all(left);
    all.insert(all.end(), right.begin(), right.end());
    std::stable_sort(all.begin(), all.end(), [](const Event& a, const Event& b) {
        return a.t != b.t ? a.t < b.t : a.camera < b.camera;
    });
    return all;
}

TEST(Event_StereoMerge, every_event_exactly_once_in_time_order_for_any_read_size)
{
    const std::vector<Event> left = burstyStream(30000, CAMERA_LEFT, 1), right = burstyStream(20000, CAMERA_RIGHT, 2);
    const std::vector<Event> expected = expectedMerge(left, right);
    std::string paths[2];
    const std::vector<Event>* streams[2] = { &left, &right };
    for (int c = 0; c < 2; c++)
    {
        paths[c] = cv::tempfile(c == 0 ? "_left.aedat4" : "_right.aedat4");
        std::vector<Event> mono = *streams[c];
        for (Event& e : mono)
            e.camera = CAMERA_LEFT;  // each file is one camera's recording
        EventWriter writer(paths[c], Size(128, 128));
        writer.write(mono);
    }
    // Batches of 1, 7, 4096 events, and windows of 1 us, 10 ms and 1 s.
    const int reads[][2] = { { EVENT_CAP_PROP_BATCH_EVENTS, 1 },  { EVENT_CAP_PROP_BATCH_EVENTS, 7 },
                             { EVENT_CAP_PROP_BATCH_EVENTS, 4096 }, { EVENT_CAP_PROP_WINDOW_US, 1 },
                             { EVENT_CAP_PROP_WINDOW_US, 10000 },  { EVENT_CAP_PROP_WINDOW_US, 1000000 } };
    for (const auto& read : reads)
    {
        SCOPED_TRACE(cv::format("%s %d", read[0] == EVENT_CAP_PROP_BATCH_EVENTS ? "batch" : "window", read[1]));
        EventCapture cap;
        if (read[0] == EVENT_CAP_PROP_WINDOW_US)
            cap.set(EVENT_CAP_PROP_BATCH_EVENTS, 0);
        cap.set(read[0], read[1]);
        ASSERT_TRUE(cap.openStereo(paths[0], paths[1]));
        std::vector<Event> all, packet;
        while (cap.read(packet))
            all.insert(all.end(), packet.begin(), packet.end());
        ASSERT_EQ(expected.size(), all.size());
        for (size_t i = 0; i < all.size(); i++)
            ASSERT_EQ(expected[i], all[i]) << "event " << i;
    }
    // The in-memory merge gives the same.
    std::vector<Event> merged;
    mergeStereoEvents(left, right, merged);
    ASSERT_EQ(expected.size(), merged.size());
    for (size_t i = 0; i < merged.size(); i++)
        ASSERT_EQ(expected[i], merged[i]) << "event " << i;
    for (const std::string& p : paths)
        std::remove(p.c_str());
}

}}  // namespace
