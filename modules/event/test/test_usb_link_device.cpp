// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The bulk-transfer bookkeeping of the live cameras against a fake link with libusb's semantics: callbacks on
// a control request's thread while another thread reads, stalls, failed resubmissions, unplugging, shutdown.
// Run under ThreadSanitizer in CI (test/sanitizers.sh).

#include "test_precomp.hpp"
#include "fake_usb_link.hpp"

#include <atomic>
#include <thread>

namespace opencv_test { namespace {

using namespace fake_usb_link;

std::vector<uint8_t> numbered(uint32_t k) { return { (uint8_t)k, (uint8_t)(k >> 8), (uint8_t)(k >> 16), (uint8_t)(k >> 24) }; }
uint32_t number(const std::vector<uint8_t>& b) { return b[0] | (b[1] << 8) | (b[2] << 16) | ((uint32_t)b[3] << 24); }

struct Reading
{
    std::vector<uint32_t> numbers;  //!< the transfers of data, in order
    UsbBulkStatus last = USB_BULK_TIMEOUT;
    int errors = 0;                 //!< USB_BULK_TRANSFER_ERROR answers
};

/** A link device on a fake link, streaming @p transfers transfers of 4 bytes. */
struct LinkDevice
{
    Ptr<FakeLink> link = makePtr<FakeLink>();
    Ptr<UsbDeviceHandle> device = createUsbLinkDevice(link);

    explicit LinkDevice(int transfers) { device->startBulkIn(0x82, transfers, 4); }

