"""Expression trees translated into SymPy (an optional dependency: `casteljau-oracle[check]`).

`to_sympy(e, ...)` gives a SymPy expression (a list of them for a tuple, a `sympy.Matrix` for a
matrix). Integer names (`ints`) become integer symbols, or their values when given; a control
point `b[j]` of a symbolic polygon is the symbol `b_j` (one symbol per point: the identities
are affine in the points, so one coordinate stands for all). `B` and `C` at symbolic
arguments are written with factorials, whose convention `1/m! = 0` for negative integers `m`
SymPy keeps (`1/factorial(-1)` is 0). A `sum` with integer bounds is added out; with symbolic
bounds it stays a `sympy.Sum`.
"""

from fractions import Fraction

import sympy

from .cert_expr import deep
from .cert_eval import Curve, Surface, Unsupported, _partial, _primes

__all__ = ["to_sympy", "is_zero", "same"]


def to_sympy(e, ints=None, reals=(), objects=None):
    """The SymPy value of tree `e`; `ints` maps integer names to values or None (symbolic)."""
    with deep():
        return _Sym(dict(ints or {}), set(reals), objects or {}).go(e)


def is_zero(v):
    """Whether a SymPy value (scalar, list or Matrix) is identically zero as a rational function."""
    if isinstance(v, (list, tuple)):
        return all(is_zero(x) for x in v)
    if isinstance(v, sympy.MatrixBase):
        return all(is_zero(x) for x in v)
    return sympy.cancel(sympy.together(v)) == 0


def same(a, b):
    """Whether two SymPy values are equal as rational functions (componentwise)."""
    return is_zero(_sub(a, b))


def _sub(a, b):
    if isinstance(a, (list, tuple)) and isinstance(b, (list, tuple)):
        if len(a) != len(b):
            raise Unsupported(f"comparing vectors of lengths {len(a)} and {len(b)}")
        return [_sub(x, y) for x, y in zip(a, b)]
    if isinstance(a, (list, tuple)) and b == 0:
        return list(a)
    if isinstance(b, (list, tuple)) and a == 0:
        return [-x for x in b]
    if isinstance(a, (list, tuple)) or isinstance(b, (list, tuple)):
        raise Unsupported("comparing a vector with a scalar")
    return a - b


def _lift(f, *vals):
    """Applies a scalar operation componentwise to lists (vectors)."""
    if any(isinstance(v, list) for v in vals):
        n = max(len(v) for v in vals if isinstance(v, list))
        cols = [v if isinstance(v, list) else [v] * n for v in vals]
        if any(len(c) != n for c in cols):
            raise Unsupported("vectors of different lengths")
        return [f(*xs) for xs in zip(*cols)]
    return f(*vals)


