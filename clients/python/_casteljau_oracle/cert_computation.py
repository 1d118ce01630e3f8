"""Method `computation` (docs/certificates.md): facts the program took from a named library
computation, re-derived here from their inputs by the rules the docs state, with `Fraction`
(standard library only), sharing nothing with the program.

- `ImplicitConic::kind`: the equation `lhs = rhs` in x, y is expanded here (its coefficients
  `A, …, F` of `lhs − rhs` must be the listed ones); the type follows from `B² − 4AC` and the
  determinant of the conic's 3×3 matrix.
- `classify_conic`: the type of the rational quadratic with the listed control points and
  weights, from collinearity, zero weights and the sign of `w1² − w0 w2`; a number may be
  `a + b√d` (`{"rational", "irrational", "radicand"}`, d square-free, not 0 or 1), computed
  here as the pair (a, b) in Q(√d).
- `fit_cubic`: text 004's cubic fit: the data `x(0), x(1), x(1/2), ẋ(0), ẋ(1)` derived here
  from the curve (Bernstein form; `ẋ(0) = n w1/w0 (b1 − b0)`, `ẋ(1) = n w_{n−1}/w_n (b_n −
  b_{n−1})`), the normal equations `M = 3/4 G`, `r = (ẋ(0)·X, ẋ(1)·X)` with `X = x(0) + x(1) −
  2 x(1/2)` and `G` the Gram matrix of `ẋ(0), ẋ(1)`, then `M·(−k, l) = r`, `det M ≠ 0` and
  `δ² = |a(1/2) − x(1/2)|²` with `a(1/2) = (x0 + 3(x0 + k ẋ(0)) + 3(x1 − l ẋ(1)) + x1)/8`.
- `convex_combination` and `affine_invariance` (text 000, resting on cited lemmas): the cited
  goals must be the ones docs/certificates.md states (their files are checked by
  `cert_links`); then, for every degree n of `degrees`, this checker proves the statement
  itself: `Σ_i B_i^n = 1` and every `B_i^n` with Bernstein coefficients ≥ 0 (as polynomials
  here), and `Φ(Σ b_i B_i^n) = Σ Φ(b_i) B_i^n` as polynomials in t for the 4 matrix units ×
  2(n+1) unit polygons and the 2 translations (both sides are affine in each of A, c and
  the polygon, so these span every case).
"""

from fractions import Fraction
from math import comb, isqrt

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
    if any(w == 0 for w in (w0, w1, w2)):
        return "degenerate (zero weight)"
    excess = w1 * w1 - w0 * w2
    sign = excess.sign() if isinstance(excess, _Sqrt) else (excess > 0) - (excess < 0)
    return "parabola" if sign == 0 else "hyperbola" if sign > 0 else "ellipse"


class _Sqrt:
    """a + b√d with rational a, b and one square-free d (exact; d > 0 for a sign)."""

    __slots__ = ("a", "b", "d")

    def __init__(self, a, b=Fraction(0), d=None):
        self.a, self.b, self.d = Fraction(a), Fraction(b), d

    def _lift(self, o):
        o = o if isinstance(o, _Sqrt) else _Sqrt(o)
        d = self.d if self.d is not None else o.d
        if self.d is not None and o.d is not None and self.d != o.d:
            raise ValueError(f"numbers of two fields, √{self.d} and √{o.d}")
        return o, d

    def __add__(self, o):
        o, d = self._lift(o)
        return _Sqrt(self.a + o.a, self.b + o.b, d)

    def __sub__(self, o):
        o, d = self._lift(o)
        return _Sqrt(self.a - o.a, self.b - o.b, d)

    def __mul__(self, o):
        o, d = self._lift(o)
        return _Sqrt(self.a * o.a + self.b * o.b * (d or 0), self.a * o.b + self.b * o.a, d)

    def __eq__(self, o):
        o, _ = self._lift(o)
        return self.a == o.a and self.b == o.b

    def sign(self):
        if self.b == 0:
            return (self.a > 0) - (self.a < 0)
        if self.d < 0:
            raise ValueError(f"√{self.d} is not real: no sign")
        sa, sb = (self.a > 0) - (self.a < 0), (self.b > 0) - (self.b < 0)
        if sa == 0 or sa == sb:
            return sb
        # a and b√d of opposite signs: the larger square wins
        diff = self.a * self.a - self.b * self.b * self.d
        return sa if diff > 0 else sb if diff < 0 else 0


