// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"
#include "common/timestamp_math.hpp"
#include "stereo/active_estimate_map.hpp"

namespace cv {
namespace event {
namespace detail {

void ActiveEstimateMap::reset(Size size)
{
    size_ = size;
    until_.assign((size_t)size.area(), NO_ESTIMATE);
    disparity_.assign((size_t)size.area(), -1.f);
    blocksPerRow_ = divUp(size.width, (int)ESTIMATE_BLOCK);
    blockUntil_.assign((size_t)size.height * blocksPerRow_, 0);
    lastEventTime_.assign((size_t)size.area(), 0);
}

void ActiveEstimateMap::remember(Point r, int64 t, int64 activeFor, float disparity)
{
    const size_t i = (size_t)r.y * size_.width + r.x;
    lastEventTime_[i] = t;
    disparity_[i] = disparity;
    if (disparity < 0)
    {
        until_[i] = NO_ESTIMATE;
        return;
    }
    const int64 until = timeAfter(t, activeFor);
    until_[i] = until;
    int64& block = blockUntil_[(size_t)r.y * blocksPerRow_ + r.x / ESTIMATE_BLOCK];
    block = std::max(block, until);
}

size_t ActiveEstimateMap::median(Point centre, int rows, int columns, int64 t, std::vector<float>& disparities,
                                 float& median) const
{
    return sampledMedian(centre, rows, columns, 1, t, disparities, median);
}

size_t ActiveEstimateMap::sampledMedian(Point centre, int rows, int columns, int rowStep, int64 t,
                                        std::vector<float>& disparities, float& median) const
{
    disparities.clear();
    for (int y = centre.y - rows; y <= centre.y + rows; y += rowStep)
        forEachActive(centre.x - columns, centre.x + columns, y, y, t, [&disparities](float d) { disparities.push_back(d); });
    if (disparities.empty())
        return 0;
    const size_t mid = disparities.size() / 2;
    std::nth_element(disparities.begin(), disparities.begin() + (std::ptrdiff_t)mid, disparities.end());
    median = disparities[mid];
    return disparities.size();
}

bool ActiveEstimateMap::shownAt(int x, int y, double t, float& disparity) const
{
    const size_t i = (size_t)y * size_.width + x;
    if (until_[i] == NO_ESTIMATE || !((double)lastEventTime_[i] <= t && t < (double)until_[i]))
        return false;
    disparity = disparity_[i];
    return true;
}

}  // namespace detail
}  // namespace event
}  // namespace cv
