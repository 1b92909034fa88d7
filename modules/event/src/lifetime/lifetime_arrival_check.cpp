// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// LifetimeArrivalCheck: when the edge of an event really reaches the next pixel, over when its lifetime says.

#include "precomp.hpp"
#include "lifetime/neighbour_along_motion.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <limits>

namespace cv {
namespace event {
namespace detail {
namespace {

const int64 kNone = std::numeric_limits<int64>::min();

// Ratios in geometric bins 1 % wide from 1e-3 to 1e3; bin 0 holds everything below, the last everything above.
const double kBinRatio = 1.01;
const double kLowestRatio = 1e-3, kHighestRatio = 1e3;
const int kBins = 1390;  // ln(1e6) / ln(1.01) = 1388.5, plus the two open ends

// The events that pointed at one pixel (and polarity) since it last fired: up to kClaims, the oldest dropped.
// Each event claims two pixels along its flow, the neighbour and the pixel beyond it; the claim at one names
// the other (its partner, as an offset from this pixel) so that only the first of the two to settle it counts.
struct Claim
{
    int64 t;                     // when the event was
    float expectedUs;            // its lifetime times this pixel's distance along its flow
    schar partnerDx, partnerDy;  // 0, 0: no partner (the pixel beyond is off the sensor)
    bool beyond;                 // the claim at the pixel beyond (2 x the expected time)
};
const int kClaims = 4;
struct Claims
{
    Claim claim[kClaims];
    int count = 0;
};

class LifetimeArrivalCheckImpl CV_FINAL : public LifetimeArrivalCheck
{
public:
    explicit LifetimeArrivalCheckImpl(Size size)
    {
        if (size.width <= 0 || size.height <= 0 || size.width > SHRT_MAX + 1 || size.height > SHRT_MAX + 1)
            CV_Error_(Error::StsBadArg, ("LifetimeArrivalCheck: sensor size %d x %d is not a valid pixel array",
                                         size.width, size.height));
        size_ = size;
        reset();
    }

    void update(InputArray events, InputArray lifetimes, InputArray flow) CV_OVERRIDE
    {
        Mat_<Event> ev = getEventMat(events);
        const int n = (int)ev.total();
        const Mat lt = lifetimes.getMat(), fl = flow.getMat();
        if (n == 0 && lt.empty() && fl.empty())
            return;  // an empty packet (an empty vector's Mat has no type to check)
        if (lt.type() != CV_32F || (int)lt.total() != n || !lt.isContinuous())
            CV_Error_(Error::StsBadArg, ("LifetimeArrivalCheck: %d events need %d lifetimes (CV_32F, continuous); "
                                         "got %d of type %d", n, n, (int)lt.total(), lt.type()));
        if (fl.depth() != CV_32F || (int)(fl.total() * fl.channels()) != 2 * n || !fl.isContinuous())
            CV_Error_(Error::StsBadArg, ("LifetimeArrivalCheck: %d events need an N x 2 CV_32F (or N x 1 CV_32FC2) "
                                         "flow; got %d values of type %d", n, (int)(fl.total() * fl.channels()),
                                         fl.type()));
        const Event* e = n ? ev[0] : nullptr;
        // Validate first so that a bad packet leaves the check as it was.
        int64 previous = lastTime_;
        for (int i = 0; i < n; i++)
        {
            if ((unsigned)e[i].x >= (unsigned)size_.width || (unsigned)e[i].y >= (unsigned)size_.height)
                CV_Error_(Error::StsOutOfRange, ("LifetimeArrivalCheck: event #%d at (x=%d, y=%d), t=%lld us, is "
                                                 "outside the %d x %d sensor", i, e[i].x, e[i].y,
                                                 (long long)e[i].t, size_.width, size_.height));
            if (e[i].t == kNone || (previous != kNone && e[i].t < previous))
                CV_Error_(Error::StsBadArg, ("LifetimeArrivalCheck: event #%d at (x=%d, y=%d), t=%lld us, goes "
                                             "back in time (previous event at %lld us)", i, e[i].x, e[i].y,
                                             (long long)e[i].t, (long long)previous));
            previous = e[i].t;
        }
        const float* l = n ? lt.ptr<float>() : nullptr;
        const float* f = n ? fl.ptr<float>() : nullptr;
        for (int i = 0; i < n; i++)
            add(e[i], l[i], f[2 * i], f[2 * i + 1]);
        lastTime_ = previous;
    }

    double getRatioQuantile(double q) const CV_OVERRIDE
    {
        CV_CheckGE(q, 0.0, "LifetimeArrivalCheck::getRatioQuantile: q in 0..1");
        CV_CheckLE(q, 1.0, "LifetimeArrivalCheck::getRatioQuantile: q in 0..1");
        if (samples_ == 0)
            return 0;
        const double rank = q * (samples_ - 1);
        double seen = 0;
        for (int b = 0; b < kBins; b++)
        {
            seen += histogram_[b];
            if (seen > rank)
                return binCentre(b);
        }
        return binCentre(kBins - 1);
    }

    double getSampleCount() const CV_OVERRIDE { return samples_; }

    void reset() CV_OVERRIDE
    {
        claims_.assign(2 * (size_t)size_.area(), Claims());
        lastFired_.assign(2 * (size_t)size_.area(), kNone);
        histogram_.assign(kBins, 0);
        samples_ = 0;
        lastTime_ = kNone;
    }

    Size getSensorSize() const CV_OVERRIDE { return size_; }

    void write(FileStorage& fs) const CV_OVERRIDE
    {
        writeFormat(fs);
        fs << "sensorWidth" << size_.width << "sensorHeight" << size_.height;
    }

