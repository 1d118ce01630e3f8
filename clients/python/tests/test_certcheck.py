"""The independent certificate checker on the texts' certificates (tests/certificates/texts,
written by `casteljau prove --certificates`), and every tampered copy of them refused — or,
where the tampered file still proves its (changed) goal, that goal confirmed by SymPy."""

import collections
import glob
import json
import os
import random

import pytest

from _casteljau_oracle.cert_check import NOT_RECHECKED, RECHECKED, REFUSED, check_certificate, check_path
from _certgen import certificates
from _mutants import mutants
from test_certcheck_pieces import _resting

HERE = os.path.dirname(os.path.abspath(__file__))
# The texts' certificates as the program writes them (`prove --certificates`), committed in
# tests/certificates/texts; tests/cert.rs keeps them current.
DATA = os.path.join(HERE, "..", "..", "..", "tests", "certificates", "texts")
FILES = sorted(glob.glob(os.path.join(DATA, "*.json")))
# Mutants per certificate at most (a deterministic sample of a larger file's), and fewer for
# a file of more than BIG_GRID points (000-4-library has 4,356; each mutant re-checks the
# whole file): pytest's time stays short.
MAX_MUTANTS_PER_FILE = 60
BIG_GRID, MAX_MUTANTS_BIG = 100, 3


def _grid(doc):
    return sum(len(e["values"]) for e in (doc.get("sampling") or {}).get("equalities", []))


def _docs():
    return [json.load(open(f, encoding="utf-8")) for f in FILES]


def test_the_texts_certificates_are_there():
    assert len(FILES) >= 3, f"no certificates in {DATA}"


def test_every_checkable_certificate_is_re_checked_and_none_refused():
    outcomes = check_path(DATA)
    refused = [o.line() for o in outcomes if o.status == REFUSED]
    assert not refused, "\n".join(refused)
    try:
        import sympy  # noqa: F401  (the for-every proofs need it)

        symbolic = True
    except ImportError:
        symbolic = False
    for o, doc in zip(outcomes, _docs()):
        if doc["check"] == "kernel" and "pieces" in doc and _resting(doc) and not symbolic:
            assert o.status == NOT_RECHECKED and "resting on" in o.detail, o.line()
        elif doc["check"] == "kernel" and "pieces" in doc and not symbolic:
            assert o.status == NOT_RECHECKED and "needs SymPy" in o.detail, o.line()
        elif doc["check"] == "kernel":
            assert o.status == RECHECKED, o.line()
        else:
            assert o.status == NOT_RECHECKED and doc["reason"] in o.detail
    # what the program's files carry data for (docs/certificates.md, version 1), all re-checked
    kernel = [
        d["id"]
        for d in _docs()
        if d["check"] == "kernel" and (symbolic or "pieces" not in d)
    ]
    assert sum(o.status == RECHECKED for o in outcomes) == len(kernel) >= 1


def _number(x):
    """A listed number in SymPy: "p/q", or a + b√d."""
    import sympy

    if isinstance(x, str):
        return sympy.Rational(x)
    return sympy.Rational(x["rational"]) + sympy.Rational(x["irrational"]) * sympy.sqrt(int(x["radicand"]))


def _fact_holds(doc):
    """A (possibly tampered) computation's facts, decided with SymPy: the implicit conic's type
    from its discriminant and matrix, the rational quadratic's from the sign of w1² − w0 w2."""
    import sympy

    x, y = sympy.symbols("x y")
    for fact in doc["computation"]["facts"]:
        if fact["computation"] == "ImplicitConic::kind":
            poly = sympy.Poly(sympy.sympify(fact["lhs"].replace("^", "**")) - sympy.sympify(fact["rhs"].replace("^", "**")), x, y)
            a, b, c, d, e, f = (poly.coeff_monomial(m) for m in (x**2, x * y, y**2, x, y, 1))
            det = sympy.Matrix([[a, b / 2, d / 2], [b / 2, c, e / 2], [d / 2, e / 2, f]]).det()
            disc = b**2 - 4 * a * c
            kind = ("degenerate" if det == 0 else "parabola" if disc == 0 else "hyperbola" if disc > 0
                    else "ellipse" if (a + c) * det < 0 else "imaginary ellipse (no real points)")
        elif fact["computation"] == "fit_cubic":
            return False  # every number of a fit is derived from the curve: none may change
        elif fact["computation"] in ("convex_combination", "affine_invariance"):
            # The convex hull property and affine invariance hold for every degree n ≥ 0; an
            # accepted copy states them for the degrees it lists (checked in range there).
            d = fact.get("degrees") or {}
            return 0 <= int(d["from"]) <= int(d["to"])
        else:
            (x0, y0), (x1, y1), (x2, y2) = (map(_number, p) for p in fact["points"])
            w0, w1, w2 = map(_number, fact["weights"])
            if sympy.simplify(sympy.Matrix([[x1 - x0, y1 - y0], [x2 - x0, y2 - y0]]).det()) == 0:
                kind = "degenerate (collinear control points)"
            elif 0 in (w0, w1, w2):
                kind = "degenerate (zero weight)"
            else:
                excess = sympy.sign(w1**2 - w0 * w2)
                kind = {0: "parabola", 1: "hyperbola", -1: "ellipse"}[int(excess)]
        if kind != fact["kind"]:
            return False
    return True


