// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The live DAVIS back-end without hardware: a fake USB transport answers the configuration channel from a
// register map, records every write, and replays scripted bulk transfers (data, failed transfers, unplug).
// EventCapture runs unchanged on top of it, so identification, configuration, start / stop, stereo sync and
// the error paths are those a real camera gets.

#include "test_precomp.hpp"
#include "fake_davis_usb.hpp"

#include <chrono>
#include <deque>
#include <mutex>
#include <thread>

namespace opencv_test { namespace {

using namespace cv::event::detail;
using namespace davis_words;
using namespace fake_davis_usb;

/** encodeEvents() followed by the clock words a running camera keeps sending (a wrap every 32.768 ms), up to
one wrap past the last event: the receiver learns that nothing older can come. */
std::vector<uint8_t> encodeWithClock(const std::vector<Event>& events)
{
    std::vector<uint8_t> bytes = encodeEvents(events);
    appendClockWords(bytes, events.back().t + 0x8000);
    return bytes;
}

std::vector<Event> randomEvents(int n, int width, int height, uint64 seed, int64 t0 = 0)
{
    cv::RNG rng(seed);
    std::vector<Event> ev;
    int64 t = t0;
    for (int i = 0; i < n; i++)
    {
        t += rng.uniform(0, 90);
        ev.emplace_back(t, rng.uniform(0, width), rng.uniform(0, height), rng.uniform(0, 2));
    }
    return ev;
}

/** Two DAVIS346 on a sync cable (@p leftMaster: which one is master), each sending @p n random events after the
master's pulse (seeds @p seed and @p seed + 1). */
struct SyncedPair
{
    FakeUsb usb;
    Ptr<FakeCamera> left, right;
    std::vector<Event> l, r;

