// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The incrementally maintained Zou descriptors (ZouDescriptorMap, internal) against descriptors computed from
// scratch from the set of active events, after every activation, deactivation and expiry of a random
// sequence that crowds the image borders: the nearest active event of each pixel and polarity within the
// maximum vector length (nearest by length, ties by angle counter-clockwise from +x), its 30-degree bin
// voted into each descriptor of the N x N window around the pixel (a pixel that is itself active votes into
// all 12 bins of its polarity), and zero descriptors in the margin around the image.

#include "test_precomp.hpp"
#include "stereo/zou_descriptor_map.hpp"

namespace opencv_test { namespace {
using namespace cv::event::detail;

struct ReferenceOffset
{
    Point d;
    int bin;  // -1: the pixel itself
};

// The vectors within maxVectorLength, nearest first, ties by angle in [0, 360) degrees.
std::vector<ReferenceOffset> referenceOffsets(int maxVectorLength)
{
    struct Entry
    {
        Point d;
        int length2;
        double degrees;
    };
    std::vector<Entry> entries;
    for (int dy = -maxVectorLength; dy <= maxVectorLength; dy++)
        for (int dx = -maxVectorLength; dx <= maxVectorLength; dx++)
            if (dx * dx + dy * dy <= maxVectorLength * maxVectorLength)
            {
                double degrees = std::atan2((double)dy, (double)dx) * 180 / CV_PI;
                if (degrees < 0)
                    degrees += 360;
                entries.push_back(Entry{ Point(dx, dy), dx * dx + dy * dy, degrees });
            }
    std::stable_sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
        return a.length2 != b.length2 ? a.length2 < b.length2 : a.degrees < b.degrees;
    });
    std::vector<ReferenceOffset> offsets;
    for (const Entry& e : entries)
        offsets.push_back(ReferenceOffset{ e.d, e.length2 == 0 ? -1 : std::min(11, (int)std::floor(e.degrees / 30 + 1e-9)) });
    return offsets;
}

// Compares every descriptor byte of the map, margin included, with the descriptors of the active set.
::testing::AssertionResult matchesReference(const ZouDescriptorMap& map, const std::vector<uchar>& active, Size size,
                                            int window, int maxVectorLength)
{
    const std::vector<ReferenceOffset> offsets = referenceOffsets(maxVectorLength);
    const int margin = map.margin(), h = window / 2;
    auto isActive = [&](int x, int y, int p) { return active[((size_t)p * size.height + y) * size.width + x] != 0; };
    // Nearest offset per pixel and polarity (-1: none within reach).
    std::vector<int> nearest((size_t)2 * size.area(), -1);
    for (int p = 0; p < 2; p++)
        for (int y = 0; y < size.height; y++)
            for (int x = 0; x < size.width; x++)
                for (size_t k = 0; k < offsets.size(); k++)
                {
                    const Point q(x + offsets[k].d.x, y + offsets[k].d.y);
                    if (q.x >= 0 && q.y >= 0 && q.x < size.width && q.y < size.height && isActive(q.x, q.y, p))
                    {
                        nearest[((size_t)p * size.height + y) * size.width + x] = (int)k;
                        break;
                    }
                }
    for (int y = -margin; y < size.height + margin; y++)
        for (int x = -margin; x < size.width + margin; x++)
        {
            uchar expected[ZouDescriptorMap::DESCRIPTOR_BYTES] = { 0 };  // outside the image: zero
            const bool inside = x >= 0 && y >= 0 && x < size.width && y < size.height;
            for (int sy = std::max(0, y - h); sy <= std::min(size.height - 1, y + h); sy++)
                for (int sx = std::max(0, x - h); sx <= std::min(size.width - 1, x + h); sx++)
                    for (int p = 0; p < 2 && inside; p++)
                    {
                        const int k = nearest[((size_t)p * size.height + sy) * size.width + sx];
                        if (k < 0)
                            continue;
                        for (int b = 0; b < 12; b++)
                            if (offsets[(size_t)k].bin < 0 || offsets[(size_t)k].bin == b)
                                expected[p * 12 + b]++;
                    }
            const uchar* got = map.descriptor(x, y);
            for (int b = 0; b < ZouDescriptorMap::DESCRIPTOR_BYTES; b++)
                if (got[b] != expected[b])
                    return ::testing::AssertionFailure() << "descriptor of (" << x << ", " << y << ") byte " << b << ": "
                                                         << (int)got[b] << ", expected " << (int)expected[b];
            if (inside)
                for (int p = 0; p < 2; p++)
                {
                    const bool structure = nearest[((size_t)p * size.height + y) * size.width + x] >= 0;
                    if (map.hasStructure(x, y, p) != structure || map.isActive(x, y, p) != isActive(x, y, p))
                        return ::testing::AssertionFailure() << "(" << x << ", " << y << ") polarity " << p
                                                             << ": activity or structure differs";
                }
        }
    return ::testing::AssertionSuccess();
}

