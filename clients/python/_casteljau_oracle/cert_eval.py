"""Exact evaluation of parsed expressions with `fractions.Fraction` (standard library only).

Values are `Fraction`s, tuples of values (vectors) and `Matrix` (rows of Fractions). The
conventions are the texts': `B(i, n, t) = C(n, i) t^i (1 - t)^(n - i)`, zero outside
`0 <= i <= n`; `C(n, k)` zero outside `0 <= k <= n`; `sum(r, a, b, body)` empty when `a > b`;
a control point `b[j]` outside `0..=n` is the zero point. Curves are evaluated in their
Bernstein form `sum_i w_i b_i B_i^n(t) / sum_i w_i B_i^n(t)` (not by de Casteljau's scheme),
derivatives through the power-basis polynomials of that form.

Anything outside what is implemented raises `Unsupported` (the certificate is then "not
re-checked", with that reason); a division by zero raises `Pole`; bad input `EvalError`.
"""

from fractions import Fraction
from math import comb, factorial

from .cert_expr import deep, parse

__all__ = ["EvalError", "Unsupported", "Pole", "Matrix", "Curve", "Surface", "evaluate", "bernstein"]

#: Largest |exponent|, Bernstein degree or binomial argument accepted.
MAX_EXPONENT = 4096
#: Largest factorial argument accepted.
MAX_FACTORIAL = 1000
#: Most terms one `sum` may add.
MAX_SUM_TERMS = 100_000


class EvalError(ValueError):
    """An expression that cannot be evaluated as written (the message says why)."""


class Unsupported(EvalError):
    """A construct this checker does not implement."""


class Pole(EvalError):
    """A division by zero at the point evaluated."""


class Matrix:
    """A matrix of exact values, `rows[i][j]`."""

    __slots__ = ("rows",)

    def __init__(self, rows):
        self.rows = tuple(tuple(r) for r in rows)

    def __eq__(self, other):
        return isinstance(other, Matrix) and self.rows == other.rows

    def __hash__(self):
        return hash(self.rows)

    def __repr__(self):
        return f"Matrix({self.rows!r})"


class Curve:
    """A Bézier curve: `points[i]` (tuples of Fractions), optional `weights`."""

    def __init__(self, points, weights=None):
        self.points = [tuple(_frac(c) for c in p) for p in points]
        if not self.points:
            raise EvalError("a curve needs at least one point")
        self.weights = None if weights is None else [_frac(w) for w in weights]
        if self.weights is not None and len(self.weights) != len(self.points):
            raise EvalError("a curve needs one weight per point")
        n = len(self.points) - 1
        w = self.weights or [Fraction(1)] * (n + 1)
        dim = len(self.points[0])
        # power-basis polynomials of the weighted numerator and of the denominator
        self.num = [_poly_lin([(w[i] * self.points[i][c], _bern_poly(i, n)) for i in range(n + 1)]) for c in range(dim)]
        self.den = _poly_lin([(w[i], _bern_poly(i, n)) for i in range(n + 1)])
        self.degree = n
        self.rational = self.weights is not None and len(set(self.weights)) > 1

    def at(self, t, k=0):
        """The k-th derivative at t (quotient rule on the power-basis polynomials)."""
        num, den = self.num, self.den
        for _ in range(k):
            num = [_poly_sub(_poly_mul(_poly_diff(p), den), _poly_mul(p, _poly_diff(den))) for p in num]
            den = _poly_mul(den, den)
        d = _poly_at(den, t)
        if d == 0:
            raise Pole("the curve's denominator vanishes")
        return tuple(_poly_at(p, t) / d for p in num)


class Surface:
    """A tensor-product Bézier surface, `net[i][j]` a point."""

    def __init__(self, net):
        self.net = [[tuple(_frac(c) for c in p) for p in row] for row in net]
        if not self.net or not self.net[0] or any(len(r) != len(self.net[0]) for r in self.net):
            raise EvalError("a surface needs a non-empty rectangular net")
        self.m, self.n = len(self.net) - 1, len(self.net[0]) - 1

    def at(self, u, v, ku=0, kv=0):
        bu = [_poly_at(_poly_diff(_bern_poly(i, self.m), ku), u) for i in range(self.m + 1)]
        bv = [_poly_at(_poly_diff(_bern_poly(j, self.n), kv), v) for j in range(self.n + 1)]
        dim = len(self.net[0][0])
        return tuple(
            sum((bu[i] * bv[j] * self.net[i][j][c] for i in range(self.m + 1) for j in range(self.n + 1)), Fraction(0))
            for c in range(dim)
        )


