// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Keeps a camera's bulk IN transfers in flight over a UsbLink. libusb runs a completion callback on whatever
// thread handles events, and a control request sent while streaming (a timestamp reset, a bias) handles them
// itself when the reading thread is between two waits: so every piece of state a callback touches is under
// one lock. What a callback cannot do (clear a stall: a synchronous request; retry a failed resubmission) is
// left to the reading thread, which does it between waits.

#include "precomp.hpp"
#include "davis/usb_link.hpp"
#include "opencv2/core/utils/logger.hpp"

#include <deque>
#include <mutex>

namespace cv {
namespace event {
namespace detail {

namespace {

const int kMaxWaitSliceMs = 100;        // the longest single wait for events, so that state is looked at often
const int kStallGatherMs = 100;         // after a stall, how long the other transfers may take to come back
const int kMaxStallRoundsWithoutData = 3;
const int kMaxResubmitRounds = 3;       // rounds of retrying failed resubmissions with none in flight
const double kStopBoundSeconds = 2.0;   // stopBulkIn() gives up waiting for transfers after this

class UsbLinkDevice CV_FINAL : public UsbDeviceHandle, public UsbLinkListener
{
public:
    explicit UsbLinkDevice(const Ptr<UsbLink>& link) : link_(link) {}

    ~UsbLinkDevice() CV_OVERRIDE { stopBulkIn(); }

    void controlOut(uint8_t requestType, uint8_t request, uint16_t value, uint16_t index, const uint8_t* data,
                    size_t size) CV_OVERRIDE
    {
        const int rc = link_->control(requestType, request, value, index, const_cast<uint8_t*>(data), (uint16_t)size);
        if (rc != (int)size)
            CV_Error_(Error::StsError, ("%s: control request 0x%02X (value %u, index %u) failed: %s",
                                        link_->location().c_str(), request, value, index,
                                        rc < 0 ? link_->errorText(rc).c_str() : "short transfer"));
    }

    void controlIn(uint8_t requestType, uint8_t request, uint16_t value, uint16_t index, uint8_t* data,
                   size_t size) CV_OVERRIDE
    {
        const int rc = link_->control(requestType, request, value, index, data, (uint16_t)size);
        if (rc != (int)size)
            CV_Error_(Error::StsError, ("%s: control read 0x%02X (value %u, index %u) failed: %s",
                                        link_->location().c_str(), request, value, index,
                                        rc < 0 ? link_->errorText(rc).c_str() : "short transfer"));
    }

    void clearHalt(uint8_t endpoint) CV_OVERRIDE
    {
        const int rc = link_->clearHalt(endpoint);
        if (rc != 0)
            CV_Error_(Error::StsError, ("%s: clearing the halt of endpoint 0x%02X failed: %s",
                                        link_->location().c_str(), endpoint, link_->errorText(rc).c_str()));
    }

    void startBulkIn(uint8_t endpoint, int transfers, int bytes) CV_OVERRIDE
    {
        CV_Assert(transfers > 0 && !allocated_);
        int rc = link_->allocateBulkIn(endpoint, transfers, bytes, this);
        if (rc != 0)
            CV_Error_(Error::StsNoMem, ("%s: cannot allocate %d USB transfers: %s", link_->location().c_str(),
                                        transfers, link_->errorText(rc).c_str()));
        {
            std::lock_guard<std::mutex> lock(mutex_);
            allocated_ = true;
            endpoint_ = endpoint;
            inFlight_.assign((size_t)transfers, false);
            stopping_ = false;
            gone_ = false;
            endReason_.clear();
            completed_.clear();
            idle_.clear();
            halted_.clear();
            stallRounds_ = resubmitRounds_ = 0;
            for (int i = 0; i < transfers && rc == 0; i++)
            {
                rc = link_->submit(i);
                if (rc == 0)
                    inFlight_[(size_t)i] = true;
            }
        }
        if (rc != 0)
        {
            stopBulkIn();
            CV_Error_(Error::StsError, ("%s: submitting bulk transfers on endpoint 0x%02X failed: %s",
                                        link_->location().c_str(), endpoint, link_->errorText(rc).c_str()));
        }
    }

