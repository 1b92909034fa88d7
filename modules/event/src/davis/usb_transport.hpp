// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_DAVIS_USB_TRANSPORT_HPP
#define OPENCV_EVENT_SRC_DAVIS_USB_TRANSPORT_HPP

// The USB layer the live camera back-ends talk to: enumerate, open, vendor control requests, a stream of
// bulk IN transfers. The real one is libusb-1.0 (usb_transport_libusb.cpp); the unit tests install a fake
// that replays a scripted conversation, so the device logic above it runs unchanged without hardware.
// Exported for the tests; not part of the public API.

#include "opencv2/event.hpp"

namespace cv {
namespace event {
namespace detail {

struct UsbDeviceId
{
    uint16_t vendorId = 0, productId = 0;
    int bus = 0, address = 0;
    int firmwareVersion = 0;  // low byte of the device descriptor's bcdDevice
    String serial;            // iSerialNumber; empty when the device cannot be opened to read it
    String location() const { return cv::format("usb %03d:%03d", bus, address); }
};

/** What a bulk read returned. */
enum UsbBulkStatus
{
    USB_BULK_DATA = 0,        //!< a completed transfer; its bytes are in the buffer
    USB_BULK_TIMEOUT = 1,     //!< nothing completed within the timeout (not an error)
    USB_BULK_TRANSFER_ERROR = 2,  //!< one transfer failed (stall, overflow, CRC): its data is lost, the stream goes on
    USB_BULK_DEVICE_GONE = 3, //!< the device was unplugged: nothing more will come
    USB_BULK_STREAM_ENDED = 4 //!< no transfer can be kept in flight any more; streamEndReason() says why
};

/** An open device (interface 0 claimed). Control requests raise cv::Exception naming the device on failure. */
class UsbDeviceHandle
{
public:
    virtual ~UsbDeviceHandle() {}
    virtual void controlOut(uint8_t requestType, uint8_t request, uint16_t value, uint16_t index,
                            const uint8_t* data, size_t size) = 0;
    virtual void controlIn(uint8_t requestType, uint8_t request, uint16_t value, uint16_t index,
                           uint8_t* data, size_t size) = 0;
    virtual void clearHalt(uint8_t endpoint) = 0;
    /** Starts @p transfers asynchronous bulk IN transfers of @p bytes each on @p endpoint, resubmitted as
    they complete, until stopBulkIn(). */
    virtual void startBulkIn(uint8_t endpoint, int transfers, int bytes) = 0;
    /** Waits up to @p timeoutMs for the next completed transfer. Only one thread calls it; control requests
    may come from others meanwhile. */
    virtual UsbBulkStatus readBulk(std::vector<uint8_t>& data, int timeoutMs) = 0;
    /** Why readBulk() said USB_BULK_STREAM_ENDED (empty before). */
    virtual String streamEndReason() const = 0;
    /** Cancels the transfers until none is in flight (bounded in time). Never raises. */
    virtual void stopBulkIn() = 0;
};

class UsbTransport
{
public:
    virtual ~UsbTransport() {}
    /** The connected devices with this vendor id and one of the product ids; empty when none (never raises). */
    virtual std::vector<UsbDeviceId> list(uint16_t vendorId, const std::vector<uint16_t>& productIds) = 0;
    /** Opens the device (configuration 1, interface 0 claimed). Raises cv::Exception naming it and the reason
    (permissions, busy, gone). */
    virtual Ptr<UsbDeviceHandle> open(const UsbDeviceId& device) = 0;
};

/** The transport live back-ends use: libusb-1.0 when built with it, else one that finds no device. */
CV_EXPORTS Ptr<UsbTransport> getUsbTransport();
/** Replaces it (tests); an empty pointer restores the default. */
CV_EXPORTS void setUsbTransport(const Ptr<UsbTransport>& transport);

Ptr<UsbTransport> createLibusbTransport();

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_DAVIS_USB_TRANSPORT_HPP
