"""For-every proofs that cite lemmas or go by induction (docs/certificates.md, "Lemmas and
induction"), proved here by this checker's own argument: the polygon's objects of text 000
are rewritten until the goal is in the grammar, and the remaining goal is proved as any
`pieces` goal (`cert_hyper.check_pieces`: exact evaluation at its first values, then the
pieces and WZ proof with SymPy).

The objects (their meanings as the page gives them), of a polygon `b` of degree `n`:

- `b(i, r, g)`, the de Casteljau point: `b(i, 0, g) = b[i]`,
  `b(i, r, g) = (1 − g)·b(i, r−1, g) + g·b(i+1, r−1, g)`;
- `b(g)` = `b(0, n, g)`; `b'(g)`, `b''(g)`, … the derivatives of `b(x)` at `x = g`;
- `delta(b, k, j)`: `Δ⁰b_j = b[j]`, `Δᵏb_j = Δᵏ⁻¹b_{j+1} − Δᵏ⁻¹b_j` (by its recursion, not the
  grammar's closed form, which is what a lemma may state of it).

A lemma is applied to an object whose kind is its left side's (`b(i, r, t)` or
`delta(b, k, j)`, every argument but the polygon a distinct symbol): its right side with the
object's arguments (and the polygon's degree for the lemma's) put for its symbols. Each
application is an obligation: every range of the lemma holds at the arguments, shown
(`cert_domain`) on the goal's domain and the ranges of the sums around the object. An
object no lemma covers, or an application not shown within the lemma's ranges, stops the
proof ("not re-checked": the proof may still hold), and so does an object not shown within
its scheme (`0 ≤ r`, `0 ≤ i ≤ n − r`; `0 ≤ k`, `0 ≤ j ≤ n − k`), which the program refuses.
`b'(g)` is rewritten as the derivative in `x` of the rewritten `b(x)`, taken here only of
`Σ c·B(j, m, x)` with `c` free of `x` (`B`'s derivatives are the grammar's `__dB`).

An induction on `v` (`pieces.induction`, range `v = a..=e`): the base is the goal at `v = a`
with each object read from the base of its recursion (its recursion argument 0 there);
the step is the goal at `v + 1`, for `v = a..=e − 1`, with each object whose recursion
argument is `v + 1` unfolded by one step of its recursion, and the goal at `v` its only
hypothesis: a lemma applied only to objects whose recursion argument is `v` itself, within
the goal's ranges. Base and step are derived here from the goal; both must be proved.

The lemmas' goals are the ones the file lists; `cert_links` checks that each is the goal of
the lemma's own file and that file re-checked here.
"""

import copy
import itertools
from fractions import Fraction

import sympy

from .cert_eval import Unsupported
from .cert_expr import FUNCTIONS, free_names, parse, show
from .cert_terms import linear

__all__ = ["prove_resting"]



def _num(k):
    return ("num", Fraction(k))


_ONE_F, _ZERO_F = _num(1), _num(0)


class _Names:
    """Fresh names for bound variables and the derivative's variable, valid in the grammar
    and distinct from every name the goal uses."""

    def __init__(self, used):
        self.used = set(used)
        self.count = itertools.count(1)

    def fresh(self, base):
        while True:
            name = f"{base.rstrip(chr(39))}_{next(self.count)}"
            if name not in self.used and name not in FUNCTIONS:
                self.used.add(name)
                return name


def _all_names(e, out):
    """Every name of `e`, free or bound (bound variables included)."""
    kind = e[0]
    if kind == "var":
        out.add(e[1])
    elif kind == "sum":
        out.add(e[1])
        for x in e[2:]:
            _all_names(x, out)
    elif kind in ("call", "index"):
        out.add(e[1])
        for x in e[2]:
            _all_names(x, out)
    elif kind == "tuple":
        for x in e[1]:
            _all_names(x, out)
    elif kind == "matrix":
        for r in e[1]:
            for x in r:
                _all_names(x, out)
    elif kind != "num":
        for x in e[1:]:
            _all_names(x, out)
    return out


