#!/usr/bin/env python3
"""Writes the fuzzers' seed files into test/fuzz/corpus/<target>/ (committed; small).

Each seed is a tiny valid file of its format, built here from the byte layouts of doc/formats.md,
so that the fuzzers start past the magic and header checks. Formats whose container is too rich to write
by hand here (AEDAT 4.0, ROS bags, HDF5) get their magic only; run.sh adds the real samples of
../shared/data/format_samples as extra seeds when they are present (never copied into the repository).
"""
import os
import random
import struct

here = os.path.dirname(os.path.abspath(__file__))
rng = random.Random(1)


def write(target, name, data):
    d = os.path.join(here, "corpus", target)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, name), "wb") as f:
        f.write(data)


def events(n, w, h):
    t = 0
    for _ in range(n):
        t += rng.randrange(0, 500)
        yield t, rng.randrange(w), rng.randrange(h), rng.randrange(2)


# text: RPG (seconds), microseconds with a size line, TUM-style camera column
write("text", "rpg_seconds.txt", "".join("%.6f %d %d %d\n" % (t / 1e6, x, y, p) for t, x, y, p in events(20, 240, 180)).encode())
write("text", "size_line_us.txt", ("346 260\n" + "".join("%d %d %d %d\n" % e for e in events(20, 346, 260))).encode())
write("text", "stereo_camera_column.txt", "".join("%d %d %d %d %d\n" % (e + (rng.randrange(2),)) for e in events(20, 128, 128)).encode())

# AEDAT 2.0: '#' header, big-endian (address, timestamp); DAVIS240 address = y << 22 | x << 12 | p << 11
hdr = b"#!AER-DAT2.0\r\n# AEChip: eu.seebetter.ini.chips.davis.DAVIS240C\r\n"
ev = list(events(20, 240, 180))  # then an external event (address bit 10): a trigger
write("aedat2", "davis240.aedat", hdr + b"".join(struct.pack(">II", (y << 22) | (x << 12) | (p << 11), t) for t, x, y, p in ev)
      + struct.pack(">II", 1 << 10, ev[-1][0] + 1))
hdr = b"#!AER-DAT2.0\r\n# AEChip: ch.unizh.ini.jaer.chip.retina.DVS128\r\n"
ev = list(events(20, 128, 128))  # then a sync event (bit 15): a trigger
write("aedat2", "dvs128.aedat", hdr + b"".join(struct.pack(">II", (y << 8) | (x << 1) | p, t) for t, x, y, p in ev)
      + struct.pack(">II", 1 << 15, ev[-1][0] + 1))

# AEDAT 3.1: text header, then packets: 28-byte header (type, source, size, ts offset, overflow, capacity,
# number, valid) and 8-byte polarity events (x << 17 | y << 2 | p << 1 | valid, timestamp); a special-event packet
# (type 0: type << 1 | valid, timestamp) with a rising and a falling edge of external input 0
hdr = b"#!AER-DAT3.1\r\n#Format: RAW\r\n#Source 1: DAVIS346B\r\n#!END-HEADER\r\n"
ev = list(events(10, 346, 260))
packet = struct.pack("<HHIIIIII", 1, 1, 8, 4, 0, len(ev), len(ev), len(ev))
packet += b"".join(struct.pack("<Ii", (x << 17) | (y << 2) | (p << 1) | 1, t) for t, x, y, p in ev)
special = struct.pack("<HHIIIIII", 0, 1, 8, 4, 0, 2, 2, 2) + struct.pack("<IiIi", 2 << 1 | 1, 10, 3 << 1 | 1, 20)
write("aedat3", "davis346.aedat", hdr + packet + special + struct.pack("<HHIIIIII", 2, 1, 16, 12, 0, 1, 1, 1) + b"\x00" * 16)

# Prophesee DAT: '% ' header, type and size bytes, 8-byte (t, y << 14 | x | p << 28) records
hdr = b"% Data file containing CD events\n% Version 2\n% Width 304\n% Height 240\n"
write("dat", "cd.dat", hdr + b"\x00\x08" + b"".join(struct.pack("<II", t, (p << 28) | (y << 14) | x) for t, x, y, p in events(20, 304, 240)))

# Prophesee RAW EVT 2.0: 32-bit words, TIME_HIGH (0x8) then CD events (type = polarity, ts low 6 bits, x, y)
hdr = b"% evt 2.0\n% format EVT2;height=480;width=640\n% end\n"
words = [0x8 << 28 | 0]
for t, x, y, p in events(20, 640, 480):
    words.append(0x8 << 28 | (t >> 6))
    words.append(p << 28 | (t & 63) << 22 | x << 11 | y)
words.append(0xA << 28 | (t & 63) << 22 | 1 << 8 | 1)  # EXT_TRIGGER: channel 1, rising
write("raw", "evt2.raw", hdr + b"".join(struct.pack("<I", w) for w in words))

