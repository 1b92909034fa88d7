"""The wrapped C++ API from Python, in either build mode: every check compares against values fixed here (closed
forms, hand-made events), so a binding that drops or mangles a field fails."""
import os
import shutil
import tempfile

import cv2
import numpy as np
import pytest

import opencv_event as ev


def test_one_import_in_either_build_mode():
    # The wrapped API comes from the package's own extension (standalone) or from cv2.event (contrib build);
    # OPENCV_EVENT_BUILD_MODE says which the run expects.
    mode = os.environ.get("OPENCV_EVENT_BUILD_MODE")
    if mode is None:
        pytest.skip("OPENCV_EVENT_BUILD_MODE (standalone or contrib) not set")
    assert mode in ("standalone", "contrib")
    assert (ev._native is getattr(cv2, "event", None)) == (mode == "contrib")
    assert ev.__version__.count(".") == 2 and callable(ev.StereoEventMatcher_create) and issubclass(ev.error, Exception)


def _packet():
    """Three events as the module's calls take them: an N x 1 x 16 uint8 array."""
    return ev.packEvents(np.array([1000.0, 1500.0, 2500.0]), np.array([1, 7, 3], np.int32),
                         np.array([2, 5, 0], np.int32), np.array([1, -1, 1], np.int32))


def test_packets_and_columns():
    # Columns -> packet -> columns: an N x 1 CV_8UC(16) Mat is an (N, 1, 16) uint8 array in numpy.
    t = np.array([1000.0, 1500.0, 2500.0])
    x = np.array([1, 7, 3], np.int32)
    y = np.array([2, 5, 0], np.int32)
    p = np.array([1, -1, 1], np.int32)
    packet = ev.packEvents(t, x, y, p)
    assert packet.shape == (3, 1, 16) and packet.dtype == np.uint8, packet.shape
    record = np.dtype([("t", "<i8"), ("x", "<i2"), ("y", "<i2"), ("p", "u1"), ("camera", "u1"), ("reserved", "<u2")])
    view = packet.reshape(3, 16).copy().view(record).ravel()
    assert list(view["t"]) == [1000, 1500, 2500] and list(view["x"]) == [1, 7, 3] and list(view["p"]) == [1, 0, 1]
    t2, x2, y2, p2, cam = ev.unpackEvents(packet)
    assert np.array_equal(t2.ravel(), t) and np.array_equal(y2.ravel(), y) and list(p2.ravel()) == [1, 0, 1]

def test_event_surface():
    packet = _packet()
    # EventSurface: the time surface at t = 2500 us with tau = 1000 us is exp(-(2500 - T) / 1000).
    surface = ev.EventSurface_create((8, 6))
    assert tuple(surface.getSensorSize()) == (8, 6)
    surface.update(packet)
    ts = surface.renderTimeSurface(2500, 1000.0, ddepth=cv2.CV_32F)
    assert ts.shape == (6, 8)
    assert abs(ts[2, 1] - np.exp(-1.5)) < 1e-6 and abs(ts[0, 3] - 1.0) < 1e-6 and ts[5, 0] == 0 and abs(ts[5, 7] - np.exp(-1.0)) < 1e-6
    assert surface.getEventCount() == 3

def test_event_statistics():
    packet = _packet()
    # EventStatistics: 3 events over 1.5 ms, 2 ON, at (1, 2), (7, 5) and (3, 0): no two are neighbours, so all
    # three are isolated, and each is its own edge crossing.
    stats = ev.EventStatistics_create((8, 6))
    stats.update(packet)
    st = stats.getStatistics()
    assert st.events == 3 and st.durationUs == 1500 and abs(st.onShare - 2 / 3) < 1e-12, (st.events, st.durationUs)
    assert st.isolatedShare == 1.0 and st.eventsPerCrossing == 1.0, (st.isolatedShare, st.eventsPerCrossing)

