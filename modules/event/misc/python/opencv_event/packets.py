"""Recordings as Python iterables of event packets.

    for packet in ev.EventCapture("rec.aedat4"):       # 10 ms windows (EVENT_CAP_PROP_WINDOW_US)
        ...
    for packet in ev.packets("rec.raw", events=100000, progress=True):
        ...

A packet is an array of :data:`~opencv_event.records.EVENT_DTYPE` records, a view of what ``read()`` returned; the
package's calls take it as it is.
"""
import os
import sys
import time

from . import records as _records
from ._accept_records import forwarding_class


def _iterate(self, raw=False, progress=False):
    """Packets until the end of the source, as EVENT_DTYPE records (``raw=True``: as read() gives them, N x 1 x 16
    uint8). `progress`: a line on stderr, as the C++ samples print it."""
    report = _Progress(self.getSource()) if progress else None
    events = 0
    while True:
        ok, packet = self.native.read()
        if not ok:
            break
        events += packet.shape[0]
        if report:
            report.update(self.native.get(_constant("EVENT_CAP_PROP_PROGRESS")), events)
        yield packet if raw else _records.as_records(packet)
    if report:
        report.finish(self.native.get(_constant("EVENT_CAP_PROP_PROGRESS")), events)


def _event_capture():
    from . import _native
    return forwarding_class(_native.EventCapture, {"__iter__": lambda self: _iterate(self), "iterate": _iterate})


#: ``cv::event::EventCapture``, every method of the C++ class (open, read, get, set, retrieveTriggers, ...), that
#: also iterates: ``for packet in EventCapture(path)`` reads packets of EVENT_DTYPE records until the source ends.
EventCapture = _event_capture()


def packets(source, window_us=None, events=None, progress=False, raw=False, properties=None):
    """Iterates over a recording (any format EventCapture reads) in packets of `window_us` microseconds (default
    EventCapture's 10 ms) or of `events` events. `properties`: {EVENT_CAP_PROP_...: value} set before opening
    (e.g. the text format's columns). A generator: the first packet asked for opens the source, and raises ev.error
    naming the file and the problem when it cannot be read."""
    if window_us is not None and events is not None:
        raise ValueError("packets: give window_us or events, not both")
    cap = EventCapture()
    for prop, value in (properties or {}).items():
        cap.set(prop, value)
    if not cap.open(os.fspath(source)):
        raise OSError("packets: cannot open %s: %s" % (source, cap.getLastError()))
    if window_us is not None:
        cap.set(_constant("EVENT_CAP_PROP_WINDOW_US"), window_us)
    if events is not None:
        cap.set(_constant("EVENT_CAP_PROP_BATCH_EVENTS"), events)
    try:
        yield from cap.iterate(raw=raw, progress=progress)
    finally:
        cap.release()


def _constant(name):
    from . import _native
    return getattr(_native, name)


class _Progress:
    """The C++ samples' progress line: redrawn in place on a terminal at most five times a second, a line at most
    every five seconds into a log."""

    def __init__(self, source):
        self.source = source
        self.terminal = sys.stderr.isatty()
        self.last = None

    def update(self, fraction, events):
        now = time.monotonic()
        if self.last is not None and now - self.last < (0.2 if self.terminal else 5.0):
            return
        self.last = now
        self._print(fraction, events)

    def finish(self, fraction, events):
        self._print(fraction, events)
        if self.terminal:
            sys.stderr.write("\n")

    def _print(self, fraction, events):
        bar = ""
        if fraction >= 0:
            filled = round(min(1.0, fraction) * 30)
            bar = "[%s%s] %d %%, " % ("#" * filled, "." * (30 - filled), round(min(1.0, fraction) * 100))
        text = "%s: %d events" % (self.source, events)
        sys.stderr.write(("\r%s%s   " if self.terminal else "%s%s\n") % (bar, text))
        sys.stderr.flush()
