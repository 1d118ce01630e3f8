"""Honest sampling certificates written here in Python for a few identities (true and false)
of the texts, as docs/certificates.md describes them: more goals for the tampering test than
the program's files alone. The degree bounds come from the checker's own derivation, so these
files test the refusal logic, not the agreement with the program (the program's files in
tests/certificates/texts do that)."""

import itertools
from fractions import Fraction

from _casteljau_oracle.cert_check import _derive_bounds, _entries, _fmt
from _casteljau_oracle.cert_eval import evaluate
from _casteljau_oracle.cert_expr import parse

GOALS = [
    ("gen-ex4-x", {"t": "real"}, [({}, "-(2*t - 1)^2 + 1", "4/3*B(1, 3, t) + 4/3*B(2, 3, t)")]),
    ("gen-ex4-y", {"t": "real"}, [({}, "-(2*t - 1)^3 + (2*t - 1)", "-4/3*B(1, 3, t) + 4/3*B(2, 3, t)")]),
    (
        "gen-partition",
        {"t": "real", "n": "integer"},
        [({"n": str(n)}, "sum(i, 0, n, B(i, n, t))", "1") for n in range(0, 5)],
    ),
    (
        "gen-recursion",
        {"t": "real", "n": "integer", "i": "integer"},
        [
            ({"n": str(n), "i": str(i)}, "B(i, n, t)", "(1 - t)*B(i, n - 1, t) + t*B(i - 1, n - 1, t)")
            for n in range(1, 4)
            for i in range(0, n + 1)
        ],
    ),
    (
        "gen-vector",
        {"s": "real", "t": "real"},
        [({}, "(s*t, (1 - s)*B(1, 2, t))", "(t*s, 2*t*(1 - t) - 2*s*t*(1 - t))")],
    ),
    (
        "gen-rational",
        {"t": "real"},
        [({}, "(1 - t^2)/(1 + t^2) + 2*t^2/(1 + t^2)", "1")],
    ),
    (
        "gen-derivative",
        {"t": "real"},
        [({}, "__dB(1, 3, t, 1)", "3*(B(0, 2, t) - B(1, 2, t))"), ({}, "__dpow(t, 4, 2)", "12*t^2")],
    ),
    (
        "gen-matrix",
        {"u": "real"},
        [({}, "det([1, u; u, 1]) + dot((u, 1), (u, -1))", "2*u^2 - 2*u^2"), ({}, "comp((u, 2*u), 2)", "u + u")],
    ),
]

FAILS = [
    ("gen-fails-y", {"t": "real"}, [({}, "(2*t - 1)^3 + (2*t - 1)", "-4/3*B(1, 3, t) + 4/3*B(2, 3, t)")], {"t": "0"}),
    ("gen-fails-sum", {"t": "real", "n": "integer"}, [({"n": "3"}, "sum(i, 0, n, i*B(i, n, t))", "n*t^2")], {"t": "1/2"}),
]


def _goal(symbols, eqs):
    return {
        "relation": "=",
        "symbols": [{"name": k, "sort": v} for k, v in symbols.items()],
        "equalities": [{"ints": ints, "lhs": lhs, "rhs": rhs} for ints, lhs, rhs in eqs],
    }


def _head(cid, verdict, method, range_=None):
    return {
        "format": "casteljau-certificate",
        "version": 1,
        "id": cid,
        "verdict": verdict,
        "method": method,
        "rests_on": [],
        "range": range_,
        "summary": "written by tests/_certgen.py",
        "check": "kernel",
    }


def _sampling(symbols, eqs):
    out = []
    names = list(symbols)
    for ints, lhs_t, rhs_t in eqs:
        lhs, rhs = parse(lhs_t, names, True), parse(rhs_t, names, True)
        iv = {k: int(v) for k, v in ints.items()}
        reals = [v for v, s in symbols.items() if s == "real" and _uses(lhs, rhs, v)]
        params, grids = [], []
        for v in reals:
            lb, rb, d = _derive_bounds(lhs, rhs, v, iv)
            pts = [Fraction(k, d or 1) for k in range(d + 1)]
            params.append(
                {"name": v, "degree": d, "lhs_degree": _fmt(lb), "rhs_degree": _fmt(rb), "points": [str(p) for p in pts]}
            )
            grids.append(pts)
        values = []
        for at in itertools.product(*grids):
            env = {k: Fraction(x) for k, x in iv.items()}
            env.update(zip(reals, at))
            values.append(
                {
                    "at": [str(x) for x in at],
                    "lhs": [str(x) for x in _entries(evaluate(lhs, env))],
                    "rhs": [str(x) for x in _entries(evaluate(rhs, env))],
                }
            )
        out.append({"params": params, "values": values})
    return {"equalities": out}


def _uses(lhs, rhs, v):
    from _casteljau_oracle.cert_expr import free_names

    return v in free_names(lhs) | free_names(rhs)


def certificates():
    docs = []
    for cid, symbols, eqs in GOALS:
        d = _head(cid, "proved", "sampling")
        if eqs[0][0]:
            ranges = {}
            for ints, *_ in eqs:
                for k, x in ints.items():
                    ranges.setdefault(k, []).append(int(x))
            if cid == "gen-recursion":
                rng = "n = 1..=3, i = 0..=n"
            else:
                rng = ", ".join(f"{k} = {min(xs)}..={max(xs)}" for k, xs in ranges.items())
            d = _head(cid, "proved_in_range", "sampling", rng)
        d["goal"] = _goal(symbols, eqs)
        d["sampling"] = _sampling(symbols, eqs)
        docs.append(d)
    for cid, symbols, eqs, at in FAILS:
        d = _head(cid, "fails", None)
        d["goal"] = _goal(symbols, eqs)
        ints, lhs, rhs = eqs[0]
        env = {k: Fraction(x) for k, x in ints.items()}
        env.update((k, Fraction(x)) for k, x in at.items())
        names = list(symbols)
        d["fails"] = {
            "equality": 0,
            "at": at,
            "lhs": [str(x) for x in _entries(evaluate(parse(lhs, names, True), env))],
            "rhs": [str(x) for x in _entries(evaluate(parse(rhs, names, True), env))],
        }
        docs.append(d)
    return docs
