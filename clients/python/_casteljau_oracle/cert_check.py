"""An independent checker of `casteljau prove --certificates` files, written from
docs/certificates.md and docs/certificate.schema.json (version 1), sharing nothing with the
program that wrote them.

Each file gets one `Outcome`:

- `re-checked`: every obligation holds, decided here in exact arithmetic (`Fraction`; a goal
  with `sqrt(d)` in Q(√d) with SymPy, `cert_sqrt`);
- `refused`: an obligation fails; `detail` names the first one;
- `not re-checked`: the file carries no checkable data (`"check": "none"`, its reason
  quoted), or uses a construct this checker does not implement (named).

Obligations of a `sampling` or `evaluation` certificate, per goal equality: the equality's
real symbols are exactly its params; the points of each param are distinct rationals and more
than a bound on the degree of the cleared difference that this checker derives itself from the
goal's expressions (the file's `lhs_degree`, `rhs_degree` and `degree` must agree with that
derivation); the grid is complete, in order; both sides, evaluated here, are the listed values
and equal at every point. A `fails` certificate: both sides evaluated at the counterexample (on
its basis polygon, when the equality lists control points) are the listed values and differ;
an implication's premise, evaluated there too, is the listed value and 0. A `verified`
certificate's bounded evidence is re-derived in `cert_convergence` (it stays evidence). A `proved_in_range` goal must cover every case of its `range` (of the variables the range
text names: an inner range it does not name, `j = 0..=n`, is not checked for completeness).
Methods `expansion` and `computation` are checked in `cert_expand` and `cert_computation`; an
inequality for every value (a `>=` goal with `pieces` data) in `cert_nonneg`.
"""

import itertools
import json
import os
import re
from fractions import Fraction

from .cert_degree import degree
from .cert_eval import EvalError, Matrix, Unsupported, evaluate
from .cert_expr import ParseError, free_names, parse
from .cert_polygon import SORT as _POINTS, PolygonError, check_affine, objects as _polygon, read_points
from .cert_hyper import PiecesRefused, check_pieces
from .cert_links import LinkRefused, lemma_refs, rests_on, resolve
from . import cert_sqrt as _sqrt

__all__ = ["Outcome", "check_certificate", "check_path", "MAX_FILE_BYTES", "MAX_FILES", "MAX_GRID"]

#: Largest certificate file read.
MAX_FILE_BYTES = 4 * 1024 * 1024
#: Most files read from one directory.
MAX_FILES = 10_000
#: Most grid points in one file (all its equalities).
MAX_GRID = 10_000

RECHECKED, REFUSED, NOT_RECHECKED = "re-checked", "refused", "not re-checked"
_RATIONAL = re.compile(r"^-?[0-9]+(/[1-9][0-9]*)?$")
_INTEGER = re.compile(r"^-?[0-9]+$")
_DEGREE = re.compile(r"^([0-9]+)(?:/([0-9]+))?$")


class Outcome:
    """One certificate's result: `status` (re-checked / refused / not re-checked), `detail`."""

    __slots__ = ("id", "status", "detail", "verdict", "method", "assumes")

    def __init__(self, id, status, detail, verdict=None, method=None):
        self.id, self.status, self.detail, self.verdict, self.method = id, status, detail, verdict, method
        # the lemma ids a proof re-derived here assumed (their files must be re-checked)
        self.assumes = []

    def line(self):
        what = f"{self.verdict}/{self.method}" if self.method else f"{self.verdict}"
        return f"{self.status:<15} {self.id}  ({what}): {self.detail}"

    def __repr__(self):
        return f"Outcome({self.id!r}, {self.status!r}, {self.detail!r})"


class _Refused(Exception):
    """An obligation that fails (the message names it)."""


def _need(cond, msg):
    if not cond:
        raise _Refused(msg)


def _rational(s, where):
    _need(isinstance(s, str) and _RATIONAL.match(s), f"{where}: {s!r} is not an exact rational \"p\" or \"p/q\"")
    v = Fraction(s)
    _need(str(v) == s, f"{where}: {s!r} is not written reduced (\"{v}\")")
    return v