def test_score_stereo_events():
    packet = _packet()
    # scoreStereoEvents: the three (left) events with a true disparity of 4 px, estimated 4.5 (within 1 px), 7 (3 px
    # off) and none; the second event is occluded, so it counts in the matching rate but not in the density.
    packet_truth = np.zeros((3, 6), np.float32)
    packet_truth[:, 0], packet_truth[:, 1], packet_truth[1, 5] = 5.0, 4.0, ev.GT_FLAG_OCCLUDED
    scores = ev.scoreStereoEvents(packet, np.array([[4.5], [7.0], [-1.0]], np.float32), packet_truth, ev.StereoEventScores())
    assert (scores.leftSignal, scores.leftWithin1, scores.visibleSignal, scores.estimated, scores.within1) == (3, 1, 2, 1, 1), \
        (scores.leftSignal, scores.leftWithin1, scores.visibleSignal, scores.estimated, scores.within1)
    assert (scores.leftEstimated, scores.leftWithin2) == (2, 1), (scores.leftEstimated, scores.leftWithin2)
    assert abs(scores.absErrorSum - 0.5) < 1e-6, scores.absErrorSum
    # The summary figures from those counts: 1 of 2 visible estimated, 1 of 1 within 1 px, 1 of 3 left events.
    assert (scores.density(), scores.precision(), scores.meanAbsError()) == (50.0, 100.0, 0.5)
    assert abs(scores.matchingRate() - 100.0 / 3) < 1e-12
    # With confidences (1000 bins over 0..1), twice through the same scores: the estimated event (confidence 0.75)
    # lands in its bin both times, so the bins cross to Python and back.
    confidence = np.array([[0.75], [0.5], [0.0]], np.float32)
    ranking = ev.scoreStereoEvents(packet, np.array([[4.5], [7.0], [-1.0]], np.float32), packet_truth,
                                   ev.StereoEventScores(), None, None, confidence)
    ranking = ev.scoreStereoEvents(packet, np.array([[4.5], [7.0], [-1.0]], np.float32), packet_truth, ranking,
                                   None, None, confidence)
    bins = np.asarray(ranking.confidenceEstimated).ravel()
    assert len(bins) == 1000 and bins.sum() == 2 and bins[750] == 2, (len(bins), bins.sum())
    assert np.asarray(ranking.confidenceWithin1).ravel()[750] == 2

def test_writer_and_capture():
    packet = _packet()
    # EventWriter -> EventCapture through a file.
    path = os.path.join(tempfile.mkdtemp(), "events.aedat4")
    writer = ev.EventWriter(path, (8, 6))
    writer.write(packet)
    writer.release()
    assert ev.detectEventFileFormat(path) == "AEDAT4"
    cap = ev.EventCapture(path)
    assert cap.isOpened() and cap.getBackendName() == "AEDAT4"
    cap.set(ev.EVENT_CAP_PROP_BATCH_EVENTS, 100)
    ok, back = cap.read()
    assert ok and np.array_equal(back, packet)
    ok, back = cap.read()
    assert not ok

def test_triggers():
    packet = _packet()
    # Trigger events of a packet, viewed with the documented dtype: an EVT 2.0 file with one event at 64000 us and a
    # rising edge on channel 3 at 64005 us.
    raw = os.path.join(tempfile.mkdtemp(), "triggers.raw")
    with open(raw, "wb") as f:
        f.write(b"% evt 2.0\n% geometry 640x480\n")
        words = [(0x8 << 28) | 1000, (1 << 28) | (7 << 11) | 9, (0xA << 28) | (5 << 22) | (3 << 8) | 1]
        f.write(np.array(words, "<u4").tobytes())
    cap = ev.EventCapture(raw)
    ok, events = cap.read()
    assert ok and events.shape == (1, 1, 16)
    ok, triggers = cap.retrieveTriggers()
    assert ok and triggers.shape == (1, 1, 16) and triggers.dtype == np.uint8, triggers.shape
    trigger_dtype = np.dtype([("t", "<i8"), ("channel", "<i2"), ("kind", "u1"), ("camera", "u1"), ("reserved", "<u4")])
    record = triggers.reshape(-1, 16).view(trigger_dtype).ravel()[0]
    assert (record["t"], record["channel"], record["kind"]) == (64005, 3, ev.EVENT_TRIGGER_RISING), record
    assert ev.getTriggerKindName(int(record["kind"])) == "rising"
    assert cap.get(ev.EVENT_CAP_PROP_TRIGGERS) == 1