def _frac(x):
    if isinstance(x, Fraction):
        return x
    if isinstance(x, bool) or isinstance(x, float):
        raise EvalError(f"a number must be exact (an integer or a string), not {x!r}")
    if isinstance(x, int):
        return Fraction(x)
    if isinstance(x, str):
        v = evaluate(parse(x), {})
        if not isinstance(v, Fraction):
            raise EvalError(f"'{x}' is not a number")
        return v
    raise EvalError(f"not an exact number: {x!r}")


# --- polynomials in one variable: coefficient lists, lowest degree first -------------------


def _bern_poly(i, n):
    """B_i^n(t) = C(n, i) t^i (1 - t)^(n - i) in the power basis."""
    out = [Fraction(0)] * (n + 1)
    for k in range(n - i + 1):
        out[i + k] = Fraction(comb(n, i) * comb(n - i, k) * (-1) ** k)
    return out


def _poly_lin(terms):
    size = max(len(p) for _, p in terms)
    out = [Fraction(0)] * size
    for c, p in terms:
        for k, a in enumerate(p):
            out[k] += c * a
    return out


def _poly_mul(a, b):
    out = [Fraction(0)] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        if x:
            for j, y in enumerate(b):
                out[i + j] += x * y
    return out


def _poly_sub(a, b):
    n = max(len(a), len(b))
    return [(a[k] if k < len(a) else 0) - (b[k] if k < len(b) else 0) for k in range(n)]


def _poly_diff(p, k=1):
    for _ in range(k):
        p = [i * p[i] for i in range(1, len(p))] or [Fraction(0)]
    return p


def _poly_at(p, t):
    acc = Fraction(0)
    for a in reversed(p):
        acc = acc * t + a
    return acc


# --- evaluation -------------------------------------------------------------------------


def bernstein(i, n, t):
    """B_i^n(t), zero outside 0 <= i <= n."""
    if n > MAX_EXPONENT:
        raise EvalError(f"Bernstein degree {n} beyond {MAX_EXPONENT}")
    if i < 0 or i > n:
        return Fraction(0)
    return comb(n, i) * t**i * (1 - t) ** (n - i)


def binomial(n, k):
    """C(n, k): 0 unless 0 <= k <= n."""
    if max(abs(n), abs(k)) > MAX_EXPONENT:
        raise EvalError(f"binomial argument beyond {MAX_EXPONENT}: C({n}, {k})")
    return Fraction(comb(n, k)) if 0 <= k <= n else Fraction(0)


def _int(v, what):
    if not isinstance(v, Fraction) or v.denominator != 1:
        raise EvalError(f"{what} must be an integer, got {_show(v)}")
    return int(v)


def _show(v):
    if isinstance(v, tuple):
        return "(" + ", ".join(_show(x) for x in v) + ")"
    return str(v)


def _zero_like(v):
    if isinstance(v, tuple):
        return tuple(_zero_like(x) for x in v)
    return Fraction(0)


def _add(a, b, sign=1):
    if isinstance(a, Fraction) and isinstance(b, Fraction):
        return a + b if sign > 0 else a - b
    if isinstance(a, tuple) and isinstance(b, tuple):
        if len(a) != len(b):
            raise EvalError(f"adding vectors of lengths {len(a)} and {len(b)}")
        return tuple(_add(x, y, sign) for x, y in zip(a, b))
    if isinstance(a, Matrix) and isinstance(b, Matrix):
        return Matrix(_add(x, y, sign) for x, y in zip(a.rows, b.rows))
    # 0 + vector: a zero control point or an empty sum meets a vector
    if a == 0 and isinstance(b, tuple):
        return _add(_zero_like(b), b, sign)
    if b == 0 and isinstance(a, tuple):
        return a
    raise EvalError(f"adding a {type(a).__name__} and a {type(b).__name__}")


