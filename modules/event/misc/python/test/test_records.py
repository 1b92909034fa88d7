"""NumPy records: views of the module's 16-byte events without a copy, and the converters from other tools' layouts,
against records written out by hand."""
import os
import shutil
import tempfile

import numpy as np
import pytest

import opencv_event as ev


def test_records_view_packets_without_a_copy():
    packet = ev.packEvents(np.array([1000.0, 1500.0]), np.array([1, 7], np.int32), np.array([2, 5], np.int32),
                           np.array([1, -1], np.int32))
    records = ev.as_records(packet)
    assert records.dtype == ev.EVENT_DTYPE and ev.EVENT_DTYPE.itemsize == 16
    assert np.shares_memory(records, packet)
    assert records.tolist() == [(1000, 1, 2, 1, 0), (1500, 7, 5, 0, 0)]
    back = ev.as_packet(records)
    assert back.shape == (2, 1, 16) and back.dtype == np.uint8 and np.shares_memory(back, packet)
    # A write through the view is the packet's.
    records["x"][1] = 9
    assert ev.unpackEvents(packet)[1].ravel().tolist() == [1, 9]


def test_records_go_into_the_module_and_come_back():
    records = ev.from_columns([10, 20, 30], [0, 3, 7], [1, 1, 2], [1, 0, -1], camera=[0, 1, 1])
    assert records.tolist() == [(10, 0, 1, 1, 0), (20, 3, 1, 0, 1), (30, 7, 2, 0, 1)]
    left, right = ev.splitStereoEvents(ev.as_packet(records))
    assert ev.as_records(left).tolist() == [(10, 0, 1, 1, 0)]
    assert ev.as_records(right)["t"].tolist() == [20, 30]
    t, x, y, p, camera = ev.to_columns(records)
    assert t.tolist() == [10, 20, 30] and p.tolist() == [1, 0, 0] and camera.tolist() == [0, 1, 1]


def test_trigger_records():
    raw = np.zeros((1, 1, 16), np.uint8)
    raw[0, 0, :8] = np.frombuffer(np.int64(64005).tobytes(), np.uint8)
    raw[0, 0, 8:10] = [3, 0]
    raw[0, 0, 10] = ev.EVENT_TRIGGER_RISING
    trigger = ev.as_trigger_records(raw)[0]
    assert (trigger["t"], trigger["channel"], trigger["kind"], trigger["camera"]) == (64005, 3, ev.EVENT_TRIGGER_RISING, 0)


def test_converters_from_other_tools():
    expected = [(5, 1, 2, 1, 0), (9, 3, 4, 0, 0)]
    dv = np.array([(5, 1, 2, True), (9, 3, 4, False)],
                  dtype=[("timestamp", "<i8"), ("x", "<i2"), ("y", "<i2"), ("polarity", "?")])
    assert ev.from_dv(dv).tolist() == expected
    metavision = np.array([(1, 2, 1, 5), (3, 4, 0, 9)], dtype=[("x", "<u2"), ("y", "<u2"), ("p", "<i2"), ("t", "<i8")])
    assert ev.from_metavision(metavision).tolist() == expected
    tonic = np.array([(1, 2, 5, 1), (3, 4, 9, 0)], dtype=[("x", "<i8"), ("y", "<i8"), ("t", "<i8"), ("p", "<i8")])
    assert ev.from_tonic(tonic).tolist() == expected
    assert ev.from_tonic(tonic, camera=1)["camera"].tolist() == [1, 1]


def test_bad_input_is_refused():
    with pytest.raises(ValueError, match="x: values outside"):
        ev.from_columns([0], [40000], [0], [1])
    with pytest.raises(ValueError, match="t: whole numbers"):
        ev.from_columns([0.5], [0], [0], [1])
    with pytest.raises(ValueError, match="16-byte records"):
        ev.as_records(np.zeros((3, 15), np.uint8))
    with pytest.raises(ValueError, match="EVENT_DTYPE records"):
        ev.as_packet(np.zeros(3, np.float64))