def test_stereo():
    packet = _packet()
    # Stereo merge with camera ids.
    merged = ev.mergeStereoEvents(packet, packet)
    tm, xm, ym, pm, cm = ev.unpackEvents(merged)
    assert list(cm.ravel()) == [0, 1, 0, 1, 0, 1]
    # StereoEventMatcher on a closed-form pair: one vertical edge at 500 px/s on a 64 x 24 rectified pair,
    # the right view 12 px to the left: matched events get disparity 12 (within 1 px), depth f B / 12.
    events = []
    for x in range(64):
        for y in range(24):
            t = 100000 + x * 2000
            events.append((t, x, y, 0))
            if x >= 12:
                events.append((t + 300, x - 12, y, 1))
    events.sort(key=lambda e: e[0])
    arr = np.array(events, dtype=np.float64)
    stereo = ev.packEvents(arr[:, 0], arr[:, 1].astype(np.int32), arr[:, 2].astype(np.int32),
                           np.ones(len(arr), np.int32), camera=arr[:, 3].astype(np.int32))
    # Where the pair's events line up: the edge's 12 px (every 20 ms slice alike: correlation 1), and -12 px with
    # the cameras exchanged.
    d, corr, score = ev.estimateDominantDisparity(stereo, (64, 24), 20)
    assert d == 12 and corr.shape == (1, 41) and abs(score - 1) < 1e-9, (d, corr.shape, score)
    exchanged = ev.packEvents(arr[:, 0], arr[:, 1].astype(np.int32), arr[:, 2].astype(np.int32),
                              np.ones(len(arr), np.int32), camera=1 - arr[:, 3].astype(np.int32))
    assert ev.estimateDominantDisparity(exchanged, (64, 24), 20)[0] == -12
    # checkStereoPair says the same, and names the exchanged cameras.
    pair = ev.checkStereoPair(stereo, (64, 24), 0, 20)
    assert pair.overlap and pair.lineUpTrusted and pair.lineUpDisparity == 12 and not pair.camerasExchanged
    assert pair.leftEvents + pair.rightEvents == len(events)
    assert ev.checkStereoPair(exchanged, (64, 24), 0, 20).camerasExchanged
    matcher = ev.StereoEventMatcher_create((64, 24), ev.STEREO_COUPLED)
    calib = ev.StereoCalibration_fromRectified((64, 24), 100.0, 0.1)
    assert abs(calib.baseline() - 0.1) < 1e-12 and calib.P2.shape == (3, 4)
    # A rectified pair's events stay where they are.
    assert np.array_equal(calib.rectifyEvents(stereo).reshape(-1), stereo.reshape(-1))
    matcher.setMaxDisparity(30)
    assert matcher.getMinConfidence() == 0  # by default every event keeps its best estimate
    matcher.setMinConfidence(0.15)
    disparity, lifetime, flags, depth, flow, confidence = matcher.process(stereo)
    found = disparity.ravel() >= 0
    # Kept estimates reach the rejection threshold; rejected ones (STEREO_AMBIGUOUS) stay below it.
    assert np.all(confidence.ravel()[found] >= matcher.getMinConfidence())
    rejected = (flags.ravel() & ev.STEREO_AMBIGUOUS) != 0
    assert rejected.sum() > 0, "no estimate rejected: the threshold's side of the check is untested"
    assert np.all(confidence.ravel()[rejected] < matcher.getMinConfidence())
    assert found.sum() > len(events) // 2, found.sum()
    # Judged away from the borders and the start, as the C++ edge test: in the bottom-right corner the clipped
    # window leaves a few events 1.05-1.2 px off (the left events come 300 us before their counterparts).
    x, y, cam = arr[:, 1], arr[:, 2], arr[:, 3]
    inner = (y >= 5) & (y < 24 - 5) & (x < 64 - 20) & np.where(cam == 0, x >= 12 + 10, x >= 10)
    assert (found & inner).sum() >= 0.9 * inner.sum(), ((found & inner).sum(), inner.sum())
    assert np.all(np.abs(disparity.ravel()[found & inner] - 12) <= 1)
    # The lifetime estimation's own time (the paper's Table I): not counted unless asked for; reset() zeroes it.
    assert not matcher.getTimeLifetimes() and matcher.getLifetimeSeconds() == 0
    matcher.setTimeLifetimes(True)
    matcher.reset()
    matcher.process(stereo)
    assert matcher.getTimeLifetimes() and matcher.getLifetimeSeconds() > 0
    matcher.reset()
    assert matcher.getLifetimeSeconds() == 0
    assert ev.getStereoModeName(ev.STEREO_DECOUPLED) == "decoupled" and ev.findStereoMode("Fixed") == ev.STEREO_FIXED_INTERVAL
    assert ev.findStereoMode("sgbm") == -1
    # The frame baseline: its own class, the same input, SGBM's disparities per event, shown for one frame window.
    frames = ev.FrameStereoMatcher_create((64, 24))
    frames.setFrameWindow(20000.0)
    frame_disparity, frame_flags, frame_depth = frames.process(stereo)
    assert frame_disparity.shape == (len(events), 1) and frame_flags.dtype == np.int32
    assert np.array_equal(frame_disparity.ravel() >= 0, (frame_flags.ravel() & ev.STEREO_HAS_DISPARITY) != 0)
    assert frames.getActiveDisparity(float(events[-1][0])).shape == (24, 64)
    matcher.process(stereo)
    picture = matcher.renderDisparity(float(events[-1][0]))
    assert picture.shape[0] == 24 and picture.shape[2] == 3
    active = matcher.getActiveDisparity(float(events[-1][0]))
    assert active.shape == (24, picture.shape[1] - 56) and active.dtype == np.float32
    assert (active >= 0).any() and np.array_equal(active < 0, np.all(picture[:, :active.shape[1]] == 0, axis=2))
    # The colour scale: the disparities present (the edge at 12 px), not the whole 0-40 px search.
    low, high = matcher.getDisparityDisplayRange(float(events[-1][0]))
    assert low <= 12 <= high and 2 <= high - low <= 8, (low, high)