def _neg(a):
    if isinstance(a, Fraction):
        return -a
    if isinstance(a, tuple):
        return tuple(_neg(x) for x in a)
    return Matrix(tuple(-x for x in r) for r in a.rows)


def _mul(a, b):
    if isinstance(a, Fraction):
        if isinstance(b, Fraction):
            return a * b
        if isinstance(b, tuple):
            return tuple(_mul(a, x) for x in b)
        return Matrix(tuple(a * x for x in r) for r in b.rows)
    if isinstance(b, Fraction):
        return _mul(b, a)
    if isinstance(a, Matrix) and isinstance(b, Matrix):
        if len(a.rows[0]) != len(b.rows):
            raise EvalError("matrix product of mismatched sizes")
        cols = list(zip(*b.rows))
        return Matrix(tuple(sum((x * y for x, y in zip(r, c)), Fraction(0)) for c in cols) for r in a.rows)
    if isinstance(a, Matrix) and isinstance(b, tuple):
        if len(a.rows[0]) != len(b):
            raise EvalError("matrix times vector of mismatched sizes")
        return tuple(sum((x * y for x, y in zip(r, b)), Fraction(0)) for r in a.rows)
    raise EvalError(f"multiplying a {type(a).__name__} by a {type(b).__name__}")


def _div(a, b):
    if not isinstance(b, Fraction):
        raise EvalError("dividing by a vector or a matrix")
    if b == 0:
        raise Pole("division by zero")
    return _mul(1 / b, a)


def _pow(a, k):
    if abs(k) > MAX_EXPONENT:
        raise EvalError(f"exponent {k} beyond {MAX_EXPONENT}")
    if isinstance(a, Matrix):
        raise Unsupported("powers of matrices")
    if not isinstance(a, Fraction):
        raise EvalError("a power of a vector")
    if a == 0 and k < 0:
        raise Pole("0 to a negative power")
    return a**k


def _det(rows):
    n = len(rows)
    if any(len(r) != n for r in rows):
        raise EvalError("det of a non-square matrix")
    m = [list(r) for r in rows]
    det = Fraction(1)
    for c in range(n):
        piv = next((r for r in range(c, n) if m[r][c] != 0), None)
        if piv is None:
            return Fraction(0)
        if piv != c:
            m[c], m[piv] = m[piv], m[c]
            det = -det
        det *= m[c][c]
        for r in range(c + 1, n):
            f = m[r][c] / m[c][c]
            if f:
                m[r] = [x - f * y for x, y in zip(m[r], m[c])]
    return det


def _inv(rows):
    n = len(rows)
    if any(len(r) != n for r in rows):
        raise EvalError("inv of a non-square matrix")
    m = [list(r) + [Fraction(int(i == j)) for j in range(n)] for i, r in enumerate(rows)]
    for c in range(n):
        piv = next((r for r in range(c, n) if m[r][c] != 0), None)
        if piv is None:
            raise Pole("inverse of a singular matrix")
        m[c], m[piv] = m[piv], m[c]
        p = m[c][c]
        m[c] = [x / p for x in m[c]]
        for r in range(n):
            if r != c and m[r][c]:
                f = m[r][c]
                m[r] = [x - f * y for x, y in zip(m[r], m[c])]
    return Matrix(r[n:] for r in m)


def _sqrt(v):
    if not isinstance(v, Fraction) or v < 0:
        raise EvalError(f"sqrt of {_show(v)}")
    from math import isqrt

    p, q = isqrt(v.numerator), isqrt(v.denominator)
    if p * p != v.numerator or q * q != v.denominator:
        raise Unsupported(f"sqrt({v}) is irrational (Q(sqrt d) is not implemented)")
    return Fraction(p, q)


def evaluate(e, env, objects=None):
    """The exact value of expression tree `e`.

    `env` maps names to values (Fractions or tuples); `objects` maps names to `Curve`,
    `Surface` or a list of control points (a symbolic polygon at a concrete degree, read by
    `b[j]`).
    """
    with deep():
        return _Eval(env, objects or {}).go(e)


