// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_DAVIS_DAVIS_PROTOCOL_HPP
#define OPENCV_EVENT_SRC_DAVIS_DAVIS_PROTOCOL_HPP

// Facts of iniVation's DAVIS USB protocol (as libcaer 3.3 speaks it; written from its public sources, see
// doc/live_davis.md): USB identities, the configuration channel's addresses and the default bias tables.
// Everything is data here; the logic that uses it is in davis_device.cpp.

#include <cstdint>

namespace cv {
namespace event {
namespace detail {
namespace davis {

const uint16_t kVendorId = 0x152A;
const uint16_t kProductFx2 = 0x841B;  // older DAVIS240 boards
const uint16_t kProductFx3 = 0x841A;  // DAVIS240C / DAVIS346 "FX3"
// The versions this protocol is for, as strict as libcaer 3.3: these exactly (another number may have moved a
// register), and logic patch 1 or later.
const int kRequiredFirmwareFx2 = 4;   // low byte of bcdDevice
const int kRequiredFirmwareFx3 = 6;
const int kRequiredLogicVersion = 18;
const int kRequiredLogicPatch = 1;
const uint8_t kDataEndpoint = 0x82;   // bulk IN: the 16-bit event word stream

// Configuration channel: vendor control requests.
const uint8_t kRequestTypeOut = 0x40;      // vendor, device, host -> device
const uint8_t kRequestTypeIn = 0xC0;       // vendor, device, device -> host
const uint8_t kRequestConfig = 0xBF;       // one 32-bit big-endian parameter; wValue = module, wIndex = param
const uint8_t kRequestConfigMulti = 0xC2;  // N x [module u8][param u8][value u32 BE]; wValue = N

// Modules and their parameters.
enum Module : uint8_t { MUX = 0, DVS = 1, APS = 2, IMU = 3, EXTINPUT = 4, BIAS = 5, SYSINFO = 6, USB = 9 };

enum MuxParam : uint8_t { MUX_RUN = 0, MUX_TIMESTAMP_RUN = 1, MUX_TIMESTAMP_RESET = 2, MUX_RUN_CHIP = 3,
                          MUX_DROP_EXTINPUT_ON_STALL = 4, MUX_DROP_DVS_ON_STALL = 5 };
enum DvsParam : uint8_t { DVS_SIZE_COLUMNS = 0, DVS_SIZE_ROWS = 1, DVS_ORIENTATION = 2, DVS_RUN = 3,
                          DVS_WAIT_ON_STALL = 4, DVS_EXTERNAL_AER_CONTROL = 5,
                          DVS_HAS_PIXEL_FILTER = 10, DVS_PIXEL_FILTER_FIRST = 11, DVS_PIXEL_FILTER_LAST = 26,
                          DVS_HAS_BA_FILTER = 30, DVS_BA_ENABLE = 31, DVS_BA_TIME = 32,
                          DVS_REFRACTORY_ENABLE = 33, DVS_REFRACTORY_TIME = 34,
                          DVS_HAS_ROI_FILTER = 40, DVS_ROI_START_COLUMN = 41, DVS_ROI_START_ROW = 42,
                          DVS_ROI_END_COLUMN = 43, DVS_ROI_END_ROW = 44,
                          DVS_HAS_SKIP_FILTER = 50, DVS_SKIP_ENABLE = 51, DVS_SKIP_EVERY = 52,
                          DVS_HAS_POLARITY_FILTER = 60, DVS_POLARITY_FLATTEN = 61, DVS_POLARITY_SUPPRESS = 62,
                          DVS_POLARITY_SUPPRESS_TYPE = 63 };
enum ApsParam : uint8_t { APS_RUN = 4, APS_WAIT_ON_STALL = 5 };
enum ImuParam : uint8_t { IMU_RUN_ACCELEROMETER = 2, IMU_RUN_GYROSCOPE = 3, IMU_RUN_TEMPERATURE = 4 };
enum ExtInputParam : uint8_t { EXTINPUT_RUN_DETECTOR = 0, EXTINPUT_DETECT_RISING_EDGES = 1,
                                EXTINPUT_DETECT_FALLING_EDGES = 2, EXTINPUT_DETECT_PULSES = 3 };
enum SysInfoParam : uint8_t { SYSINFO_LOGIC_VERSION = 0, SYSINFO_CHIP_IDENTIFIER = 1, SYSINFO_DEVICE_IS_MASTER = 2,
                              SYSINFO_LOGIC_CLOCK = 3, SYSINFO_ADC_CLOCK = 4, SYSINFO_USB_CLOCK = 5,
                              SYSINFO_CLOCK_DEVIATION = 6, SYSINFO_LOGIC_PATCH = 7 };
enum UsbParam : uint8_t { USB_RUN = 0, USB_EARLY_PACKET_DELAY = 1 };

const uint32_t kOrientationInvertXY = 1u << 2;  // DVS ORIENTATION_INFO: raw columns are the user's rows
const int kBackgroundActivityTimeUnitUs = 250;  // DVS_BA_TIME and DVS_REFRACTORY_TIME count 250 us steps
const int kEarlyPacketSlices = 8;               // libcaer default: the device sends a packet at least every 1 ms
const int kEarlyPacketSliceUs = 125;

// SYSINFO_CHIP_IDENTIFIER values.
enum ChipId { DAVIS240A = 0, DAVIS240B = 1, DAVIS240C = 2, DAVIS128 = 3, DAVIS346A = 4, DAVIS346B = 5,
              DAVIS640 = 6, DAVIS640H = 7, DAVIS208 = 8, DAVIS346C = 9 };

inline const char* chipName(int chip)
{
    switch (chip)
    {
    case DAVIS240A: return "DAVIS240A";
    case DAVIS240B: return "DAVIS240B";
    case DAVIS240C: return "DAVIS240C";
    case DAVIS128: return "DAVIS128";
    case DAVIS346A: return "DAVIS346A";
    case DAVIS346B: return "DAVIS346B";
    case DAVIS640: return "DAVIS640";
    case DAVIS640H: return "DAVIS640H";
    case DAVIS208: return "DAVIS208";
    case DAVIS346C: return "DAVIS346C";
    default: return "unknown DAVIS";
    }
}

inline bool isDavis240(int chip) { return chip == DAVIS240A || chip == DAVIS240B || chip == DAVIS240C; }
/** The chips whose biases and chip fields the tables below are right for. DAVIS208 and DAVIS640 take further
biases and overrides, and DAVIS640H has other bias addresses: they are refused rather than misconfigured. */
inline bool isSupportedChip(int chip)
{
    return isDavis240(chip) || chip == DAVIS128 || chip == DAVIS346A || chip == DAVIS346B || chip == DAVIS346C;
}
/** DAVIS346 chips (of those supported): they have the AdcTestVoltage bias (index 4) and the TestADC chip field. */
inline bool hasTestAdc(int chip) { return chip == DAVIS346A || chip == DAVIS346B || chip == DAVIS346C; }

/** One value of the chip configuration: module 5 parameter (bias index < 128, shift-register field >= 128). */
struct ChipSetting
{
    uint8_t param;
    uint16_t value;
};

// libcaer's default bias words (coarse/fine, VDAC and shifted-source encodings already applied).
const ChipSetting kDavis240Biases[] = {
    { 0, 0x427F }, { 1, 0x5FFF }, { 2, 0x400F }, { 3, 0x5B9B }, { 4, 0x573B }, { 5, 0x6DBF }, { 6, 0x5A4F },
    { 7, 0x690F }, { 8, 0x23AD }, { 9, 0x110D }, { 10, 0x419D }, { 11, 0x65BF }, { 12, 0x531F }, { 13, 0x450D },
    { 14, 0x798D }, { 15, 0x5FFF }, { 16, 0x5FFF }, { 17, 0x7D7F }, { 18, 0x6FDF }, { 19, 0x5FEF },
    { 20, 0x8410 }, { 21, 0x8410 },
};

// DAVIS346 (also DAVIS128): the 37-branch bias generator. Index 4 exists on the 346 only.
const ChipSetting kDavis346Biases[] = {
    { 0, 0x019B }, { 1, 0x0195 }, { 2, 0x01E0 }, { 3, 0x01C1 }, { 4, 0x01D5 }, { 8, 0x5A4F }, { 9, 0x7D7E },
    { 10, 0x427F }, { 11, 0x5FFF }, { 12, 0x401F }, { 13, 0x690F }, { 14, 0x23AD }, { 15, 0x110D },
    { 16, 0x419D }, { 17, 0x614D }, { 18, 0x6DBF }, { 19, 0x514D }, { 20, 0x001F }, { 21, 0x63CD },
    { 22, 0x531F }, { 23, 0x65BF }, { 24, 0x450D }, { 25, 0x798D }, { 26, 0x5FFF }, { 27, 0x5FFF },
    { 34, 0x5FEF }, { 35, 0x8410 }, { 36, 0x8410 },
};

// Chip shift-register fields every DAVIS takes (DigitalMux0..3, AnalogMux0..2, BiasMux0, ResetCalibNeuron,
// TypeNCalibNeuron, ResetTestPixel, AERnArow, UseAOut).
const ChipSetting kCommonChipFields[] = {
    { 128, 0 }, { 129, 0 }, { 130, 0 }, { 131, 0 }, { 132, 0 }, { 133, 0 }, { 134, 0 }, { 135, 0 },
    { 136, 1 }, { 137, 0 }, { 138, 1 }, { 140, 0 }, { 141, 0 },
};
const uint8_t kFieldSpecialPixelControl = 139;  // DAVIS240A/B only: 0
const uint8_t kFieldSelectGrayCounter = 143;    // DAVIS128/346: 1
const uint8_t kFieldTestAdc = 144;              // DAVIS346: 0
const uint32_t kSkipEveryDefault = 5;           // DVS skip filter's N when it is off (libcaer's default)

}  // namespace davis
}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_DAVIS_DAVIS_PROTOCOL_HPP