def subst(e, m, names):
    """`e` with the variables of `m` (name → tree) replaced simultaneously; a bound variable
    that would capture a free name of a value is renamed first."""
    kind = e[0]
    if kind == "var":
        return m.get(e[1], e)
    if kind == "num":
        return e
    if kind == "sum":
        _, v, lo, hi, body = e
        lo, hi = subst(lo, m, names), subst(hi, m, names)
        inner = {k: x for k, x in m.items() if k != v}
        if any(v in free_names(x) for x in inner.values()):
            w = names.fresh(v)
            inner[v] = ("var", w)
            v = w
        return ("sum", v, lo, hi, subst(body, inner, names))
    if kind == "call" and e[1] == "integral":
        raise Unsupported("an integral in a goal citing lemmas")
    if kind in ("call", "index"):
        return (kind, e[1], tuple(subst(a, m, names) for a in e[2]))
    if kind == "tuple":
        return ("tuple", tuple(subst(a, m, names) for a in e[1]))
    if kind == "matrix":
        return ("matrix", tuple(tuple(subst(a, m, names) for a in r) for r in e[1]))
    return (kind,) + tuple(subst(a, m, names) for a in e[1:])


def _affine(e, syms):
    """An integer expression as an affine SymPy value in `syms` (name → Symbol)."""

    def go(x):
        k = x[0]
        if k == "num":
            return sympy.Rational(x[1].numerator, x[1].denominator)
        if k == "var":
            if x[1] not in syms:
                raise Unsupported(f"{x[1]} is not an integer symbol here")
            return syms[x[1]]
        if k == "neg":
            return -go(x[1])
        if k in ("add", "sub", "mul", "div"):
            a, b = go(x[1]), go(x[2])
            return {"add": a + b, "sub": a - b, "mul": a * b}.get(k) if k != "div" else a / b
        raise Unsupported(f"{show(x)} is not an affine integer expression")

    return linear(go(e), list(syms.values()))


class _Object:
    """A call of the polygon's objects: `kind` ('point', 'delta', 'curve', 'derivative'),
    its arguments, and (for 'derivative') its order."""

    def __init__(self, kind, args, order=0):
        self.kind, self.args, self.order = kind, args, order


def _object(e, poly):
    """The object `e` calls, or None when `e` is not a call of one."""
    if e[0] != "call":
        return None
    name, args = e[1], e[2]
    if name == "delta":
        if len(args) == 3 and args[0] == ("var", poly):
            return _Object("delta", args)
        raise Unsupported(f"{show(e)}: delta of another name than the polygon {poly}")
    if name == poly and len(args) == 3:
        return _Object("point", args)
    if name == poly and len(args) == 1:
        return _Object("curve", args)
    stem = name.rstrip("'")
    if stem == poly and len(args) == 1 and stem != name:
        return _Object("derivative", args, len(name) - len(stem))
    if name not in FUNCTIONS:
        raise Unsupported(f"{show(e)}: an object this checker does not know")
    return None


def _recursion_arg(obj):
    return obj.args[1]


def _base_of(obj, poly):
    """The base of an object's recursion (its recursion argument 0)."""
    if obj.kind == "point":
        return ("index", poly, (obj.args[0],))
    return ("index", poly, (obj.args[2],))


def _unfold(obj, poly):
    """One step of an object's recursion (its recursion argument `a ≥ 1`, `a − 1` below)."""
    a1 = ("sub", obj.args[1], _ONE_F)
    if obj.kind == "point":
        i, _, g = obj.args
        left = ("mul", ("sub", _ONE_F, g), ("call", poly, (i, a1, g)))
        right = ("mul", g, ("call", poly, (("add", i, _ONE_F), a1, g)))
        return ("add", left, right)
    _, _, j = obj.args
    return ("sub", ("call", "delta", (("var", poly), a1, ("add", j, _ONE_F))), ("call", "delta", (("var", poly), a1, j)))



