"""Every wrapped call takes events as records too.

OpenCV's bindings turn a NumPy array into a Mat only for plain number types, so a structured EVENT_DTYPE array
would be refused where the C++ call takes a packet. The package therefore hands the wrapped API on through thin
layers that pass every argument that is an array of records as its packet view (no copy) and leave everything else
as it is: functions are wrapped, and each wrapped class gets a class of the same name that holds the C++ object and
forwards to it (OpenCV 4.6's wrapped types cannot be subclassed from Python: their deallocator frees a subclass's
instance at the wrong address). Objects that calls return come back as those classes, so their methods take records
as well.
"""
import functools

import numpy as np

from . import records as _records

_forwarding_classes = {}  # native type -> its forwarding class


def _argument(value):
    if isinstance(value, np.ndarray) and value.dtype.names == _records.EVENT_DTYPE.names:
        return _records.as_packet(value)
    if isinstance(value, Forwarding):
        return value.native
    if isinstance(value, (list, tuple)) and any(isinstance(v, (np.ndarray, Forwarding)) for v in value):
        return type(value)(_argument(v) for v in value)
    return value


def _result(value):
    cls = _forwarding_classes.get(type(value))
    if cls is not None:
        return cls._wrap(value)
    if isinstance(value, (tuple, list)):
        return type(value)(_result(v) for v in value)
    return value


def accepting_records(function):
    """`function` taking records wherever it takes events, and giving forwarding objects for wrapped ones."""
    @functools.wraps(function)
    def call(*args, **kwargs):
        return _result(function(*[_argument(a) for a in args], **{k: _argument(v) for k, v in kwargs.items()}))
    return call


class _ForwardingType(type):
    """Class attributes (static methods such as ``create``, constants) come from the wrapped type."""

    def __getattr__(cls, name):
        native_type = cls.__dict__.get("_native_type")
        if native_type is None:
            raise AttributeError(name)
        value = getattr(native_type, name)
        return accepting_records(value) if callable(value) and not isinstance(value, type) else value

    def __dir__(cls):
        native_type = cls.__dict__.get("_native_type")
        return sorted(set(super().__dir__()) | (set(dir(native_type)) if native_type is not None else set()))


class Forwarding(metaclass=_ForwardingType):
    """Holds one wrapped C++ object (``native``) and forwards every attribute to it."""

    __slots__ = ("native",)

    def __init__(self, *args, **kwargs):
        from . import error
        try:
            native = self._native_type(*[_argument(a) for a in args], **{k: _argument(v) for k, v in kwargs.items()})
        except SystemError as failure:
            # OpenCV 4.6's generated constructors report a C++ exception as a SystemError whose cause is the
            # cv2.error that names the file and the problem: raise that one.
            if isinstance(failure.__cause__, error):
                raise failure.__cause__ from None
            raise
        object.__setattr__(self, "native", native)

    @classmethod
    def _wrap(cls, native):
        self = cls.__new__(cls)
        object.__setattr__(self, "native", native)
        return self

    def __getattr__(self, name):
        if name == "native":  # the constructor failed
            raise AttributeError(name)
        value = getattr(self.native, name)
        return accepting_records(value) if callable(value) else value

    def __setattr__(self, name, value):
        setattr(self.native, name, _argument(value))

    def __dir__(self):
        # Tab completion and help() list the C++ object's methods too.
        return sorted(set(super().__dir__()) | set(dir(self.native)))

    def __repr__(self):
        return "<opencv_event.%s %r>" % (type(self).__name__, self.native)


def forwarding_class(native_type, namespace=None):
    """The forwarding class of `native_type` (made once), with the wrapped bases' forwarding classes as bases."""
    cls = _forwarding_classes.get(native_type)
    if cls is None:
        bases = tuple(forwarding_class(b) for b in native_type.__bases__ if b is not object) or (Forwarding,)
        attributes = dict(namespace or {}, _native_type=native_type, __slots__=(), __doc__=native_type.__doc__)
        cls = _ForwardingType(native_type.__name__, bases, attributes)
        _forwarding_classes[native_type] = cls
    return cls
