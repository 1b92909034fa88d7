// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// StereoEventMatcher's parameters: the validated setters, FileStorage I/O and the row reach they imply.

#include "precomp.hpp"
#include "stereo/stereo_event_matcher_impl.hpp"

namespace cv {
namespace event {
namespace detail {

void StereoEventMatcherImpl::setMode(int mode)
{
    checkMode(mode);
    mode_ = mode;
    reset();
}

void StereoEventMatcherImpl::setSensorSize(Size s)
{
    if (s.width <= 0 || s.height <= 0 || s.width > 32768 || s.height > 32768)
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: sensor size %d x %d is not valid", s.width, s.height));
    size_ = s;
    for (const Ptr<RowBandLifetimeEstimator>& est : estimators_)
        est->setSensorSize(s);
    if (!calibration_.empty() && calibration_.imageSize != s)
    {
        calibration_ = StereoCalibration();
        lut_[0].clear();
        lut_[1].clear();
        focalBaseline_ = 0;
    }
    reset();
}

void StereoEventMatcherImpl::setDescriptorWindow(int n)
{
    descriptorWindow_ = oddWindow(n, 1, 15, "descriptor window");
    reset();
}

void StereoEventMatcherImpl::setMaxVectorLength(int r)
{
    if (r < 0 || r > 7)
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: max vector length %d; must be 0..7 px", r));
    maxVectorLength_ = r;
    reset();
}

void StereoEventMatcherImpl::setCostWindow(int w)
{
    costWindow_ = oddWindow(w, 1, 31, "cost window");
    aggregationWindow_ = std::max(aggregationWindow_, costWindow_);
    reset();
}

void StereoEventMatcherImpl::setLifetimeWindow(int w)
{
    lifetimeWindow_ = oddWindow(w, 1, 31, "lifetime window");
    reset();
}

void StereoEventMatcherImpl::setAggregationWindow(int a)
{
    aggregationWindow_ = oddWindow(a, costWindow_, 31, "aggregation window (>= the cost window)");
    reset();
}

void StereoEventMatcherImpl::setUniquenessRatio(int u)
{
    if (u < 0 || u > 99)
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: uniqueness ratio %d; must be 0..99 %%", u));
    uniquenessRatio_ = u;
}

void StereoEventMatcherImpl::setMinConfidence(double c)
{
    if (!(c >= 0 && c <= 1))
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: minimum confidence %g; must be 0..1 (0: every event with a "
                                     "candidate keeps its best disparity)", c));
    minConfidence_ = c;
}

void StereoEventMatcherImpl::setMatchedLifetimeConfidence(double c)
{
    if (!(c >= 0 && c <= 1))
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: matched lifetime confidence %g; must be 0..1 (0: every match "
                                     "passes its counterpart's lifetime)", c));
    matchedLifetimeConfidence_ = c;
}

void StereoEventMatcherImpl::setLifetimeCopyConfidence(double c)
{
    if (!(c >= 0 && c <= 1))
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: lifetime copy confidence %g; must be 0..1 (0: every match "
                                     "passes its lifetime on)", c));
    lifetimeCopyConfidence_ = c;
}

void StereoEventMatcherImpl::setMaxLifetimeCopies(int copies)
{
    if (copies < 0 || copies > 255)
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: max lifetime copies %d; must be 0..255 (0: every event "
                                     "fits its plane, 255: no limit)", copies));
    maxLifetimeCopies_ = copies;
}

void StereoEventMatcherImpl::setPriorTolerance(int percent)
{
    if (percent < 0 || percent > 1000)
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: prior tolerance %d %%; must be 0..1000 %% (0: no temporal prior)", percent));
    priorTolerance_ = percent;
}

void StereoEventMatcherImpl::setRecencyWeight(int percent)
{
    if (percent < 0 || percent > 100)
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: recency weight %d %%; must be 0..100 %% (0: the cost of the "
                                     "descriptors alone)", percent));
    recencyWeight_ = percent;
}

