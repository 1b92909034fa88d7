"""opencv_event: event cameras in OpenCV, from Python.

    import opencv_event as ev

gives the module's whole wrapped C++ API (the names of ``cv2.event`` in an OpenCV build with this module) plus
NumPy event records (:mod:`opencv_event.records`) and iteration over recordings (:mod:`opencv_event.packets`).
It works in both build modes: the standalone build ships the wrapped API in ``opencv_event._bindings`` (OpenCV's
binding generator run on the module's headers); inside an OpenCV build with this module the package takes it
from ``cv2.event``.
"""
import importlib.util as _importlib_util
import sys as _sys

# Both builds register their API as the module "cv2.event": where one is loaded already (an OpenCV build with this
# module imported before, or this package's own extension), it is taken; loading the other as well would add to it.
_loaded = _sys.modules.get("cv2.event")
_own = _sys.modules.get(__name__ + "._bindings")
if _loaded is None and _importlib_util.find_spec(__name__ + "._bindings") is not None:
    from . import _bindings as _own  # standalone build
    _native, error = _own.event, _own.error
elif _loaded is not None and _own is not None and _loaded is _own.event:
    _native, error = _loaded, _own.error
else:
    try:
        import cv2 as _cv2
        _native, error = _cv2.event, _cv2.error
    except (ImportError, AttributeError) as _error:
        import glob as _glob
        import os as _os
        import sysconfig as _sysconfig
        _built = sorted(_os.path.basename(f) for f in _glob.glob(_os.path.join(_os.path.dirname(__file__), "_bindings*")))
        raise ImportError(
            "opencv_event: neither this package's own bindings (the standalone build) nor cv2.event (an OpenCV build "
            "with the event module) are there: build or install one of them" +
            ("; this package's extension (%s) was built for another Python than this one (%s, %s)"
             % (", ".join(_built), _sys.executable, _sysconfig.get_config_var("EXT_SUFFIX")) if _built else "")) from _error

from .records import (EVENT_DTYPE, TRIGGER_DTYPE, as_packet, as_records, as_trigger_records,  # noqa: E402
                      from_columns, from_dv, from_metavision, from_tonic, to_columns)
from .packets import EventCapture, packets  # noqa: E402
from ._accept_records import accepting_records as _accepting_records, forwarding_class as _forwarding_class  # noqa: E402

# The wrapped API, each call taking records wherever it takes events (see _accept_records).
for _name in dir(_native):
    if _name.startswith("__") or _name == "EventCapture":
        continue
    _value = getattr(_native, _name)
    if isinstance(_value, type):
        _value = _forwarding_class(_value)
    elif callable(_value):
        _value = _accepting_records(_value)
    globals()[_name] = _value
from ._version import __version__  # noqa: E402  (written by either build)
