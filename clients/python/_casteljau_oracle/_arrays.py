"""numpy arrays out, when numpy is there and wanted; lists otherwise.

numpy is imported only when an array is to be made: the client works without it.
"""

from .errors import OracleError


def numpy():
    """The numpy module, or an OracleError saying it is needed."""
    try:
        import numpy as np
    except ImportError:
        raise OracleError("arrays=True needs numpy (pip install numpy)") from None
    return np


def is_array(x):
    """Whether `x` is a numpy array (without importing numpy)."""
    return type(x).__module__ == "numpy" and type(x).__name__ == "ndarray"


def exact(rows):
    """Exact values (Fractions in nested lists) as an object array of the same shape (numpy
    would otherwise read a Fraction as a float)."""
    np = numpy()
    shape = []
    probe = rows
    while isinstance(probe, list):
        shape.append(len(probe))
        probe = probe[0] if probe else None
    out = np.empty(tuple(shape), dtype=object)
    for index in np.ndindex(*shape):
        v = rows
        for i in index:
            v = v[i]
        out[index] = v
    return out


def floats(rows):
    """Floats (None as NaN) as a float64 array."""
    np = numpy()
    return np.array(_none_as_nan(rows), dtype=np.float64)


def _none_as_nan(rows):
    if isinstance(rows, list):
        return [_none_as_nan(r) for r in rows]
    return float("nan") if rows is None else rows


def bools(rows):
    np = numpy()
    return np.array(rows, dtype=bool)


#: how each field of a judgement becomes an array
_FIELDS = {
    "point": exact,
    "points": exact,
    "ulps": floats,
    "error_ulps": floats,
    "nearest": floats,
    "bound": floats,
    "condition": floats,
    "within_bound": bools,
}


def judgement(j):
    """A judgement (or a list of them, one per parameter, stacked on a first axis) with
    each numeric field as an array; `verdict` stays a list."""
    if isinstance(j, list):
        if not j:
            return {}
        stacked = {k: [x[k] for x in j] for k in j[0]}
        return {k: (_FIELDS[k](v) if k in _FIELDS else v) for k, v in stacked.items()}
    return {k: (_FIELDS[k](v) if k in _FIELDS else v) for k, v in j.items()}
