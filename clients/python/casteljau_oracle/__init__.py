"""A client for `casteljau oracle`: exact Bézier answers and float error bounds.

The oracle reads one JSON request per line and answers each with one line, flushed
before it reads on. `Oracle` starts it, sends requests and reads the answers; many
requests at once are written by a second thread while this one reads, so neither side
ever waits on a full pipe.

    with Oracle() as o:
        o.eval_exact([[0, 0], [1, 2], [2, 0]], Fraction(1, 3))   # [Fraction(2, 3), Fraction(8, 9)]
        o.within_bound([[0.1], [0.7]], 0.5, [0.4])                # True

Numbers go out exactly: a float as the JSON number that reads back as that float, a
`Fraction` or `int` exactly, a float answer that is inf or NaN as "inf", "-inf", "nan".
Exact results come back as `Fraction`s.
"""

import json
import math
import os
import shutil
import subprocess
import threading
from fractions import Fraction

__all__ = ["Oracle", "OracleError", "find_binary", "METHODS"]

#: the float algorithms the oracle has a bound for (`method`)
METHODS = ("de_casteljau", "lerp", "horner", "bernstein", "compensated")


class OracleError(Exception):
    """The oracle answered a request with an error (its message), or stopped."""


def find_binary(binary=None):
    """The casteljau executable: `binary`, else $CASTELJAU_BIN, else `casteljau` on PATH."""
    path = binary or os.environ.get("CASTELJAU_BIN") or shutil.which("casteljau")
    if not path:
        raise OracleError("casteljau not found: pass binary=, set CASTELJAU_BIN or put it on PATH")
    return path


def _number(x):
    """A number as the oracle reads it exactly."""
    if isinstance(x, bool):
        raise TypeError("a number, not a bool")
    if isinstance(x, int):
        return x
    if isinstance(x, Fraction):
        return str(x.numerator) if x.denominator == 1 else f"{x.numerator}/{x.denominator}"
    if isinstance(x, float):
        if math.isnan(x):
            raise ValueError("NaN is no input (send it as an answer, in approx)")
        if math.isinf(x):
            raise ValueError(f"{x} is no input (send it as an answer, in approx)")
        return x
    if isinstance(x, str):
        return x
    raise TypeError(f"not a number: {x!r}")


def _answer(x):
    """A float answer: a JSON number, or "inf", "-inf", "nan"."""
    x = float(x)
    if math.isnan(x):
        return "nan"
    if math.isinf(x):
        return "inf" if x > 0 else "-inf"
    return x


def _points(points):
    return [[_number(c) for c in p] for p in points]


def _fraction(s):
    return Fraction(s)


def _float(v):
    """A JSON number or the strings "inf", "-inf", "nan" as a float."""
    return float(v)


def _ulps(v):
    """`ulps`: an int, a decimal string beyond 2^53, or "nan" (None)."""
    if v == "nan":
        return None
    return int(v)


