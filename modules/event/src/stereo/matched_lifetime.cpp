// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// COUPLED: the lifetime of a matched event, the median of the active lifetimes in the other sensor's window
// around its counterpart.

#include "precomp.hpp"
#include "stereo/stereo_event_matcher_impl.hpp"

namespace cv {
namespace event {
namespace detail {

Rect StereoEventMatcherImpl::lifetimeWindowAround(int x, int y) const
{
    const int h = params_.lifetimeWindow / 2;
    return Rect(Point(x - h, y - h), Point(x + h + 1, y + h + 1)) & Rect(Point(), params_.sensorSize);
}

void StereoEventMatcherImpl::prefetchMatchedWindow(int c, int x, int y, int p) const
{
    if (params_.mode != STEREO_COUPLED)
        return;
    const Rect w = lifetimeWindowAround(x, y);
    maps_[c].prefetchLifetimes(w.x, w.x + w.width - 1, w.y, w.y + w.height - 1, p);
}

// Matched events copy their lifetime, so most windows hold equal lifetimes: the median is taken in the order
// (lifetime, position in the map), which fixes whose flow is returned whatever the selection algorithm
// (WindowMedianKernels: the events are gathered in map order).
bool StereoEventMatcherImpl::matchedLifetime(int c, int x, int y, int p, MatchScratch& s, float& lifetime, Vec2f& flow,
                                             int& copies) const
{
    const ZouDescriptorMap& map = maps_[c];
    const Rect w = lifetimeWindowAround(x, y);
    int* const values = s.matchedValues.data();
    int* const positions = s.matchedPositions.data();
    const int n = windowMedian_.gather(map.lifetimes(), map.lifetimeIndex(w.x, w.y, p), map.lifetimeRowStep(), w.width,
                                       w.height, values, positions);
    if (n == 0)
        return false;
    std::fill_n(values + n, (int)WINDOW_MEDIAN_PAD, WINDOW_MEDIAN_PAD_VALUE);
    const int median = windowMedian_.medianPosition(values, n, s.matchedKeys.data());
    std::memcpy(&lifetime, &values[median], sizeof(lifetime));
    flow = map.flowAt(positions[median]);
    copies = map.copiesAt(positions[median]);
    return true;
}

}  // namespace detail
}  // namespace event
}  // namespace cv
