"""Sets of integer points given by affine inequalities `L ≥ 0` (the pieces of a for-every
proof in `cert_pieces`), decided by Fourier–Motzkin elimination over the rationals with the
integer tightening of each derived inequality (`Σ a·x + c ≥ 0` with `g = gcd(a)` becomes
`Σ (a/g)·x ≥ ⌈−c/g⌉`, true of every integer point). Empty over the rationals implies no
integer point, so `implies` is sound; it may miss an implication that holds only at integer
points (then the proof splits more, or stops undecided)."""

from math import gcd

import sympy

__all__ = ["Domain", "TooLarge"]

#: Most inequalities kept during one elimination.
MAX_ROWS = 4_000


class TooLarge(Exception):
    pass


def _row(expr, syms):
    """`expr` (affine, integer coefficients) as ({symbol: int}, const)."""
    expr = sympy.expand(expr)
    p = sympy.Poly(expr, *syms) if syms else None
    coef = {}
    const = expr
    if p is not None:
        const = p.coeff_monomial(1)
        for i, s in enumerate(syms):
            mono = [0] * len(syms)
            mono[i] = 1
            a = p.coeff_monomial(tuple(mono))
            if a != 0:
                coef[s] = int(a)
    return coef, int(const)


def _tight(coef, const):
    g = 0
    for a in coef.values():
        g = gcd(g, abs(a))
    if g > 1:
        coef = {s: a // g for s, a in coef.items()}
        const = const // g  # Σ a'x ≥ −c/g ⇒ Σ a'x ≥ ⌈−c/g⌉ = −⌊c/g⌋
    return coef, const


def _feasible(rows, syms):
    rows = [_tight(c, k) for c, k in rows]
    for s in syms:
        pos, neg, rest = [], [], []
        for c, k in rows:
            a = c.get(s, 0)
            (pos if a > 0 else neg if a < 0 else rest).append((c, k))
        if len(pos) * len(neg) + len(rest) > MAX_ROWS:
            raise TooLarge()
        new = {}
        for c, k in rest:
            new[(tuple(sorted((str(x), x, a) for x, a in c.items())), k)] = (c, k)
        for cp, kp in pos:
            for cn, kn in neg:
                ap, an = cp[s], -cn[s]
                c = {}
                for x in set(cp) | set(cn):
                    if x == s:
                        continue
                    v = an * cp.get(x, 0) + ap * cn.get(x, 0)
                    if v:
                        c[x] = v
                c, k = _tight(c, an * kp + ap * kn)
                new[(tuple(sorted((str(x), x, a) for x, a in c.items())), k)] = (c, k)
        rows = list(new.values())
        for c, k in rows:
            if not c and k < 0:
                return False
    return all(k >= 0 for c, k in rows if not c)


class Domain:
    """Inequalities `L ≥ 0` over the integer symbols `syms` (SymPy), and the substitution that
    made earlier equalities explicit (`sub`: an eliminated symbol to its affine value)."""

    def __init__(self, syms, ineqs=(), sub=None):
        self.syms = list(syms)
        self.ineqs = [sympy.expand(x) for x in ineqs]
        self.sub = dict(sub or {})

    def rows(self, extra=()):
        return [_row(x, self.syms) for x in list(self.ineqs) + list(extra)]

    def feasible(self, extra=()):
        rows = self.rows(extra)
        for c, k in rows:
            if not c and k < 0:
                return False
        return _feasible(rows, self.syms)

    def implies(self, expr):
        """Whether `expr ≥ 0` at every integer point."""
        return not self.feasible([-expr - 1])

    def sign(self, expr):
        """+1 if `expr ≥ 1` everywhere, -1 if `≤ −1`, 0 if `= 0`, None if undecided."""
        expr = sympy.expand(expr)
        if expr.is_Integer:
            v = int(expr)
            return (v > 0) - (v < 0)
        if self.implies(expr - 1):
            return 1
        if self.implies(-expr - 1):
            return -1
        if self.implies(expr) and self.implies(-expr):
            return 0
        return None

    def with_(self, *ineqs, add_syms=()):
        return Domain(self.syms + list(add_syms), self.ineqs + list(ineqs), self.sub)

    def substitute(self, var, value):
        """The domain with `var = value` (affine in the other symbols) substituted."""
        m = {var: value}
        sub = {k: sympy.expand(v.xreplace(m)) for k, v in self.sub.items()}
        sub[var] = value
        return Domain([s for s in self.syms if s != var], [x.xreplace(m) for x in self.ineqs], sub)

    def equality(self):
        """An inequality that holds with equality at every point, solved: (var, value) for a
        symbol of coefficient ±1, or None."""
        for x in self.ineqs:
            if x.is_Integer or not self.implies(-x):
                continue
            coef, _ = _row(x, self.syms)
            for s, a in coef.items():
                if abs(a) == 1:
                    return s, sympy.expand(s - x / a)
        return None

    def show(self):
        parts = [f"{x} >= 0" for x in self.ineqs if not x.is_Integer]
        parts += [f"{k} = {v}" for k, v in self.sub.items() if not str(k).startswith("%")]
        return ", ".join(parts) or "everywhere"
