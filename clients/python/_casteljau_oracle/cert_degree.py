"""Degree bounds re-derived from an expression (standard library only).

An expression that is a rational function of the parameter `t` (its other names fixed) gets a
bound `(p, q)`: it can be written `P/Q` with `deg_t P <= p` and `deg_t Q <= q`. The rules are
those of a textbook: `P1/Q1 ± P2/Q2 = (P1 Q2 ± P2 Q1)/(Q1 Q2)`, products add, quotients
cross, `(P/Q)^k` multiplies by `k`, `B(i, n, g) = C(n, i) P^i (Q - P)^(n-i) / Q^n` for
`g = P/Q`, a Bézier curve of degree n at `g` is `n` times `g`'s bound (a rational curve's
numerator and denominator both), and so on. The identity `L = R` cleared of denominators is
`P_L Q_R - P_R Q_L`, of degree at most `max(p_L + q_R, p_R + q_L)` (`cleared_degree`).

Integer names (range and summation variables) must have values in `ints`; an expression
whose degree depends on a symbolic integer raises `Unsupported`.
"""

from fractions import Fraction

from .cert_expr import deep, free_names

from .cert_eval import Curve, EvalError, Surface, Unsupported, _partial, _primes, evaluate

__all__ = ["degree", "cleared_degree"]


def cleared_degree(lhs, rhs, var, ints=None, objects=None):
    """A bound on the degree in `var` of `lhs - rhs` cleared of denominators."""
    pl, ql = degree(lhs, var, ints, objects)
    pr, qr = degree(rhs, var, ints, objects)
    if ql == 0 and qr == 0:
        return max(pl, pr)
    return max(pl + qr, pr + ql)


def degree(e, var, ints=None, objects=None):
    """The bound `(p, q)` of `e` as a rational function of `var`."""
    with deep():
        return _Deg(var, dict(ints or {}), objects or {}).go(e)


def _add(a, b):
    if a[1] == 0 and b[1] == 0:
        return (max(a[0], b[0]), 0)
    return (max(a[0] + b[1], b[0] + a[1]), a[1] + b[1])