    UsbBulkStatus readBulk(std::vector<uint8_t>& data, int timeoutMs) CV_OVERRIDE
    {
        const int64 deadline = getTickCount() + (int64)(timeoutMs * getTickFrequency() / 1000.0);
        for (;;)
        {
            std::vector<int> halted, idle;
            {
                std::lock_guard<std::mutex> lock(mutex_);
                if (!completed_.empty())
                {
                    Completed c = std::move(completed_.front());
                    completed_.pop_front();
                    if (!c.ok)
                        return USB_BULK_TRANSFER_ERROR;
                    data.swap(c.data);
                    return USB_BULK_DATA;
                }
                if (gone_)
                    return USB_BULK_DEVICE_GONE;
                if (!endReason_.empty())
                    return USB_BULK_STREAM_ENDED;
                // A stall halts every transfer on the endpoint: clear it once they are all back (or after a
                // short while), not once per transfer.
                if (!halted_.empty() && (inFlightCount() == 0 || elapsedMs(firstStall_) >= kStallGatherMs))
                    halted.swap(halted_);
                if (!idle_.empty())
                    idle.swap(idle_);
            }
            if (!halted.empty())
                recoverFromStall(halted);
            if (!idle.empty())
                retrySubmit(idle);
            const int64 left = deadline - getTickCount();
            if (left <= 0)
                return USB_BULK_TIMEOUT;
            const int leftMs = std::max(1, (int)((double)left * 1000.0 / getTickFrequency()));
            const int rc = link_->handleEvents(std::min(leftMs, kMaxWaitSliceMs));
            if (rc == USB_LINK_ERROR_NO_DEVICE)
            {
                std::lock_guard<std::mutex> lock(mutex_);
                gone_ = true;
            }
            else if (rc < 0 && rc != USB_LINK_ERROR_INTERRUPTED && rc != USB_LINK_ERROR_TIMEOUT)
            {
                std::lock_guard<std::mutex> lock(mutex_);
                endReason_ = "handling USB events failed: " + link_->errorText(rc);
            }
        }
    }

    String streamEndReason() const CV_OVERRIDE
    {
        std::lock_guard<std::mutex> lock(mutex_);
        return endReason_;
    }

    void stopBulkIn() CV_OVERRIDE
    {
        if (!allocated_)
            return;
        const int64 start = getTickCount();
        bool done = false;
        // Cancel until none is in flight: a transfer that completed just before its cancel is not resubmitted
        // (stopping_), but one resubmitted by a callback racing with the flag is caught by the next round.
        while (!done && (double)(getTickCount() - start) / getTickFrequency() < kStopBoundSeconds)
        {
            std::vector<int> inFlight;
            {
                std::lock_guard<std::mutex> lock(mutex_);
                stopping_ = true;
                for (size_t i = 0; i < inFlight_.size(); i++)
                    if (inFlight_[i])
                        inFlight.push_back((int)i);
                done = inFlight.empty();
            }
            if (done)
                break;
            for (int i : inFlight)
                link_->cancel(i);  // NOT_FOUND when it completed meanwhile: its callback comes next
            link_->handleEvents(10);
        }
        std::lock_guard<std::mutex> lock(mutex_);
        if (done)
        {
            link_->freeBulkIn();
            allocated_ = false;
        }
        else
            CV_LOG_WARNING(NULL, link_->location() << ": " << inFlightCount()
                                                   << " USB transfers did not come back when cancelled; their memory "
                                                      "is kept until the program ends");
        completed_.clear();
        halted_.clear();
        idle_.clear();
    }

