// When the tools apply a clock offset they estimated (event_stereo's --right-time-offset-ms=auto), shared with
// the benchmark that reports what the estimate would do (perf/clock_offset_sweep).

#ifndef OPENCV_EVENT_COMMON_CLOCK_OFFSET_POLICY_HPP
#define OPENCV_EVENT_COMMON_CLOCK_OFFSET_POLICY_HPP

/** Above this uncertainty (cv::event::estimateClockOffset()) the events do not pin a clock offset down well
    enough to apply it (the half millisecond that moves an edge at 200 px/s by a tenth of a pixel). */
constexpr double kSampleMaxClockUncertaintyUs = 500;

#endif
