"""The book-style expression grammar of the claims and certificates, parsed into a small tree.

Written from the grammar in docs/claims.md and proofs/README.md (not from the Rust parser):

    list    := sum ("," sum)*               a comma list inside ( ) is a tuple
    sum     := term (("+" | "-") term)*
    term    := unary (("*" | "/" | implicit) unary)*     2t, 4x^2, (1-t)(1+t)
    unary   := "-" unary | "+" unary | power
    power   := postfix ("^" unary)?         right associative: -t^2 = -(t^2), t^-1
    postfix := primary "!"*
    primary := number | name | name "(" args ")" | name "[" args "]" | "(" list ")"
             | "[" rows "]"

A run of letters that is neither a known name nor a call is a product of one-letter variables
(`st` = s*t); names with digits, `_` or `'` (`t0`, `x_u`, `b'`) are single names.

Nodes are tuples whose first item is the kind: ("num", Fraction), ("var", name),
("neg", a), ("add"|"sub"|"mul"|"div"|"pow", a, b), ("fact", a), ("call", name, args),
("index", name, args), ("sum", var, lo, hi, body), ("tuple", items), ("matrix", rows).
Only the standard library is used.
"""

import contextlib
import sys
from fractions import Fraction

__all__ = ["ParseError", "parse", "FUNCTIONS", "free_names", "show", "deep", "MAX_LEN", "MAX_DEPTH", "MAX_TREE_DEPTH"]

#: Built-in function names: never split into one-letter variables.
FUNCTIONS = frozenset(
    "B C binom sum sqrt diff dot det inv rows cols transpose delta comp integral __dB __dpow".split()
)
#: Longest expression text accepted.
MAX_LEN = 20_000
#: Deepest nesting accepted (parentheses, powers, calls).
MAX_DEPTH = 200
#: Deepest tree accepted (a chain `a + b + ... + z` of N terms is N deep); every pass over a
#: tree recurses once per level, under `deep()`.
MAX_TREE_DEPTH = 4000

_SYMBOLS = "+-*/^()[],;!"
_ALIASES = {"·": "*", "×": "*", "−": "-"}


@contextlib.contextmanager
def deep():
    """Room for the recursion of a pass over a tree of up to MAX_TREE_DEPTH levels."""
    old = sys.getrecursionlimit()
    sys.setrecursionlimit(max(old, 12 * MAX_TREE_DEPTH))
    try:
        yield
    finally:
        sys.setrecursionlimit(old)


def tree_depth(e):
    """The depth of a tree, computed without recursion."""
    best, stack = 0, [(e, 1)]
    while stack:
        node, d = stack.pop()
        best = max(best, d)
        kind = node[0]
        if kind in ("num", "var"):
            continue
        if kind in ("call", "index"):
            kids = node[2]
        elif kind == "tuple":
            kids = node[1]
        elif kind == "matrix":
            kids = [a for r in node[1] for a in r]
        elif kind == "sum":
            kids = node[2:]
        else:
            kids = node[1:]
        stack.extend((k, d + 1) for k in kids)
    return best


class ParseError(ValueError):
    """An expression that is not in the grammar (the message names the text)."""


def _lex(text, known, strict):
    if len(text) > MAX_LEN:
        raise ParseError(f"expression of {len(text)} characters (limit {MAX_LEN})")
    toks = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if c.isspace():
            i += 1
        elif c.isdigit() or (c == "." and i + 1 < n and text[i + 1].isdigit()):
            j = i
            while j < n and (text[j].isdigit() or text[j] == "."):
                j += 1
            lit = text[i:j]
            if lit.count(".") > 1:
                raise ParseError(f"bad number '{lit}' in '{text}'")
            toks.append(("num", Fraction(lit)))
            i = j
        elif c.isalpha() or c == "_":
            j = i
            while j < n and (text[j].isalnum() or text[j] in "_'"):
                j += 1
            word = text[i:j]
            called = j < n and text[j] == "("
            if strict or called or word in known or word in FUNCTIONS or len(word) == 1 or not word.isalpha():
                toks.append(("name", word))
            else:
                toks.extend(("name", ch) for ch in word)
            i = j
        elif c in _SYMBOLS or (c in _ALIASES and not strict):
            toks.append(("sym", _ALIASES.get(c, c)))
            i += 1
        else:
            raise ParseError(f"unexpected character '{c}' in '{text}'")
    return toks