class Lemma:
    """A goal assumed: its left side an object of symbols, its right side a formula.
    `only_at`: for an induction hypothesis, `(symbol, value)`: applied only where the
    symbol's argument is that value."""

    def __init__(self, lid, goal, only_at=None):
        self.id, self.only_at = lid, only_at
        if not isinstance(goal, dict) or goal.get("relation") != "=":
            raise Unsupported(f"lemma {lid}: its goal is not an equality")
        eqs = goal.get("equalities")
        if not isinstance(eqs, list) or len(eqs) != 1:
            raise Unsupported(f"lemma {lid}: its goal is not one equality")
        poly = goal.get("polygon")
        if not isinstance(poly, dict) or not isinstance(poly.get("name"), str) or goal.get("net") is not None:
            raise Unsupported(f"lemma {lid}: its goal is not over a polygon")
        self.poly = poly["name"]
        deg = parse(poly.get("degree"), strict=True)
        if deg[0] != "var":
            raise Unsupported(f"lemma {lid}: its polygon's degree is not a symbol")
        self.degree = deg[1]
        self.sorts = {s["name"]: s["sort"] for s in goal.get("symbols", [])}
        self.ranges = [(r["name"], parse(r["from"], strict=True), None if r.get("to") is None else parse(r["to"], strict=True)) for r in goal.get("for_all", [])]
        lhs = parse(eqs[0].get("lhs"), [self.poly], strict=True)
        self.rhs = parse(eqs[0].get("rhs"), [self.poly], strict=True)
        obj = _object(lhs, self.poly)
        if obj is None or obj.kind not in ("point", "delta"):
            raise Unsupported(f"lemma {lid}: its left side is not b(i, r, t) or delta(b, k, j) of symbols")
        self.kind = obj.kind
        params = obj.args if obj.kind == "point" else obj.args[1:]
        if any(p[0] != "var" for p in params) or len({p[1] for p in params}) != len(params):
            raise Unsupported(f"lemma {lid}: its left side's arguments are not distinct symbols")
        self.params = [p[1] for p in params]
        bound = set(self.params) | {self.degree}
        if set(self.sorts) - bound:
            raise Unsupported(f"lemma {lid}: its symbols {sorted(set(self.sorts) - bound)} are not the object's arguments")
        if any(_object(x, self.poly) for x in _calls(self.rhs)):
            raise Unsupported(f"lemma {lid}: its right side uses an object")

    def bind(self, obj, degree):
        """The lemma's symbols → the object's arguments and the polygon's degree."""
        args = obj.args if obj.kind == "point" else obj.args[1:]
        m = dict(zip(self.params, args))
        if self.degree in m:
            raise Unsupported(f"lemma {self.id}: the polygon's degree is also an argument")
        m[self.degree] = degree
        return m


def _calls(e):
    out = []

    def go(x):
        if x[0] == "call":
            out.append(x)
        if x[0] in ("call", "index"):
            for a in x[2]:
                go(a)
        elif x[0] == "sum":
            for a in x[2:]:
                go(a)
        elif x[0] == "tuple":
            for a in x[1]:
                go(a)
        elif x[0] == "matrix":
            for r in x[1]:
                for a in r:
                    go(a)
        elif x[0] not in ("num", "var"):
            for a in x[1:]:
                go(a)

    go(e)
    return out


