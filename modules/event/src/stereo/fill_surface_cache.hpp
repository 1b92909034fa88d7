// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_STEREO_FILL_SURFACE_CACHE_HPP
#define OPENCV_EVENT_SRC_STEREO_FILL_SURFACE_CACHE_HPP

#include "opencv2/core.hpp"

#include <vector>

namespace cv {
namespace event {
namespace detail {

/** The surfaces that filling found for one sensor's events (StereoEventMatcher::setFillReuseTime), so that the
events after them nearby take them instead of each scanning the fill window again: per stretch of COLUMNS
columns of a row, the latest surface found there and when. An event at r reuses the first one, on its own row,
then 1, 2 .. ROWS rows above and below it (nearest first, above before below), of its stretch of columns that was
found less than the reuse time before it and had at least the support asked for.

Row bands: an entry of row y is written only by an event of row y and read only by events at most ROWS rows away,
within the rows an event's processing reads anyway, so the bands see it as one thread does. */
class CV_EXPORTS FillSurfaceCache  // exported for opencv_test_event only; not public API
{
public:
    enum { COLUMNS = 8, ROWS = 4 };

    // A surface as filling reads it: the median of the window's estimates, their count, and the share of them
    // within a pixel of the median (support -1: no surface).
    struct Surface
    {
        int64 time;
        float median;
        float agreeing;
        int support;
    };

    // Forgets every surface and sizes the cache for a sensor of `size`.
    void reset(Size size);

    // The surface an event at r of time t reuses, found less than reuseTime us before t (0: none) with a support
    // of at least minSupport (>= 0), or null when none serves (see the class).
    const Surface* find(Point r, int64 t, int64 reuseTime, int minSupport) const;

    // Keeps the surface found for the event at r (its time in s) for the events after it.
    void store(Point r, const Surface& s) { at(r.x, r.y) = s; }
private:
    Surface& at(int x, int y) { return surfaces_[(size_t)y * stretchesPerRow_ + (size_t)(x / COLUMNS)]; }
    const Surface& at(int x, int y) const { return surfaces_[(size_t)y * stretchesPerRow_ + (size_t)(x / COLUMNS)]; }

    Size size_;
    int stretchesPerRow_ = 0;
    std::vector<Surface> surfaces_;
};

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_STEREO_FILL_SURFACE_CACHE_HPP
