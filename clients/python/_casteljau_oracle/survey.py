"""A conformance survey: float Bézier code judged by the oracle, case by seeded case.

A survey is (library, op, seed, count): `cases` draws `count` curves from the seed, each
from its own `random.Random` (so any range of case numbers gives the same cases whichever
process draws them), the library answers each in floats, and the oracle judges every
answer against the exact one. `run` does it in one process with an `OraclePool`;
`run_on_dask` splits the case numbers into partitions and runs the same `run` on each
partition on a Dask cluster (each task with its own pool), so the records are the same.

Ops, in the shape of the oracle's exact answers:

- `eval` at t: a point; `split` at t, `subdivide` (split at 1/2) and `specialize` (two
  calls, [0, t] and [t, 1]): `{"left": points, "right": points}`; `elevate` (by one):
  points; `derivative`: the hodograph's control points; `derivative_at`: the derivative
  vector at t.

Each record gives, over the answer's coordinates, the largest `ulps` (steps from the
correctly rounded exact value) and `error_ulps`, and how many coordinates are outside the
a priori bound of the algorithm (`bound_method`), or None where the oracle gives no bound
for that op. The core needs only the standard library; the numpy reference needs numpy and
the `bezier` library needs the PyPI package `bezier`.
"""

import json
import math
import random
from fractions import Fraction

from .errors import OracleError
from .floats import ulps as float_ulps
from .pool import OraclePool

#: the oracle op and the exact answer's fields for each surveyed op
_EXACT = {
    "eval": ("eval", ("point",)),
    "split": ("split", ("left", "right")),
    "subdivide": ("split", ("left", "right")),
    "specialize": ("split", ("left", "right")),
    "elevate": ("elevate", ("points",)),
    "derivative": ("derivative", ("points",)),
    "derivative_at": ("derivative", ("vector",)),
}

#: ops that take a parameter t
_WITH_T = {"eval", "split", "subdivide", "specialize", "derivative_at"}

KINDS = ("ordinary", "near_root", "cancel")


def case(seed, i, degrees=range(1, 13), dims=(2, 3), t=None):
    """Case `i` of the seed: a dict with `id`, `degree`, `dim`, `kind`, `points` (floats)
    and `t` (a float in [0, 1], or the given `t`).

    Half of the cases are ordinary (coordinates uniform in ±2^k, |k| ≤ 8, t uniform); a
    quarter put a root of multiplicity n of every coordinate near t (b_i = (−r)^(n−i)
    (1 − r)^i, rounded, r within 2^−10 … 2^−40 of t): the value is tiny beside the control
    points; a quarter alternate large control points (±2^10 … 2^30, each off by a little)
    around a small offset, with t near 1/2: cancellation."""
    rng = random.Random(seed * 1_000_003 + i)
    degrees, dims = list(degrees), list(dims)
    n = degrees[rng.randrange(len(degrees))]
    dim = dims[rng.randrange(len(dims))]
    u = rng.random()
    kind = "ordinary" if u < 0.5 else ("near_root" if u < 0.75 else "cancel")
    if kind == "ordinary":
        tt = rng.random() if t is None else t
        scale = 2.0 ** rng.randint(-8, 8)
        points = [[rng.uniform(-1, 1) * scale for _ in range(dim)] for _ in range(n + 1)]
    elif kind == "near_root":
        tt = rng.random() if t is None else t
        coords = []
        for _ in range(dim):
            r = tt + rng.choice((-1.0, 1.0)) * 2.0 ** -rng.randint(10, 40)
            scale = 2.0 ** rng.randint(-4, 4)
            coords.append([scale * (-r) ** (n - k) * (1 - r) ** k for k in range(n + 1)])
        points = [[coords[c][k] for c in range(dim)] for k in range(n + 1)]
    else:
        tt = 0.5 + rng.uniform(-1e-3, 1e-3) if t is None else t
        big = 2.0 ** rng.randint(10, 30)
        points = [
            [(-1) ** k * big * (1 + rng.uniform(-1e-6, 1e-6)) + rng.uniform(-1, 1) for _ in range(dim)]
            for k in range(n + 1)
        ]
    return {"id": i, "degree": n, "dim": dim, "kind": kind, "points": points, "t": tt}


