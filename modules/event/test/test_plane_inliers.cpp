// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The plane fit's inlier count, for this CPU's kernels and the scalar one: against counts known by construction
// (points placed on and off each hypothesis plane), and the vector kernels against the scalar one on random
// windows, for every number of points a 31 x 31 window holds and every number of hypotheses up to 3 paddings.

#include "test_precomp.hpp"
#include "lifetime/plane_inliers.hpp"

namespace opencv_test { namespace {
using namespace cv::event::detail;

struct PlaneProblem
{
    std::vector<double> x, y, t, a, b, threshold;
};

// n hypotheses and m points of a window with offsets up to `radius`, times up to 100 ms back; the hypotheses'
// arrays padded as the kernels require.
PlaneProblem randomProblem(RNG& rng, int m, int n, int radius)
{
    PlaneProblem p;
    for (int i = 0; i < m; i++)
    {
        p.x.push_back(rng.uniform(-radius, radius + 1));
        p.y.push_back(rng.uniform(-radius, radius + 1));
        p.t.push_back(-rng.uniform(0, 100000) * 1e-3);
    }
    const size_t slots = alignSize(std::max(n, 1), (int)PLANE_HYPOTHESES_PAD);
    for (size_t k = 0; k < slots; k++)
    {
        p.a.push_back(rng.uniform(-20.0, 20.0));
        p.b.push_back(rng.uniform(-20.0, 20.0));
        p.threshold.push_back(rng.uniform(0.05, 20.0));
    }
    return p;
}

std::vector<int> countWith(const PlaneInlierKernels& kernels, const PlaneProblem& p, int n)
{
    std::vector<int> counts(p.a.size(), -1);
    kernels.count(p.x.data(), p.y.data(), p.t.data(), (int)p.x.size(), p.a.data(), p.b.data(), p.threshold.data(), n,
                  counts.data());
    counts.resize((size_t)n);
    return counts;
}

TEST(Event_PlaneInliers, counts_the_points_placed_on_each_plane)
{
    // Hypothesis k is the plane t = a_k x + b_k y; point i lies at distance 0.5 ms (inside a threshold of 1 ms)
    // from hypothesis i % n and at 9.5 ms or more from every other hypothesis, so hypothesis k has exactly the points
    // i with i % n == k. The planes are steep and far apart (a_k = 10 k) and every point has x >= 1.
    for (const PlaneInlierKernels& kernels : { planeInlierKernelsForThisCpu(), scalarPlaneInlierKernels() })
        for (int n : { 1, 3, 8, 19 })
        {
            PlaneProblem p;
            const int m = 47;
            for (size_t k = 0; k < alignSize(n, (int)PLANE_HYPOTHESES_PAD); k++)
            {
                p.a.push_back(10.0 * (double)k);
                p.b.push_back(0.25);
                p.threshold.push_back(1.0);
            }
            for (int i = 0; i < m; i++)
            {
                const int k = i % n;
                const double x = 1 + i % 5, y = -2 + i % 4;
                p.x.push_back(x);
                p.y.push_back(y);
                p.t.push_back(p.a[(size_t)k] * x + p.b[(size_t)k] * y + (i % 2 ? 0.5 : -0.5));
            }
            const std::vector<int> counts = countWith(kernels, p, n);
            for (int k = 0; k < n; k++)
                EXPECT_EQ((m - k + n - 1) / n, counts[(size_t)k]) << kernels.name << ": hypothesis " << k << " of " << n;
        }
}

TEST(Event_PlaneInliers, vector_kernels_count_as_the_scalar_one)
{
    const PlaneInlierKernels vector = planeInlierKernelsForThisCpu(), scalar = scalarPlaneInlierKernels();
    RNG rng(20261127);
    int compared = 0;
    for (int m = 0; m <= 31 * 31 - 1; m += m < 40 ? 1 : 37)
        for (int n = 0; n <= 3 * PLANE_HYPOTHESES_PAD; n++)
        {
            const PlaneProblem p = randomProblem(rng, m, n, 15);
            ASSERT_EQ(countWith(scalar, p, n), countWith(vector, p, n)) << m << " points, " << n << " hypotheses";
            compared += n;
        }
    EXPECT_GT(compared, 10000);
}

}} // namespace
