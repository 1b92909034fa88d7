// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// UsbTransport over libusb-1.0: enumeration, and the libusb calls of an open device (LibusbLink) under the
// shared transfer bookkeeping (usb_link_device.cpp). Without libusb (OPENCV_EVENT_HAVE_LIBUSB unset) the
// transport finds no device and open() says why.

#include "precomp.hpp"
#include "davis/usb_link.hpp"

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
static_assert((int)USB_LINK_ERROR_NOT_FOUND == (int)LIBUSB_ERROR_NOT_FOUND &&
                  (int)USB_LINK_ERROR_NO_DEVICE == (int)LIBUSB_ERROR_NO_DEVICE &&
                  (int)USB_LINK_ERROR_TIMEOUT == (int)LIBUSB_ERROR_TIMEOUT && (int)USB_LINK_ERROR_PIPE == (int)LIBUSB_ERROR_PIPE &&
                  (int)USB_LINK_ERROR_INTERRUPTED == (int)LIBUSB_ERROR_INTERRUPTED &&
                  (int)USB_LINK_ERROR_BUSY == (int)LIBUSB_ERROR_BUSY && (int)USB_LINK_ERROR_IO == (int)LIBUSB_ERROR_IO,
              "UsbLink's error codes are libusb's");
// What a user without access to the camera's device node needs (iniVation's vendor id; every product).
const char* const kUdevRuleHint =
    "a udev rule such as SUBSYSTEM==\"usb\", ATTR{idVendor}==\"152a\", MODE=\"0666\" in /etc/udev/rules.d/, then re-plug";

String usbError(int code)
{
    return cv::format("%s (%s)", libusb_error_name(code), libusb_strerror((libusb_error)code));
}

/** The libusb calls of one open device; each has its own context, so that the reading thread of each camera
of a stereo pair handles only its own transfers. The bookkeeping above it is createUsbLinkDevice(). */
class LibusbLink CV_FINAL : public UsbLink
{
public:
    LibusbLink(const UsbDeviceId& id) : id_(id)
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

    ~LibusbLink() CV_OVERRIDE
    {
        freeBulkIn();
        closeDevice();
    }

    String location() const CV_OVERRIDE { return id_.location(); }
    String errorText(int code) const CV_OVERRIDE { return usbError(code); }

    int control(uint8_t requestType, uint8_t request, uint16_t value, uint16_t index, uint8_t* data,
                uint16_t size) CV_OVERRIDE
    {
        return libusb_control_transfer(handle_, requestType, request, value, index, data, size, kControlTimeoutMs);
    }

    int clearHalt(uint8_t endpoint) CV_OVERRIDE { return libusb_clear_halt(handle_, endpoint); }

    int allocateBulkIn(uint8_t endpoint, int transfers, int bytes, UsbLinkListener* listener) CV_OVERRIDE
    {
        CV_Assert(transfers_.empty());
        listener_ = listener;
        for (int i = 0; i < transfers; i++)
        {
            libusb_transfer* t = libusb_alloc_transfer(0);
            if (!t)
            {
                freeBulkIn();
                return LIBUSB_ERROR_NO_MEM;
            }
            buffers_.emplace_back((size_t)bytes);
            libusb_fill_bulk_transfer(t, handle_, endpoint, buffers_.back().data(), bytes, &LibusbLink::completed,
                                      this, 0);
            transfers_.push_back(t);
        }
        return LIBUSB_SUCCESS;
    }

    int submit(int transfer) CV_OVERRIDE { return libusb_submit_transfer(transfers_[(size_t)transfer]); }
    int cancel(int transfer) CV_OVERRIDE { return libusb_cancel_transfer(transfers_[(size_t)transfer]); }

    int handleEvents(int timeoutMs) CV_OVERRIDE
    {
        timeval tv;
        tv.tv_sec = timeoutMs / 1000;
        tv.tv_usec = (timeoutMs % 1000) * 1000;
        return libusb_handle_events_timeout_completed(ctx_, &tv, nullptr);
    }

    void freeBulkIn() CV_OVERRIDE
    {
        for (libusb_transfer* t : transfers_)
            libusb_free_transfer(t);
        transfers_.clear();
        buffers_.clear();
    }

private:
    static void LIBUSB_CALL completed(libusb_transfer* t)
    {
        LibusbLink* self = static_cast<LibusbLink*>(t->user_data);
        const int index = (int)(std::find(self->transfers_.begin(), self->transfers_.end(), t) - self->transfers_.begin());
        UsbTransferStatus status = USB_TRANSFER_FAILED;  // error, timeout, overflow
        switch (t->status)
        {
        case LIBUSB_TRANSFER_COMPLETED: status = USB_TRANSFER_COMPLETED; break;
        case LIBUSB_TRANSFER_CANCELLED: status = USB_TRANSFER_CANCELLED; break;
        case LIBUSB_TRANSFER_NO_DEVICE: status = USB_TRANSFER_NO_DEVICE; break;
        case LIBUSB_TRANSFER_STALL: status = USB_TRANSFER_STALL; break;
        default: break;
        }
        self->listener_->transferDone(index, status, t->buffer, t->actual_length);
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
    UsbLinkListener* listener_ = nullptr;
    std::vector<libusb_transfer*> transfers_;
    std::deque<std::vector<uint8_t> > buffers_;  // deque: growing it never moves a buffer already allocated
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
        return createUsbLinkDevice(makePtr<LibusbLink>(device));
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