def cases(seed, start, stop, op, degrees=range(1, 13), dims=(2, 3)):
    """Cases start..stop of the seed for `op` (`subdivide` splits at 1/2; ops without t
    drop it)."""
    out = []
    for i in range(start, stop):
        c = case(seed, i, degrees, dims, t=0.5 if op == "subdivide" else None)
        if op not in _WITH_T:
            c["t"] = None
        out.append(c)
    return out


# -- the libraries ----------------------------------------------------------------------


def numpy_answer(op, points, t):
    """The numpy reference: de Casteljau's convex form fl(fl(s·a) + fl(t·b)), s = fl(1 − t),
    for eval and split; elevation w_i = fl(fl(α_i·b_(i−1)) + fl(β_i·b_i)) with
    α_i = fl(i/(n+1)), β_i = fl((n+1−i)/(n+1)); the hodograph fl(n·fl(b_(i+1) − b_i)).
    The oracle's methods de_casteljau, formula and differences."""
    import numpy as np

    b = np.asarray(points, dtype=np.float64)
    n = len(b) - 1
    if op in ("eval", "split", "subdivide"):
        s = 1.0 - t
        rows, left, right = b, [b[0]], [b[-1]]
        for _ in range(n):
            rows = s * rows[:-1] + t * rows[1:]
            left.append(rows[0])
            right.append(rows[-1])
        if op == "eval":
            return rows[0].tolist()
        return {"left": np.array(left).tolist(), "right": np.array(right[::-1]).tolist()}
    if op == "elevate":
        i = np.arange(1, n + 1, dtype=np.float64)[:, None]
        inner = (i / (n + 1)) * b[:-1] + ((n + 1 - i) / (n + 1)) * b[1:]
        return np.concatenate([b[:1], inner, b[-1:]]).tolist()
    if op == "derivative":
        return (float(n) * (b[1:] - b[:-1])).tolist()
    raise OracleError(f"the numpy reference has no {op}")


def bezier_answer(op, points, t):
    """The PyPI package `bezier` (its compiled speedups where built): Curve.evaluate (the
    VS algorithm, a nested Bernstein sum), subdivide (sums with exact dyadic weights),
    specialize (de Casteljau rounds; a closed form for quadratics), elevate,
    evaluate_hodograph."""
    try:
        import bezier
        import numpy as np
    except ImportError as e:
        raise OracleError(f"the survey of `bezier` needs numpy and bezier (pip install numpy bezier): {e}") from None

    nodes = np.asfortranarray(np.asarray(points, dtype=np.float64).T)
    curve = bezier.Curve(nodes, degree=len(points) - 1, copy=False)
    if op == "eval":
        return curve.evaluate(t)[:, 0].tolist()
    if op == "subdivide":
        left, right = curve.subdivide()
        return {"left": left.nodes.T.tolist(), "right": right.nodes.T.tolist()}
    if op == "specialize":
        return {"left": curve.specialize(0.0, t).nodes.T.tolist(), "right": curve.specialize(t, 1.0).nodes.T.tolist()}
    if op == "elevate":
        return curve.elevate().nodes.T.tolist()
    if op == "derivative_at":
        return curve.evaluate_hodograph(t)[:, 0].tolist()
    raise OracleError(f"bezier has no {op} here")


#: library name -> (answer function or None for answers computed elsewhere, ops, degrees, dims)
LIBRARIES = {
    "numpy": (numpy_answer, ("eval", "split", "elevate", "derivative"), range(1, 13), (2, 3)),
    "bezier": (bezier_answer, ("eval", "subdivide", "specialize", "elevate", "derivative_at"), range(1, 13), (2, 3)),
    "kurbo": (None, ("eval", "subdivide", "split", "elevate", "derivative"), range(1, 4), (2,)),
    "lyon": (None, ("eval", "split", "elevate", "derivative_at"), range(1, 4), (2,)),
}

#: the Rust crates' ops only for some degrees (kurbo and lyon elevate only quadratics,
#: kurbo's hodograph starts at quadratics, lyon's derivative_at at quadratics)
_DEGREES = {
    ("kurbo", "elevate"): range(2, 3),
    ("lyon", "elevate"): range(2, 3),
    ("kurbo", "derivative"): range(2, 4),
    ("lyon", "derivative_at"): range(2, 4),
}


