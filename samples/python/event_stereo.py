#!/usr/bin/env python3
"""event_stereo in Python: per-event stereo disparity, depth and lifetime of a stereo recording (StereoEventMatcher),
with matplotlib pictures and the summary of the C++ event_stereo.

    python3 event_stereo.py --input=pair.aedat4 [--truth=pair.aedat4.gt.csv] [--calib=calib.yml] [--output=DIR]
    python3 event_stereo.py --left=L.aedat4 --right=R.aedat4 --sensor=DAVIS240

Writes into DIR: events.csv (t,x,y,p,camera,disparity,depth,lifetime,flags,confidence: the same file as
event_stereo's for the same input and options, bit for bit), disparity_NNNNN.png (the left camera's active events
coloured by disparity, for the first window and one per eighth of the run), depth_NNNNN.png beside them with a
calibration, disparity_histogram.png and summary.md. A simulated scene written by
`event_stereo --scene=S --record=rec.aedat4` comes with its ground truth in rec.aedat4.gt.csv: give it as --truth.
"""
import argparse
import math
import os
import sys
import time

import numpy as np

import opencv_event as ev

MAX_CLOCK_UNCERTAINTY_US = 500  # as event_stereo: an estimate less sure than this is not applied
CLOCK_SIGNIFICANCE = 2  # ... nor one within this many of its uncertainties of zero