void StereoEventMatcherImpl::setRecencyTime(double us)
{
    if (!(us >= 1 && us <= 1e6))
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: recency time %g us; must be 1..1e6 us", us));
    recencyTime_ = (int64)std::llround(us);
}

void StereoEventMatcherImpl::setAveragingRadius(int px)
{
    // The row bands' reach covers PRIOR_RADIUS rows around an event (eventRowReach).
    if (px < 0 || px > (int)PRIOR_RADIUS)
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: averaging radius %d px; must be 0..%d px (0: each event keeps "
                                     "its own estimate)", px, (int)PRIOR_RADIUS));
    averagingRadius_ = px;
}

void StereoEventMatcherImpl::setLookAhead(double us)
{
    if (!(us >= 0 && us <= 1e6))
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: look-ahead %g us; must be 0..1e6 us (0: each event is decided "
                                     "when it arrives)", us));
    lookAhead_ = (int64)std::llround(us);
}

void StereoEventMatcherImpl::setNoiseActiveTime(double us)
{
    if (!(us >= 0 && us <= 1e6))
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: noise active time %g us; must be 0..1e6 us (0: an event "
                                     "without a lifetime is not active)", us));
    noiseActiveTime_ = (int64)std::llround(us);
}

void StereoEventMatcherImpl::setFrameWindow(double us)
{
    frameWindow_ = duration(us, "frame window");
    reset();
}

void StereoEventMatcherImpl::setActiveDistance(double px)
{
    if (!(px >= 0.1 && px <= 100))
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: active distance %g px; must be 0.1..100 px (1: active "
                                     "for one lifetime, as in the paper)", px));
    activeDistance_ = px;
}

void StereoEventMatcherImpl::setNumThreads(int threads)
{
    if (threads < 1 || threads > 64)
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: %d threads; must be 1..64", threads));
    numThreads_ = threads;
}

void StereoEventMatcherImpl::write(FileStorage& fs) const
{
    writeFormat(fs);
    fs << "mode" << getStereoModeName(mode_) << "sensorWidth" << size_.width << "sensorHeight" << size_.height
       << "minDisparity" << minDisparity_ << "maxDisparity" << maxDisparity_ << "descriptorWindow" << descriptorWindow_
       << "maxVectorLength" << maxVectorLength_ << "costWindow" << costWindow_ << "lifetimeWindow" << lifetimeWindow_
       << "aggregationWindow" << aggregationWindow_ << "uniquenessRatio" << uniquenessRatio_
       << "minConfidence" << minConfidence_ << "matchedLifetimeConfidence" << matchedLifetimeConfidence_
       << "lifetimeCopyConfidence" << lifetimeCopyConfidence_ << "maxLifetimeCopies" << maxLifetimeCopies_
       << "priorTolerance" << priorTolerance_ << "recencyWeight" << recencyWeight_ << "recencyTime" << (double)recencyTime_
       << "averagingRadius" << averagingRadius_ << "lookAhead" << (double)lookAhead_ << "fixedInterval" << (double)fixedInterval_
       << "frameWindow" << (double)frameWindow_ << "maxLifetime" << (double)maxLifetime_ << "activeDistance"
       << activeDistance_ << "noiseActiveTime" << (double)noiseActiveTime_;
    fs << "lifetimeEstimator" << "{";
    estimators_[0]->write(fs);
    fs << "}";
    if (!calibration_.empty())
    {
        fs << "calibration" << "{";
        calibration_.write(fs);
        fs << "}";
    }
}