def library_cases(lib, op, seed, start, stop):
    """The cases of `lib` for `op`: its degrees and dimensions."""
    if lib not in LIBRARIES:
        raise OracleError(f"no library {lib!r} in the survey (one of {', '.join(LIBRARIES)})")
    _, ops, degrees, dims = LIBRARIES[lib]
    if op not in ops:
        raise OracleError(f"{lib} has no {op} in the survey (it has {', '.join(ops)})")
    return cases(seed, start, stop, op, _DEGREES.get((lib, op), degrees), dims)


#: per (library, op): the oracle's name of the algorithm whose a priori bound judges the
#: answers, per degree, and whether it is the library's own algorithm (then an answer
#: outside it is a finding) or only the textbook algorithm's bound, for reference
_METHODS = {
    # sums of products (Bernstein form): bezier's VS algorithm, kurbo's and lyon's curves
    ("numpy", "eval"): lambda n: ("de_casteljau", True),
    ("bezier", "eval"): lambda n: ("bernstein", True),
    ("kurbo", "eval"): lambda n: ("lerp", True) if n == 1 else ("bernstein", True),  # Vec2::lerp: a + t(b − a)
    ("lyon", "eval"): lambda n: ("de_casteljau", True) if n == 1 else ("bernstein", True),  # euclid: (1 − t)a + tb
    ("numpy", "split"): lambda n: ("de_casteljau", True),
    # sums with exact dyadic weights (Pascal's triangle halved): at most j + 1 roundings
    # for point j, within de Casteljau's 2j at t = 1/2
    ("bezier", "subdivide"): lambda n: ("de_casteljau", True),
    # rounds of (1 − t)a + tb and exact rounds of (1, 0), (0, 1); the quadratic's is a
    # closed form of products (bezier's specialize_curve_quadratic)
    ("bezier", "specialize"): lambda n: ("de_casteljau", n != 2),
    # midpoints, (a + 2b + c)/4 and eval(1/2): at most 2j roundings for point j; the line's
    # halves are subsegments, its end point recomputed as p0 + 1·(p1 − p0)
    ("kurbo", "subdivide"): lambda n: ("de_casteljau", n != 1),
    # subsegment: ends by eval, inner points from the derivative and fl(1/3): not de Casteljau
    ("kurbo", "split"): lambda n: ("de_casteljau", False),
    # the cubic's triangle in the lerp form; the quadratic's split point is a Bernstein sum
    ("lyon", "split"): lambda n: ("lerp", True) if n == 3 else ("de_casteljau", n == 1),
    ("numpy", "elevate"): lambda n: ("formula", True),
    ("bezier", "elevate"): lambda n: ("formula", True),  # fl(fl(i·a + (m+1−i)·b)/(m+1))
    ("lyon", "elevate"): lambda n: ("formula", True),  # (a + 2b)/3
    ("kurbo", "elevate"): lambda n: ("formula", False),  # a + fl(2/3)·(b − a)
    ("numpy", "derivative"): lambda n: ("differences", True),
    ("kurbo", "derivative"): lambda n: ("differences", True),
}


def bound_method(lib, op, degree):
    """(the oracle's method name, whether it is `lib`'s own algorithm) for `op` at `degree`,
    or (None, False) where the survey names none."""
    pick = _METHODS.get((lib, op))
    return pick(degree) if pick else (None, False)


# -- judging ------------------------------------------------------------------------------


def exact_request(op, c):
    """The oracle request for the exact answer of case `c`."""
    oracle_op, _ = _EXACT[op]
    req = {"op": oracle_op, "points": c["points"]}
    if oracle_op == "elevate":
        req["by"] = 1
    elif oracle_op == "derivative":
        req["order"] = 1
    if c.get("t") is not None:
        req["t"] = c["t"]
    return req


def _ulp(x):
    """ulp of the exact value x as docs/oracle.md defines it."""
    if x == 0:
        return Fraction(1, 2**1074)
    e = math.floor(math.log2(abs(x)))
    while Fraction(2) ** e > abs(x):
        e -= 1
    while Fraction(2) ** (e + 1) <= abs(x):
        e += 1
    return Fraction(2) ** (max(e, -1022) - 52)


def _flat(answer, fields):
    out = []
    for f in fields:
        v = answer[f]
        out.extend(c for p in v for c in p) if v and isinstance(v[0], list) else out.extend(v)
    return out


