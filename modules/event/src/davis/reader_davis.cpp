// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Live DAVIS back-end of EventCapture: a reader thread turns the camera's bulk transfers into decoded event
// chunks in a bounded queue; next() hands them out. Nothing is dropped silently: a full queue, a failed
// transfer and an invalid address each have a counter, and an unplugged camera ends the stream with a
// message. Stereo: two cameras on a sync cable, the master's clock reset once both run and both decoders are
// armed for that reset (not for one the slave's FPGA latched before); later resets nobody asked for give both
// the same new epoch (DavisPairClock), and one that finds the sync cable gone ends the stream saying so.

#include "precomp.hpp"
#include "io/event_reader.hpp"
#include "davis/davis_device.hpp"
#include "davis/davis_event_decoder.hpp"
#include "davis/davis_pair_clock.hpp"
#include "davis/davis_protocol.hpp"

#include <atomic>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <thread>

namespace cv {
namespace event {
namespace detail {

namespace {

// libcaer's defaults for DAVIS: 8 transfers of 8 KiB in flight.
const int kTransfers = 8;
const int kTransferBytes = 8192;
const int kPollMs = 100;  // how often the reader thread and a waiting next() look at the stop / end flags

class DavisReader CV_FINAL : public EventReader
{
public:
    /** @param pair the clock two cameras of a stereo pair share, with @p pairIndex this camera's (0 or 1);
    empty for a single camera. */
    DavisReader(const Ptr<DavisDevice>& device, const ReaderOptions& options, bool resetsClock,
                const Ptr<DavisPairClock>& pair = Ptr<DavisPairClock>(), int pairIndex = 0)
        : device_(device), capacity_((size_t)std::max(1, options.liveQueueCapacity)), resetsClock_(resetsClock),
          pair_(pair), pairIndex_(pairIndex),
          decoder_(device->identity().rawColumns, device->identity().rawRows, device->identity().invertXY, true)
    {
        decoder_.disarm();  // a reset the FPGA latched before the start must not set the time: armClock() does
        if (pair_)
            decoder_.setUnarmedResetEpoch([this](int64 lastTime) {
                return pair_->agree(pairIndex_, unarmedResets_++, lastTime);
            });
    }

    ~DavisReader() CV_OVERRIDE { shutdown(); }

    /** Starts the transfers and the reader thread (the clock reset comes later, see openDavis*). */
    void start()
    {
        started_ = true;
        device_->start(kTransfers, kTransferBytes);
        thread_ = std::thread(&DavisReader::run, this);
    }

    /** The next timestamp reset sets this camera's time to @p epochUs. Returns once the reader thread has
    taken it (bounded), so that a pulse sent afterwards is the one it waits for. */
    void armClock(int64 epochUs)
    {
        std::unique_lock<std::mutex> lock(mutex_);
        armEpoch_ = epochUs;
        armPending_ = true;
        armTaken_.wait_for(lock, std::chrono::seconds(2), [&] { return !armPending_ || ended_; });
    }

    /** Arms this camera for time 0 and pulses its reset (and, through the cable, its slave's). */
    void resetClock()
    {
        armClock(0);
        device_->resetTimestamp();
    }

    String name() const CV_OVERRIDE { return "DAVIS"; }
    Size sensorSize() const CV_OVERRIDE { return device_->identity().sensorSize(); }
    bool isLive() const CV_OVERRIDE { return true; }
    int64 timeHorizon() const CV_OVERRIDE
    {
        // Only what next() has handed out counts: events still queued may be older than the camera's clock.
        std::lock_guard<std::mutex> lock(mutex_);
        return queue_.empty() ? cameraHorizon_ : deliveredHorizon_;
    }

    String endMessage() const CV_OVERRIDE
    {
        std::lock_guard<std::mutex> lock(mutex_);
        return endMessage_;
    }

    bool next(std::vector<Event>& out) CV_OVERRIDE
    {
        std::unique_lock<std::mutex> lock(mutex_);
        if (queue_.empty() && !ended_)
            ready_.wait_for(lock, std::chrono::milliseconds(kPollMs), [&] { return !queue_.empty() || ended_; });
        if (!queue_.empty())
        {
            out.insert(out.end(), queue_.front().events.begin(), queue_.front().events.end());
            triggers_.insert(triggers_.end(), queue_.front().triggers.begin(), queue_.front().triggers.end());
            deliveredHorizon_ = queue_.front().horizon;
            queue_.pop_front();
            return true;
        }
        if (ended_)
        {
            if (!fatalError_.empty())
                CV_Error(Error::StsError, fatalError_);
            return false;
        }
        return true;  // nothing yet: the caller may look at timeHorizon() and call again
    }

    bool setProperty(int propId, double value) CV_OVERRIDE
    {
        if (propId == EVENT_CAP_PROP_DEVICE_TIMESTAMP_RESET && !resetsClock_)
            return cvRound(value) == 1;  // a stereo slave: the master's pulse resets it
        return device_->setProperty(propId, value);
    }

    bool getProperty(int propId, double& value) const CV_OVERRIDE
    {
        std::lock_guard<std::mutex> lock(mutex_);
        switch (propId)
        {
        case EVENT_CAP_PROP_DROPPED_EVENTS: value = (double)droppedEvents_; return true;
        case EVENT_CAP_PROP_DROPPED_TRANSFERS: value = (double)droppedTransfers_; return true;
        case EVENT_CAP_PROP_INVALID_ADDRESSES: value = (double)counters_.invalidAddresses; return true;
        default: return device_->getProperty(propId, value);
        }
    }

    int64 skippedEvents() const CV_OVERRIDE
    {
        std::lock_guard<std::mutex> lock(mutex_);
        return counters_.eventsBeforeReset;
    }

    /** Stops the thread and the camera; bounded time, never raises. */
    void shutdown()
    {
        stop_ = true;
        if (thread_.joinable())
            thread_.join();
        if (started_)
            device_->stop();
        started_ = false;
    }

private:
    void run()
    {
        std::vector<uint8_t> transfer;
        std::vector<Event> events;
        std::vector<EventTrigger> triggers;
        int64 resetsSeen = 0;
        while (!stop_)
        {
            {
                std::lock_guard<std::mutex> lock(mutex_);
                if (armPending_)
                {
                    decoder_.arm(armEpoch_);
                    armPending_ = false;
                    armTaken_.notify_all();
                }
            }
            UsbBulkStatus status;
            try
            {
                status = device_->usb().readBulk(transfer, kPollMs);
            }
            catch (const cv::Exception& e)
            {
                finish(String(), e.err);
                return;
            }
            if (status == USB_BULK_TIMEOUT)
                continue;
            if (status == USB_BULK_TRANSFER_ERROR)
            {
                std::lock_guard<std::mutex> lock(mutex_);
                droppedTransfers_++;
                continue;
            }
            if (status == USB_BULK_DEVICE_GONE)
            {
                finish(cv::format("%s: the camera was unplugged (USB device gone); the stream ends here",
                                  device_->identity().name().c_str()), String());
                return;
            }
            if (status == USB_BULK_STREAM_ENDED)
            {
                finish(cv::format("%s: %s; the stream ends here", device_->identity().name().c_str(),
                                  device_->usb().streamEndReason().c_str()), String());
                return;
            }
            events.clear();
            triggers.clear();
            decoder_.decode(transfer.data(), transfer.size(), events);
            decoder_.takeTriggers(triggers);
            if (pair_)
            {
                pair_->publish(pairIndex_, decoder_.currentTime());
                const int64 resets = decoder_.counters().timestampResets;
                if (resets != resetsSeen && decoder_.synchronised() && syncCableLost())
                    return;
                resetsSeen = resets;
            }
            {
                std::lock_guard<std::mutex> lock(mutex_);
                counters_ = decoder_.counters();
                const int64 horizon = decoder_.synchronised() ? decoder_.currentTime() : INT64_MIN;
                if (!events.empty() || !triggers.empty())
                {
                    if (queue_.size() < capacity_)
                        queue_.push_back({ events, triggers, horizon });
                    else
                    {
                        droppedEvents_ += (int64)events.size();  // read() is not keeping up: counted, not silent
                        // Triggers are few and precious: they ride with the last queued chunk instead.
                        queue_.back().triggers.insert(queue_.back().triggers.end(), triggers.begin(), triggers.end());
                    }
                }
                cameraHorizon_ = horizon;
            }
            ready_.notify_one();
        }
    }

    /** After a reset: whether this camera's master / slave role changed (libcaer reads it on every reset).
    A slave turned master has lost its sync cable: its clock runs apart from here, so the stream ends. */
    bool syncCableLost()
    {
        bool master;
        try
        {
            master = device_->readConfig(davis::SYSINFO, davis::SYSINFO_DEVICE_IS_MASTER) != 0;
        }
        catch (const cv::Exception&)
        {
            return false;  // gone or not answering: the next read says so
        }
        if (master == device_->identity().master)
            return false;
        finish(cv::format("%s: the stereo sync cable was unplugged (this camera, %s at the start, now reports "
                          "%s): the two clocks run apart from here, so the stream ends; reconnect it and reopen",
                          device_->identity().name().c_str(), master ? "the slave" : "the master",
                          master ? "master" : "slave"), String());
        return true;
    }

    void finish(const String& endMessage, const String& fatal)
    {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            endMessage_ = endMessage;
            fatalError_ = fatal;
            ended_ = true;
        }
        ready_.notify_all();
        armTaken_.notify_all();
    }

    Ptr<DavisDevice> device_;
    const size_t capacity_;
    const bool resetsClock_;
    Ptr<DavisPairClock> pair_;
    const int pairIndex_;
    DavisEventDecoder decoder_;  // reader thread only
    int unarmedResets_ = 0;      // reader thread only
    std::thread thread_;
    bool started_ = false;
    std::atomic<bool> stop_{ false };

