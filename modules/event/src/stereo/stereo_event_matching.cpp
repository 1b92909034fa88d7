// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The matching core of StereoEventMatcher: candidates along the row, descriptor cost with iterative
// aggregation, the winner and its uniqueness, the left-right check and the matched window's lifetime.

#include "precomp.hpp"
#include "stereo/stereo_event_matcher_impl.hpp"
#include "common/prefetch.hpp"


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

// Sum of the descriptor values over [x0, x1] x [y0, y1] relative to q: the cost of matching against nothing.
unsigned StereoEventMatcherImpl::rectMass(const ZouDescriptorMap& map, Point q, int x0, int x1, int y0, int y1) const
{
    // The batch kernel without candidates: it returns the rectangle's mass alone.
    return rectSadBatch_(map.descriptor(q.x + x0, q.y + y0), nullptr, map.descriptorRowStep(), 0, nullptr, 0,
                         x1 - x0 + 1, y1 - y0 + 1, nullptr);
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

// A cost over `seen` of a window's `width` columns, scaled to the whole window (rounded).
inline uint64 scaleToWindow(uint64 cost, int width, int seen)
{
    return seen == width ? cost : (cost * (uint64)width + (uint64)seen / 2) / (uint64)seen;
}

// The share of the neighbourhood's estimates within a pixel of their median: the confidence of an estimate
// the neighbours decide (the temporal prior, an event past the other camera's view).
inline float agreeingShare(const std::vector<float>& disparities, float median)
{
    int agree = 0;
    for (float v : disparities)
        agree += std::abs(v - median) <= 1.f;
    return (float)agree / (float)disparities.size();
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
    const int unseen = sign < 0 ? d - r.x - x0 : x1 - (size_.width - 1 - r.x - d);
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
    const int mostUnseen = unseenColumns(sign, r, x0, x1, minDisparity_ + candidates[n - 1]);
    if (mostUnseen == 0 && columnsAt < 0)
    {
        s.unseenMass[0] = 0;
        return s.cost.data();
    }
    // The event's own mass per unseen column (index j + the largest half-width). The unseen columns are those
    // that the largest disparity maps past the border: their inner end is the same at every window size, and
    // each step adds columns at the outer end. Grown from the previous window by its new columns and the new
    // row at each end of the old ones; once needed, kept up at every step (the unseen columns only grow).
    const int base = aggregationWindow_ / 2;
    unsigned* const columnMass = s.columnMass.data();
    const auto massOfColumn = [&](int j, int ya, int yb) {
        unsigned sum = 0;
        for (int y = ya; y <= yb; y++)
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
        const int unseen = unseenColumns(sign, r, x0, x1, minDisparity_ + candidates[i]);
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
    // The other sensor's event times that the recency cost reads are loaded while the first window is summed.
    const Range recencyColumns = recencyWeight_ > 0 ? recencyColumnRange(sign, r, s) : Range::all();
    if (recencyWeight_ > 0)
        for (int y = std::max(0, r.y - 1); y <= std::min(size_.height - 1, r.y + 1); y++)
        {
            prefetchRange(other.eventTimeRow(y, p) + recencyColumns.start, other.eventTimeRow(y, p) + recencyColumns.end);
            prefetchRange(other.activeRow(y, p) + recencyColumns.start, other.activeRow(y, p) + recencyColumns.end);
        }
    int h = costWindow_ / 2;
    unsigned mass = addRect(self, other, r, -h, h, -h, h, s);
    int columnsAt = -1;
    int priorColumns = -1;  // priorColumnReach(c, r), read once: the flows it reads do not change during match()
    if (recencyWeight_ > 0)
        recencyShares(other, recencyColumns, sign, r, p, t, s);
    for (;;)
    {
        const unsigned* score = scoreSeenColumns(self, sign, r, h, columnsAt, s);
        const bool allColumnsSeen = score == cost;
        // Each candidate pays its share of recencyWeight_ % of the window's mass (its cost against nothing), so
        // that the recency cost keeps its weight as the aggregation grows the window.
        const double recencyFullCost = (double)mass * recencyWeight_ / 100.0;
        const auto recencyCost = [&](int i) { return (uint64)std::lround(recencyFullCost * s.recencyShare[(size_t)i]); };
        if (recencyWeight_ > 0)
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
        const int xo = r.x + sign * (minDisparity_ + kBest);  // the counterpart's column
        int x0 = -h, x1 = h, y0 = -h, y1 = h;
        clipToImage(r, x0, x1, y0, y1);  // the costs' columns, never empty (r is inside)
        const int width = x1 - x0 + 1;
        const int seen = width - (allColumnsSeen ? 0 : unseenColumns(sign, r, x0, x1, minDisparity_ + kBest));
        // The alternatives the winner must beat: every candidate further than one pixel away, and "no
        // counterpart (yet)", with the cost of matching against nothing (the window's mass). A winner that
        // only just beats nothing is most often a neighbour of a counterpart that has not arrived yet, off by
        // 2 px. The other side may simply hold more (a more sensitive sensor): against nothing, the larger
        // of the two sides' masses counts (taken only when it can change the outcome).
        const uint64 margin = (uint64)(100 - uniquenessRatio_);
        const auto clearlyBelow = [margin](uint64 cost, uint64 alternative) { return cost * 100 < alternative * margin; };
        const bool last = h >= aggregationWindow_ / 2;
        // Both masses over the columns the other sensor sees at the winner, scaled like its score (the other
        // sensor's descriptors past its border are zero).
        uint64 nothing = scaleToWindow(mass - s.unseenMass[(size_t)(width - seen)], width, seen);
        if (!clearlyBelow(bestCost, nothing) && (last || clearlyBelow(bestCost, second)))
            nothing = std::max(nothing, scaleToWindow(rectMass(other, Point(xo, r.y), x0, x1, y0, y1), width, seen));
        // Against nothing the winner's descriptors count alone: a counterpart that fires a little apart in time is
        // still there, so its recency cost is added to nothing's as well.
        if (recencyWeight_ > 0)
            nothing += recencyCost(best);
        const uint64 alternative = std::min(second, nothing);
        const bool unique = clearlyBelow(bestCost, alternative);
        // Not unique: the temporal prior may decide between the near-equals at the largest window, and on a
        // horizontal edge already at the first one. Along such an edge the candidates on the other sensor's copy
        // of it cost about the same at every window size (only the edge's ends, far away, tell them apart), so
        // growing the window seldom decides, while it costs such an event several times a first window's work.
        if (!unique && priorTolerance_ > 0 && (last || h == costWindow_ / 2))
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
            double d = minDisparity_ + kBest;
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
    const int xFirst = r.x + sign * (minDisparity_ + s.candidates[0]);
    const int xLast = r.x + sign * (minDisparity_ + s.candidates[(size_t)s.count - 1]);
    return Range(std::max(0, std::min(xFirst, xLast) - 1), std::min(size_.width, std::max(xFirst, xLast) + 2));
}

// An edge's events fire in both sensors at about the same time; the trail another edge left a while ago (a
// slower one: a torso behind a swinging leg, a pole behind a passing box) can match the window's layout as well
// or better, but not the moment. A candidate's share of the recency cost grows with the time between the event
// and the other sensor's active event nearest to it in time within a pixel of the candidate: 0 for none, 1
// from recencyTime_ on, and 1 where no event is active within a pixel (a candidate needs structure only
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
    for (int y = std::max(0, r.y - 1); y <= std::min(size_.height - 1, r.y + 1); y++)
    {
        const uchar* const active = other.activeRow(y, p);
        const int64* const times = other.eventTimeRow(y, p);
        // |t - time| in unsigned arithmetic: exact for any two int64 times, without overflow.
        for (int x = x0; x <= x1; x++)
        {
            const uint64 apart = t >= times[x] ? (uint64)t - (uint64)times[x] : (uint64)times[x] - (uint64)t;
            gap[x] = std::min(gap[x], active[x] ? apart : std::numeric_limits<uint64>::max());
        }
    }
    float* const share = s.recencyShare.data();
    for (int i = 0; i < n; i++)
    {
        const int x = r.x + sign * (minDisparity_ + candidates[i]);
        const uint64 nearest = std::min(gap[x], std::min(gap[std::max(x0, x - 1)], gap[std::min(x1, x + 1)]));
        share[i] = nearest >= (uint64)recencyTime_ ? 1.f : (float)((double)nearest / (double)recencyTime_);
    }
}

// The temporal prior (see match()): this sensor's still active estimates within PRIOR_RADIUS rows and `columns`
// columns of r, at least PRIOR_SUPPORT of them. Their median is the prior; the cheapest candidate within a pixel
// of it wins when its cost is within priorTolerance_ % of the best's, with the share of those estimates that
// agree with the median within a pixel as its confidence. Edges move across the sensor a pixel at a time: what their events
// were matched to a moment ago, nearby, is most often what the next one should be matched to.
bool StereoEventMatcherImpl::decideByPrior(int c, Point r, int p, int64 t, int columns, const unsigned* score, unsigned bestCost, MatchScratch& s,
                                           MatchResult& m) const
{
    float prior;
    const size_t support = activeEstimateMedian(c, r, PRIOR_RADIUS, columns, t, s, prior);
    if (support < PRIOR_SUPPORT)
        return false;
    const int* const candidates = s.candidates.data();
    int chosen = -1;
    for (int i = 0; i < s.count; i++)
        if (std::abs((float)(minDisparity_ + candidates[i]) - prior) <= 1.f && (chosen < 0 || score[i] < score[chosen]))
            chosen = i;
    if (chosen < 0 || (uint64)score[chosen] * 100 > (uint64)bestCost * (uint64)(100 + priorTolerance_))
        return false;
    const int d = minDisparity_ + candidates[chosen];
    m.disparity = (float)d;
    m.counterpartX = r.x + (c == CAMERA_LEFT ? -d : d);
    m.confidence = agreeingShare(s.disparities, prior);  // before consistent() below refills s.disparities
    prefetchMatchedWindow(1 - c, m.counterpartX, r.y, p);
    if (!consistent(1 - c, m.counterpartX, r.y, d, t, s))
        m.confidence = 0.f;
    return true;
}

// Along a horizontal edge every candidate on the other sensor's copy of the edge costs about the same: only
// the edge's ends tell them apart, and an event far from both stays ambiguous, as do its neighbours, so that
// the prior's 11 x 11 neighbourhood holds no estimates or only the ends' wrong ones. On such an edge the prior
// reads 30 px to each side along the row, the width of the largest cost window at its default, to reach the
// edge's corners and the vertical edges at its ends. The edge's direction comes from the normal flow of the
// active events around the event (both polarities): mostly vertical flow is a horizontal edge. Its rows stay
// PRIOR_RADIUS, so that the row bands' reach is unchanged.
int StereoEventMatcherImpl::priorColumnReach(int c, Point r) const
{
    const ZouDescriptorMap& map = maps_[c];
    float across = 0, along = 0;  // |flow x|, |flow y| summed
    for (int p = 0; p < 2; p++)
        for (int y = std::max(0, r.y - 1); y <= std::min(size_.height - 1, r.y + 1); y++)
            for (int x = std::max(0, r.x - 1); x <= std::min(size_.width - 1, r.x + 1); x++)
                if (map.isActive(x, y, p))
                {
                    const Vec2f f = map.flow(x, y, p);
                    across += std::abs(f[0]);
                    along += std::abs(f[1]);
                }
    return along > across ? (int)PRIOR_ROW_REACH : (int)PRIOR_RADIUS;
}

// A near object's first columns in the left image (its last ones in the right image) lie past the other
// camera's view: no counterpart exists, and a candidate found there is another scene point. The estimates
// around the event tell where it lies: when their median puts the counterpart past the border, it is the
// event's disparity. It reads as far along the row as the prior on a horizontal edge, to reach the part of
// the object both cameras see; its estimate counts for the next events nearer the border.
bool StereoEventMatcherImpl::estimateBeyondView(int c, Point r, int64 t, MatchScratch& s, MatchResult& m) const
{
    // The estimates run up to maxDisparity_ + 0.5 (sub-pixel): further from the border, every one lies inside.
    const int fromBorder = c == CAMERA_LEFT ? r.x : size_.width - 1 - r.x;
    if (fromBorder > maxDisparity_)
        return false;
    float prior;
    const size_t support = activeEstimateMedian(c, r, PRIOR_RADIUS, PRIOR_ROW_REACH, t, s, prior);
    if (support < PRIOR_SUPPORT || cvRound(prior) <= fromBorder)
        return false;
    m.disparity = prior;
    m.confidence = agreeingShare(s.disparities, prior);
    m.flags = STEREO_BEYOND_VIEW;
    return true;
}

// Left-right check against the other sensor's own estimates: the active events around the counterpart
// were matched the other way (toward this sensor); when they have disparities, their median must agree
// within one pixel. Without any there is nothing to contradict the match.
bool StereoEventMatcherImpl::consistent(int c, int x, int y, double d, int64 t, MatchScratch& s) const
{
    float median;
    return activeEstimateMedian(c, Point(x, y), 1, 1, t, s, median) == 0 || std::abs(median - d) <= 1.0;
}

// The disparities of sensor c's estimates still active at time t within `radius` rows and `columns` columns of
// `centre` (into s.disparities, in no particular order), their count and, when there are any, their median.
size_t StereoEventMatcherImpl::activeEstimateMedian(int c, Point centre, int radius, int columns, int64 t,
                                                    MatchScratch& s, float& median) const
{
    std::vector<float>& disparities = s.disparities;
    disparities.clear();
    forEachActiveEstimate(c, centre.x - columns, centre.x + columns, centre.y - radius, centre.y + radius, t,
                          [&disparities](float d) { disparities.push_back(d); });
    if (disparities.empty())
        return 0;
    const size_t mid = disparities.size() / 2;
    std::nth_element(disparities.begin(), disparities.begin() + (std::ptrdiff_t)mid, disparities.end());
    median = disparities[mid];
    return disparities.size();
}

float StereoEventMatcherImpl::averagedDisparity(int c, Point r, int64 t, float own, int counterpartX) const
{
    double sum = own;
    int n = 1;
    const int radius = averagingRadius_;
    // This sensor's estimates around the event, then the other's around its counterpart (same rows: rectified).
    for (int side = 0; side < (counterpartX >= 0 ? 2 : 1); side++)
    {
        const int centreX = side == 0 ? r.x : counterpartX;
        forEachActiveEstimate(side == 0 ? c : 1 - c, centreX - radius, centreX + radius, r.y - radius, r.y + radius, t,
                              [&](float d) {
                                  if (std::abs(d - own) <= AVERAGING_TOLERANCE)
                                  {
                                      sum += d;
                                      n++;
                                  }
                              });
    }
    return (float)(sum / n);
}

Rect StereoEventMatcherImpl::lifetimeWindowAround(int x, int y) const
{
    const int h = lifetimeWindow_ / 2;
    return Rect(Point(x - h, y - h), Point(x + h + 1, y + h + 1)) & Rect(Point(), size_);
}

void StereoEventMatcherImpl::prefetchMatchedWindow(int c, int x, int y, int p) const
{
    if (mode_ != STEREO_COUPLED)
        return;
    const Rect w = lifetimeWindowAround(x, y);
    maps_[c].prefetchLifetimes(w.x, w.x + w.width - 1, w.y, w.y + w.height - 1, p);
}

// Median lifetime (and the flow of that event) of the active events of polarity p in the lifetime window
// around (x, y) of sensor c. False when none has a lifetime.
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