    /** Reads until @p n transfers of data came, the stream ended, or 5000 reads were made. */
    Reading read(size_t n)
    {
        Reading r;
        std::vector<uint8_t> data;
        for (int k = 0; k < 5000 && r.numbers.size() < n; k++)
        {
            r.last = device->readBulk(data, 20);
            if (r.last == USB_BULK_DATA)
                r.numbers.push_back(number(data));
            else if (r.last == USB_BULK_TRANSFER_ERROR)
                r.errors++;
            else if (r.last != USB_BULK_TIMEOUT)
                break;
        }
        return r;
    }
};

std::vector<uint32_t> iota(uint32_t from, uint32_t to)
{
    std::vector<uint32_t> v;
    for (uint32_t k = from; k < to; k++)
        v.push_back(k);
    return v;
}

TEST(Event_UsbLinkDevice, callbacks_on_a_control_request_thread_lose_and_repeat_nothing)
{
    // libusb runs completion callbacks on a thread sending a control request (a reset, a bias) whenever the
    // reading thread is between two waits: both threads then touch the completed-transfer queue.
    LinkDevice d(8);
    const uint32_t n = 3000;
    std::vector<uint32_t> got;
    std::atomic<size_t> received{ 0 };
    std::thread reader([&] {
        std::vector<uint8_t> data;
        for (int r = 0; r < 200000 && got.size() < n; r++)
            if (d.device->readBulk(data, 5) == USB_BULK_DATA)
            {
                got.push_back(number(data));
                received = got.size();
            }
    });
    const uint8_t value[4] = { 0, 0, 0, 1 };
    for (uint32_t k = 0; k < n; k++)
    {
        d.link->pushData(numbered(k));
        if (k % 10 == 9)  // left to the reading thread's wait, so that both threads run callbacks
            for (int i = 0; i < 10000 && received <= k; i++)
                std::this_thread::sleep_for(std::chrono::microseconds(100));
        else
            d.device->controlOut(0x40, 0xBF, 1, 3, value, 4);
    }
    reader.join();
    EXPECT_EQ(iota(0, n), got);
    const FakeLink::Counts c = d.link->counts();
    EXPECT_EQ(2u, c.callbackThreads.size()) << "the callbacks ran on one thread only: the case was not exercised";
    d.device->stopBulkIn();
    EXPECT_EQ(0, d.link->counts().inFlightWhenFreed);
}

TEST(Event_UsbLinkDevice, a_stall_is_cleared_from_the_reading_thread_and_the_stream_goes_on)
{
    LinkDevice d(8);
    for (uint32_t k = 0; k < 10; k++)
        d.link->pushData(numbered(k));
    d.link->pushStatus(USB_TRANSFER_STALL);
    for (uint32_t k = 10; k < 20; k++)
        d.link->pushData(numbered(k));
    const Reading r = d.read(20);
    EXPECT_EQ(iota(0, 20), r.numbers);
    EXPECT_EQ(1, r.errors);  // one loss reported for the stall, not one per transfer it failed
    EXPECT_EQ(1, d.link->counts().clearHalts);
    EXPECT_EQ(8, d.link->inFlight());
}

TEST(Event_UsbLinkDevice, an_endpoint_that_stalls_after_every_clear_ends_the_stream_with_the_reason)
{
    LinkDevice d(4);
    for (int k = 0; k < 10; k++)
        d.link->pushStatus(USB_TRANSFER_STALL);
    const Reading r = d.read(1);
    EXPECT_TRUE(r.numbers.empty());
    ASSERT_EQ(USB_BULK_STREAM_ENDED, r.last);
    EXPECT_NE(std::string::npos, d.device->streamEndReason().find("stalled 4 times in a row")) << d.device->streamEndReason();
    EXPECT_EQ(4, d.link->counts().clearHalts);
    std::vector<uint8_t> data;
    EXPECT_EQ(USB_BULK_STREAM_ENDED, d.device->readBulk(data, 10));  // and stays ended
}

TEST(Event_UsbLinkDevice, a_halt_that_cannot_be_cleared_ends_the_stream_with_the_reason)
{
    LinkDevice d(4);
    d.link->clearHaltResult = USB_LINK_ERROR_PIPE;
    d.link->pushData(numbered(7));
    d.link->pushStatus(USB_TRANSFER_STALL);
    const Reading r = d.read(2);
    EXPECT_EQ(std::vector<uint32_t>{ 7 }, r.numbers);
    ASSERT_EQ(USB_BULK_STREAM_ENDED, r.last);
    EXPECT_NE(std::string::npos, d.device->streamEndReason().find("clearing the halt failed: LIBUSB error -9"))
        << d.device->streamEndReason();
}

TEST(Event_UsbLinkDevice, failed_resubmissions_are_retried_and_no_data_is_lost)
{
    LinkDevice d(2);
    {
        std::lock_guard<std::mutex> lock(d.link->mutex);
        d.link->failingSubmits = 3;  // the two resubmissions after the first data, and one retry
    }
    for (uint32_t k = 0; k < 40; k++)
        d.link->pushData(numbered(k));
    const Reading r = d.read(40);
    EXPECT_EQ(iota(0, 40), r.numbers);
    EXPECT_EQ(0, r.errors);
    std::vector<uint8_t> data;
    EXPECT_EQ(USB_BULK_TIMEOUT, d.device->readBulk(data, 5));  // the last one left idle is retried here
    EXPECT_EQ(2, d.link->inFlight());
}

TEST(Event_UsbLinkDevice, resubmissions_that_keep_failing_end_the_stream_with_the_reason)
{
    LinkDevice d(2);
    {
        std::lock_guard<std::mutex> lock(d.link->mutex);
        d.link->failingSubmits = -1;
    }
    d.link->pushData(numbered(1));
    d.link->pushData(numbered(2));
    const Reading r = d.read(3);
    EXPECT_EQ(std::vector<uint32_t>({ 1, 2 }), r.numbers);
    ASSERT_EQ(USB_BULK_STREAM_ENDED, r.last);
    EXPECT_NE(std::string::npos, d.device->streamEndReason().find("no USB transfer could be kept in flight"))
        << d.device->streamEndReason();
    EXPECT_NE(std::string::npos, d.device->streamEndReason().find("LIBUSB error -1")) << d.device->streamEndReason();
}

TEST(Event_UsbLinkDevice, unplugging_ends_the_stream_as_gone)
{
    LinkDevice d(4);
    d.link->pushData(numbered(5));
    d.link->pushStatus(USB_TRANSFER_NO_DEVICE);
    const Reading r = d.read(2);
    EXPECT_EQ(std::vector<uint32_t>{ 5 }, r.numbers);
    EXPECT_EQ(USB_BULK_DEVICE_GONE, r.last);
    const uint8_t value[4] = { 0, 0, 0, 0 };
    EXPECT_THROW(d.device->controlOut(0x40, 0xBF, 1, 3, value, 4), cv::Exception);
    d.device->stopBulkIn();
    EXPECT_EQ(0, d.link->counts().inFlightWhenFreed);
}

TEST(Event_UsbLinkDevice, stopping_cancels_until_no_transfer_is_in_flight)
{
    // Two transfers complete just before the cancel (their cancel finds nothing); their callbacks run after
    // it. Resubmitting them then would leave transfers in flight that nobody cancels.
    LinkDevice d(4);
    d.link->pushData(numbered(1));
    d.link->pushData(numbered(2));
    d.device->stopBulkIn();
    const FakeLink::Counts c = d.link->counts();
    EXPECT_EQ(0, c.inFlightWhenFreed);
    EXPECT_EQ(0, c.submitsWhileStopping);
    EXPECT_EQ(4, c.callbacks);
}

}}  // namespace