class Oracle:
    """A running `casteljau oracle` process."""

    def __init__(self, binary=None, args=()):
        self.binary = find_binary(binary)
        self._proc = subprocess.Popen(
            [self.binary, "oracle", *args],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            text=True,
            encoding="utf-8",
            bufsize=1,
        )
        self._lock = threading.Lock()

    def close(self):
        """Ends the oracle (end of input) and waits for it."""
        if self._proc.poll() is None:
            try:
                self._proc.stdin.close()
            except BrokenPipeError:
                pass
            self._proc.wait(timeout=30)
        self._proc.stdout.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    # -- the protocol ---------------------------------------------------------------

    def _read(self):
        line = self._proc.stdout.readline()
        if not line:
            raise OracleError(f"the oracle stopped (exit status {self._proc.poll()})")
        return json.loads(line)

    def requests(self, reqs, check=True):
        """Sends many requests and returns their answers, in order. A writer thread feeds
        the oracle while this thread reads, so any number and size of requests is safe."""
        lines = [json.dumps(r, allow_nan=False) + "\n" for r in reqs]
        with self._lock:
            failure = []

            def write():
                try:
                    for line in lines:
                        self._proc.stdin.write(line)
                    self._proc.stdin.flush()
                except (BrokenPipeError, OSError) as e:  # the reader reports the stop
                    failure.append(e)

            writer = threading.Thread(target=write, daemon=True)
            writer.start()
            answers = [self._read() for _ in lines]
            writer.join()
        if check:
            for a in answers:
                if not a.get("ok"):
                    raise OracleError(a.get("error", "unknown error"))
        return answers

    def request(self, req, check=True):
        """Sends one request (a dict with "op" and its fields) and returns the answer."""
        return self.requests([req], check=check)[0]

    # -- exact values ---------------------------------------------------------------

    def eval_exact(self, points, t):
        """b(t) exactly, one Fraction per coordinate."""
        a = self.request({"op": "eval", "points": _points(points), "t": _number(t)})
        return [_fraction(c) for c in a["point"]]

    def eval_exact_batch(self, points, ts):
        """b(t) exactly at each t, one request."""
        a = self.request({"op": "eval", "points": _points(points), "t": [_number(t) for t in ts]})
        return [[_fraction(c) for c in r["point"]] for r in a["results"]]

    # -- judging float answers ------------------------------------------------------

    def judge(self, points, t, approx, method="de_casteljau"):
        """The oracle's verdict on a float answer `approx` (one float per coordinate) of
        the caller's `method`: a dict with `point` (Fractions), `ulps` (steps from the
        correctly rounded value; None for NaN), `error_ulps`, `nearest`, `bound` (ulps of
        the exact value), `within_bound`, `condition` (with a float t), and `verdict`
        (a sentence per coordinate when an answer is inf or NaN, else None)."""
        a = self.request(
            {
                "op": "eval",
                "points": _points(points),
                "t": _number(t),
                "approx": [_answer(x) for x in approx],
                "method": method,
            }
        )
        return _judgement(a)

    def judge_batch(self, points, ts, approxes, method="de_casteljau"):
        """`judge` at many parameters in one request (one approximation per t)."""
        a = self.request(
            {
                "op": "eval",
                "points": _points(points),
                "t": [_number(t) for t in ts],
                "approx": [[_answer(x) for x in ap] for ap in approxes],
                "method": method,
            }
        )
        return [_judgement(r) for r in a["results"]]

    def ulps(self, points, t, approx):
        """Per coordinate, how many floats `approx` is from the correctly rounded b(t)."""
        return self.judge(points, t, approx)["ulps"]

    def within_bound(self, points, t, approx, method="de_casteljau"):
        """Whether every coordinate of `approx` is within the a priori error bound of
        `method` (decided exactly)."""
        return all(self.judge(points, t, approx, method)["within_bound"])

    def bound(self, points, t, method="de_casteljau"):
        """The a priori error bound of `method` at a float t, in ulps of the exact value,
        per coordinate."""
        a = self.request({"op": "eval", "points": _points(points), "t": _number(t), "method": method})
        return [_float(b) for b in a["bound"]]

    def bound_batch(self, points, ts, method="de_casteljau"):
        """`bound` at many float parameters, one request."""
        a = self.request(
            {"op": "eval", "points": _points(points), "t": [_number(t) for t in ts], "method": method}
        )
        return [[_float(b) for b in r["bound"]] for r in a["results"]]


def _judgement(a):
    out = {"point": [_fraction(c) for c in a["point"]]}
    if "ulps" in a:
        out["ulps"] = [_ulps(u) for u in a["ulps"]]
        out["error_ulps"] = [_float(e) for e in a["error_ulps"]]
        out["nearest"] = [_float(e) for e in a["nearest"]]
        out["verdict"] = a.get("verdict", [None] * len(a["ulps"]))
    if "bound" in a:
        out["bound"] = [_float(b) for b in a["bound"]]
    if "within_bound" in a:
        out["within_bound"] = a["within_bound"]
    if "condition" in a:
        out["condition"] = [_float(c) for c in a["condition"]]
    return out
from .prove import prove_identity  # noqa: E402,F401  (after OracleError and find_binary, which it uses)
