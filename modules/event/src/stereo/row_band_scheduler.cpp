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

std::exception_ptr RowBandScheduler::run(const std::vector<int>& firstRows, int height, int conflictRows,
                                         const std::vector<int>& rows, const std::vector<int64>& times, int valid,
                                         const Operations& ops)
{
    const int bands = (int)firstRows.size();
    if (bands != bands_)
    {
        progress_.reset(new BandProgress[(size_t)bands]);
        bands_ = bands;
    }
    for (int b = 0; b < bands; b++)
        progress_[(size_t)b].key.store(-1, std::memory_order_relaxed);
    // With a core for every band a waiting band spins: the neighbour it waits for is running, and a yield
    // (a system call) costs more than the wait. With more bands than cores it yields soon, so that the band it
    // waits for gets the core.
    spinLimit_ = bands <= getNumberOfCPUs() ? 1 << 17 : 64;
    std::vector<std::exception_ptr> failures((size_t)bands);
    auto runOne = [&](int b) {
        try
        {
            runBand(b, firstRows, height, conflictRows, rows, times, valid, ops);
        }
        catch (...)
        {
            failures[(size_t)b] = std::current_exception();
        }
        // Done (or failed): never keep the neighbours waiting.
        progress_[(size_t)b].key.store(std::numeric_limits<int64>::max(), std::memory_order_release);
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

void RowBandScheduler::runBand(int b, const std::vector<int>& firstRows, int height, int conflictRows,
                               const std::vector<int>& rows, const std::vector<int64>& times, int valid,
                               const Operations& ops)
{
    const int bands = (int)firstRows.size();
    const int top = firstRows[(size_t)b], bottom = b + 1 < bands ? firstRows[(size_t)b + 1] : height;
    const int64 stride = bands + 1, none = std::numeric_limits<int64>::max();
    BandProgress& mine = progress_[(size_t)b];
    // Waits until the neighbours that may hold an operation within conflictRows of row y are past `key`.
    auto waitForNeighbours = [&](int y, int64 key) {
        if (b > 0 && y < top + conflictRows)
            waitPast(progress_[(size_t)b - 1], key);
        if (b + 1 < bands && y >= bottom - conflictRows)
            waitPast(progress_[(size_t)b + 1], key);
    };
    int i = 0;
    for (;;)
    {
        while (i < valid && !(rows[(size_t)i] >= top && rows[(size_t)i] < bottom))
            i++;
        const int64 eventKey = i < valid ? (int64)i * stride + bands : none;
        int64 expiryKey = none, expiryTime = none;
        int expiryRow = 0, token = -1;
        if (ops.earliestExpiry(b, expiryTime, expiryRow, token))
        {
            const int64 position = std::lower_bound(times.begin(), times.begin() + valid, expiryTime) - times.begin();
            if (position < valid)
                expiryKey = position * stride + b;
        }
        const int64 key = std::min(eventKey, expiryKey);
        if (key == none)
            break;
        mine.key.store(key, std::memory_order_release);
        if (expiryKey < eventKey)
        {
            waitForNeighbours(expiryRow, key);
            ops.expire(b, token);
            continue;
        }
        waitForNeighbours(rows[(size_t)i], key);
        ops.process(b, i);
        i++;
    }
}

void RowBandScheduler::waitPast(const BandProgress& neighbour, int64 key) const
{
    for (int spins = 0; neighbour.key.load(std::memory_order_acquire) <= key; spins++)
        if (spins >= spinLimit_)
            std::this_thread::yield();
}

}  // namespace detail
}  // namespace event
}  // namespace cv