class _Deg:
    def __init__(self, var, ints, objects):
        self.var = var
        self.ints = ints
        self.objects = objects

    def integer(self, e, what):
        try:
            v = evaluate(e, {k: Fraction(x) for k, x in self.ints.items()})
        except EvalError as err:
            raise Unsupported(f"{what} is not a known integer here ({err})") from None
        if not isinstance(v, Fraction) or v.denominator != 1:
            raise Unsupported(f"{what} is not an integer")
        return int(v)

    def uses_var(self, e):
        return self.var in free_names(e)

    def go(self, e):
        kind = e[0]
        if kind == "num":
            return (0, 0)
        if kind == "var":
            return (1, 0) if e[1] == self.var else (0, 0)
        if kind == "neg":
            return self.go(e[1])
        if kind in ("add", "sub"):
            return _add(self.go(e[1]), self.go(e[2]))
        if kind == "mul":
            a, b = self.go(e[1]), self.go(e[2])
            return (a[0] + b[0], a[1] + b[1])
        if kind == "div":
            a, b = self.go(e[1]), self.go(e[2])
            return (a[0] + b[1], a[1] + b[0])
        if kind == "pow":
            if self.uses_var(e[2]):
                raise Unsupported(f"an exponent depending on {self.var}")
            a = self.go(e[1])
            if a == (0, 0):
                return a
            k = self.integer(e[2], "an exponent")
            return (k * a[0], k * a[1]) if k >= 0 else (-k * a[1], -k * a[0])
        if kind == "fact":
            return self.constant(e, "a factorial")
        if kind in ("tuple", "matrix"):
            items = e[1] if kind == "tuple" else [a for r in e[1] for a in r]
            bounds = [self.go(a) for a in items]
            # componentwise: the largest numerator and denominator bound cover every component
            return (max(b[0] for b in bounds), max(b[1] for b in bounds))
        if kind == "sum":
            _, v, lo, hi, body = e
            a, b = self.integer(lo, "a sum's bound"), self.integer(hi, "a sum's bound")
            acc = None
            saved = self.ints.get(v)
            try:
                for k in range(a, b + 1):
                    self.ints[v] = k
                    term = self.go(body)
                    acc = term if acc is None else _add(acc, term)
            finally:
                if saved is None:
                    self.ints.pop(v, None)
                else:
                    self.ints[v] = saved
            return acc or (0, 0)
        if kind == "index":
            for a in e[2]:
                self.constant(a, "an index")
            return (0, 0)
        if kind == "call":
            return self.call(e)
        raise Unsupported(f"the degree of a '{kind}'")

    def constant(self, e, what):
        if self.uses_var(e):
            raise Unsupported(f"{what} depending on {self.var}")
        return (0, 0)

    def call(self, e):
        name, args = e[1], e[2]
        if name in ("B", "__dB"):
            # as documented, whatever i is (a zero B keeps the bound of degree n)
            self.constant(args[0], "a Bernstein index")
            n = max(self.integer(args[1], "a Bernstein degree"), 0)
            if name == "__dB":
                # the k-th derivative of a polynomial of degree n has degree n - k
                n = max(n - self.integer(args[3], "a derivative's order"), 0)
            p, q = self.go(args[2])
            return (n * max(p, q), n * q)
        if name == "__dpow":
            e = self.integer(args[1], "an exponent") - self.integer(args[2], "a derivative's order")
            p, q = self.go(args[0])
            return (e * p, e * q) if e >= 0 else (-e * q, -e * p)
        if name == "delta":
            # a combination of control points: constant in the parameter (its k and j too)
            for x in args[1:]:
                self.constant(x, "delta's order or index")
            return (0, 0)
        if name in ("C", "binom", "sqrt", "integral"):
            return self.constant(e, name)
        if name == "dot":
            a, b = self.go(args[0]), self.go(args[1])
            return self.repeat_add((a[0] + b[0], a[1] + b[1]), args[0])
        if name == "comp":
            return self.go(args[0])
        if name in ("rows", "cols", "transpose"):
            bounds = [self.go(a) for a in args]
            return (max(b[0] for b in bounds), max(b[1] for b in bounds))
        if name == "det":
            m = args[0]
            if m[0] != "matrix":
                raise Unsupported("det of a matrix that is not written out")
            n = len(m[1])
            bounds = [self.go(a) for r in m[1] for a in r]
            p, q = max(b[0] for b in bounds), max(b[1] for b in bounds)
            # n! products of n entries each
            prod = (n * p, n * q)
            acc = prod
            for _ in range(_fact(n) - 1):
                acc = _add(acc, prod)
            return acc
        if name == "diff":
            p, q = self.go(args[0])
            by = args[1][1] if args[1][0] == "var" else None
            k = 1 if len(args) == 2 else self.integer(args[2], "diff's order")
            for _ in range(k):
                if q == 0:
                    p = max(p - 1, 0) if by == self.var else p
                else:
                    p, q = (p + q - 1 if by == self.var else p + q), 2 * q
            return (p, q)
        base, k = _primes(name)
        obj = self.objects.get(base)
        if isinstance(obj, Curve):
            if len(args) == 3 and k == 0:
                r = self.integer(args[1], "a scheme level")
                p, q = self.go(args[2])
                return (r * max(p, q), r * q)
            p, q = self.go(args[0])
            n = obj.degree
            if obj.weights is None or not obj.rational:
                n = max(n - k, 0)
                return (n * max(p, q), n * q)
            n = n * 2**k
            return (n * max(p, q), n * max(p, q))
        surf, ku, kv = _partial(name, self.objects)
        if surf is not None:
            pu, qu = self.go(args[0])
            pv, qv = self.go(args[1])
            m, n = max(surf.m - ku, 0), max(surf.n - kv, 0)
            return (m * max(pu, qu) + n * max(pv, qv), m * qu + n * qv)
        raise Unsupported(f"the degree of '{name}(…)'")

    def repeat_add(self, term, vec):
        if vec[0] != "tuple":
            # a vector's length is unknown here: the bound holds for any length only
            # when there is no denominator
            if term[1] != 0:
                raise Unsupported("dot of rational vectors of unknown length")
            return term
        acc = term
        for _ in range(len(vec[1]) - 1):
            acc = _add(acc, term)
        return acc


def _fact(n):
    out = 1
    for k in range(2, n + 1):
        out *= k
    return out