def _square_free(d):
    m = abs(d)
    return all(m % (k * k) for k in range(2, isqrt(m) + 1))


def _number(x, rational, need, at):
    if isinstance(x, str):
        return _Sqrt(rational(x, at))
    need(isinstance(x, dict) and set(x) == {"rational", "irrational", "radicand"}, f"{at}: not p/q nor rational, irrational, radicand")
    d = x["radicand"]
    need(isinstance(d, str) and d.lstrip("-").isdigit(), f"{at}.radicand: not an integer")
    d = int(d)
    need(d not in (0, 1) and _square_free(d), f"{at}.radicand: {d} is not square-free other than 0 and 1 (√d would be rational)")
    a, b = rational(x["rational"], f"{at}.rational"), rational(x["irrational"], f"{at}.irrational")
    need(b != 0, f"{at}: a rational number is written as p/q")
    return _Sqrt(a, b, d)


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


def _vec(v, rational, at):
    return [rational(x, at) for x in v]


def _dot(u, v):
    return sum((x * y for x, y in zip(u, v)), Fraction(0))


def fit_data(points, weights):
    """x(0), x(1), x(1/2), ẋ(0), ẋ(1) of the curve (weights None: a polynomial curve)."""
    n = len(points) - 1
    w = weights or [Fraction(1)] * (n + 1)

    def at(t):
        den = sum(w[i] * comb(n, i) * t**i * (1 - t) ** (n - i) for i in range(n + 1))
        return [sum(w[i] * comb(n, i) * t**i * (1 - t) ** (n - i) * p[c] for i, p in enumerate(points)) / den for c in range(len(points[0]))]

    d0 = [n * w[1] / w[0] * (y - x) for x, y in zip(points[0], points[1])]
    d1 = [n * w[n - 1] / w[n] * (y - x) for x, y in zip(points[n - 1], points[n])]
    return {"x0": at(Fraction(0)), "x1": at(Fraction(1)), "xh": at(Fraction(1, 2)), "d0": d0, "d1": d1}


def _check_fit(fact, need, rational, at):
    pts, ws = fact.get("points"), fact.get("weights")
    need(isinstance(pts, list) and len(pts) >= 2, f"{at}.points: fewer than two control points")
    need(all(isinstance(p, list) and len(p) >= 2 and len(p) == len(pts[0]) for p in pts), f"{at}.points: not of one dimension ≥ 2")
    pts = [_vec(p, rational, f"{at}.points") for p in pts]
    if ws is not None:
        need(isinstance(ws, list) and len(ws) == len(pts), f"{at}.weights: not one per control point")
        ws = _vec(ws, rational, f"{at}.weights")
        need(ws[0] != 0 and ws[-1] != 0, f"{at}.weights: an end weight is 0")
    data = fit_data(pts, ws)
    listed = fact.get("data")
    need(isinstance(listed, dict) and set(listed) == set(data), f"{at}.data: not x0, x1, xh, d0, d1")
    for key, v in data.items():
        got = _vec(listed[key], rational, f"{at}.data.{key}") if isinstance(listed[key], list) else None
        need(got == v, f"{at}.data.{key}: {got}, the curve gives {v}")
    x0, x1, xh, d0, d1 = (data[k] for k in ("x0", "x1", "xh", "d0", "d1"))
    big_x = [a + b - 2 * c for a, b, c in zip(x0, x1, xh)]
    m = [[Fraction(3, 4) * _dot(u, v) for v in (d0, d1)] for u in (d0, d1)]
    r = [_dot(d0, big_x), _dot(d1, big_x)]
    eqs = fact.get("normal_equations")
    need(isinstance(eqs, dict) and isinstance(eqs.get("matrix"), list) and len(eqs["matrix"]) == 2, f"{at}.normal_equations: not a 2×2 matrix and rhs")
    need([_vec(row, rational, f"{at}.normal_equations.matrix") for row in eqs["matrix"]] == m, f"{at}.normal_equations.matrix: not 3/4 of the Gram matrix of ẋ(0), ẋ(1)")
    need(isinstance(eqs.get("rhs"), list) and _vec(eqs["rhs"], rational, f"{at}.normal_equations.rhs") == r, f"{at}.normal_equations.rhs: not (ẋ(0)·X, ẋ(1)·X)")
    k, l = (rational(fact.get(key), f"{at}.{key}") for key in ("k", "l"))
    for i in range(2):
        need(m[i][0] * -k + m[i][1] * l == r[i], f"{at}: row {i} of the normal equations fails at k = {k}, l = {l}")
    need(m[0][0] * m[1][1] - m[0][1] * m[1][0] != 0, f"{at}: the normal equations are singular")
    a1 = [x + k * d for x, d in zip(x0, d0)]
    a2 = [x - l * d for x, d in zip(x1, d1)]
    mid = [(p + 3 * q + 3 * s + t) / 8 for p, q, s, t in zip(x0, a1, a2, x1)]
    d2 = sum(((a - b) ** 2 for a, b in zip(mid, xh)), Fraction(0))
    need(rational(fact.get("delta2"), f"{at}.delta2") == d2, f"{at}.delta2: δ² at (k, l) is {d2}")


