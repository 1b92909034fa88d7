// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The DAVIS data-endpoint decoder on crafted word streams: every word type, wraps, resets, orientation,
// invalid addresses, odd bytes and transfer boundaries anywhere.

#include "test_precomp.hpp"
#include "davis_test_words.hpp"
#include "davis/davis_event_decoder.hpp"

namespace opencv_test { namespace {

using cv::event::detail::DavisEventDecoder;
using namespace davis_words;

std::vector<Event> decodeAll(DavisEventDecoder& d, const std::vector<uint8_t>& bytes)
{
    std::vector<Event> out;
    d.decode(bytes.data(), bytes.size(), out);
    return out;
}

TEST(Event_DavisDecoder, events_take_the_time_of_the_last_timestamp_word)
{
    WordStream s;
    s.word(timestampWord(100)).word(rowWord(7)).word(columnWord(12, 1)).word(columnWord(13, 0));
    s.word(timestampWord(250)).word(columnWord(14, 1));  // same row as before: Y is remembered
    s.word(rowWord(8)).word(columnWord(3, 0));
    DavisEventDecoder d(346, 260, false, false);
    const std::vector<Event> ev = decodeAll(d, s.bytes);
    const std::vector<Event> expected = { Event(100, 12, 7, 1), Event(100, 13, 7, 0), Event(250, 14, 7, 1),
                                          Event(250, 3, 8, 0) };
    EXPECT_EQ(expected, ev);
    EXPECT_EQ(4, d.counters().events);
    EXPECT_EQ((int64)s.bytes.size() / 2, d.counters().words);
    EXPECT_EQ(250, d.currentTime());
}

TEST(Event_DavisDecoder, wraps_add_32768_us_each_and_reset_returns_to_zero)
{
    WordStream s;
    s.word(timestampWord(32000)).word(rowWord(1)).word(columnWord(1, 1));
    s.word(wrapWord(1)).word(rowWord(2)).word(columnWord(2, 1));       // just after the wrap: t = 32768
    s.word(timestampWord(5)).word(columnWord(3, 1));                  // 32768 + 5
    s.word(wrapWord(3)).word(timestampWord(7)).word(columnWord(4, 0)); // 4 x 32768 + 7
    DavisEventDecoder d(240, 180, false, false);
    const std::vector<Event> ev = decodeAll(d, s.bytes);
    ASSERT_EQ(4u, ev.size());
    EXPECT_EQ(32000, ev[0].t);
    EXPECT_EQ(32768, ev[1].t);
    EXPECT_EQ(32773, ev[2].t);
    EXPECT_EQ(4 * 32768 + 7, ev[3].t);
    EXPECT_EQ(2, d.counters().wraps);
}

TEST(Event_DavisDecoder, waits_for_the_requested_reset_then_keeps_later_resets_monotonic)
{
    WordStream s;
    s.word(timestampWord(9000)).word(rowWord(1)).word(columnWord(1, 1)).word(columnWord(2, 1));  // old clock
    s.word(timestampResetWord()).word(timestampWord(40)).word(rowWord(5)).word(columnWord(6, 0));
    s.word(wrapWord(2)).word(timestampWord(10)).word(rowWord(5)).word(columnWord(7, 1));
    // A reset nobody asked for (another program, a master restarting): time must not go back.
    s.word(timestampResetWord()).word(timestampWord(3)).word(rowWord(5)).word(columnWord(8, 1));
    DavisEventDecoder d(240, 180, false, true);
    EXPECT_FALSE(d.synchronised());
    const std::vector<Event> ev = decodeAll(d, s.bytes);
    EXPECT_TRUE(d.synchronised());
    ASSERT_EQ(3u, ev.size());
    EXPECT_EQ(Event(40, 6, 5, 0), ev[0]);
    EXPECT_EQ(Event(65536 + 10, 7, 5, 1), ev[1]);
    EXPECT_EQ(Event(65536 + 10 + 3, 8, 5, 1), ev[2]);
    EXPECT_EQ(2, d.counters().eventsBeforeReset);
    EXPECT_EQ(2, d.counters().timestampResets);
    // A row word from before a reset does not survive it.
    DavisEventDecoder d2(240, 180, false, false);
    std::vector<Event> none;
    WordStream u;
    u.word(rowWord(3)).word(timestampResetWord()).word(columnWord(1, 1));
    d2.decode(u.bytes.data(), u.bytes.size(), none);
    EXPECT_TRUE(none.empty());
    EXPECT_EQ(1, d2.counters().invalidAddresses);
}

TEST(Event_DavisDecoder, invert_xy_swaps_columns_and_rows)
{
    // A sensor whose raw columns are the user's rows: raw 180 columns x 240 rows -> 240 x 180 events.
    WordStream s;
    s.word(timestampWord(1)).word(rowWord(200)).word(columnWord(50, 1));
    DavisEventDecoder d(180, 240, true, false);
    const std::vector<Event> ev = decodeAll(d, s.bytes);
    ASSERT_EQ(1u, ev.size());
    EXPECT_EQ(200, ev[0].x);
    EXPECT_EQ(50, ev[0].y);
}

TEST(Event_DavisDecoder, invalid_addresses_are_counted_and_skipped)
{
    WordStream s;
    s.word(timestampWord(1));
    s.word(columnWord(5, 1));                           // X before any Y
    s.word(rowWord(180)).word(columnWord(5, 1));        // Y beyond 180 rows: it and the X after it
    s.word(rowWord(179)).word(columnWord(240, 0));      // X beyond 240 columns
    s.word(columnWord(239, 0));                         // the last valid pixel
    DavisEventDecoder d(240, 180, false, false);
    const std::vector<Event> ev = decodeAll(d, s.bytes);
    ASSERT_EQ(1u, ev.size());
    EXPECT_EQ(Event(1, 239, 179, 0), ev[0]);
    EXPECT_EQ(4, d.counters().invalidAddresses);
}

TEST(Event_DavisDecoder, aps_imu_and_special_words_are_not_events)
{
    WordStream s;
    s.word(timestampWord(10)).word(rowWord(2));
    for (int code : { 4, 5, 6 })
        s.word((uint16_t)((code << 12) | 0x123));
    for (int special : { 0, 2, 3, 4, 5, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17 })
        s.word((uint16_t)special);
    s.word(columnWord(9, 1));
    DavisEventDecoder d(346, 260, false, false);
    const std::vector<Event> ev = decodeAll(d, s.bytes);
    ASSERT_EQ(1u, ev.size());
    EXPECT_EQ(Event(10, 9, 2, 1), ev[0]);
    EXPECT_EQ(3 + 11, d.counters().otherWords);  // the 16 special words but the five trigger ones
    EXPECT_EQ(5, d.counters().triggers);
}

TEST(Event_DavisDecoder, external_input_words_are_triggers_on_the_event_clock)
{
    // Special word 3 = rising, 2 = falling, 4 = pulse, 17 / 16 = the generator's rising / falling edge, each
    // at the time of the timestamp word before it; before the first reset (when waiting for one) none counts.
    WordStream s;
    s.word(timestampWord(5)).word(3);
    s.word(1);  // the timestamp reset: time 0 from here
    s.word(timestampWord(100)).word(3).word(timestampWord(250)).word(2);
    s.word(wrapWord(2)).word(timestampWord(7)).word(4).word(17).word(16);
    DavisEventDecoder d(240, 180, false, true);
    d.arm(0);
    decodeAll(d, s.bytes);
    std::vector<EventTrigger> triggers;
    d.takeTriggers(triggers);
    const std::vector<EventTrigger> expected = {
        EventTrigger(100, EVENT_TRIGGER_RISING), EventTrigger(250, EVENT_TRIGGER_FALLING),
        EventTrigger(65536 + 7, EVENT_TRIGGER_PULSE), EventTrigger(65536 + 7, EVENT_TRIGGER_GENERATOR_RISING),
        EventTrigger(65536 + 7, EVENT_TRIGGER_GENERATOR_FALLING) };
    EXPECT_EQ(expected, triggers);
    EXPECT_EQ(6, d.counters().triggers);
    triggers.clear();
    d.takeTriggers(triggers);
    EXPECT_TRUE(triggers.empty());
}

TEST(Event_DavisDecoder, transfer_boundaries_anywhere_give_the_same_events)
{
    // 2000 events over several wraps, split into transfers at every possible even offset of a prefix and at
    // random even lengths after it: the row, the time base and the current time carry over.
    cv::RNG rng(7);
    std::vector<Event> truth;
    int64 t = 0;
    for (int i = 0; i < 2000; i++)
    {
        t += rng.uniform(0, 400);
        truth.emplace_back(t, rng.uniform(0, 346), rng.uniform(0, 260), rng.uniform(0, 2));
    }
    const std::vector<uint8_t> bytes = encodeEvents(truth);
    DavisEventDecoder whole(346, 260, false, false);
    EXPECT_EQ(truth, decodeAll(whole, bytes));
    for (size_t cut = 0; cut <= 64; cut += 2)
    {
        DavisEventDecoder d(346, 260, false, false);
        std::vector<Event> out;
        d.decode(bytes.data(), cut, out);
        size_t pos = cut;
        while (pos < bytes.size())
        {
            const size_t n = std::min(bytes.size() - pos, (size_t)(2 * rng.uniform(1, 700)));
            d.decode(bytes.data() + pos, n, out);
            pos += n;
        }
        ASSERT_EQ(truth, out) << "first transfer of " << cut << " bytes";
    }
}

TEST(Event_DavisDecoder, odd_trailing_byte_is_dropped_and_counted)
{
    WordStream s;
    s.word(timestampWord(3)).word(rowWord(1)).word(columnWord(2, 1));
    std::vector<uint8_t> bytes = s.bytes;
    bytes.push_back(0x31);  // half a word
    DavisEventDecoder d(240, 180, false, false);
    const std::vector<Event> ev = decodeAll(d, bytes);
    EXPECT_EQ(1u, ev.size());
    EXPECT_EQ(1, d.counters().oddBytes);
    EXPECT_EQ(3, d.counters().words);
}

}}  // namespace