def _judged_locally(exact, approx):
    """ulps and error_ulps per coordinate, without a bound (the oracle gives none for this op)."""
    rows = []
    for x, a in zip(exact, approx):
        x = Fraction(x)
        if not math.isfinite(a):
            rows.append((None, math.inf, None, None))
            continue
        err = abs(Fraction(a) - x) / _ulp(x)
        rows.append((float_ulps(a, float(x)), float(err), None, None))
    return rows


def _judged_by_oracle(answer, fields):
    """(ulps, error_ulps, within_bound) per coordinate from the oracle's judged fields."""

    def flat(name, conv):
        if name not in answer:
            return None
        v = answer[name]
        if isinstance(v, dict):
            return [conv(c) for f in fields for p in v[f] for c in p]
        return [conv(c) for c in _flat({name: v}, [name])] if v and isinstance(v[0], list) else [conv(c) for c in v]

    def num(x):
        return math.inf if x == "inf" else float(x)

    def steps(x):
        return None if x is None else int(x)

    us, es = flat("ulps", steps), flat("error_ulps", num)
    if us is None:  # an answer without judged fields (a point of one control point)
        raise OracleError(f"the oracle did not judge: {answer}")
    wb = flat("within_bound", bool)
    wb = wb if wb is not None else [None] * len(us)
    bs = flat("bound", num)
    bs = bs if bs is not None else [None] * len(us)
    return list(zip(us, es, wb, bs))


def _split_by_points(c, method):
    """A split judged point by point: left point j is de Casteljau's triangle at level j
    over b_0..b_j, right point k at level n − k over b_k..b_n, each the same float
    operations as evaluating that sub-curve at t, so the evaluation bound of the sub-curve
    (`eval` with `method`) is the bound of that point (for the oracles without `approx` on
    `split`)."""
    pts, t, n = c["points"], c["t"], c["degree"]
    reqs = [{"op": "eval", "points": pts[: j + 1], "t": t, "approx": c["approx"]["left"][j]} for j in range(n + 1)]
    reqs += [{"op": "eval", "points": pts[k:], "t": t, "approx": c["approx"]["right"][k]} for k in range(n + 1)]
    for r in reqs:
        r["method"] = method
    return reqs


def judge(pool, lib, op, answered, capabilities):
    """Records for the answered cases (each case with its `approx`), judged by the pool."""
    oracle_op, fields = _EXACT[op]
    # the oracle judges a derivative's control points, not its vector at t
    with_approx = capabilities.get(oracle_op, False) and op != "derivative_at"
    by_points = oracle_op == "split" and not with_approx and capabilities.get("eval", False)
    reqs, parts = [], []
    for c in answered:
        req = exact_request(op, c)
        method, _ = bound_method(lib, op, c["degree"])
        if with_approx:
            req["approx"] = c["approx"]
            if method is not None:
                req["method"] = method
        reqs.append(req)
        parts.append(_split_by_points(c, method or "de_casteljau") if by_points else [req])
    flat = pool.requests([r for ps in parts for r in ps], check=True)
    records, at = [], 0
    for c, req, ps in zip(answered, reqs, parts):
        answers, at = flat[at : at + len(ps)], at + len(ps)
        if by_points:
            rows = [row for a in answers for row in _judged_by_oracle(a, ("point",))]
        elif with_approx:
            rows = _judged_by_oracle(answers[0], fields)
        else:
            rows = _judged_locally(_flat(answers[0], fields), _flat_approx(c["approx"], fields))
        finite = [u for u, _, _, _ in rows if u is not None]
        judged = [w for _, _, w, _ in rows if w is not None]
        # the share of its bound an answer uses: error_ulps / bound (1 at the bound)
        used = [e / b if b else (0.0 if e == 0 else math.inf) for _, e, _, b in rows if b is not None]
        repro = dict(req)
        repro["approx"] = c["approx"]
        records.append(
            {
                "lib": lib,
                "op": op,
                "id": c["id"],
                "degree": c["degree"],
                "dim": c["dim"],
                "kind": c["kind"],
                "ulps": max(finite) if len(finite) == len(rows) else None,
                "error_ulps": max(e for _, e, _, _ in rows),
                "bound_used": max(used) if used else None,
                "outside": sum(1 for w in judged if not w) if judged else None,
                "bound_method": _method_label(lib, op, c["degree"]) if judged else None,
                "own": bound_method(lib, op, c["degree"])[1] if judged else None,
                "request": repro,
            }
        )
    return records


