// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// FillSurfaceCache: which surface an event reuses, against the rule the class states (its stretch of 8 columns,
// its row, then 1 .. 4 rows above and below, nearest first and above first; found less than the reuse time
// before it; support enough), at the image's borders and at the ends of the 64-bit times.

#include "test_precomp.hpp"
#include "stereo/fill_surface_cache.hpp"

namespace opencv_test { namespace {
using namespace cv::event::detail;

FillSurfaceCache::Surface surface(int64 t, float median, int support = 10)
{
    return FillSurfaceCache::Surface{ t, median, 0.9f, support };
}

// The median of the surface found for an event at r of time t (-1: none).
float reused(const FillSurfaceCache& cache, Point r, int64 t, int64 reuseTime = 5000, int minSupport = 5)
{
    const FillSurfaceCache::Surface* s = cache.find(r, t, reuseTime, minSupport);
    return s ? s->median : -1.f;
}

TEST(FillSurfaceCache, reuses_the_stretch_of_columns_within_four_rows_for_less_than_the_reuse_time)
{
    FillSurfaceCache cache;
    cache.reset(Size(240, 180));
    EXPECT_EQ(reused(cache, Point(100, 50), 0), -1.f) << "nothing found yet";
    cache.store(Point(100, 50), surface(1000, 12.5f));
    // Columns 96..103 are the stretch of column 100.
    for (int x = 94; x <= 105; x++)
        for (int y = 44; y <= 56; y++)
        {
            const bool within = x >= 96 && x <= 103 && std::abs(y - 50) <= 4;
            EXPECT_EQ(reused(cache, Point(x, y), 1000), within ? 12.5f : -1.f) << x << ", " << y;
        }
    EXPECT_EQ(reused(cache, Point(100, 50), 5999), 12.5f);
    EXPECT_EQ(reused(cache, Point(100, 50), 6000), -1.f) << "found 5000 us before: no longer";
    EXPECT_EQ(reused(cache, Point(100, 50), 999), -1.f) << "found after the event";
    EXPECT_EQ(reused(cache, Point(100, 50), 1000, 0), -1.f) << "reuse time 0: never";
    EXPECT_EQ(reused(cache, Point(100, 50), 1000, 5000, 11), -1.f) << "support 10 < 11";
    EXPECT_EQ(reused(cache, Point(100, 50), 1000, 5000, 10), 12.5f);
}

TEST(FillSurfaceCache, takes_the_nearest_row_first_and_above_before_below)
{
    FillSurfaceCache cache;
    cache.reset(Size(64, 32));
    cache.store(Point(10, 20), surface(0, 3.f));  // 4 below the event's row 16
    cache.store(Point(11, 13), surface(0, 2.f));  // 3 above
    cache.store(Point(12, 19), surface(0, 1.f));  // 3 below
    EXPECT_EQ(reused(cache, Point(9, 16), 100), 2.f);
    cache.store(Point(15, 17), surface(50, 4.f));  // 1 below
    EXPECT_EQ(reused(cache, Point(9, 16), 100), 4.f);
    cache.store(Point(8, 16), surface(60, 5.f, 4));  // its own row, but too little support
    EXPECT_EQ(reused(cache, Point(9, 16), 100), 4.f);
    cache.store(Point(8, 16), surface(70, 6.f));  // its own row, replaced
    EXPECT_EQ(reused(cache, Point(9, 16), 100), 6.f);
}

TEST(FillSurfaceCache, stays_inside_the_image_and_exact_at_the_ends_of_time)
{
    FillSurfaceCache cache;
    cache.reset(Size(13, 3));  // a short last stretch: columns 8..12
    const int64 latest = std::numeric_limits<int64>::max(), earliest = std::numeric_limits<int64>::min() + 1;
    cache.store(Point(12, 0), surface(latest - 10, 7.f));
    EXPECT_EQ(reused(cache, Point(8, 2), latest - 1), 7.f) << "rows past the border are skipped";
    EXPECT_EQ(reused(cache, Point(7, 2), latest - 1), -1.f);
    cache.store(Point(0, 2), surface(earliest, 8.f));
    EXPECT_EQ(reused(cache, Point(3, 0), earliest + 4999), 8.f);
    EXPECT_EQ(reused(cache, Point(3, 0), earliest + 5000), -1.f);
    EXPECT_EQ(reused(cache, Point(3, 0), latest), -1.f) << "no overflow between the ends";
    cache.reset(Size(13, 3));
    EXPECT_EQ(reused(cache, Point(12, 0), earliest, 1000000, 0), -1.f) << "reset: nothing found, whatever the support";
}

}}  // namespace
