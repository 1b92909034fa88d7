// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"
#include "stereo/stereo_matcher_params.hpp"

namespace cv {
namespace event {
namespace detail {

namespace {

int oddWindow(int n, int lo, int hi, const char* what)
{
    if (n < lo || n > hi || n % 2 == 0)
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: %s %d; must be odd, %d..%d", what, n, lo, hi));
    return n;
}

int64 duration(double us, const char* what)
{
    return checkedDuration(us, what, "StereoEventMatcher");
}

// A share from 0 to 1; @p zero says what 0 means.
double share(double c, const char* what, const char* zero)
{
    if (!(c >= 0 && c <= 1))
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: %s %g; must be 0..1 (0: %s)", what, c, zero));
    return c;
}

// A time from 0 to 1 s in microseconds; @p zero says what 0 means.
int64 upToOneSecond(double us, const char* what, const char* zero)
{
    if (!(us >= 0 && us <= 1e6))
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: %s %g us; must be 0..1e6 us (0: %s)", what, us, zero));
    return (int64)std::llround(us);
}

}  // namespace

void checkSensorSize(Size s, const char* owner)
{
    if (s.width <= 0 || s.height <= 0 || s.width > 32768 || s.height > 32768)
        CV_Error_(Error::StsBadArg, ("%s: sensor size %d x %d is not valid", owner, s.width, s.height));
}

void checkDisparityRange(int lo, int hi, const char* owner)
{
    if (lo < 0 || hi < lo || hi > 1024)
        CV_Error_(Error::StsBadArg, ("%s: disparity range [%d, %d]; need 0 <= min <= max <= 1024", owner, lo, hi));
}

int64 checkedDuration(double us, const char* what, const char* owner)
{
    if (!(us >= 1) || us > 1e12)
        CV_Error_(Error::StsBadArg, ("%s: %s %g us; must be 1 us .. 1e12 us", owner, what, us));
    return (int64)std::llround(us);
}

void StereoMatcherParams::setMode(int m)
{
    if (m < STEREO_COUPLED || m > STEREO_FIXED_INTERVAL)
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: mode %d; use a StereoMatchMode (0..2; frames + StereoSGBM "
                                     "are FrameStereoMatcher's)", m));
    mode = m;
}

void StereoMatcherParams::setSensorSize(Size s)
{
    checkSensorSize(s, "StereoEventMatcher");
    sensorSize = s;
}

void StereoMatcherParams::setDisparityRange(int lo, int hi)
{
    checkDisparityRange(lo, hi, "StereoEventMatcher");
    minDisparity = lo;
    maxDisparity = hi;
}

void StereoMatcherParams::setDescriptorWindow(int n)
{
    descriptorWindow = oddWindow(n, 1, 15, "descriptor window");
}

void StereoMatcherParams::setMaxVectorLength(int r)
{
    if (r < 0 || r > 7)
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: max vector length %d; must be 0..7 px", r));
    maxVectorLength = r;
}

void StereoMatcherParams::setCostWindow(int w)
{
    costWindow = oddWindow(w, 1, 31, "cost window");
    aggregationWindow = std::max(aggregationWindow, costWindow);
}

void StereoMatcherParams::setLifetimeWindow(int w)
{
    lifetimeWindow = oddWindow(w, 1, 31, "lifetime window");
}

void StereoMatcherParams::setAggregationWindow(int a)
{
    aggregationWindow = oddWindow(a, costWindow, 31, "aggregation window (>= the cost window)");
}

void StereoMatcherParams::setCostRowStep(int k)
{
    if (k < 1 || k > (int)MAX_COST_ROW_STEP)
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: cost row step %d; must be 1..%d (1: every row of the cost "
                                     "windows)", k, (int)MAX_COST_ROW_STEP));
    costRowStep = k;
}

void StereoMatcherParams::setUniquenessRatio(int u)
{
    if (u < 0 || u > 99)
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: uniqueness ratio %d; must be 0..99 %%", u));
    uniquenessRatio = u;
}

void StereoMatcherParams::setMinConfidence(double c)
{
    minConfidence = share(c, "minimum confidence", "every event with a candidate keeps its best disparity");
}

void StereoMatcherParams::setMatchedLifetimeConfidence(double c)
{
    matchedLifetimeConfidence = share(c, "matched lifetime confidence", "every match passes its counterpart's lifetime");
}

void StereoMatcherParams::setLifetimeCopyConfidence(double c)
{
    lifetimeCopyConfidence = share(c, "lifetime copy confidence", "every match passes its lifetime on");
}

void StereoMatcherParams::setMaxLifetimeCopies(int copies)
{
    if (copies < 0 || copies > 255)
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: max lifetime copies %d; must be 0..255 (0: every event "
                                     "fits its plane, 255: no limit)", copies));
    maxLifetimeCopies = copies;
}

void StereoMatcherParams::setPriorTolerance(int percent)
{
    if (percent < 0 || percent > 1000)
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: prior tolerance %d %%; must be 0..1000 %% (0: no temporal prior)", percent));
    priorTolerance = percent;
}

void StereoMatcherParams::setRecencyWeight(int percent)
{
    if (percent < 0 || percent > 100)
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: recency weight %d %%; must be 0..100 %% (0: the cost of the "
                                     "descriptors alone)", percent));
    recencyWeight = percent;
}

void StereoMatcherParams::setRecencyTime(double us)
{
    if (!(us >= 1 && us <= 1e6))
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: recency time %g us; must be 1..1e6 us", us));
    recencyTime = (int64)std::llround(us);
}