def _entries(v):
    """A value flattened entry by entry (vector order; a matrix row by row)."""
    if isinstance(v, Fraction):
        return [v]
    if isinstance(v, tuple):
        return [x for item in v for x in _entries(item)]
    if isinstance(v, Matrix):
        return [x for row in v.rows for x in row]
    raise EvalError(f"a value of type {type(v).__name__}")


def _shape(v):
    if isinstance(v, tuple):
        return ("vector", tuple(_shape(x) for x in v))
    if isinstance(v, Matrix):
        return ("matrix", len(v.rows), len(v.rows[0]) if v.rows else 0)
    return "scalar"


def _show(vals):
    return "(" + ", ".join(str(x) for x in vals) + ")" if len(vals) != 1 else str(vals[0])


def check_certificate(doc, name="?", symbolic=False):
    """Checks one parsed certificate (a dict); returns an `Outcome`.

    `symbolic`: also prove each equality of a re-checked `proved` goal as an identity of
    rational functions with SymPy (`cancel`), a second argument by other means (needs SymPy).
    """
    if not isinstance(doc, dict):
        return Outcome(name, REFUSED, "the file is not a JSON object")
    cid = doc.get("id") if isinstance(doc.get("id"), str) else name
    verdict, method = doc.get("verdict"), doc.get("method")
    out = lambda status, detail: Outcome(cid, status, detail, verdict, method)  # noqa: E731
    try:
        _check_header(doc)
        if doc["check"] == "none":
            return out(NOT_RECHECKED, f"no checkable data in the file: {doc['reason']}")
        if "pieces" in doc and isinstance(doc.get("goal"), dict) and doc["goal"].get("relation") in (">=", "<="):
            from .cert_nonneg import NonnegRefused, check_nonneg

            try:
                proved, detail = check_nonneg(doc)
                return out(RECHECKED if proved else NOT_RECHECKED, detail)
            except NonnegRefused as e:
                return out(REFUSED, str(e))
        if "pieces" in doc:
            try:
                resting = rests_on(doc)
                if resting is None:
                    proved, detail = check_pieces(doc)
                    return out(RECHECKED if proved else NOT_RECHECKED, detail)
                # the objects rewritten by the lemmas' goals, or an induction's base and step
                # derived (`cert_lemmas`); a proof citing lemmas is re-checked only once
                # `cert_links.resolve` finds each lemma's file re-checked with that goal
                try:
                    from .cert_lemmas import prove_resting
                except ImportError:
                    return out(NOT_RECHECKED, f"a for-every proof resting on {resting}: not re-checked (needs SymPy)")
                refs = lemma_refs(doc)
                try:
                    proved, detail = prove_resting(doc, refs, check_pieces)
                except Unsupported as e:
                    return out(NOT_RECHECKED, f"a for-every proof resting on {resting}: not implemented here: {e}")
                if not proved:
                    return out(NOT_RECHECKED, f"a for-every proof resting on {resting}: {detail}")
                if refs:
                    # alone, a file citing lemmas is not re-checked (`resolve` decides it among
                    # the files checked together)
                    detail += "; re-checked only with its lemmas' files"
                o = out(RECHECKED if not refs else NOT_RECHECKED, detail)
                o.assumes = [lid for lid, _ in refs]
                return o
            except (PiecesRefused, LinkRefused) as e:
                return out(REFUSED, str(e))
        if verdict in ("proved", "proved_in_range") and method == "computation":
            from .cert_computation import check_computation

            return out(RECHECKED, check_computation(doc, _need, _rational))
        if verdict == "verified":
            _need("convergence" in doc, "verdict 'verified' with check 'kernel': only convergence data is defined")
            from .cert_convergence import check_convergence

            return out(RECHECKED, check_convergence(doc.get("convergence"), _need, _rational))
        if verdict in ("proved", "proved_in_range") and method == "expansion":
            from .cert_expand import check_expansion

            goal = _proved_goal(doc.get("goal"))
            _check_range(doc, goal)
            detail = check_expansion(doc.get("expansion"), goal, _need, _rational)
            if symbolic:
                _check_symbolic(goal)
                detail += "; every equality an identity in SymPy"
            return out(RECHECKED, detail)
        if verdict in ("proved", "proved_in_range"):
            _need(method in ("sampling", "evaluation"), f"method {method!r} carries no data in format version 1")
            goal = _proved_goal(doc.get("goal"))
            _check_range(doc, goal)
            _check_sampling(doc.get("sampling"), goal, method)
            detail = f"{len(goal.equalities)} equalities, {_count_points(doc)} points, all exact"
            if goal.radicand is not None:
                detail += f" in Q(√{goal.radicand}) (SymPy)"
            if symbolic:
                _check_symbolic(goal)
                detail += "; every equality an identity in SymPy"
            return out(RECHECKED, detail)
        if verdict == "fails":
            goal = _Goal(doc.get("goal"))
            detail = _check_fails(doc.get("fails"), goal)
            return out(RECHECKED, detail)
        return out(NOT_RECHECKED, f"verdict {verdict!r} with check 'kernel': nothing to re-check in version 1")
    except _Refused as e:
        return out(REFUSED, str(e))
    except ParseError as e:
        return out(REFUSED, f"goal: {e}")
    except Unsupported as e:
        return out(NOT_RECHECKED, f"not implemented here: {e}")
    except EvalError as e:
        return out(REFUSED, f"evaluation: {e}")
    except RecursionError:
        return out(REFUSED, "an expression nested too deeply")
    except (KeyError, TypeError, AttributeError, IndexError, ValueError) as e:
        # a field of the wrong type or shape that no obligation above names
        return out(REFUSED, f"malformed certificate: {type(e).__name__}: {e}")