def test_noise_filters():
    # Noise filters: an isolated event goes, a column of neighbours stays (background activity).
    ba = ev.BackgroundActivityFilter_create((16, 8), 2000.0)
    column = ev.packEvents(np.array([1000.0, 1000, 1000, 50000]), np.array([3, 3, 3, 12], np.int32),
                           np.array([2, 3, 4, 6], np.int32), np.ones(4, np.uint8))
    kept, mask = ba.filter(column)
    assert list(mask.ravel()) == [0, 255, 255, 0], mask.ravel()
    assert kept.shape[0] == 2 and ba.getKeptCount() == 2 and ba.getProcessedCount() == 4
    assert "anti_flicker" in ev.getEventFilterNames()
    hot = ev.createEventFilter("hot_pixels", (16, 8))
    assert hot.getDefaultName() == "HotPixelFilter"
    # A flickering lamp in the simulator: the ground truth flags its events, and the anti-flicker filter removes
    # them from a lamp pixel's fifth burst (about 17.5 ms at 100 Hz) on, keeping the motion's.
    sim = ev.StereoEventSimulator_create("boxes_flicker")
    ok, events, truth = sim.generate(60000.0)
    assert ok and truth.shape == (events.shape[0], 6), truth.shape
    flags = truth[:, ev.GT_FLAGS].astype(np.int32)
    flicker = (flags & ev.GT_FLAG_FLICKER) != 0
    motion = (flags & (ev.GT_FLAG_FLICKER | ev.GT_FLAG_NOISE)) == 0
    assert flicker.sum() > 10000 and motion.sum() > 1000, (flicker.sum(), motion.sum())
    kept, mask = ev.AntiFlickerFilter_create(tuple(sim.getSensorSize())).filter(events)
    kept_mask = mask.ravel() != 0
    assert (~kept_mask & flicker).sum() > 0.6 * flicker.sum() and (kept_mask & motion).sum() >= 0.99 * motion.sum()