void StereoMatcherParams::setAveragingRadius(int px)
{
    if (px < 0 || px > (int)MAX_AVERAGING_RADIUS)
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: averaging radius %d px; must be 0..%d px (0: each event keeps "
                                     "its own estimate)", px, (int)MAX_AVERAGING_RADIUS));
    averagingRadius = px;
}

void StereoMatcherParams::setFillRadius(int px)
{
    if (px < 0 || px > (int)MAX_FILL_RADIUS)
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: fill radius %d px; must be 0..%d px (0: no filling)", px,
                                     (int)MAX_FILL_RADIUS));
    fillRadius = px;
}

void StereoMatcherParams::setFillReuseTime(double us)
{
    fillReuseTime = upToOneSecond(us, "fill reuse time", "every event finds its own surface");
}

void StereoMatcherParams::setLookAhead(double us)
{
    lookAhead = upToOneSecond(us, "look-ahead", "each event is decided when it arrives");
}

void StereoMatcherParams::setFixedInterval(double us)
{
    fixedInterval = duration(us, "fixed interval");
}

void StereoMatcherParams::setMaxLifetime(double us)
{
    maxLifetime = duration(us, "max lifetime");
}

void StereoMatcherParams::setNoiseActiveTime(double us)
{
    noiseActiveTime = upToOneSecond(us, "noise active time", "an event without a lifetime is not active");
}

void StereoMatcherParams::setActiveDistance(double px)
{
    if (!(px >= 0.1 && px <= 100))
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: active distance %g px; must be 0.1..100 px (1: active "
                                     "for one lifetime, as in the paper)", px));
    activeDistance = px;
}

void StereoMatcherParams::setNumThreads(int threads)
{
    if (threads < 1 || threads > 64)
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: %d threads; must be 1..64", threads));
    numThreads = threads;
}

void StereoMatcherParams::write(FileStorage& fs) const
{
    fs << "mode" << getStereoModeName(mode) << "sensorWidth" << sensorSize.width << "sensorHeight" << sensorSize.height
       << "minDisparity" << minDisparity << "maxDisparity" << maxDisparity << "descriptorWindow" << descriptorWindow
       << "maxVectorLength" << maxVectorLength << "costWindow" << costWindow << "lifetimeWindow" << lifetimeWindow
       << "aggregationWindow" << aggregationWindow << "costRowStep" << costRowStep << "uniquenessRatio" << uniquenessRatio
       << "minConfidence" << minConfidence << "matchedLifetimeConfidence" << matchedLifetimeConfidence
       << "lifetimeCopyConfidence" << lifetimeCopyConfidence << "maxLifetimeCopies" << maxLifetimeCopies
       << "priorTolerance" << priorTolerance << "recencyWeight" << recencyWeight << "recencyTime" << (double)recencyTime
       << "averagingRadius" << averagingRadius << "fillRadius" << fillRadius << "fillReuseTime" << (double)fillReuseTime
       << "lookAhead" << (double)lookAhead << "fixedInterval" << (double)fixedInterval
       << "maxLifetime" << (double)maxLifetime << "activeDistance" << activeDistance
       << "noiseActiveTime" << (double)noiseActiveTime;
}

void StereoMatcherParams::read(const FileNode& fn)
{
    auto num = [&](const char* key, double def) { return fn[key].empty() ? def : (double)fn[key]; };
    if (!fn["mode"].empty())
    {
        const int m = findStereoMode((String)fn["mode"]);
        if (m < 0)
            CV_Error_(Error::StsParseError, ("StereoEventMatcher: unknown mode '%s' (coupled, decoupled or fixed; "
                                             "frames + StereoSGBM are FrameStereoMatcher's)",
                                             ((String)fn["mode"]).c_str()));
        setMode(m);
    }
    setSensorSize(Size((int)num("sensorWidth", sensorSize.width), (int)num("sensorHeight", sensorSize.height)));
    setDisparityRange((int)num("minDisparity", minDisparity), (int)num("maxDisparity", maxDisparity));
    setDescriptorWindow((int)num("descriptorWindow", descriptorWindow));
    setMaxVectorLength((int)num("maxVectorLength", maxVectorLength));
    setCostWindow((int)num("costWindow", costWindow));
    setLifetimeWindow((int)num("lifetimeWindow", lifetimeWindow));
    setAggregationWindow((int)num("aggregationWindow", aggregationWindow));
    setCostRowStep((int)num("costRowStep", costRowStep));
    setUniquenessRatio((int)num("uniquenessRatio", uniquenessRatio));
    setMinConfidence(num("minConfidence", minConfidence));
    setMatchedLifetimeConfidence(num("matchedLifetimeConfidence", matchedLifetimeConfidence));
    setLifetimeCopyConfidence(num("lifetimeCopyConfidence", lifetimeCopyConfidence));
    setMaxLifetimeCopies((int)num("maxLifetimeCopies", maxLifetimeCopies));
    setPriorTolerance((int)num("priorTolerance", priorTolerance));
    setRecencyWeight((int)num("recencyWeight", recencyWeight));
    setRecencyTime(num("recencyTime", (double)recencyTime));
    setAveragingRadius((int)num("averagingRadius", averagingRadius));
    setFillRadius((int)num("fillRadius", fillRadius));
    setFillReuseTime(num("fillReuseTime", (double)fillReuseTime));
    setLookAhead(num("lookAhead", (double)lookAhead));
    setFixedInterval(num("fixedInterval", (double)fixedInterval));
    setMaxLifetime(num("maxLifetime", (double)maxLifetime));
    setActiveDistance(num("activeDistance", activeDistance));
    setNoiseActiveTime(num("noiseActiveTime", (double)noiseActiveTime));
}

}  // namespace detail
}  // namespace event
}  // namespace cv
