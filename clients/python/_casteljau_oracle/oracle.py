"""`Oracle`: a running `casteljau oracle` and the requests a float test needs."""

import itertools
import json
import math
import os
import shutil
import threading

from . import _arrays as A
from . import _values as V
from ._channel import Channel
from ._report import within_bound_message
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
    try:
        return os.fspath(path)
    except TypeError:
        raise OracleInputError(f"binary is a path, not {path!r}") from None


class Oracle:
    """A running `casteljau oracle` process.

    Results are lists (of `Fraction`s, floats, bools), or numpy arrays of the same shape
    (object arrays of `Fraction`s for exact values) when `arrays` is True, or when it is
    None (the default) and the call's points (or net, or power coefficients) came as a
    numpy array.

    `timeout` is the longest the client waits for any one answer, in seconds (None: no
    limit); past it `OracleTimeout` is raised. After a timeout, an answer out of step or an
    exception in the caller's thread during an exchange (KeyboardInterrupt, an alarm), the
    process is ended and the next request starts a fresh one (`restarts` counts them), so
    an interrupted batch never leaves answers behind for the next call to read.
    """

    def __init__(self, binary=None, args=(), timeout=DEFAULT_TIMEOUT, arrays=None):
        self.binary = find_binary(binary)
        if arrays not in (None, True, False):
            raise OracleInputError(f"arrays is None (like the input), True or False, not {arrays!r}")
        if arrays:
            A.numpy()
        self.arrays = arrays
        self.args = tuple(args)
        if timeout is not None and not (
            isinstance(timeout, (int, float)) and not isinstance(timeout, bool) and 0 < timeout < math.inf
        ):
            raise OracleInputError(f"timeout must be a positive number of seconds or None, not {timeout!r}")
        self.timeout = timeout
        self.restarts = 0
        self._ids = itertools.count(1)
        self._lock = threading.Lock()
        self._closed = False
        self._killed = []
        self._channel = self._start()

    def _reap(self):
        while self._killed:
            self._killed.pop().reap()

    def _start(self):
        self._reap()
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
            self._reap()

    def __del__(self):
        try:
            self._reap()
        except Exception:  # noqa: BLE001 - nothing may escape a finaliser
            pass

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    # -- the protocol ---------------------------------------------------------------

    def requests(self, reqs, check=True):
        """Sends many requests (dicts with "op" and its fields) and returns their answers,
        in order. Any number and size of requests is safe (a writer thread feeds the
        oracle while this thread reads). numpy scalars and arrays, `Fraction`s and
        `Decimal`s in a request are sent exactly. The client numbers the requests with its
        own `id`s and checks each answer's; a request's own `id` is given back in its
        answer. With `check`, an error answer raises `OracleError` with its message."""
        lines, ids, own_ids = [], [], []
        for r in reqs:
            if not isinstance(r, dict):
                raise OracleInputError(f"a request is a dict with an 'op', not {r!r}")
            i = next(self._ids)
            try:
                body = {k: v for k, v in r.items() if k != "id"}
                line = json.dumps({"id": i, **body}, allow_nan=False, default=V.json_default)
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
                self._killed.append(channel)
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

    # -- results as lists or arrays ---------------------------------------------------

    def _arrays_for(self, given):
        return self.arrays if self.arrays is not None else A.is_array(given)

    def _exact(self, given, rows):
        return A.exact(rows) if self._arrays_for(given) else rows

    def _floats(self, given, rows):
        return A.floats(rows) if self._arrays_for(given) else rows

    def _judged(self, given, j):
        return A.judgement(j) if self._arrays_for(given) else j

    # -- exact values ---------------------------------------------------------------

    def eval_exact(self, points, t):
        """b(t) exactly, one Fraction per coordinate."""
        a = self.request({"op": "eval", "points": V.points(points), "t": V.number(t)})
        return self._exact(points, _fractions(V.field(a, "point")))

    def eval_exact_batch(self, points, ts):
        """b(t) exactly at each t, one request (one row per t)."""
        a = self.request({"op": "eval", "points": V.points(points), "t": V.parameters(ts)})
        return self._exact(points, [_fractions(V.field(r, "point")) for r in V.field(a, "results")])

    def elevate(self, points, by=1, approx=None, method=None):
        """The control points of the same curve at degree n + by, exactly; with `approx`
        (your elevated points) or `method` ("formula"), the judgement (see `_judge_points`)."""
        req = {"op": "elevate", "points": V.points(points), "by": V.number(by)}
        if approx is not None or method is not None:
            return self._judge_points(points, req, approx, method)
        return self._exact(points, _point_list(V.field(self.request(req), "points")))

    def split(self, points, t, approx=None, method=None):
        """The control points of b on [0, t] and on [t, 1], exactly: (left, right). With
        `approx` (your halves: a pair, or {"left": ..., "right": ...}) or `method`
        ("de_casteljau", "lerp"), the judgement: {"method", "left": {...}, "right": {...}},
        each half judged as `_judge_points` describes."""
        req = {"op": "split", "points": V.points(points), "t": V.number(t)}
        if approx is not None or method is not None:
            return self._judge_points(points, req, approx, method, split=True)
        a = self.request(req)
        left, right = (_point_list(V.field(a, k)) for k in ("left", "right"))
        return self._exact(points, left), self._exact(points, right)

    def derivative(self, points, order=1, t=None, approx=None, method=None):
        """The control points of the `order`-th derivative (degree n − order), or with `t`
        the derivative vector at t, exactly; with `approx` (your control points of the
        derivative) or `method` ("differences"), the judgement (see `_judge_points`)."""
        req = {"op": "derivative", "points": V.points(points), "order": V.number(order)}
        if t is not None:
            req["t"] = V.number(t)
            return self._exact(points, _fractions(V.field(self.request(req), "vector")))
        if approx is not None or method is not None:
            return self._judge_points(points, req, approx, method)
        return self._exact(points, _point_list(V.field(self.request(req), "points")))

    def to_bezier(self, power, approx=None, method=None):
        """The Bézier control points of the polynomial curve with power coefficients
        `power` (one list per coordinate, of the coefficients of t^0..t^n), exactly; with
        `approx` (your control points) or `method` ("formula"), the judgement."""
        rows = V._as_list(power)
        if not isinstance(rows, list):
            raise OracleInputError(f"power must be one list of coefficients per coordinate, not {power!r}")
        req = {"op": "to_bezier", "power": [V.coordinates(r, "a coordinate's coefficients") for r in rows]}
        if approx is not None or method is not None:
            return self._judge_points(power, req, approx, method)
        return self._exact(power, _point_list(V.field(self.request(req), "points")))

    def _judge_points(self, given, req, approx, method, split=False):
        """Sends `req` with `approx` and `method`; the judgement of a list of points: a dict
        with `points` (Fractions), and per point and coordinate `ulps`, `error_ulps`,
        `nearest`, `verdict` (with `approx`), `bound` (ulps of the exact value),
        `within_bound` (with `approx`) and `condition` (when the inputs are floats), plus
        `method`. For a split, {"method", "left": judgement, "right": judgement}. With
        arrays, each numeric field is an array of shape (points, coordinates)."""
        if method is not None:
            req["method"] = method
        if approx is not None:
            if split:
                halves = (approx["left"], approx["right"]) if isinstance(approx, dict) else tuple(approx)
                if len(halves) != 2:
                    raise OracleInputError("a split's approx is (left, right) or {'left': ..., 'right': ...}")
                req["approx"] = {"left": _answer_points(halves[0]), "right": _answer_points(halves[1])}
            else:
                req["approx"] = _answer_points(approx)
        a = self.request(req)
        keys = ("left", "right") if split else ("points",)
        groups = {k: self._judged(given, _points_judgement(a, k)) for k in keys}
        out = groups if split else groups["points"]
        out["method"] = V.field(a, "method")
        return out

    def rational_eval(self, points, weights, t):
        """The rational curve with `weights` at t, exactly, one Fraction per coordinate."""
        a = self.request(_rational(points, weights, t))
        return self._exact(points, _fractions(V.field(a, "point")))

    def surface_eval(self, net, u, v):
        """The tensor-product surface with control net `net` (rows of points) at (u, v),
        exactly, one Fraction per coordinate."""
        a = self.request(_surface(net, u, v))
        return self._exact(net, _fractions(V.field(a, "point")))

    def conic(self, points, weights):
        """The conic through a rational quadratic: (type, implicit coefficients
        [A, B, C, D, E, F] as Fractions, or None when the points are collinear)."""
        a = self.request({"op": "conic", "points": V.points(points), "weights": V.coordinates(weights, "weights")})
        implicit = V.field(a, "implicit")
        return V.field(a, "type"), (None if implicit is None else _fractions(implicit))

    # -- judging float answers ------------------------------------------------------

    def judge(self, points, t, approx, method="de_casteljau"):
        """The oracle's verdict on a float answer `approx` (one float per coordinate) of
        the caller's `method`: a dict with `point` (Fractions), `ulps` (steps from the
        correctly rounded value; None for NaN), `error_ulps`, `nearest`, `bound` (ulps of
        the exact value), `within_bound`, `condition` (with a float t), and `verdict`
        (a sentence per coordinate when an answer is inf or NaN, else None)."""
        return self._judged(points, self._judge(points, t, approx, method))

    def judge_batch(self, points, ts, approxes, method="de_casteljau"):
        """`judge` at many parameters in one request (one approximation per t): a list of
        judgements, or with arrays one judgement whose fields have a first axis over t."""
        return self._judged(points, self._judge_batch(points, ts, approxes, method))

    def _judge(self, points, t, approx, method):
        req = {"op": "eval", "points": V.points(points), "t": V.number(t), "approx": V.answers(approx)}
        req["method"] = method
        return _judgement(self.request(req))

    def _judge_batch(self, points, ts, approxes, method):
        req = {"op": "eval", "points": V.points(points), "t": V.parameters(ts)}
        req["approx"] = [V.answers(ap) for ap in V._as_list(approxes)]
        req["method"] = method
        return [_judgement(r) for r in V.field(self.request(req), "results")]

    def judge_rational(self, points, weights, t, approx):
        """`judge` for a rational curve: homogeneous de Casteljau then one division."""
        req = _rational(points, weights, t)
        req["approx"] = V.answers(approx)
        return self._judged(points, _judgement(self.request(req)))

    def judge_surface(self, net, u, v, approx):
        """`judge` for a tensor-product surface: de Casteljau on the rows, then the column."""
        req = _surface(net, u, v)
        req["approx"] = V.answers(approx)
        return self._judged(net, _judgement(self.request(req)))

    def ulps(self, points, t, approx):
        """Per coordinate, how many floats `approx` is from the correctly rounded b(t)."""
        return self.judge(points, t, approx)["ulps"]

    def within_bound(self, points, t, approx, method="de_casteljau"):
        """Whether every coordinate of `approx` is within the a priori error bound of
        `method` (decided exactly)."""
        return all(V.field(self._judge(points, t, approx, method), "within_bound", _NO_BOUND))

    def assert_within_bound(self, points, t, approx, method="de_casteljau"):
        """Asserts that `approx` (or, when `t` is a list, each of `approx`'s rows) is within
        `method`'s bound; the failure says, per coordinate, the answer, the correctly
        rounded value, ulps, the bound, the condition number and the exact value."""
        if V.is_scalar(t):
            judgements = [(t, V._as_list(approx), self._judge(points, t, approx, method))]
        else:
            ts, approxes = V._as_list(t), V._as_list(approx)
            judgements = list(zip(ts, approxes, self._judge_batch(points, ts, approxes, method)))
        for ti, ap, j in judgements:
            if "within_bound" not in j:
                raise OracleError("the oracle gave no bound" + _NO_BOUND)
            if not all(j["within_bound"]):
                raise AssertionError(within_bound_message(method, ti, ap, j))

    def bound(self, points, t, method="de_casteljau"):
        """The a priori error bound of `method` at a float t, in ulps of the exact value,
        per coordinate."""
        a = self.request({"op": "eval", "points": V.points(points), "t": V.number(t), "method": method})
        return self._floats(points, [V.to_float(b) for b in V.field(a, "bound", _NO_BOUND)])

    def bound_batch(self, points, ts, method="de_casteljau"):
        """`bound` at many float parameters, one request (one row per t)."""
        a = self.request({"op": "eval", "points": V.points(points), "t": V.parameters(ts), "method": method})
        rows = [[V.to_float(b) for b in V.field(r, "bound", _NO_BOUND)] for r in V.field(a, "results")]
        return self._floats(points, rows)


