"""Real recordings read in Python give what event_info gives: counts, first and last timestamps, pixel ranges."""
import json
import subprocess

import numpy as np
import pytest

import opencv_event as ev
from event_test_support import require_recording, require_tool

SAMPLES = ["aestream_davis346.aedat4", "tonic_sample_dvxplorer.aedat4", "tonic_sample_ncars.dat", "evt2_sample.raw",
           "evt3_sample.raw", "ecpy_test_events_1_ros1.bag", "ecpy_legacy_eventarray_ros2", "ecpy_test_events_2_mcap"]


@pytest.mark.parametrize("name", SAMPLES)
def test_recording_matches_event_info(name):
    path = require_recording("format_samples/" + name)
    info = json.loads(subprocess.run([require_tool("event_info"), "--json", str(path)], check=True,
                                     capture_output=True, text=True).stdout)[0]
    events, triggers = 0, 0
    on = 0
    first = last = None
    x_range = [np.iinfo(np.int16).max, -1]
    y_range = [np.iinfo(np.int16).max, -1]
    cap = ev.EventCapture(str(path))
    for packet in cap:
        if len(packet) == 0:
            continue
        events += len(packet)
        on += int(packet["p"].sum())
        first = packet["t"][0] if first is None else first
        last = packet["t"][-1]
        x_range = [min(x_range[0], packet["x"].min()), max(x_range[1], packet["x"].max())]
        y_range = [min(y_range[0], packet["y"].min()), max(y_range[1], packet["y"].max())]
    triggers = int(cap.get(ev.EVENT_CAP_PROP_TRIGGERS))
    assert (events, on, events - on) == (info["events"], info["on"], info["off"])
    assert (first, last) == (info["first_us"], info["last_us"])
    assert x_range == [info["x_min"], info["x_max"]] and y_range == [info["y_min"], info["y_max"]]
    assert triggers == sum(info["triggers"].values())


def test_packets_of_n_events_and_of_n_microseconds():
    path = require_recording("format_samples/evt3_sample.raw")
    sizes = [len(p) for p in ev.packets(path, events=1000)]
    assert all(n == 1000 for n in sizes[:-1]) and 0 < sizes[-1] <= 1000
    spans = [(p["t"][0], p["t"][-1]) for p in ev.packets(path, window_us=5000) if len(p)]
    assert all(b - a < 5000 for a, b in spans)
    assert sum(len(p) for p in ev.packets(path, window_us=5000)) == sum(sizes)


def test_a_missing_file_names_itself():
    with pytest.raises(ev.error, match="no_such_recording.aedat4"):
        ev.EventCapture("no_such_recording.aedat4")
    with pytest.raises(ev.error, match="no_such_recording.raw"):
        next(ev.packets("no_such_recording.raw"))