def _count_points(doc):
    return sum(len(e["values"]) for e in doc["sampling"]["equalities"])


def _check_header(doc):
    _need(doc.get("format") == "casteljau-certificate", "format: not \"casteljau-certificate\"")
    _need(doc.get("version") == 1, f"version {doc.get('version')!r}: only version 1 is known")
    for key in ("id", "summary"):
        _need(isinstance(doc.get(key), str), f"{key}: missing or not a string")
    _need(
        doc.get("verdict") in ("proved", "proved_in_range", "verified", "fails", "error"),
        f"verdict {doc.get('verdict')!r} is not a verdict",
    )
    _need(doc.get("check") in ("kernel", "none"), f"check {doc.get('check')!r}: not \"kernel\" or \"none\"")
    if doc["check"] == "none":
        _need(isinstance(doc.get("reason"), str), "check \"none\" without a reason")
    _need("range" in doc and (doc["range"] is None or isinstance(doc["range"], str)), "range: missing")
    if doc["verdict"] == "proved_in_range" and doc["check"] == "kernel":
        _need(isinstance(doc["range"], str), "proved_in_range without its range")
    if doc["verdict"] != "proved_in_range":
        _need(doc["range"] is None, f"verdict {doc['verdict']} with a range (only proved_in_range has one)")