def _method_label(lib, op, degree):
    """The bound's method, marked † when it is not the library's own algorithm."""
    method, own = bound_method(lib, op, degree)
    return (method or "default") + ("" if own else "†")


def _flat_approx(approx, fields):
    if isinstance(approx, dict):
        return [float(x) for f in fields for p in approx[f] for x in p]
    if approx and isinstance(approx[0], list):
        return [float(x) for p in approx for x in p]
    return [float(x) for x in approx]


def capabilities(pool):
    """Which oracle ops judge an `approx` (the others are judged here: ulps, no bound)."""
    probes = {
        "eval": {"op": "eval", "points": [[0.0], [1.0]], "t": 0.5, "approx": [0.5]},
        "split": {
            "op": "split",
            "points": [[0.0], [1.0]],
            "t": 0.5,
            "approx": {"left": [[0.0], [0.5]], "right": [[0.5], [1.0]]},
        },
        "elevate": {"op": "elevate", "points": [[0.0], [1.0]], "by": 1, "approx": [[0.0], [0.5], [1.0]]},
        "derivative": {"op": "derivative", "points": [[0.0], [1.0]], "order": 1, "approx": [[1.0]]},
    }
    answers = pool.requests(list(probes.values()), check=False)
    return {op: bool(a.get("ok")) and "ulps" in a for op, a in zip(probes, answers)}


def answer_cases(lib, op, cs, rust_answers=None):
    """The cases with the library's `approx`; `rust_answers(lib, op, cases)` answers for
    the Rust crates (scripts/survey.py runs the example)."""
    fn = LIBRARIES[lib][0]
    if fn is None:
        if rust_answers is None:
            raise OracleError(f"{lib} is a Rust crate: its answers come from scripts/peers_survey.rs")
        approxes = rust_answers(lib, op, cs)
    else:
        approxes = [fn(op, c["points"], c["t"]) for c in cs]
    return [dict(c, approx=a) for c, a in zip(cs, approxes)]


def run(lib, op, seed, start, stop, binary=None, pool_size=2, rust_answers=None, pool=None):
    """Records of cases start..stop of (lib, op, seed), in case order. Uses `pool`, or
    opens an `OraclePool` of `pool_size` oracles for the call."""
    cs = answer_cases(lib, op, library_cases(lib, op, seed, start, stop), rust_answers)
    if pool is not None:
        return judge(pool, lib, op, cs, capabilities(pool))
    with OraclePool(pool_size, binary) as p:
        return judge(p, lib, op, cs, capabilities(p))


