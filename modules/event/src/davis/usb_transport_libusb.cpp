// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// UsbTransport over libusb-1.0. Each open device has its own libusb context, so that the reader thread of
// each camera of a stereo pair pumps only its own transfers. Without libusb (OPENCV_EVENT_HAVE_LIBUSB unset)
// the transport finds no device and open() says why.

#include "precomp.hpp"
#include "davis/usb_transport.hpp"

#include <deque>
#include <mutex>

#ifdef OPENCV_EVENT_HAVE_LIBUSB
#include <libusb.h>
#endif

namespace cv {
namespace event {
namespace detail {

#ifdef OPENCV_EVENT_HAVE_LIBUSB

namespace {

const unsigned kControlTimeoutMs = 1000;
// What a user without access to the camera's device node needs (iniVation's vendor id; every product).
const char* const kUdevRuleHint =
    "a udev rule such as SUBSYSTEM==\"usb\", ATTR{idVendor}==\"152a\", MODE=\"0666\" in /etc/udev/rules.d/, then re-plug";

String usbError(int code)
{
    return cv::format("%s (%s)", libusb_error_name(code), libusb_strerror((libusb_error)code));
}

class LibusbDevice CV_FINAL : public UsbDeviceHandle
{
public:
    LibusbDevice(const UsbDeviceId& id) : id_(id)
    {
        int rc = libusb_init(&ctx_);
        if (rc != LIBUSB_SUCCESS)
            CV_Error_(Error::StsError, ("%s: libusb_init failed: %s", id.location().c_str(), usbError(rc).c_str()));
        try
        {
            openDevice();
        }
        catch (...)
        {
            closeDevice();
            throw;
        }
    }

    ~LibusbDevice() CV_OVERRIDE
    {
        stopBulkIn();
        closeDevice();
    }

    void controlOut(uint8_t requestType, uint8_t request, uint16_t value, uint16_t index,
                    const uint8_t* data, size_t size) CV_OVERRIDE
    {
        const int rc = libusb_control_transfer(handle_, requestType, request, value, index,
                                               const_cast<unsigned char*>(data), (uint16_t)size, kControlTimeoutMs);
        if (rc != (int)size)
            CV_Error_(Error::StsError, ("%s: control request 0x%02X (value %u, index %u) failed: %s",
                                        id_.location().c_str(), request, value, index,
                                        rc < 0 ? usbError(rc).c_str() : "short transfer"));
    }

    void controlIn(uint8_t requestType, uint8_t request, uint16_t value, uint16_t index,
                   uint8_t* data, size_t size) CV_OVERRIDE
    {
        const int rc = libusb_control_transfer(handle_, requestType, request, value, index, data, (uint16_t)size,
                                               kControlTimeoutMs);
        if (rc != (int)size)
            CV_Error_(Error::StsError, ("%s: control read 0x%02X (value %u, index %u) failed: %s",
                                        id_.location().c_str(), request, value, index,
                                        rc < 0 ? usbError(rc).c_str() : "short transfer"));
    }

    void clearHalt(uint8_t endpoint) CV_OVERRIDE
    {
        const int rc = libusb_clear_halt(handle_, endpoint);
        if (rc != LIBUSB_SUCCESS)
            CV_Error_(Error::StsError, ("%s: clearing the halt of endpoint 0x%02X failed: %s",
                                        id_.location().c_str(), endpoint, usbError(rc).c_str()));
    }

    void startBulkIn(uint8_t endpoint, int transfers, int bytes) CV_OVERRIDE
    {
        CV_Assert(transfers_.empty());
        for (int i = 0; i < transfers; i++)
        {
            libusb_transfer* t = libusb_alloc_transfer(0);
            if (!t)
                CV_Error_(Error::StsNoMem, ("%s: cannot allocate a USB transfer", id_.location().c_str()));
            buffers_.emplace_back((size_t)bytes);
            libusb_fill_bulk_transfer(t, handle_, endpoint, buffers_.back().data(), bytes, &LibusbDevice::completed,
                                      this, 0);
            transfers_.push_back(t);
            const int rc = libusb_submit_transfer(t);
            if (rc != LIBUSB_SUCCESS)
            {
                stopBulkIn();
                CV_Error_(Error::StsError, ("%s: submitting bulk transfers on endpoint 0x%02X failed: %s",
                                            id_.location().c_str(), endpoint, usbError(rc).c_str()));
            }
            active_++;
        }
    }

