// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_DAVIS_DAVIS_EVENT_DECODER_HPP
#define OPENCV_EVENT_SRC_DAVIS_DAVIS_EVENT_DECODER_HPP

// Decoder of the DAVIS data endpoint: a stream of 16-bit little-endian words, split into USB transfers at
// arbitrary points. Its state (row, time base, current time) carries over from one transfer to the next.
// Exported for the unit tests and the fuzz target; not part of the public API.

#include "opencv2/event.hpp"

#include <functional>

namespace cv {
namespace event {
namespace detail {

class CV_EXPORTS DavisEventDecoder
{
public:
    /** @param rawColumns, rawRows the DVS array as the device reports it (DVS SIZE_COLUMNS / SIZE_ROWS).
    @param invertXY the DVS orientation bit 2: raw columns are the user's rows (x and y are swapped).
    @param waitForTimestampReset when true, events before the first timestamp-reset word are not delivered
    (they carry the clock of before the reset) but counted in eventsBeforeReset; that reset is time 0. */
    DavisEventDecoder(int rawColumns, int rawRows, bool invertXY, bool waitForTimestampReset);

    /** The next timestamp-reset word sets the time to @p epochUs (and synchronises the decoder). Before the
    first one, a reset that was not armed (one the FPGA latched while stopped and sends at the start) is
    counted in staleResets and changes nothing. */
    void arm(int64 epochUs);
    /** Undoes arm() and the constructor's wait: until arm(), resets do not synchronise. */
    void disarm();
    /** Where the time goes on after a reset that was not armed, once synchronised: @p epoch(lastTime) with the
    time of the last timestamp word before it (default: that time, so that time never goes back). */
    void setUnarmedResetEpoch(const std::function<int64(int64)>& epoch) { unarmedEpoch_ = epoch; }

    /** Decodes one transfer and appends its DVS events (camera = @p camera) to @p out. A transfer of odd
    length has a trailing byte that is no word: it is dropped and counted in oddBytes. */
    void decode(const uint8_t* data, size_t size, std::vector<Event>& out, int camera = CAMERA_LEFT);
    /** Moves the trigger events decoded so far (external-input and generator words once synchronised, with
    the camera of their decode() call) to the end of @p out. */
    void takeTriggers(std::vector<EventTrigger>& out);

    /** Device time [us] of the last timestamp or wrap word: no later event can be older than this. */
    int64 currentTime() const { return current_; }
    /** True once a timestamp-reset word was seen (always true when not waiting for one). */
    bool synchronised() const { return synchronised_; }

    struct Counters
    {
        int64 words = 0;              //!< 16-bit words decoded
        int64 events = 0;             //!< DVS events delivered
        int64 invalidAddresses = 0;   //!< Y or X words beyond the array (skipped), X words before any Y
        int64 eventsBeforeReset = 0;  //!< events dropped while waiting for the first timestamp reset
        int64 timestampResets = 0;    //!< timestamp-reset words
        int64 staleResets = 0;        //!< of those, resets before synchronisation that were not armed
        int64 wraps = 0;              //!< timestamp-wrap words (each adds data x 32768 us)
        int64 triggers = 0;           //!< external-input and generator words (trigger events once synchronised)
        int64 otherWords = 0;         //!< APS, IMU and other special words (not events)
        int64 oddBytes = 0;           //!< trailing bytes of odd-length transfers
    };
    const Counters& counters() const { return counters_; }

private:
    int rawColumns_, rawRows_;
    bool invertXY_;
    bool synchronised_;
    bool armed_;
    int64 armedEpoch_ = 0;
    std::function<int64(int64)> unarmedEpoch_;
    int lastRow_ = -1;       // -1: no valid Y word since the last reset
    int64 wrapBase_ = 0;     // us added by wrap words since the last reset
    int64 current_ = 0;      // time of the last timestamp word
    int64 epochOffset_ = 0;  // keeps time monotonic across resets after the first (see decode())
    Counters counters_;
    std::vector<EventTrigger> triggers_;
};

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_DAVIS_DAVIS_EVENT_DECODER_HPP