#: The facts resting on cited lemmas: what each rests on in the library.
_LEMMA_FACTS = {"convex_combination": "bernstein_all", "affine_invariance": "BezierCurve::transform"}
#: Largest degree checked (as the program's limit).
_MAX_DEGREE = 64
_NONNEG_GOAL = {
    "relation": ">=",
    "symbols": [{"name": "t", "sort": "real"}, {"name": "n", "sort": "integer"}, {"name": "i", "sort": "integer"}],
    "for_all": [{"name": "n", "from": "0", "to": None}, {"name": "i", "from": "0", "to": "n"}],
    "interval": {"name": "t", "from": "0", "to": "1"},
    "inequality": {"lhs": "B(i, n, t)", "rhs": "0"},
}


def _unity_goal(goal, lo):
    """Whether `goal` is `Σ_{i=0}^{n} B(i, n, t) = 1` for every real t and n ≥ n0, n0 ≤ lo."""
    if not isinstance(goal, dict) or set(goal) - {"relation", "symbols", "for_all", "equalities"}:
        return False
    ranges = goal.get("for_all")
    ok_range = (
        isinstance(ranges, list) and len(ranges) == 1 and isinstance(ranges[0], dict)
        and ranges[0].get("name") == "n" and ranges[0].get("to") is None
        and isinstance(ranges[0].get("from"), str) and ranges[0]["from"].lstrip("-").isdigit()
        and int(ranges[0]["from"]) <= lo
    )
    return (
        ok_range
        and goal.get("relation") == "="
        and goal.get("symbols") == [{"name": "t", "sort": "real"}, {"name": "n", "sort": "integer"}]
        and goal.get("equalities") == [{"lhs": "sum(i, 0, n, B(i, n, t))", "rhs": "1"}]
    )


def _poly_eq(a, b):
    n = max(len(a), len(b))
    return all((a[k] if k < len(a) else 0) == (b[k] if k < len(b) else 0) for k in range(n))


def _bern(i, n):
    """B_i^n in the power basis (lowest degree first)."""
    return [Fraction(comb(n, i) * comb(n - i, k - i) * (-1) ** (k - i)) if k >= i else Fraction(0) for k in range(n + 1)]


def _check_lemma_fact(doc, fact, name, need, at):
    rests = doc.get("rests_on")
    need(_LEMMA_FACTS[name] in rests, f"{at}: rests on {_LEMMA_FACTS[name]}, not named in rests_on")
    deg = fact.get("degrees")
    need(isinstance(deg, dict), f"{at}.degrees: missing")
    try:
        lo, hi = int(deg.get("from")), int(deg.get("to"))
    except (TypeError, ValueError):
        need(False, f"{at}.degrees: not integers")
    need(0 <= lo <= hi <= _MAX_DEGREE, f"{at}.degrees: not 0 ≤ from ≤ to ≤ {_MAX_DEGREE}")
    lemmas = doc.get("lemmas")
    need(isinstance(lemmas, list), f"{at}: the lemmas it cites are missing")
    cited = {x.get("id"): x.get("goal") for x in lemmas if isinstance(x, dict)}

    def goal_of(key):
        lid = fact.get(key)
        need(isinstance(lid, str) and lid in cited, f"{at}.{key}: lemma {lid!r} is not among the file's lemmas")
        return cited[lid]

    need(_unity_goal(goal_of("sum_one"), lo), f"{at}.sum_one: the lemma's goal is not Σ B(i, n, t) = 1 for every n ≥ 0")
    if name == "convex_combination":
        need(goal_of("nonnegative") == _NONNEG_GOAL, f"{at}.nonnegative: the lemma's goal is not B(i, n, t) ≥ 0 on [0, 1]")
    for n in range(lo, hi + 1):
        basis = [_bern(i, n) for i in range(n + 1)]
        total = [sum(b[k] for b in basis) for k in range(n + 1)]
        need(_poly_eq(total, [Fraction(1)]), f"{at}: Σ_i B_i^{n} is not 1")
        if name == "convex_combination":
            # B_i^n has the Bernstein coefficients of the unit vector e_i on [0, 1].
            for i, b in enumerate(basis):
                coeffs = [sum(b[k] * Fraction(comb(j, k), comb(n, k)) for k in range(j + 1)) for j in range(n + 1)]
                need(all(c >= 0 for c in coeffs), f"{at}: B_{i}^{n} has a negative Bernstein coefficient")
        else:
            _check_affine(n, basis, need, at)


