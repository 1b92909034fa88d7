// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"
#include "zou_descriptor_map.hpp"

namespace cv {
namespace event {

void ZouDescriptorMap::configure(Size size, int descriptorWindow, int maxVectorLength, int margin)
{
    CV_Assert(size.width > 0 && size.height > 0 && descriptorWindow % 2 == 1 && maxVectorLength >= 0 &&
              maxVectorLength <= 7 && margin >= descriptorWindow / 2);
    size_ = size;
    window_ = descriptorWindow;
    maxVectorLength_ = maxVectorLength;
    margin_ = margin;
    stride_ = size.width + 2 * margin;

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
    bins_.clear();
    for (const Offset& o : table)
    {
        offsets_.push_back(o.d);
        // Bin k covers [30k, 30(k+1)) degrees; a tiny nudge keeps exact multiples (0, 30, ...) at the start.
        bins_.push_back((uchar)std::min(BINS - 1, (int)std::floor((o.angle + 1e-9) / (CV_PI / 6))));
    }
    reset();
}

void ZouDescriptorMap::reset()
{
    const size_t ids = 2 * (size_t)size_.area();
    active_.assign(ids, 0);
    nearest_.assign(ids, (uchar)NONE);
    lifetime_.assign(ids, 0.f);
    flow_.assign(ids, Vec2f());
    descriptors_.assign((size_t)stride_ * (size_.height + 2 * margin_) * DESCRIPTOR_BYTES, 0);
    expiry_.reset((int)ids);
}

inline ZouDescriptorMap::VoteWindow ZouDescriptorMap::voteWindow(int x, int y, int p)
{
    const int h = window_ / 2;
    const int x0 = std::max(0, x - h), x1 = std::min(size_.width - 1, x + h);
    const int y0 = std::max(0, y - h), y1 = std::min(size_.height - 1, y + h);
    VoteWindow w;
    w.first = &descriptors_[((size_t)(y0 + margin_) * stride_ + (size_t)(x0 + margin_)) * DESCRIPTOR_BYTES] + p * BINS;
    w.width = x1 - x0 + 1;
    w.height = y1 - y0 + 1;
    return w;
}

void ZouDescriptorMap::vote(int x, int y, int p, int code, int delta)
{
    const VoteWindow w = voteWindow(x, y, p);
    const size_t rowStep = descriptorRowStep();
    uchar* row = w.first;
    const uchar d = (uchar)delta;  // +1 or 255 (-1 modulo 256): counts never go below zero
    if (code == 0)
    {
        for (int yy = 0; yy < w.height; yy++, row += rowStep)
            for (int xx = 0; xx < w.width; xx++)
            {
                uchar* bins = row + (size_t)xx * DESCRIPTOR_BYTES;
                for (int b = 0; b < BINS; b++)
                    bins[b] = (uchar)(bins[b] + d);
            }
        return;
    }
    const int bin = bins_[(size_t)code];
    for (int yy = 0; yy < w.height; yy++, row += rowStep)
        for (int xx = 0; xx < w.width; xx++)
            row[(size_t)xx * DESCRIPTOR_BYTES + bin] = (uchar)(row[(size_t)xx * DESCRIPTOR_BYTES + bin] + d);
}

void ZouDescriptorMap::revote(int x, int y, int p, int oldCode, int newCode)
{
    if (oldCode == NONE || newCode == NONE || oldCode == 0 || newCode == 0)
    {
        if (oldCode != NONE)
            vote(x, y, p, oldCode, -1);
        if (newCode != NONE)
            vote(x, y, p, newCode, +1);
        return;
    }
    // Both are single-bin vectors: move the vote in one pass over the window.
    const VoteWindow w = voteWindow(x, y, p);
    const size_t rowStep = descriptorRowStep();
    uchar* row = w.first;
    const int from = bins_[(size_t)oldCode], to = bins_[(size_t)newCode];
    for (int yy = 0; yy < w.height; yy++, row += rowStep)
        for (int xx = 0; xx < w.width; xx++)
        {
            uchar* bins = row + (size_t)xx * DESCRIPTOR_BYTES;
            bins[from]--;
            bins[to]++;
        }
}

int ZouDescriptorMap::scanNearest(int x, int y, int p, int from) const
{
    for (int k = from; k < (int)offsets_.size(); k++)
    {
        const int qx = x + offsets_[(size_t)k].x, qy = y + offsets_[(size_t)k].y;
        if ((unsigned)qx < (unsigned)size_.width && (unsigned)qy < (unsigned)size_.height && active_[id(qx, qy, p)])
            return k;
    }
    return NONE;
}

void ZouDescriptorMap::activate(int x, int y, int p, int64 expiry, float lifetime, const Vec2f& flow)
{
    const int i = id(x, y, p);
    lifetime_[i] = lifetime;
    flow_[i] = flow;
    expiry_.set(i, expiry);
    if (active_[i])
        return;
    active_[i] = 1;
    // Pixel s sees this event at offset k = (x, y) - s; it becomes s's nearest if closer than the current.
    for (int k = 0; k < (int)offsets_.size(); k++)
    {
        const int sx = x - offsets_[(size_t)k].x, sy = y - offsets_[(size_t)k].y;
        if ((unsigned)sx >= (unsigned)size_.width || (unsigned)sy >= (unsigned)size_.height)
            continue;
        uchar& cur = nearest_[id(sx, sy, p)];
        if (cur != NONE && cur <= k)
            continue;
        revote(sx, sy, p, cur, k);
        cur = (uchar)k;
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
    expiry_.remove(i);
    active_[i] = 0;
    lifetime_[i] = 0.f;
    const int area = size_.area();
    const int p = i / area, x = (i % area) % size_.width, y = (i % area) / size_.width;
    for (int k = 0; k < (int)offsets_.size(); k++)
    {
        const int sx = x - offsets_[(size_t)k].x, sy = y - offsets_[(size_t)k].y;
        if ((unsigned)sx >= (unsigned)size_.width || (unsigned)sy >= (unsigned)size_.height)
            continue;
        uchar& cur = nearest_[id(sx, sy, p)];
        if (cur != k)
            continue;
        // Offsets before k were all inactive (else one of them would be the nearest): search after k.
        cur = (uchar)scanNearest(sx, sy, p, k + 1);
        revote(sx, sy, p, k, cur);
    }
}

void ZouDescriptorMap::expireUntil(int64 t)
{
    while (!expiry_.empty() && expiry_.topTime() <= t)
        deactivateId(expiry_.topId());
}

}  // namespace event
}  // namespace cv