class _Parser:
    def __init__(self, text, known, strict):
        self.text = text
        self.known = known
        self.strict = strict
        self.toks = _lex(text, known, strict)
        self.pos = 0
        self.depth = 0

    def fail(self, msg):
        raise ParseError(f"{msg} in '{self.text}'")

    def peek_sym(self, c):
        return self.pos < len(self.toks) and self.toks[self.pos] == ("sym", c)

    def take(self, c):
        if not self.peek_sym(c):
            found = self.toks[self.pos][1] if self.pos < len(self.toks) else "end of input"
            self.fail(f"expected '{c}', found {found}")
        self.pos += 1

    def nest(self):
        self.depth += 1
        if self.depth > MAX_DEPTH:
            self.fail(f"nesting deeper than {MAX_DEPTH}")

    def parse_list(self):
        first = self.parse_sum()
        if not self.peek_sym(","):
            return first
        items = [first]
        while self.peek_sym(","):
            self.pos += 1
            if self.peek_sym(")"):
                break
            items.append(self.parse_sum())
        return ("tuple", tuple(items))

    def parse_sum(self):
        acc = self.parse_term()
        while self.peek_sym("+") or self.peek_sym("-"):
            op = "add" if self.toks[self.pos][1] == "+" else "sub"
            self.pos += 1
            acc = (op, acc, self.parse_term())
        return acc

    def starts_primary(self):
        if self.pos >= len(self.toks):
            return False
        kind, val = self.toks[self.pos]
        return kind in ("num", "name") or val in ("(", "[")

    def parse_term(self):
        acc = self.parse_unary()
        while True:
            if self.peek_sym("*"):
                self.pos += 1
                acc = ("mul", acc, self.parse_unary())
            elif self.peek_sym("/"):
                self.pos += 1
                acc = ("div", acc, self.parse_unary())
            elif self.starts_primary():
                if self.strict:
                    self.fail(f"'{self.toks[self.pos][1]}' follows a term without an operator")
                acc = ("mul", acc, self.parse_power())
            else:
                return acc

    def parse_unary(self):
        if self.peek_sym("-"):
            self.pos += 1
            self.nest()
            e = ("neg", self.parse_unary())
            self.depth -= 1
            return e
        if self.peek_sym("+"):
            self.pos += 1
            self.nest()
            e = self.parse_unary()
            self.depth -= 1
            return e
        return self.parse_power()

    def parse_power(self):
        base = self.parse_postfix()
        if self.peek_sym("^"):
            self.pos += 1
            self.nest()
            e = ("pow", base, self.parse_unary())
            self.depth -= 1
            return e
        return base

    def parse_postfix(self):
        e = self.parse_primary()
        while self.peek_sym("!"):
            self.pos += 1
            e = ("fact", e)
        return e

    def parse_args(self, close):
        args = []
        if self.peek_sym(close):
            self.pos += 1
            return tuple(args)
        while True:
            args.append(self.parse_sum())
            if self.peek_sym(","):
                self.pos += 1
            else:
                self.take(close)
                return tuple(args)

    def parse_primary(self):
        self.nest()
        try:
            return self._primary()
        finally:
            self.depth -= 1

    def _primary(self):
        if self.pos >= len(self.toks):
            self.fail("unexpected end of expression")
        kind, val = self.toks[self.pos]
        self.pos += 1
        if kind == "num":
            return ("num", val)
        if kind == "sym":
            if val == "(":
                e = self.parse_list()
                self.take(")")
                return e
            if val == "[":
                return self.parse_matrix()
            self.fail(f"unexpected '{val}'")
        name = val
        plain_letter = not self.strict and len(name) == 1 and name not in FUNCTIONS and name not in self.known
        if self.peek_sym("(") and not plain_letter:
            self.pos += 1
            args = self.parse_args(")")
            if name == "sum":
                if len(args) != 4 or args[0][0] != "var":
                    self.fail("sum needs sum(var, from, to, body)")
                return ("sum", args[0][1], args[1], args[2], args[3])
            _check_arity(name, len(args), self.fail)
            return ("call", name, args)
        # strict (a certificate's goal): only a declared name is indexed (its control points,
        # or a for-every goal's symbolic polygon or net)
        if self.peek_sym("[") and (not self.strict or name in self.known):
            self.pos += 1
            args = self.parse_args("]")
            if not args:
                self.fail(f"{name}[] needs an index")
            return ("index", name, args)
        if name in FUNCTIONS:
            self.fail(f"function {name} needs arguments in parentheses")
        return ("var", name)

    def parse_matrix(self):
        if self.peek_sym("]"):
            self.fail("empty matrix")
        rows = [[]]
        while True:
            rows[-1].append(self.parse_sum())
            if self.peek_sym(","):
                self.pos += 1
            elif self.peek_sym(";"):
                self.pos += 1
                rows.append([])
            else:
                self.take("]")
                break
        if any(len(r) != len(rows[0]) for r in rows):
            self.fail("matrix rows of different lengths")
        return ("matrix", tuple(tuple(r) for r in rows))