class _Goal:
    def __init__(self, goal):
        _need(isinstance(goal, dict), "goal: missing")
        _need(goal.get("relation") == "=", "goal: relation is not \"=\"")
        syms = goal.get("symbols")
        _need(isinstance(syms, list), "goal: symbols missing")
        self.sorts = {}
        for s in syms:
            _need(isinstance(s, dict) and isinstance(s.get("name"), str), "goal: a symbol without a name")
            _need(s.get("sort") in ("real", "integer", _POINTS), f"goal: symbol {s.get('name')}: sort not real/integer/{_POINTS}")
            _need(s["name"] not in self.sorts, f"goal: symbol {s['name']} declared twice")
            self.sorts[s["name"]] = s["sort"]
        eqs = goal.get("equalities")
        _need(isinstance(eqs, list) and eqs, "goal: no equalities")
        known = list(self.sorts)
        self.equalities, self.points, self.premises = [], [], []
        for k, eq in enumerate(eqs):
            fields = set(eq) - {"control_points", "premise"} if isinstance(eq, dict) else None
            _need(fields == {"ints", "lhs", "rhs"}, f"equality {k}: not ints, lhs, rhs (and control_points, premise)")
            try:
                points = read_points(eq, self.sorts, f"equality {k}")
            except PolygonError as e:
                raise _Refused(str(e)) from None
            ints = {}
            _need(isinstance(eq["ints"], dict), f"equality {k}: ints is not an object")
            for v, x in eq["ints"].items():
                _need(self.sorts.get(v) == "integer", f"equality {k}: ints gives {v}, not an integer symbol")
                _need(isinstance(x, str) and _INTEGER.match(x), f"equality {k}: ints {v} = {x!r} is not an integer")
                ints[v] = int(x)
            lhs = parse(eq["lhs"], known, strict=True)
            rhs = parse(eq["rhs"], known, strict=True)
            premise = None
            if "premise" in eq:
                _need(isinstance(eq["premise"], str), f"equality {k}: the premise is not an expression")
                premise = parse(eq["premise"], known, strict=True)
            used = free_names(lhs) | free_names(rhs) | (free_names(premise) if premise else set())
            for u in sorted(used):
                _need(u in self.sorts, f"equality {k}: '{u}' is not a declared symbol")
                if self.sorts[u] == "integer":
                    _need(u in ints, f"equality {k}: the integer symbol {u} has no value in ints")
            reals = [u for u in self.sorts if self.sorts[u] == "real" and u in used]
            names = {n for n, _ in points}
            for u in used:
                _need(self.sorts[u] != _POINTS or u in names, f"equality {k}: {u} has no control points listed")
            for side, e in (("lhs", lhs), ("rhs", rhs)) if names else ():
                try:
                    check_affine(e, names, ints, f"equality {k}: {side}")
                except PolygonError as err:
                    raise _Refused(str(err)) from None
            self.points.append(points)
            self.premises.append(premise)
            self.equalities.append((ints, lhs, rhs, reals))
        try:
            exprs = [e for (_, l, r, _) in self.equalities for e in (l, r)] + [p for p in self.premises if p]
            self.radicand = _sqrt.radicand(exprs)
        except _sqrt.SqrtError as err:
            raise _Refused(f"goal: {err}") from None


def _proved_goal(doc):
    goal = _Goal(doc)
    _need(not any(goal.premises), "goal: a premise is defined only for a counterexample")
    return goal


def _check_range(doc, goal):
    """The cases of a proved_in_range goal are exactly those of its range text."""
    if doc["verdict"] != "proved_in_range":
        return
    cases = _range_cases(doc["range"])
    # the range text may name only the outer ranges (`n = 0..=10` of `j = 0..=n`): compare
    # the cases on the variables it names
    named = {v for c in cases for v, _ in c}
    have = set()
    for ints, *_ in goal.equalities:
        _need(named <= set(ints), f"range {doc['range']}: an equality without a value for {sorted(named - set(ints))}")
        have.add(tuple(sorted((v, x) for v, x in ints.items() if v in named)))
    missing = [c for c in cases if c not in have]
    _need(not missing, f"range {doc['range']}: the case {_case(missing[0]) if missing else ''} has no equality")
    extra = [c for c in have if c not in cases]
    _need(not extra, f"range {doc['range']}: an equality at {_case(extra[0]) if extra else ''} outside it")


def _case(c):
    return ", ".join(f"{k} = {v}" for k, v in c)


def _range_cases(text):
    """Every integer point of `n = 0..=10, i = 0..=n` (later bounds may use earlier names)."""
    ranges = []
    for part in re.split(r"[,;]", text):
        m = re.match(r"^\s*([A-Za-z_][A-Za-z0-9_']*)\s*=\s*(.+?)\s*\.\.=\s*(.+?)\s*$", part)
        _need(m, f"range: cannot read {part.strip()!r} as 'v = a..=b'")
        ranges.append((m.group(1), parse(m.group(2)), parse(m.group(3))))
    cases = set()

    def walk(k, env):
        if len(cases) > MAX_GRID:
            raise _Refused(f"range: more than {MAX_GRID} cases")
        if k == len(ranges):
            cases.add(tuple(sorted((v, int(x)) for v, x in env.items())))
            return
        v, lo, hi = ranges[k]
        a, b = evaluate(lo, env), evaluate(hi, env)
        _need(a.denominator == 1 and b.denominator == 1, f"range: {v}'s bounds are not integers")
        for x in range(int(a), int(b) + 1):
            walk(k + 1, {**env, v: Fraction(x)})

    walk(0, {})
    return cases


