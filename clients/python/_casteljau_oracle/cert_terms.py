"""Hypergeometric terms of a for-every goal (methods `pieces` and `wz`), for the proof in
`cert_pieces`: an expression tree becomes a list of items, each a `Term` or a `Sum`.

A `Term` is `c · Π C(a, b)^±1 · Π base^e` where `c` is a rational function (SymPy) of the
integer and real symbols, each `a`, `b`, `e` is an affine integer expression in the integer
symbols and each `base` a polynomial in the real symbols. It carries the conventions of the
evaluator (docs/certificates.md) as conditions on the integer symbols: `conds` (`L ≥ 0`, else
the term is 0: `B(i, n, t)` is 0 unless `0 ≤ i ≤ n`, `C(n, k)` is 0 unless `0 ≤ k ≤ n`), `eqs`
(`L = 0`, else 0: a control point `b[e]` of the unit polygon at `k` is `[e = k]`) and `musts`
(`L ≥ 0`, else the term is undefined: a binomial in a denominator). Where its conditions hold,
the term equals its formula: the binomials are `a!/(b!(a−b)!)` with `a, b, a − b ≥ 0`.

A `Sum` is `Σ_{var = lo}^{hi} body` (empty when `hi < lo`), `body` a list of items; factors
multiplied onto a sum are moved into its body. Needs SymPy.
"""

import itertools

import sympy

from .cert_eval import Unsupported

__all__ = ["Term", "Sum", "Converter", "linear", "fresh"]

_COUNT = itertools.count()
#: Highest derivative order of `__dB` written out (Leibniz's rule, k + 1 terms).
MAX_ORDER = 16


def fresh(prefix="%k"):
    """A new integer symbol no goal can name (`%` is not in the grammar)."""
    return sympy.Symbol(f"{prefix}{next(_COUNT)}")


def linear(x, ints):
    """`x` as an affine expression in the integer symbols with integer coefficients, or raises
    `Unsupported`."""
    x = sympy.expand(x)
    if x.free_symbols - set(ints):
        raise Unsupported(f"{x} is not an expression in the integer symbols")
    p = sympy.Poly(x, *ints) if ints else None
    if p is not None and p.total_degree() > 1:
        raise Unsupported(f"{x} is not affine in the integer symbols")
    coeffs = p.coeffs() if p is not None else [x]
    if not all(sympy.sympify(c).is_integer for c in coeffs):
        raise Unsupported(f"{x} has a coefficient that is not an integer")
    return x


def _subs(x, m):
    return sympy.expand(x.xreplace(m)) if m else x


class Term:
    __slots__ = ("c", "conds", "eqs", "musts", "binoms", "pows", "has_b", "lazy", "nonzeros")

    def __init__(self, c=sympy.Integer(1), conds=(), eqs=(), musts=(), binoms=(), pows=(), has_b=False, lazy=False, nonzeros=()):
        self.c, self.conds, self.eqs, self.musts = c, tuple(conds), tuple(eqs), tuple(musts)
        # nonzeros: integer divisors of the goal (`L ≠ 0`, else undefined), kept apart from
        # `c` where SymPy would cancel them (`(n - 10)/(n - 10)` is undefined at n = 10)
        self.nonzeros = tuple(nonzeros)
        self.binoms, self.pows, self.has_b = tuple(binoms), tuple(pows), has_b
        # lazy: 0 wherever a condition fails, even where `c` has a pole (a term this checker
        # builds, `G = R·F` of a WZ pair, defined so); else the evaluator's order: a pole first
        self.lazy = lazy

    def with_(self, **kw):
        f = {k: getattr(self, k) for k in self.__slots__}
        f.update(kw)
        return Term(**f)

    def pure(self):
        return not (self.conds or self.eqs or self.musts or self.binoms or self.pows or self.has_b)

    def times(self, o):
        if self.has_b and o.has_b:
            raise Unsupported("a product of two control points: the goal is not affine in them")
        return Term(
            self.c * o.c, self.conds + o.conds, self.eqs + o.eqs, self.musts + o.musts,
            self.binoms + o.binoms, self.pows + o.pows, self.has_b or o.has_b, self.lazy or o.lazy,
            self.nonzeros + o.nonzeros,
        )

    def scaled(self, k, lazy=None):
        return self.with_(c=k * self.c, lazy=self.lazy if lazy is None else lazy)

    def subs(self, m):
        """The term with the symbols of `m` replaced (integer symbols by affine expressions)."""
        if not m:
            return self
        return Term(
            self.c.xreplace(m),
            [_subs(x, m) for x in self.conds],
            [_subs(x, m) for x in self.eqs],
            [_subs(x, m) for x in self.musts],
            [(_subs(a, m), _subs(b, m), s) for a, b, s in self.binoms],
            [(base.xreplace(m), _subs(e, m)) for base, e in self.pows],
            self.has_b,
            self.lazy,
            [_subs(x, m) for x in self.nonzeros],
        )

    def __repr__(self):
        return f"Term({self.c}, conds={self.conds}, eqs={self.eqs}, C={self.binoms}, pows={self.pows})"