_ARITY = {
    "B": (3, 3),
    "C": (2, 2),
    "binom": (2, 2),
    "dot": (2, 2),
    "comp": (2, 2),
    "sqrt": (1, 1),
    "det": (1, 1),
    "inv": (1, 1),
    "transpose": (1, 1),
    "diff": (2, 3),
    "delta": (3, 3),
    "integral": (4, 4),
    "__dB": (4, 4),
    "__dpow": (3, 3),
    "rows": (1, 10**6),
    "cols": (1, 10**6),
}


def _check_arity(name, n, fail):
    lo, hi = _ARITY.get(name, (0, 10**6))
    if not lo <= n <= hi:
        fail(f"{name} takes {lo}{'' if lo == hi else '+'} arguments, got {n}")


def parse(text, known=(), strict=False):
    """Parses `text`; `known` lists multi-letter names not to split into letters.

    `strict`: the certificates' grammar (docs/certificates.md), where every product is
    written with `*`: no implicit multiplication, a word is always one name, only ASCII
    operators, and `name(` is always a call.
    """
    if not isinstance(text, str):
        raise ParseError(f"an expression must be a string, not {type(text).__name__}")
    p = _Parser(text, frozenset(known), strict)
    if not p.toks:
        raise ParseError("empty expression")
    with deep():
        e = p.parse_list()
    if p.pos < len(p.toks):
        p.fail(f"unexpected '{p.toks[p.pos][1]}'")
    if tree_depth(e) > MAX_TREE_DEPTH:
        raise ParseError(f"an expression tree deeper than {MAX_TREE_DEPTH} levels")
    return e


def free_names(e, bound=frozenset()):
    """The variable names `e` uses that no `sum` (or integral) binds."""
    out = set()
    _free(e, bound, out)
    return out


def _free(e, bound, out):
    kind = e[0]
    if kind == "var":
        if e[1] not in bound:
            out.add(e[1])
    elif kind == "num":
        pass
    elif kind == "sum":
        _free(e[2], bound, out)
        _free(e[3], bound, out)
        _free(e[4], bound | {e[1]}, out)
    elif kind == "call" and e[1] == "integral" and e[2][1][0] == "var":
        v = e[2][1][1]
        _free(e[2][0], bound | {v}, out)
        _free(e[2][2], bound, out)
        _free(e[2][3], bound, out)
    elif kind in ("call", "index"):
        for a in e[2]:
            _free(a, bound, out)
    elif kind == "tuple":
        for a in e[1]:
            _free(a, bound, out)
    elif kind == "matrix":
        for row in e[1]:
            for a in row:
                _free(a, bound, out)
    else:
        for a in e[1:]:
            _free(a, bound, out)


_PREC = {"add": 1, "sub": 1, "mul": 2, "div": 2, "neg": 3, "pow": 4, "fact": 5}


def show(e):
    """The expression written back in the grammar (fully parenthesised where needed)."""
    kind = e[0]
    if kind == "num":
        return str(e[1])
    if kind == "var":
        return e[1]
    if kind == "neg":
        return f"-{_wrap(e[1], 3)}"
    if kind in ("add", "sub", "mul", "div"):
        sym = {"add": " + ", "sub": " - ", "mul": "*", "div": "/"}[kind]
        return f"{_wrap(e[1], _PREC[kind])}{sym}{_wrap(e[2], _PREC[kind] + 1)}"
    if kind == "pow":
        return f"{_wrap(e[1], 5)}^{_wrap(e[2], 5)}"
    if kind == "fact":
        return f"{_wrap(e[1], 6)}!"
    if kind == "call":
        return f"{e[1]}({', '.join(show(a) for a in e[2])})"
    if kind == "index":
        return f"{e[1]}[{', '.join(show(a) for a in e[2])}]"
    if kind == "sum":
        return f"sum({e[1]}, {show(e[2])}, {show(e[3])}, {show(e[4])})"
    if kind == "tuple":
        inner = ", ".join(show(a) for a in e[1])
        return f"({inner}{',' if len(e[1]) == 1 else ''})"
    if kind == "matrix":
        return "[" + "; ".join(", ".join(show(a) for a in r) for r in e[1]) + "]"
    raise ValueError(f"not an expression node: {kind}")


def _wrap(e, prec):
    s = show(e)
    if e[0] == "num":
        p = 3 if e[1] < 0 else 2 if e[1].denominator != 1 else 9
    else:
        p = _PREC.get(e[0], 9)
    return f"({s})" if p < prec else s
