// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_STEREO_ACTIVE_ESTIMATE_MAP_HPP
#define OPENCV_EVENT_SRC_STEREO_ACTIVE_ESTIMATE_MAP_HPP

#include "opencv2/core.hpp"
#include "stereo/estimate_gather.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

namespace cv {
namespace event {
namespace detail {

/** One sensor's per-event disparity estimates as the neighbours read them (the temporal prior, the estimates
past the other sensor's view, the left-right check, the averaging) and as renderDisparity() shows them: per
pixel, the last event's time, its own estimate and the end of that estimate's activity.

The ends and the disparities are two arrays: the scans read a row's ends, and a disparity only where one is
active. An end is kept as a 32-bit offset from a time of its row (half the bytes a scan reads); the row's time
moves, and its offsets with it, when an end no longer fits. So an estimate stays active at most 2^31 - 1 us
(about 36 minutes) after its event, and a query more than that long before a later event of the row finds the
estimates that had ended by then inactive. Per ESTIMATE_BLOCK pixels of a row the latest end in the block (it
only grows) lets a scan skip the blocks where no estimate can be active. Row bands on several threads each
write their own rows. */
class CV_EXPORTS ActiveEstimateMap  // exported for opencv_test_event only; not public API
{
public:
    // Forgets every estimate and sizes the map for a sensor of `size`.
    void reset(Size size);

    // The event at r of time t: its estimate `disparity` stays active until activeFor after t; a negative
    // disparity (no estimate) ends the pixel's estimate at once.
    void remember(Point r, int64 t, int64 activeFor, float disparity);

    // Adds to sum each estimate active at time t in columns [x0, x1] of rows [y0, y1] (clipped to the image) that
    // lies within `tolerance` of `value`, and counts them in n: the sum is bit for bit the one additions row by row,
    // left to right, give; without a branch per pixel (the window's activity is random).
    void sumNear(int x0, int x1, int y0, int y1, int64 t, float value, float tolerance, double& sum, int& n) const;

    // The disparities of the estimates active at time t within `rows` rows and `columns` columns of `centre`
    // (into `disparities`, in no particular order), their count and, when there are any, their median.
    size_t median(Point centre, int rows, int columns, int64 t, std::vector<float>& disparities, float& median) const;

    // As median(), over every `rowStep`-th row of the window from its first: a tall window's median from a
    // fraction of its estimates.
    size_t sampledMedian(Point centre, int rows, int columns, int rowStep, int64 t, std::vector<float>& disparities,
                         float& median) const;

    // The estimate shown at time t at pixel (x, y): that of the pixel's last event at or before t, while active.
    bool shownAt(int x, int y, double t, float& disparity) const;

private:
    enum { ESTIMATE_BLOCK = 16 };
    // Ends no query can find active: none (the last event has no estimate), and one over 2^31 us before the
    // row's time. A query's offset is at least ENDED_LONG_AGO, so that one compare tells an active estimate.
    static constexpr int32_t NO_ESTIMATE = std::numeric_limits<int32_t>::min();
    static constexpr int32_t ENDED_LONG_AGO = NO_ESTIMATE + 1;

    // Time t as an offset from row y's time, clamped to [ENDED_LONG_AGO, INT32_MAX]; in that range an estimate
    // is active at t exactly when t's offset is below its end's.
    int32_t offsetInRow(int y, int64 t) const;
    // Moves row y's time to `time`, and its ends' offsets with it.
    void moveRowTime(int y, int64 time);

    Size size_;
    std::vector<int32_t> until_;  // the ends, as offsets from their row's time
    std::vector<int64> rowTime_;
    std::vector<float> disparity_;
    std::vector<int64> blockUntil_;
    int blocksPerRow_ = 0;
    std::vector<int64> lastEventTime_;
    EstimateGatherFn gather_ = estimateGatherKernelsForThisCpu().gather;
    ValuesInRangeFn valuesInRange_ = estimateGatherKernelsForThisCpu().valuesInRange;
    EstimateNearSumFn nearSum_ = estimateGatherKernelsForThisCpu().nearSum;
};

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_STEREO_ACTIVE_ESTIMATE_MAP_HPP