class _Rewriter:
    """Rewrites the objects of one goal: `ints` its integer symbols, `ineqs` its domain
    (`L ≥ 0` trees), `poly`/`degree` its polygon."""

    def __init__(self, ints, ineqs, poly, degree, names):
        self.ints, self.ineqs, self.poly, self.degree, self.names = ints, ineqs, poly, degree, names
        self.applied = []

    def _domain(self, ctx):
        from .cert_domain import Domain

        syms = {v: sympy.Symbol(v) for v in self.ints}
        rows = []
        for v, lo, hi in ctx:
            if v in syms:
                raise Unsupported(f"a sum over {v}, a name the goal already uses")
            syms[v] = sympy.Symbol(v)
            rows += [("sub", ("var", v), lo), ("sub", hi, ("var", v))]
        rows = [_affine(r, syms) for r in self.ineqs + rows]
        return Domain(list(syms.values()), rows), syms

    def holds(self, ctx, ineqs):
        dom, syms = self._domain(ctx)
        return all(dom.implies(_affine(x, syms)) for x in ineqs)

    def equal(self, ctx, a, b):
        _, syms = self._domain(ctx)
        return sympy.expand(_affine(a, syms) - _affine(b, syms)) == 0

    def defined(self, obj, ctx):
        """Raises `Unsupported` unless the object is read within its scheme on the domain:
        `b(i, r, g)` for `0 ≤ r`, `0 ≤ i ≤ n − r`; `delta(b, k, j)` for `0 ≤ k`, `0 ≤ j ≤ n − k`
        (`n` the polygon's degree). The program refuses an object read outside; this checker
        does not prove such a goal either."""
        if obj.kind not in ("point", "delta"):
            return
        step, index = (obj.args[1], obj.args[0]) if obj.kind == "point" else (obj.args[1], obj.args[2])
        need = [step, index, ("sub", ("sub", self.degree, step), index)]
        if not self.holds(ctx, need):
            args = ", ".join(show(a) for a in obj.args)
            raise Unsupported(f"the object {obj.kind}({args}) is not shown within its scheme (0 ≤ {show(step)}, 0 ≤ {show(index)} ≤ {show(self.degree)} − {show(step)})")

    def rewrite(self, e, visit, ctx=()):
        """`e` with every object call replaced by `visit(obj, ctx)` (bottom-up)."""
        kind = e[0]
        if kind in ("num", "var"):
            return e
        if kind == "sum":
            _, v, lo, hi, body = e
            lo, hi = self.rewrite(lo, visit, ctx), self.rewrite(hi, visit, ctx)
            return ("sum", v, lo, hi, self.rewrite(body, visit, ctx + ((v, lo, hi),)))
        if kind in ("call", "index"):
            e = (kind, e[1], tuple(self.rewrite(a, visit, ctx) for a in e[2]))
            obj = _object(e, self.poly) if kind == "call" else None
            return e if obj is None else visit(obj, ctx)
        if kind == "tuple":
            return ("tuple", tuple(self.rewrite(a, visit, ctx) for a in e[1]))
        if kind == "matrix":
            return ("matrix", tuple(tuple(self.rewrite(a, visit, ctx) for a in r) for r in e[1]))
        return (kind,) + tuple(self.rewrite(a, visit, ctx) for a in e[1:])

    def apply(self, lemmas, obj, ctx):
        """The object rewritten by the first lemma that applies to it within its ranges."""
        if obj.kind == "curve":
            return self.apply(lemmas, _Object("point", (_ZERO_F, self.degree, obj.args[0])), ctx)
        if obj.kind == "derivative":
            x = self.names.fresh("x")
            curve = self.apply(lemmas, _Object("point", (_ZERO_F, self.degree, ("var", x))), ctx)
            return subst(_derivative(curve, x, obj.order), {x: obj.args[0]}, self.names)
        self.defined(obj, ctx)
        why = []
        for lem in lemmas:
            if lem.kind != obj.kind:
                continue
            m = lem.bind(obj, self.degree)
            if lem.only_at is not None and not self.equal(ctx, m[lem.only_at[0]], lem.only_at[1]):
                why.append(f"{lem.id}: not at {lem.only_at[0]} = {show(lem.only_at[1])}")
                continue
            names = _Names(self.names.used)
            need = []
            for v, lo, hi in lem.ranges:
                val = m[v]
                need.append(("sub", val, subst(lo, m, names)))
                if hi is not None:
                    need.append(("sub", subst(hi, m, names), val))
            if not self.holds(ctx, need):
                why.append(f"{lem.id}: not shown within its ranges")
                continue
            self.applied.append(lem.id)
            m = dict(m)
            if lem.poly != self.poly:
                raise Unsupported(f"lemma {lem.id}: its polygon is named {lem.poly}, the goal's {self.poly}")
            return subst(lem.rhs, m, self.names)
        args = ", ".join(show(a) for a in obj.args)
        raise Unsupported(f"no lemma applies to the object {obj.kind}({args})" + (f" ({'; '.join(why)})" if why else ""))



