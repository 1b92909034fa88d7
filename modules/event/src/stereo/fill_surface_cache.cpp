// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"
#include "common/timestamp_math.hpp"
#include "stereo/fill_surface_cache.hpp"

namespace cv {
namespace event {
namespace detail {

void FillSurfaceCache::reset(Size size)
{
    CV_Assert(size.width > 0 && size.height > 0);
    size_ = size;
    stretchesPerRow_ = divUp(size.width, (int)COLUMNS);
    // Support below any asked for: never reused.
    const Surface none{ std::numeric_limits<int64>::min(), 0.f, 0.f, -1 };
    surfaces_.assign((size_t)size.height * stretchesPerRow_, none);
}

const FillSurfaceCache::Surface* FillSurfaceCache::find(Point r, int64 t, int64 reuseTime, int minSupport) const
{
    if (reuseTime <= 0)
        return nullptr;
    for (int d = 0; d <= (int)ROWS; d++)
        for (int side = d == 0 ? 1 : -1; side <= 1; side += 2)
        {
            const int y = r.y + side * d;
            if (y < 0 || y >= size_.height)
                continue;
            const Surface& s = at(r.x, y);
            if (s.support >= minSupport && s.time <= t && t < timeAfter(s.time, reuseTime))
                return &s;
        }
    return nullptr;
}

}  // namespace detail
}  // namespace event
}  // namespace cv
