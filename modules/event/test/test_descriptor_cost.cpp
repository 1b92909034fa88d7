// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The matcher's SIMD cost kernels against their scalar reference: the same integers for every window shape
// the matcher uses (1..31 wide, 1..31 high), row steps of the descriptor map and of 0 (a row of zeros),
// unaligned starts, and counts up to 255 (the largest a descriptor byte holds); the batch kernel for every
// number of candidates up to 11 (its blocks of 4, 2 and 1), shifted either way along the row. Descriptors
// are packed (24 bytes), so a row of w descriptors ends 0, 8, 16 or 24 bytes into a 32-byte chunk: widths
// of every residue are checked, and the bytes right after each row are nonzero, so a kernel that read past
// the rectangle would count them.

#include "test_precomp.hpp"
#include "stereo/descriptor_cost.hpp"
#include "stereo/zou_descriptor_map.hpp"

namespace opencv_test { namespace {
using namespace cv::event::detail;

const int bytes = ZouDescriptorMap::DESCRIPTOR_BYTES;

// Sparse counts like real descriptors (one byte in `oneIn` nonzero, any value up to 255, so some saturated).
// a and b are drawn alternately, byte by byte.
void fillSparseDescriptors(RNG& rng, int oneIn, std::vector<uchar>& a, std::vector<uchar>& b)
{
    for (size_t i = 0; i < a.size(); i++)
    {
        a[i] = (uchar)(rng.uniform(0, oneIn) == 0 ? rng.uniform(0, 256) : 0);
        b[i] = (uchar)(rng.uniform(0, oneIn) == 0 ? rng.uniform(0, 256) : 0);
    }
}

TEST(Event_DescriptorCost, simd_kernel_equals_scalar_reference)
{
    RNG rng(11);
    const int stride = 40, rows = 34;
    std::vector<uchar> a((size_t)stride * rows * bytes + 64), b(a.size());
    fillSparseDescriptors(rng, 4, a, b);
    const size_t step = (size_t)stride * bytes;
    const DescriptorRectSadFn simd = descriptorRectSadFunction();
    int checked = 0;
    for (int w = 1; w <= 31; w += 1)
        for (int h = 1; h <= 31; h += 3)
            for (int offset : { 0, 1, 7 })  // descriptors 0, 1 or 7 along: no alignment is assumed
            {
                const uchar* pa = &a[(size_t)offset * bytes];
                const uchar* pb = &b[(size_t)(offset + 2) * bytes + step];
                ASSERT_EQ(descriptorRectSadScalar(pa, pb, step, step, w, h), simd(pa, pb, step, step, w, h))
                    << w << " x " << h << " at " << offset << " (" << descriptorRectSadKernel() << ")";
                ASSERT_EQ(descriptorRectSadScalar(pa, pb, step, 0, w, h), simd(pa, pb, step, 0, w, h))
                    << w << " x " << h << " against one row";
                checked++;
            }
    EXPECT_EQ(checked, 31 * 11 * 3);
    // Closed form: all 24 counts 255 against zeros over 31 x 31 descriptors.
    std::vector<uchar> full((size_t)31 * bytes, 255), zeros(full.size(), 0);
    EXPECT_EQ(simd(full.data(), zeros.data(), 0, 0, 31, 31), 31u * 31u * 24u * 255u);
    // A rectangle that ends where its buffer ends: nothing past it is read (or counted).
    for (int w = 1; w <= 8; w++)
    {
        std::vector<uchar> last((size_t)w * bytes, 7), none(last.size(), 0);
        EXPECT_EQ(simd(last.data(), none.data(), 0, 0, w, 3), 3u * (unsigned)w * 24u * 7u) << w << " wide";
    }
}

TEST(Event_DescriptorCost, batch_kernel_equals_one_rectangle_per_candidate_and_the_mass)
{
    RNG rng(12);
    const int stride = 80, rows = 34;
    std::vector<uchar> a((size_t)stride * rows * bytes), b(a.size());
    fillSparseDescriptors(rng, 3, a, b);
    const size_t step = (size_t)stride * bytes;
    const DescriptorRectSadBatchFn batch = descriptorRectSadBatchFunction();
    const std::vector<uchar> zeros((size_t)32 * bytes, 0);  // one row of 32 empty descriptors, step 0
    int checked = 0;
    for (int sign : { -1, 1 })  // the left sensor's candidates lie to the left, the right one's to the right
        for (int n = 0; n <= 11; n++)
            // Rows ending 24, 16, 8, 0, 0, 24, 24, 8 bytes into a chunk; widths 8 and 9 (six full chunks) and 1 (none)
            // take the kernel's unrolled rows.
            for (int w : { 1, 2, 3, 4, 8, 9, 17, 31 })
                for (int h : { 1, 9, 17, 31 })
                {
                    // The rectangle at column 40; candidate i is shifted by a disparity of 2i + (i % 3) columns.
                    const uchar* pa = &a[(size_t)40 * bytes];
                    const uchar* pb = &b[(size_t)(sign < 0 ? 40 : 8) * bytes];
                    std::vector<ptrdiff_t> offsets;
                    std::vector<unsigned> expected, sums;
                    for (int i = 0; i < n; i++)
                    {
                        offsets.push_back((ptrdiff_t)sign * (2 * i + i % 3) * bytes);
                        // Start from a nonzero sum: the kernel adds to it.
                        expected.push_back(1000u * (unsigned)i + descriptorRectSadScalar(pa, pb + offsets.back(), step, step, w, h));
                        sums.push_back(1000u * (unsigned)i);
                    }
                    const unsigned mass = batch(pa, pb, step, step, offsets.data(), n, w, h, sums.data());
                    ASSERT_EQ(expected, sums) << n << " candidates, " << w << " x " << h << ", sign " << sign << " ("
                                              << descriptorRectSadKernel() << ")";
                    ASSERT_EQ(descriptorRectSadScalar(pa, zeros.data(), step, 0, w, h), mass)
                        << "mass, " << n << " candidates, " << w << " x " << h << " (" << descriptorRectSadKernel() << ")";
                    checked++;
                }
    EXPECT_EQ(checked, 2 * 12 * 8 * 4);
}

}}  // namespace