class _Sym:
    def __init__(self, ints, reals, objects):
        self.ints = ints
        self.reals = reals
        self.objects = objects

    def sym(self, name):
        if name in self.ints:
            v = self.ints[name]
            return sympy.Integer(v) if v is not None else sympy.Symbol(name, integer=True)
        return sympy.Symbol(name)

    def go(self, e):
        kind = e[0]
        if kind == "num":
            return sympy.Rational(e[1].numerator, e[1].denominator)
        if kind == "var":
            return self.sym(e[1])
        if kind == "neg":
            return _lift(lambda a: -a, self.go(e[1]))
        if kind == "add":
            return _lift(lambda a, b: a + b, self.go(e[1]), self.go(e[2]))
        if kind == "sub":
            return _lift(lambda a, b: a - b, self.go(e[1]), self.go(e[2]))
        if kind == "mul":
            a, b = self.go(e[1]), self.go(e[2])
            if isinstance(a, sympy.MatrixBase) or isinstance(b, sympy.MatrixBase):
                return _matmul(a, b)
            if isinstance(a, list) and isinstance(b, list):
                raise Unsupported("a product of two vectors (use dot)")
            return _lift(lambda x, y: x * y, a, b)
        if kind == "div":
            a, b = self.go(e[1]), self.go(e[2])
            if isinstance(b, (list, sympy.MatrixBase)):
                raise Unsupported("division by a vector")
            return _lift(lambda x: x / b, a)
        if kind == "pow":
            a, k = self.go(e[1]), self.go(e[2])
            if isinstance(a, (list, sympy.MatrixBase)):
                raise Unsupported("a power of a vector or matrix")
            return a**k
        if kind == "fact":
            return sympy.factorial(self.go(e[1]))
        if kind == "tuple":
            return [self.go(a) for a in e[1]]
        if kind == "matrix":
            return sympy.Matrix([[self.go(a) for a in r] for r in e[1]])
        if kind == "sum":
            return self.sum(e)
        if kind == "index":
            return self.index(e)
        if kind == "call":
            return self.call(e[1], e[2])
        raise Unsupported(f"a '{kind}' node")

    def sum(self, e):
        _, v, lo, hi, body = e
        a, b = self.go(lo), self.go(hi)
        if a.is_Integer and b.is_Integer:
            saved = self.ints.get(v, "absent")
            acc = sympy.Integer(0)
            try:
                for k in range(int(a), int(b) + 1):
                    self.ints[v] = k
                    acc = _lift(lambda x, y: x + y, acc, self.go(body)) if k > int(a) else self.go(body)
            finally:
                if saved == "absent":
                    self.ints.pop(v, None)
                else:
                    self.ints[v] = saved
            return acc
        saved = self.ints.get(v, "absent")
        self.ints[v] = None
        try:
            inner = self.go(body)
        finally:
            if saved == "absent":
                self.ints.pop(v, None)
            else:
                self.ints[v] = saved
        k = sympy.Symbol(v, integer=True)
        return _lift(lambda x: sympy.Sum(x, (k, a, b)), inner)

    def index(self, e):
        name, args = e[1], e[2]
        idx = [self.go(a) for a in args]
        obj = self.objects.get(name)
        if isinstance(obj, Surface):
            i, j = (int(x) for x in idx)
            if 0 <= i <= obj.m and 0 <= j <= obj.n:
                return [sympy.Rational(c.numerator, c.denominator) for c in obj.net[i][j]]
            return [sympy.Integer(0)] * len(obj.net[0][0])
        if isinstance(obj, Curve):
            j = int(idx[0])
            if 0 <= j < len(obj.points):
                return [sympy.Rational(c.numerator, c.denominator) for c in obj.points[j]]
            return [sympy.Integer(0)] * len(obj.points[0])
        degree = self.objects.get(("degree", name))
        if degree is not None and all(x.is_Integer for x in idx):
            # a symbolic polygon or net at concrete degrees: zero outside its indices
            if any(int(x) < 0 or int(x) > int(self.go(d)) for x, d in zip(idx, degree)):
                return sympy.Integer(0)
        return sympy.Symbol(name + "_" + "_".join(str(x) for x in idx))

    def call(self, name, args):
        if name == "B":
            return _bern(*(self.go(a) for a in args))
        if name in ("C", "binom"):
            n, k = (self.go(a) for a in args)
            if n.is_Integer and k.is_Integer:
                return sympy.binomial(n, k) if 0 <= k <= n else sympy.Integer(0)
            return sympy.factorial(n) / (sympy.factorial(k) * sympy.factorial(n - k))
        if name == "__dB":
            i, n, x, k = (self.go(a) for a in args)
            y = sympy.Dummy("y")
            return sympy.diff(_bern(i, n, y), y, int(k)).subs(y, x)
        if name == "__dpow":
            x, e, k = (self.go(a) for a in args)
            y = sympy.Dummy("y")
            return sympy.diff(y**e, y, int(k)).subs(y, x)
        if name == "delta":
            k, j = (self.go(a) for a in args[1:])
            if not (k.is_Integer and j.is_Integer):
                raise Unsupported("delta(b, k, j) at a symbolic k or j")
            k, j = int(k), int(j)
            return sum(
                ((-1) ** (k - i) * sympy.binomial(k, i) * self.index(("index", args[0][1], [("num", Fraction(j + i))])) for i in range(k + 1)),
                sympy.Integer(0),
            )
        if name == "sqrt":
            return sympy.sqrt(self.go(args[0]))
        if name == "dot":
            a, b = self.go(args[0]), self.go(args[1])
            if not (isinstance(a, list) and isinstance(b, list) and len(a) == len(b)):
                raise Unsupported("dot of values that are not vectors of one length")
            return sum((x * y for x, y in zip(a, b)), sympy.Integer(0))
        if name == "comp":
            v, k = self.go(args[0]), self.go(args[1])
            return v[int(k) - 1]
        if name in ("det", "inv", "transpose"):
            m = self.go(args[0])
            if not isinstance(m, sympy.MatrixBase):
                raise Unsupported(f"{name} of a non-matrix")
            return {"det": m.det, "inv": m.inv, "transpose": m.transpose}[name]()
        if name in ("rows", "cols"):
            vs = [self.go(a) for a in args]
            m = sympy.Matrix(vs)
            return m if name == "rows" else m.T
        if name == "diff":
            body = self.go(args[0])
            if args[1][0] != "var":
                raise Unsupported("diff by something that is not a name")
            v = self.sym(args[1][1])
            k = int(self.go(args[2])) if len(args) == 3 else 1
            return _lift(lambda x: sympy.diff(x, v, k), body)
        if name == "integral":
            if args[1][0] != "var":
                raise Unsupported("an integral by something that is not a name")
            body = self.go(args[0])
            v = self.sym(args[1][1])
            a, b = self.go(args[2]), self.go(args[3])
            return _lift(lambda x: sympy.integrate(sympy.expand(x), (v, a, b)), body)
        base, k = _primes(name)
        obj = self.objects.get(base)
        if isinstance(obj, Curve):
            if len(args) != 1:
                raise Unsupported(f"{name} with {len(args)} arguments")
            x = sympy.Dummy("x")
            t = self.go(args[0])
            n = obj.degree
            w = obj.weights or [1] * (n + 1)
            den = sum(sympy.Rational(w[i]) * sympy.binomial(n, i) * x**i * (1 - x) ** (n - i) for i in range(n + 1))
            out = []
            for c in range(len(obj.points[0])):
                num = sum(
                    sympy.Rational(w[i] * obj.points[i][c]) * sympy.binomial(n, i) * x**i * (1 - x) ** (n - i)
                    for i in range(n + 1)
                )
                out.append(sympy.diff(num / den, x, k).subs(x, t))
            return out
        surf, ku, kv = _partial(name, self.objects)
        if surf is not None:
            x, y = sympy.Dummy("x"), sympy.Dummy("y")
            u, v = self.go(args[0]), self.go(args[1])
            out = []
            for c in range(len(surf.net[0][0])):
                f = sum(
                    sympy.Rational(surf.net[i][j][c])
                    * sympy.binomial(surf.m, i)
                    * x**i
                    * (1 - x) ** (surf.m - i)
                    * sympy.binomial(surf.n, j)
                    * y**j
                    * (1 - y) ** (surf.n - j)
                    for i in range(surf.m + 1)
                    for j in range(surf.n + 1)
                )
                out.append(sympy.diff(f, x, ku, y, kv).subs({x: u, y: v}))
            return out
        raise Unsupported(f"the function or library operation '{name}'")


def _bern(i, n, t):
    if i.is_Integer and n.is_Integer:
        if i < 0 or i > n:
            return sympy.Integer(0)
        return sympy.binomial(n, i) * t**i * (1 - t) ** (n - i)
    return sympy.factorial(n) / (sympy.factorial(i) * sympy.factorial(n - i)) * t**i * (1 - t) ** (n - i)


def _matmul(a, b):
    if isinstance(a, list):
        a = sympy.Matrix(a)
    if isinstance(b, list):
        b = sympy.Matrix(b)
    r = a * b
    if isinstance(r, sympy.MatrixBase) and r.shape[1] == 1 and not (
        isinstance(b, sympy.MatrixBase) and b.shape[1] != 1
    ):
        return list(r)
    return r
