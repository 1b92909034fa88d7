// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// StereoEventMatcher with look-ahead or on several threads: a packet's admission, then its operations (each
// event's arrival and decision, the expiries) in time order, spread over row bands (RowBandScheduler).

#include "precomp.hpp"
#include "common/timestamp_math.hpp"
#include "stereo/stereo_event_matcher_impl.hpp"

namespace cv {
namespace event {
namespace detail {

// The admission runs here in order (the checks, the rectified pixel and the cold start depend on the events
// before); then the packet's operations (scheduleOperations) run in that order on one thread, or in row bands
// ordered by RowBandScheduler as on one thread.
void StereoEventMatcherImpl::processOperations(const Mat_<Event>& ev, const StoreFn& store)
{
    const int n = (int)ev.total();
    admitted_.resize((size_t)n);
    admittedRows_.resize((size_t)n);
    times_.resize((size_t)n);
    // An event that fails admission ends the packet after the events before it, as on one thread.
    int valid = n;
    std::exception_ptr badEvent;
    for (int i = 0; i < n; i++)
    {
        Admission& a = admitted_[(size_t)i];
        try
        {
            a.rectified = admit(ev(i));
        }
        catch (...)
        {
            badEvent = std::current_exception();
            valid = i;
            break;
        }
        a.coldStartEnd = coldStartEnd_;
        admittedRows_[(size_t)i] = a.rectified.x < 0 ? -1 : a.rectified.y;
        times_[(size_t)i] = ev(i).t;
        if (a.rectified.x < 0)
        {
            StereoEventEstimate outside;
            outside.rectified = a.rectified;
            outside.flags = STEREO_OUTSIDE;
            store(i, outside);
        }
    }
    scheduleOperations(valid);
    const int count = (int)operations_.size();
    // Decision: the event's match, lifetime and final activity (processEvent after admission). Arrival (look-ahead
    // only): the event becomes active in its sensor's map, for the decisions of the events before it.
    // Events decided on a band's thread keep their estimates in its scratch until the bands are done: the
    // outputs of events of both bands share cache lines, which the threads would otherwise pass to and fro.
    auto run = [&](int k, MatchScratch& s, bool keep) {
        const int i = operations_[(size_t)k] >> 1;
        const Event& e = ev(i);
        const Admission& a = admitted_[(size_t)i];
        const int p = e.p ? 1 : 0;
        const size_t pixel = ((size_t)a.rectified.y * params_.sensorSize.width + a.rectified.x) * 2 + p;
        if (!(operations_[(size_t)k] & 1))
        {
            activateUndecided(e.camera, a.rectified, p, e.t);
            pendingEvents_[e.camera][pixel]++;
            return;
        }
        const bool laterPending = params_.lookAhead > 0 && --pendingEvents_[e.camera][pixel] > 0;
        StereoEventEstimate est;
        est.rectified = a.rectified;
        processAdmitted(e, a.rectified, a.coldStartEnd, laterPending, s, est);
        if (keep)
            s.decided.emplace_back(i, est);
        else
            store(i, est);
    };
    std::exception_ptr failure;
    if (params_.numThreads == 1 || n < MIN_EVENTS_FOR_BANDS)
    {
        try
        {
            for (int k = 0; k < count; k++)
            {
                if (operations_[(size_t)k] & 1)
                {
                    maps_[0].expireUntil(operationTimes_[(size_t)k]);
                    maps_[1].expireUntil(operationTimes_[(size_t)k]);
                }
                run(k, scratch_, false);
            }
        }
        catch (...)
        {
            failure = std::current_exception();
        }
        for (int c = 0; c < 2; c++)
            estimators_[c]->addStatusCounts(scratch_.lifetimes[c]);
    }
    else
    {
        const int conflictRows = bandConflictRows();
        const int bands = std::max(1, std::min(params_.numThreads, params_.sensorSize.height / (conflictRows + 1)));
        const std::vector<int> first = RowBandScheduler::splitRows(operationRows_, count, params_.sensorSize.height, bands,
                                                                   conflictRows + 1);
        const std::vector<int> segments = RowBandScheduler::splitSegments(first, params_.sensorSize.height, conflictRows);
        maps_[0].setRowBands(segments);
        maps_[1].setRowBands(segments);
        if (bandScratch_.size() < (size_t)bands)
        {
            bandScratch_.resize((size_t)bands);
            for (MatchScratch& s : bandScratch_)
                sizeScratch(s);
        }
        RowBandScheduler::Operations ops;
        // The segment's earliest expiry over both maps (the left map's first on a tie); the token is the map.
        ops.earliestExpiry = [this](int segment, int64& time, int& row, int& map) {
            bool found = false;
            time = std::numeric_limits<int64>::max();
            for (int c = 0; c < 2; c++)
            {
                int64 t;
                int y;
                if (maps_[c].earliestExpiry(segment, t, y) && t < time)
                {
                    map = c;
                    time = t;
                    row = y;
                    found = true;
                }
            }
            return found;
        };
        ops.expire = [this](int segment, int map) { maps_[map].expireEarliest(segment); };
        ops.process = [&](int b, int k) { run(k, bandScratch_[(size_t)b], true); };
        failure = bands_.run(first, params_.sensorSize.height, conflictRows, operationRows_, operationTimes_, count, ops);
        for (int b = 0; b < bands; b++)
        {
            for (const std::pair<int, StereoEventEstimate>& d : bandScratch_[(size_t)b].decided)
                store(d.first, d.second);
            bandScratch_[(size_t)b].decided.clear();
        }
        for (int b = 0; b < bands; b++)
            for (int c = 0; c < 2; c++)
                estimators_[c]->addStatusCounts(bandScratch_[(size_t)b].lifetimes[c]);
    }
    if (failure)
    {
        // Arrivals after the failure are never decided: none stays pending.
        for (std::vector<int>& pending : pendingEvents_)
            std::fill(pending.begin(), pending.end(), 0);
        std::rethrow_exception(failure);
    }
    if (badEvent)
        std::rethrow_exception(badEvent);
}

// The operations of the first `valid` admitted events, in the order one thread runs them, with their rows and
// times (the scheduler takes the expiries due before the first operation at or after their time: the single
// thread's expiries before a decision). Without look-ahead an event is decided when it arrives. With it, an
// event arrives (becomes active in its map) in stream order and is decided once an event more than
// params_.lookAhead later has arrived, or at the end of the packet; an arrival carries the time of the decision
// before it, so that no expiry moves before it.
void StereoEventMatcherImpl::scheduleOperations(int valid)
{
    operations_.clear();
    operationRows_.clear();
    operationTimes_.clear();
    auto add = [&](int i, bool decide, int64 t) {
        operations_.push_back(i * 2 + (decide ? 1 : 0));
        operationRows_.push_back(admittedRows_[(size_t)i]);
        operationTimes_.push_back(t);
    };
    if (params_.lookAhead == 0)
    {
        for (int i = 0; i < valid; i++)
            if (admittedRows_[(size_t)i] >= 0)
                add(i, true, times_[(size_t)i]);
        return;
    }
    // The events arrive and are decided in index order (times do not decrease): the undecided ones are the
    // events from `next` to the last arrival, those outside the image aside.
    int64 decided = std::numeric_limits<int64>::min();
    int next = 0;
    // Decides the events before `end` that are due when an event arrives at `arrival`; all of them at the end.
    auto decideUntil = [&](int end, int64 arrival, bool all) {
        for (; next < end && (all || admittedRows_[(size_t)next] < 0 || timeAfter(times_[(size_t)next], params_.lookAhead) < arrival);
             next++)
            if (admittedRows_[(size_t)next] >= 0)
            {
                decided = times_[(size_t)next];
                add(next, true, decided);
            }
    };
    for (int j = 0; j < valid; j++)
        if (admittedRows_[(size_t)j] >= 0)
        {
            decideUntil(j, times_[(size_t)j], false);
            add(j, false, decided);
        }
    decideUntil(valid, 0, true);
}

}  // namespace detail
}  // namespace event
}  // namespace cv
