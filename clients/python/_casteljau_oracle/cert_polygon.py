"""Goals with symbolic control points (docs/certificates.md, "Control points"), checked here
independently: the sides must be affine in the control points (a degree bound of at most 1 in
all of them together, none in a denominator), and are evaluated on the zero polygon and on
each unit polygon (one listed control point 1, every other 0). An affine function that is 0
on all of these is 0 for every value of the control points; on each of them, the sides are
polynomials in the params, equal on a grid larger than their degree. A control point the
equality does not list is 0.
"""

from fractions import Fraction

from .cert_degree import _Deg
from .cert_expr import deep

SORT = "control_points"


class PolygonError(ValueError):
    """Control points that are not well formed (the message names the obligation)."""


def read_points(eq, sorts, where):
    """The equality's control points as (name, index tuple), in the unit polygons' order."""
    listed = eq.get("control_points", [])
    if not isinstance(listed, list) or ("control_points" in eq and not listed):
        raise PolygonError(f"{where}: control_points is not a non-empty list")
    out = []
    for p in listed:
        ok = isinstance(p, dict) and set(p) == {"name", "index"} and isinstance(p["index"], list)
        if not ok or sorts.get(p.get("name")) != SORT:
            raise PolygonError(f"{where}: a control point {p!r} is not a name of sort {SORT} and an index")
        idx = p["index"]
        if not idx or not all(isinstance(i, int) and not isinstance(i, bool) for i in idx):
            raise PolygonError(f"{where}: control point {p['name']}{idx}: the index is not a list of integers")
        key = (p["name"], tuple(idx))
        if key in out:
            raise PolygonError(f"{where}: control point {p['name']}{idx} listed twice")
        out.append(key)
    return out


def objects(points, k):
    """The control points at basis polygon `k`: 0 the zero polygon, `j + 1` the unit one of
    the j-th listed point (a dict per name, index tuple -> value; unlisted points are 0)."""
    out = {name: {} for name, _ in points}
    for j, (name, idx) in enumerate(points):
        out[name][idx] = Fraction(1 if k == j + 1 else 0)
    return out


class _PointsDeg(_Deg):
    """The degree bound in all control points together (each a variable of degree 1)."""

    def __init__(self, names, ints):
        super().__init__("\0control points", dict(ints), {})
        self.names = names

    def go(self, e):
        if e[0] == "index" and e[1] in self.names:
            for a in e[2]:
                self.constant(a, "an index")
            return (1, 0)
        if e[0] == "call" and e[1] == "delta" and e[2][0][0] == "var" and e[2][0][1] in self.names:
            return (1, 0)  # a combination of the control points
        return super().go(e)


def check_affine(side, names, ints, where):
    """Refuses a side that is not affine in the control points (by its degree bound)."""
    with deep():
        p, q = _PointsDeg(set(names), ints).go(side)
    if q != 0 or p > 1:
        raise PolygonError(f"{where}: the side is not affine in the control points (degree bound {p}/{q})")


def unlisted_to_zero(value, points, declared):
    """A SymPy value with every control point the equality does not list set to 0 (SymPy
    names a point `b[i, j]` `b_i_j`; a name that is a declared symbol is kept)."""
    import sympy

    listed = {name + "_" + "_".join(str(i) for i in idx) for name, idx in points}
    names = {name for name, _ in points}

    def fix(v):
        if isinstance(v, (list, tuple)):
            return [fix(x) for x in v]
        if isinstance(v, sympy.MatrixBase):
            return v.applyfunc(fix)
        zero = {
            s: 0
            for s in v.free_symbols
            if s.name not in listed and s.name not in declared and any(s.name.startswith(n + "_") for n in names)
        }
        return v.subs(zero) if zero else v

    return fix(value)
