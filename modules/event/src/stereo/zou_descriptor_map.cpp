// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"
#include "stereo/zou_descriptor_map.hpp"
#include "common/prefetch.hpp"

namespace cv {
namespace event {
namespace detail {

void ZouDescriptorMap::configure(Size size, int descriptorWindow, int maxVectorLength, int margin)
{
    CV_Assert(size.width > 0 && size.height > 0 && descriptorWindow % 2 == 1 && maxVectorLength >= 0 &&
              maxVectorLength <= 7 && margin >= descriptorWindow / 2);
    size_ = size;
    window_ = descriptorWindow;
    maxVectorLength_ = maxVectorLength;
    margin_ = margin;
    stride_ = size.width + 2 * margin;
    border_ = maxVectorLength;
    paddedWidth_ = size.width + 2 * border_;
    paddedHeight_ = size.height + 2 * border_;

    struct Offset
    {
        Point d;
        int length2;
        double angle;
    };
    std::vector<Offset> table;
    const int r = maxVectorLength;
    for (int dy = -r; dy <= r; dy++)
        for (int dx = -r; dx <= r; dx++)
            if (dx * dx + dy * dy <= r * r)
            {
                double angle = std::atan2((double)dy, (double)dx);
                if (angle < 0)
                    angle += 2 * CV_PI;
                table.push_back(Offset{ Point(dx, dy), dx * dx + dy * dy, angle });
            }
    std::sort(table.begin(), table.end(), [](const Offset& a, const Offset& b) {
        return a.length2 != b.length2 ? a.length2 < b.length2 : a.angle < b.angle;
    });
    CV_Assert(table.size() < NONE);
    offsets_.clear();
    idOffsets_.clear();
    bins_.clear();
    voteOffsets_.clear();
    const int h = descriptorWindow / 2;
    for (const Offset& o : table)
    {
        offsets_.push_back(o.d);
        idOffsets_.push_back(o.d.y * paddedWidth_ + o.d.x);
        // The pixel that sees the event at offset d is at -d from it; its window starts h further up and left.
        voteOffsets_.push_back(((ptrdiff_t)(-o.d.y - h) * stride_ + (-o.d.x - h)) * DESCRIPTOR_BYTES);
        // Bin k covers [30k, 30(k+1)) degrees; a tiny nudge keeps exact multiples (0, 30, ...) at the start.
        bins_.push_back((uchar)std::min(BINS - 1, (int)std::floor((o.angle + 1e-9) / (CV_PI / 6))));
    }
    reset();
}

void ZouDescriptorMap::reset()
{
    const size_t ids = 2 * (size_t)paddedWidth_ * paddedHeight_;
    active_.assign(ids, 0);
    // Border pixels: offset 0, which no update passes (activate skips codes <= k, deactivate needs code == k > 0
    // off the event's own pixel, which is inside).
    nearest_.assign(ids, 0);
    for (int p = 0; p < 2; p++)
        for (int y = 0; y < size_.height; y++)
            std::fill_n(&nearest_[(size_t)id(0, y, p)], size_.width, (uchar)NONE);
    time_.assign(ids, 0);
    lifetime_.assign(ids, 0.f);
    flow_.assign(ids, Vec2f());
    copies_.assign(ids, 0);
    descriptors_.assign((size_t)stride_ * (size_.height + 2 * margin_) * DESCRIPTOR_BYTES, 0);
    if (bandFirstRow_.empty() || bandFirstRow_.back() >= size_.height)
        bandFirstRow_.assign(1, 0);
    resetExpiries();
}

void ZouDescriptorMap::assignRowBands()
{
    rowBand_.assign((size_t)size_.height, 0);
    for (size_t b = 1; b < bandFirstRow_.size(); b++)
        std::fill(rowBand_.begin() + bandFirstRow_[b], rowBand_.end(), (uchar)b);
}

void ZouDescriptorMap::resetExpiries()
{
    assignRowBands();
    expiry_.resize(bandFirstRow_.size());
    for (size_t b = 0; b < expiry_.size(); b++)
        resetHeap(b);
}

void ZouDescriptorMap::resetHeap(size_t b)
{
    // Room for every pixel and polarity of the band's rows: a band's heap never grows while its rows stay.
    const int end = b + 1 < bandFirstRow_.size() ? bandFirstRow_[b + 1] : size_.height;
    expiry_[b].reset((int)active_.size(), (size_t)(end - bandFirstRow_[b]) * (size_t)size_.width * 2);
}

void ZouDescriptorMap::setRowBands(const std::vector<int>& firstRows)
{
    CV_Assert(!firstRows.empty() && firstRows[0] == 0 && firstRows.size() <= 256 && firstRows.back() < size_.height);
    for (size_t b = 1; b < firstRows.size(); b++)
        CV_Assert(firstRows[b] > firstRows[b - 1]);
    if (firstRows == bandFirstRow_)
        return;
    // Move the pending expiries whose band changed to the heaps of their new bands; the heaps stay (the row
    // bands move a little with every packet, and a heap's reset writes a slot for every pixel).
    bandFirstRow_ = firstRows;
    assignRowBands();
    std::vector<std::pair<int, int64>> moving;
    for (size_t b = 0; b < expiry_.size(); b++)
    {
        ExpiryHeap& heap = expiry_[b];
        const size_t first = moving.size();
        for (size_t i = 0; i < heap.size(); i++)
            if ((size_t)bandOfRow(rowOf(heap.idAt(i))) != b)
                moving.emplace_back(heap.idAt(i), heap.timeAt(i));
        for (size_t i = first; i < moving.size(); i++)
            heap.remove(moving[i].first);
    }
    const size_t before = expiry_.size();
    expiry_.resize(bandFirstRow_.size());
    for (size_t b = before; b < expiry_.size(); b++)
        resetHeap(b);
    for (const std::pair<int, int64>& e : moving)
        heapOfRow(rowOf(e.first)).set(e.first, e.second);
}

bool ZouDescriptorMap::earliestExpiry(int band, int64& time, int& row) const
{
    const ExpiryHeap& heap = expiry_[(size_t)band];
    if (heap.empty())
        return false;
    time = heap.topTime();
    row = rowOf(heap.topId());
    return true;
}

void ZouDescriptorMap::expireEarliest(int band)
{
    deactivateId(expiry_[(size_t)band].topId());
}

ZouDescriptorMap::VotedWindow ZouDescriptorMap::votedWindow(int x, int y, int p)
{
    const int h = window_ / 2;
    const int x0 = std::max(0, x - h), x1 = std::min(size_.width - 1, x + h);
    const int y0 = std::max(0, y - h), y1 = std::min(size_.height - 1, y + h);
    return VotedWindow{ bins(x0, y0, p), x1 - x0 + 1, y1 - y0 + 1 };
}

template <typename Op>
inline void ZouDescriptorMap::forEachVoted(const VotedWindow& w, Op op)
{
    const size_t rowStep = descriptorRowStep();
    uchar* row = w.topLeft;
    if (w.width == 3 && w.height == 3)
    {
        // The default 3 x 3 window away from the border: a fixed loop the compiler unrolls (votes are a fifth of
        // the matcher's instructions, mostly loop control around one or two byte updates).
        for (int yy = 0; yy < 3; yy++, row += rowStep)
            for (int xx = 0; xx < 3; xx++)
                op(row + xx * DESCRIPTOR_BYTES);
        return;
    }
    for (int yy = 0; yy < w.height; yy++, row += rowStep)
        for (int xx = 0; xx < w.width; xx++)
            op(row + (size_t)xx * DESCRIPTOR_BYTES);
}

void ZouDescriptorMap::vote(const VotedWindow& w, int code, int delta)
{
    const uchar d = (uchar)delta;  // +1 or 255 (-1 modulo 256): counts never go below zero
    if (code == 0)
    {
        forEachVoted(w, [d](uchar* bins) {
            for (int b = 0; b < BINS; b++)
                bins[b] = (uchar)(bins[b] + d);
        });
        return;
    }
    const int bin = bins_[(size_t)code];
    forEachVoted(w, [d, bin](uchar* bins) { bins[bin] = (uchar)(bins[bin] + d); });
}

inline void ZouDescriptorMap::revote(const VotedWindow& w, int oldCode, int newCode)
{
    if (oldCode == NONE || newCode == NONE || oldCode == 0 || newCode == 0)
    {
        if (oldCode != NONE)
            vote(w, oldCode, -1);
        if (newCode != NONE)
            vote(w, newCode, +1);
        return;
    }
    // Both are single-bin vectors: move the vote in one pass over the window.
    const int from = bins_[(size_t)oldCode], to = bins_[(size_t)newCode];
    forEachVoted(w, [from, to](uchar* bins) {
        bins[from]--;
        bins[to]++;
    });
}

int ZouDescriptorMap::scanNearest(int i, int from) const
{
    const uchar* active = &active_[(size_t)i];
    for (int k = from; k < (int)idOffsets_.size(); k++)
        if (active[idOffsets_[(size_t)k]])
            return k;
    return NONE;
}

void ZouDescriptorMap::activate(int x, int y, int p, int64 time, int64 expiry, float lifetime, const Vec2f& flow, int copies)
{
    const int i = id(x, y, p);
    time_[i] = time;
    lifetime_[i] = lifetime;
    flow_[i] = flow;
    copies_[i] = (uchar)std::min(copies, 254);
    heapOfRow(y).set(i, expiry);
    if (active_[i])
        return;
    active_[i] = 1;
    // Pixel s sees this event at offset k = (x, y) - s; it becomes s's nearest if closer than the current
    // (NONE is larger than every offset; border pixels hold 0 and are skipped).
    uchar* nearest = &nearest_[(size_t)i];
    const bool interior = isInterior(x, y);
    uchar* const eventBins = bins(x, y, p);
    for (int k = 0; k < (int)idOffsets_.size(); k++)
    {
        uchar& cur = nearest[-idOffsets_[(size_t)k]];
        if (cur <= k)
            continue;
        revote(windowSeeing(x, y, p, k, interior, eventBins), cur, k);
        cur = (uchar)k;
    }
}

void ZouDescriptorMap::prefetchLifetimes(int x0, int x1, int y0, int y1, int p) const
{
    for (int y = y0; y <= y1; y++)
    {
        const size_t first = (size_t)id(x0, y, p), last = (size_t)id(x1, y, p);
        prefetchRange(&lifetime_[first], &lifetime_[last] + 1);
        prefetchRange(&flow_[first], &flow_[last] + 1);
        prefetchRange(&copies_[first], &copies_[last] + 1);
    }
}

void ZouDescriptorMap::deactivate(int x, int y, int p)
{
    const int i = id(x, y, p);
    if (active_[i])
        deactivateId(i);
}

void ZouDescriptorMap::deactivateId(int i)
{
    const int plane = paddedWidth_ * paddedHeight_;
    const int p = i / plane, x = (i % plane) % paddedWidth_ - border_, y = (i % plane) / paddedWidth_ - border_;
    heapOfRow(y).remove(i);
    active_[i] = 0;
    lifetime_[i] = 0.f;
    const bool interior = isInterior(x, y);
    uchar* const eventBins = bins(x, y, p);
    for (int k = 0; k < (int)idOffsets_.size(); k++)
    {
        const int s = i - idOffsets_[(size_t)k];
        uchar& cur = nearest_[(size_t)s];
        if (cur != k)
            continue;
        // Offsets before k were all inactive (else one of them would be the nearest): search after k.
        cur = (uchar)scanNearest(s, k + 1);
        revote(windowSeeing(x, y, p, k, interior, eventBins), k, cur);
    }
}

void ZouDescriptorMap::expireUntil(int64 t)
{
    // Band by band: the state after these expiries does not depend on their order.
    for (ExpiryHeap& heap : expiry_)
        while (!heap.empty() && heap.topTime() <= t)
            deactivateId(heap.topId());
}

}  // namespace detail
}  // namespace event
}  // namespace cv
