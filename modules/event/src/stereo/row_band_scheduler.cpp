// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"
#include "stereo/row_band_scheduler.hpp"

#include <limits>
#include <thread>

namespace cv {
namespace event {
namespace detail {

namespace {

const int64 NONE_LEFT = std::numeric_limits<int64>::max();

// A band's view of its segments' earliest expiries, refreshed only after an operation in the segment (an
// expiry taken, or an event that (de)activates its pixel there): the heaps change only then.
struct SegmentCache
{
    enum { MAX_SEGMENTS = 3 };
    int64 key[MAX_SEGMENTS];
    int row[MAX_SEGMENTS];
    int token[MAX_SEGMENTS];
    bool fresh[MAX_SEGMENTS];
};

}  // namespace

std::vector<int> RowBandScheduler::splitRows(const std::vector<int>& rows, int valid, int height, int bands, int minHeight)
{
    std::vector<int> upTo((size_t)height + 1, 0);  // upTo[y + 1]: processed events in rows <= y
    for (int i = 0; i < valid; i++)
        if (rows[(size_t)i] >= 0)
            upTo[(size_t)rows[(size_t)i] + 1]++;
    for (int y = 0; y < height; y++)
        upTo[(size_t)y + 1] += upTo[(size_t)y];
    const int64 total = upTo.back();
    std::vector<int> first(1, 0);
    for (int b = 1; b < bands; b++)
    {
        const int64 target = total * b / bands;
        const int y = (int)(std::lower_bound(upTo.begin(), upTo.end(), target) - upTo.begin());
        first.push_back(std::min(std::max(y, first.back() + minHeight), height - (bands - b) * minHeight));
    }
    return first;
}

std::vector<int> RowBandScheduler::splitSegments(const std::vector<int>& firstRows, int height, int conflictRows)
{
    const int bands = (int)firstRows.size();
    std::vector<int> first;
    for (int b = 0; b < bands; b++)
    {
        const int top = firstRows[(size_t)b], bottom = b + 1 < bands ? firstRows[(size_t)b + 1] : height;
        std::vector<int> cuts(1, top);
        if (b > 0 && top + conflictRows < bottom)
            cuts.push_back(top + conflictRows);
        if (b + 1 < bands && bottom - conflictRows > top)
            cuts.push_back(bottom - conflictRows);
        std::sort(cuts.begin(), cuts.end());
        cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
        first.insert(first.end(), cuts.begin(), cuts.end());
    }
    return first;
}

std::exception_ptr RowBandScheduler::run(const std::vector<int>& firstRows, int height, int conflictRows,
                                         const std::vector<int>& rows, const std::vector<int64>& times, int valid,
                                         const Operations& ops)
{
    const int bands = (int)firstRows.size();
    stride_ = bands + 1;
    if (height != height_)
    {
        rowNext_.reset(new std::atomic<int64>[(size_t)height]);
        height_ = height;
    }
    if (bands_.size() != (size_t)bands)
        zoneNext_.reset(new PaddedKey[2 * (size_t)bands]);
    bands_.assign((size_t)bands, Band());
    const std::vector<int> segments = splitSegments(firstRows, height, conflictRows);
    for (int b = 0; b < bands; b++)
    {
        Band& band = bands_[(size_t)b];
        band.top = firstRows[(size_t)b];
        band.bottom = b + 1 < bands ? firstRows[(size_t)b + 1] : height;
        band.zoneEnd[0] = b > 0 ? std::min(band.top + conflictRows, band.bottom) : band.top;
        band.zoneBegin[1] = b + 1 < bands ? std::max(band.bottom - conflictRows, band.top) : band.bottom;
        for (int s = 0; s < (int)segments.size(); s++)
        {
            const int begin = segments[(size_t)s], end = s + 1 < (int)segments.size() ? segments[(size_t)s + 1] : height;
            if (begin < band.top || begin >= band.bottom)
                continue;
            band.segments.push_back(s);
            band.segmentEnd.push_back(end);
            band.segmentInZone[0].push_back(begin < band.zoneEnd[0]);
            band.segmentInZone[1].push_back(end > band.zoneBegin[1]);
        }
        CV_Assert(!band.segments.empty() && band.segments.size() <= (size_t)SegmentCache::MAX_SEGMENTS);
    }
    // Each row's first event, and each event's next one in its row.
    nextInRow_.assign((size_t)valid, -1);
    std::vector<int> firstInRow((size_t)height, -1);
    for (int i = valid - 1; i >= 0; i--)
    {
        const int y = rows[(size_t)i];
        if (y < 0)
            continue;
        nextInRow_[(size_t)i] = firstInRow[(size_t)y];
        firstInRow[(size_t)y] = i;
    }
    for (int y = 0; y < height; y++)
        rowNext_[(size_t)y].store(eventKey(firstInRow[(size_t)y]), std::memory_order_relaxed);
    for (int b = 0; b < bands; b++)
        for (int z = 0; z < 2; z++)
            zoneNext_[(size_t)b * 2 + z].key.store(zoneExpiryKey(b, z, times, valid, ops), std::memory_order_relaxed);
    // With a core for every band a waiting band spins: the neighbour it waits for is running, and a yield
    // (a system call) costs more than the wait. With more bands than cores it yields soon, so that the band it
    // waits for gets the core.
    spinLimit_ = bands <= getNumberOfCPUs() ? 1 << 17 : 64;
    std::vector<std::exception_ptr> failures((size_t)bands);
    auto runOne = [&](int b) {
        try
        {
            runBand(b, conflictRows, rows, times, valid, ops);
        }
        catch (...)
        {
            failures[(size_t)b] = std::current_exception();
        }
        // Done (or failed): never keep the neighbours waiting.
        publishDone(b);
    };
    std::vector<std::thread> threads;
    for (int b = 1; b < bands; b++)
        threads.emplace_back(runOne, b);
    runOne(0);
    for (std::thread& t : threads)
        t.join();
    for (const std::exception_ptr& f : failures)
        if (f)
            return f;
    return std::exception_ptr();
}

int64 RowBandScheduler::expiryKey(int segment, int band, const std::vector<int64>& times, int valid,
                                  const Operations& ops, int& row, int& token) const
{
    int64 time = 0;
    if (!ops.earliestExpiry(segment, time, row, token))
        return NONE_LEFT;
    const int64 position = std::lower_bound(times.begin(), times.begin() + valid, time) - times.begin();
    return position < valid ? position * stride_ + band : NONE_LEFT;
}

int64 RowBandScheduler::zoneExpiryKey(int b, int z, const std::vector<int64>& times, int valid,
                                      const Operations& ops) const
{
    const Band& band = bands_[(size_t)b];
    int64 key = NONE_LEFT;
    int row = 0, token = 0;
    for (size_t k = 0; k < band.segments.size(); k++)
        if (band.segmentInZone[z][k])
            key = std::min(key, expiryKey(band.segments[k], b, times, valid, ops, row, token));
    return key;
}

void RowBandScheduler::runBand(int b, int conflictRows, const std::vector<int>& rows, const std::vector<int64>& times,
                               int valid, const Operations& ops)
{
    const Band& me = bands_[(size_t)b];
    const int segmentCount = (int)me.segments.size();
    SegmentCache cache;
    for (int k = 0; k < segmentCount; k++)
        cache.fresh[k] = false;
    // Local segment k's earliest expiry key, looked up again only after an operation in the segment.
    auto segmentKey = [&](int k) {
        if (!cache.fresh[k])
        {
            cache.key[k] = expiryKey(me.segments[(size_t)k], b, times, valid, ops, cache.row[k], cache.token[k]);
            cache.fresh[k] = true;
        }
        return cache.key[k];
    };
    int i = 0;
    for (;;)
    {
        while (i < valid && !(rows[(size_t)i] >= me.top && rows[(size_t)i] < me.bottom))
            i++;
        const int64 nextEventKey = eventKey(i < valid ? i : -1);
        int earliest = -1;
        for (int k = 0; k < segmentCount; k++)
            if (segmentKey(k) != NONE_LEFT && (earliest < 0 || cache.key[k] < cache.key[earliest]))
                earliest = k;
        const int64 expiryKeyNow = earliest >= 0 ? cache.key[earliest] : NONE_LEFT;
        const int64 key = std::min(nextEventKey, expiryKeyNow);
        if (key == NONE_LEFT)
            break;
        const bool isExpiry = expiryKeyNow < nextEventKey;
        const int y = isExpiry ? cache.row[earliest] : rows[(size_t)i];
        // An expiry outside its band would break the waits (and hang them): the caller's heaps must follow
        // splitSegments.
        CV_Assert(y >= me.top && y < me.bottom);
        const bool inZone[2] = { y < me.zoneEnd[0], y >= me.zoneBegin[1] };
        for (int z = 0; z < 2; z++)
            if (inZone[z])
                waitForNeighbour(b, z, y, key, conflictRows);
        if (isExpiry)
        {
            ops.expire(me.segments[(size_t)earliest], cache.token[earliest]);
            cache.fresh[earliest] = false;
        }
        else
        {
            ops.process(b, i);
            // The event's pixel may have been (de)activated: its segment's heap changed.
            int k = 0;
            while (y >= me.segmentEnd[(size_t)k])
                k++;
            cache.fresh[k] = false;
        }
        // Publish what changed in a zone: its next expiry, then (an event) its row's next event, so that a
        // neighbour that sees the row's new key also sees the expiry the event may have added.
        for (int z = 0; z < 2; z++)
            if (inZone[z])
            {
                int64 next = NONE_LEFT;
                for (int k = 0; k < segmentCount; k++)
                    if (me.segmentInZone[z][(size_t)k])
                        next = std::min(next, segmentKey(k));
                zoneNext_[(size_t)b * 2 + z].key.store(next, std::memory_order_release);
            }
        if (!isExpiry)
        {
            if (inZone[0] || inZone[1])
                rowNext_[(size_t)y].store(eventKey(nextInRow_[(size_t)i]), std::memory_order_release);
            i++;
        }
    }
}

void RowBandScheduler::waitForNeighbour(int b, int z, int y, int64 key, int conflictRows) const
{
    const int neighbour = z == 0 ? b - 1 : b + 1;
    const Band& me = bands_[(size_t)b];
    const Band& other = bands_[(size_t)neighbour];
    // The neighbour's rows within conflictRows of y: its events there first, then its zone's expiries (an
    // event's new expiry is published before the row's key).
    const int first = z == 0 ? std::max(other.top, y - conflictRows) : me.bottom;
    const int last = z == 0 ? me.top - 1 : std::min(other.bottom - 1, y + conflictRows);
    for (int row = first; row <= last; row++)
        waitPast(rowNext_[(size_t)row], key);
    waitPast(zoneNext_[(size_t)neighbour * 2 + (1 - z)].key, key);
}

void RowBandScheduler::waitPast(const std::atomic<int64>& published, int64 key) const
{
    for (int spins = 0; published.load(std::memory_order_acquire) <= key; spins++)
        if (spins >= spinLimit_)
            std::this_thread::yield();
}

void RowBandScheduler::publishDone(int b)
{
    const Band& me = bands_[(size_t)b];
    for (int z = 0; z < 2; z++)
        zoneNext_[(size_t)b * 2 + z].key.store(NONE_LEFT, std::memory_order_release);
    for (int y = me.top; y < me.bottom; y++)
        rowNext_[(size_t)y].store(NONE_LEFT, std::memory_order_release);
}

}  // namespace detail
}  // namespace event
}  // namespace cv