def _side_bound(text, where):
    m = _DEGREE.match(text) if isinstance(text, str) else None
    _need(m, f"{where}: {text!r} is not a degree bound \"n\" or \"n/m\"")
    return (int(m.group(1)), int(m.group(2) or 0))


def _cleared(lb, rb):
    if lb[1] == 0 and rb[1] == 0:
        return max(lb[0], rb[0])
    return max(lb[0] + rb[1], rb[0] + lb[1])


def _entry_exprs(e):
    """The entries of a tuple or matrix written out (the bound is taken entry by entry)."""
    if e[0] == "tuple":
        return [x for item in e[1] for x in _entry_exprs(item)]
    if e[0] == "matrix":
        return [x for row in e[1] for x in row]
    return [e]


def _derive_bounds(lhs, rhs, var, ints):
    """(lhs bound, rhs bound, d): the side bounds and the cleared difference's degree bound."""
    lb, rb = degree(lhs, var, ints), degree(rhs, var, ints)
    le, re_ = _entry_exprs(lhs), _entry_exprs(rhs)
    if len(le) == len(re_) and len(le) > 1:
        d = max(_cleared(degree(a, var, ints), degree(b, var, ints)) for a, b in zip(le, re_))
    else:
        d = _cleared(lb, rb)
    return lb, rb, d


def _fmt(b):
    return f"{b[0]}" if b[1] == 0 else f"{b[0]}/{b[1]}"


def _check_sampling(sampling, goal, method):
    _need(isinstance(sampling, dict) and isinstance(sampling.get("equalities"), list), "sampling: missing")
    eqs = sampling["equalities"]
    _need(len(eqs) == len(goal.equalities), f"sampling: {len(eqs)} entries for {len(goal.equalities)} equalities")
    _need(all(isinstance(e, dict) and isinstance(e.get("values"), list) for e in eqs), "sampling: an entry without values")
    total = sum(len(e["values"]) for e in eqs)
    _need(total <= MAX_GRID, f"sampling: {total} grid points (limit {MAX_GRID} per file)")
    with_params = any(e.get("params") for e in eqs)
    _need(with_params == (method == "sampling"), f"method {method} but {'some' if with_params else 'no'} equality has a param")
    for k, (data, (ints, lhs, rhs, reals)) in enumerate(zip(eqs, goal.equalities)):
        where = f"equality {k}"
        _need(isinstance(data, dict) and isinstance(data.get("params"), list), f"{where}: params missing")
        params = data["params"]
        names = [p.get("name") if isinstance(p, dict) else None for p in params]
        # The grid's order is the file's (a claim's `vars` order); a listed param the sides
        # do not use is constant in them (degree 0), so only missing or repeated ones matter.
        _need(
            len(set(names)) == len(names)
            and set(names) >= set(reals)
            and all(goal.sorts.get(n) == "real" for n in names),
            f"{where}: params {names} but the sides' real symbols are {reals}",
        )
        if method == "evaluation":
            _need(not params, f"{where}: an evaluation certificate with params")
        grids = []
        for p in params:
            var = p["name"]
            pts = [_rational(x, f"{where}: {var}'s points") for x in p.get("points") or []]
            _need(len(set(pts)) == len(pts), f"{where}: {var}'s points are not distinct")
            stated_l = _side_bound(p.get("lhs_degree"), f"{where}: {var}'s lhs_degree")
            stated_r = _side_bound(p.get("rhs_degree"), f"{where}: {var}'s rhs_degree")
            stated_d = p.get("degree")
            _need(isinstance(stated_d, int) and not isinstance(stated_d, bool), f"{where}: {var}'s degree is not an integer")
            lb, rb, d = _derive_bounds(lhs, rhs, var, ints)
            _need(
                stated_l == lb and stated_r == rb,
                f"{where}: {var}: the file's side bounds {_fmt(stated_l)}, {_fmt(stated_r)} are not the derived {_fmt(lb)}, {_fmt(rb)}",
            )
            _need(stated_d == d, f"{where}: {var}: the file's degree {stated_d} is not the derived {d}")
            _need(len(pts) > d, f"{where}: {len(pts)} points in {var} do not exceed the degree bound {d}")
            grids.append(pts)
        _check_grid(data.get("values"), grids, ints, lhs, rhs, params, where, goal.points[k], goal.radicand)


