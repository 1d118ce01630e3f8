"""A client for `casteljau oracle`: exact Bézier answers and float error bounds.

The oracle reads one JSON request per line and answers each with one line, flushed
before it reads on. `Oracle` starts it, sends requests and reads the answers; many
requests at once are written by a second thread while this one reads, so neither side
ever waits on a full pipe. Every request carries an id and every answer is checked
against it; a wait for an answer times out (`Oracle(timeout=...)`).

    with Oracle() as o:
        o.eval_exact([[0, 0], [1, 2], [2, 0]], Fraction(1, 3))   # [Fraction(2, 3), Fraction(8, 9)]
        o.within_bound([[0.1], [0.7]], 0.5, [0.4])                # True

Numbers go out exactly: a float as the JSON number that reads back as that float, a
`Fraction` or `int` exactly, a float answer that is inf or NaN as "inf", "-inf", "nan".
Exact results come back as `Fraction`s; inputs may be numpy arrays of any numeric dtype,
and results are numpy arrays when they are (or with `Oracle(arrays=True)`). Every error
the client raises is an `OracleError`.
"""

from .errors import OracleError, OracleInputError, OracleProtocolError, OracleTimeout
from .floats import ulps
from .oracle import DEFAULT_TIMEOUT, METHODS, Oracle, find_binary
from .pool import OraclePool


def assert_within_bound(oracle, points, t, approx, method="de_casteljau"):
    """`oracle.assert_within_bound(points, t, approx, method)`: an AssertionError, when
    `approx` is outside `method`'s bound, that gives per coordinate the answer, the
    correctly rounded value, ulps, the bound, the condition number and the exact value."""
    oracle.assert_within_bound(points, t, approx, method)


__all__ = [
    "DEFAULT_TIMEOUT",
    "METHODS",
    "Oracle",
    "OracleError",
    "OracleInputError",
    "OraclePool",
    "OracleProtocolError",
    "OracleTimeout",
    "assert_within_bound",
    "find_binary",
    "ulps",
]