def _goal_holds(doc):
    """SymPy's verdict on a (possibly tampered) proved goal: every equality an identity."""
    from _casteljau_oracle.cert_expr import parse
    from _casteljau_oracle.cert_polygon import unlisted_to_zero
    from _casteljau_oracle.cert_sympy import same, to_sympy

    if doc.get("method") == "computation":
        return _fact_holds(doc)
    if "pieces" in doc and _resting(doc):
        # its objects (b(i, r, t), delta(b, k, j)) are not evaluated apart from the checker
        # under test: it holds when it is the committed file's goal (proved by the kernel)
        committed = {d["id"]: d.get("goal") for d in _docs()}
        return doc["goal"] == committed.get(doc.get("id"))
    if "pieces" in doc:  # a for-every goal: exact values at its first seven values
        from test_certcheck_pieces import _false_somewhere

        return not _false_somewhere(doc)

    names = [s["name"] for s in doc["goal"]["symbols"]]
    for eq in doc["goal"]["equalities"]:
        ints = {v: int(x) for v, x in eq["ints"].items()}
        lhs = to_sympy(parse(eq["lhs"], names, True), ints)
        rhs = to_sympy(parse(eq["rhs"], names, True), ints)
        points = [(p["name"], tuple(p["index"])) for p in eq.get("control_points") or []]
        if points:  # a control point the equality does not list is 0
            lhs, rhs = (unlisted_to_zero(v, points, names) for v in (lhs, rhs))
        if not same(lhs, rhs):
            return False
    return True


def test_the_generated_certificates_are_re_checked():
    for doc in certificates():
        o = check_certificate(doc)
        assert o.status == RECHECKED, o.line()


def test_tampered_certificates_are_refused():
    counts = collections.Counter()
    accepted = []
    for doc in _docs() + certificates():
        # for-every proofs (`pieces` data) have their own test: test_certcheck_hyper.py; the
        # facts citing lemmas theirs: test_cert_nonneg.py
        if doc["check"] != "kernel" or "pieces" in doc or "lemmas" in doc:
            continue
        ms = mutants(doc)
        cap = MAX_MUTANTS_BIG if _grid(doc) > BIG_GRID else MAX_MUTANTS_PER_FILE
        if len(ms) > cap:
            ms = random.Random(doc["id"]).sample(ms, cap)
        for kind, where, make in ms:
            mutant = make()
            o = check_certificate(mutant)
            counts[kind, o.status] += 1
            if o.status == RECHECKED:
                accepted.append((doc["id"], kind, where, mutant))
            else:
                assert o.status == REFUSED, (doc["id"], kind, where, o.line())
    total = sum(counts.values())
    print(f"\n{total} mutants: " + ", ".join(f"{k} {s}: {n}" for (k, s), n in sorted(counts.items())))
    for cid, kind, where, mutant in accepted:
        print(f"  still proves its goal: {cid} {kind} {where}")
    if accepted:
        pytest.importorskip("sympy")
        for cid, kind, where, mutant in accepted:
            # bounded evidence is computed again in full: only an edited control point whose
            # curve has the same distances (the maximum taken elsewhere) may pass, and the
            # evidence is then true of the edited curve (re-derived here)
            if mutant["verdict"] == "verified":
                assert "/points/" in where, (cid, kind, where, "accepted edited evidence")
            elif mutant["verdict"] != "fails":
                assert _goal_holds(mutant), (cid, kind, where, "accepted a false goal")
    assert total >= 2000, total


def _damaged(doc, rng):
    """A copy with one field removed, retyped or emptied (for the no-crash test)."""
    import copy

    d = copy.deepcopy(doc)
    nodes = [d]
    parents = []
    while nodes:
        n = nodes.pop()
        items = n.items() if isinstance(n, dict) else enumerate(n) if isinstance(n, list) else []
        for k, v in items:
            parents.append((n, k))
            nodes.append(v)
    parent, k = rng.choice(parents)
    choice = rng.randrange(4)
    if choice == 0 and isinstance(parent, dict):
        del parent[k]
    else:
        parent[k] = [None, 7, "", [], {}, "1/0", "x(", -1, 1.5, True][rng.randrange(10)]
    return d


def test_damaged_files_are_refused_never_a_crash():
    import random

    rng = random.Random(4343)
    docs = [d for d in _docs() if _grid(d) <= BIG_GRID]
    seen = collections.Counter()
    for _ in range(1000):
        doc = _damaged(rng.choice(docs), rng)
        o = check_certificate(doc)
        seen[o.status] += 1
        if o.status == RECHECKED and doc.get("verdict") in ("proved", "proved_in_range"):
            pytest.importorskip("sympy")
            assert _goal_holds(doc), o.line()
    assert seen[REFUSED] > 300, seen


def test_the_checker_runs_without_sympy():
    """The client's core and the exact re-check import no SymPy (it is the extra `check`)."""
    import subprocess
    import sys

    code = (
        "import sys; sys.modules['sympy'] = None\n"
        "import casteljau_oracle, casteljau_oracle.certcheck as c\n"
        f"sys.exit(c.main([{DATA!r}]))\n"
    )
    here = os.path.join(os.path.dirname(__file__), "..")
    r = subprocess.run([sys.executable, "-c", code], cwd=here, capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr + r.stdout
    assert "summary:" in r.stdout and "refused" in r.stdout
    r = subprocess.run(
        [sys.executable, "-c", code.replace(f"[{DATA!r}]", f"['--symbolic', {DATA!r}]")],
        cwd=here, capture_output=True, text=True, timeout=120,
    )
    assert r.returncode == 2 and "needs SymPy" in r.stderr