    UsbBulkStatus readBulk(std::vector<uint8_t>& data, int timeoutMs) CV_OVERRIDE
    {
        const int64 deadline = getTickCount() + (int64)(timeoutMs * getTickFrequency() / 1000.0);
        while (completed_.empty() && !gone_)
        {
            const int64 left = deadline - getTickCount();
            if (left <= 0)
                return USB_BULK_TIMEOUT;
            const double leftUs = (double)left * 1e6 / getTickFrequency();
            timeval tv;
            tv.tv_sec = (long)(leftUs / 1e6);
            tv.tv_usec = (long)(leftUs - (double)tv.tv_sec * 1e6);
            const int rc = libusb_handle_events_timeout_completed(ctx_, &tv, nullptr);
            if (rc == LIBUSB_ERROR_NO_DEVICE)
                gone_ = true;
            else if (rc != LIBUSB_SUCCESS && rc != LIBUSB_ERROR_INTERRUPTED && rc != LIBUSB_ERROR_TIMEOUT)
                return USB_BULK_TRANSFER_ERROR;
        }
        if (completed_.empty())
            return USB_BULK_DEVICE_GONE;
        Completed c = std::move(completed_.front());
        completed_.pop_front();
        if (!c.ok)
            return USB_BULK_TRANSFER_ERROR;
        data.swap(c.data);
        return USB_BULK_DATA;
    }

    void stopBulkIn() CV_OVERRIDE
    {
        for (libusb_transfer* t : transfers_)
            libusb_cancel_transfer(t);  // NOT_FOUND for those already returned: fine
        // Every transfer must have returned before its memory goes; bounded at 1 s so that a wedged host
        // controller cannot hang release().
        for (int i = 0; i < 100 && active_ > 0; i++)
        {
            timeval tv = { 0, 10000 };
            libusb_handle_events_timeout_completed(ctx_, &tv, nullptr);
        }
        if (active_ == 0)
        {
            for (libusb_transfer* t : transfers_)
                libusb_free_transfer(t);
            transfers_.clear();
            buffers_.clear();
        }
        // else: leak the few transfers still in flight rather than free memory the kernel may still write
        completed_.clear();
    }

private:
    struct Completed
    {
        bool ok;
        std::vector<uint8_t> data;
    };

    static void LIBUSB_CALL completed(libusb_transfer* t)
    {
        LibusbDevice* self = static_cast<LibusbDevice*>(t->user_data);
        switch (t->status)
        {
        case LIBUSB_TRANSFER_COMPLETED:
            self->completed_.push_back({ true, std::vector<uint8_t>(t->buffer, t->buffer + t->actual_length) });
            break;
        case LIBUSB_TRANSFER_CANCELLED:
            self->active_--;
            return;
        case LIBUSB_TRANSFER_NO_DEVICE:
            self->gone_ = true;
            self->active_--;
            return;
        default:  // error, stall, overflow, timeout: this transfer's data is lost; the stream goes on
            self->completed_.push_back({ false, std::vector<uint8_t>() });
            break;
        }
        const int rc = libusb_submit_transfer(t);
        if (rc != LIBUSB_SUCCESS)
        {
            self->active_--;
            if (rc == LIBUSB_ERROR_NO_DEVICE)
                self->gone_ = true;
        }
    }

    void openDevice()
    {
        libusb_device** list = nullptr;
        const ssize_t n = libusb_get_device_list(ctx_, &list);
        libusb_device* found = nullptr;
        for (ssize_t i = 0; i < n; i++)
            if (libusb_get_bus_number(list[i]) == id_.bus && libusb_get_device_address(list[i]) == id_.address)
                found = list[i];
        int rc = found ? libusb_open(found, &handle_) : LIBUSB_ERROR_NO_DEVICE;
        if (n >= 0)
            libusb_free_device_list(list, 1);
        if (rc == LIBUSB_ERROR_ACCESS)
            CV_Error_(Error::StsError, ("%s: permission denied opening the camera: add %s "
                                        "(or run as root)", id_.location().c_str(), kUdevRuleHint));
        if (rc != LIBUSB_SUCCESS)
            CV_Error_(Error::StsError, ("%s: cannot open the camera: %s", id_.location().c_str(), usbError(rc).c_str()));
        int configuration = 0;
        rc = libusb_get_configuration(handle_, &configuration);
        if (rc == LIBUSB_SUCCESS && configuration != 1)
            rc = libusb_set_configuration(handle_, 1);
        if (rc != LIBUSB_SUCCESS)
            CV_Error_(Error::StsError, ("%s: cannot select USB configuration 1: %s", id_.location().c_str(),
                                        usbError(rc).c_str()));
        rc = libusb_claim_interface(handle_, 0);
        if (rc == LIBUSB_ERROR_BUSY)
            CV_Error_(Error::StsError, ("%s: the camera is in use by another program (interface 0 busy)",
                                        id_.location().c_str()));
        if (rc != LIBUSB_SUCCESS)
            CV_Error_(Error::StsError, ("%s: cannot claim interface 0: %s", id_.location().c_str(), usbError(rc).c_str()));
        claimed_ = true;
    }

