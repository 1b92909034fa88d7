// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"
#include "davis/davis_device.hpp"
#include "davis/davis_protocol.hpp"

#include <chrono>
#include <thread>

namespace cv {
namespace event {
namespace detail {

using namespace davis;

namespace {

void sleepMs(int ms) { std::this_thread::sleep_for(std::chrono::milliseconds(ms)); }

}  // namespace

String DavisIdentity::model() const
{
    return chipId >= 0 ? String(chipName(chipId)) : String("DAVIS");
}

String DavisIdentity::name() const
{
    return cv::format("davis:%s (%s, %s)", usb.serial.empty() ? "?" : usb.serial.c_str(), model().c_str(),
                      usb.location().c_str());
}

std::vector<UsbDeviceId> findDavisCameras(UsbTransport& transport)
{
    try
    {
        return transport.list(kVendorId, { kProductFx3, kProductFx2 });
    }
    catch (const cv::Exception&)
    {
        return std::vector<UsbDeviceId>();
    }
}

UsbDeviceId resolveDavisCamera(UsbTransport& transport, const String& source, const String& selector)
{
    const std::vector<UsbDeviceId> cameras = findDavisCameras(transport);
    if (cameras.empty())
        CV_Error_(Error::StsError, ("%s: no DAVIS camera is connected (USB %04x:%04x / %04x:%04x not found)", source.c_str(),
                                    kVendorId, kProductFx3, kVendorId, kProductFx2));
    // Serial numbers have 8 characters; a short all-digit selector is an index.
    const bool isIndex = !selector.empty() && selector.size() <= 3 &&
                         std::all_of(selector.begin(), selector.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (isIndex)
    {
        const size_t i = (size_t)std::stoul(selector);
        if (i < cameras.size())
            return cameras[i];
    }
    for (const UsbDeviceId& c : cameras)
        if (c.serial == selector)
            return c;
    String connected;
    for (const UsbDeviceId& c : cameras)
        connected += cv::format("%s%s (%s)", connected.empty() ? "" : ", ", c.serial.empty() ? "?" : c.serial.c_str(),
                                c.location().c_str());
    CV_Error_(Error::StsError, ("%s: no such DAVIS camera; connected: %s", source.c_str(), connected.c_str()));
}

DavisDevice::DavisDevice(const Ptr<UsbTransport>& transport, const UsbDeviceId& id)
{
    identity_.usb = id;
    const bool fx2 = id.productId == kProductFx2;
    const int required = fx2 ? kRequiredFirmwareFx2 : kRequiredFirmwareFx3;
    if (id.firmwareVersion != required)
        CV_Error_(Error::StsError, ("%s: USB firmware version %d is %s (this back-end speaks the protocol of "
                                    "version %d of %s cameras): %s", identity_.name().c_str(), id.firmwareVersion,
                                    id.firmwareVersion < required ? "too old" : "newer than supported", required,
                                    fx2 ? "FX2" : "FX3",
                                    id.firmwareVersion < required ? "update it with iniVation's DV software"
                                                                  : "use iniVation's DV software or libcaer"));
    usb_ = transport->open(id);
    identify();
}

DavisDevice::~DavisDevice()
{
    if (running_)
        stop();
}

void DavisDevice::writeConfig(uint8_t module, uint8_t param, uint32_t value)
{
    const uint8_t bytes[4] = { (uint8_t)(value >> 24), (uint8_t)(value >> 16), (uint8_t)(value >> 8), (uint8_t)value };
    usb_->controlOut(kRequestTypeOut, kRequestConfig, module, param, bytes, 4);
}

uint32_t DavisDevice::readConfig(uint8_t module, uint8_t param)
{
    uint8_t bytes[4] = { 0, 0, 0, 0 };
    usb_->controlIn(kRequestTypeIn, kRequestConfig, module, param, bytes, 4);
    return ((uint32_t)bytes[0] << 24) | ((uint32_t)bytes[1] << 16) | ((uint32_t)bytes[2] << 8) | bytes[3];
}

void DavisDevice::identify()
{
    DavisIdentity& d = identity_;
    d.logicVersion = (int)readConfig(SYSINFO, SYSINFO_LOGIC_VERSION);
    d.logicPatch = (int)readConfig(SYSINFO, SYSINFO_LOGIC_PATCH);
    if (d.logicVersion != kRequiredLogicVersion || d.logicPatch < kRequiredLogicPatch)
        CV_Error_(Error::StsError, ("%s: FPGA logic version %d patch %d is %s (this back-end speaks the protocol "
                                    "of logic %d, patch %d or later): %s", d.name().c_str(), d.logicVersion,
                                    d.logicPatch, d.logicVersion > kRequiredLogicVersion ? "newer than supported"
                                                                                         : "too old",
                                    kRequiredLogicVersion, kRequiredLogicPatch,
                                    d.logicVersion > kRequiredLogicVersion ? "use iniVation's DV software or libcaer"
                                                                           : "update it with iniVation's DV software"));
    d.chipId = (int)readConfig(SYSINFO, SYSINFO_CHIP_IDENTIFIER);
    if (!isSupportedChip(d.chipId))
        CV_Error_(Error::StsError, ("%s: chip %s (id %d) is not supported: this back-end has the bias tables of "
                                    "DAVIS240A/B/C, DAVIS128 and DAVIS346A/B/C only", d.name().c_str(),
                                    chipName(d.chipId), d.chipId));
    d.master = readConfig(SYSINFO, SYSINFO_DEVICE_IS_MASTER) != 0;
    d.logicClockMHz = (int)readConfig(SYSINFO, SYSINFO_LOGIC_CLOCK);
    d.usbClockMHz = (int)readConfig(SYSINFO, SYSINFO_USB_CLOCK);
    d.clockDeviation = (int)readConfig(SYSINFO, SYSINFO_CLOCK_DEVIATION);
    d.rawColumns = (int)readConfig(DVS, DVS_SIZE_COLUMNS);
    d.rawRows = (int)readConfig(DVS, DVS_SIZE_ROWS);
    d.invertXY = (readConfig(DVS, DVS_ORIENTATION) & kOrientationInvertXY) != 0;
    d.hasBackgroundActivityFilter = readConfig(DVS, DVS_HAS_BA_FILTER) != 0;
    d.hasRoiFilter = readConfig(DVS, DVS_HAS_ROI_FILTER) != 0;
    if (d.rawColumns <= 0 || d.rawRows <= 0 || d.rawColumns > 4096 || d.rawRows > 4096)
        CV_Error_(Error::StsError, ("%s: the camera reports a %d x %d DVS array: not a DAVIS this back-end knows",
                                    d.name().c_str(), d.rawColumns, d.rawRows));
    roi_ = Rect(Point(0, 0), d.sensorSize());
}

void DavisDevice::sendDefaultConfig()
{
    const int chip = identity_.chipId;
    if (isDavis240(chip))
        for (const ChipSetting& b : kDavis240Biases)
            writeConfig(BIAS, b.param, b.value);
    else
        for (const ChipSetting& b : kDavis346Biases)
            if (b.param != 4 || hasTestAdc(chip))
                writeConfig(BIAS, b.param, b.value);
    for (const ChipSetting& f : kCommonChipFields)
        writeConfig(BIAS, f.param, f.value);
    if (chip == DAVIS240A || chip == DAVIS240B)
        writeConfig(BIAS, kFieldSpecialPixelControl, 0);
    if (!isDavis240(chip))
        writeConfig(BIAS, kFieldSelectGrayCounter, 1);
    if (hasTestAdc(chip))
        writeConfig(BIAS, kFieldTestAdc, 0);

    // FPGA: drop data rather than stall the sensor when USB falls behind; events only.
    writeConfig(MUX, MUX_DROP_EXTINPUT_ON_STALL, 1);
    writeConfig(MUX, MUX_DROP_DVS_ON_STALL, 1);
    writeConfig(DVS, DVS_WAIT_ON_STALL, 0);
    writeConfig(DVS, DVS_EXTERNAL_AER_CONTROL, 0);
    // Every filter register is written, whatever a previous program left: a camera last used with "suppress
    // OFF events" would otherwise stream one polarity.
    if (readConfig(DVS, DVS_HAS_PIXEL_FILTER) != 0)
        for (int p = DVS_PIXEL_FILTER_FIRST; p <= DVS_PIXEL_FILTER_LAST; p++)  // (row, column) pairs out of range = unused
            writeConfig(DVS, (uint8_t)p, (uint32_t)((p - DVS_PIXEL_FILTER_FIRST) % 2 == 0 ? identity_.rawRows
                                                                                      : identity_.rawColumns));
    if (readConfig(DVS, DVS_HAS_SKIP_FILTER) != 0)
    {
        writeConfig(DVS, DVS_SKIP_ENABLE, 0);
        writeConfig(DVS, DVS_SKIP_EVERY, kSkipEveryDefault);
    }
    if (readConfig(DVS, DVS_HAS_POLARITY_FILTER) != 0)
    {
        writeConfig(DVS, DVS_POLARITY_FLATTEN, 0);
        writeConfig(DVS, DVS_POLARITY_SUPPRESS, 0);
        writeConfig(DVS, DVS_POLARITY_SUPPRESS_TYPE, 0);
    }
    if (identity_.hasBackgroundActivityFilter)
    {
        writeConfig(DVS, DVS_BA_ENABLE, backgroundActivity_ ? 1 : 0);
        writeConfig(DVS, DVS_BA_TIME, (uint32_t)(backgroundActivityTimeUs_ / kBackgroundActivityTimeUnitUs));
        writeConfig(DVS, DVS_REFRACTORY_ENABLE, 0);
        writeConfig(DVS, DVS_REFRACTORY_TIME, 1);
    }
    if (identity_.hasRoiFilter)
        applyRoi(roi_.x, roi_.y, roi_.width, roi_.height);
    writeConfig(APS, APS_RUN, 0);
    writeConfig(APS, APS_WAIT_ON_STALL, 1);
    // The device sends a packet at least every 8 x 125 us, in device cycles of the actual USB clock.
    const double usbClock = identity_.usbClockMHz * identity_.clockDeviation / 1000.0;
    writeConfig(USB, USB_EARLY_PACKET_DELAY, (uint32_t)std::lround(kEarlyPacketSlices * kEarlyPacketSliceUs * usbClock));
}

void DavisDevice::start(int transfers, int transferBytes)
{
    // Everything off first, whatever state a previous program left.
    writeConfig(DVS, DVS_RUN, 0);
    writeConfig(APS, APS_RUN, 0);
    writeConfig(IMU, IMU_RUN_ACCELEROMETER, 0);
    writeConfig(IMU, IMU_RUN_GYROSCOPE, 0);
    writeConfig(IMU, IMU_RUN_TEMPERATURE, 0);
    writeConfig(EXTINPUT, EXTINPUT_RUN_DETECTOR, 0);
    writeConfig(MUX, MUX_RUN, 0);
    writeConfig(MUX, MUX_TIMESTAMP_RUN, 0);
    writeConfig(USB, USB_RUN, 0);
    writeConfig(MUX, MUX_RUN_CHIP, 0);
    sleepMs(10);  // the FPGA's buffers drain
    usb_->clearHalt(kDataEndpoint);
    usb_->startBulkIn(kDataEndpoint, transfers, transferBytes);
    running_ = true;
    writeConfig(MUX, MUX_RUN_CHIP, 1);
    sleepMs(200);  // biases settle
    writeConfig(USB, USB_RUN, 1);
    writeConfig(MUX, MUX_TIMESTAMP_RUN, 1);
    writeConfig(MUX, MUX_RUN, 1);
    sleepMs(50);
    writeConfig(DVS, DVS_RUN, 1);
    if (externalInput_)
        writeConfig(EXTINPUT, EXTINPUT_RUN_DETECTOR, 1);
}

bool DavisDevice::stop()
{
    bool ok = true;
    const struct { uint8_t module, param; } sequence[] = {
        { DVS, DVS_RUN }, { APS, APS_RUN }, { IMU, IMU_RUN_ACCELEROMETER }, { IMU, IMU_RUN_GYROSCOPE },
        { IMU, IMU_RUN_TEMPERATURE }, { EXTINPUT, EXTINPUT_RUN_DETECTOR }, { MUX, MUX_RUN },
        { MUX, MUX_TIMESTAMP_RUN }, { USB, USB_RUN }, { MUX, MUX_RUN_CHIP },
    };
    for (const auto& s : sequence)
    {
        try
        {
            writeConfig(s.module, s.param, 0);
        }
        catch (const cv::Exception&)
        {
            ok = false;  // gone or not answering: the rest is still attempted, then the transfers go
        }
    }
    usb_->stopBulkIn();
    running_ = false;
    return ok;
}

void DavisDevice::resetTimestamp()
{
    // One multi-write so that the pulse is atomic: (MUX, TIMESTAMP_RESET, 1) then (MUX, TIMESTAMP_RESET, 0).
    const uint8_t records[12] = { MUX, MUX_TIMESTAMP_RESET, 0, 0, 0, 1, MUX, MUX_TIMESTAMP_RESET, 0, 0, 0, 0 };
    usb_->controlOut(kRequestTypeOut, kRequestConfigMulti, 2, 0, records, sizeof(records));
}

bool DavisDevice::applyRoi(int x, int y, int width, int height)
{
    const Size s = identity_.sensorSize();
    if (!identity_.hasRoiFilter || width < 1 || height < 1 || x < 0 || y < 0 || x + width > s.width ||
        y + height > s.height)
        return false;
    // The filter works in raw (column, row) coordinates, inclusive ends.
    const int c0 = identity_.invertXY ? y : x, r0 = identity_.invertXY ? x : y;
    const int c1 = identity_.invertXY ? y + height - 1 : x + width - 1;
    const int r1 = identity_.invertXY ? x + width - 1 : y + height - 1;
    writeConfig(DVS, DVS_ROI_START_COLUMN, (uint32_t)c0);
    writeConfig(DVS, DVS_ROI_START_ROW, (uint32_t)r0);
    writeConfig(DVS, DVS_ROI_END_COLUMN, (uint32_t)c1);
    writeConfig(DVS, DVS_ROI_END_ROW, (uint32_t)r1);
    roi_ = Rect(x, y, width, height);
    return true;
}

bool DavisDevice::setProperty(int propId, double value)
{
    const int v = cvRound(value);
    switch (propId)
    {
    case EVENT_CAP_PROP_DEVICE_BIAS_PRESET:
        if (v != 0)
            return false;
        sendDefaultConfig();
        return true;
    case EVENT_CAP_PROP_DEVICE_BIAS_SELECT:
        if (v < 0 || v > 36)
            return false;
        biasSelect_ = v;
        return true;
    case EVENT_CAP_PROP_DEVICE_BIAS_VALUE:
        if (v < 0 || v > 0xFFFF)
            return false;
        writeConfig(BIAS, (uint8_t)biasSelect_, (uint32_t)v);
        return true;
    case EVENT_CAP_PROP_DEVICE_BA_FILTER:
        if (!identity_.hasBackgroundActivityFilter)
            return false;
        backgroundActivity_ = v != 0;
        writeConfig(DVS, DVS_BA_ENABLE, backgroundActivity_ ? 1 : 0);
        return true;
    case EVENT_CAP_PROP_DEVICE_BA_FILTER_TIME_US:
    {
        const int steps = cvRound(value / kBackgroundActivityTimeUnitUs);
        if (!identity_.hasBackgroundActivityFilter || steps < 1 || steps > 4095)
            return false;
        backgroundActivityTimeUs_ = steps * kBackgroundActivityTimeUnitUs;
        writeConfig(DVS, DVS_BA_TIME, (uint32_t)steps);
        return true;
    }
    case EVENT_CAP_PROP_DEVICE_ROI_X: return applyRoi(v, roi_.y, roi_.width, roi_.height);
    case EVENT_CAP_PROP_DEVICE_ROI_Y: return applyRoi(roi_.x, v, roi_.width, roi_.height);
    case EVENT_CAP_PROP_DEVICE_ROI_WIDTH: return applyRoi(roi_.x, roi_.y, v, roi_.height);
    case EVENT_CAP_PROP_DEVICE_ROI_HEIGHT: return applyRoi(roi_.x, roi_.y, roi_.width, v);
    case EVENT_CAP_PROP_DEVICE_TIMESTAMP_RESET:
        if (v != 1)
            return false;
        resetTimestamp();
        return true;
    case EVENT_CAP_PROP_DEVICE_EXTERNAL_INPUT:
        if (v != 0 && v != 1)
            return false;
        externalInput_ = v == 1;
        writeConfig(EXTINPUT, EXTINPUT_DETECT_RISING_EDGES, 1);
        writeConfig(EXTINPUT, EXTINPUT_DETECT_FALLING_EDGES, 1);
        writeConfig(EXTINPUT, EXTINPUT_DETECT_PULSES, 0);
        if (running_)
            writeConfig(EXTINPUT, EXTINPUT_RUN_DETECTOR, externalInput_ ? 1 : 0);
        return true;
    default: return false;
    }
}

bool DavisDevice::getProperty(int propId, double& value) const
{
    switch (propId)
    {
    case EVENT_CAP_PROP_DEVICE_BIAS_PRESET: value = 0; return true;
    case EVENT_CAP_PROP_DEVICE_BIAS_SELECT: value = biasSelect_; return true;
    case EVENT_CAP_PROP_DEVICE_BA_FILTER: value = backgroundActivity_ ? 1 : 0; return true;
    case EVENT_CAP_PROP_DEVICE_EXTERNAL_INPUT: value = externalInput_ ? 1 : 0; return true;
    case EVENT_CAP_PROP_DEVICE_BA_FILTER_TIME_US: value = backgroundActivityTimeUs_; return true;
    case EVENT_CAP_PROP_DEVICE_ROI_X: value = roi_.x; return true;
    case EVENT_CAP_PROP_DEVICE_ROI_Y: value = roi_.y; return true;
    case EVENT_CAP_PROP_DEVICE_ROI_WIDTH: value = roi_.width; return true;
    case EVENT_CAP_PROP_DEVICE_ROI_HEIGHT: value = roi_.height; return true;
    case EVENT_CAP_PROP_DEVICE_IS_MASTER: value = identity_.master ? 1 : 0; return true;
    case EVENT_CAP_PROP_DEVICE_LOGIC_VERSION: value = identity_.logicVersion; return true;
    case EVENT_CAP_PROP_DEVICE_FIRMWARE_VERSION: value = identity_.usb.firmwareVersion; return true;
    case EVENT_CAP_PROP_DEVICE_CHIP_ID: value = identity_.chipId; return true;
    default: return false;
    }
}

}  // namespace detail
}  // namespace event
}  // namespace cv
