"""Goals in a real quadratic field Q(√d) (docs/certificates.md, "Square roots"), with SymPy.

A goal may call `sqrt(d)` for one integer d >= 2 that is square-free (√d real and
irrational); every call in the goal the same d. Its listed values are exact rationals "p/q"
or `{"rational": "a", "irrational": "b", "radicand": "d"}`, the number a + b√d with b != 0 and
the goal's d. The sides are evaluated at a grid point by substituting the point's rationals
into the tree and translating it with `cert_sympy.to_sympy` (`sqrt` is SymPy's, exact); a
value is reduced to the form a + b√d by `radsimp` (rationalising denominators) and `expand`,
which decide exactly whether it is zero. Every divisor (and the base of a negative power) is
evaluated on its own and must be non-zero at the point.
"""

import re
from fractions import Fraction

from .cert_eval import EvalError, Pole, Unsupported
from .cert_expr import deep

__all__ = ["SqrtError", "radicand", "number", "values", "same", "MAX_RADICAND"]

#: Largest radicand read (the program's limit, 2^40).
MAX_RADICAND = 1 << 40
_RATIONAL = re.compile(r"^-?[0-9]+(/[1-9][0-9]*)?$")


class SqrtError(ValueError):
    """A goal or value outside one field Q(√d) as the docs define it (the message says why)."""


def _is_node(x):
    return isinstance(x, tuple) and bool(x) and isinstance(x[0], str)


def _children(e):
    """The sub-trees of a node: its node items, and the nodes of its (nested) sequences."""
    stack = list(e[1:])
    while stack:
        x = stack.pop(0)
        if _is_node(x):
            yield x
        elif isinstance(x, (tuple, list)):
            stack[:0] = list(x)


def _nodes(e):
    """Every node of a tree (a node: a tuple whose first item is its kind)."""
    yield e
    for x in _children(e):
        yield from _nodes(x)


def _square_free(d):
    p = 2
    while p * p <= d:
        if d % (p * p) == 0:
            return False
        p += 1
    return True


def _sympy():
    try:
        import sympy
    except ImportError:  # pragma: no cover - SymPy is the optional [check] dependency
        raise Unsupported("a goal in Q(√d) needs SymPy") from None
    return sympy


def radicand(exprs):
    """The d of the `sqrt(d)` calls of the trees `exprs` (None: there is none)."""
    found = None
    with deep():
        for e in exprs:
            for node in _nodes(e):
                if node[0] != "call" or node[1] != "sqrt":
                    continue
                args = node[2]
                d = None
                if len(args) == 1 and args[0][0] == "num" and args[0][1].denominator == 1:
                    d = int(args[0][1])
                if d is None or d < 2:
                    raise SqrtError("sqrt's argument is not an integer d >= 2 (a real irrational √d)")
                if d > MAX_RADICAND:
                    raise SqrtError(f"sqrt({d}): the radicand exceeds {MAX_RADICAND}")
                if not _square_free(d):
                    raise SqrtError(f"sqrt({d}): {d} is not square-free")
                if found is not None and found != d:
                    raise SqrtError(f"the goal mixes sqrt({found}) and sqrt({d}): one field Q(√d) per goal")
                found = d
    return found


def _rational(s, where):
    if not (isinstance(s, str) and _RATIONAL.match(s) and str(Fraction(s)) == s):
        raise SqrtError(f"{where}: {s!r} is not an exact rational \"p\" or \"p/q\" written reduced")
    return Fraction(s)


def number(x, where, d):
    """A listed value as a SymPy number of Q(√d) (`d` the goal's radicand)."""
    sympy = _sympy()
    if isinstance(x, str):
        v = _rational(x, where)
        return sympy.Rational(v.numerator, v.denominator)
    if not isinstance(x, dict) or set(x) != {"rational", "irrational", "radicand"}:
        raise SqrtError(f"{where}: {x!r} is not a rational or a number a + b√d")
    parts = []
    for k in ("rational", "irrational"):
        v = _rational(x[k], f"{where}.{k}")
        parts.append(sympy.Rational(v.numerator, v.denominator))
    r = x["radicand"]
    if not (isinstance(r, str) and r.lstrip("-").isdigit() and str(int(r)) == r):
        raise SqrtError(f"{where}: radicand {r!r} is not an integer")
    if int(r) != d:
        raise SqrtError(f"{where}: a number of Q(√{r}), the goal is in Q(√{d})")
    if parts[1] == 0:
        raise SqrtError(f"{where}: a rational number is written \"p/q\"")
    return parts[0] + parts[1] * sympy.sqrt(d)


def _canon(v):
    sympy = _sympy()
    return sympy.expand(sympy.radsimp(v))


def _substitute(e, env):
    if e[0] == "var" and e[1] in env:
        return ("num", env[e[1]])
    if e[0] == "sum":
        raise Unsupported("a sum in a goal in Q(√d)")

    def go(x):
        if _is_node(x):
            return _substitute(x, env)
        if isinstance(x, (tuple, list)):
            return type(x)(go(y) for y in x)
        return x

    return (e[0],) + tuple(go(x) for x in e[1:])


def _entries(v):
    sympy = _sympy()
    if isinstance(v, list):
        return [x for item in v for x in _entries(item)]
    if isinstance(v, sympy.MatrixBase):
        return [_canon(x) for x in v]
    return [_canon(v)]


def values(e, env):
    """The entries of tree `e` at the rational point `env` (name -> Fraction), each a + b√d;
    `Pole` when a divisor is zero there."""
    sympy = _sympy()
    from .cert_sympy import to_sympy

    with deep():
        t = _substitute(e, env)
        for node in _nodes(t):
            divisor = None
            if node[0] == "div":
                divisor = node[2]
            elif node[0] == "pow":
                k = to_sympy(node[2])
                if not (isinstance(k, sympy.Integer)):
                    raise EvalError("an exponent that is not an integer")
                if k < 0:
                    divisor = node[1]
            if divisor is not None:
                v = to_sympy(divisor)
                if isinstance(v, (list, sympy.MatrixBase)):
                    raise Unsupported("division by a vector or matrix")
                if _canon(v) == 0:
                    raise Pole("division by zero")
        return _entries(to_sympy(t))


def same(a, b):
    """Whether two numbers of Q(√d) are equal (exactly: their difference reduces to 0)."""
    return _canon(a - b) == 0