void StereoEventMatcherImpl::read(const FileNode& fn)
{
    auto num = [&](const char* key, double def) { return fn[key].empty() ? def : (double)fn[key]; };
    if (!fn["mode"].empty())
    {
        const int m = findStereoMode((String)fn["mode"]);
        if (m < 0)
            CV_Error_(Error::StsParseError, ("StereoEventMatcher: unknown mode '%s'", ((String)fn["mode"]).c_str()));
        checkMode(m);
        mode_ = m;
    }
    const Size s((int)num("sensorWidth", size_.width), (int)num("sensorHeight", size_.height));
    if (s != size_)
        setSensorSize(s);
    setDisparityRange((int)num("minDisparity", minDisparity_), (int)num("maxDisparity", maxDisparity_));
    setDescriptorWindow((int)num("descriptorWindow", descriptorWindow_));
    setMaxVectorLength((int)num("maxVectorLength", maxVectorLength_));
    setCostWindow((int)num("costWindow", costWindow_));
    setLifetimeWindow((int)num("lifetimeWindow", lifetimeWindow_));
    setAggregationWindow((int)num("aggregationWindow", aggregationWindow_));
    setUniquenessRatio((int)num("uniquenessRatio", uniquenessRatio_));
    setMinConfidence(num("minConfidence", minConfidence_));
    setMatchedLifetimeConfidence(num("matchedLifetimeConfidence", matchedLifetimeConfidence_));
    setLifetimeCopyConfidence(num("lifetimeCopyConfidence", lifetimeCopyConfidence_));
    setMaxLifetimeCopies((int)num("maxLifetimeCopies", maxLifetimeCopies_));
    setPriorTolerance((int)num("priorTolerance", priorTolerance_));
    setRecencyWeight((int)num("recencyWeight", recencyWeight_));
    setRecencyTime(num("recencyTime", (double)recencyTime_));
    setAveragingRadius((int)num("averagingRadius", averagingRadius_));
    setLookAhead(num("lookAhead", (double)lookAhead_));
    setFixedInterval(num("fixedInterval", (double)fixedInterval_));
    setFrameWindow(num("frameWindow", (double)frameWindow_));
    setMaxLifetime(num("maxLifetime", (double)maxLifetime_));
    setActiveDistance(num("activeDistance", activeDistance_));
    setNoiseActiveTime(num("noiseActiveTime", (double)noiseActiveTime_));
    if (!fn["lifetimeEstimator"].empty())
        for (const Ptr<RowBandLifetimeEstimator>& est : estimators_)
            est->read(fn["lifetimeEstimator"]);
    if (!fn["calibration"].empty())
    {
        StereoCalibration c;
        c.read(fn["calibration"], "StereoEventMatcher calibration");
        setCalibration(c);
    }
    reset();
}

void StereoEventMatcherImpl::checkMode(int mode)
{
    if (mode < STEREO_COUPLED || mode > STEREO_FRAME_SGBM)
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: mode %d; use a StereoMatchMode (0..3)", mode));
}

int StereoEventMatcherImpl::oddWindow(int n, int lo, int hi, const char* what)
{
    if (n < lo || n > hi || n % 2 == 0)
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: %s %d; must be odd, %d..%d", what, n, lo, hi));
    return n;
}

int64 StereoEventMatcherImpl::duration(double us, const char* what)
{
    if (!(us >= 1) || us > 1e12)
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: %s %g us; must be 1 us .. 1e12 us", what, us));
    return (int64)std::llround(us);
}

void StereoEventMatcherImpl::setDisparityRange(int lo, int hi)
{
    if (lo < 0 || hi < lo || hi > 1024)
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: disparity range [%d, %d]; need 0 <= min <= max <= 1024", lo, hi));
    minDisparity_ = lo;
    maxDisparity_ = hi;
    reset();
}

int StereoEventMatcherImpl::eventRowReach() const
{
    return std::max({ aggregationWindow_ / 2, costWindow_ / 2, lifetimeWindow_ / 2, 1, (int)PRIOR_RADIUS,
                      expiryRowReach(), estimators_[0]->rowReach(), estimators_[1]->rowReach() });
}

}  // namespace detail
}  // namespace event
}  // namespace cv
