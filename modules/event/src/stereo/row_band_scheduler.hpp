// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_STEREO_ROW_BAND_SCHEDULER_HPP
#define OPENCV_EVENT_SRC_STEREO_ROW_BAND_SCHEDULER_HPP

#include "opencv2/core.hpp"

#include <atomic>
#include <exception>
#include <functional>
#include <limits>
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
(conflictRows: the largest write reach + the largest reach of any access). Bands are more than conflictRows
tall, so only neighbours can conflict, and only operations in the conflictRows rows on either side of their
boundary (the boundary's zone).

An operation in a zone waits until the neighbouring band has done every operation with a smaller key that it
could conflict with: every event in the neighbour's rows within conflictRows of its own row, and every
expiry in the neighbour's side of the zone. Each band publishes, for each row of its zones, the key of its
next event there, and for each zone the key of its next expiry there; those are the only figures a waiting
band reads, and they change only when the band does an operation in that zone. So a band runs its other
operations, and its zone operations that no earlier operation of the neighbour is near, without waiting.
The expiries are kept in one heap per segment of rows (splitSegments: each band's zones apart from the rest
of it), so that a zone's next expiry is known. Two bands never wait on each other at once: the smaller of
the two keys goes first.

The scheduler knows rows, times and keys only; what an operation does comes through Operations. */
class RowBandScheduler
{
public:
    /** The caller's operations, called on the thread of the band that holds @p segment or @p event. */
    struct Operations
    {
        /** The earliest pending expiry of the pixels of segment @p segment (splitSegments): its time, its
        row and a token for expire(); false when none is pending. */
        std::function<bool(int segment, int64& time, int& row, int& token)> earliestExpiry;
        /** Carries out the expiry earliestExpiry() returned for @p segment with @p token. */
        std::function<void(int segment, int token)> expire;
        /** Processes event @p event, whose row lies in band @p band. */
        std::function<void(int band, int event)> process;
    };

    /** First rows of @p bands bands of at least @p minHeight rows each over an image of @p height rows, each
    holding about as many of the first @p valid events; @p rows holds each event's row, -1 for an event that
    is not processed. */
    static std::vector<int> splitRows(const std::vector<int>& rows, int valid, int height, int bands, int minHeight);

    /** First rows of the segments whose expiries run() keeps apart: each band of @p firstRows cut where its
    zones (the @p conflictRows rows next to a neighbouring band) begin and end. The caller keeps one expiry heap
    per segment (Operations::earliestExpiry). */
    static std::vector<int> splitSegments(const std::vector<int>& firstRows, int height, int conflictRows);

    /** Runs the first @p valid events (@p rows and @p times as for splitRows; times non-decreasing) and the
    expiries due before the last of them on one thread per band (@p firstRows from splitRows with a minimum
    height above @p conflictRows, one band on the calling thread; the expiries by the segments of
    splitSegments). @p conflictRows: two operations (events or expiries) whose rows are further apart never
    touch data that one of them writes. Returns once every band is done, with the first failure of any band
    (null when none): a failed band stops, the others finish. */
    std::exception_ptr run(const std::vector<int>& firstRows, int height, int conflictRows,
                           const std::vector<int>& rows, const std::vector<int64>& times, int valid,
                           const Operations& ops);

private:
    // A published key, padded to a cache line: a zone's next expiry.
    struct PaddedKey
    {
        std::atomic<int64> key;
        char padding[64 - sizeof(std::atomic<int64>)];
    };
    // A band's rows and segments. zoneEnd[0]: the end of its top zone (its first row when it has none);
    // zoneBegin[1]: the start of its bottom zone (its end when it has none).
    struct Band
    {
        int top = 0, bottom = 0;
        int zoneEnd[2] = { 0, 0 }, zoneBegin[2] = { 0, 0 };
        std::vector<int> segments;         // its segments, top to bottom
        std::vector<int> segmentEnd;       // the row after each
        std::vector<uchar> segmentInZone[2];  // each holds rows of its top [0] / bottom [1] zone
    };

    // Key of event `event` (event x (bands + 1) + bands: after the expiries at its position); the largest int64
    // for -1 (none).
    int64 eventKey(int event) const
    {
        return event >= 0 ? (int64)event * stride_ + (stride_ - 1) : std::numeric_limits<int64>::max();
    }
    void runBand(int band, int conflictRows, const std::vector<int>& rows, const std::vector<int64>& times,
                 int valid, const Operations& ops);
    // Key of the segment's earliest expiry (with its row and token); the largest int64 when none is due in the
    // packet.
    int64 expiryKey(int segment, int band, const std::vector<int64>& times, int valid, const Operations& ops,
                    int& row, int& token) const;
    // The next expiry key over the segments of band b's zone z (0 top, 1 bottom).
    int64 zoneExpiryKey(int b, int z, const std::vector<int64>& times, int valid, const Operations& ops) const;
    // Waits until band b's neighbour on side z (0: above, 1: below) has done every operation with a key below
    // `key` that an operation in row y could conflict with.
    void waitForNeighbour(int b, int z, int y, int64 key, int conflictRows) const;
    void waitPast(const std::atomic<int64>& published, int64 key) const;
    // Publishes "nothing left" for every row and zone of band b.
    void publishDone(int b);

    std::vector<Band> bands_;
    int height_ = 0;
    int stride_ = 1;
    // Per image row, for the rows in a zone: the key of its band's next event in that row.
    std::unique_ptr<std::atomic<int64>[]> rowNext_;
    std::vector<int> nextInRow_;                 // per event: the next event in its row, -1 when none
    std::unique_ptr<PaddedKey[]> zoneNext_;      // per band and zone (b * 2 + z): the key of its next expiry
    int spinLimit_ = 64;  // checks of a published key before each yield
};

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_STEREO_ROW_BAND_SCHEDULER_HPP