class _Eval:
    def __init__(self, env, objects):
        self.env = dict(env)
        self.objects = objects

    def go(self, e):
        kind = e[0]
        if kind == "num":
            return e[1]
        if kind == "var":
            if e[1] in self.env:
                return self.env[e[1]]
            raise EvalError(f"unknown name '{e[1]}'")
        if kind == "neg":
            return _neg(self.go(e[1]))
        if kind in ("add", "sub"):
            return _add(self.go(e[1]), self.go(e[2]), 1 if kind == "add" else -1)
        if kind == "mul":
            return _mul(self.go(e[1]), self.go(e[2]))
        if kind == "div":
            return _div(self.go(e[1]), self.go(e[2]))
        if kind == "pow":
            return _pow(self.go(e[1]), _int(self.go(e[2]), "an exponent"))
        if kind == "fact":
            m = _int(self.go(e[1]), "a factorial's argument")
            if m < 0 or m > MAX_FACTORIAL:
                raise EvalError(f"factorial of {m} (0..={MAX_FACTORIAL})")
            return Fraction(factorial(m))
        if kind == "tuple":
            return tuple(self.go(a) for a in e[1])
        if kind == "matrix":
            return Matrix(tuple(self.go(a) for a in r) for r in e[1])
        if kind == "sum":
            return self.sum(e)
        if kind == "index":
            return self.index(e[1], [self.go(a) for a in e[2]])
        if kind == "call":
            return self.call(e[1], e[2])
        raise EvalError(f"not an expression node: {kind}")

    def sum(self, e):
        _, var, lo, hi, body = e
        a = _int(self.go(lo), "a sum's bound")
        b = _int(self.go(hi), "a sum's bound")
        if b - a + 1 > MAX_SUM_TERMS:
            raise EvalError(f"a sum of {b - a + 1} terms (limit {MAX_SUM_TERMS})")
        saved = self.env.get(var)
        acc = Fraction(0)
        try:
            for k in range(a, b + 1):
                self.env[var] = Fraction(k)
                acc = _add(acc, self.go(body))
        finally:
            if saved is None:
                self.env.pop(var, None)
            else:
                self.env[var] = saved
        return acc

    def index(self, name, idx):
        obj = self.objects.get(name)
        if obj is None:
            raise EvalError(f"unknown control polygon or net '{name}'")
        if isinstance(obj, Surface):
            if len(idx) != 2:
                raise EvalError(f"{name}[i, j] needs two indices")
            i, j = (_int(x, "an index") for x in idx)
            if 0 <= i <= obj.m and 0 <= j <= obj.n:
                return obj.net[i][j]
            return _zero_like(obj.net[0][0])
        if isinstance(obj, Curve):
            obj = obj.points
        if isinstance(obj, dict):  # a symbolic net at concrete degrees: {(i, j): value}
            key = tuple(_int(x, "an index") for x in idx)
            return obj.get(key, Fraction(0))
        if len(idx) != 1:
            raise EvalError(f"{name}[j] needs one index")
        j = _int(idx[0], "an index")
        return obj[j] if 0 <= j < len(obj) else _zero_like(obj[0]) if obj else Fraction(0)

    def call(self, name, args):
        if name == "B":
            i, n = (_int(self.go(a), "a Bernstein index") for a in args[:2])
            return bernstein(i, n, self.scalar(args[2]))
        if name in ("C", "binom"):
            n, k = (_int(self.go(a), "a binomial argument") for a in args)
            return binomial(n, k)
        if name == "__dB":
            i, n = (_int(self.go(a), "a Bernstein index") for a in args[:2])
            x = self.scalar(args[2])
            k = _int(self.go(args[3]), "a derivative's order")
            if max(abs(n), abs(k)) > MAX_EXPONENT or k < 0:
                raise EvalError(f"__dB(i, {n}, x, {k}) outside 0..={MAX_EXPONENT}")
            if i < 0 or i > n:
                return Fraction(0)
            return _poly_at(_poly_diff(_bern_poly(i, n), k), x)
        if name == "__dpow":
            x = self.scalar(args[0])
            e, k = (_int(self.go(a), "an exponent or order") for a in args[1:])
            if max(abs(e), abs(k)) > MAX_EXPONENT or k < 0:
                raise EvalError(f"__dpow(x, {e}, {k}) outside the limits")
            coeff = Fraction(1)
            for j in range(k):
                coeff *= e - j
            if coeff == 0:
                return Fraction(0)
            return coeff * _pow(x, e - k)
        if name == "delta":
            # the k-th forward difference of a polygon's points: Σ_i (-1)^(k-i) C(k, i) b[j + i]
            if args[0][0] != "var":
                raise EvalError("delta(b, k, j) needs a polygon's name first")
            k, j = (_int(self.go(a), "delta's order or index") for a in args[1:])
            if not 0 <= k <= MAX_EXPONENT:
                raise EvalError(f"delta(b, {k}, j): the order is outside 0..={MAX_EXPONENT}")
            terms = [_mul(Fraction((-1) ** (k - i) * binomial(k, i)), self.index(args[0][1], [Fraction(j + i)])) for i in range(k + 1)]
            return sum_vectors(terms) if isinstance(terms[0], tuple) else sum(terms, Fraction(0))
        if name == "sqrt":
            return _sqrt(self.go(args[0]))
        if name == "dot":
            a, b = self.go(args[0]), self.go(args[1])
            if not (isinstance(a, tuple) and isinstance(b, tuple) and len(a) == len(b)):
                raise EvalError("dot needs two vectors of one length")
            return sum((_mul(x, y) for x, y in zip(a, b)), Fraction(0))
        if name == "comp":
            v, k = self.go(args[0]), _int(self.go(args[1]), "comp's index")
            if not isinstance(v, tuple) or not 1 <= k <= len(v):
                raise EvalError(f"comp(v, {k}) of {_show(v)} (coordinates count from 1)")
            return v[k - 1]
        if name in ("det", "inv", "transpose"):
            m = self.go(args[0])
            if not isinstance(m, Matrix):
                raise EvalError(f"{name} of a non-matrix")
            if name == "det":
                return _det(m.rows)
            if name == "inv":
                return _inv(m.rows)
            return Matrix(zip(*m.rows))
        if name in ("rows", "cols"):
            vs = [self.go(a) for a in args]
            if not all(isinstance(v, tuple) and len(v) == len(vs[0]) for v in vs):
                raise EvalError(f"{name} needs vectors of one length")
            return Matrix(vs) if name == "rows" else Matrix(zip(*vs))
        if name in ("diff", "integral"):
            raise Unsupported(f"{name} in an exact evaluation (the SymPy path handles it)")
        base, k = _primes(name)
        obj = self.objects.get(base)
        if isinstance(obj, Curve):
            if len(args) == 1:
                return obj.at(self.scalar(args[0]), k)
            if len(args) == 3 and k == 0:
                # the point b_i^r(t) of de Casteljau's scheme, by its closed form
                i, r = (_int(self.go(a), "a scheme index") for a in args[:2])
                t = self.scalar(args[2])
                return _add(
                    _zero_like(obj.points[0]),
                    sum_vectors(_mul(bernstein(j, r, t), self.index(base, [Fraction(i + j)])) for j in range(r + 1)),
                )
            raise EvalError(f"{name}(…) takes (t) or (i, r, t)")
        surf, ku, kv = _partial(name, self.objects)
        if surf is not None:
            if len(args) != 2:
                raise EvalError(f"the surface {name} takes (u, v)")
            return surf.at(self.scalar(args[0]), self.scalar(args[1]), ku, kv)
        raise Unsupported(f"the function or library operation '{name}'")

    def scalar(self, a):
        v = self.go(a)
        if not isinstance(v, Fraction):
            raise EvalError(f"expected a number, got {_show(v)}")
        return v


def sum_vectors(vs):
    acc = Fraction(0)
    for v in vs:
        acc = _add(acc, v)
    return acc


def _primes(name):
    k = len(name) - len(name.rstrip("'"))
    return name[: len(name) - k], k


def _partial(name, objects):
    """(surface, ku, kv) for `x` or a partial `x_uv`; (None, 0, 0) otherwise."""
    obj = objects.get(name)
    if isinstance(obj, Surface):
        return obj, 0, 0
    base, _, letters = name.rpartition("_")
    obj = objects.get(base)
    if isinstance(obj, Surface) and letters and set(letters) <= {"u", "v"}:
        return obj, letters.count("u"), letters.count("v")
    return None, 0, 0