TEST(Event_ZouDescriptorMap, incremental_descriptors_equal_descriptors_from_scratch)
{
    const Size size(23, 17);
    // (descriptor window, max vector length, margin): the matcher's defaults, the smallest and largest values, and
    // a 5 x 5 window with room inside (events more than vector length + N / 2 from every border vote without
    // clipping; with a vector length of 7 no pixel of this image is that far in).
    const int configs[][3] = { { 3, 3, 8 }, { 1, 0, 0 }, { 5, 7, 2 }, { 3, 1, 1 }, { 5, 3, 2 } };
    for (const auto& config : configs)
    {
        const int window = config[0], maxVectorLength = config[1], margin = config[2];
        SCOPED_TRACE(cv::format("window %d, max vector length %d, margin %d", window, maxVectorLength, margin));
        ZouDescriptorMap map;
        map.configure(size, window, maxVectorLength, margin);
        std::vector<uchar> active((size_t)2 * size.area(), 0);
        std::vector<int64> expiry(active.size(), 0);
        RNG rng(17);
        int64 t = 0;
        int changes = 0, mostActive = 0;
        for (int step = 0; step < 400; step++)
        {
            t += rng.uniform(0, 10);
            // Expiry first, as the matcher does: every event with expiry <= t goes.
            map.expireUntil(t);
            for (size_t i = 0; i < active.size(); i++)
                if (active[i] && expiry[i] <= t)
                    active[i] = 0, changes++;
            // Half the events in the outer 2 px, where windows and vectors are clipped.
            int x = rng.uniform(0, size.width), y = rng.uniform(0, size.height);
            if (rng.uniform(0, 2) == 0)
            {
                x = rng.uniform(0, 2) ? rng.uniform(0, 2) : size.width - 1 - rng.uniform(0, 2);
                y = rng.uniform(0, size.height);
            }
            const int p = rng.uniform(0, 2);
            const size_t i = ((size_t)p * size.height + y) * size.width + x;
            if (rng.uniform(0, 5) == 0)
            {
                map.deactivate(x, y, p);
                changes += active[i];
                active[i] = 0;
            }
            else
            {
                const int64 until = t + rng.uniform(1, 400);
                map.activate(x, y, p, t, until, 1.f, Vec2f());
                changes += !active[i];
                active[i] = 1;
                expiry[i] = until;
            }
            ASSERT_TRUE(matchesReference(map, active, size, window, maxVectorLength)) << "step " << step << ", t = " << t;
            mostActive = std::max(mostActive, (int)std::count(active.begin(), active.end(), 1));
        }
        // The sequence really exercised the map: many activations and deactivations, and crowded states, where
        // vectors compete and deactivations must re-search.
        EXPECT_GT(changes, 300);
        EXPECT_GT(mostActive, 30);
    }
}

// The recency cost's input: by row, whether an event is active and its time (in the image's corner as well,
// with no border around the per-pixel arrays: vector length 0).
TEST(Event_ZouDescriptorMap, active_and_time_rows_hold_the_active_events)
{
    for (int maxVectorLength : { 3, 0 })
    {
        SCOPED_TRACE(cv::format("max vector length %d", maxVectorLength));
        ZouDescriptorMap map;
        map.configure(Size(8, 6), 3, maxVectorLength, 1);
        for (int p = 0; p < 2; p++)
            for (int y = 0; y < 6; y++)
                for (int x = 0; x < 8; x++)
                    ASSERT_EQ(map.activeRow(y, p)[x], 0);
        map.activate(0, 0, 1, 1000, 100000, 1.f, Vec2f());
        map.activate(7, 5, 1, 7500, 100000, 1.f, Vec2f());
        map.activate(7, 5, 0, std::numeric_limits<int64>::min(), 100000, 1.f, Vec2f());  // the other polarity
        map.activate(0, 0, 1, 2500, 100000, 1.f, Vec2f());  // a later event of the same pixel
        EXPECT_NE(map.activeRow(0, 1)[0], 0);
        EXPECT_EQ(map.eventTimeRow(0, 1)[0], 2500);
        EXPECT_EQ(map.eventTimeRow(5, 1)[7], 7500);
        EXPECT_EQ(map.eventTimeRow(5, 0)[7], std::numeric_limits<int64>::min());
        EXPECT_EQ(map.activeRow(5, 0)[6], 0);
        EXPECT_EQ(map.activeRow(0, 0)[0], 0);
        map.deactivate(7, 5, 1);
        EXPECT_EQ(map.activeRow(5, 1)[7], 0);
        EXPECT_NE(map.activeRow(0, 1)[0], 0);
        map.expireUntil(100000);
        EXPECT_EQ(map.activeRow(0, 1)[0], 0);
        EXPECT_EQ(map.activeRow(5, 0)[7], 0);
    }
}

}}  // namespace
