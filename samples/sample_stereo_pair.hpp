// Checks the stereo samples make of a pair of cameras: whether the events say where they line up, and which
// option exchanges the cameras when they look exchanged.

#ifndef OPENCV_EVENT_SAMPLES_SAMPLE_STEREO_PAIR_HPP
#define OPENCV_EVENT_SAMPLES_SAMPLE_STEREO_PAIR_HPP

#include <opencv2/core.hpp>

#include <string>

/** Below this correlation (cv::event::estimateDominantDisparity()) the events do not say where they line up
    (measured: 0.18-0.85 on the simulated scenes, 2 s each). */
constexpr double kSampleMinLineUpScore = 0.1;

/** Below this score (cv::event::estimateRowAlignment()) the events say too little about the rows to act on. */
constexpr double kSampleMinRowScore = 0.4;

/** Above this uncertainty (cv::event::estimateClockOffset()) the events do not pin a clock offset down well
    enough to apply it (the half millisecond that moves an edge at 200 px/s by a tenth of a pixel). */
constexpr double kSampleMaxClockUncertaintyUs = 500;

/** The option that exchanges the cameras: of two files (--left/--right), of a text file's camera column, or of
    any other recording of both cameras. */
inline std::string sampleCameraSwapAdvice(bool twoFiles, bool textFile, int leftCameraValue)
{
    if (twoFiles)
        return "exchange --left and --right";
    if (textFile)
        return cv::format("give --left-camera-value=%d", 1 - leftCameraValue);
    return "exchange the left and right cameras";
}

#endif
