// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// What the neighbours' own estimates decide for an event: the temporal prior where the cost has no unique
// winner, the estimate past the other image's border, the left-right check, the averaged output and the
// filled one.

#include "precomp.hpp"
#include "stereo/stereo_event_matcher_impl.hpp"

namespace cv {
namespace event {
namespace detail {

namespace {

// The share of the neighbourhood's estimates within a pixel of their median: the confidence of an estimate
// the neighbours decide (the temporal prior, an event past the other camera's view).
inline float agreeingShare(const std::vector<float>& disparities, float median)
{
    int agree = 0;
    for (float v : disparities)
        agree += std::abs(v - median) <= 1.f;
    return (float)agree / (float)disparities.size();
}

}  // namespace

// The temporal prior (see match()): this sensor's still active estimates within PRIOR_RADIUS rows and `columns`
// columns of r, at least PRIOR_SUPPORT of them. Their median is the prior; the cheapest candidate within a pixel
// of it wins when its cost is within params_.priorTolerance % of the best's, with the share of those estimates that
// agree with the median within a pixel as its confidence. Edges move across the sensor a pixel at a time: what their events
// were matched to a moment ago, nearby, is most often what the next one should be matched to.
bool StereoEventMatcherImpl::decideByPrior(int c, Point r, int p, int64 t, int columns, const unsigned* score, unsigned bestCost, MatchScratch& s,
                                           MatchResult& m) const
{
    float prior;
    const size_t support = estimates_[c].median(r, PRIOR_RADIUS, columns, t, s.disparities, prior);
    if (support < PRIOR_SUPPORT)
        return false;
    const int* const candidates = s.candidates.data();
    int chosen = -1;
    for (int i = 0; i < s.count; i++)
        if (std::abs((float)(params_.minDisparity + candidates[i]) - prior) <= 1.f && (chosen < 0 || score[i] < score[chosen]))
            chosen = i;
    if (chosen < 0 || (uint64)score[chosen] * 100 > (uint64)bestCost * (uint64)(100 + params_.priorTolerance))
        return false;
    const int d = params_.minDisparity + candidates[chosen];
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
        for (int y = std::max(0, r.y - 1); y <= std::min(params_.sensorSize.height - 1, r.y + 1); y++)
            for (int x = std::max(0, r.x - 1); x <= std::min(params_.sensorSize.width - 1, r.x + 1); x++)
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
    // The estimates run up to params_.maxDisparity + 0.5 (sub-pixel): further from the border, every one lies inside.
    const int fromBorder = c == CAMERA_LEFT ? r.x : params_.sensorSize.width - 1 - r.x;
    if (fromBorder > params_.maxDisparity)
        return false;
    float prior;
    const size_t support = estimates_[c].median(r, PRIOR_RADIUS, PRIOR_ROW_REACH, t, s.disparities, prior);
    if (support < PRIOR_SUPPORT || cvRound(prior) <= fromBorder)
        return false;
    m.disparity = prior;
    m.confidence = agreeingShare(s.disparities, prior);
    m.flags = STEREO_BEYOND_VIEW;
    return true;
}

bool StereoEventMatcherImpl::consistent(int c, int x, int y, double d, int64 t, MatchScratch& s) const
{
    float median;
    return estimates_[c].median(Point(x, y), 1, 1, t, s.disparities, median) == 0 || std::abs(median - d) <= 1.0;
}

float StereoEventMatcherImpl::averagedDisparity(int c, Point r, int64 t, float own, int counterpartX) const
{
    double sum = own;
    int n = 1;
    const int radius = params_.averagingRadius;
    // This sensor's estimates around the event, then the other's around its counterpart (same rows: rectified).
    for (int side = 0; side < (counterpartX >= 0 ? 2 : 1); side++)
    {
        const int centreX = side == 0 ? r.x : counterpartX;
        estimates_[side == 0 ? c : 1 - c].sumNear(centreX - radius, centreX + radius, r.y - radius, r.y + radius, t, own,
                                                  AVERAGING_TOLERANCE, sum, n);
    }
    return (float)(sum / n);
}

// One camera may not see an edge the other sees (a weaker sensor; an outline against a background that
// differs between the views): its events there have no counterpart and match something else, nothing, or a
// neighbouring edge a pixel or two off. The confident estimates of the surface around them, over the last
// FILL_TIME, say where they are. Only the events' own estimates support it, never filled ones, so that a fill
// does not spread by itself.
bool StereoEventMatcherImpl::filledDisparity(int c, Point r, int64 t, MatchScratch& s, float own, float confidence,
                                             float& disparity)
{
    const int radius = params_.fillRadius;
    if (radius == 0)
        return false;
    const FillSurfaceCache::Surface surface = fillSurface(c, r, t, s);
    const float median = surface.median, agreeing = surface.agreeing;
    if (surface.support < FILL_SUPPORT || agreeing < FILL_AGREEING)
        return false;
    const float gap = std::abs(own - median);
    if (own >= 0 && confidence >= FILL_BELOW_CONFIDENCE && gap > FILL_REFINE_GAP)
    {
        // Apart from the surface: replaced only where the surface is clearly one (most of it within a pixel),
        // and kept where the events of a narrow band around it agree with it (a pole, a limb in front of the
        // body).
        if (gap <= FILL_OUTLIER_GAP || agreeing < FILL_OUTLIER_AGREEING)
            return false;
        float narrow = 0;
        if (confidentEstimates_[c].median(r, radius, FILL_NARROW_COLUMNS, t, s.disparities, narrow) >= (size_t)FILL_NARROW_SUPPORT &&
            std::abs(narrow - own) <= 1.f)
            return false;
    }
    disparity = median;
    return true;
}

FillSurfaceCache::Surface StereoEventMatcherImpl::fillSurface(int c, Point r, int64 t, MatchScratch& s)
{
    // The events of an edge fire close together, and the surfaces of neighbours a few pixels and milliseconds
    // apart are nearly the same (at the defaults, a 41 x 41 window moved by a fifth of its radius at most). Only
    // a surface that could fill is reused, so that one found before the estimates around it arrived does not
    // hold them off.
    const FillSurfaceCache::Surface* found = fillSurfaces_[c].find(r, t, params_.fillReuseTime, FILL_SUPPORT);
    if (found)
        return *found;
    FillSurfaceCache::Surface surface{ t, 0.f, 0.f, 0 };
    // Every other row: an edge's estimates repeat from row to row, and the window's scan is what filling costs.
    const int radius = params_.fillRadius;
    surface.support = (int)confidentEstimates_[c].sampledMedian(r, radius, radius, FILL_ROW_STEP, t, s.disparities,
                                                                surface.median);
    if (surface.support >= FILL_SUPPORT)
        surface.agreeing = agreeingShare(s.disparities, surface.median);
    if (params_.fillReuseTime > 0)
        fillSurfaces_[c].store(r, surface);
    return surface;
}

void StereoEventMatcherImpl::rememberConfident(int c, Point r, int64 t, float disparity, float confidence)
{
    if (params_.fillRadius > 0 && disparity >= 0 && confidence >= FILL_SUPPORT_CONFIDENCE)
        confidentEstimates_[c].remember(r, t, FILL_TIME, disparity);
}

}  // namespace detail
}  // namespace event
}  // namespace cv
