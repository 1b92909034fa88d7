"""Events and trigger events as NumPy structured records.

The module's C++ calls take and give events as N x 1 arrays of 16-byte records (``uint8``, shape (N, 1, 16)):
``cv::event::Event``, t (int64, us), x, y (int16), p (0 = OFF, 1 = ON), camera (0 = left, 1 = right) and two
reserved bytes. :data:`EVENT_DTYPE` is that record as a NumPy structured type, so the two layouts are views of the
same memory: :func:`as_records` and :func:`as_packet` convert without a copy. The ``from_*`` converters copy the
layouts other tools use into records.
"""
import numpy as np

#: One event, as ``cv::event::Event`` lays it out: 16 bytes.
EVENT_DTYPE = np.dtype({"names": ["t", "x", "y", "p", "camera"],
                        "formats": ["<i8", "<i2", "<i2", "u1", "u1"],
                        "offsets": [0, 8, 10, 12, 13], "itemsize": 16})

#: One trigger event, as ``cv::event::EventTrigger`` lays it out (kind: see ``getTriggerKindName``): 16 bytes.
TRIGGER_DTYPE = np.dtype({"names": ["t", "channel", "kind", "camera"],
                          "formats": ["<i8", "<i2", "u1", "u1"],
                          "offsets": [0, 8, 10, 11], "itemsize": 16})


def _same_fields(a, dtype):
    """Records with `dtype`'s fields in another layout: NumPy packs them (drops the record's padding) when it
    concatenates or promotes structured arrays."""
    return a.dtype.names == dtype.names and all(a.dtype[n] == dtype[n] for n in dtype.names)


def _relaid(a, dtype):
    out = np.empty(a.shape, dtype)
    for name in dtype.names:
        out[name] = a[name]
    return out


def _view(array, dtype, what, dtype_name):
    a = np.asarray(array)
    if a.dtype == dtype:
        return a.reshape(-1)
    if _same_fields(a, dtype):
        return _relaid(a, dtype).reshape(-1)
    if a.dtype != np.uint8 or a.size % 16 != 0 or (a.ndim > 0 and a.shape[-1] != 16):
        raise ValueError("%s: expected %s records (see from_columns and the from_* converters) or a uint8 array of "
                         "16-byte records (N x 1 x 16), got %s %s" % (what, dtype_name, a.dtype, a.shape))
    return np.ascontiguousarray(a).reshape(-1, 16).view(dtype).reshape(-1)


def as_records(packet):
    """The events of `packet` (what the module's calls return: uint8, N x 1 x 16) as :data:`EVENT_DTYPE` records,
    a view of the same memory (a copy only where `packet` is not contiguous). Records are returned as they are
    (records in NumPy's packed layout, as np.concatenate gives them, are copied into the 16-byte one)."""
    return _view(packet, EVENT_DTYPE, "events", "EVENT_DTYPE")


def as_trigger_records(packet):
    """The trigger events of `packet` (``EventCapture.retrieveTriggers``) as :data:`TRIGGER_DTYPE` records, a view."""
    return _view(packet, TRIGGER_DTYPE, "trigger events", "TRIGGER_DTYPE")


def as_packet(events):
    """`events` (:data:`EVENT_DTYPE` records, or already a packet) as the N x 1 x 16 uint8 array the module's calls
    take: a view of the same memory (a copy only where the records are not contiguous or in NumPy's packed layout,
    as np.concatenate gives them)."""
    return np.ascontiguousarray(as_records(events)).view(np.uint8).reshape(-1, 1, 16)


def from_columns(t, x, y, p, camera=0):
    """Records from columns: t in us, x and y in pixels, p > 0 for ON (0 or -1 for OFF), camera 0 (left) or 1."""
    t = np.asarray(t)
    records = np.zeros(t.shape[0] if t.ndim else 1, EVENT_DTYPE)
    for name, column in (("t", t), ("x", x), ("y", y)):
        records[name] = _exact(column, EVENT_DTYPE[name], name)
    records["p"] = np.asarray(p).reshape(-1) > 0 if np.ndim(p) else p > 0
    records["camera"] = _exact(camera, EVENT_DTYPE["camera"], "camera")
    return records


def to_columns(events):
    """Columns t, x, y, p, camera (copies) of records or a packet."""
    r = as_records(events)
    return r["t"].copy(), r["x"].copy(), r["y"].copy(), r["p"].copy(), r["camera"].copy()


def from_dv(events, camera=0):
    """Records from dv-processing's event arrays (``EventStore.numpy()``: ``timestamp`` us, ``x``, ``y``,
    ``polarity``)."""
    return from_columns(events["timestamp"], events["x"], events["y"], events["polarity"], camera)


def from_metavision(events, camera=0):
    """Records from Metavision / OpenEB ``EventCD`` arrays (``x``, ``y``, ``p``, ``t`` us)."""
    return from_columns(events["t"], events["x"], events["y"], events["p"], camera)


def from_tonic(events, camera=0):
    """Records from tonic's event arrays (``x``, ``y``, ``t`` us, ``p``)."""
    return from_columns(events["t"], events["x"], events["y"], events["p"], camera)


def _exact(column, dtype, name):
    """`column` as `dtype`, refusing values that the record's field cannot hold (a silent wrap would move events)."""
    c = np.asarray(column).reshape(-1) if np.ndim(column) else np.asarray(column)
    if c.dtype.kind == "f":
        if not np.all(np.isfinite(c)) or np.any(c != np.round(c)):
            raise ValueError("%s: whole numbers expected" % name)
    info = np.iinfo(dtype)
    if c.size and (c.min() < info.min or c.max() > info.max):
        raise ValueError("%s: values outside %s (%d..%d)" % (name, dtype, info.min, info.max))
    return c.astype(dtype)
