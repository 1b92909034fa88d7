// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_DAVIS_USB_LINK_HPP
#define OPENCV_EVENT_SRC_DAVIS_USB_LINK_HPP

// The libusb calls one open device needs, as an interface, with libusb's semantics: completion callbacks run
// on whichever thread handles events, and a synchronous control request handles events itself when no other
// thread does at that moment. The transfer bookkeeping above it (createUsbLinkDevice) is written for those
// semantics, and the unit tests run it against a fake link that has them, without a camera.
// Exported for the tests; not part of the public API.

#include "davis/usb_transport.hpp"

namespace cv {
namespace event {
namespace detail {

/** Results of UsbLink calls: 0 or a count on success, else one of these (libusb's own values). */
enum UsbLinkError
{
    USB_LINK_ERROR_IO = -1,
    USB_LINK_ERROR_NOT_FOUND = -5,   //!< cancel(): the transfer is not in flight (it has completed already)
    USB_LINK_ERROR_NO_DEVICE = -4,   //!< the device was unplugged
    USB_LINK_ERROR_BUSY = -6,
    USB_LINK_ERROR_TIMEOUT = -7,
    USB_LINK_ERROR_PIPE = -9,        //!< the endpoint stalled
    USB_LINK_ERROR_INTERRUPTED = -10
};

/** How a bulk transfer came back. */
enum UsbTransferStatus
{
    USB_TRANSFER_COMPLETED = 0,  //!< data (possibly none) arrived
    USB_TRANSFER_FAILED = 1,     //!< error, timeout or overflow: its data is lost, the endpoint still works
    USB_TRANSFER_CANCELLED = 2,
    USB_TRANSFER_STALL = 3,      //!< the endpoint halted: nothing more comes until the halt is cleared
    USB_TRANSFER_NO_DEVICE = 4
};

class UsbLinkListener
{
public:
    virtual ~UsbLinkListener() {}
    /** A bulk transfer came back; it is not in flight any more until submitted again. Runs on the thread that
    handles events, never on two threads at once. */
    virtual void transferDone(int transfer, UsbTransferStatus status, const uint8_t* data, int length) = 0;
};

class UsbLink
{
public:
    virtual ~UsbLink() {}
    /** "usb 001:004": how messages name the device. */
    virtual String location() const = 0;
    /** What an error code means, in libusb's words. */
    virtual String errorText(int code) const = 0;
    /** A synchronous control request; returns the bytes transferred or an error. May run completion
    callbacks on the calling thread. */
    virtual int control(uint8_t requestType, uint8_t request, uint16_t value, uint16_t index, uint8_t* data,
                        uint16_t size) = 0;
    /** Clears a halted endpoint (a synchronous control request: may run completion callbacks). */
    virtual int clearHalt(uint8_t endpoint) = 0;
    /** Allocates @p transfers bulk IN transfers of @p bytes on @p endpoint that report to @p listener;
    none is submitted yet. */
    virtual int allocateBulkIn(uint8_t endpoint, int transfers, int bytes, UsbLinkListener* listener) = 0;
    virtual int submit(int transfer) = 0;
    /** Asks a transfer in flight to come back as cancelled; NOT_FOUND when it is not in flight. */
    virtual int cancel(int transfer) = 0;
    /** Runs the callbacks of what has completed, waiting up to @p timeoutMs for something to. */
    virtual int handleEvents(int timeoutMs) = 0;
    /** Frees the transfers; call only when none is in flight. */
    virtual void freeBulkIn() = 0;
};

/** The UsbDeviceHandle over a link: bulk transfers kept in flight and resubmitted as they return, under one
lock whatever thread their callbacks run on; a stalled endpoint cleared from the reading thread; a stream
that ends with a reason when no transfer can be kept in flight; a shutdown that cancels until none is. */
CV_EXPORTS Ptr<UsbDeviceHandle> createUsbLinkDevice(const Ptr<UsbLink>& link);

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_DAVIS_USB_LINK_HPP
