// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_STEREO_STEREO_MATCHER_PARAMS_HPP
#define OPENCV_EVENT_SRC_STEREO_STEREO_MATCHER_PARAMS_HPP

#include "opencv2/event/stereo_event_matcher.hpp"

namespace cv {
namespace event {
namespace detail {

/** The checks both stereo matchers (StereoEventMatcher, FrameStereoMatcher) make of the parameters they share;
each raises cv::Error::StsBadArg naming @p owner, the value and its valid range. */
void checkSensorSize(Size s, const char* owner);
void checkDisparityRange(int lo, int hi, const char* owner);
/** A time of 1 us .. 1e12 us, rounded to whole microseconds. */
int64 checkedDuration(double us, const char* what, const char* owner);

/** StereoEventMatcher's parameters (their meaning is in the public header's getters), with their validation and
their FileStorage form. Each setter checks its argument and raises cv::Error::StsBadArg naming the parameter and
its valid range, leaving the struct unchanged; what a change does to the matcher's state is the matcher's. */
struct StereoMatcherParams
{
    int mode = STEREO_COUPLED;
    Size sensorSize;
    int minDisparity = 0, maxDisparity = 40;
    int descriptorWindow = 3, maxVectorLength = 3, costWindow = 17, lifetimeWindow = 9, aggregationWindow = 31;
    int costRowStep = 2;
    int uniquenessRatio = 15;
    double minConfidence = 0, matchedLifetimeConfidence = 0.15, lifetimeCopyConfidence = 0.3;
    int maxLifetimeCopies = 1;
    int priorTolerance = 30;  // %
    int recencyWeight = 15;   // %
    int averagingRadius = 4;
    int fillRadius = 20;
    // Times in microseconds.
    int64 recencyTime = 10000, lookAhead = 10000, fixedInterval = 10000, maxLifetime = 100000, noiseActiveTime = 25000;
    int64 fillReuseTime = 5000;
    double activeDistance = 2.5;
    int numThreads = 1;  // not stored: a property of the machine, not of the method

    /** The widest averaging radius: the temporal prior's, whose rows an event's processing already reaches. */
    enum { MAX_AVERAGING_RADIUS = 5 };
    /** The widest filling radius: the temporal prior's reach along a horizontal edge. */
    enum { MAX_FILL_RADIUS = 30 };
    /** The sparsest sampling of the cost windows' rows: every 4th row still reads 5 of the default window's 17. */
    enum { MAX_COST_ROW_STEP = 4 };

    void setMode(int m);
    void setSensorSize(Size s);
    void setDisparityRange(int lo, int hi);
    void setDescriptorWindow(int n);
    void setMaxVectorLength(int r);
    /** Also widens the aggregation window to at least @p w. */
    void setCostWindow(int w);
    void setLifetimeWindow(int w);
    /** At least the cost window. */
    void setAggregationWindow(int a);
    void setCostRowStep(int k);
    void setUniquenessRatio(int u);
    void setMinConfidence(double c);
    void setMatchedLifetimeConfidence(double c);
    void setLifetimeCopyConfidence(double c);
    void setMaxLifetimeCopies(int copies);
    void setPriorTolerance(int percent);
    void setRecencyWeight(int percent);
    void setRecencyTime(double us);
    void setAveragingRadius(int px);
    void setFillRadius(int px);
    void setFillReuseTime(double us);
    void setLookAhead(double us);
    void setFixedInterval(double us);
    void setMaxLifetime(double us);
    void setNoiseActiveTime(double us);
    void setActiveDistance(double px);
    void setNumThreads(int threads);

    /** Writes every stored parameter under its getter's name (mode by name, times in us). */
    void write(FileStorage& fs) const;
    /** Sets each parameter that @p fn holds, through its setter, in write()'s order; keys it lacks keep their
        value. An unknown mode name raises cv::Error::StsParseError. */
    void read(const FileNode& fn);
};

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif
