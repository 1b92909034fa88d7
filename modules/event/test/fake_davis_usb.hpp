// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// A fake USB transport for the live DAVIS back-end: it answers the configuration channel from a register map,
// records every write, and replays scripted bulk transfers (data, failed transfers, unplug). EventCapture runs
// unchanged on top of it, so identification, configuration, start / stop, stereo sync and the error paths are
// those a real camera gets.

#ifndef OPENCV_EVENT_TEST_FAKE_DAVIS_USB_HPP
#define OPENCV_EVENT_TEST_FAKE_DAVIS_USB_HPP

#include "test_precomp.hpp"
#include "davis_test_words.hpp"
#include "davis/usb_transport.hpp"

#include <chrono>
#include <deque>
#include <mutex>
#include <thread>

namespace opencv_test {
namespace fake_davis_usb {

using namespace cv::event::detail;
using namespace davis_words;

struct ConfigWrite
{
    int camera, module, param;
    uint32_t value;
};

/** What every fake camera of one test writes, in order (a stereo test checks the order across cameras). */
struct WriteLog
{
    std::mutex mutex;
    std::vector<ConfigWrite> writes;
    std::vector<std::pair<int, std::string> > usbCalls;  // (camera, "clearHalt 0x82" / "startBulkIn" / "stopBulkIn")
    void add(const ConfigWrite& w)
    {
        std::lock_guard<std::mutex> lock(mutex);
        writes.push_back(w);
    }
    void call(int camera, const std::string& what)
    {
        std::lock_guard<std::mutex> lock(mutex);
        usbCalls.emplace_back(camera, what);
    }
    /** Index of the first write (module, param, value) of @p camera at or after @p from; -1 when none. */
    int find(int camera, int module, int param, uint32_t value, int from = 0)
    {
        std::lock_guard<std::mutex> lock(mutex);
        for (size_t i = (size_t)from; i < writes.size(); i++)
            if (writes[i].camera == camera && writes[i].module == module && writes[i].param == param &&
                writes[i].value == value)
                return (int)i;
        return -1;
    }
    std::map<std::pair<int, int>, uint32_t> lastValues(int camera)
    {
        std::lock_guard<std::mutex> lock(mutex);
        std::map<std::pair<int, int>, uint32_t> m;
        for (const ConfigWrite& w : writes)
            if (w.camera == camera)
                m[std::make_pair(w.module, w.param)] = w.value;
        return m;
    }
};

/** One scripted camera. Register reads come from `registers` (writes go there too); bulk reads replay `bulk`;
a timestamp-reset pulse while the multiplexer runs appends a reset word and then `afterReset` to its stream
and to that of its slave. Like the FPGA, a camera whose multiplexer is stopped latches a reset instead
(`latchedReset`: a slave has one from its power-up) and sends it as its first word at the next start,
followed by `beforeSync` (what it records until the master's pulse). */
struct FakeCamera
{
    int index = 0;
    UsbDeviceId id;
    std::map<std::pair<int, int>, uint32_t> registers;  // under `mutex` once a capture is open
    std::vector<uint8_t> afterReset, beforeSync;
    bool latchedReset = false;
    bool muxRunning = false;
    FakeCamera* slave = nullptr;
    bool unplugWhenDrained = false;
    std::string openError;
    Ptr<WriteLog> log;

    /** Paced replay: data transfers come out no faster than this many bytes per second, counted from the
    first one (0: as fast as they are read), as from a camera streaming live. */
    double bytesPerSecond = 0;

    std::mutex mutex;
    std::deque<std::pair<UsbBulkStatus, std::vector<uint8_t> > > bulk;
    bool gone = false;
    int resets = 0;
    int readsWhenDrained = 0;  // bulk reads that found nothing left after a reset: every transfer was handled
    bool paced = false;  // the first paced transfer went out at paceStart
    std::chrono::steady_clock::time_point paceStart;
    double pacedBytes = 0;

    /** With pacing: how long the next data transfer must still wait [us] (0: it may go now). Starts the
    clock at the first call. */
    double paceWaitUs(size_t transferBytes)
    {
        if (!(bytesPerSecond > 0))
            return 0;
        const auto now = std::chrono::steady_clock::now();
        if (!paced)
        {
            paced = true;
            paceStart = now;
        }
        const double dueUs = (pacedBytes + (double)transferBytes) / bytesPerSecond * 1e6;
        const double elapsedUs = std::chrono::duration<double, std::micro>(now - paceStart).count();
        if (elapsedUs < dueUs)
            return dueUs - elapsedUs;
        pacedBytes += (double)transferBytes;
        return 0;
    }

    void pushData(const std::vector<uint8_t>& bytes, size_t transferBytes = 4096)
    {
        std::lock_guard<std::mutex> lock(mutex);
        for (size_t i = 0; i < bytes.size(); i += transferBytes)
            bulk.emplace_back(USB_BULK_DATA, std::vector<uint8_t>(bytes.begin() + i,
                                                                  bytes.begin() + std::min(bytes.size(), i + transferBytes)));
    }
    void pushStatus(UsbBulkStatus s)
    {
        std::lock_guard<std::mutex> lock(mutex);
        bulk.emplace_back(s, std::vector<uint8_t>());
    }
    /** The reset pulse reaching this camera's FPGA. */
    void resetPulse()
    {
        {
            std::lock_guard<std::mutex> lock(mutex);
            if (!muxRunning)
            {
                latchedReset = true;
                return;
            }
        }
        timestampReset();
    }
    /** The multiplexer's run bit written. */
    void setMuxRunning(bool run)
    {
        bool sendLatched;
        {
            std::lock_guard<std::mutex> lock(mutex);
            sendLatched = run && !muxRunning && latchedReset;
            muxRunning = run;
            if (sendLatched)
                latchedReset = false;
        }
        if (sendLatched)
        {
            WordStream reset;
            reset.word(timestampResetWord());
            std::vector<uint8_t> bytes = reset.bytes;
            bytes.insert(bytes.end(), beforeSync.begin(), beforeSync.end());
            pushData(bytes);
        }
    }
    void setRegister(int module, int param, uint32_t value)
    {
        std::lock_guard<std::mutex> lock(mutex);
        registers[std::make_pair(module, param)] = value;
    }
    void timestampReset()
    {
        WordStream reset;
        reset.word(timestampResetWord());
        std::vector<uint8_t> bytes = reset.bytes;
        bytes.insert(bytes.end(), afterReset.begin(), afterReset.end());
        pushData(bytes);
        std::lock_guard<std::mutex> lock(mutex);
        resets++;
    }
};

inline Ptr<FakeCamera> makeDavis(int index, int chip, int columns, int rows, bool invertXY, bool master, const Ptr<WriteLog>& log)
{
    Ptr<FakeCamera> c = makePtr<FakeCamera>();
    c->index = index;
    c->log = log;
    c->id.vendorId = 0x152A;
    c->id.productId = 0x841A;
    c->id.bus = 1;
    c->id.address = 10 + index;
    c->id.firmwareVersion = 6;
    c->id.serial = cv::format("0000049%d", index);
    c->registers = {
        { { 6, 0 }, 18 }, { { 6, 7 }, 1 }, { { 6, 1 }, (uint32_t)chip }, { { 6, 2 }, master ? 1u : 0u },
        { { 6, 3 }, 104 }, { { 6, 5 }, 80 }, { { 6, 6 }, 1000 },
        { { 1, 0 }, (uint32_t)columns }, { { 1, 1 }, (uint32_t)rows }, { { 1, 2 }, invertXY ? 4u : 0u },
        { { 1, 10 }, 1 }, { { 1, 30 }, 1 }, { { 1, 40 }, 1 }, { { 1, 50 }, 1 }, { { 1, 60 }, 1 },
    };
    return c;
}

class FakeHandle CV_FINAL : public UsbDeviceHandle
{
public:
    explicit FakeHandle(const Ptr<FakeCamera>& c) : c_(c) {}
    ~FakeHandle() CV_OVERRIDE { c_->log->call(c_->index, "close"); }

    void controlOut(uint8_t requestType, uint8_t request, uint16_t value, uint16_t index, const uint8_t* data,
                    size_t size) CV_OVERRIDE
    {
        checkPresent();
        ASSERT_EQ(0x40, requestType);
        if (request == 0xBF)
        {
            ASSERT_EQ(4u, size);
            c_->log->add({ c_->index, value, index, bigEndian(data) });
            c_->setRegister(value, index, bigEndian(data));
            if (value == 0 && index == 0)
                c_->setMuxRunning(bigEndian(data) != 0);
        }
        else if (request == 0xC2)
        {
            ASSERT_EQ(6u * value, size);
            bool pulse = false;
            for (size_t i = 0; i < value; i++)
            {
                const uint32_t v = bigEndian(data + 6 * i + 2);
                c_->log->add({ c_->index, data[6 * i], data[6 * i + 1], v });
                pulse = pulse || (data[6 * i] == 0 && data[6 * i + 1] == 2 && v == 1);
            }
            if (pulse)
            {
                c_->resetPulse();
                if (c_->slave)
                    c_->slave->resetPulse();  // the sync cable carries the pulse
            }
        }
        else
            FAIL() << "unexpected request " << (int)request;
    }