# Prophesee RAW EVT 3.0: 16-bit words: TIME_HIGH, TIME_LOW, ADDR_Y, ADDR_X, a VECT_BASE_X + VECT_12
hdr = b"% evt 3.0\n% format EVT3;height=720;width=1280\n% end\n"
words = []
for t, x, y, p in events(20, 1268, 720):
    words += [0x8 << 12 | (t >> 12) & 0xFFF, 0x6 << 12 | t & 0xFFF, 0x0 << 12 | y, 0x2 << 12 | p << 11 | x]
words += [0x3 << 12 | 1 << 11 | 100, 0x4 << 12 | 0b101010101010, 0x5 << 12 | 0xFF]
words += [0xA << 12 | 2 << 8 | 1, 0xA << 12 | 2 << 8]  # EXT_TRIGGER: channel 2, rising then falling
write("raw", "evt3.raw", hdr + b"".join(struct.pack("<H", w) for w in words))

# Containers: magic only (run.sh adds real samples when ../shared/data is there)
write("aedat4", "magic.aedat4", b"#!AER-DAT4.0\r\n")
write("rosbag1", "magic.bag", b"#ROSBAG V2.0\n")
write("rosbag2", "magic.db3", b"SQLite format 3\x00")
write("hdf5", "magic.h5", b"\x89HDF\r\n\x1a\n" + b"\x00" * 8)

# DAVIS words: byte 0 = geometry/options, byte 1 = transfer size; then timestamp, Y, X, wrap, reset words
def davis_stream(options, transfer, wait_reset):
    out = bytearray([options, transfer])
    def word(w):
        out.extend(struct.pack("<H", w))
    if wait_reset:
        word(0x8000 | 5); word(0x1000 | 3); word(0x3000 | 4)   # before the reset: skipped
        word(0x0001)                                          # timestamp reset
    base = 0
    for t, x, y, p in events(30, 240, 180):
        if t - base >= 0x8000:
            word(0x7000 | (t - base) // 0x8000)
            base += (t - base) // 0x8000 * 0x8000
        word(0x8000 | (t - base)); word(0x1000 | y); word((0x3000 if p else 0x2000) | x)
    word(0x4000 | 0x123); word(0x5000 | 0x045); word(0x6000 | 0x3FF); word(0x0005)  # APS / IMU / misc / special
    word(0x0003); word(0x0002)                                                        # external input edges
    return bytes(out)

write("davis_decoder", "davis240.bin", davis_stream(0x00, 200, False))
write("davis_decoder", "davis240_wait_reset.bin", davis_stream(0x80, 7, True))
write("davis_decoder", "invert_xy.bin", davis_stream(0x40 | 0x02 | 0x10, 100, False))

# ROS 2 bag in MCAP storage: magic, records {u8 opcode, u64 length, content} (strings: u32 length), a schema,
# a channel and two CDR event_camera_msgs/msg/EventPacket messages in libcaer_cmp (16-bit words, code in the
# top 4 bits: 0 time high, 1 time low, 2 column, 3 row + polarity), then the data end, the footer, the magic.
def mcap_record(opcode, content):
    return struct.pack("<BQ", opcode, len(content)) + content


def mcap_str(s):
    return struct.pack("<I", len(s)) + s


def cdr_event_packet(time_base, words):
    out = bytearray(b"\x00\x01\x00\x00")
    def align(a):
        while (len(out) - 4) % a:
            out.append(0)
    def put(fmt, v):
        align(struct.calcsize(fmt))
        out.extend(struct.pack("<" + fmt, v))
    def cdr_str(s):
        put("I", len(s) + 1)
        out.extend(s + b"\x00")
    put("i", 1700000000); put("I", 0); cdr_str(b"camera")
    put("I", 260); put("I", 346); put("Q", 1); put("Q", time_base); cdr_str(b"libcaer_cmp"); put("B", 0)
    payload = b"".join(struct.pack("<H", w) for w in words)
    put("I", len(payload))
    out.extend(payload)
    return bytes(out)


def cmp_words(evs):
    words = []
    for t, x, y, p in evs:
        words += [0x0 << 12 | (t >> 12) & 0xFFF, 0x1 << 12 | t & 0xFFF, 0x2 << 12 | x, 0x3 << 12 | p << 11 | y]
    return words


mcap = b"\x89MCAP0\r\n" + mcap_record(0x01, mcap_str(b"ros2") + mcap_str(b"make_seeds.py"))
mcap += mcap_record(0x03, struct.pack("<H", 1) + mcap_str(b"event_camera_msgs/msg/EventPacket") + mcap_str(b"ros2msg") + struct.pack("<I", 0))
mcap += mcap_record(0x04, struct.pack("<HH", 1, 1) + mcap_str(b"/events") + mcap_str(b"cdr") + struct.pack("<I", 0))
for k in range(2):
    data = cdr_event_packet(10000000 * (k + 1), cmp_words(sorted(events(8, 346, 260))))  # 10 ms apart
    mcap += mcap_record(0x05, struct.pack("<HIQQ", 1, k, k, k) + data)
mcap += mcap_record(0x0F, struct.pack("<I", 0)) + mcap_record(0x02, struct.pack("<QQI", 0, 0, 0)) + b"\x89MCAP0\r\n"
write("mcap", "two_messages.mcap", mcap)