def _check_affine(n, basis, need, at):
    """Φ(Σ b_i B_i) = Σ Φ(b_i) B_i as polynomials in t, on the basis maps and polygons (plane)."""
    dim = 2
    maps = []
    for r in range(dim):
        for c in range(dim):
            maps.append(([[Fraction(int(a == r and b == c)) for b in range(dim)] for a in range(dim)], [Fraction(0)] * dim))
        maps.append(([[Fraction(0)] * dim for _ in range(dim)], [Fraction(int(a == r)) for a in range(dim)]))
    polygons = [[[Fraction(0)] * dim for _ in range(n + 1)]]
    for k in range(n + 1):
        for c in range(dim):
            polygons.append([[Fraction(int(i == k and a == c)) for a in range(dim)] for i in range(n + 1)])
    apply = lambda m, p: [sum(m[0][a][b] * p[b] for b in range(dim)) + m[1][a] for a in range(dim)]  # noqa: E731
    for m in maps:
        for pts in polygons:
            for a in range(dim):
                # Φ(b(t))_a = Σ_b A_ab b(t)_b + c_a, with b(t)_b = Σ_i pts[i][b] B_i(t).
                curve = [[sum(pts[i][b] * basis[i][k] for i in range(n + 1)) for k in range(n + 1)] for b in range(dim)]
                left = [sum(m[0][a][b] * curve[b][k] for b in range(dim)) + (m[1][a] if k == 0 else 0) for k in range(n + 1)]
                moved = [apply(m, p) for p in pts]
                right = [sum(moved[i][a] * basis[i][k] for i in range(n + 1)) for k in range(n + 1)]
                need(_poly_eq(left, right), f"{at}: Φ(Σ b_i B_i^{n}) ≠ Σ Φ(b_i) B_i^{n} for a basis map and polygon")


def check_computation(doc, need, rational):
    """Re-derives every listed fact; returns the detail line (refuses through `need`)."""
    data = doc.get("computation")
    need(isinstance(data, dict) and isinstance(data.get("facts"), list) and data["facts"], "computation: facts missing")
    rests = doc.get("rests_on")
    need(isinstance(rests, list), "rests_on: missing")
    for k, fact in enumerate(data["facts"]):
        at = f"computation.facts[{k}]"
        name = fact.get("computation") if isinstance(fact, dict) else None
        if name in _LEMMA_FACTS:
            _check_lemma_fact(doc, fact, name, need, at)
            continue
        need(isinstance(fact, dict) and (name == "fit_cubic" or isinstance(fact.get("kind"), str)), f"{at}: kind missing")
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
            pts = [[_number(x, rational, need, f"{at}.points") for x in p] for p in pts]
            try:
                got = weights_kind(pts, [_number(w, rational, need, f"{at}.weights") for w in ws])
            except ValueError as e:
                need(False, f"{at}: {e}")
        elif name == "fit_cubic":
            _check_fit(fact, need, rational, at)
            got = fact.get("kind")
        else:
            need(False, f"{at}: the computation {name!r} is not one this checker knows")
        need(got == fact.get("kind"), f"{at}: the type is {got!r}, the file says {fact.get('kind')!r}")
    n = len(data["facts"])
    lemma_facts = [f.get("computation") for f in data["facts"] if f.get("computation") in _LEMMA_FACTS]
    if lemma_facts:
        return (f"{', '.join(lemma_facts)}: the cited lemmas' goals are the documented ones, and the statement "
                f"proved here for every degree listed (Σ B_i^n = 1 and the basis as polynomials)")
    return f"{n} library computation{'s' if n > 1 else ''} re-derived here from the listed inputs: the same result"