def test_every_call_that_takes_events_takes_records():
    sim = ev.StereoEventSimulator_create("two_planes")
    ok, packet, truth = sim.generate(60000.0)
    records = ev.as_records(packet).copy()  # records of their own, not a view of the packet
    size = tuple(sim.getSensorSize())
    # Module functions.
    left_p, right_p = ev.splitStereoEvents(packet)
    left_r, right_r = ev.splitStereoEvents(records)
    assert np.array_equal(left_p, left_r) and np.array_equal(right_p, right_r)
    # Methods of objects from factories, and of objects that calls return.
    matcher = ev.StereoEventMatcher_create(size, ev.STEREO_COUPLED)
    from_packet = matcher.process(packet)
    matcher.reset()
    from_records = matcher.process(records)
    assert all(np.array_equal(a, b) for a, b in zip(from_packet, from_records))
    assert isinstance(matcher, ev.StereoEventMatcher)
    estimator = matcher.getLifetimeEstimator(ev.CAMERA_LEFT)
    assert isinstance(estimator, ev.LifetimeEstimator) and estimator.process(ev.as_records(left_p))[0].shape[0] == len(left_p)
    lifetimes = ev.LifetimeEstimator_create(size).process(left_p)[0]
    assert np.array_equal(ev.LifetimeEstimator_create(size).process(ev.as_records(left_p))[0], lifetimes)
    surface = ev.EventSurface_create(size)
    surface.update(records)
    assert surface.getEventCount() == len(records)
    kept, mask = ev.BackgroundActivityFilter_create(size, 2000.0).filter(records)
    assert np.array_equal(mask, ev.BackgroundActivityFilter_create(size, 2000.0).filter(packet)[1])
    # A class constructed directly, and a wrapped object handed to another call.
    folder = tempfile.mkdtemp()
    writer = ev.EventWriter(os.path.join(folder, "records.aedat4"), size)
    left = ev.as_records(left_p).copy()
    writer.write(left)
    writer.release()
    capture = ev.EventCapture(os.path.join(folder, "records.aedat4"))
    capture.set(ev.EVENT_CAP_PROP_BATCH_EVENTS, len(left))
    assert np.array_equal(next(iter(capture)), left)
    fresh = ev.StereoEventSimulator_create("moving_line")
    written = ev.writeSimulatedRecording(fresh, os.path.join(folder, "sim.aedat4"), 50000.0)
    assert written == ev.StereoEventSimulator_create("moving_line").generate(50000.0)[1].shape[0] > 0
    shutil.rmtree(folder)


def test_concatenated_records_are_taken_in_numpy_packed_layout():
    a = ev.from_columns([1, 2], [3, 4], [5, 6], [1, 0])
    b = ev.from_columns([7], [8], [9], [1], camera=1)
    joined = np.concatenate([a, b])  # NumPy drops the record's padding here
    assert ev.as_records(joined).tolist() == a.tolist() + b.tolist()
    assert ev.as_packet(joined).shape == (3, 1, 16)
    left, right = ev.splitStereoEvents(joined)
    assert ev.as_records(right).tolist() == b.tolist()


def test_wrapped_classes_show_and_create_like_the_cpp_ones():
    matcher = ev.StereoEventMatcher.create((64, 24), ev.STEREO_DECOUPLED)  # the static method on the class
    assert isinstance(matcher, ev.StereoEventMatcher) and matcher.getMode() == ev.STEREO_DECOUPLED
    assert "process" in dir(matcher) and "setMaxDisparity" in dir(ev.StereoEventMatcher)
    matcher.setMaxDisparity(17)
    assert matcher.getMaxDisparity() == 17 and matcher.native.getMaxDisparity() == 17
    scores = ev.StereoEventScores()
    scores.leftSignal = 4  # a property set through the forwarding object lands on the C++ struct
    assert scores.native.leftSignal == 4
