"""Method `expansion` (docs/certificates.md): identities of rational functions, re-checked by
expanding both sides here with exact polynomial arithmetic over `Fraction` (standard library
only), written from the docs, sharing nothing with the program that wrote the file.

A polynomial is a dict {exponents: Fraction} (no zero coefficients) over a fixed list of
variables; a rational function a pair (numerator, denominator), never reduced: two of them
are equal when the cross products are (`a/b = c/d` iff `a d = c b`), so no gcd is needed.

Obligations, per goal equality: the file's `vars` are distinct real symbols of the goal; both
sides expanded here are equal as rational functions, entry by entry (the cleared difference is
the zero polynomial); and each listed `num`/`den` pair is that side's entry (its cross product
with this checker's expansion vanishes, the listed denominator is not zero).
"""

from fractions import Fraction
from math import comb, factorial

from .cert_eval import EvalError, Unsupported
from .cert_expr import deep

__all__ = ["check_expansion", "expand_side"]

#: Most terms one polynomial may reach here.
MAX_TERMS = 200_000
#: Largest |exponent|, Bernstein degree or binomial argument.
MAX_EXPONENT = 4096
#: Largest matrix for det and inv (cofactor expansion).
MAX_MATRIX = 6


def _padd(a, b, sign=1):
    out = dict(a)
    for e, c in b.items():
        x = out.get(e, 0) + sign * c
        if x:
            out[e] = x
        else:
            out.pop(e, None)
    return out


def _pmul(a, b):
    out = {}
    for e1, c1 in a.items():
        for e2, c2 in b.items():
            e = tuple(x + y for x, y in zip(e1, e2))
            x = out.get(e, 0) + c1 * c2
            if x:
                out[e] = x
            else:
                del out[e]
    if len(out) > MAX_TERMS:
        raise EvalError(f"a polynomial of more than {MAX_TERMS} terms")
    return out


def _const_of(p, n):
    if not p:
        return Fraction(0)
    if len(p) == 1 and (0,) * n in p:
        return p[(0,) * n]
    return None


class _RF:
    """num / den over n variables (den never the zero polynomial)."""

    __slots__ = ("num", "den", "n")

    def __init__(self, num, den, n):
        c = _const_of(den, n)
        if c is not None and c != 1:  # fold a constant denominator into the numerator
            num, den = {e: x / c for e, x in num.items()}, {(0,) * n: Fraction(1)}
        self.num, self.den, self.n = num, den, n

    @staticmethod
    def const(c, n):
        c = Fraction(c)
        return _RF({(0,) * n: c} if c else {}, {(0,) * n: Fraction(1)}, n)

    def constant(self):
        """The value when this is a constant, else None."""
        c, d = _const_of(self.num, self.n), _const_of(self.den, self.n)
        return None if c is None or d is None else c / d

    def __add__(self, o):
        if self.den == o.den:
            return _RF(_padd(self.num, o.num), self.den, self.n)
        return _RF(_padd(_pmul(self.num, o.den), _pmul(o.num, self.den)), _pmul(self.den, o.den), self.n)

    def __neg__(self):
        return _RF({e: -c for e, c in self.num.items()}, self.den, self.n)

    def __sub__(self, o):
        return self + (-o)

    def __mul__(self, o):
        return _RF(_pmul(self.num, o.num), _pmul(self.den, o.den), self.n)

    def __truediv__(self, o):
        if not o.num:
            raise EvalError("division by the zero polynomial")
        return _RF(_pmul(self.num, o.den), _pmul(self.den, o.num), self.n)

    def is_zero(self):
        return not self.num

    def same(self, o):
        return not _padd(_pmul(self.num, o.den), _pmul(o.num, self.den), -1)


class _Mat:
    __slots__ = ("rows",)

    def __init__(self, rows):
        self.rows = [list(r) for r in rows]
        if not self.rows or any(len(r) != len(self.rows[0]) for r in self.rows):
            raise EvalError("a matrix needs non-empty rows of one length")


def _add(a, b, sign=1):
    if isinstance(a, _RF) and isinstance(b, _RF):
        return a + b if sign > 0 else a - b
    if isinstance(a, tuple) and isinstance(b, tuple) and len(a) == len(b):
        return tuple(_add(x, y, sign) for x, y in zip(a, b))
    if isinstance(a, _Mat) and isinstance(b, _Mat) and len(a.rows) == len(b.rows):
        return _Mat(_add(tuple(x), tuple(y), sign) for x, y in zip(a.rows, b.rows))
    if isinstance(a, _RF) and a.is_zero() and isinstance(b, tuple):  # an empty sum meets a vector
        return _add(tuple(a for _ in b), b, sign)
    raise EvalError("adding values of different shapes")