def _check_grid(values, grids, ints, lhs, rhs, params, where, points, radicand=None):
    size = 1
    for g in grids:
        size *= len(g)
    polygons = len(points) + 1
    size *= polygons
    _need(size <= MAX_GRID, f"{where}: a grid of {size} points (limit {MAX_GRID})")
    _need(isinstance(values, list) and len(values) == size, f"{where}: {len(values or [])} values for a grid of {size} points")
    env0 = {v: Fraction(x) for v, x in ints.items()}
    # every grid point (the last param fastest) on every basis polygon, the polygon fastest
    cells = ((at, k) for at in itertools.product(*grids) for k in range(polygons))
    for row, (at, k) in zip(values, cells):
        fields = {"at", "lhs", "rhs", "polygon"} if points else {"at", "lhs", "rhs"}
        _need(isinstance(row, dict) and set(row) == fields, f"{where}: a value row without {', '.join(sorted(fields))}")
        _need(not points or row["polygon"] == k, f"{where}: the row of basis polygon {k} is listed as polygon {row.get('polygon')!r}")
        listed_at = [_rational(x, f"{where}: at") for x in row["at"]] if isinstance(row["at"], list) else None
        _need(listed_at == list(at), f"{where}: the grid point {_show(list(at))} is listed as {row['at']}")
        env = dict(env0)
        env.update((p["name"], x) for p, x in zip(params, at))
        point = ", ".join(f"{p['name']} = {x}" for p, x in zip(params, at)) or "the evaluation"
        point += f" on basis polygon {k}" if points else ""
        if radicand is not None:
            _check_row_in_field(row, lhs, rhs, env, where, point, radicand, points)
            continue
        objs = _polygon(points, k)
        lv, rv = evaluate(lhs, env, objs), evaluate(rhs, env, objs)
        _need(_shape(lv) == _shape(rv), f"{where}: {point}: the sides have different shapes")
        for side, got in (("lhs", lv), ("rhs", rv)):
            listed = row[side]
            _need(isinstance(listed, list) and listed, f"{where}: {point}: {side} values missing")
            said = [_rational(x, f"{where}: {point}: {side}") for x in listed]
            _need(_entries(got) == said, f"{where}: {point}: {side} is {_show(_entries(got))}, the file says {_show(said)}")
        _need(_entries(lv) == _entries(rv), f"{where}: {point}: the sides differ: {_show(_entries(lv))} and {_show(_entries(rv))}")


def _check_row_in_field(row, lhs, rhs, env, where, point, d, points):
    """One grid row of a goal in Q(√d): both sides evaluated with SymPy (`cert_sqrt`)."""
    if points:
        raise Unsupported("control points in a goal in Q(√d)")
    got = {"lhs": _sqrt.values(lhs, env), "rhs": _sqrt.values(rhs, env)}
    for side in ("lhs", "rhs"):
        listed = row[side]
        _need(isinstance(listed, list) and listed, f"{where}: {point}: {side} values missing")
        try:
            said = [_sqrt.number(x, f"{where}: {point}: {side}", d) for x in listed]
        except _sqrt.SqrtError as err:
            raise _Refused(str(err)) from None
        _need(
            len(said) == len(got[side]) and all(_sqrt.same(a, b) for a, b in zip(got[side], said)),
            f"{where}: {point}: {side} is {_show(got[side])}, the file says {_show(said)}",
        )
    _need(
        len(got["lhs"]) == len(got["rhs"]) and all(_sqrt.same(a, b) for a, b in zip(got["lhs"], got["rhs"])),
        f"{where}: {point}: the sides differ: {_show(got['lhs'])} and {_show(got['rhs'])}",
    )


def _check_symbolic(goal):
    from .cert_sympy import same, to_sympy

    from .cert_polygon import unlisted_to_zero

    for k, (ints, lhs, rhs, _) in enumerate(goal.equalities):
        sides = [to_sympy(e, ints) for e in (lhs, rhs)]
        if goal.points[k]:
            sides = [unlisted_to_zero(v, goal.points[k], goal.sorts) for v in sides]
        ok = same(*sides)
        _need(ok, f"equality {k}: SymPy finds lhs - rhs not identically zero")


