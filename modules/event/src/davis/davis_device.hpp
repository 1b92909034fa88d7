// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_DAVIS_DAVIS_DEVICE_HPP
#define OPENCV_EVENT_SRC_DAVIS_DAVIS_DEVICE_HPP

// One DAVIS camera on its configuration channel: identification, default configuration (biases, chip,
// FPGA), the events-only start / stop sequences, timestamp reset and the user's knobs. It does not read
// events; reader_davis.cpp does, on the same UsbDeviceHandle.

#include "davis/usb_transport.hpp"

namespace cv {
namespace event {
namespace detail {

struct DavisIdentity
{
    UsbDeviceId usb;
    int logicVersion = 0, logicPatch = 0, chipId = -1;
    bool master = true;
    int rawColumns = 0, rawRows = 0;
    bool invertXY = false;
    int logicClockMHz = 0, usbClockMHz = 0, clockDeviation = 1000;
    bool hasBackgroundActivityFilter = false, hasRoiFilter = false;
    /** Sensor size as delivered (after the invertXY swap). */
    Size sensorSize() const { return invertXY ? Size(rawRows, rawColumns) : Size(rawColumns, rawRows); }
    String model() const;
    /** "davis:<serial> (DAVIS346B, usb 001:004)": how every message names the camera. */
    String name() const;
};

class DavisDevice
{
public:
    /** Opens the camera and identifies it; raises cv::Exception naming it when it cannot be used (firmware or
    logic too old, not answering). */
    DavisDevice(const Ptr<UsbTransport>& transport, const UsbDeviceId& id);
    ~DavisDevice();

    const DavisIdentity& identity() const { return identity_; }
    UsbDeviceHandle& usb() { return *usb_; }

    /** Biases and chip configuration (libcaer's defaults for this chip), then FPGA defaults: events only. */
    void sendDefaultConfig();
    /** The start sequence up to and including DVS RUN; APS, IMU and external input stay off. Starts the bulk
    transfers on the data endpoint first. */
    void start(int transfers, int transferBytes);
    /** The stop sequence in reverse order, then the transfers are cancelled. Never raises (the camera may be
    gone); returns false when a request failed. */
    bool stop();
    /** Resets the timestamp counter (of the slave too, through the sync cable, when this is the master). */
    void resetTimestamp();

    /** Device properties (EVENT_CAP_PROP_DEVICE_*): set writes them to the camera. False when the id is not one
    of them or the value is out of range / not supported by this camera. */
    bool setProperty(int propId, double value);
    bool getProperty(int propId, double& value) const;

    void writeConfig(uint8_t module, uint8_t param, uint32_t value);
    uint32_t readConfig(uint8_t module, uint8_t param);

private:
    void identify();
    bool applyRoi(int x, int y, int width, int height);

    Ptr<UsbDeviceHandle> usb_;
    DavisIdentity identity_;
    bool running_ = false;
    bool backgroundActivity_ = true;
    bool externalInput_ = false;  // edges on the external input become trigger events
    int backgroundActivityTimeUs_ = 2000;
    Rect roi_;
    int biasSelect_ = 0;
};

/** The DAVIS cameras connected (FX2 and FX3), in bus order; index i is "davis:i". Never raises. */
std::vector<UsbDeviceId> findDavisCameras(UsbTransport& transport);

/** Resolves "0" (an index) or "00000499" (a serial number) to a connected camera; raises naming @p source and
listing what is connected when nothing matches. */
UsbDeviceId resolveDavisCamera(UsbTransport& transport, const String& source, const String& selector);

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_DAVIS_DAVIS_DEVICE_HPP
