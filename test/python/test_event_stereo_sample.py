"""samples/python/event_stereo.py against the C++ event_stereo on the same input: the same per-event output bit for bit,
the same summary (but for the timing and the video that only the C++ program writes), and its pictures."""
import pathlib
import subprocess
import sys

REPO = pathlib.Path(__file__).resolve().parents[2]
SAMPLE = REPO / "samples" / "python" / "event_stereo.py"
sys.path.insert(0, str(REPO / "modules" / "event" / "misc" / "python" / "test"))
from event_test_support import require_recording, require_tool as tool  # noqa: E402


def run_both(tmp_path, args):
    cpp, py = tmp_path / "cpp", tmp_path / "py"
    subprocess.run([tool("event_stereo")] + args + ["--output=%s" % cpp], check=True, capture_output=True)
    subprocess.run([sys.executable, str(SAMPLE)] + args + ["--output=%s" % py], check=True, capture_output=True)
    return cpp, py


def summary_rows(folder):
    rows = {}
    for line in (folder / "summary.md").read_text().splitlines():
        cells = line.split(" | ")
        if line.startswith("| ") and len(cells) >= 2 and not line.startswith("| |"):
            rows[cells[0][2:]] = " | ".join(cells[1:])[:-2]
    return rows


def assert_same_run(cpp, py):
    assert (cpp / "events.csv").read_bytes() == (py / "events.csv").read_bytes()
    a, b = summary_rows(cpp), summary_rows(py)
    for row in ("processing", "outputs"):
        a.pop(row), b.pop(row)
    assert a == b
    pictures = sorted(p.name for p in py.glob("disparity_0*.png"))
    assert pictures == sorted(p.name for p in cpp.glob("disparity_0*.png")) and len(pictures) >= 2
    assert (py / "disparity_histogram.png").stat().st_size > 0


def test_a_real_pair_gives_what_event_stereo_gives(tmp_path):
    fan = require_recording("stereo_dvs128_tum/Fan_disp8.dat")
    assert_same_run(*run_both(tmp_path, ["--input=%s" % fan, "--left-camera-value=1", "--sensor=DVS128"]))


def test_a_pair_whose_clocks_differ_gives_what_event_stereo_gives(tmp_path):
    # boxes_fast_pair recorded with its right clock as simulated (2.5 ms early): both programs estimate the
    # offset from the recording and apply the same one.
    recording = tmp_path / "pair.aedat4"
    subprocess.run([tool("event_stereo"), "--scene=boxes_fast_pair", "--duration-ms=800", "--right-time-offset-ms=0",
                    "--no-csv", "--record=%s" % recording, "--output=%s" % (tmp_path / "sim")], check=True, capture_output=True)
    cpp, py = run_both(tmp_path, ["--input=%s" % recording])
    assert_same_run(cpp, py)
    assert summary_rows(py)["right camera's clock against the left one's"].endswith(": applied")


def test_ground_truth_and_depth_pictures(tmp_path):
    import opencv_event as ev
    recording = tmp_path / "planes.aedat4"
    subprocess.run([tool("event_stereo"), "--scene=two_planes", "--duration-ms=300", "--no-csv",
                    "--record=%s" % recording, "--output=%s" % (tmp_path / "sim")], check=True, capture_output=True)
    calib = tmp_path / "calib.yml"
    size = tuple(ev.EventCapture(str(recording)).getSensorSize())
    ev.writeStereoCalibration(str(calib), ev.StereoCalibration_fromRectified(size, 200.0, 0.1))
    py = tmp_path / "py"
    subprocess.run([sys.executable, str(SAMPLE), "--input=%s" % recording, "--truth=%s.gt.csv" % recording,
                    "--calib=%s" % calib, "--output=%s" % py], check=True, capture_output=True)
    rows, simulated = summary_rows(py), summary_rows(tmp_path / "sim")
    # The scene's planes at 10 and 20 px; the matching rate as event_stereo scores the scene in memory.
    assert rows["dominant disparity"].split()[0] in ("10", "20")
    rate = float(rows["ground truth: matching rate (left signal events within 1 px, over all of them)"].split()[0])
    assert abs(rate - float(simulated["ground truth: matching rate (left signal events within 1 px, over all of "
                                      "them)"].split()[0])) < 1.0 and rate > 90
    assert len(list(py.glob("depth_0*.png"))) == len(list(py.glob("disparity_0*.png"))) >= 2