def _check_fails(fails, goal):
    _need(isinstance(fails, dict), "fails: missing")
    k = fails.get("equality")
    _need(isinstance(k, int) and not isinstance(k, bool) and 0 <= k < len(goal.equalities), f"fails: equality {k!r} is not in the goal")
    ints, lhs, rhs, reals = goal.equalities[k]
    points, premise = goal.points[k], goal.premises[k]
    basis = 0
    if points:
        basis = fails.get("polygon")
        ok = isinstance(basis, int) and not isinstance(basis, bool) and 0 <= basis <= len(points)
        _need(ok, f"fails: polygon {basis!r} is not a basis polygon 0..={len(points)}")
    else:
        _need("polygon" not in fails, "fails: a polygon without control points")
    _need((premise is None) == ("premise" not in fails), "fails: the premise's value is given exactly when the goal has a premise")
    at = fails.get("at")
    _need(isinstance(at, dict), "fails: at missing")
    _need(set(at) >= set(reals), f"fails: at gives {sorted(at)}, the sides use {reals}")
    for v in at:
        _need(goal.sorts.get(v) == "real", f"fails: at gives {v}, not a real symbol")
    env = {v: Fraction(x) for v, x in ints.items()}
    env.update((v, _rational(x, f"fails: at {v}")) for v, x in at.items())
    point = ", ".join(f"{v} = {at[v]}" for v in reals) or "the evaluation"
    point += f" on basis polygon {basis}" if points else ""
    objs = _polygon(points, basis)
    if premise is not None:
        pv = evaluate(premise, env, objs)
        listed = fails.get("premise")
        _need(isinstance(listed, list) and listed, "fails: premise values missing")
        said = [_rational(x, "fails: premise") for x in listed]
        _need(_entries(pv) == said, f"fails: at {point}: the premise is {_show(_entries(pv))}, the file says {_show(said)}")
        _need(all(x == 0 for x in _entries(pv)), f"fails: at {point} the premise is {_show(_entries(pv))}, not 0")
    lv, rv = evaluate(lhs, env, objs), evaluate(rhs, env, objs)
    for side, got in (("lhs", lv), ("rhs", rv)):
        listed = fails.get(side)
        _need(isinstance(listed, list) and listed, f"fails: {side} values missing")
        said = [_rational(x, f"fails: {side}") for x in listed]
        _need(_entries(got) == said, f"fails: at {point}: {side} is {_show(_entries(got))}, the file says {_show(said)}")
    _need(_entries(lv) != _entries(rv) or _shape(lv) != _shape(rv), f"fails: at {point} the sides are equal: no counterexample")
    holds = "the premise is 0 and " if premise is not None else ""
    return f"counterexample at {point}: {holds}{_show(_entries(lv))} ≠ {_show(_entries(rv))}"


def check_path(path, symbolic=False):
    """Outcomes for a certificate file or every `*.json` file of a directory (sorted), the
    lemma references resolved among the files checked together (`cert_links`)."""
    if os.path.isdir(path):
        names = sorted(n for n in os.listdir(path) if n.endswith(".json"))
        if len(names) > MAX_FILES:
            raise ValueError(f"{path}: {len(names)} files (limit {MAX_FILES})")
        checked = [_check_file(os.path.join(path, n), symbolic) for n in names]
    else:
        checked = [_check_file(path, symbolic)]
    outcomes, docs = [o for o, _ in checked], [d for _, d in checked]
    return resolve(outcomes, docs, REFUSED, NOT_RECHECKED)


def _check_file(path, symbolic):
    name = os.path.basename(path)
    try:
        with open(path, "rb") as f:
            data = f.read(MAX_FILE_BYTES + 1)
    except OSError as e:
        return Outcome(name, REFUSED, f"cannot read: {e}"), None
    if len(data) > MAX_FILE_BYTES:
        return Outcome(name, REFUSED, f"larger than {MAX_FILE_BYTES} bytes"), None
    try:
        doc = json.loads(data.decode("utf-8"))
    except (UnicodeDecodeError, ValueError) as e:
        return Outcome(name, REFUSED, f"not JSON: {e}"), None
    return check_certificate(doc, name, symbolic), doc