def run_on_dask(client, lib, op, seed, count, partitions, binary=None, pool_size=1, rust_answers=None):
    """`run` over case numbers 0..count in `partitions` Dask tasks, each opening its own
    pool of `pool_size` oracles on its worker: the records in case order, the same as
    `run(lib, op, seed, 0, count)`'s. `binary` (and whatever `rust_answers` runs) must
    exist on the workers."""
    for name, value, least in (("count", count, 0), ("partitions", partitions, 1)):
        if not isinstance(value, int) or isinstance(value, bool) or value < least:
            raise OracleError(f"{name} must be an int of at least {least}, not {value!r}")
    if count == 0:
        return []
    step = -(-count // partitions)
    bounds = [(s, min(s + step, count)) for s in range(0, count, step)]
    futures = client.map(
        lambda b: run(lib, op, seed, b[0], b[1], binary=binary, pool_size=pool_size, rust_answers=rust_answers),
        bounds,
        key=[f"casteljau-survey-{lib}-{op}-{seed}-{a}-{b}" for a, b in bounds],
    )
    return [r for part in client.gather(futures) for r in part]


# -- the summary ----------------------------------------------------------------------------


def _quantile(sorted_values, q):
    """The q-quantile by the nearest rank (an element of the data)."""
    if not sorted_values:
        return None
    k = max(0, math.ceil(q * len(sorted_values)) - 1)
    return sorted_values[k]


def _farthest(records):
    """The answers farthest outside the bound: the farthest finite multiple of it, and the
    first where the bound is 0 (an exact point not kept exactly), when there are such."""
    finite = [r for r in records if r["bound_used"] is not None and r["bound_used"] < math.inf]
    zero = [r for r in records if r["bound_used"] == math.inf]
    return ([max(finite, key=lambda r: r["bound_used"])] if finite else []) + zero[:1]


def summary(records):
    """Per (lib, op): counts, median/p99/max of the largest ulps per answer (overall and
    per kind), answers outside the bound, and the worst case's request."""
    out = {}
    for r in records:
        out.setdefault((r["lib"], r["op"]), []).append(r)
    rows = []
    for (lib, op), rs in out.items():

        def stats(sub):
            us = sorted(math.inf if r["ulps"] is None else r["ulps"] for r in sub)
            top = us[-1] if us else None
            return {"n": len(sub), "median": _quantile(us, 0.5), "p99": _quantile(us, 0.99), "max": top}

        judged = [r for r in rs if r["outside"] is not None and r["own"]]
        outside = [r for r in judged if r["outside"]]
        reference = [r for r in rs if r["outside"] is not None and not r["own"]]
        worst = max(rs, key=lambda r: (math.inf if r["ulps"] is None else r["ulps"], r["error_ulps"]))
        rows.append(
            {
                "lib": lib,
                "op": op,
                "all": stats(rs),
                "ordinary": stats([r for r in rs if r["kind"] == "ordinary"]),
                "ill": stats([r for r in rs if r["kind"] != "ordinary"]),
                "judged": len(judged),
                "bound_used": max((r["bound_used"] for r in judged if r["bound_used"] is not None), default=None),
                "bound_used_reference": max(
                    (r["bound_used"] for r in reference if r["bound_used"] is not None), default=None
                ),
                "outside": len(outside),
                "reference": len(reference),
                "outside_reference": sum(1 for r in reference if r["outside"]),
                "methods": sorted({r["bound_method"] for r in judged + reference}),
                "worst": worst,
                "worst_outside": _farthest(outside),
                "worst_outside_reference": _farthest([r for r in reference if r["outside"]]),
            }
        )
    return rows


def _fmt(x):
    if x is None:
        return "–"
    if x == math.inf:
        return "inf"
    return f"{x:.3g}" if x >= 1e6 else str(x)


def _compact(req):
    return json.dumps(req, separators=(",", ":"))


def _share(x):
    return "–" if x is None else ("inf" if x == math.inf else f"{x:.3g}")


def markdown(rows):
    """The summary as a Markdown table, then the worst inputs as requests."""
    lines = [
        "| library | op | answers | ulps median / p99 / max (ordinary) | ulps median / p99 / max (ill-conditioned)"
        " | outside the bound | most of the bound used | bound of |",
        "|---|---|---:|---|---|---|---|---|",
    ]
    for r in rows:
        o, i = r["ordinary"], r["ill"]
        outside = f"{r['outside']} of {r['judged']}" if r["judged"] else ""
        used = _share(r["bound_used"]) if r["judged"] else ""
        if r["reference"]:
            outside += ("; " if outside else "") + f"{r['outside_reference']} of {r['reference']} †"
            used += ("; " if used else "") + f"{_share(r['bound_used_reference'])} †"
        outside, used = outside or "no bound", used or "–"
        ulps = " | ".join(" / ".join(_fmt(x[k]) for k in ("median", "p99", "max")) for x in (o, i))
        methods = ", ".join(r["methods"]) or "–"
        lines.append(f"| {r['lib']} | {r['op']} | {r['all']['n']} | {ulps} | {outside} | {used} | {methods} |")
    lines.append("")
    for r in rows:
        w = r["worst"]
        lines.append(f"- {r['lib']} {r['op']}, the most ulps ({_fmt(w['ulps'])}, case {w['id']}, {w['kind']}):")
        lines.append(f"  `{_compact(w['request'])}`")
        for key, what in (("worst_outside", "its algorithm's bound"), ("worst_outside_reference", "the † bound")):
            for w in r[key]:
                how = "where it is 0" if w["bound_used"] == math.inf else f"{_share(w['bound_used'])} times it"
                lines.append(f"  outside {what} ({how}, case {w['id']}, degree {w['degree']}, {w['kind']}):")
                lines.append(f"  `{_compact(w['request'])}`")
    return "\n".join(lines)