def _derivative(e, x, k):
    """The k-th derivative in `x` of `e`, a sum of `c·B(j, m, x)` terms with `c` free of `x`."""
    if x not in free_names(e):
        return _ZERO_F
    kind = e[0]
    if kind in ("add", "sub"):
        return (kind, _derivative(e[1], x, k), _derivative(e[2], x, k))
    if kind == "neg":
        return ("neg", _derivative(e[1], x, k))
    if kind == "sum" and x not in free_names(e[2]) | free_names(e[3]):
        return ("sum", e[1], e[2], e[3], _derivative(e[4], x, k))
    if kind == "mul":
        if x not in free_names(e[1]):
            return ("mul", e[1], _derivative(e[2], x, k))
        if x not in free_names(e[2]):
            return ("mul", _derivative(e[1], x, k), e[2])
    if kind == "call" and e[1] == "B" and e[2][2] == ("var", x) and x not in free_names(e[2][0]) | free_names(e[2][1]):
        i, m, _ = e[2]
        return ("call", "__dB", (i, m, ("var", x), _num(k)))
    raise Unsupported(f"the derivative of {show(e)} (only sums of c·B(j, m, x) are differentiated here)")


def _goal_parts(goal):
    poly = goal.get("polygon")
    if not isinstance(poly, dict) or goal.get("net") is not None:
        raise Unsupported("a goal with objects but no polygon")
    name = poly["name"]
    degree = parse(poly["degree"], strict=True)
    ints = [s["name"] for s in goal["symbols"] if s.get("sort") == "integer"]
    ineqs = []
    for r in goal["for_all"]:
        v = ("var", r["name"])
        ineqs.append(("sub", v, parse(r["from"], strict=True)))
        if r.get("to") is not None:
            ineqs.append(("sub", parse(r["to"], strict=True), v))
    used = set()
    for eq in goal["equalities"]:
        for key in ("lhs", "rhs"):
            _all_names(parse(eq[key], [name], strict=True), used)
    used |= {s["name"] for s in goal["symbols"]} | {name}
    return name, degree, ints, ineqs, _Names(used)


def _derived(doc, goal, equalities, for_all=None, symbols=None):
    """A `pieces` document of the rewritten goal (the file's WZ certificates kept)."""
    g = copy.deepcopy(goal)
    g["equalities"] = [{"lhs": show(a), "rhs": show(b)} for a, b in equalities]
    if for_all is not None:
        g["for_all"] = for_all
    if symbols is not None:
        g["symbols"] = symbols
    return {"goal": g, "pieces": {"certificates": list(doc["pieces"].get("certificates", []))}}


def _rewrite_goal(goal, lemmas):
    """The goal's equalities with every object rewritten by a lemma; and the ids applied."""
    name, degree, ints, ineqs, names = _goal_parts(goal)
    rw = _Rewriter(ints, ineqs, name, degree, names)
    visit = lambda obj, ctx: rw.apply(lemmas, obj, ctx)  # noqa: E731
    out = []
    for eq in goal["equalities"]:
        out.append(tuple(rw.rewrite(parse(eq[k], [name], strict=True), visit) for k in ("lhs", "rhs")))
    return out, rw.applied


def prove_resting(doc, refs, check_pieces):
    """The proof of a `pieces` file citing the lemmas `refs` (`(id, goal)` pairs) or by
    induction: `(proved, detail)`; raises `PiecesRefused` (through `check_pieces`) when a
    derived goal is refuted, `Unsupported` when the argument is not implemented here."""
    goal = doc.get("goal")
    if not isinstance(goal, dict):
        raise Unsupported("goal: missing")
    var = doc["pieces"].get("induction")
    lemmas = [Lemma(lid, g) for lid, g in refs]
    if var is None:
        eqs, applied = _rewrite_goal(goal, lemmas)
        proved, detail = check_pieces(_derived(doc, goal, eqs))
        used = ", ".join(dict.fromkeys(applied)) or "none"
        return proved, f"{detail}; the goal rewritten with its lemmas' goals assumed (applied: {used}), each application within the lemma's ranges"
    if lemmas:
        raise Unsupported("an induction that also cites lemmas")
    # as for any for-every goal: a range empty at a value evaluated, or a polygon of negative
    # degree there, is refused (the base and step, derived, may have empty ranges)
    from .cert_hyper import check_ranges

    check_ranges(doc)
    return _prove_induction(doc, goal, var, check_pieces)