_NO_BOUND = ": a bound is given only where t (and every input) is a float exactly"


def _fractions(values):
    return [V.fraction(c) for c in values]


def _point_list(points):
    return [_fractions(p) for p in points]


def _rational(points, weights, t):
    return {
        "op": "rational_eval",
        "points": V.points(points),
        "weights": V.coordinates(weights, "weights"),
        "t": V.number(t),
    }


def _surface(net, u, v):
    rows = V._as_list(net)
    if isinstance(rows, (str, bytes)) or not hasattr(rows, "__iter__"):
        raise OracleInputError(f"net must be a list of rows of points, not {net!r}")
    return {"op": "surface_eval", "net": [V.points(r) for r in rows], "u": V.number(u), "v": V.number(v)}


def _answer_points(points):
    rows = V._as_list(points)
    if isinstance(rows, (str, bytes)) or not hasattr(rows, "__iter__"):
        raise OracleInputError(f"approx must be a list of points (one float per coordinate), not {points!r}")
    return [V.answers(p) for p in rows]


def _points_judgement(a, key):
    """One group (`points`, `left` or `right`) of a judged answer."""

    def group(v):
        return v[key] if isinstance(v, dict) else v

    exact = _point_list(V.field(a, key))
    out = {"points": exact}
    if "ulps" in a:
        out["ulps"] = [[V.ulps_count(u) for u in p] for p in group(a["ulps"])]
        out["error_ulps"] = [[V.to_float(e) for e in p] for p in group(V.field(a, "error_ulps"))]
        out["nearest"] = [[V.to_float(e) for e in p] for p in group(V.field(a, "nearest"))]
        verdict = a.get("verdict")
        out["verdict"] = group(verdict) if verdict is not None else [[None] * len(p) for p in exact]
    if "bound" in a:
        out["bound"] = [[V.to_float(b) for b in p] for p in group(a["bound"])]
    if "within_bound" in a:
        out["within_bound"] = group(a["within_bound"])
    if "condition" in a:
        out["condition"] = [[V.to_float(c) for c in p] for p in group(a["condition"])]
    return out


def _judgement(a):
    out = {"point": _fractions(V.field(a, "point"))}
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