    mutable std::mutex mutex_;  // guards everything below
    std::condition_variable ready_, armTaken_;
    bool armPending_ = false;
    int64 armEpoch_ = 0;
    struct Chunk
    {
        std::vector<Event> events;
        std::vector<EventTrigger> triggers;
        int64 horizon;  // the camera's clock after the transfer that held them
    };
    std::deque<Chunk> queue_;
    int64 cameraHorizon_ = INT64_MIN, deliveredHorizon_ = INT64_MIN;
    bool ended_ = false;
    String endMessage_, fatalError_;
    int64 droppedEvents_ = 0, droppedTransfers_ = 0;
    DavisEventDecoder::Counters counters_;
};

Ptr<DavisDevice> openConfiguredDevice(const Ptr<UsbTransport>& transport, const UsbDeviceId& id,
                                      const ReaderOptions& options)
{
    Ptr<DavisDevice> device = makePtr<DavisDevice>(transport, id);
    device->sendDefaultConfig();
    for (const auto& s : options.deviceSettings)
        if (s.first != EVENT_CAP_PROP_DEVICE_TIMESTAMP_RESET && !device->setProperty(s.first, s.second))
            CV_Error_(Error::StsBadArg, ("%s: property %d cannot be set to %g on this camera",
                                         device->identity().name().c_str(), s.first, s.second));
    return device;
}

}  // namespace

Ptr<EventReader> openDavisReader(const String& source, const String& selector, const ReaderOptions& options)
{
    const Ptr<UsbTransport> transport = getUsbTransport();
    Ptr<DavisReader> reader = makePtr<DavisReader>(
        openConfiguredDevice(transport, resolveDavisCamera(*transport, source, selector), options), options, true);
    reader->start();
    reader->resetClock();  // events from before the reset are skipped: time starts at 0 with the capture
    return reader;
}

Ptr<EventReader> openDavisStereo(const String& leftSource, const String& leftSelector, const String& rightSource,
                                 const String& rightSelector, const ReaderOptions& options, int64 rightTimeOffset)
{
    const Ptr<UsbTransport> transport = getUsbTransport();
    const UsbDeviceId leftId = resolveDavisCamera(*transport, leftSource, leftSelector);
    const UsbDeviceId rightId = resolveDavisCamera(*transport, rightSource, rightSelector);
    if (leftId.bus == rightId.bus && leftId.address == rightId.address)
        CV_Error_(Error::StsBadArg, ("%s and %s are the same camera (%s)", leftSource.c_str(), rightSource.c_str(),
                                     leftId.location().c_str()));
    Ptr<DavisDevice> left = openConfiguredDevice(transport, leftId, options);
    Ptr<DavisDevice> right = openConfiguredDevice(transport, rightId, options);
    const bool leftMaster = left->identity().master, rightMaster = right->identity().master;
    if (leftMaster && rightMaster)
        CV_Error_(Error::StsError, ("stereo %s + %s: both cameras report master, so their clocks run apart: connect "
                                    "the sync cable (one camera's sync output to the other's input)",
                                    left->identity().name().c_str(), right->identity().name().c_str()));
    if (!leftMaster && !rightMaster)
        CV_Error_(Error::StsError, ("stereo %s + %s: both cameras report slave: each waits for a clock the other "
                                    "does not send (check the sync cable's direction)",
                                    left->identity().name().c_str(), right->identity().name().c_str()));
    Ptr<DavisPairClock> pair = makePtr<DavisPairClock>();
    Ptr<DavisReader> l = makePtr<DavisReader>(left, options, leftMaster, pair, 0);
    Ptr<DavisReader> r = makePtr<DavisReader>(right, options, rightMaster, pair, 1);
    // The slave runs first, so that it counts from the master's reset pulse like the master does; its FPGA may
    // send a reset it latched while stopped as its first word: only the pulse after arming counts.
    Ptr<DavisReader> master = leftMaster ? l : r, slave = leftMaster ? r : l;
    slave->start();
    master->start();
    slave->armClock(0);
    master->resetClock();
    return openStereoMerge(l, r, rightTimeOffset);
}

}  // namespace detail

std::vector<EventDeviceInfo> listEventDevices()
{
    using namespace detail;
    std::vector<EventDeviceInfo> devices;
    const Ptr<UsbTransport> transport = getUsbTransport();
    const std::vector<UsbDeviceId> cameras = findDavisCameras(*transport);
    for (size_t i = 0; i < cameras.size(); i++)
    {
        EventDeviceInfo info;
        info.source = cameras[i].serial.empty() ? cv::format("davis:%d", (int)i) : "davis:" + cameras[i].serial;
        info.model = "DAVIS";
        info.serial = cameras[i].serial;
        info.usbLocation = cameras[i].location();
        info.firmwareVersion = cameras[i].firmwareVersion;
        info.logicVersion = -1;
        info.master = false;
        try
        {
            DavisDevice device(transport, cameras[i]);
            const DavisIdentity& d = device.identity();
            info.model = d.model();
            info.logicVersion = d.logicVersion;
            info.sensorSize = d.sensorSize();
            info.master = d.master;
        }
        catch (const cv::Exception& e)
        {
            info.error = e.err;
        }
        devices.push_back(info);
    }
    return devices;
}

}  // namespace event
}  // namespace cv