    void closeDevice()
    {
        if (handle_)
        {
            if (claimed_)
                libusb_release_interface(handle_, 0);
            libusb_close(handle_);
            handle_ = nullptr;
        }
        if (ctx_)
        {
            libusb_exit(ctx_);
            ctx_ = nullptr;
        }
    }

    UsbDeviceId id_;
    libusb_context* ctx_ = nullptr;
    libusb_device_handle* handle_ = nullptr;
    bool claimed_ = false;
    std::vector<libusb_transfer*> transfers_;
    std::deque<std::vector<uint8_t> > buffers_;  // deque: growing it never moves a buffer already submitted
    std::deque<Completed> completed_;            // touched only on the thread that pumps events
    int active_ = 0;
    bool gone_ = false;
};

class LibusbTransport CV_FINAL : public UsbTransport
{
public:
    std::vector<UsbDeviceId> list(uint16_t vendorId, const std::vector<uint16_t>& productIds) CV_OVERRIDE
    {
        std::vector<UsbDeviceId> found;
        libusb_context* ctx = nullptr;
        if (libusb_init(&ctx) != LIBUSB_SUCCESS)
            return found;  // no USB at all (e.g. a container without /dev/bus/usb): no camera
        libusb_device** list = nullptr;
        const ssize_t n = libusb_get_device_list(ctx, &list);
        for (ssize_t i = 0; i < n; i++)
        {
            libusb_device_descriptor d;
            if (libusb_get_device_descriptor(list[i], &d) != LIBUSB_SUCCESS || d.idVendor != vendorId ||
                std::find(productIds.begin(), productIds.end(), d.idProduct) == productIds.end())
                continue;
            UsbDeviceId id;
            id.vendorId = d.idVendor;
            id.productId = d.idProduct;
            id.bus = libusb_get_bus_number(list[i]);
            id.address = libusb_get_device_address(list[i]);
            id.firmwareVersion = d.bcdDevice & 0xFF;
            libusb_device_handle* h = nullptr;
            if (d.iSerialNumber != 0 && libusb_open(list[i], &h) == LIBUSB_SUCCESS)
            {
                unsigned char serial[64] = { 0 };
                if (libusb_get_string_descriptor_ascii(h, d.iSerialNumber, serial, sizeof(serial) - 1) > 0)
                    id.serial = String(reinterpret_cast<const char*>(serial));
                libusb_close(h);
            }
            found.push_back(id);
        }
        if (n >= 0)
            libusb_free_device_list(list, 1);
        libusb_exit(ctx);
        std::sort(found.begin(), found.end(), [](const UsbDeviceId& a, const UsbDeviceId& b) {
            return a.bus != b.bus ? a.bus < b.bus : a.address < b.address;
        });
        return found;
    }

    Ptr<UsbDeviceHandle> open(const UsbDeviceId& device) CV_OVERRIDE
    {
        return makePtr<LibusbDevice>(device);
    }
};

}  // namespace

Ptr<UsbTransport> createLibusbTransport() { return makePtr<LibusbTransport>(); }

#else  // no libusb

namespace {

class NoUsbTransport CV_FINAL : public UsbTransport
{
public:
    std::vector<UsbDeviceId> list(uint16_t, const std::vector<uint16_t>&) CV_OVERRIDE { return {}; }
    Ptr<UsbDeviceHandle> open(const UsbDeviceId& device) CV_OVERRIDE
    {
        CV_Error_(Error::StsNotImplemented, ("%s: opencv_event was built without libusb-1.0: no live cameras "
                                             "(install libusb-1.0-0-dev and rebuild)", device.location().c_str()));
    }
};

}  // namespace

Ptr<UsbTransport> createLibusbTransport() { return makePtr<NoUsbTransport>(); }

#endif

namespace {

std::mutex& transportMutex()
{
    static std::mutex m;
    return m;
}

Ptr<UsbTransport>& transportOverride()
{
    static Ptr<UsbTransport> t;
    return t;
}

}  // namespace

Ptr<UsbTransport> getUsbTransport()
{
    std::lock_guard<std::mutex> lock(transportMutex());
    Ptr<UsbTransport>& t = transportOverride();
    return t ? t : createLibusbTransport();
}

void setUsbTransport(const Ptr<UsbTransport>& transport)
{
    std::lock_guard<std::mutex> lock(transportMutex());
    transportOverride() = transport;
}

}  // namespace detail
}  // namespace event
}  // namespace cv
