"""Method `computation` (docs/certificates.md): facts the program took from a named library
computation, re-derived here from their inputs by the rules the docs state, with `Fraction`
(standard library only), sharing nothing with the program.

- `ImplicitConic::kind`: the equation `lhs = rhs` in x, y is expanded here (its coefficients
  `A, …, F` of `lhs − rhs` must be the listed ones); the type follows from `B² − 4AC` and the
  determinant of the conic's 3×3 matrix.
- `classify_conic`: the type of the rational quadratic with the listed control points and
  weights, from collinearity, zero weights and the sign of `w1² − w0 w2`.
"""

from fractions import Fraction

from .cert_expand import expand_side
from .cert_expr import free_names, parse

__all__ = ["check_computation", "implicit_kind", "weights_kind"]


def implicit_kind(a, b, c, d, e, f):
    """The type of `A x² + B xy + C y² + D x + E y + F = 0`."""
    if a == b == c == 0:
        return "not a conic (no quadratic terms)"
    m = [[a, b / 2, d / 2], [b / 2, c, e / 2], [d / 2, e / 2, f]]
    det = (
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
        - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
        + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    )
    if det == 0:
        return "degenerate"
    disc = b * b - 4 * a * c
    if disc == 0:
        return "parabola"
    if disc > 0:
        return "hyperbola"
    return "ellipse" if (a + c) * det < 0 else "imaginary ellipse (no real points)"


def weights_kind(points, weights):
    """The type of the conic of a rational quadratic Bézier curve."""
    p0, p1, p2 = points
    u = [x - y for x, y in zip(p1, p0)]
    v = [x - y for x, y in zip(p2, p0)]
    if all(u[i] * v[j] == u[j] * v[i] for i in range(len(u)) for j in range(i + 1, len(u))):
        return "degenerate (collinear control points)"
    w0, w1, w2 = weights
    if 0 in (w0, w1, w2):
        return "degenerate (zero weight)"
    excess = w1 * w1 - w0 * w2
    return "parabola" if excess == 0 else "hyperbola" if excess > 0 else "ellipse"


_SLOTS = {(2, 0): 0, (1, 1): 1, (0, 2): 2, (1, 0): 3, (0, 1): 4, (0, 0): 5}


def _coefficients(lhs, rhs, need, at):
    value = expand_side(("sub", lhs, rhs), ["x", "y"], {})
    need(not isinstance(value, (tuple, list)) and hasattr(value, "num"), f"{at}: the equation is not a number")
    dens = list(value.den.items())
    need(dens == [((0, 0), Fraction(1))], f"{at}: lhs − rhs is not a polynomial in x, y")
    out = [Fraction(0)] * 6
    for e, k in value.num.items():
        need(e in _SLOTS, f"{at}: lhs − rhs has degree above 2 in x, y: not a conic")
        out[_SLOTS[e]] = k
    return out


def check_computation(doc, need, rational):
    """Re-derives every listed fact; returns the detail line (refuses through `need`)."""
    data = doc.get("computation")
    need(isinstance(data, dict) and isinstance(data.get("facts"), list) and data["facts"], "computation: facts missing")
    rests = doc.get("rests_on")
    need(isinstance(rests, list), "rests_on: missing")
    for k, fact in enumerate(data["facts"]):
        at = f"computation.facts[{k}]"
        need(isinstance(fact, dict) and isinstance(fact.get("kind"), str), f"{at}: kind missing")
        name = fact.get("computation")
        need(name in rests, f"{at}: {name!r} is not named in rests_on")
        if name == "ImplicitConic::kind":
            sides = []
            for key in ("lhs", "rhs"):
                need(isinstance(fact.get(key), str), f"{at}.{key}: missing")
                e = parse(fact[key], ["x", "y"], strict=True)
                need(free_names(e) <= {"x", "y"}, f"{at}.{key}: names other than x, y")
                sides.append(e)
            coef = _coefficients(sides[0], sides[1], need, at)
            listed = fact.get("coefficients")
            need(isinstance(listed, list) and len(listed) == 6, f"{at}.coefficients: not six numbers")
            listed = [rational(x, f"{at}.coefficients") for x in listed]
            need(listed == coef, f"{at}.coefficients: {listed}, the equation's are {coef}")
            got = implicit_kind(*coef)
        elif name == "classify_conic":
            pts, ws = fact.get("points"), fact.get("weights")
            need(isinstance(pts, list) and len(pts) == 3, f"{at}.points: not three control points")
            need(all(isinstance(p, list) and p and len(p) == len(pts[0]) for p in pts), f"{at}.points: not of one dimension")
            need(isinstance(ws, list) and len(ws) == 3, f"{at}.weights: not three weights")
            pts = [[rational(x, f"{at}.points") for x in p] for p in pts]
            got = weights_kind(pts, [rational(w, f"{at}.weights") for w in ws])
        else:
            need(False, f"{at}: the computation {name!r} is not one this checker knows")
        need(got == fact["kind"], f"{at}: the type is {got!r}, the file says {fact['kind']!r}")
    n = len(data["facts"])
    return f"{n} library computation{'s' if n > 1 else ''} re-derived here from the listed inputs: the same type"
