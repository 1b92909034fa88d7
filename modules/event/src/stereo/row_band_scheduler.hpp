// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_STEREO_ROW_BAND_SCHEDULER_HPP
#define OPENCV_EVENT_SRC_STEREO_ROW_BAND_SCHEDULER_HPP

#include "opencv2/core.hpp"

#include <atomic>
#include <exception>
#include <functional>
#include <memory>
#include <vector>

namespace cv {
namespace event {
namespace detail {

/** Runs a packet's per-event operations on several threads with the results of one thread.

The image rows are split into bands, each processed by its own thread in time order: its events, and the
expiries of its pixels where the single thread would take them (before the first event at or after the
expiry time). Every operation has a key, its place in the single thread's order: position x (bands + 1) +
band for an expiry (position: the index of that first event; expiries at one position commute, a map's state
depends only on what is active), index x (bands + 1) + bands for an event. Two operations conflict only when
one writes data the other reads or writes: the caller gives the row distance beyond which none do
(conflictRows: the largest write reach + the largest reach of any access). An operation within conflictRows
of a neighbouring band's rows first waits until that neighbour's next operation has a larger key: every
operation it could conflict with then ran in the single thread's order. Bands are more than conflictRows
tall, so only neighbours can conflict. Two bands never wait on each other at once: the smaller of their keys
goes first.

The scheduler knows rows, times and keys only; what an operation does comes through Operations. */
class RowBandScheduler
{
public:
    /** The caller's operations, each called on the thread of band @p band. */
    struct Operations
    {
        /** The earliest pending expiry of the band's pixels: its time, its row and a token for expire();
        false when none is pending. */
        std::function<bool(int band, int64& time, int& row, int& token)> earliestExpiry;
        /** Carries out the expiry earliestExpiry() returned with @p token. */
        std::function<void(int band, int token)> expire;
        /** Processes event @p event, whose row lies in the band. */
        std::function<void(int band, int event)> process;
    };

    /** First rows of @p bands bands of at least @p minHeight rows each over an image of @p height rows, each
    holding about as many of the first @p valid events; @p rows holds each event's row, -1 for an event that
    is not processed. */
    static std::vector<int> splitRows(const std::vector<int>& rows, int valid, int height, int bands, int minHeight);

    /** Runs the first @p valid events (@p rows and @p times as for splitRows; times non-decreasing) and the
    expiries due before the last of them on one thread per band (@p firstRows from splitRows with a minimum
    height above @p conflictRows, one band on the calling thread). @p conflictRows: two operations (events or
    expiries) whose rows are further apart never touch data that one of them writes. Returns once every band
    is done, with the first failure of any band (null when none): a failed band stops, the others finish. */
    std::exception_ptr run(const std::vector<int>& firstRows, int height, int conflictRows,
                           const std::vector<int>& rows, const std::vector<int64>& times, int valid,
                           const Operations& ops);

private:
    // A band's progress: the key of the next operation it has not done yet. Padded to a cache line: each
    // band's thread writes its own after every operation.
    struct BandProgress
    {
        std::atomic<int64> key;
        char padding[64 - sizeof(std::atomic<int64>)];
    };

    void runBand(int band, const std::vector<int>& firstRows, int height, int conflictRows,
                 const std::vector<int>& rows, const std::vector<int64>& times, int valid, const Operations& ops);
    void waitPast(const BandProgress& neighbour, int64 key) const;

    std::unique_ptr<BandProgress[]> progress_;
    int bands_ = 0;
    int spinLimit_ = 64;  // checks of the neighbour's progress before each yield
};

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_STEREO_ROW_BAND_SCHEDULER_HPP
