// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "perf_precomp.hpp"

namespace opencv_test { namespace {

// Two interleaved, time-ordered camera streams at a steady rate (one event per microsecond each).
void makeStereoStreams(int n, std::vector<Event>& left, std::vector<Event>& right)
{
    RNG rng(12345);
    left.resize(n);
    right.resize(n);
    for (int i = 0; i < n; i++)
    {
        left[i] = Event(i, rng.uniform(0, 240), rng.uniform(0, 180), rng.uniform(0, 2));
        right[i] = Event(i + (i & 1), rng.uniform(0, 240), rng.uniform(0, 180), rng.uniform(0, 2));
    }
    std::sort(right.begin(), right.end(), [](const Event& a, const Event& b) { return a.t < b.t; });
}

typedef TestBaseWithParam<int> Event_MergeStereo;

PERF_TEST_P(Event_MergeStereo, merge, testing::Values(100000, 1000000))
{
    std::vector<Event> left, right, merged;
    makeStereoStreams(GetParam(), left, right);
    TEST_CYCLE() mergeStereoEvents(left, right, merged);
    ASSERT_EQ(left.size() + right.size(), merged.size());
    SANITY_CHECK_NOTHING();
}

typedef TestBaseWithParam<int> Event_PackColumns;

PERF_TEST_P(Event_PackColumns, pack_unpack, testing::Values(100000, 1000000))
{
    std::vector<Event> left, right, packed;
    makeStereoStreams(GetParam(), left, right);
    Mat t, x, y, p;
    TEST_CYCLE()
    {
        unpackEvents(left, t, x, y, p);
        packEvents(t, x, y, p, packed);
    }
    ASSERT_EQ(left.size(), packed.size());
    SANITY_CHECK_NOTHING();
}

}} // namespace