    void transferDone(int transfer, UsbTransferStatus status, const uint8_t* data, int length) CV_OVERRIDE
    {
        std::lock_guard<std::mutex> lock(mutex_);
        inFlight_[(size_t)transfer] = false;
        switch (status)
        {
        case USB_TRANSFER_COMPLETED:
            completed_.push_back({ true, std::vector<uint8_t>(data, data + length) });
            stallRounds_ = 0;
            resubmitRounds_ = 0;
            break;
        case USB_TRANSFER_CANCELLED:
            return;
        case USB_TRANSFER_NO_DEVICE:
            gone_ = true;
            return;
        case USB_TRANSFER_STALL:
            if (halted_.empty())  // one stall fails every transfer in flight: one loss for the reader to count
            {
                completed_.push_back({ false, std::vector<uint8_t>() });
                firstStall_ = getTickCount();
            }
            if (!stopping_)
                halted_.push_back(transfer);
            return;
        case USB_TRANSFER_FAILED:
            completed_.push_back({ false, std::vector<uint8_t>() });
            break;
        }
        if (stopping_)
            return;
        submitLocked(transfer);
    }

private:
    struct Completed
    {
        bool ok;
        std::vector<uint8_t> data;
    };

    static double elapsedMs(int64 since) { return (double)(getTickCount() - since) * 1000.0 / getTickFrequency(); }

    int inFlightCount() const { return (int)std::count(inFlight_.begin(), inFlight_.end(), true); }

    /** Resubmits @p transfer (lock held); a failure leaves it to the reading thread to retry. */
    void submitLocked(int transfer)
    {
        const int rc = link_->submit(transfer);
        if (rc == 0)
            inFlight_[(size_t)transfer] = true;
        else if (rc == USB_LINK_ERROR_NO_DEVICE)
            gone_ = true;
        else
        {
            idle_.push_back(transfer);
            lastSubmitError_ = link_->errorText(rc);
        }
    }

    void recoverFromStall(const std::vector<int>& halted)
    {
        int rc = link_->clearHalt(endpoint_);
        std::lock_guard<std::mutex> lock(mutex_);
        if (stopping_)
            return;
        if (rc == USB_LINK_ERROR_NO_DEVICE)
        {
            gone_ = true;
            return;
        }
        if (rc != 0)
        {
            endReason_ = cv::format("the data endpoint 0x%02X stalled and clearing the halt failed: %s", endpoint_,
                                    link_->errorText(rc).c_str());
            return;
        }
        if (++stallRounds_ > kMaxStallRoundsWithoutData)
        {
            endReason_ = cv::format("the data endpoint 0x%02X stalled %d times in a row with no data in between, "
                                    "each time right after its halt was cleared (re-plug the camera)", endpoint_,
                                    stallRounds_);
            return;
        }
        for (int t : halted)
            submitLocked(t);
    }

    void retrySubmit(const std::vector<int>& idle)
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (stopping_)
            return;
        for (int t : idle)
            submitLocked(t);
        // Transfers still idle with none in flight: nothing can arrive. A few rounds (a transient failure may
        // pass), then the stream ends saying why instead of waiting forever.
        if (inFlightCount() == 0 && !gone_ && ++resubmitRounds_ > kMaxResubmitRounds)
            endReason_ = cv::format("no USB transfer could be kept in flight (%d resubmissions failed in a row: %s)",
                                    resubmitRounds_, lastSubmitError_.c_str());
    }

    Ptr<UsbLink> link_;
    bool allocated_ = false;  // caller's thread only
    uint8_t endpoint_ = 0;

    mutable std::mutex mutex_;  // guards everything below: callbacks may run on any thread
    std::vector<bool> inFlight_;
    std::deque<Completed> completed_;
    std::vector<int> halted_, idle_;  // stalled, and failed to resubmit: the reading thread resubmits them
    int64 firstStall_ = 0;
    int stallRounds_ = 0, resubmitRounds_ = 0;
    bool stopping_ = false, gone_ = false;
    String endReason_, lastSubmitError_;
};

}  // namespace

Ptr<UsbDeviceHandle> createUsbLinkDevice(const Ptr<UsbLink>& link)
{
    return makePtr<UsbLinkDevice>(link);
}

}  // namespace detail
}  // namespace event
}  // namespace cv
