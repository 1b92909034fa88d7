// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The live DAVIS word decoder, per sensor size: what one reader thread can sustain (events / s) while the
// camera streams, transfer by transfer (8 KiB, as the back-end reads them).

#include "perf_precomp.hpp"
#include "davis/davis_event_decoder.hpp"

namespace opencv_test { namespace {

// Words as a DAVIS sends them for random events at about 1 Mev/s: timestamp, Y, X words and clock wraps.
std::vector<uint8_t> davisStream(int n, Size sensor)
{
    RNG rng(4242);
    std::vector<uint8_t> bytes;
    auto word = [&](unsigned w) { bytes.push_back((uint8_t)w); bytes.push_back((uint8_t)(w >> 8)); };
    int64 t = 0, base = 0;
    for (int i = 0; i < n; i++)
    {
        t += rng.uniform(0, 3);
        if (t - base >= 0x8000)
        {
            word(0x7001);
            base += 0x8000;
        }
        word(0x8000u | (unsigned)(t - base));
        word(0x1000u | (unsigned)rng.uniform(0, sensor.height));
        word((rng.uniform(0, 2) ? 0x3000u : 0x2000u) | (unsigned)rng.uniform(0, sensor.width));
    }
    return bytes;
}

typedef TestBaseWithParam<Size> Event_DavisDecoder;

PERF_TEST_P(Event_DavisDecoder, decode_1M_events, testing::Values(Size(240, 180), Size(346, 260)))
{
    const Size sensor = GetParam();
    const std::vector<uint8_t> bytes = davisStream(1000000, sensor);
    std::vector<Event> out;
    out.reserve(1000000);
    TEST_CYCLE()
    {
        out.clear();
        cv::event::detail::DavisEventDecoder decoder(sensor.width, sensor.height, false, false);
        for (size_t pos = 0; pos < bytes.size(); pos += 8192)
            decoder.decode(bytes.data() + pos, std::min((size_t)8192, bytes.size() - pos), out);
    }
    ASSERT_EQ(1000000u, out.size());
    SANITY_CHECK_NOTHING();
}

}} // namespace
