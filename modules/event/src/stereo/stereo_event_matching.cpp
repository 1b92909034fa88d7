// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The matching core of StereoEventMatcher: candidates along the row, descriptor cost with iterative
// aggregation, the winner and its uniqueness, the left-right check and the matched window's lifetime.

#include "precomp.hpp"
#include "stereo/stereo_event_matcher_impl.hpp"

namespace cv {
namespace event {
namespace detail {

// Adds the SAD over the rectangle [x0, x1] x [y0, y1] (relative to the event) to every candidate's cost;
// returns the same sum against an empty map (the event's side alone).
unsigned StereoEventMatcherImpl::addRect(const ZouDescriptorMap& self, const ZouDescriptorMap& other, Point r, int x0, int x1, int y0, int y1,
                 MatchScratch& s) const
{
    if (!clipToImage(r, x0, x1, y0, y1))
        return 0;
    // Candidate i's rectangle is this one shifted by its disparity along the row: offsets[i] bytes.
    return rectSadBatch_(self.descriptor(r.x + x0, r.y + y0), other.descriptor(r.x + x0, r.y + y0),
                         self.descriptorRowStep(), other.descriptorRowStep(), s.offsets.data(),
                         s.count, x1 - x0 + 1, y1 - y0 + 1, s.cost.data());
}

// Clips the rectangle [x0, x1] x [y0, y1] relative to the event's pixel r to the image; false when nothing is
// left. Cost windows cover only the event's own image: past its border both sensors' descriptors are zero for
// a candidate that also runs past the other border (d near 0 at the right border of the left image), which
// would match "nothing" against "nothing" for free and pull border events toward that candidate.
bool StereoEventMatcherImpl::clipToImage(Point r, int& x0, int& x1, int& y0, int& y1) const
{
    x0 = std::max(x0, -r.x);
    x1 = std::min(x1, size_.width - 1 - r.x);
    y0 = std::max(y0, -r.y);
    y1 = std::min(y1, size_.height - 1 - r.y);
    return x0 <= x1 && y0 <= y1;
}

// Sum of the descriptor values over [x0, x1] x [y0, y1] relative to q: the cost of matching against nothing.
unsigned StereoEventMatcherImpl::rectMass(const ZouDescriptorMap& map, Point q, int x0, int x1, int y0, int y1) const
{
    // The batch kernel without candidates: it returns the rectangle's mass alone.
    return rectSadBatch_(map.descriptor(q.x + x0, q.y + y0), nullptr, map.descriptorRowStep(), 0, nullptr, 0,
                         x1 - x0 + 1, y1 - y0 + 1, nullptr);
}

// Matches the event at r (camera c, polarity p, time t) along its row.
MatchResult StereoEventMatcherImpl::match(int c, Point r, int p, int64 t, MatchScratch& s) const
{
    MatchResult m;
    const ZouDescriptorMap& self = maps_[c];
    const ZouDescriptorMap& other = maps_[1 - c];
    const int sign = c == CAMERA_LEFT ? -1 : 1;  // left x_l matches right x_l - d; right x_r matches left x_r + d
    int* const candidates = s.candidates.data();
    ptrdiff_t* const offsets = s.offsets.data();
    unsigned* const cost = s.cost.data();
    // Disparity indices k whose column xo = r.x + sign * (min + k) lies in the other image; there, a candidate
    // is a column where the other sensor has structure of this polarity. Every k is written and the count
    // advances past the candidates: no branch on the (random) activity pattern.
    const int kEnd = std::min(maxDisparity_, sign < 0 ? r.x : size_.width - 1 - r.x) - minDisparity_ + 1;
    const uchar* structure = other.nearestRow(r.y, p);
    const int x0 = r.x + sign * minDisparity_;
    const ptrdiff_t offsetStep = (ptrdiff_t)sign * ZouDescriptorMap::DESCRIPTOR_BYTES;
    int n = 0;
    for (int k = 0; k < kEnd; k++)
    {
        candidates[n] = k;
        n += structure[x0 + sign * k] != ZouDescriptorMap::NONE;
    }
    for (int i = 0; i < n; i++)
        offsets[i] = (minDisparity_ + candidates[i]) * offsetStep;
    s.count = n;
    if (n == 0)
    {
        m.flags = STEREO_NO_COUNTERPART;
        return m;
    }
    std::fill_n(cost, n, 0u);
    int h = costWindow_ / 2;
    unsigned mass = addRect(self, other, r, -h, h, -h, h, s);
    for (;;)
    {
        int best = 0;  // index into candidates, which run by disparity: ties go to the smaller disparity
        for (int i = 1; i < n; i++)
            if (cost[i] < cost[best])
                best = i;
        const int kBest = candidates[best];
        // The candidates within one pixel of the best are next to it (they run by disparity, one each):
        // the runner-up is the cheapest outside [lo, hi].
        const int lo = best > 0 && candidates[best - 1] == kBest - 1 ? best - 1 : best;
        const int hi = best < n - 1 && candidates[best + 1] == kBest + 1 ? best + 1 : best;
        uint64 second = std::numeric_limits<uint64>::max();
        for (int i = 0; i < lo; i++)
            second = std::min(second, (uint64)cost[i]);
        for (int i = hi + 1; i < n; i++)
            second = std::min(second, (uint64)cost[i]);
        const unsigned bestCost = cost[best];
        const int xo = r.x + sign * (minDisparity_ + kBest);  // the counterpart's column
        // The alternatives the winner must beat: every candidate further than one pixel away, and "no
        // counterpart (yet)", with the cost of matching against nothing (the window's mass). A winner that
        // only just beats nothing is most often a neighbour of a counterpart that has not arrived yet, off by
        // 2 px. The other side may simply hold more (a more sensitive sensor): against nothing, the larger
        // of the two sides' masses counts (taken only when it can change the outcome).
        const uint64 margin = (uint64)(100 - uniquenessRatio_);
        const auto clearlyBelow = [margin](uint64 cost, uint64 alternative) { return cost * 100 < alternative * margin; };
        const bool last = h >= aggregationWindow_ / 2;
        uint64 nothing = mass;
        if (!clearlyBelow(bestCost, nothing) && (last || clearlyBelow(bestCost, second)))
        {
            int x0 = -h, x1 = h, y0 = -h, y1 = h;
            clipToImage(r, x0, x1, y0, y1);  // the same columns as the costs, never empty (r is inside)
            nothing = std::max(nothing, (uint64)rectMass(other, Point(xo, r.y), x0, x1, y0, y1));
        }
        const uint64 alternative = std::min(second, nothing);
        const bool unique = clearlyBelow(bestCost, alternative);
        // Not unique at the largest window: the temporal prior may decide between the near-equals.
        if (!unique && last && priorTolerance_ > 0 && decideByPrior(c, r, t, bestCost, s, m))
            return m;
        // The aggregation stops when the winner beats every alternative by the uniqueness margin, or at the
        // largest window.
        if (unique || last)
        {
            // Confidence: the share by which the winner beats the best alternative; 0 when the other
            // sensor's own estimates around the counterpart contradict it (left-right check).
            m.confidence = alternative > 0 ? std::max(0.f, (float)(1.0 - (double)bestCost / (double)alternative)) : 0.f;
            double d = minDisparity_ + kBest;
            // Candidates run by disparity: the neighbours, when they are candidates, are next to the best.
            if (lo == best - 1 && hi == best + 1)
            {
                const double cm = cost[best - 1], c0 = bestCost, cp = cost[best + 1];
                const double denom = cm + cp - 2 * c0;
                if (denom > 0)
                    d += std::max(-0.5, std::min(0.5, 0.5 * (cm - cp) / denom));
            }
            m.counterpartX = xo;
            m.disparity = (float)d;
            if (!consistent(1 - c, m.counterpartX, r.y, d, t, s))
                m.confidence = 0.f;
            return m;
        }
        // Iterative aggregation: add the ring one pixel further out.
        h++;
        mass += addRect(self, other, r, -h, h, -h, -h, s);
        mass += addRect(self, other, r, -h, h, h, h, s);
        mass += addRect(self, other, r, -h, -h, -h + 1, h - 1, s);
        mass += addRect(self, other, r, h, h, -h + 1, h - 1, s);
    }
}

// The temporal prior (see match()): this sensor's still active estimates within PRIOR_RADIUS pixels of r, at
// least PRIOR_SUPPORT of them. Their median is the prior; the cheapest candidate within a pixel of it wins when
// its cost is within priorTolerance_ % of the best's, with the share of those estimates that agree with the
// median within a pixel as its confidence. Edges move across the sensor a pixel at a time: what their events
// were matched to a moment ago, nearby, is most often what the next one should be matched to.
bool StereoEventMatcherImpl::decideByPrior(int c, Point r, int64 t, unsigned bestCost, MatchScratch& s, MatchResult& m) const
{
    float prior;
    const size_t support = activeEstimateMedian(c, r, PRIOR_RADIUS, t, s, prior);
    if (support < PRIOR_SUPPORT)
        return false;
    const int* const candidates = s.candidates.data();
    const unsigned* const cost = s.cost.data();
    int chosen = -1;
    for (int i = 0; i < s.count; i++)
        if (std::abs((float)(minDisparity_ + candidates[i]) - prior) <= 1.f && (chosen < 0 || cost[i] < cost[chosen]))
            chosen = i;
    if (chosen < 0 || (uint64)cost[chosen] * 100 > (uint64)bestCost * (uint64)(100 + priorTolerance_))
        return false;
    int agree = 0;  // s.disparities still holds the neighbourhood: consistent() below reuses it
    for (float v : s.disparities)
        agree += std::abs(v - prior) <= 1.f;
    const int d = minDisparity_ + candidates[chosen];
    m.disparity = (float)d;
    m.counterpartX = r.x + (c == CAMERA_LEFT ? -d : d);
    m.confidence = (float)agree / (float)support;
    if (!consistent(1 - c, m.counterpartX, r.y, d, t, s))
        m.confidence = 0.f;
    return true;
}

// Left-right check against the other sensor's own estimates: the active events around the counterpart
// were matched the other way (toward this sensor); when they have disparities, their median must agree
// within one pixel. Without any there is nothing to contradict the match.
bool StereoEventMatcherImpl::consistent(int c, int x, int y, double d, int64 t, MatchScratch& s) const
{
    float median;
    return activeEstimateMedian(c, Point(x, y), 1, t, s, median) == 0 || std::abs(median - d) <= 1.0;
}

// The disparities of sensor c's estimates still active at time t within `radius` pixels of `centre` (into
// s.disparities, in no particular order), their count and, when there are any, their median.
size_t StereoEventMatcherImpl::activeEstimateMedian(int c, Point centre, int radius, int64 t, MatchScratch& s, float& median) const
{
    const std::vector<PixelEstimate>& last = lastEstimate_[c];
    std::vector<float>& disparities = s.disparities;
    disparities.clear();
    const int x0 = std::max(0, centre.x - radius), x1 = std::min(size_.width - 1, centre.x + radius);
    for (int y = std::max(0, centre.y - radius); y <= std::min(size_.height - 1, centre.y + radius); y++)
    {
        const PixelEstimate* row = &last[(size_t)y * size_.width];
        for (int x = x0; x <= x1; x++)
            if (row[x].disparity >= 0 && t < row[x].until)
                disparities.push_back(row[x].disparity);
    }
    if (disparities.empty())
        return 0;
    const size_t mid = disparities.size() / 2;
    std::nth_element(disparities.begin(), disparities.begin() + (std::ptrdiff_t)mid, disparities.end());
    median = disparities[mid];
    return disparities.size();
}

// Median lifetime (and the flow of that event) of the active events of polarity p in the cost window
// around (x, y) of sensor c. False when none has a lifetime.
bool StereoEventMatcherImpl::matchedLifetime(int c, int x, int y, int p, MatchScratch& s, float& lifetime, Vec2f& flow) const
{
    const ZouDescriptorMap& map = maps_[c];
    const int h = costWindow_ / 2;
    // Every pixel is written, and the end advances past those with a lifetime: no branch on the (random)
    // activity pattern. The scratch holds a whole window (sizeScratch()).
    Neighbour* const first = s.neighbours.data();
    Neighbour* end = first;
    const int x0 = std::max(0, x - h), x1 = std::min(size_.width - 1, x + h);
    const float* const lifetimes = map.lifetimes();
    for (int yy = std::max(0, y - h); yy <= std::min(size_.height - 1, y + h); yy++)
    {
        const int i1 = map.lifetimeIndex(x1, yy, p);
        for (int i = map.lifetimeIndex(x0, yy, p); i <= i1; i++)
        {
            const float v = lifetimes[i];
            *end = Neighbour{ v, i };
            end += v > 0;
        }
    }
    if (end == first)
        return false;
    const std::ptrdiff_t mid = (end - first) / 2;
    std::nth_element(first, first + mid, end, [](const Neighbour& a, const Neighbour& b) { return a.lifetime < b.lifetime; });
    const Neighbour& q = first[mid];
    lifetime = q.lifetime;
    flow = map.flowAt(q.index);
    return true;
}

}  // namespace detail
}  // namespace event
}  // namespace cv
