// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// A fake UsbLink with libusb's semantics where the transfer bookkeeping depends on them: a transfer completes
// when the "device" has something for it, its callback runs on whichever thread handles events next (a
// synchronous control request does so too), never on two threads at once; cancelling a transfer that has
// completed finds nothing; a stalled endpoint fails every transfer in flight and every new one until its halt
// is cleared; an unplugged device fails everything.

#ifndef OPENCV_EVENT_TEST_FAKE_USB_LINK_HPP
#define OPENCV_EVENT_TEST_FAKE_USB_LINK_HPP

#include "test_precomp.hpp"
#include "davis/usb_link.hpp"

#include <chrono>
#include <deque>
#include <mutex>
#include <set>
#include <thread>

namespace opencv_test {
namespace fake_usb_link {

using namespace cv::event::detail;

class FakeLink CV_FINAL : public UsbLink
{
public:
    /** Settings a test changes before or while streaming (under `mutex` once streaming). */
    bool callbacksOnControl = true;  // a control request handles events (no other thread is at that moment)
    int failingSubmits = 0;          // the next this many submissions fail with an I/O error (-1: all)
    int clearHaltResult = 0;

    /** What the device sends next, to the oldest transfer in flight. */
    void pushData(const std::vector<uint8_t>& bytes) { push(USB_TRANSFER_COMPLETED, bytes); }
    void pushStatus(UsbTransferStatus status) { push(status, std::vector<uint8_t>()); }

    /** Counters the tests read. */
    struct Counts
    {
        int controls = 0, clearHalts = 0, submits = 0, submitsWhileStopping = 0, cancels = 0, callbacks = 0;
        int inFlightWhenFreed = -1;  // -1: never freed
        std::set<std::thread::id> callbackThreads;
    };
    Counts counts()
    {
        std::lock_guard<std::mutex> lock(mutex);
        return counts_;
    }
    int inFlight()
    {
        std::lock_guard<std::mutex> lock(mutex);
        return (int)std::count(state_.begin(), state_.end(), IN_FLIGHT);
    }

    String location() const CV_OVERRIDE { return "usb 001:042"; }
    String errorText(int code) const CV_OVERRIDE { return cv::format("LIBUSB error %d (fake)", code); }

    int control(uint8_t, uint8_t, uint16_t, uint16_t, uint8_t*, uint16_t size) CV_OVERRIDE
    {
        bool deliverHere;
        {
            std::lock_guard<std::mutex> lock(mutex);
            counts_.controls++;
            if (gone_)
                return USB_LINK_ERROR_NO_DEVICE;
            deliverHere = callbacksOnControl;
        }
        if (deliverHere)
            deliver();
        return size;
    }

    int clearHalt(uint8_t) CV_OVERRIDE
    {
        std::lock_guard<std::mutex> lock(mutex);
        counts_.clearHalts++;
        if (gone_)
            return USB_LINK_ERROR_NO_DEVICE;
        if (clearHaltResult == 0)
            halted_ = false;
        return clearHaltResult;
    }

    int allocateBulkIn(uint8_t, int transfers, int, UsbLinkListener* listener) CV_OVERRIDE
    {
        std::lock_guard<std::mutex> lock(mutex);
        listener_ = listener;
        state_.assign((size_t)transfers, IDLE);
        return 0;
    }

    int submit(int transfer) CV_OVERRIDE
    {
        std::lock_guard<std::mutex> lock(mutex);
        counts_.submits++;
        if (counts_.cancels > 0)
            counts_.submitsWhileStopping++;
        if (gone_)
            return USB_LINK_ERROR_NO_DEVICE;
        if (failingSubmits != 0)
        {
            if (failingSubmits > 0)
                failingSubmits--;
            return USB_LINK_ERROR_IO;
        }
        if (state_[(size_t)transfer] != IDLE)
            return USB_LINK_ERROR_BUSY;  // submitted twice: the bookkeeping lost track of it
        state_[(size_t)transfer] = IN_FLIGHT;
        waiting_.push_back(transfer);
        assign();
        return 0;
    }

    int cancel(int transfer) CV_OVERRIDE
    {
        std::lock_guard<std::mutex> lock(mutex);
        counts_.cancels++;
        auto it = std::find(waiting_.begin(), waiting_.end(), transfer);
        if (it == waiting_.end())
            return USB_LINK_ERROR_NOT_FOUND;  // idle, or completed and its callback not yet run
        waiting_.erase(it);
        done_.push_back({ transfer, USB_TRANSFER_CANCELLED, std::vector<uint8_t>() });
        return 0;
    }

    int handleEvents(int timeoutMs) CV_OVERRIDE
    {
        if (!deliver())
            std::this_thread::sleep_for(std::chrono::milliseconds(std::min(timeoutMs, 1)));
        return 0;
    }

    void freeBulkIn() CV_OVERRIDE
    {
        std::lock_guard<std::mutex> lock(mutex);
        counts_.inFlightWhenFreed = (int)std::count(state_.begin(), state_.end(), IN_FLIGHT);
        state_.clear();
    }

    std::mutex mutex;

private:
    enum TransferState { IDLE, IN_FLIGHT };
    struct Completion
    {
        int transfer;
        UsbTransferStatus status;
        std::vector<uint8_t> data;
    };

    void push(UsbTransferStatus status, const std::vector<uint8_t>& bytes)
    {
        std::lock_guard<std::mutex> lock(mutex);
        script_.push_back({ -1, status, bytes });
        assign();
    }

    /** Completes the transfers in flight that the device has something for (lock held). */
    void assign()
    {
        while (!waiting_.empty())
        {
            Completion c;
            if (gone_)
                c.status = USB_TRANSFER_NO_DEVICE;
            else if (halted_)
                c.status = USB_TRANSFER_STALL;
            else if (!script_.empty())
            {
                c = script_.front();
                script_.pop_front();
                if (c.status == USB_TRANSFER_STALL)
                    halted_ = true;
                if (c.status == USB_TRANSFER_NO_DEVICE)
                    gone_ = true;
            }
            else
                break;
            c.transfer = waiting_.front();
            waiting_.pop_front();
            done_.push_back(c);
        }
    }

    /** Runs the callbacks of the completed transfers on this thread, one thread at a time (libusb's event
    lock); true when there was any. */
    bool deliver()
    {
        std::lock_guard<std::mutex> events(eventLock_);
        bool any = false;
        for (;;)
        {
            Completion c;
            {
                std::lock_guard<std::mutex> lock(mutex);
                if (done_.empty())
                    break;
                c = std::move(done_.front());
                done_.pop_front();
                state_[(size_t)c.transfer] = IDLE;
                counts_.callbacks++;
                counts_.callbackThreads.insert(std::this_thread::get_id());
            }
            listener_->transferDone(c.transfer, c.status, c.data.data(), (int)c.data.size());
            any = true;
        }
        return any;
    }

    std::mutex eventLock_;
    UsbLinkListener* listener_ = nullptr;
    std::vector<TransferState> state_;
    std::deque<int> waiting_;            // in flight, nothing for them yet (in submission order)
    std::deque<Completion> done_;        // completed, callback not yet run
    std::deque<Completion> script_;      // what the device sends next
    bool halted_ = false, gone_ = false;
    Counts counts_;
};

}  // namespace fake_usb_link
}  // namespace opencv_test

#endif  // OPENCV_EVENT_TEST_FAKE_USB_LINK_HPP
