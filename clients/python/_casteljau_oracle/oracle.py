"""`Oracle`: a running `casteljau oracle` and the requests a float test needs."""

import itertools
import json
import os
import shutil
import threading

from . import _values as V
from ._channel import Channel
from .errors import OracleError, OracleInputError

#: the float algorithms the oracle has a bound for (`method`)
METHODS = ("de_casteljau", "lerp", "horner", "bernstein", "compensated")

#: seconds the client waits for any one answer unless told otherwise: eight times the
#: oracle's work limit per request (half a second, docs/limits.md)
DEFAULT_TIMEOUT = 4.0

_ABSENT = object()


def find_binary(binary=None):
    """The casteljau executable: `binary`, else $CASTELJAU_BIN, else `casteljau` on PATH."""
    path = binary or os.environ.get("CASTELJAU_BIN") or shutil.which("casteljau")
    if not path:
        raise OracleError("casteljau not found: pass binary=, set CASTELJAU_BIN or put it on PATH")
    return os.fspath(path)


class Oracle:
    """A running `casteljau oracle` process.

    `timeout` is the longest the client waits for any one answer, in seconds (None: no
    limit); past it `OracleTimeout` is raised. After a timeout, an answer out of step or an
    exception in the caller's thread during an exchange (KeyboardInterrupt, an alarm), the
    process is ended and the next request starts a fresh one (`restarts` counts them), so
    an interrupted batch never leaves answers behind for the next call to read.
    """

    def __init__(self, binary=None, args=(), timeout=DEFAULT_TIMEOUT):
        self.binary = find_binary(binary)
        self.args = tuple(args)
        if timeout is not None and not timeout > 0:
            raise OracleInputError(f"timeout must be a positive number of seconds or None, not {timeout!r}")
        self.timeout = timeout
        self.restarts = 0
        self._ids = itertools.count(1)
        self._lock = threading.Lock()
        self._closed = False
        self._channel = self._start()

    def _start(self):
        channel = Channel([self.binary, "oracle", *self.args])
        self._proc = channel.proc  # the latest process, for a test that signals it
        return channel

    def close(self):
        """Ends the oracle (end of input) and waits for it."""
        with self._lock:
            self._closed = True
            channel, self._channel = self._channel, None
            if channel is not None:
                channel.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    # -- the protocol ---------------------------------------------------------------

    def requests(self, reqs, check=True):
        """Sends many requests (dicts with "op" and its fields) and returns their answers,
        in order. Any number and size of requests is safe (a writer thread feeds the
        oracle while this thread reads). The client numbers the requests with its own
        `id`s and checks each answer's; a request's own `id` is given back in its answer.
        With `check`, an error answer raises `OracleError` with the oracle's message."""
        lines, ids, own_ids = [], [], []
        for r in reqs:
            if not isinstance(r, dict):
                raise OracleInputError(f"a request is a dict with an 'op', not {r!r}")
            i = next(self._ids)
            try:
                line = json.dumps({"id": i, **{k: v for k, v in r.items() if k != "id"}}, allow_nan=False)
            except (TypeError, ValueError) as e:
                raise OracleInputError(f"the request cannot be sent as JSON ({e}): {r!r}"[:300]) from None
            lines.append(line.encode("utf-8") + b"\n")
            ids.append(i)
            own_ids.append(r.get("id", _ABSENT))
        with self._lock:
            if self._closed:
                raise OracleError("this Oracle was closed")
            channel = self._channel
            if channel is None:
                channel = self._channel = self._start()
                self.restarts += 1
            try:
                answers = channel.exchange(lines, ids, self.timeout)
            except BaseException:
                # whatever stopped the exchange, answers may still come: none may be read
                self._channel = None
                channel.kill()
                raise
        for a, own in zip(answers, own_ids):
            if own is _ABSENT:
                del a["id"]
            else:
                a["id"] = own
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
        a = self.request({"op": "eval", "points": V.points(points), "t": V.number(t)})
        return [V.fraction(c) for c in V.field(a, "point")]

    def eval_exact_batch(self, points, ts):
        """b(t) exactly at each t, one request."""
        a = self.request({"op": "eval", "points": V.points(points), "t": V.parameters(ts)})
        return [[V.fraction(c) for c in V.field(r, "point")] for r in V.field(a, "results")]

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
                "points": V.points(points),
                "t": V.number(t),
                "approx": V.answers(approx),
                "method": method,
            }
        )
        return _judgement(a)

    def judge_batch(self, points, ts, approxes, method="de_casteljau"):
        """`judge` at many parameters in one request (one approximation per t)."""
        a = self.request(
            {
                "op": "eval",
                "points": V.points(points),
                "t": V.parameters(ts),
                "approx": [V.answers(ap) for ap in V._as_list(approxes)],
                "method": method,
            }
        )
        return [_judgement(r) for r in V.field(a, "results")]

    def ulps(self, points, t, approx):
        """Per coordinate, how many floats `approx` is from the correctly rounded b(t)."""
        return self.judge(points, t, approx)["ulps"]

    def within_bound(self, points, t, approx, method="de_casteljau"):
        """Whether every coordinate of `approx` is within the a priori error bound of
        `method` (decided exactly)."""
        return all(V.field(self.judge(points, t, approx, method), "within_bound", _NO_BOUND))

    def bound(self, points, t, method="de_casteljau"):
        """The a priori error bound of `method` at a float t, in ulps of the exact value,
        per coordinate."""
        a = self.request({"op": "eval", "points": V.points(points), "t": V.number(t), "method": method})
        return [V.to_float(b) for b in V.field(a, "bound", _NO_BOUND)]

    def bound_batch(self, points, ts, method="de_casteljau"):
        """`bound` at many float parameters, one request."""
        a = self.request({"op": "eval", "points": V.points(points), "t": V.parameters(ts), "method": method})
        return [[V.to_float(b) for b in V.field(r, "bound", _NO_BOUND)] for r in V.field(a, "results")]


_NO_BOUND = ": a bound is given only where t (and every input) is a float exactly"


def _judgement(a):
    out = {"point": [V.fraction(c) for c in V.field(a, "point")]}
    if "ulps" in a:
        out["ulps"] = [V.ulps_count(u) for u in a["ulps"]]
        out["error_ulps"] = [V.to_float(e) for e in V.field(a, "error_ulps")]
        out["nearest"] = [V.to_float(e) for e in V.field(a, "nearest")]
        out["verdict"] = a.get("verdict", [None] * len(a["ulps"]))
    if "bound" in a:
        out["bound"] = [V.to_float(b) for b in a["bound"]]
    if "within_bound" in a:
        out["within_bound"] = a["within_bound"]
    if "condition" in a:
        out["condition"] = [V.to_float(c) for c in a["condition"]]
    return out
