// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_TEST_DAVIS_TEST_WORDS_HPP
#define OPENCV_EVENT_TEST_DAVIS_TEST_WORDS_HPP

// Builds DAVIS data-endpoint byte streams for the tests, written from the word layout of the protocol fact
// sheet (bit 15 = timestamp; code in bits 14..12: 0 special, 1 Y, 2 X OFF, 3 X ON, 7 wrap), independently of
// the decoder under test.

#include "test_precomp.hpp"

namespace opencv_test { namespace davis_words {

inline uint16_t timestampWord(int us) { return (uint16_t)(0x8000 | (us & 0x7FFF)); }
inline uint16_t wrapWord(int wraps) { return (uint16_t)(0x7000 | (wraps & 0xFFF)); }
inline uint16_t rowWord(int y) { return (uint16_t)(0x1000 | (y & 0xFFF)); }
inline uint16_t columnWord(int x, int polarity) { return (uint16_t)((polarity ? 0x3000 : 0x2000) | (x & 0xFFF)); }
inline uint16_t timestampResetWord() { return 0x0001; }

struct WordStream
{
    std::vector<uint8_t> bytes;
    WordStream& word(uint16_t w)
    {
        bytes.push_back((uint8_t)(w & 0xFF));  // little-endian
        bytes.push_back((uint8_t)(w >> 8));
        return *this;
    }
};

/** Words for time-ordered events, as the camera sends them: a wrap word whenever 32768 us have passed since
the last one, a timestamp word per new time, a Y word per new row, then the X word. Times count from
@p start, the time of the last reset (or wrap) of the camera's clock. */
inline std::vector<uint8_t> encodeEvents(const std::vector<Event>& events, int64 start = 0)
{
    WordStream s;
    int64 base = start, lastTime = -1;
    int lastRow = -1;
    for (const Event& e : events)
    {
        if (e.t - base >= 0x8000)
        {
            const int64 wraps = (e.t - base) / 0x8000;
            s.word(wrapWord((int)wraps));
            base += wraps * 0x8000;
            lastTime = -1;
            lastRow = -1;  // not needed by the protocol; exercises more Y words
        }
        if (e.t != lastTime)
            s.word(timestampWord((int)(e.t - base)));
        if (e.y != lastRow)
            s.word(rowWord(e.y));
        s.word(columnWord(e.x, e.p));
        lastTime = e.t;
        lastRow = e.y;
    }
    return s.bytes;
}

/** Appends the clock words a running camera keeps sending: a wrap word every 32.768 ms from the reset up to
@p untilUs, so that the receiver learns that nothing older can come. */
inline void appendClockWords(std::vector<uint8_t>& bytes, int64 untilUs)
{
    WordStream clock;
    for (int64 t = 0; t <= untilUs; t += 0x8000)
        clock.word(wrapWord(1));
    bytes.insert(bytes.end(), clock.bytes.begin(), clock.bytes.end());
}

}}  // namespace

#endif
