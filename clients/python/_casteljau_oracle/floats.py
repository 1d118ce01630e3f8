"""`ulps(a, b)`: how many f64 values lie between two floats, without the oracle."""

import math
import struct

from ._arrays import is_array
from .errors import OracleInputError


def _ordinal(x):
    """The float's place in the ordered sequence of all f64 values (+0 and −0 both 0)."""
    (i,) = struct.unpack("<q", struct.pack("<d", x))
    return i if i >= 0 else -(i & 0x7FFFFFFFFFFFFFFF)


def _ulps_one(a, b):
    try:
        a, b = float(a), float(b)
    except (TypeError, ValueError, OverflowError):
        raise OracleInputError(f"ulps() takes floats, not {a!r} and {b!r}") from None
    if math.isnan(a) or math.isnan(b):
        return None
    return abs(_ordinal(a) - _ordinal(b))


def ulps(a, b):
    """The number of steps between the f64 values `a` and `b`: 0 when they are equal (+0
    and −0 are), 1 for neighbours, counting across zero and up to ±inf (the largest float
    and inf are 1 apart); None when either is NaN. Values are read as f64 (a float32 is
    widened exactly). Lists give lists, elementwise; numpy arrays give a float64 array
    (NaN for NaN), broadcast (exact up to 2^53 steps)."""
    if is_array(a) or is_array(b):
        import numpy as np

        x = np.asarray(a, dtype=np.float64)
        y = np.asarray(b, dtype=np.float64)
        x, y = np.broadcast_arrays(x, y)
        ix, iy = (_ordinals(v, np) for v in (x, y))
        ax, ay = np.abs(ix).astype(np.uint64), np.abs(iy).astype(np.uint64)
        # in uint64 neither the difference nor the sum (across zero) can overflow
        steps = np.where((ix >= 0) == (iy >= 0), np.maximum(ax, ay) - np.minimum(ax, ay), ax + ay)
        out = steps.astype(np.float64)
        out[np.isnan(x) | np.isnan(y)] = np.nan
        return out
    if isinstance(a, (list, tuple)) or isinstance(b, (list, tuple)):
        if not isinstance(a, (list, tuple)):
            a = [a] * len(b)
        if not isinstance(b, (list, tuple)):
            b = [b] * len(a)
        if len(a) != len(b):
            raise OracleInputError(f"ulps() of lists of lengths {len(a)} and {len(b)}")
        return [ulps(x, y) for x, y in zip(a, b)]
    return _ulps_one(a, b)


def _ordinals(x, np):
    i = x.view(np.int64)
    return np.where(i >= 0, i, -(i & np.int64(0x7FFFFFFFFFFFFFFF)))