def parse_args(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--input", help="a stereo recording (one file holding both cameras)")
    p.add_argument("--left", help="the left camera's recording (with --right)")
    p.add_argument("--right", help="the right camera's recording (with --left)")
    p.add_argument("--truth", help="ground truth beside a simulated recording (FILE.gt.csv); the clocks are then taken as recorded")
    p.add_argument("--calib", help="stereo calibration (FileStorage: K1 D1 K2 D2 R T, image size)")
    p.add_argument("--sensor", help="sensor size WxH or a name (DVS128, DAVIS240, DAVIS346) when the format has none")
    p.add_argument("--left-camera-value", type=int, default=0, help="the camera column's value that means left, in text recordings")
    p.add_argument("--one-based", action="store_true", help="text recordings count pixels from 1")
    p.add_argument("--right-time-offset-ms", default="auto",
                   help="added to the right camera's timestamps [ms]; auto: estimated from the first seconds and applied when clear")
    p.add_argument("--mode", default="coupled", choices=["coupled", "decoupled", "fixed"])
    p.add_argument("--min-disparity", type=int, default=0)
    p.add_argument("--max-disparity", type=int, default=40)
    p.add_argument("--frame-ms", type=float, default=33, help="window of one packet and one picture [ms]")
    p.add_argument("--no-csv", action="store_true", help="do not write events.csv")
    p.add_argument("--output", default="output/event_stereo_py", help="output folder")
    a = p.parse_args(argv)
    if bool(a.left) != bool(a.right) or bool(a.input) == bool(a.left):
        p.error("give --input, or --left and --right")
    return a


def open_source(a, offset_ms):
    cap = ev.EventCapture()
    cap.set(ev.EVENT_CAP_PROP_TEXT_LEFT_CAMERA_VALUE, a.left_camera_value)
    cap.set(ev.EVENT_CAP_PROP_TEXT_ONE_BASED, 1 if a.one_based else 0)
    cap.set(ev.EVENT_CAP_PROP_RIGHT_TIME_OFFSET_US, offset_ms * 1000)
    if a.sensor:
        width, height = ev.parseSensorSize(a.sensor)
        cap.set(ev.EVENT_CAP_PROP_SENSOR_WIDTH, width)
        cap.set(ev.EVENT_CAP_PROP_SENSOR_HEIGHT, height)
    cap.set(ev.EVENT_CAP_PROP_WINDOW_US, a.frame_ms * 1000)
    if a.left:
        cap.openStereo(a.left, a.right)
    else:
        cap.open(a.input)
    if not cap.get(ev.EVENT_CAP_PROP_STEREO):
        sys.exit("event_stereo.py: %s is not a stereo source; give each camera's recording with --left and --right"
                 % cap.getSource())
    return cap


def check_clocks(a, calibration):
    """The right camera's clock against the left one's, as event_stereo finds it: (offset applied [ms], text)."""
    if a.truth and a.right_time_offset_ms == "auto":
        # The ground truth lines follow the recording's own times and order: nothing is shifted.
        return 0.0, "+0.00 ms, as recorded (--truth: the ground truth follows the recording's times)"
    if a.right_time_offset_ms != "auto":
        offset = float(a.right_time_offset_ms)
        return offset, "%+.2f ms, as given (--right-time-offset-ms)" % offset
    cap = open_source(a, 0)
    size = tuple(cap.getSensorSize())
    packets, count, first = [], 0, None
    for packet in cap.iterate():
        if len(packet) == 0:
            continue
        packets.append(packet)
        count += len(packet)
        first = packet["t"][0] if first is None else first
        span = packet["t"][-1] - first
        if (span > 3000000 and count >= 20000) or span > 20000000 or count >= 300000:
            break
    events = np.concatenate(packets) if packets else np.zeros(0, ev.EVENT_DTYPE)
    seconds = (events["t"][-1] - events["t"][0]) * 1e-6 if len(events) else 0
    left, right = int(np.sum(events["camera"] == 0)), int(np.sum(events["camera"] == 1))
    if min(left, right) < 1000:
        return 0.0, "not estimated (left %d events, right %d in the first %.1f s)" % (left, right, seconds)
    if calibration is not None:
        events = calibration.rectifyEvents(events)
    offset, uncertainty = ev.estimateClockOffset(events, size, a.min_disparity, a.max_disparity)
    text = "%+.2f ms +- %.2f ms (estimateClockOffset, first %.1f s)" % (offset * 1e-3, uncertainty * 1e-3, seconds)
    if uncertainty > MAX_CLOCK_UNCERTAINTY_US:
        return 0.0, text + (": not applied, the events do not pin it down (uncertainty above %.1f ms: one object at "
                            "one speed along the rows, or surfaces whose speeds follow their depth)"
                            % (MAX_CLOCK_UNCERTAINTY_US * 1e-3))
    if abs(offset) < CLOCK_SIGNIFICANCE * uncertainty:
        return 0.0, text + (": not applied, within %g of its uncertainties of none: the events do not show the clocks "
                            "apart" % CLOCK_SIGNIFICANCE)
    return math.copysign(math.floor(abs(offset) / 10 + 0.5), offset) * 0.01, text + ": applied"  # as std::round


class Tally:
    """The summary's counts, as event_stereo keeps them."""

    def __init__(self, min_disparity, max_disparity, sensor_width):
        self.min_disparity = min_disparity
        self.sensor_width = sensor_width
        # Per third of the columns: the sum of the signed errors [1/1024 px] and the count (Tally.signed_error).
        self.signed_error_sum = np.zeros(3, np.int64)
        self.signed_error_count = np.zeros(3, np.int64)
        self.histogram = np.zeros(max_disparity - min_disparity + 1, np.int64)
        self.confidences = np.zeros(101, np.int64)
        self.per_camera = np.zeros(2, np.int64)
        self.with_disparity = np.zeros(2, np.int64)
        self.with_lifetime = np.zeros(2, np.int64)
        self.scores = None

    def add(self, records, disparity, flags, confidence, truth=None):
        if truth is not None:
            self.scores = ev.scoreStereoEvents(records, disparity, truth,
                                               self.scores if self.scores is not None else ev.StereoEventScores())
            self.add_signed_errors(records, disparity, truth)
        camera = records["camera"].astype(np.intp)
        found = disparity >= 0
        self.per_camera += np.bincount(camera, minlength=2)
        self.with_disparity += np.bincount(camera[found], minlength=2)
        self.with_lifetime += np.bincount(camera[(flags & ev.STEREO_HAS_LIFETIME) != 0], minlength=2)
        left = found & (camera == ev.CAMERA_LEFT)
        bins = np.clip((confidence[left] * np.float32(100)).astype(np.int64), 0, 100)
        self.confidences += np.bincount(bins, minlength=101)
        # Rounded half away from zero, as std::lround.
        k = np.floor(disparity[found].astype(np.float64) + 0.5).astype(np.int64) - self.min_disparity
        self.histogram += np.bincount(np.clip(k, 0, len(self.histogram) - 1), minlength=len(self.histogram))

    def add_signed_errors(self, records, disparity, truth):
        """The left camera's signal events estimated within 3 px of the truth, per third of the columns, as
        samples/sample_signed_errors.hpp counts them: one sign everywhere is a principal point off, a sign that
        changes across the image a focal length off."""
        truth = np.asarray(truth, np.float32).reshape(len(records), -1)
        d = disparity.astype(np.float64)
        error = d - truth[:, ev.GT_DISPARITY].astype(np.float64)
        signal = (truth[:, ev.GT_FLAGS].astype(np.int64) & ev.GT_FLAG_NOISE) == 0
        use = (records["camera"] == ev.CAMERA_LEFT) & signal & (d >= 0) & (np.abs(error) <= 3)
        third = np.minimum(2, 3 * np.maximum(0, records["x"][use].astype(np.int64)) // max(1, self.sensor_width))
        np.add.at(self.signed_error_sum, third, np.floor(error[use] * 1024 + 0.5).astype(np.int64))
        self.signed_error_count += np.bincount(third, minlength=3)

    def signed_error(self, third):
        n = self.signed_error_count[third]
        if not n:
            return "-"
        rounded = np.floor(self.signed_error_sum[third] / 1024.0 / n * 100 + 0.5) / 100
        return "%+.2f" % (rounded if rounded != 0 else 0.0)

    def events(self):
        return int(self.per_camera.sum())


def pct(a, b):
    return 100.0 * a / b if b else 0.0


def g(value):
    """A number as C++'s ostream prints a double (six significant digits)."""
    return "%g" % value


def confidence_quartiles(h):
    n = int(h.sum())
    if n == 0:
        return "none (no left estimate)"
    cumulative = np.cumsum(h)

    def quantile(q):
        k = np.nonzero(cumulative > int(q * (n - 1)))[0]
        return k[0] / 100.0 if len(k) else 1.0
    low = int(h[:15].sum())
    return "%.2f / %.2f / %.2f (%.1f %% below %.2f)" % (quantile(0.25), quantile(0.5), quantile(0.75), 100.0 * low / n, 0.15)


def save_pictures(plt, matcher, t, index, output, calibration):
    low, high = matcher.getDisparityDisplayRange(t)
    active = matcher.getActiveDisparity(t)
    shown = np.ma.masked_less(active, 0)
    fig, ax = plt.subplots(figsize=(6, 5))
    image = ax.imshow(shown, cmap="jet", vmin=low, vmax=high, interpolation="nearest")
    fig.colorbar(image, ax=ax, label="disparity [px]")
    ax.set_title("left camera's active events at %.3f s" % (t * 1e-6))
    ax.set_xlabel("x [px]")
    ax.set_ylabel("y [px]")
    fig.savefig(os.path.join(output, "disparity_%05d.png" % index), dpi=100)
    plt.close(fig)
    if calibration is not None:
        depth = np.ma.masked_where(active <= 0, calibration.focalLength() * calibration.baseline() / np.maximum(active, 1e-6))
        fig, ax = plt.subplots(figsize=(6, 5))
        image = ax.imshow(depth, cmap="viridis_r", interpolation="nearest")
        fig.colorbar(image, ax=ax, label="depth [m]")
        ax.set_title("depth of the left camera's active events at %.3f s" % (t * 1e-6))
        fig.savefig(os.path.join(output, "depth_%05d.png" % index), dpi=100)
        plt.close(fig)


def main(argv):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    a = parse_args(argv)
    os.makedirs(a.output, exist_ok=True)
    calibration = ev.readStereoCalibration(a.calib) if a.calib else None
    applied_ms, clock_text = check_clocks(a, calibration)
    cap = open_source(a, applied_ms)
    size = tuple(cap.getSensorSize())
    mode = {"coupled": ev.STEREO_COUPLED, "decoupled": ev.STEREO_DECOUPLED, "fixed": ev.STEREO_FIXED_INTERVAL}[a.mode]
    matcher = ev.StereoEventMatcher_create(size, mode)
    matcher.setMinDisparity(a.min_disparity)
    matcher.setMaxDisparity(a.max_disparity)
    if a.calib:
        matcher.loadCalibration(a.calib)
    truth_reader = ev.SimulatedGroundTruthReader(a.truth) if a.truth else None
    csv = None if a.no_csv else open(os.path.join(a.output, "events.csv"), "w")
    if csv:
        csv.write("t,x,y,p,camera,disparity,depth,lifetime,flags,confidence\n")
    tally = Tally(a.min_disparity, a.max_disparity, size[0])
    pair = PairSample()
    windows = pictures = 0
    last_eighth = 0
    seconds = 0.0
    for records in cap.iterate(progress=True):
        truth = truth_reader.read(records) if truth_reader is not None else None
        pair.add(records)
        start = time.perf_counter()
        disparity, lifetime, flags, depth, _flow, confidence = matcher.process(records)
        seconds += time.perf_counter() - start
        disparity, lifetime, flags, depth, confidence = (m.ravel() for m in (disparity, lifetime, flags, depth, confidence))
        tally.add(records, disparity, flags, confidence, truth)
        if csv and len(records):
            columns = np.rec.fromarrays([records["t"], records["x"], records["y"], records["p"], records["camera"],
                                         disparity, depth, lifetime, flags, confidence])
            np.savetxt(csv, columns, fmt="%d,%d,%d,%d,%d,%.2f,%.4f,%.0f,%d,%.3f")
        window_end = cap.get(ev.EVENT_CAP_PROP_POS_US)
        progress = cap.get(ev.EVENT_CAP_PROP_PROGRESS)
        eighth = int(math.floor(progress * 8)) if progress >= 0 else 0
        if windows == 0 or eighth > last_eighth:
            last_eighth = max(last_eighth, eighth)
            save_pictures(plt, matcher, window_end - 1, windows, a.output, calibration)
            pictures += 1
        windows += 1
    if csv:
        csv.close()

    fig, ax = plt.subplots(figsize=(7, 3.5))
    ax.bar(np.arange(a.min_disparity, a.max_disparity + 1), tally.histogram, color="#1e5ab4")
    ax.set_xlabel("disparity [px]")
    ax.set_ylabel("events")
    fig.tight_layout()
    fig.savefig(os.path.join(a.output, "disparity_histogram.png"), dpi=100)
    plt.close(fig)

    events = tally.events()
    found = tally.with_disparity
    dominant = int(np.argmax(tally.histogram)) if tally.histogram.any() else -1
    rows = [("source", "%s (%s)" % (cap.getSource(), cap.getBackendName())),
            ("sensor", "%d x %d%s" % (size[0], size[1], ", calibration " + a.calib if a.calib else "")),
            ("mode", "%s, disparities %d..%d px" % (a.mode, a.min_disparity, a.max_disparity)),
            ("events", "%d (left %d, right %d)" % (events, tally.per_camera[0], tally.per_camera[1])),
            ("input events outside the sensor (not processed) / going back in time (clamped)",
             "%d / %d" % (cap.get(ev.EVENT_CAP_PROP_REJECTED_OUTSIDE), cap.get(ev.EVENT_CAP_PROP_TIME_BACKWARDS))),
            ("processing", "%s s, %s Mev/s (1 thread)" % (g(seconds), g(events / max(1e-9, seconds) / 1e6))),
            ("events with a disparity", "%s %% (left %s %%, right %s %%)" % (
                g(pct(found.sum(), events)), g(pct(found[0], tally.per_camera[0])), g(pct(found[1], tally.per_camera[1])))),
            ("events with a lifetime", "%s %% (left %d, right %d)" % (
                g(pct(tally.with_lifetime.sum(), events)), tally.with_lifetime[0], tally.with_lifetime[1])),
            ("right camera's clock against the left one's", clock_text)]
    rows += pair_rows(pair.events(), size, a, calibration)
    rows += [("dominant disparity", "%d px (%s %% of estimates)" % (
                 a.min_disparity + dominant if dominant >= 0 else -1,
                 g(pct(tally.histogram[dominant] if dominant >= 0 else 0, found.sum())))),
             ("confidence of the left estimates (quartiles)", confidence_quartiles(tally.confidences))]
    s = tally.scores
    if s is not None:
        rows += [("ground truth: density (estimated / non-occluded signal)", "%s %%" % g(s.density())),
                 ("ground truth: estimates within 1 px", "%s %%" % g(s.precision())),
                 ("ground truth: matching rate (left signal events within 1 px, over all of them)", "%s %%" % g(s.matchingRate())),
                 ("ground truth: left signal events 1-2 px off / over 2 px off / without a disparity", "%.1f / %.1f / %.1f %%" % (
                     pct(s.leftWithin2 - s.leftWithin1, s.leftSignal), pct(s.leftEstimated - s.leftWithin2, s.leftSignal),
                     pct(s.leftSignal - s.leftEstimated, s.leftSignal))),
                 ("ground truth: mean absolute disparity error", "%s px" % g(s.meanAbsError())),
                 ("ground truth: mean signed error of the left estimates within 3 px, by third of the columns (left / "
                  "middle / right)", "%s / %s / %s px" % tuple(tally.signed_error(k) for k in range(3)))]
    rows.append(("outputs", "%s%d of %d windows as disparity_NNNNN.png%s, disparity_histogram.png" % (
        "" if a.no_csv else "events.csv, ", pictures, windows, " (+ depth_NNNNN.png)" if calibration is not None else "")))
    text = "# event_stereo summary\n\n| | |\n|---|---|\n" + "".join("| %s | %s |\n" % r for r in rows)
    with open(os.path.join(a.output, "summary.md"), "w") as f:
        f.write(text)
    print(text, end="")
    return 0


class PairSample:
    """The events the pair check looks at, as event_stereo takes them: from the first on, until one lies more than
    2 s after it with 20,000 taken, or 20 s after it, or 2,000,000 are taken."""

    def __init__(self):
        self.parts, self.taken, self.first, self.done = [], 0, None, False

    def add(self, records):
        if self.done or len(records) == 0:
            return
        self.first = records["t"][0] if self.first is None else self.first
        span = records["t"] - self.first
        index = self.taken + np.arange(len(records))
        stop = np.nonzero(((span > 2000000) & (index >= 20000)) | (span > 20000000) | (index >= 2000000))[0]
        end = stop[0] if len(stop) else len(records)
        self.parts.append(records[:end].copy())
        self.taken += end
        self.done = len(stop) > 0

    def events(self):
        return np.concatenate(self.parts) if self.parts else np.zeros(0, ev.EVENT_DTYPE)


def pair_rows(records, size, a, calibration):
    """The row alignment and the line-up over the first two seconds (checkStereoPair), as event_stereo writes them."""
    if calibration is not None and len(records):
        records = calibration.rectifyEvents(records)
    c = ev.checkStereoPair(records, size, a.min_disparity, a.max_disparity)
    n = int(c.leftEvents + c.rightEvents)
    span = "first %.1f s" % (c.spanUs * 1e-6)
    if n < 2000:
        rows = disparity = "not estimated (too few events)"
    elif not c.overlap:
        rows = disparity = "not estimated (left %.0f events, right %.0f)" % (c.leftEvents, c.rightEvents)
    else:
        disparity = "%d px (correlation %.2f, %d events)" % (c.lineUpDisparity, c.lineUpScore, n)
        if not c.rowsEstimated:
            rows = "not estimated (too narrow a sensor for the disparity range)"
        else:
            rows = "offset %+.2f px, roll %+.4f rad: up to %.2f px at the sides (score %.2f, %d events)" % (
                c.rowOffset, c.roll, c.rowsOffAtSides, c.rowScore, n)
            if not c.rowsTrusted:
                rows += "; a score below 0.4: too uncertain to act on"
    return [("row alignment of the pair (estimateRowAlignment, %s)" % span, rows),
            ("disparity the pair's events line up at (estimateDominantDisparity, %s)" % span, disparity)]


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv[1:]))
    except ev.error as e:
        sys.exit("event_stereo.py: %s" % e)
