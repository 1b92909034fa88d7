// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Matching one event along its row: the candidates, the descriptor cost with iterative aggregation (costs
// past the other image's border scored on the seen columns), the recency cost, the winner, its uniqueness and
// its sub-pixel refinement.

#include "precomp.hpp"
#include "common/prefetch.hpp"
#include "stereo/stereo_event_matcher_impl.hpp"

namespace cv {
namespace event {
namespace detail {

unsigned StereoEventMatcherImpl::addRect(const ZouDescriptorMap& self, const ZouDescriptorMap& other, Point r, int x0, int x1, int y0, int y1,
                 MatchScratch& s) const
{
    if (!clipToImage(r, x0, x1, y0, y1))
        return 0;
    const int rows = sampleRows(y0, y1);
    if (rows == 0)
        return 0;
    const size_t k = (size_t)params_.costRowStep;
    // Candidate i's rectangle is this one shifted by its disparity along the row: offsets[i] bytes.
    return rectSadBatch_(self.descriptor(r.x + x0, r.y + y0), other.descriptor(r.x + x0, r.y + y0),
                         k * self.descriptorRowStep(), k * other.descriptorRowStep(), s.offsets.data(),
                         s.count, x1 - x0 + 1, rows, s.cost.data());
}

unsigned StereoEventMatcherImpl::rectMass(const ZouDescriptorMap& map, Point q, int x0, int x1, int y0, int y1) const
{
    const int rows = sampleRows(y0, y1);
    if (rows == 0)
        return 0;
    // The batch kernel without candidates: it returns the rectangle's mass alone.
    return rectSadBatch_(map.descriptor(q.x + x0, q.y + y0), nullptr, (size_t)params_.costRowStep * map.descriptorRowStep(),
                         0, nullptr, 0, x1 - x0 + 1, rows, nullptr);
}

namespace {

// The sum of one descriptor's counts: its SAD against nothing. Eight counts at a time: pairs of bytes into 16-bit
// lanes, then the four lanes by one multiplication (a descriptor's 24 counts sum to far below 65536).
inline unsigned descriptorMass(const uchar* d)
{
    static_assert(ZouDescriptorMap::DESCRIPTOR_BYTES == 24, "three 8-byte words per descriptor");
    const uint64 bytes = 0x00FF00FF00FF00FFull, lanes = 0x0001000100010001ull;
    uint64 sum = 0;
    for (int w = 0; w < 3; w++)
    {
        uint64 v;
        std::memcpy(&v, d + 8 * w, sizeof(v));
        sum += (v & bytes) + ((v >> 8) & bytes);
    }
    return (unsigned)((sum * lanes) >> 48);
}

// std::lround of a non-negative x below 2^53 without a library call (one per candidate and window size): its whole
// part converts exactly, and so does the fraction x minus it, so halves round up as lround rounds them.
inline uint64 roundNonNegative(double x)
{
    CV_DbgAssert(x >= 0 && x < 0x1p53);
    const uint64 whole = (uint64)x;
    return whole + (uint64)(x - (double)whole >= 0.5);
}

// A cost over `seen` of a window's `width` columns, scaled to the whole window (rounded).
inline uint64 scaleToWindow(uint64 cost, int width, int seen)
{
    return seen == width ? cost : (cost * (uint64)width + (uint64)seen / 2) / (uint64)seen;
}

// The sub-pixel offset of the cost minimum c0 from its neighbours' costs cm (one pixel less) and cp (one
// more), in [-0.5, 0.5]: two lines of equal and opposite slope through the three (equiangular fit). A SAD
// grows linearly with a small shift, so its minimum is a V, not a parabola: a parabola pulls the estimates
// towards whole pixels (by up to 0.06 px on a plane at fractional disparities), the V does not.
inline double subPixelOffset(double cm, double c0, double cp)
{
    const double rise = std::max(cm, cp) - c0;
    if (!(rise > 0))
        return 0;
    return std::max(-0.5, std::min(0.5, 0.5 * (cm - cp) / rise));
}

}  // namespace

int StereoEventMatcherImpl::unseenColumns(int sign, Point r, int x0, int x1, int d) const
{
    // Column j of the window is column r.x + j + sign * d of the other image.
    const int unseen = sign < 0 ? d - r.x - x0 : x1 - (params_.sensorSize.width - 1 - r.x - d);
    return std::max(0, std::min(x1 - x0 + 1, unseen));
}

// Near the other image's border, a candidate's window runs partly past it, where the other sensor's descriptors
// are zero: there its cost is the event's own mass whatever the scene, which would favour the candidates whose
// window stays inside (the smaller disparities) and weigh every candidate against "nothing" unfairly. Such a
// candidate is scored on the columns the other sensor sees, scaled to the whole window, so that all candidates
// and "nothing" are compared per column. The candidates run by disparity and the unseen columns grow with it:
// those with unseen columns are the last ones.
const unsigned* StereoEventMatcherImpl::scoreSeenColumns(const ZouDescriptorMap& self, int sign, Point r, int h,
                                                         int& columnsAt, MatchScratch& s) const
{
    const int n = s.count;
    const int* const candidates = s.candidates.data();
    int x0 = -h, x1 = h, y0 = -h, y1 = h;
    clipToImage(r, x0, x1, y0, y1);
    const int width = x1 - x0 + 1;
    const int mostUnseen = unseenColumns(sign, r, x0, x1, params_.minDisparity + candidates[n - 1]);
    if (mostUnseen == 0 && columnsAt < 0)
    {
        s.unseenMass[0] = 0;
        return s.cost.data();
    }
    // The event's own mass per unseen column (index j + the largest half-width). The unseen columns are those
    // that the largest disparity maps past the border: their inner end is the same at every window size, and
    // each step adds columns at the outer end. Grown from the previous window by its new columns and the new
    // row at each end of the old ones; once needed, kept up at every step (the unseen columns only grow).
    const int base = params_.aggregationWindow / 2;
    unsigned* const columnMass = s.columnMass.data();
    const auto massOfColumn = [&](int j, int ya, int yb) {
        unsigned sum = 0;
        if (sampleRows(ya, yb) > 0)
            for (int y = ya; y <= yb; y += params_.costRowStep)
                sum += descriptorMass(self.descriptor(r.x + j, r.y + y));
        return sum;
    };
    int px0 = 0, px1 = -1, py0 = 0, py1 = -1;  // the previous window, empty when there is none
    if (columnsAt >= 0)
    {
        CV_DbgAssert(columnsAt == h - 1);
        px0 = -columnsAt, px1 = columnsAt, py0 = -columnsAt, py1 = columnsAt;
        clipToImage(r, px0, px1, py0, py1);
    }
    const int firstUnseen = sign < 0 ? x0 : x1 - mostUnseen + 1;
    for (int j = firstUnseen; j < firstUnseen + mostUnseen; j++)
    {
        unsigned& m = columnMass[j + base];
        if (j < px0 || j > px1)
            m = massOfColumn(j, y0, y1);
        else
            m += (y0 < py0 ? massOfColumn(j, y0, y0) : 0u) + (y1 > py1 ? massOfColumn(j, y1, y1) : 0u);
    }
    columnsAt = h;
    // The mass of the first k unseen columns, from the window's left end (left camera) or its right end.
    unsigned* const unseenMass = s.unseenMass.data();
    unseenMass[0] = 0;
    for (int k = 1; k <= mostUnseen; k++)
        unseenMass[k] = unseenMass[k - 1] + columnMass[(sign < 0 ? x0 + k - 1 : x1 - k + 1) + base];
    const unsigned* const cost = s.cost.data();
    unsigned* const score = s.seenScore.data();
    for (int i = n - 1; i >= 0; i--)
    {
        const int unseen = unseenColumns(sign, r, x0, x1, params_.minDisparity + candidates[i]);
        if (unseen == 0)
        {
            std::copy(cost, cost + i + 1, score);
            break;
        }
        // A candidate's centre column lies in the other image, so it sees at least one column. Its cost over
        // the unseen columns is their mass exactly (SAD against zeros).
        CV_DbgAssert(unseen < width && cost[i] >= unseenMass[unseen]);
        score[i] = (unsigned)std::min<uint64>(std::numeric_limits<unsigned>::max(),
                                              scaleToWindow(cost[i] - unseenMass[unseen], width, width - unseen));
    }
    return score;
}

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
    const int kEnd = std::min(params_.maxDisparity, sign < 0 ? r.x : params_.sensorSize.width - 1 - r.x) - params_.minDisparity + 1;
    const uchar* structure = other.nearestRow(r.y, p);
    const int x0 = r.x + sign * params_.minDisparity;
    const ptrdiff_t offsetStep = (ptrdiff_t)sign * ZouDescriptorMap::DESCRIPTOR_BYTES;
    int n = 0;
    for (int k = 0; k < kEnd; k++)
    {
        candidates[n] = k;
        n += structure[x0 + sign * k] != ZouDescriptorMap::NONE;
    }
    for (int i = 0; i < n; i++)
        offsets[i] = (params_.minDisparity + candidates[i]) * offsetStep;
    s.count = n;
    if (n == 0)
    {
        m.flags = STEREO_NO_COUNTERPART;
        return m;
    }
    std::fill_n(cost, n, 0u);
    // The other sensor's event times that the recency cost reads are loaded while the first window is summed.
    const Range recencyColumns = params_.recencyWeight > 0 ? recencyColumnRange(sign, r, s) : Range::all();
    if (params_.recencyWeight > 0)
        for (int y = std::max(0, r.y - 1); y <= std::min(params_.sensorSize.height - 1, r.y + 1); y++)
        {
            prefetchRange(other.eventTimeRow(y, p) + recencyColumns.start, other.eventTimeRow(y, p) + recencyColumns.end);
            prefetchRange(other.activeRow(y, p) + recencyColumns.start, other.activeRow(y, p) + recencyColumns.end);
        }
    int h = params_.costWindow / 2;
    unsigned mass = addRect(self, other, r, -h, h, -h, h, s);
    int columnsAt = -1;
    int priorColumns = -1;  // priorColumnReach(c, r), read once: the flows it reads do not change during match()
    if (params_.recencyWeight > 0)
        recencyShares(other, recencyColumns, sign, r, p, t, s);
    for (;;)
    {
        const unsigned* score = scoreSeenColumns(self, sign, r, h, columnsAt, s);
        const bool allColumnsSeen = score == cost;
        // Each candidate pays its share of params_.recencyWeight % of the window's mass (its cost against nothing), so
        // that the recency cost keeps its weight as the aggregation grows the window.
        const double recencyFullCost = (double)mass * params_.recencyWeight / 100.0;
        const auto recencyCost = [&](int i) { return roundNonNegative(recencyFullCost * s.recencyShare[(size_t)i]); };
        if (params_.recencyWeight > 0)
        {
            // Into s.seenScore: in place where scoreSeenColumns put the scores there.
            unsigned* const withRecency = s.seenScore.data();
            for (int i = 0; i < n; i++)
                withRecency[i] = (unsigned)std::min<uint64>(std::numeric_limits<unsigned>::max(), (uint64)score[i] + recencyCost(i));
            score = withRecency;
        }
        int best = 0;  // index into candidates, which run by disparity: ties go to the smaller disparity
        for (int i = 1; i < n; i++)
            if (score[i] < score[best])
                best = i;
        const int kBest = candidates[best];
        // The candidates within one pixel of the best are next to it (they run by disparity, one each):
        // the runner-up is the cheapest outside [lo, hi].
        const int lo = best > 0 && candidates[best - 1] == kBest - 1 ? best - 1 : best;
        const int hi = best < n - 1 && candidates[best + 1] == kBest + 1 ? best + 1 : best;
        uint64 second = std::numeric_limits<uint64>::max();
        for (int i = 0; i < lo; i++)
            second = std::min(second, (uint64)score[i]);
        for (int i = hi + 1; i < n; i++)
            second = std::min(second, (uint64)score[i]);
        const unsigned bestCost = score[best];
        const int xo = r.x + sign * (params_.minDisparity + kBest);  // the counterpart's column
        int x0 = -h, x1 = h, y0 = -h, y1 = h;
        clipToImage(r, x0, x1, y0, y1);  // the costs' columns, never empty (r is inside)
        const int width = x1 - x0 + 1;
        const int seen = width - (allColumnsSeen ? 0 : unseenColumns(sign, r, x0, x1, params_.minDisparity + kBest));
        // The alternatives the winner must beat: every candidate further than one pixel away, and "no
        // counterpart (yet)", with the cost of matching against nothing (the window's mass). A winner that
        // only just beats nothing is most often a neighbour of a counterpart that has not arrived yet, off by
        // 2 px. The other side may simply hold more (a more sensitive sensor): against nothing, the larger
        // of the two sides' masses counts (taken only when it can change the outcome).
        const uint64 margin = (uint64)(100 - params_.uniquenessRatio);
        const auto clearlyBelow = [margin](uint64 cost, uint64 alternative) { return cost * 100 < alternative * margin; };
        const bool last = h >= params_.aggregationWindow / 2;
        // Both masses over the columns the other sensor sees at the winner, scaled like its score (the other
        // sensor's descriptors past its border are zero).
        uint64 nothing = scaleToWindow(mass - s.unseenMass[(size_t)(width - seen)], width, seen);
        if (!clearlyBelow(bestCost, nothing) && (last || clearlyBelow(bestCost, second)))
            nothing = std::max(nothing, scaleToWindow(rectMass(other, Point(xo, r.y), x0, x1, y0, y1), width, seen));
        // Against nothing the winner's descriptors count alone: a counterpart that fires a little apart in time is
        // still there, so its recency cost is added to nothing's as well.
        if (params_.recencyWeight > 0)
            nothing += recencyCost(best);
        const uint64 alternative = std::min(second, nothing);
        const bool unique = clearlyBelow(bestCost, alternative);
        // Not unique: the temporal prior may decide between the near-equals at the largest window, and on a
        // horizontal edge already at the first one. Along such an edge the candidates on the other sensor's copy
        // of it cost about the same at every window size (only the edge's ends, far away, tell them apart), so
        // growing the window seldom decides, while it costs such an event several times a first window's work.
        if (!unique && params_.priorTolerance > 0 && (last || h == params_.costWindow / 2))
        {
            if (priorColumns < 0)
                priorColumns = priorColumnReach(c, r);
            if ((last || priorColumns == (int)PRIOR_ROW_REACH)
                && decideByPrior(c, r, p, t, priorColumns, score, bestCost, s, m))
                return m;
        }
        // The aggregation stops when the winner beats every alternative by the uniqueness margin, or at the
        // largest window.
        if (unique || last)
        {
            // Confidence: the share by which the winner beats the best alternative; 0 when the other
            // sensor's own estimates around the counterpart contradict it (left-right check).
            m.confidence = alternative > 0 ? std::max(0.f, (float)(1.0 - (double)bestCost / (double)alternative)) : 0.f;
            double d = params_.minDisparity + kBest;
            // Candidates run by disparity: the neighbours, when they are candidates, are next to the best.
            if (lo == best - 1 && hi == best + 1)
                d += subPixelOffset(score[best - 1], bestCost, score[best + 1]);
            m.counterpartX = xo;
            m.disparity = (float)d;
            prefetchMatchedWindow(1 - c, xo, r.y, p);
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

Range StereoEventMatcherImpl::recencyColumnRange(int sign, Point r, const MatchScratch& s) const
{
    // The candidates' columns run from r.x + sign * (min + candidates[0]) to that of the last.
    const int xFirst = r.x + sign * (params_.minDisparity + s.candidates[0]);
    const int xLast = r.x + sign * (params_.minDisparity + s.candidates[(size_t)s.count - 1]);
    return Range(std::max(0, std::min(xFirst, xLast) - 1), std::min(params_.sensorSize.width, std::max(xFirst, xLast) + 2));
}

// An edge's events fire in both sensors at about the same time; the trail another edge left a while ago (a
// slower one: a torso behind a swinging leg, a pole behind a passing box) can match the window's layout as well
// or better, but not the moment. A candidate's share of the recency cost grows with the time between the event
// and the other sensor's active event nearest to it in time within a pixel of the candidate: 0 for none, 1
// from params_.recencyTime on, and 1 where no event is active within a pixel (a candidate needs structure only
// within the maximum vector length). The candidates' 3 x 3 neighbourhoods overlap: the three rows' smallest
// gap is taken once per column, then the smallest of three columns per candidate.
void StereoEventMatcherImpl::recencyShares(const ZouDescriptorMap& other, const Range& columns, int sign, Point r, int p,
                                           int64 t, MatchScratch& s) const
{
    const int n = s.count;
    const int* const candidates = s.candidates.data();
    const int x0 = columns.start, x1 = columns.end - 1;
    uint64* const gap = s.columnTimeGap.data();
    std::fill(gap + x0, gap + x1 + 1, std::numeric_limits<uint64>::max());
    for (int y = std::max(0, r.y - 1); y <= std::min(params_.sensorSize.height - 1, r.y + 1); y++)
    {
        const uchar* const active = other.activeRow(y, p);
        const int64* const times = other.eventTimeRow(y, p);
        // |t - time| in unsigned arithmetic: exact for any two int64 times, without overflow. An inactive pixel's
        // gap is all ones (the largest) by a mask, not a branch: which pixels are active is random.
        for (int x = x0; x <= x1; x++)
        {
            const uint64 apart = t >= times[x] ? (uint64)t - (uint64)times[x] : (uint64)times[x] - (uint64)t;
            gap[x] = std::min(gap[x], apart | ((uint64)(active[x] == 0) * std::numeric_limits<uint64>::max()));
        }
    }
    float* const share = s.recencyShare.data();
    for (int i = 0; i < n; i++)
    {
        const int x = r.x + sign * (params_.minDisparity + candidates[i]);
        const uint64 nearest = std::min(gap[x], std::min(gap[std::max(x0, x - 1)], gap[std::min(x1, x + 1)]));
        // Capped at recencyTime (at most 1e6 us) first: the share is then 1 there exactly, without a branch.
        const int64 capped = (int64)std::min(nearest, (uint64)params_.recencyTime);
        share[i] = (float)((double)capped / (double)params_.recencyTime);
    }
}

}  // namespace detail
}  // namespace event
}  // namespace cv