def test_lifetimes():
    # LifetimeEstimator and LifetimeArrivalCheck: an edge sliding right at 100 px/s (10 ms per pixel) over a
    # 16 x 8 sensor, pixel (x, y) firing at 1 ms + 10 ms x. Its lifetimes are 10 ms, and the check finds the
    # edge reaching the next pixel after one of them; inlierDistance, crossingLifetimes (each pixel fires once:
    # no crossing to continue), skipEarlierEdges (one edge: nothing earlier to skip) and refitCrossingLifetimes go through the
    # bindings.
    # Every event lies on the plane, so each lifetime's quality is 1 / (1 + 1 / (n - 2)) for a whole number n of
    # inliers.
    xs, ys = np.meshgrid(np.arange(16, dtype=np.int32), np.arange(8, dtype=np.int32))
    order = np.argsort(xs.ravel(), kind="stable")
    edge = ev.packEvents((1000.0 + 10000.0 * xs.ravel()[order]), xs.ravel()[order], ys.ravel()[order],
                         np.ones(128, np.int32))
    estimator = ev.LifetimeEstimator_create((16, 8))
    estimator.setInlierDistance(0.35)
    assert estimator.getInlierDistance() == 0.35
    assert estimator.getCrossingLifetimes() == 2.0
    estimator.setCrossingLifetimes(3.5)
    assert estimator.getCrossingLifetimes() == 3.5
    assert estimator.getSkipEarlierEdges()
    estimator.setSkipEarlierEdges(False)
    assert not estimator.getSkipEarlierEdges()
    assert estimator.getRefitCrossingLifetimes() == 4.0
    estimator.setRefitCrossingLifetimes(6.0)
    assert estimator.getRefitCrossingLifetimes() == 6.0
    lifetimes, flow, status, quality = estimator.process(edge)
    assert lifetimes.shape == (128, 1) and flow.shape == (128, 2) and quality.shape == (128, 1)
    fitted = lifetimes.ravel() > 0
    assert fitted.sum() > 60 and np.allclose(lifetimes.ravel()[fitted], 10000.0, rtol=0.02), lifetimes.ravel()
    q = quality.ravel()
    inliers = 2 + q[fitted] / (1 - q[fitted])
    assert np.all(q[~fitted] == 0) and np.all(q[fitted] > 0) and np.allclose(inliers, np.round(inliers), atol=0.05), q
    # At the last event's time the last column is alive; a quality threshold above every lifetime's draws
    # nothing, one at the lowest draws them all.
    t = 1000.0 + 10000.0 * 15
    alive = estimator.renderActiveEvents(t)
    assert np.count_nonzero(alive) > 0
    assert np.array_equal(estimator.renderActiveEvents(t, minQuality=float(q[fitted].min())), alive)
    assert np.count_nonzero(estimator.renderActiveEvents(t, minQuality=min(1.0, float(q.max()) + 1e-6))) == 0
    check = ev.LifetimeArrivalCheck_create((16, 8))
    check.update(edge, lifetimes, flow)
    assert check.getSampleCount() > 50 and abs(check.getRatioQuantile(0.5) - 1.0) < 0.02, check.getRatioQuantile(0.5)

def test_simulated_recording():
    # A simulated recording with its ground truth beside it, read back in step with its events.
    folder = tempfile.mkdtemp()
    path = os.path.join(folder, "rec.aedat4")
    written = ev.writeSimulatedRecording(ev.StereoEventSimulator_create("moving_line"), path, 50000.0)
    ok, sim_events, sim_truth = ev.StereoEventSimulator_create("moving_line").generate(50000.0)
    truth_reader = ev.SimulatedGroundTruthReader(path + ".gt.csv")
    assert truth_reader.isOpened() and written == sim_events.shape[0] > 100
    assert np.array_equal(truth_reader.read(sim_events), sim_truth) and truth_reader.getLinesRead() == written
    shutil.rmtree(folder)
