"""Verdict `verified` (docs/certificates.md, "Verdict `verified`"): the bounded evidence of
Theorem 1.2, re-derived here with `Fraction` (standard library only), sharing nothing with the
program. For each listed curve of degree n and each r = 0..=steps: the r-times degree-elevated
polygon (b'_i = i/(m+1) b_{i-1} + (1 - i/(m+1)) b_i per step from degree m), the curve
evaluated in Bernstein form at i/(n+r), their largest coordinate difference (the max-norm
distance) must be the listed one, never increase with r, and be at most the bound
n(n-1)/(2(n+r)) * max_j |Δ²b_j|_∞ (0 for n < 2). Evidence for the limit, not a proof: the file
stays `verified`.
"""

from fractions import Fraction
from math import comb

__all__ = ["check_convergence", "MAX_STEPS"]

#: Most elevation steps a file may ask for.
MAX_STEPS = 512


def _eval(points, t):
    n = len(points) - 1
    out = [Fraction(0)] * len(points[0])
    for i, p in enumerate(points):
        b = comb(n, i) * t**i * (1 - t) ** (n - i)
        out = [o + b * x for o, x in zip(out, p)]
    return out


def _elevate(points):
    m = len(points) - 1
    dim = len(points[0])
    out = []
    for i in range(m + 2):
        a = Fraction(i, m + 1)
        prev = points[i - 1] if i > 0 else [Fraction(0)] * dim
        cur = points[i] if i <= m else [Fraction(0)] * dim
        out.append([a * x + (1 - a) * y for x, y in zip(prev, cur)])
    return out


def _bound(points, r):
    n = len(points) - 1
    if n < 2:
        return Fraction(0)
    d2 = [[points[j + 2][c] - 2 * points[j + 1][c] + points[j][c] for c in range(len(points[0]))] for j in range(n - 1)]
    m = max(abs(x) for row in d2 for x in row)
    return Fraction(n * (n - 1), 2 * (n + r)) * m


def distances(points, steps):
    """The max-norm distances for r = 0..=steps."""
    out = []
    elevated = points
    for r in range(steps + 1):
        if r > 0:
            elevated = _elevate(elevated)
        total = len(elevated) - 1
        worst = Fraction(0)
        for i, p in enumerate(elevated):
            t = Fraction(i, total) if total else Fraction(0)
            on = _eval(points, t)
            worst = max([worst] + [abs(x - y) for x, y in zip(p, on)])
        out.append(worst)
    return out


def check_convergence(data, need, rational):
    """Re-derives the bounded evidence; returns the detail line (refuses through `need`)."""
    need(isinstance(data, dict), "convergence: missing")
    steps = data.get("steps")
    ok = isinstance(steps, int) and not isinstance(steps, bool) and 0 <= steps <= MAX_STEPS
    need(ok, f"convergence.steps: not an integer 0..={MAX_STEPS}")
    curves = data.get("curves")
    need(isinstance(curves, list) and curves, "convergence.curves: none")
    names = []
    for k, c in enumerate(curves):
        at = f"convergence.curves[{k}]"
        need(isinstance(c, dict) and isinstance(c.get("name"), str), f"{at}: name missing")
        pts = c.get("points")
        need(isinstance(pts, list) and pts and all(isinstance(p, list) and p and len(p) == len(pts[0]) for p in pts), f"{at}.points: not control points of one dimension")
        pts = [[rational(x, f"{at}.points") for x in p] for p in pts]
        listed = c.get("distances")
        need(isinstance(listed, list) and len(listed) == steps + 1, f"{at}.distances: not one per r = 0..={steps}")
        listed = [rational(x, f"{at}.distances") for x in listed]
        got = distances(pts, steps)
        for r, (l, g) in enumerate(zip(listed, got)):
            need(l == g, f"{at}: at r = {r} the distance is {g}, the file says {l}")
            need(g <= _bound(pts, r), f"{at}: at r = {r} the distance {g} exceeds the bound {_bound(pts, r)}")
        for r in range(steps):
            need(got[r + 1] <= got[r], f"{at}: the distance grows from r = {r} to r = {r + 1}")
        names.append(c["name"])
    return f"verified (bounded evidence, not a proof): {', '.join(names)}, r = 0..={steps}: distances re-derived, non-increasing, within the bound"
