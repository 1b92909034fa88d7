// When the tools apply a clock offset they estimated (event_stereo's --right-time-offset-ms=auto), shared with
// the benchmark that reports what the estimate would do (perf/clock_offset_sweep).

#ifndef OPENCV_EVENT_COMMON_CLOCK_OFFSET_POLICY_HPP
#define OPENCV_EVENT_COMMON_CLOCK_OFFSET_POLICY_HPP

#include <cmath>

/** Above this uncertainty (cv::event::estimateClockOffset()) the events do not pin a clock offset down well
    enough to apply it (the half millisecond that moves an edge at 200 px/s by a tenth of a pixel). */
constexpr double kSampleMaxClockUncertaintyUs = 500;

/** An estimate within this many of its uncertainties of zero does not show the clocks apart: applying it would
    move the right camera by its noise alone. */
constexpr double kSampleClockSignificance = 2;

/** Whether an estimate is applied: sure enough, and clear of zero. */
inline bool sampleAppliesClockOffset(double offsetUs, double uncertaintyUs)
{
    return uncertaintyUs <= kSampleMaxClockUncertaintyUs && std::abs(offsetUs) >= kSampleClockSignificance * uncertaintyUs;
}

#endif