    void controlIn(uint8_t requestType, uint8_t request, uint16_t value, uint16_t index, uint8_t* data,
                   size_t size) CV_OVERRIDE
    {
        checkPresent();
        ASSERT_EQ(0xC0, requestType);
        ASSERT_EQ(0xBF, request);
        ASSERT_EQ(4u, size);
        uint32_t v = 0;
        {
            std::lock_guard<std::mutex> lock(c_->mutex);
            const auto it = c_->registers.find(std::make_pair((int)value, (int)index));
            if (it != c_->registers.end())
                v = it->second;
        }
        data[0] = (uint8_t)(v >> 24);
        data[1] = (uint8_t)(v >> 16);
        data[2] = (uint8_t)(v >> 8);
        data[3] = (uint8_t)v;
    }

    void clearHalt(uint8_t endpoint) CV_OVERRIDE { c_->log->call(c_->index, cv::format("clearHalt 0x%02X", endpoint)); }
    void startBulkIn(uint8_t endpoint, int transfers, int bytes) CV_OVERRIDE
    {
        c_->log->call(c_->index, cv::format("startBulkIn 0x%02X %d x %d", endpoint, transfers, bytes));
    }
    void stopBulkIn() CV_OVERRIDE { c_->log->call(c_->index, "stopBulkIn"); }
    String streamEndReason() const CV_OVERRIDE { return String(); }

    UsbBulkStatus readBulk(std::vector<uint8_t>& data, int timeoutMs) CV_OVERRIDE
    {
        {
            std::unique_lock<std::mutex> lock(c_->mutex);
            if (!c_->bulk.empty() && c_->bulk.front().first == USB_BULK_DATA)
            {
                const double waitUs = c_->paceWaitUs(c_->bulk.front().second.size());
                if (waitUs > 0)
                {
                    lock.unlock();
                    std::this_thread::sleep_for(std::chrono::microseconds((int64)std::min(waitUs, timeoutMs * 1000.0)));
                    return USB_BULK_TIMEOUT;
                }
            }
            if (!c_->bulk.empty())
            {
                const UsbBulkStatus s = c_->bulk.front().first;
                data = c_->bulk.front().second;
                c_->bulk.pop_front();
                if (s == USB_BULK_DEVICE_GONE)
                    c_->gone = true;
                return s;
            }
            if (c_->gone || (c_->unplugWhenDrained && c_->resets > 0))
            {
                c_->gone = true;
                return USB_BULK_DEVICE_GONE;
            }
            if (c_->resets > 0)
                c_->readsWhenDrained++;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(std::min(timeoutMs, 2)));
        return USB_BULK_TIMEOUT;
    }

private:
    static uint32_t bigEndian(const uint8_t* b)
    {
        return ((uint32_t)b[0] << 24) | ((uint32_t)b[1] << 16) | ((uint32_t)b[2] << 8) | b[3];
    }
    void checkPresent()
    {
        std::lock_guard<std::mutex> lock(c_->mutex);
        if (c_->gone)
            CV_Error(cv::Error::StsError, c_->id.location() + ": LIBUSB_ERROR_NO_DEVICE (fake)");
    }
    Ptr<FakeCamera> c_;
};

class FakeTransport CV_FINAL : public UsbTransport
{
public:
    std::vector<Ptr<FakeCamera> > cameras;
    std::vector<UsbDeviceId> list(uint16_t vendorId, const std::vector<uint16_t>& productIds) CV_OVERRIDE
    {
        std::vector<UsbDeviceId> ids;
        for (const Ptr<FakeCamera>& c : cameras)
            if (c->id.vendorId == vendorId && std::count(productIds.begin(), productIds.end(), c->id.productId) && !c->gone)
                ids.push_back(c->id);
        return ids;
    }
    Ptr<UsbDeviceHandle> open(const UsbDeviceId& id) CV_OVERRIDE
    {
        for (const Ptr<FakeCamera>& c : cameras)
            if (c->id.address == id.address)
            {
                if (!c->openError.empty())
                    CV_Error(cv::Error::StsError, id.location() + ": " + c->openError);
                c->log->call(c->index, "open");
                return makePtr<FakeHandle>(c);
            }
        CV_Error(cv::Error::StsError, id.location() + ": no such device");
    }
};

/** Installs a fake transport for one test and restores the real one afterwards. */
struct FakeUsb
{
    Ptr<FakeTransport> transport = makePtr<FakeTransport>();
    Ptr<WriteLog> log = makePtr<WriteLog>();
    FakeUsb() { setUsbTransport(transport); }
    ~FakeUsb() { setUsbTransport(Ptr<UsbTransport>()); }
    Ptr<FakeCamera> add(int chip, int columns, int rows, bool invertXY = false, bool master = true)
    {
        Ptr<FakeCamera> c = makeDavis((int)transport->cameras.size(), chip, columns, rows, invertXY, master, log);
        transport->cameras.push_back(c);
        return c;
    }
};

}  // namespace fake_davis_usb
}  // namespace opencv_test

#endif  // OPENCV_EVENT_TEST_FAKE_DAVIS_USB_HPP
