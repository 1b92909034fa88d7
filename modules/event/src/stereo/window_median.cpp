// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"
#include "stereo/window_median.hpp"

#include <opencv2/core/hal/intrin.hpp>

namespace cv {
namespace event {
namespace detail {

int windowMedianPosition(const int* values, int n, uint64* keys)
{
    CV_DbgAssert(n >= 1);
    const int want = n / 2;
    if (n > WINDOW_MEDIAN_RANKED)
    {
        for (int j = 0; j < n; j++)
            keys[j] = ((uint64)(uint32_t)values[j] << 32) | (uint32_t)j;
        std::nth_element(keys, keys + want, keys + n);
        return (int)(uint32_t)keys[want];
    }
    static_assert((int)v_int32x4::nlanes == (int)WINDOW_MEDIAN_PAD, "the padding is one vector");
    const int padded = alignSize(n, v_int32x4::nlanes);
    for (int i = 0; i < n; i++)
    {
        if (i > 0 && values[i] == values[i - 1])
            continue;  // the same rank as the one before
        const v_int32x4 value = v_setall_s32(values[i]);
        v_int32x4 below = v_setzero_s32(), equal = v_setzero_s32();
        for (int j = 0; j < padded; j += v_int32x4::nlanes)
        {
            const v_int32x4 other = v_load(values + j);
            below -= v_reinterpret_as_s32(other < value);  // a true lane is -1
            equal -= v_reinterpret_as_s32(other == value);
        }
        const int less = v_reduce_sum(below);
        if (less <= want && want < less + v_reduce_sum(equal))
        {
            // The median has this value: it is the (want - less)-th with it, in position order.
            for (int j = 0, k = want - less;; j++)
                if (values[j] == values[i] && k-- == 0)
                    return j;
        }
    }
    CV_Error(Error::StsInternal, "windowMedianPosition: no median (a value equal to the padding?)");
}

}  // namespace detail
}  // namespace event
}  // namespace cv