def _prove_induction(doc, goal, var, check_pieces):
    if len(goal.get("equalities", [])) != 1:
        raise Unsupported("an induction over a chain of equalities")
    ranges = goal["for_all"]
    names_ = [r["name"] for r in ranges]
    if var not in names_:
        raise Unsupported(f"pieces.induction: {var} is not a range symbol of the goal")
    k = names_.index(var)
    lo = parse(ranges[k]["from"], strict=True)
    hi = None if ranges[k].get("to") is None else parse(ranges[k]["to"], strict=True)
    if var in free_names(lo):
        raise Unsupported(f"the range of {var} starts at an expression in {var}")
    name, degree, ints, ineqs, names = _goal_parts(goal)
    if var in free_names(degree):
        raise Unsupported(f"the polygon's degree depends on {var}")
    eq = goal["equalities"][0]
    lhs, rhs = (parse(eq[key], [name], strict=True) for key in ("lhs", "rhs"))
    vv = ("var", var)

    def shifted_ranges(value, own):
        out = []
        for j, r in enumerate(ranges):
            if j == k:
                if own is not None:
                    out.append(own)
                continue
            m = {var: value}
            f = show(subst(parse(r["from"], strict=True), m, names))
            t = None if r.get("to") is None else show(subst(parse(r["to"], strict=True), m, names))
            out.append({"name": r["name"], "from": f, "to": t})
        return out

    def ineqs_of(for_all):
        out = []
        for r in for_all:
            out.append(("sub", ("var", r["name"]), parse(r["from"], strict=True)))
            if r.get("to") is not None:
                out.append(("sub", parse(r["to"], strict=True), ("var", r["name"])))
        return out

    # the base: the goal at v = lo, each object read from the base of its recursion
    base_ranges = shifted_ranges(lo, None)
    base_ints = [n for n in ints if n != var]
    rw = _Rewriter(base_ints, ineqs_of(base_ranges), name, degree, names)

    def at_base(obj, ctx):
        rw.defined(obj, ctx)
        if obj.kind not in ("point", "delta") or not rw.equal(ctx, _recursion_arg(obj), _ZERO_F):
            args = ", ".join(show(a) for a in obj.args)
            raise Unsupported(f"the base: the object {obj.kind}({args}) is not at the base of its recursion")
        return _base_of(obj, name)

    base_eq = [tuple(rw.rewrite(subst(s, {var: lo}, names), at_base) for s in (lhs, rhs))]
    symbols = [s for s in goal["symbols"] if s["name"] != var]
    base = _derived(doc, goal, base_eq, base_ranges, symbols)
    # the step: the goal at v + 1 for v = lo..=hi − 1, objects at v + 1 unfolded once, the
    # goal at v its only hypothesis
    own = {"name": var, "from": ranges[k]["from"], "to": None if hi is None else show(("sub", hi, _ONE_F))}
    step_ranges = shifted_ranges(("add", vv, _ONE_F), None)
    step_ranges.insert(k, own)
    rs = _Rewriter(ints, ineqs_of(step_ranges), name, degree, names)
    hyp = Lemma(f"the hypothesis at {var}", goal, only_at=(var, vv))

    def at_step(obj, ctx):
        rs.defined(obj, ctx)
        if obj.kind in ("point", "delta") and rs.equal(ctx, _recursion_arg(obj), ("add", vv, _ONE_F)):
            return rs.rewrite(_unfold(obj, name), lambda o, c: rs.apply([hyp], o, c), ctx)
        return rs.apply([hyp], obj, ctx)

    up = {var: ("add", vv, _ONE_F)}
    step_eq = [tuple(rs.rewrite(subst(s, up, names), at_step) for s in (lhs, rhs))]
    step = _derived(doc, goal, step_eq, step_ranges)
    p1, d1 = check_pieces(base, skip_empty=True)
    p2, d2 = check_pieces(step, skip_empty=True)
    detail = (
        f"by induction on {var}: the base {var} = {show(lo)} ({show(base_eq[0][0])} = {show(base_eq[0][1])}): {d1}; "
        f"the step {var} → {var} + 1, the goal at {var} its only hypothesis "
        f"({show(step_eq[0][0])} = {show(step_eq[0][1])}): {d2}"
    )
    return p1 and p2, detail