class Sum:
    __slots__ = ("var", "lo", "hi", "body", "name")

    def __init__(self, var, lo, hi, body, name):
        self.var, self.lo, self.hi, self.body, self.name = var, lo, hi, list(body), name

    def subs(self, m):
        return Sum(self.var, _subs(self.lo, m), _subs(self.hi, m), [x.subs(m) for x in self.body], self.name)

    def renamed(self):
        """The same sum with a new bound variable (before it is copied into another sum)."""
        v = fresh("%s")
        return Sum(v, self.lo, self.hi, [x.subs({self.var: v}) for x in self.body], self.name)

    def __repr__(self):
        return f"Sum({self.var}={self.lo}..{self.hi}, {self.body})"


def _times(a, b):
    if isinstance(a, Term) and isinstance(b, Term):
        return a.times(b)
    if isinstance(a, Sum):
        a = a.renamed()
        return Sum(a.var, a.lo, a.hi, [_times(x, b) for x in a.body], a.name)
    b = b.renamed()
    return Sum(b.var, b.lo, b.hi, [_times(a, x) for x in b.body], b.name)


def times(xs, ys):
    return [_times(a, b) for a in xs for b in ys]


class Converter:
    """Expression trees to items. `ints`, `reals`: names to SymPy symbols; `unit`: `None` for
    the zero polygon, else the symbols `(k,)` or `(k, l)` of the unit polygon or net."""

    def __init__(self, ints, reals, poly_name=None, unit=None):
        self.env = dict(ints)
        self.ints = dict(ints)
        self.reals = dict(reals)
        self.poly_name, self.unit = poly_name, unit

    def int_symbols(self):
        return list(dict.fromkeys([v for v in self.env.values() if isinstance(v, sympy.Symbol)] + list(self.ints.values())))

    def items(self, e):
        kind = e[0]
        if kind == "num":
            return [Term(sympy.Rational(e[1].numerator, e[1].denominator))]
        if kind == "var":
            if e[1] in self.env:
                return [Term(self.env[e[1]])]
            if e[1] in self.reals:
                return [Term(self.reals[e[1]])]
            raise Unsupported(f"unknown name {e[1]}")
        if kind == "neg":
            return [self._neg(x) for x in self.items(e[1])]
        if kind == "add":
            return self.items(e[1]) + self.items(e[2])
        if kind == "sub":
            return self.items(e[1]) + [self._neg(x) for x in self.items(e[2])]
        if kind == "mul":
            return times(self.items(e[1]), self.items(e[2]))
        if kind == "div":
            if e[1][0] == e[2][0] == "fact":
                return [self.falling(e[1][1], e[2][1])]
            return times(self.items(e[1]), [self.inverse(self.items(e[2]))])
        if kind == "pow":
            return self.power(e[1], e[2])
        if kind == "sum":
            _, name, lo, hi, body = e
            lo, hi = self.affine(lo), self.affine(hi)
            v = fresh("%s")
            saved = self.env.get(name)
            self.env[name] = v
            try:
                inner = self.items(body)
            finally:
                if saved is None:
                    self.env.pop(name)
                else:
                    self.env[name] = saved
            return [Sum(v, lo, hi, inner, name)]
        if kind == "call":
            return self.call(e[1], e[2])
        if kind == "index":
            return self.index(e[1], e[2])
        raise Unsupported(f"{kind} in a for-every goal")

    @staticmethod
    def _neg(x):
        if isinstance(x, Term):
            return x.scaled(-1)
        return Sum(x.var, x.lo, x.hi, [Converter._neg(y) for y in x.body], x.name)

    def pure(self, e, what):
        """A sub-expression with no binomial, power, sum or control point, as one SymPy value."""
        xs = self.items(e)
        if not all(isinstance(x, Term) and x.pure() for x in xs):
            raise Unsupported(f"{what} is not a plain rational expression")
        return sympy.expand(sum((x.c for x in xs), sympy.Integer(0)))

    def affine(self, e):
        return linear(self.pure(e, "an integer argument"), self.int_symbols())

    def real(self, e):
        x = self.pure(e, "the argument of B")
        if x.free_symbols & set(self.int_symbols()):
            raise Unsupported(f"{x}: a base that depends on an integer symbol")
        return x

    def inverse(self, xs):
        if len(xs) != 1 and all(isinstance(x, Term) and x.pure() for x in xs):
            xs = [Term(sum((x.c for x in xs), sympy.Integer(0)))]
        if len(xs) != 1 or not isinstance(xs[0], Term):
            raise Unsupported("a divisor that is a sum of terms")
        t = xs[0]
        if t.eqs or t.has_b:
            raise Unsupported("a control point in a divisor")
        if t.c == 0:
            raise Unsupported("division by zero")
        ints = set(self.int_symbols())
        nonzeros = list(t.nonzeros)
        for f, _ in sympy.factor_list(sympy.together(t.c))[1]:
            if f.free_symbols & ints:
                if f.free_symbols - ints:
                    raise Unsupported(f"a divisor {f} that mixes integer and real symbols")
                nonzeros.append(linear(f, list(ints)))
        return Term(1 / t.c, (), (), t.conds + t.musts, [(a, b, -s) for a, b, s in t.binoms], [(b, -e) for b, e in t.pows],
                    nonzeros=nonzeros)

    def falling(self, a, b):
        """`a!/b!` where `a − b` is a constant `c ≥ 0`: the product `a(a−1)…(b+1)`, defined
        where `b ≥ 0` (a factorial of a negative integer is undefined)."""
        a, b = self.affine(a), self.affine(b)
        c = sympy.expand(a - b)
        if not c.is_Integer or not 0 <= c <= MAX_ORDER:
            raise Unsupported(f"({a})!/({b})!: the arguments do not differ by a constant 0..={MAX_ORDER}")
        return Term(sympy.expand(sympy.Mul(*[a - m for m in range(int(c))])), musts=[b])

    def power(self, base, exp):
        e = self.pure(exp, "an exponent")
        if e.is_Integer:
            k = int(e)
            if abs(k) > 64:
                raise Unsupported(f"the constant exponent {k}")
            xs = self.items(base)
            if k < 0:
                xs, k = [self.inverse(xs)], -k
            out = [Term()]
            for _ in range(k):
                out = times(out, xs)
            return out
        e = linear(e, self.int_symbols())
        return [Term(pows=[(self.real(base), e)])]

    def call(self, name, args):
        if name == "B":
            i, n = self.affine(args[0]), self.affine(args[1])
            x = self.real(args[2])
            return [Term(conds=[i, n - i], binoms=[(n, i, 1)], pows=[(x, i), (1 - x, n - i)])]
        if name in ("C", "binom"):
            n, k = self.affine(args[0]), self.affine(args[1])
            return [Term(conds=[k, n - k], binoms=[(n, k, 1)])]
        if name == "__dB":
            i, n = self.affine(args[0]), self.affine(args[1])
            x = self.real(args[2])
            order = self.pure(args[3], "a derivative's order")
            if not order.is_Integer or not 0 <= order <= MAX_ORDER:
                raise Unsupported(f"__dB of order {order} (a constant 0..={MAX_ORDER} here)")
            # d^k/dx^k C(n, i) x^i (1 - x)^(n - i) by Leibniz's rule, a polynomial for
            # 0 <= i <= n: Σ_l C(k, l)·i(i−1)…(i−l+1)·x^(i−l)·(−1)^(k−l)·(n−i)…(n−i−k+l+1)·(1−x)^(n−i−k+l)
            # (a term whose falling factorial is 0 carries a negative power only where it is 0)
            k = int(order)
            common = dict(conds=[i, n - i], binoms=[(n, i, 1)])
            out = []
            for l in range(k + 1):
                c = sympy.binomial(k, l) * (-1) ** (k - l)
                c *= sympy.Mul(*[i - m for m in range(l)]) * sympy.Mul(*[n - i - m for m in range(k - l)])
                out.append(Term(sympy.expand(c), pows=[(x, i - l), (1 - x, n - i - (k - l))], **common))
            return out
        raise Unsupported(f"the function {name} in a for-every goal")

    def index(self, name, args):
        if name != self.poly_name:
            raise Unsupported(f"{name}[…] is not the goal's polygon or net")
        if self.unit is None:
            return []
        if len(args) != len(self.unit):
            raise Unsupported(f"{name}[…] with {len(args)} indices")
        return [Term(eqs=[self.affine(a) - k for a, k in zip(args, self.unit)], has_b=True)]
