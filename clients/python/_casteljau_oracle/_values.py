"""Numbers in and out: every input sent exactly, every answer read back exactly.

Inputs may be Python numbers, `Fraction`s, `Decimal`s, exact strings, numpy scalars of any
numeric dtype, and nested lists, tuples or numpy arrays of them. numpy is never imported
here: an array is recognised by its `tolist`, a numpy scalar by the number classes it
registers with (`numbers.Integral` for int64, `numbers.Real` for float32).
"""

import math
import numbers
from decimal import Decimal
from fractions import Fraction

from .errors import OracleError, OracleInputError


def _as_list(x):
    """A numpy array (or anything with `tolist`) as nested lists; anything else as it is."""
    tolist = getattr(x, "tolist", None)
    if tolist is not None and not isinstance(x, (numbers.Number, str)):
        return tolist()
    return x


def is_scalar(x):
    """Whether `x` is one number (a numpy scalar too), not a list or array of them."""
    return isinstance(x, (str, numbers.Number, Decimal)) or not hasattr(x, "__iter__")


def _exact_fraction(x):
    """The exact value of a real number that is neither an int nor a Fraction."""
    if isinstance(x, Decimal):
        if not x.is_finite():
            raise OracleInputError(f"{x} is no input (send it as an answer, in approx)")
        return Fraction(x)
    ratio = getattr(x, "as_integer_ratio", None)
    if ratio is None:
        raise OracleInputError(f"not a number the client can send exactly: {x!r}")
    try:
        p, q = ratio()
    except (OverflowError, ValueError):
        raise OracleInputError(f"{x} is no input (send it as an answer, in approx)") from None
    return Fraction(p, q)


def number(x):
    """A number as the oracle reads it exactly: a JSON integer, a JSON number meaning that
    float, or an exact string "p/q"."""
    if isinstance(x, bool) or x is None:
        raise OracleInputError(f"a number, not {x!r}")
    if isinstance(x, str):
        return x
    if isinstance(x, numbers.Integral):
        return int(x)
    if isinstance(x, numbers.Rational):
        q = Fraction(int(x.numerator), int(x.denominator))
        return str(q.numerator) if q.denominator == 1 else f"{q.numerator}/{q.denominator}"
    if isinstance(x, Decimal):
        return number(_exact_fraction(x))
    if isinstance(x, numbers.Real):
        try:
            f = float(x)
        except (OverflowError, ValueError):
            f = None
        if f is not None and math.isnan(f):
            raise OracleInputError("NaN is no input (send it as an answer, in approx)")
        if f is not None and math.isfinite(f) and f == x:
            return f  # a JSON number is exactly that float
        return number(_exact_fraction(x))  # a longdouble beyond f64: exactly, as a fraction
    raise OracleInputError(f"not a number: {_short(x)}")


def _short(x):
    s = repr(x)
    return s if len(s) <= 40 else s[:20] + "…" + s[-10:] + f" ({len(s)} characters)"


def answer(x):
    """A float answer: a JSON number, or "inf", "-inf", "nan". It must be a float exactly
    (an int, Fraction or float32 that is one is taken)."""
    if isinstance(x, (bool, str)) or x is None:
        raise OracleInputError(f"a float answer, not {_short(x)}")
    try:
        f = float(x)
    except OverflowError:
        raise OracleInputError(
            f"the answer {_short(x)} is beyond the largest float: a float computation gives inf (send math.inf)"
        ) from None
    except (TypeError, ValueError):
        raise OracleInputError(f"a float answer, not {_short(x)}") from None
    if math.isnan(f):
        return "nan"
    if f != x:
        raise OracleInputError(f"the answer {_short(x)} is not a float (the nearest is {f!r})")
    if math.isinf(f):
        return "inf" if f > 0 else "-inf"
    return f


def points(pts):
    """Control points: a sequence (or array) of points, each a sequence of coordinates."""
    pts = _as_list(pts)
    if isinstance(pts, (str, numbers.Number)) or not hasattr(pts, "__iter__"):
        raise OracleInputError(f"points must be a list of points, not {pts!r}")
    return [coordinates(p, "a point") for p in pts]


def coordinates(p, what="approx"):
    """One point's coordinates (or an answer's), as exact numbers."""
    p = _as_list(p)
    if isinstance(p, (str, numbers.Number)) or not hasattr(p, "__iter__"):
        raise OracleInputError(f"{what} must be a list of coordinates, not {p!r}")
    return [number(c) for c in p]


def answers(p):
    """One float answer per coordinate."""
    p = _as_list(p)
    if isinstance(p, (str, numbers.Number)) or not hasattr(p, "__iter__"):
        raise OracleInputError(f"approx must be a list of one float per coordinate, not {p!r}")
    return [answer(c) for c in p]


def parameters(ts):
    """A list (or array) of parameters."""
    ts = _as_list(ts)
    if isinstance(ts, (str, numbers.Number)) or not hasattr(ts, "__iter__"):
        raise OracleInputError(f"expected a list of parameters, not {ts!r}")
    return [number(t) for t in ts]


def json_default(x):
    """`json.dumps`' `default`: a number JSON does not know (a numpy scalar, a Fraction, a
    Decimal) exactly, an array as nested lists; anything else is refused."""
    if isinstance(x, (numbers.Number, Decimal)):
        return number(x)
    converted = _as_list(x)
    if converted is not x:
        return converted
    raise TypeError(f"{type(x).__name__} is not a number or a list")


# -- answers back -------------------------------------------------------------------


def field(a, name, why=""):
    """The answer's field `name`, or an OracleError saying it is absent and why."""
    try:
        return a[name]
    except (KeyError, TypeError):
        raise OracleError(f"the oracle's answer has no {name!r}{why}") from None


def fraction(s):
    try:
        return Fraction(s)
    except (TypeError, ValueError, ZeroDivisionError):
        raise OracleError(f"not an exact number in the oracle's answer: {s!r}") from None


def to_float(v):
    """A JSON number or the strings "inf", "-inf", "nan" as a float."""
    try:
        return float(v)
    except (TypeError, ValueError):
        raise OracleError(f"not a number in the oracle's answer: {v!r}") from None


def ulps_count(v):
    """`ulps`: an int, a decimal string beyond 2^53, or "nan" (None)."""
    if v == "nan":
        return None
    try:
        return int(v)
    except (TypeError, ValueError):
        raise OracleError(f"not a count of ulps in the oracle's answer: {v!r}") from None