def _mul(a, b):
    if isinstance(a, _RF):
        if isinstance(b, _RF):
            return a * b
        if isinstance(b, tuple):
            return tuple(_mul(a, x) for x in b)
        return _Mat([a * x for x in r] for r in b.rows)
    if isinstance(b, _RF):
        return _mul(b, a)
    if isinstance(a, _Mat) and isinstance(b, _Mat):
        if len(a.rows[0]) != len(b.rows):
            raise EvalError("a matrix product of mismatched sizes")
        return _Mat([_dot(r, c) for c in zip(*b.rows)] for r in a.rows)
    if isinstance(a, _Mat) and isinstance(b, tuple):
        if len(a.rows[0]) != len(b):
            raise EvalError("a matrix times a vector of mismatched size")
        return tuple(_dot(r, b) for r in a.rows)
    raise EvalError("multiplying two vectors (write dot)")


def _dot(a, b):
    if len(a) != len(b) or not all(isinstance(x, _RF) for x in list(a) + list(b)):
        raise EvalError("dot needs two vectors of numbers of one length")
    acc = a[0] * b[0]
    for x, y in zip(a[1:], b[1:]):
        acc = acc + x * y
    return acc


def _det(rows):
    """Cofactor expansion along the first row."""
    n = len(rows)
    if n == 1:
        return rows[0][0]
    acc = None
    for j in range(n):
        minor = [r[:j] + r[j + 1 :] for r in rows[1:]]
        term = rows[0][j] * _det(minor)
        acc = term if acc is None else (acc + term if j % 2 == 0 else acc - term)
    return acc


def _inv(rows):
    """adj(M) / det(M)."""
    n = len(rows)
    d = _det(rows)
    if d.is_zero():
        raise EvalError("the inverse of a matrix whose determinant is the zero polynomial")
    if n == 1:
        return _Mat([[_RF.const(1, d.n) / d]])
    out = [[None] * n for _ in range(n)]
    for i in range(n):
        for j in range(n):
            minor = [r[:j] + r[j + 1 :] for k, r in enumerate(rows) if k != i]
            c = _det(minor)
            out[j][i] = (c if (i + j) % 2 == 0 else -c) / d
    return _Mat(out)


def _upoly_at(coeffs, x, n):
    """sum_k coeffs[k] x^k for a rational function x (Horner)."""
    acc = _RF.const(0, n)
    for c in reversed(coeffs):
        acc = acc * x + _RF.const(c, n)
    return acc


def _bern_coeffs(i, n):
    out = [Fraction(0)] * (n + 1)
    for k in range(n - i + 1):
        out[i + k] = Fraction(comb(n, i) * comb(n - i, k) * (-1) ** k)
    return out


class _Expander:
    def __init__(self, variables, ints):
        self.index = {v: k for k, v in enumerate(variables)}
        self.n = len(variables)
        self.ints = dict(ints)

    def const(self, c):
        return _RF.const(c, self.n)

    def var(self, name):
        if name in self.ints:
            return self.const(self.ints[name])
        k = self.index.get(name)
        if k is None:
            raise EvalError(f"unknown name '{name}'")
        e = [0] * self.n
        e[k] = 1
        return _RF({tuple(e): Fraction(1)}, {(0,) * self.n: Fraction(1)}, self.n)

    def integer(self, e, what):
        v = self.go(e)
        c = v.constant() if isinstance(v, _RF) else None
        if c is None or c.denominator != 1:
            raise EvalError(f"{what} is not an integer")
        if abs(c) > MAX_EXPONENT:
            raise EvalError(f"{what} {c} beyond {MAX_EXPONENT}")
        return int(c)

    def scalar(self, e):
        v = self.go(e)
        if not isinstance(v, _RF):
            raise EvalError("expected a number, got a vector or a matrix")
        return v

    def go(self, e):
        kind = e[0]
        if kind == "num":
            return self.const(e[1])
        if kind == "var":
            return self.var(e[1])
        if kind == "neg":
            v = self.go(e[1])
            return _mul(self.const(-1), v)
        if kind in ("add", "sub"):
            return _add(self.go(e[1]), self.go(e[2]), 1 if kind == "add" else -1)
        if kind == "mul":
            return _mul(self.go(e[1]), self.go(e[2]))
        if kind == "div":
            a, b = self.go(e[1]), self.go(e[2])
            if not isinstance(b, _RF):
                raise EvalError("dividing by a vector or a matrix")
            return _mul(self.const(1) / b, a)
        if kind == "pow":
            base, k = self.scalar(e[1]), self.integer(e[2], "an exponent")
            acc = self.const(1)
            for _ in range(abs(k)):
                acc = acc * base
            return acc if k >= 0 else self.const(1) / acc
        if kind == "fact":
            m = self.integer(e[1], "a factorial's argument")
            if m < 0:
                raise EvalError(f"the factorial of {m}")
            return self.const(factorial(m))
        if kind == "tuple":
            return tuple(self.go(a) for a in e[1])
        if kind == "matrix":
            return _Mat([self.scalar(a) for a in r] for r in e[1])
        if kind == "sum":
            return self.sum(e)
        if kind == "call":
            return self.call(e[1], e[2])
        raise Unsupported(f"'{kind}' in an expansion")

    def sum(self, e):
        _, var, lo, hi, body = e
        a, b = self.integer(lo, "a sum's bound"), self.integer(hi, "a sum's bound")
        saved = self.ints.get(var)
        acc = self.const(0)
        try:
            for k in range(a, b + 1):
                self.ints[var] = k
                acc = _add(acc, self.go(body))
        finally:
            if saved is None:
                self.ints.pop(var, None)
            else:
                self.ints[var] = saved
        return acc

    def call(self, name, args):
        ints = lambda k: [self.integer(a, f"an argument of {name}") for a in args[:k]]  # noqa: E731
        if name == "B":
            i, n = ints(2)
            if i < 0 or i > n:
                return self.const(0)
            return _upoly_at(_bern_coeffs(i, n), self.scalar(args[2]), self.n)
        if name in ("C", "binom"):
            n, k = ints(2)
            return self.const(comb(n, k) if 0 <= k <= n else 0)
        if name == "__dB":
            i, n = ints(2)
            k = self.integer(args[3], "a derivative's order")
            if k < 0:
                raise EvalError("a negative derivative order")
            if i < 0 or i > n:
                return self.const(0)
            p = _bern_coeffs(i, n)
            for _ in range(k):
                p = [j * p[j] for j in range(1, len(p))] or [Fraction(0)]
            return _upoly_at(p, self.scalar(args[2]), self.n)
        if name == "__dpow":
            x = self.scalar(args[0])
            ex, k = self.integer(args[1], "an exponent"), self.integer(args[2], "an order")
            c = 1
            for j in range(k):
                c *= ex - j
            if c == 0:
                return self.const(0)
            return self._power(x, ex - k, c)
        if name == "dot":
            a, b = self.go(args[0]), self.go(args[1])
            if not (isinstance(a, tuple) and isinstance(b, tuple)):
                raise EvalError("dot needs two vectors")
            return _dot(a, b)
        if name == "comp":
            v, k = self.go(args[0]), self.integer(args[1], "comp's index")
            if not isinstance(v, tuple) or not 1 <= k <= len(v):
                raise EvalError(f"comp(v, {k}) outside the vector")
            return v[k - 1]
        if name in ("det", "inv", "transpose"):
            m = self.go(args[0])
            if not isinstance(m, _Mat):
                raise EvalError(f"{name} of a non-matrix")
            if name == "transpose":
                return _Mat(zip(*m.rows))
            if len(m.rows) != len(m.rows[0]) or len(m.rows) > MAX_MATRIX:
                raise Unsupported(f"{name} of a {len(m.rows)}×{len(m.rows[0])} matrix")
            return _det(m.rows) if name == "det" else _inv(m.rows)
        if name in ("rows", "cols"):
            vs = [self.go(a) for a in args]
            if not all(isinstance(v, tuple) and len(v) == len(vs[0]) for v in vs):
                raise EvalError(f"{name} needs vectors of one length")
            return _Mat(vs) if name == "rows" else _Mat(zip(*vs))
        raise Unsupported(f"the function '{name}' in an expansion")

    def _power(self, x, k, c):
        acc = self.const(1)
        for _ in range(abs(k)):
            acc = acc * x
        return self.const(c) * (acc if k >= 0 else self.const(1) / acc)


def _entries(v):
    if isinstance(v, _RF):
        return [v]
    if isinstance(v, tuple):
        return [x for item in v for x in _entries(item)]
    return [x for r in v.rows for x in r]


def _shape(v):
    if isinstance(v, _RF):
        return "scalar"
    if isinstance(v, tuple):
        return ("vector", len(v))
    return ("matrix", len(v.rows), len(v.rows[0]))


def expand_side(expr, variables, ints):
    """The value of a parsed expression as rational functions of `variables` (scalars, tuples
    or `_Mat`s of `_RF`)."""
    with deep():
        return _Expander(variables, ints).go(expr)


def _read_poly(v, file_vars, order, where, need, rational):
    need(isinstance(v, list), f"{where}: not a list of terms")
    out = {}
    n = len(order)
    for k, t in enumerate(v):
        at = f"{where}[{k}]"
        need(isinstance(t, list) and len(t) == 2, f"{at}: not [coefficient, exponents]")
        c, e = t
        need(isinstance(c, str), f"{at}: the coefficient is not a string")
        c = rational(c, at)
        need(c != 0, f"{at}: a zero coefficient")
        ok = isinstance(e, list) and len(e) == len(file_vars)
        ok = ok and all(isinstance(x, int) and not isinstance(x, bool) and 0 <= x <= MAX_EXPONENT for x in e)
        need(ok, f"{at}: not one exponent 0..={MAX_EXPONENT} per variable ({len(file_vars)})")
        mono = [0] * n
        for name, x in zip(file_vars, e):
            mono[order[name]] = x
        mono = tuple(mono)
        need(mono not in out, f"{at}: the monomial is listed twice")
        out[mono] = c
    return out


def check_expansion(data, goal, need, rational):
    """Re-checks the `expansion` part of a certificate against its parsed goal; `need(cond,
    message)` refuses with the message, `rational(text, where)` reads an exact number.
    Returns the detail line."""
    need(isinstance(data, dict) and isinstance(data.get("equalities"), list), "expansion: equalities missing")
    eqs = data["equalities"]
    need(len(eqs) == len(goal.equalities), f"expansion: {len(eqs)} entries for {len(goal.equalities)} goal equalities")
    listed_terms = 0
    for k, (item, (ints, lhs, rhs, reals)) in enumerate(zip(eqs, goal.equalities)):
        where = f"expansion.equalities[{k}]"
        need(isinstance(item, dict), f"{where}: not an object")
        fv = item.get("vars")
        need(isinstance(fv, list) and all(isinstance(v, str) for v in fv), f"{where}: vars missing")
        need(len(set(fv)) == len(fv), f"{where}: a variable listed twice")
        for v in fv:
            need(goal.sorts.get(v) == "real", f"{where}: '{v}' is not a real symbol of the goal")
        variables = sorted(set(fv) | set(reals))
        order = {v: i for i, v in enumerate(variables)}
        lv, rv = expand_side(lhs, variables, ints), expand_side(rhs, variables, ints)
        need(_shape(lv) == _shape(rv), f"equality {k}: the sides have different shapes")
        le, re_ = _entries(lv), _entries(rv)
        for j, (a, b) in enumerate(zip(le, re_)):
            need(a.same(b), f"equality {k}: entry {j}: lhs − rhs is not the zero rational function")
        entries = item.get("entries")
        need(isinstance(entries, list) and len(entries) == len(le), f"{where}: not one listed pair per entry ({len(le)})")
        for j, (pair, mine) in enumerate(zip(entries, zip(le, re_))):
            for side, own in zip(("lhs", "rhs"), mine):
                at = f"{where}.entries[{j}].{side}"
                got = pair.get(side) if isinstance(pair, dict) else None
                need(isinstance(got, dict), f"{at}: missing")
                num = _read_poly(got.get("num"), fv, order, f"{at}.num", need, rational)
                den = _read_poly(got.get("den"), fv, order, f"{at}.den", need, rational)
                need(bool(den), f"{at}.den: the zero polynomial")
                listed = _RF(num, den, len(variables))
                need(listed.same(own), f"{at}: num/den is not the {side} side's entry {j}")
                listed_terms += len(num) + len(den)
    return f"{len(eqs)} equalities expanded here as rational functions: lhs − rhs = 0, the {listed_terms} listed terms agree"