    SyncedPair(bool leftMaster, int n, uint64 seed)
    {
        left = usb.add(5, 346, 260, false, leftMaster);
        right = usb.add(5, 346, 260, false, !leftMaster);
        (leftMaster ? left : right)->slave = (leftMaster ? right : left).get();
        l = randomEvents(n, 346, 260, seed);
        r = randomEvents(n, 346, 260, seed + 1);
        left->afterReset = encodeWithClock(l);
        right->afterReset = encodeWithClock(r);
    }
};

/** Reads until @p n events came or the stream ended. */
std::vector<Event> readEvents(EventCapture& cap, size_t n)
{
    cap.set(EVENT_CAP_PROP_BATCH_EVENTS, 1000);
    std::vector<Event> all, packet;
    while (all.size() < n && cap.read(packet))
        all.insert(all.end(), packet.begin(), packet.end());
    return all;
}

TEST(Event_Capture_Davis, davis346_identified_configured_started_and_stopped)
{
    FakeUsb usb;
    Ptr<FakeCamera> cam = usb.add(5 /* DAVIS346B */, 346, 260);
    cam->registers[{ 1, 51 }] = 1;  // left by an earlier program: skip every 2nd event, suppress OFF events
    cam->registers[{ 1, 52 }] = 2;
    cam->registers[{ 1, 62 }] = 1;
    // Events from before the capture's clock reset must not come out; those after it must, exactly.
    cam->pushData(encodeEvents(randomEvents(300, 346, 260, 1, 20000)));
    const std::vector<Event> truth = randomEvents(5000, 346, 260, 2);
    cam->afterReset = encodeEvents(truth);

    EventCapture cap("davis:0");
    ASSERT_TRUE(cap.isOpened());
    EXPECT_EQ("DAVIS", cap.getBackendName());
    EXPECT_EQ(Size(346, 260), cap.getSensorSize());
    EXPECT_EQ(1, cap.get(EVENT_CAP_PROP_DEVICE_IS_MASTER));
    EXPECT_EQ(18, cap.get(EVENT_CAP_PROP_DEVICE_LOGIC_VERSION));
    EXPECT_EQ(6, cap.get(EVENT_CAP_PROP_DEVICE_FIRMWARE_VERSION));
    EXPECT_EQ(5, cap.get(EVENT_CAP_PROP_DEVICE_CHIP_ID));
    EXPECT_EQ(truth, readEvents(cap, truth.size()));
    EXPECT_EQ(300, cap.get(EVENT_CAP_PROP_SKIPPED));  // before the reset
    EXPECT_EQ(0, cap.get(EVENT_CAP_PROP_DROPPED_EVENTS));

    // Default biases of the DAVIS346 bias generator (values of the protocol fact sheet).
    std::map<std::pair<int, int>, uint32_t> cfg = usb.log->lastValues(0);
    EXPECT_EQ(0x5FFFu, (cfg[{ 5, 11 }]));  // OnBn
    EXPECT_EQ(0x401Fu, (cfg[{ 5, 12 }]));  // OffBn
    EXPECT_EQ(0x427Fu, (cfg[{ 5, 10 }]));  // DiffBn
    EXPECT_EQ(0x23ADu, (cfg[{ 5, 14 }]));  // PrBp
    EXPECT_EQ(0x7D7Eu, (cfg[{ 5, 9 }]));   // PadFollBn, disabled
    EXPECT_EQ(0x8410u, (cfg[{ 5, 36 }]));  // SSN
    EXPECT_EQ(1u, (cfg[{ 5, 143 }]));      // SelectGrayCounter
    EXPECT_EQ(8u, (cfg[{ 1, 32 }]));       // background-activity filter 2 ms = 8 x 250 us
    EXPECT_EQ(80000u, (cfg[{ 9, 1 }]));    // early packet: 8 x 125 us at 80 MHz, in clock cycles
    EXPECT_EQ(0u, (cfg[{ 2, 4 }]));        // APS off
    EXPECT_EQ(-1, usb.log->find(0, 5, 139, 0));  // a DAVIS240A/B field: never written to a 346
    // Every FPGA filter back to its default, whatever the previous program left (the fake starts with the skip
    // filter on and OFF events suppressed); unused hot-pixel slots point outside the array, row then column.
    {
        std::lock_guard<std::mutex> lock(cam->mutex);
        EXPECT_EQ(0u, (cam->registers[{ 1, 51 }]));
        EXPECT_EQ(5u, (cam->registers[{ 1, 52 }]));
        EXPECT_EQ(0u, (cam->registers[{ 1, 62 }]));
    }
    EXPECT_NE(-1, usb.log->find(0, 1, 61, 0));
    EXPECT_NE(-1, usb.log->find(0, 1, 63, 0));
    for (int p = 11; p <= 26; p += 2)
    {
        EXPECT_EQ(260u, (cfg[{ 1, p }])) << "hot-pixel row " << p;
        EXPECT_EQ(346u, (cfg[{ 1, p + 1 }])) << "hot-pixel column " << p + 1;
    }

    // Start sequence: everything off, chip on, then USB, timestamps, mux, DVS; nothing else runs.
    int at = usb.log->find(0, 1, 3, 0);
    ASSERT_GE(at, 0);
    for (const ConfigWrite& step : std::vector<ConfigWrite>{ { 0, 0, 3, 1 }, { 0, 9, 0, 1 }, { 0, 0, 1, 1 },
                                                              { 0, 0, 0, 1 }, { 0, 1, 3, 1 }, { 0, 0, 2, 1 } })
    {
        const int next = usb.log->find(0, step.module, step.param, step.value, at);
        ASSERT_GT(next, at) << "(" << step.module << ", " << step.param << ") = " << step.value << " out of order";
        at = next;
    }
    EXPECT_EQ(-1, usb.log->find(0, 2, 4, 1));  // APS never runs
    EXPECT_EQ(-1, usb.log->find(0, 3, 2, 1));  // nor the IMU
    EXPECT_EQ("clearHalt 0x82", usb.log->usbCalls[1].second);
    EXPECT_EQ("startBulkIn 0x82 8 x 8192", usb.log->usbCalls[2].second);

    // Stop sequence on release: DVS off first, chip off last, then the transfers go.
    const int before = (int)usb.log->writes.size();
    cap.release();
    EXPECT_FALSE(cap.isOpened());
    const int dvsOff = usb.log->find(0, 1, 3, 0, before), chipOff = usb.log->find(0, 0, 3, 0, before);
    EXPECT_GE(dvsOff, 0);
    EXPECT_GT(chipOff, dvsOff);
    EXPECT_EQ("stopBulkIn", usb.log->usbCalls[usb.log->usbCalls.size() - 2].second);
    EXPECT_EQ("close", usb.log->usbCalls.back().second);
}

TEST(Event_Capture_Davis, davis240_fx2_invert_xy_biases_and_knobs)
{
    FakeUsb usb;
    Ptr<FakeCamera> cam = usb.add(2 /* DAVIS240C */, 180, 240, true);  // raw columns are rows
    cam->id.productId = 0x841B;  // FX2
    cam->id.firmwareVersion = 4;
    cam->afterReset = encodeEvents({ Event(5, 179, 239, 1) });  // raw (column 179, row 239)

    EventCapture cap;
    cap.set(EVENT_CAP_PROP_DEVICE_BA_FILTER_TIME_US, 1000);  // before open: applied by open()
    ASSERT_TRUE(cap.open("davis:00000490"));                  // by serial
    EXPECT_EQ(Size(240, 180), cap.getSensorSize());
    const std::vector<Event> ev = readEvents(cap, 1);
    ASSERT_EQ(1u, ev.size());
    EXPECT_EQ(Event(5, 239, 179, 1), ev[0]);

    std::map<std::pair<int, int>, uint32_t> cfg = usb.log->lastValues(0);
    EXPECT_EQ(0x427Fu, (cfg[{ 5, 0 }]));   // DiffBn
    EXPECT_EQ(0x5FFFu, (cfg[{ 5, 1 }]));   // OnBn
    EXPECT_EQ(0x400Fu, (cfg[{ 5, 2 }]));   // OffBn
    EXPECT_EQ(0x8410u, (cfg[{ 5, 21 }]));  // SSN
    EXPECT_EQ(0, (int)cfg.count({ 5, 22 })); // the DAVIS240 has 22 biases
    EXPECT_EQ(4u, (cfg[{ 1, 32 }]));        // 1000 us
    EXPECT_EQ(1000, cap.get(EVENT_CAP_PROP_DEVICE_BA_FILTER_TIME_US));

    // ROI in event coordinates -> the filter's raw (column, row) coordinates, swapped here, inclusive ends.
    EXPECT_TRUE(cap.set(EVENT_CAP_PROP_DEVICE_ROI_WIDTH, 100));
    EXPECT_TRUE(cap.set(EVENT_CAP_PROP_DEVICE_ROI_X, 10));
    EXPECT_TRUE(cap.set(EVENT_CAP_PROP_DEVICE_ROI_HEIGHT, 50));
    cfg = usb.log->lastValues(0);
    EXPECT_EQ(0u, (cfg[{ 1, 41 }]));    // start column = y
    EXPECT_EQ(10u, (cfg[{ 1, 42 }]));   // start row = x
    EXPECT_EQ(49u, (cfg[{ 1, 43 }]));   // end column = y + height - 1
    EXPECT_EQ(109u, (cfg[{ 1, 44 }]));  // end row = x + width - 1
    EXPECT_FALSE(cap.set(EVENT_CAP_PROP_DEVICE_ROI_WIDTH, 300));  // beyond the sensor
    EXPECT_EQ(100, cap.get(EVENT_CAP_PROP_DEVICE_ROI_WIDTH));
    EXPECT_TRUE(cap.set(EVENT_CAP_PROP_DEVICE_BA_FILTER, 0));
    EXPECT_EQ(0u, (usb.log->lastValues(0)[{ 1, 31 }]));
    EXPECT_TRUE(cap.set(EVENT_CAP_PROP_DEVICE_BIAS_SELECT, 1));
    EXPECT_TRUE(cap.set(EVENT_CAP_PROP_DEVICE_BIAS_VALUE, 0x5F0F));
    EXPECT_EQ(0x5F0Fu, (usb.log->lastValues(0)[{ 5, 1 }]));
    EXPECT_TRUE(cap.set(EVENT_CAP_PROP_DEVICE_BIAS_PRESET, 0));
    EXPECT_EQ(0x5FFFu, (usb.log->lastValues(0)[{ 5, 1 }]));
    const int resetsBefore = cam->resets;
    EXPECT_TRUE(cap.set(EVENT_CAP_PROP_DEVICE_TIMESTAMP_RESET, 1));
    EXPECT_EQ(resetsBefore + 1, cam->resets);
    EXPECT_FALSE(cap.set(EVENT_CAP_PROP_POS_US, 0));  // a camera cannot seek
}

TEST(Event_Capture_Davis, unusable_cameras_are_refused_with_the_reason)
{
    {
        FakeUsb usb;  // nothing connected
        EXPECT_TRUE(listEventDevices().empty());
        EventCapture cap;
        cap.set(EVENT_CAP_PROP_EXCEPTION_MODE, 0);
        EXPECT_FALSE(cap.open("davis:0"));
        EXPECT_NE(std::string::npos, cap.getLastError().find("davis:0: no DAVIS camera is connected")) << cap.getLastError();
    }
    struct Case { std::function<void(FakeCamera&)> spoil; std::string source, message; };
    const std::vector<Case> cases = {
        { [](FakeCamera& c) { c.registers[{ 6, 0 }] = 17; }, "davis:0", "FPGA logic version 17 patch 1 is too old" },
        { [](FakeCamera& c) { c.registers[{ 6, 0 }] = 19; }, "davis:0", "FPGA logic version 19 patch 1 is newer than supported" },
        { [](FakeCamera& c) { c.registers[{ 6, 7 }] = 0; }, "davis:0", "FPGA logic version 18 patch 0 is too old" },
        { [](FakeCamera& c) { c.id.firmwareVersion = 5; }, "davis:0", "USB firmware version 5 is too old" },
        { [](FakeCamera& c) { c.id.firmwareVersion = 7; }, "davis:0", "USB firmware version 7 is newer than supported" },
        { [](FakeCamera& c) { c.registers[{ 6, 1 }] = 6; }, "davis:0", "chip DAVIS640 (id 6) is not supported" },
        { [](FakeCamera& c) { c.registers[{ 6, 1 }] = 7; }, "davis:0", "chip DAVIS640H (id 7) is not supported" },
        { [](FakeCamera& c) { c.registers[{ 6, 1 }] = 8; }, "davis:0", "chip DAVIS208 (id 8) is not supported" },
        { [](FakeCamera& c) { c.registers[{ 6, 1 }] = 42; }, "davis:0", "chip unknown DAVIS (id 42) is not supported" },
        { [](FakeCamera& c) { c.openError = "LIBUSB_ERROR_BUSY"; }, "davis:0", "LIBUSB_ERROR_BUSY" },
        { [](FakeCamera& c) { c.registers[{ 1, 0 }] = 0; }, "davis:0", "0 x 260 DVS array" },
        { [](FakeCamera&) {}, "davis:3", "davis:3: no such DAVIS camera; connected: 00000490 (usb 001:010)" },
        { [](FakeCamera&) {}, "davis:12345678", "no such DAVIS camera" },
    };
    for (const Case& c : cases)
    {
        FakeUsb usb;
        c.spoil(*usb.add(5, 346, 260));
        EventCapture cap;
        cap.set(EVENT_CAP_PROP_EXCEPTION_MODE, 0);
        EXPECT_FALSE(cap.open(c.source));
        EXPECT_FALSE(cap.isOpened());
        EXPECT_NE(std::string::npos, cap.getLastError().find(c.message)) << cap.getLastError();
    }
}

TEST(Event_Capture_Davis, list_devices_identifies_each_camera)
{
    FakeUsb usb;
    usb.add(5, 346, 260, false, true);
    usb.add(2, 180, 240, true, false)->openError = "LIBUSB_ERROR_ACCESS";
    const std::vector<EventDeviceInfo> list = listEventDevices();
    ASSERT_EQ(2u, list.size());
    EXPECT_EQ("davis:00000490", list[0].source);
    EXPECT_EQ("DAVIS346B", list[0].model);
    EXPECT_EQ(Size(346, 260), list[0].sensorSize);
    EXPECT_EQ(18, list[0].logicVersion);
    EXPECT_TRUE(list[0].master);
    EXPECT_TRUE(list[0].error.empty());
    EXPECT_EQ("davis:00000491", list[1].source);
    EXPECT_EQ(-1, list[1].logicVersion);
    EXPECT_NE(std::string::npos, list[1].error.find("LIBUSB_ERROR_ACCESS"));
}

TEST(Event_Capture_Davis, real_transport_without_cameras_lists_none_and_open_says_why)
{
    // The libusb transport on a machine without a DAVIS (CI): an empty list, open() false with a message.
    // Skipped where a camera is actually connected.
    if (!listEventDevices().empty())
        throw SkipTestException("a DAVIS camera is connected to this machine");
    EventCapture cap;
    cap.set(EVENT_CAP_PROP_EXCEPTION_MODE, 0);
    EXPECT_FALSE(cap.open("davis:0"));
    EXPECT_NE(std::string::npos, cap.getLastError().find("no DAVIS camera is connected")) << cap.getLastError();
}

TEST(Event_Capture_Davis, unplug_ends_the_stream_with_a_status_and_release_returns)
{
    FakeUsb usb;
    Ptr<FakeCamera> cam = usb.add(5, 346, 260);
    const std::vector<Event> truth = randomEvents(3000, 346, 260, 3);
    cam->afterReset = encodeEvents(truth);
    cam->unplugWhenDrained = true;
    EventCapture cap("davis:0");
    std::vector<Event> all, packet;
    cap.set(EVENT_CAP_PROP_BATCH_EVENTS, 700);
    while (cap.read(packet))  // exception mode is on: the unplug is still a status, not an exception
        all.insert(all.end(), packet.begin(), packet.end());
    EXPECT_EQ(truth, all);  // everything sent before the unplug is delivered
    EXPECT_NE(std::string::npos, cap.getLastError().find("davis:00000490 (DAVIS346B, usb 001:010): the camera was unplugged"))
        << cap.getLastError();
    EXPECT_FALSE(cap.read(packet));
    cap.release();  // stop requests fail on a gone device; release still returns
    EXPECT_FALSE(cap.isOpened());
}

TEST(Event_Capture_Davis, failed_transfers_and_a_full_queue_are_counted_not_silent)
{
    FakeUsb usb;
    Ptr<FakeCamera> cam = usb.add(5, 346, 260);
    const std::vector<Event> truth = randomEvents(20000, 346, 260, 4);
    cam->afterReset = encodeEvents(truth);
    cam->pushStatus(USB_BULK_TRANSFER_ERROR);  // before the reset: the stream goes on after it
    cam->pushStatus(USB_BULK_TRANSFER_ERROR);
    EventCapture cap;
    cap.set(EVENT_CAP_PROP_QUEUE_CAPACITY, 2);
    ASSERT_TRUE(cap.open("davis:0"));
    // read() waits until the reader thread has handled every transfer (it came back for more after the last
    // one): 2 chunks fit in the queue, the others must be counted as dropped.
    for (int i = 0; i < 30000; i++)
    {
        {
            std::lock_guard<std::mutex> lock(cam->mutex);
            if (cam->readsWhenDrained > 0)
                break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    cap.set(EVENT_CAP_PROP_BATCH_EVENTS, 1000);
    std::vector<Event> delivered, packet;
    while (delivered.size() + (size_t)cap.get(EVENT_CAP_PROP_DROPPED_EVENTS) < truth.size() && cap.read(packet))
        delivered.insert(delivered.end(), packet.begin(), packet.end());
    EXPECT_EQ(2, cap.get(EVENT_CAP_PROP_DROPPED_TRANSFERS));
    const double dropped = cap.get(EVENT_CAP_PROP_DROPPED_EVENTS);
    EXPECT_GT(dropped, 0);
    EXPECT_EQ(truth.size(), delivered.size() + (size_t)dropped);  // every event delivered or counted
    // What is delivered is a subsequence of what was sent, in order.
    size_t j = 0;
    for (const Event& e : delivered)
    {
        while (j < truth.size() && truth[j] != e)
            j++;
        ASSERT_LT(j, truth.size());
        j++;
    }
}

TEST(Event_Capture_Davis, stereo_pair_shares_the_master_clock)
{
    SyncedPair pair(false, 4000, 5);  // the right camera is master
    const std::vector<Event>& l = pair.l;
    const std::vector<Event>& r = pair.r;
    Ptr<FakeCamera> left = pair.left, right = pair.right;
    FakeUsb& usb = pair.usb;
    left->pushData(encodeEvents(randomEvents(100, 346, 260, 7, 50000)));  // before the reset: skipped

    EventCapture cap;
    ASSERT_TRUE(cap.openStereo("davis:0", "davis:1"));
    EXPECT_EQ(1, cap.get(EVENT_CAP_PROP_STEREO));
    const std::vector<Event> merged = readEvents(cap, l.size() + r.size());
    std::vector<Event> expected;
    mergeStereoEvents(l, r, expected);
    EXPECT_EQ(expected, merged);
    // One reset pulse, from the master only, after both cameras run; the slave started first.
    EXPECT_EQ(-1, usb.log->find(0, 0, 2, 1));
    const int pulse = usb.log->find(1, 0, 2, 1);
    EXPECT_GT(pulse, usb.log->find(0, 1, 3, 1));
    EXPECT_GT(pulse, usb.log->find(1, 1, 3, 1));
    EXPECT_LT(usb.log->find(0, 1, 3, 1), usb.log->find(1, 1, 3, 1));
    EXPECT_EQ(1, left->resets);
    EXPECT_EQ(1, right->resets);
    // A reset asked of the pair pulses the master only; the cable carries it.
    EXPECT_TRUE(cap.set(EVENT_CAP_PROP_DEVICE_TIMESTAMP_RESET, 1));
    EXPECT_EQ(2, left->resets);
    EXPECT_EQ(2, right->resets);
}

TEST(Event_Capture_Davis, stereo_pair_with_a_reset_latched_by_the_slave_starts_both_clocks_at_zero)
{
    // The slave's FPGA latched a reset at power-up (slave detection) and sends it as its first word when it
    // starts, about 0.3 s before the master's pulse: taken for the pulse, it would set the slave's clock that
    // far ahead of the master's.
    SyncedPair pair(false, 3000, 10);  // the left camera is the slave
    const std::vector<Event>& l = pair.l;
    const std::vector<Event>& r = pair.r;
    pair.left->latchedReset = true;
    pair.left->beforeSync = encodeWithClock(randomEvents(500, 346, 260, 9));

    EventCapture cap;
    ASSERT_TRUE(cap.openStereo("davis:0", "davis:1"));
    const std::vector<Event> merged = readEvents(cap, l.size() + r.size());
    std::vector<Event> expected;
    mergeStereoEvents(l, r, expected);
    EXPECT_EQ(expected, merged);  // both clocks from 0 at the pulse, to the microsecond
    EXPECT_EQ(500, cap.get(EVENT_CAP_PROP_SKIPPED));  // what the slave recorded on its stale clock
}

/** Events of one camera at the given device times (from its last reset), each followed by nothing else. */
std::vector<Event> eventsAt(const std::vector<int64>& times, int x)
{
    std::vector<Event> ev;
    for (int64 t : times)
        ev.emplace_back(t, x, 7, 1);
    return ev;
}

TEST(Event_Capture_Davis, a_reset_mid_stream_gives_both_cameras_the_same_new_epoch)
{
    // A reset nobody asked for (a sync glitch, the FPGA's reset after a long USB stall) reaches both cameras
    // at once, at device time 130 ms. The left camera's last timestamp word before it is 128.3 ms (an event),
    // the right one's 98.3 ms (a wrap word: it saw nothing since). Each re-based on its own last word, the
    // two clocks would be 30 ms apart from then on.
    FakeUsb usb;
    Ptr<FakeCamera> left = usb.add(5, 346, 260, false, true);    // master
    Ptr<FakeCamera> right = usb.add(5, 346, 260, false, false);  // slave
    left->slave = right.get();
    const std::vector<Event> lBefore = eventsAt({ 1000, 50000, 128304 }, 10);
    const std::vector<Event> rBefore = eventsAt({ 2000, 60000 }, 20);
    std::vector<uint8_t> lBytes = encodeEvents(lBefore), rBytes = encodeEvents(rBefore);
    WordStream rClock;
    rClock.word(wrapWord(1)).word(wrapWord(1));  // a running camera's clock words: 65.536 and 98.304 ms
    rBytes.insert(rBytes.end(), rClock.bytes.begin(), rClock.bytes.end());
    const std::vector<Event> lAfter = eventsAt({ 500, 20000, 40000 }, 11), rAfter = eventsAt({ 600, 20100, 40100 }, 21);
    WordStream reset;
    reset.word(timestampResetWord());
    for (auto* side : { &lBytes, &rBytes })
        side->insert(side->end(), reset.bytes.begin(), reset.bytes.end());
    std::vector<uint8_t> lTail = encodeEvents(lAfter), rTail = encodeEvents(rAfter);
    appendClockWords(lTail, 70000);
    appendClockWords(rTail, 70000);
    lBytes.insert(lBytes.end(), lTail.begin(), lTail.end());
    rBytes.insert(rBytes.end(), rTail.begin(), rTail.end());
    left->afterReset = lBytes;
    right->afterReset = rBytes;

    EventCapture cap;
    ASSERT_TRUE(cap.openStereo("davis:0", "davis:1"));
    const std::vector<Event> merged = readEvents(cap, 11);
    ASSERT_EQ(11u, merged.size());
    std::vector<int64> epochs[2];  // delivered time - device time, of each camera's events after the reset
    int64 lastBefore = 0;
    for (const Event& e : merged)
        if (e.x == 10 || e.x == 20)
            lastBefore = std::max(lastBefore, (int64)e.t);
        else if (e.x == 11 && epochs[0].size() < lAfter.size())
            epochs[0].push_back(e.t - lAfter[epochs[0].size()].t);
        else if (e.x == 21 && epochs[1].size() < rAfter.size())
            epochs[1].push_back(e.t - rAfter[epochs[1].size()].t);
    ASSERT_EQ(3u, epochs[0].size());
    ASSERT_EQ(3u, epochs[1].size());
    for (int k = 0; k < 3; k++)
    {
        EXPECT_EQ(epochs[0][0], epochs[0][k]);
        EXPECT_EQ(epochs[0][0], epochs[1][k]) << "the two cameras took different epochs at the reset";
    }
    EXPECT_EQ(128304, lastBefore);
    EXPECT_GE(epochs[0][0], 128304);  // time never goes back
    EXPECT_LE(epochs[0][0], 128304 + 32768 + 1000);
}

TEST(Event_Capture_Davis, a_reset_that_finds_the_sync_cable_gone_ends_the_stereo_stream_saying_so)
{
    SyncedPair pair(true, 200, 12);  // the right camera is the slave
    EventCapture cap;
    ASSERT_TRUE(cap.openStereo("davis:0", "davis:1"));
    EXPECT_EQ(400u, readEvents(cap, 400).size());
    // The cable is pulled: the slave's FPGA becomes its own master and resets its clock.
    pair.right->setRegister(6, 2, 1);
    WordStream reset;
    reset.word(timestampResetWord());
    pair.right->pushData(reset.bytes);
    cap.set(EVENT_CAP_PROP_BATCH_EVENTS, 1);
    std::vector<Event> packet;
    int reads = 0;
    while (reads < 200 && cap.read(packet))  // live: each read returns within a poll period
        reads++;
    EXPECT_LT(reads, 200) << "the pair goes on with one camera whose clock runs apart";
    EXPECT_NE(std::string::npos, cap.getLastError().find("davis:00000491 (DAVIS346B, usb 001:011): the stereo sync cable "
                                                        "was unplugged (this camera, the slave at the start, now reports master)"))
        << cap.getLastError();
}

TEST(Event_Capture_Davis, stereo_without_sync_cable_is_refused)
{
    FakeUsb usb;
    usb.add(5, 346, 260, false, true);
    usb.add(5, 346, 260, false, true);
    EventCapture cap;
    cap.set(EVENT_CAP_PROP_EXCEPTION_MODE, 0);
    EXPECT_FALSE(cap.openStereo("davis:0", "davis:1"));
    EXPECT_NE(std::string::npos, cap.getLastError().find("both cameras report master")) << cap.getLastError();
    EXPECT_NE(std::string::npos, cap.getLastError().find("sync cable")) << cap.getLastError();
    EXPECT_FALSE(cap.openStereo("davis:0", "davis:0"));
    EXPECT_NE(std::string::npos, cap.getLastError().find("are the same camera")) << cap.getLastError();
    EXPECT_FALSE(cap.openStereo("davis:0", "some_file.aedat4"));
    EXPECT_NE(std::string::npos, cap.getLastError().find("one live camera and one file")) << cap.getLastError();
}

TEST(Event_Capture_Davis, stereo_goes_on_while_one_camera_is_silent)
{
    // The right camera sees nothing, but its clock words say how far time has gone: the left events
    // older than that are delivered instead of waiting for a right event that never comes.
    FakeUsb usb;
    Ptr<FakeCamera> left = usb.add(5, 346, 260, false, true);
    Ptr<FakeCamera> right = usb.add(5, 346, 260, false, false);
    left->slave = right.get();
    const std::vector<Event> l = randomEvents(2000, 346, 260, 8);
    left->afterReset = encodeEvents(l);
    WordStream clock;
    for (int64 t = 32768; t <= l.back().t + 32768; t += 32768)
        clock.word(wrapWord(1));
    right->afterReset = clock.bytes;
    EventCapture cap;
    ASSERT_TRUE(cap.openStereo("davis:0", "davis:1"));
    const std::vector<Event> merged = readEvents(cap, l.size());
    ASSERT_EQ(l.size(), merged.size());
    for (size_t i = 0; i < l.size(); i++)
        ASSERT_EQ(Event(l[i].t, l[i].x, l[i].y, l[i].p, CAMERA_LEFT), merged[i]);
}

TEST(Event_Capture_Davis, time_windows_close_on_the_camera_clock)
{
    // Events at 1 ms and 25 ms, then only the clock up to 98 ms: 10 ms windows from the first event
    // come out as 1, 0, 1, 0, ... events, without waiting for an event after each window.
    FakeUsb usb;
    Ptr<FakeCamera> cam = usb.add(5, 346, 260);
    std::vector<uint8_t> bytes = encodeEvents({ Event(1000, 3, 4, 1), Event(25000, 5, 6, 0) });
    WordStream clock;
    clock.word(wrapWord(1)).word(wrapWord(1)).word(timestampWord(32000));  // 65536 + 32000 us
    bytes.insert(bytes.end(), clock.bytes.begin(), clock.bytes.end());
    cam->afterReset = bytes;
    EventCapture cap("0", EVENT_CAP_DAVIS);  // the index alone, with the back-end named
    cap.set(EVENT_CAP_PROP_WINDOW_US, 10000);
    std::vector<size_t> sizes;
    std::vector<Event> packet;
    for (int k = 0; k < 9 && cap.read(packet); k++)
        sizes.push_back(packet.size());
    EXPECT_EQ(std::vector<size_t>({ 1, 0, 1, 0, 0, 0, 0, 0, 0 }), sizes);
    EXPECT_EQ(91000, cap.get(EVENT_CAP_PROP_POS_US));
}

TEST(Event_Capture_Davis, external_input_edges_come_out_as_triggers_once_enabled)
{
    // With EVENT_CAP_PROP_DEVICE_EXTERNAL_INPUT = 1 the detector runs (EXTINPUT module 4: rising and falling
    // edges, no pulses, RUN_DETECTOR after the start); special words 3 / 2 are rising / falling edges.
    FakeUsb usb;
    Ptr<FakeCamera> cam = usb.add(5, 346, 260);
    std::vector<uint8_t> bytes = encodeEvents({ Event(1000, 3, 4, 1) });
    WordStream s;
    s.word(timestampWord(1500)).word(3).word(timestampWord(2500)).word(2);
    bytes.insert(bytes.end(), s.bytes.begin(), s.bytes.end());
    const std::vector<uint8_t> later = encodeEvents({ Event(3000, 5, 6, 0) });
    bytes.insert(bytes.end(), later.begin(), later.end());
    appendClockWords(bytes, 3000 + 0x8000);
    cam->afterReset = bytes;
    EventCapture cap;
    ASSERT_TRUE(cap.set(EVENT_CAP_PROP_DEVICE_EXTERNAL_INPUT, 1));
    ASSERT_TRUE(cap.open("davis:0"));
    EXPECT_EQ(1.0, cap.get(EVENT_CAP_PROP_DEVICE_EXTERNAL_INPUT));
    const int started = usb.log->find(0, 1, 3, 1);  // DVS RUN
    ASSERT_NE(-1, started);
    EXPECT_NE(-1, usb.log->find(0, 4, 0, 1, started));  // the detector runs once the camera does
    std::map<std::pair<int, int>, uint32_t> cfg = usb.log->lastValues(0);
    EXPECT_EQ(1u, cfg[std::make_pair(4, 1)]);
    EXPECT_EQ(1u, cfg[std::make_pair(4, 2)]);
    EXPECT_EQ(0u, cfg[std::make_pair(4, 3)]);
    cap.set(EVENT_CAP_PROP_WINDOW_US, 10000);
    std::vector<Event> packet;
    std::vector<EventTrigger> triggers;
    ASSERT_TRUE(cap.read(packet));
    EXPECT_EQ(2u, packet.size());
    cap.retrieveTriggers(triggers);
    const std::vector<EventTrigger> expected = { EventTrigger(1500, EVENT_TRIGGER_RISING),
                                                 EventTrigger(2500, EVENT_TRIGGER_FALLING) };
    EXPECT_EQ(expected, triggers);
}

}}  // namespace