    void read(const FileNode& fn) CV_OVERRIDE
    {
        const Size s(fn["sensorWidth"].empty() ? size_.width : (int)fn["sensorWidth"],
                     fn["sensorHeight"].empty() ? size_.height : (int)fn["sensorHeight"]);
        if (s == size_)
            return;
        if (s.width <= 0 || s.height <= 0 || s.width > SHRT_MAX + 1 || s.height > SHRT_MAX + 1)
            CV_Error_(Error::StsBadArg, ("LifetimeArrivalCheck: sensor size %d x %d is not a valid pixel array",
                                         s.width, s.height));
        size_ = s;
        reset();
    }

    String getDefaultName() const CV_OVERRIDE { return "LifetimeArrivalCheck"; }

private:
    static double binCentre(int b)
    {
        if (b == 0)
            return kLowestRatio / std::sqrt(kBinRatio);
        return kLowestRatio * std::pow(kBinRatio, b - 0.5);
    }

    void add(const Event& e, float lifetime, float vx, float vy)
    {
        const int p = e.p ? 1 : 0;
        // This pixel fired: every earlier event that pointed here gets its sample, unless the claim's partner
        // settled it first.
        const size_t plane = (size_t)p * size_.area();
        const size_t hereIndex = plane + (size_t)e.y * size_.width + e.x;
        Claims& here = claims_[hereIndex];
        int kept = 0;
        for (int i = 0; i < here.count; i++)
        {
            const Claim c = here.claim[i];
            if (c.t == e.t)
            {
                here.claim[kept++] = c;  // at the same instant: not yet a delay
                continue;
            }
            // The pixel beyond settles a claim only from the time the neighbour was due on (half its own expected
            // time): before, its firing is not this edge (another edge, noise, clutter). So the neighbour's claim
            // was settled by the pixel beyond if that fired after the neighbour was due, and the claim beyond by
            // the neighbour if that fired at all.
            const double ratio = (double)(e.t - c.t) / c.expectedUs;
            if (c.beyond && ratio < 0.5)
                continue;
            if (c.partnerDx != 0 || c.partnerDy != 0)
            {
                const size_t partner = plane + (size_t)(e.y + c.partnerDy) * size_.width + (e.x + c.partnerDx);
                const double settledAfter = (double)c.t + (c.beyond ? 0.0 : (double)c.expectedUs);
                if ((double)lastFired_[partner] > settledAfter)
                    continue;
            }
            // The open ends first: a ratio past 1e3 (up to infinity) must not reach the integer conversion.
            const int b = ratio < kLowestRatio ? 0
                        : !(ratio < kHighestRatio) ? kBins - 1
                        : std::min(kBins - 1, 1 + (int)(std::log(ratio / kLowestRatio) / std::log(kBinRatio)));
            histogram_[b]++;
            samples_++;
        }
        here.count = kept;
        const int64 previousHere = lastFired_[hereIndex];
        lastFired_[hereIndex] = e.t;
        const double speed = std::sqrt((double)vx * vx + (double)vy * vy);
        if (!(lifetime > 0) || !(speed > 0) || !std::isfinite(speed) || !std::isfinite(lifetime))
            return;
        // The 8-neighbour the flow points to, the one LifetimeEstimator predicts.
        Point offset;
        if (!neighbourAlongMotion(vx, vy, offset))
            return;
        const int dx = offset.x, dy = offset.y;
        const int x = e.x + dx, y = e.y + dy;
        if (x < 0 || x >= size_.width || y < 0 || y >= size_.height)
            return;
        // > 0: the neighbour lies within 22.5 degrees of the flow (checked again against rounding).
        const float expected = (float)(lifetime * (vx * dx + vy * dy) / speed);
        if (!(expected > 0))
            return;
        // A pixel that fired within the expected time before is still in the same crossing (an edge blurred over
        // a few pixels fires several events at each): measured from there, the neighbour, already in its own
        // crossing, would fire early. Only the crossing's first event claims.
        if (previousHere != kNone && (double)(e.t - previousHere) <= (double)expected)
            return;
        // A dotted edge skips pixels: where the neighbour does not fire on this crossing, the pixel beyond it
        // (twice the time) tells when the edge passed, instead of the neighbour's next crossing.
        const int x2 = x + dx, y2 = y + dy;
        const bool beyond = x2 >= 0 && x2 < size_.width && y2 >= 0 && y2 < size_.height;
        addClaim(claims_[plane + (size_t)y * size_.width + x],
                 Claim{ e.t, expected, (schar)(beyond ? dx : 0), (schar)(beyond ? dy : 0), false });
        if (beyond)
            addClaim(claims_[plane + (size_t)y2 * size_.width + x2],
                     Claim{ e.t, 2 * expected, (schar)-dx, (schar)-dy, true });
    }

    static void addClaim(Claims& c, const Claim& claim)
    {
        if (c.count == kClaims)
        {
            std::copy(c.claim + 1, c.claim + kClaims, c.claim);
            c.count--;
        }
        c.claim[c.count++] = claim;
    }

    Size size_;
    std::vector<Claims> claims_;
    std::vector<int64> lastFired_;  // per pixel and polarity: the time of its last event
    std::vector<double> histogram_;
    double samples_ = 0;
    int64 lastTime_ = kNone;
};

}  // namespace
}  // namespace detail

Ptr<LifetimeArrivalCheck> LifetimeArrivalCheck::create(Size sensorSize)
{
    return makePtr<detail::LifetimeArrivalCheckImpl>(sensorSize);
}

}  // namespace event
}  // namespace cv
