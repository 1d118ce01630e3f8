"""The proof of a for-every goal (methods `pieces` and `wz`), this checker's own argument
(docs/certificates.md, "The Python checker"); needs SymPy.

`prove(dom, items)` shows `Σ items = 0` at every integer point of `dom` and every real value:

1. An inequality of `dom` that holds with equality is substituted (a boundary line becomes an
   identity in fewer symbols). An empty `dom` is proved.
2. Each term's conditions are decided on `dom` (`Domain.implies`): a term whose condition
   fails is 0 and dropped, a condition that holds is dropped; a sum's control-point indicator
   `[var + c = k]` collapses the sum to the one term `var = k − c` (with `lo ≤ k − c ≤ hi`);
   a sum of constant length is written out.
3. A condition still undecided splits `dom` into pieces (`L ≥ 0` / `L ≤ −1`, or `L ≥ 1` /
   `L = 0` / `L ≤ −1` for an indicator, a zero base's exponent, a divisor), each proved.
4. Every term is then given by its formula on all of `dom`: divided by the first term, each is
   a rational function (factorials whose arguments differ by constants, powers of one base
   whose exponents differ by constants, both valid since every factorial argument is ≥ 0 on
   `dom`), and their sum must cancel to 0 (SymPy `cancel`). It is an identity of rational
   functions, so it holds at every point where no divisor vanishes: integer divisors are
   nonzero on `dom` (step 3), real ones vanish only on a set whose complement is dense, and
   each side is a rational function of the reals, so it holds there too.
5. Sums of symbolic length: see `cert_wz` (sums of one length compared term by term; a sum
   against closed terms, or a nested sum, by a WZ certificate of the file).
"""

import sympy

from .cert_domain import TooLarge
from .cert_terms import Sum, Term

__all__ = ["Refuted", "Undecided", "Prover"]

#: Most pieces one goal is split into.
MAX_PIECES = 20_000
#: Longest sum written out term by term.
MAX_EXPAND = 64


class Refuted(Exception):
    """A necessary obligation fails (the message names it)."""


class Undecided(Exception):
    """The argument does not apply (the message says where)."""


def _is_int_only(x, syms):
    return x.free_symbols and x.free_symbols <= syms


class Prover:
    def __init__(self, reals, wz=None):
        self.reals = set(reals)
        self.pieces = 0
        self.wz = wz  # cert_wz.Wz: sums of symbolic length

    # --- step 1 and 2 ---------------------------------------------------------------

    def normalize(self, dom, items):
        while True:
            if not dom.feasible():
                return None, None
            eq = dom.equality()
            if eq is None:
                return dom, items
            var, val = eq
            dom = dom.substitute(var, val)
            items = [x.subs({var: val}) for x in items]

    def simplify(self, dom, items):
        out = []
        for x in items:
            out.extend(self._simplify_term(dom, x) if isinstance(x, Term) else self._simplify_sum(dom, x))
        return out

    def _simplify_term(self, dom, t):
        if t.lazy and self._zero(dom, t):
            return []
        # where the term is undefined (a vanishing binomial or integer divisor), the goal is:
        # decided before any condition that would make the term 0 (the evaluator divides too)
        musts = []
        for L in t.musts:
            if dom.implies(L):
                continue
            if L.is_Integer or dom.implies(-L - 1):
                raise Refuted(f"division by a vanishing binomial where {dom.show()}")
            musts.append(L)
        nonzeros = []
        for L in t.nonzeros:
            sign = dom.sign(L)
            if sign == 0:
                raise Refuted(f"division by zero (a divisor of the goal vanishes) where {dom.show()}")
            if sign is None:
                nonzeros.append(L)
        c = sympy.cancel(t.c)
        pending = bool(musts) or bool(nonzeros) or self._divisor(dom, c) is not None
        if pending:
            return [t.with_(c=c, musts=musts, nonzeros=nonzeros)]
        if c == 0:
            return []
        conds, eqs, binoms, pows = [], [], [], []
        for L in t.conds:
            if L.is_Integer:
                if L < 0:
                    return []
                continue
            if dom.implies(L):
                continue
            if dom.implies(-L - 1):
                return []
            conds.append(L)
        for L in t.eqs:
            if L.is_Integer:
                if L != 0:
                    return []
                continue
            if dom.implies(L - 1) or dom.implies(-L - 1):
                return []
            eqs.append(L)
        for a, b, s in t.binoms:
            if a.is_Integer and b.is_Integer:
                if 0 <= b <= a:
                    c *= sympy.binomial(a, b) ** s
                    continue
                if s > 0:
                    return []
                raise Refuted(f"division by C({a}, {b}) = 0 where {dom.show()}")
            binoms.append((a, b, s))
        for base, e in t.pows:
            base = sympy.expand(base)
            if base == 1:
                continue
            if e.is_Integer:
                if base == 0 and e < 0:
                    raise Refuted(f"0 to the power {e} where {dom.show()}")
                c *= base ** int(e)
                continue
            if base == 0:
                if dom.implies(e - 1):
                    return []
                if dom.implies(-e - 1):
                    raise Refuted(f"0 to a negative power {e} where {dom.show()}")
            pows.append((base, e))
        c = sympy.cancel(c)
        if c == 0:
            return []
        return [t.with_(c=c, conds=conds, eqs=eqs, musts=musts, binoms=binoms, pows=pows, nonzeros=())]

    def _simplify_sum(self, dom, s):
        length = sympy.expand(s.hi - s.lo)
        if length.is_Integer and length < 0:
            return []
        inner = dom.with_(s.var - s.lo, s.hi - s.var, add_syms=[s.var])
        body = self.simplify(inner, s.body)
        kept, out = [], []
        for x in body:
            # a term that may divide by zero at another value of var is not collapsed (the
            # evaluator divides there even where the control point is 0)
            if (
                isinstance(x, Term)
                and not x.musts
                and not x.nonzeros
                and not sympy.fraction(sympy.together(x.c))[1].has(s.var)
            ):
                hit = _collapse(x, s.var)
                # a term nonzero only in a window a ≤ var ≤ a + c (c a constant): written out
                vals = [hit] if hit is not None else None if x.lazy else _window(x, s.var)
                if vals is not None:
                    for val in vals:
                        moved = x.subs({s.var: val})
                        out.append(moved.with_(conds=moved.conds + (val - s.lo, s.hi - val)))
                    continue
            nested = _collapse_nested(x, s)
            if nested is not None:
                out.append(nested)
                continue
            kept.append(x)
        if kept and not out:
            s = _tighten(dom, Sum(s.var, s.lo, s.hi, kept, s.name))
            kept, length = s.body, sympy.expand(s.hi - s.lo)
            if length.is_Integer and length < 0:
                return []
        if kept and length.is_Integer:
            if length > MAX_EXPAND:
                raise Undecided(f"a sum of {length + 1} terms")
            for j in range(int(length) + 1):
                out.extend(x.subs({s.var: s.lo + j}) for x in kept)
            kept = []
        if out:
            return self.simplify(dom, out) + ([Sum(s.var, s.lo, s.hi, kept, s.name)] if kept else [])
        return [Sum(s.var, s.lo, s.hi, kept, s.name)] if kept else []

    # --- step 3 ---------------------------------------------------------------------

    def _divisor(self, dom, c):
        """An integer divisor of `c` whose sign is undecided on `dom` (None if none); raises
        when one vanishes on all of `dom`."""
        syms = set(dom.syms)
        _, den = sympy.fraction(sympy.together(c))
        for f, _ in sympy.factor_list(den)[1]:
            if not f.free_symbols & syms:
                continue
            if not _is_int_only(f, syms):
                raise Undecided(f"a divisor {f} that mixes integer and real symbols")
            if sympy.Poly(f, *sorted(syms, key=str)).total_degree() > 1:
                raise Undecided(f"a divisor {f} that is not affine")
            sign = dom.sign(f)
            if sign == 0:
                raise Refuted(f"division by {f} = 0 where {dom.show()}")
            if sign is None:
                return f
        return None

    @staticmethod
    def _zero(dom, t):
        """Whether a condition of `t` fails on all of `dom`."""
        for L in t.conds:
            if (L.is_Integer and L < 0) or (not L.is_Integer and dom.implies(-L - 1)):
                return True
        for L in t.eqs:
            if (L.is_Integer and L != 0) or (not L.is_Integer and (dom.implies(L - 1) or dom.implies(-L - 1))):
                return True
        return False

    def _split(self, dom, items):
        """The pieces of `dom` for the first undecided condition, or None."""
        for t in items:
            if not isinstance(t, Term):
                continue
            if t.lazy:
                for L in t.conds:
                    if not L.is_Integer and not dom.implies(L):
                        return [dom.with_(L), dom.with_(-L - 1)]
            for L in t.musts:
                return [dom.with_(L), dom.with_(-L - 1)]
            for L in t.nonzeros:
                return [dom.with_(L - 1), dom.with_(L, -L), dom.with_(-L - 1)]
            f = self._divisor(dom, t.c)
            if f is not None:
                return [dom.with_(f - 1), dom.with_(f, -f), dom.with_(-f - 1)]
            for L in t.conds:
                return [dom.with_(L), dom.with_(-L - 1)]
            for L in t.eqs:
                return [dom.with_(L - 1), dom.with_(L, -L), dom.with_(-L - 1)]
            for base, e in t.pows:
                if base == 0:
                    return [dom.with_(e - 1), dom.with_(e, -e), dom.with_(-e - 1)]
        return None

    # --- the whole argument ---------------------------------------------------------

    def prove(self, dom, items):
        """Proves `Σ items = 0` on `dom`, or raises `Refuted` / `Undecided`."""
        self.pieces += 1
        if self.pieces > MAX_PIECES:
            raise Undecided(f"more than {MAX_PIECES} pieces")
        try:
            dom, items = self.normalize(dom, items)
            if dom is None:
                return
            items = self.simplify(dom, items)
            if not items:
                return
            pieces = self._split(dom, items)
        except TooLarge:
            raise Undecided("a domain too large to decide") from None
        if pieces is not None:
            for p in pieces:
                self.prove(p, items)
            return
        terms = [x for x in items if isinstance(x, Term)]
        sums = [x for x in items if isinstance(x, Sum)]
        if not sums:
            self.identity(dom, terms)
            return
        if self.wz is None:
            raise Undecided("a sum of symbolic length")
        self.wz.sums(self, dom, terms, sums)

    def identity(self, dom, terms):
        """Step 4: the terms, each given by its formula on `dom`, sum to 0. Terms are grouped
        into classes of rational multiples of one another; each class must cancel (with one
        class this is also necessary; with several, a class that does not cancel leaves the
        goal undecided)."""
        classes = []  # [(reference signature, first c, accumulated sum of c·ratio)]
        for t in terms:
            sig = _signature(t)
            for cl in classes:
                r = ratio(sig, cl[0])
                if r is not None:
                    cl[2].append(t.c * r)
                    break
            else:
                classes.append((sig, t.c, [t.c]))
        for sig, c0, parts in classes:
            rest = sympy.cancel(sympy.together(sympy.Add(*parts) / c0))
            if rest != 0:
                msg = f"where {dom.show()} the terms do not cancel: their sum is {c0}·H·({rest})"
                raise (Refuted if len(classes) == 1 else Undecided)(msg)


def _tighten(dom, s):
    """`s` with its range cut to where every term of its body may be nonzero: a condition
    `var ≥ a` (or `var ≤ b`) that every term has, with `a ≥ lo` (`b ≤ hi`) on `dom`."""
    if not s.body or not all(isinstance(t, Term) and not t.lazy for t in s.body):
        return s
    # a term that may divide by zero at a dropped value is kept whole (the evaluator divides)
    if any(t.musts or t.nonzeros or sympy.fraction(sympy.together(t.c))[1].has(s.var) for t in s.body):
        return s
    lo, hi = s.lo, s.hi
    for sign in (1, -1):
        common = None
        for t in s.body:
            bounds = set()
            for L in t.conds:
                if sympy.expand(L).coeff(s.var) == sign:
                    bounds.add(sympy.expand(s.var - sign * L))
            common = bounds if common is None else common & bounds
        for b in sorted(common or (), key=str):
            if sign == 1 and dom.implies(b - lo):
                lo = b
            elif sign == -1 and dom.implies(hi - b):
                hi = b
    return Sum(s.var, lo, hi, s.body, s.name)


def _window(t, var):
    """The values `a, a + 1, …, b` of `var` where `t`'s conditions `var ≥ a`, `var ≤ b` may
    hold, when `b − a` is a constant `0..=MAX_EXPAND`; else None."""
    lows, ups = [], []
    for L in t.conds:
        L = sympy.expand(L)
        a = L.coeff(var)
        if a == 1:
            lows.append(sympy.expand(var - L))
        elif a == -1:
            ups.append(sympy.expand(L + var))
    for lo in lows:
        for hi in ups:
            width = sympy.expand(hi - lo)
            if width.is_Integer and 0 <= width <= MAX_EXPAND:
                return [sympy.expand(lo + m) for m in range(int(width) + 1)]
    return None


def _collapse_nested(x, s):
    """`Σ_v Σ_{w=a(v)}^{b(v)} [v = val]·T(v, w)` over `s` (v its variable): the inner sum `x` at
    `v = val`, its terms given the conditions `lo ≤ val ≤ hi` of `s`, when every term of its
    body has the same indicator on `v` (`val` free of `w`); else None."""
    if not isinstance(x, Sum) or not x.body or not all(isinstance(t, Term) for t in x.body):
        return None
    vals = set()
    for t in x.body:
        # as for a term: one that may divide by zero at another value of v is kept whole
        if t.musts or t.nonzeros or sympy.fraction(sympy.together(t.c))[1].has(s.var):
            return None
        hit = _collapse(t, s.var)
        if hit is None or hit.has(x.var):
            return None
        vals.add(sympy.expand(hit))
    if len(vals) != 1:
        return None
    val = vals.pop()
    moved = x.subs({s.var: val})
    body = [t.with_(conds=t.conds + (val - s.lo, s.hi - val)) for t in moved.body]
    return Sum(moved.var, moved.lo, moved.hi, body, moved.name)


def _collapse(t, var):
    """The value `var` takes by an indicator `[var + c = k]` of `t`, or None."""
    for L in t.eqs:
        a = sympy.expand(L).coeff(var)
        if a in (1, -1) and not (sympy.expand(L - a * var).has(var)):
            return sympy.expand(var - L / a)
    return None


def _signature(t):
    """(factorials {arg: multiplicity}, powers {base: exponent}) of a term's formula."""
    facts = {}
    for a, b, s in t.binoms:
        for x, m in ((a, s), (b, -s), (sympy.expand(a - b), -s)):
            facts[x] = facts.get(x, 0) + m
    pows = {}
    for base, e in t.pows:
        q, factors = sympy.factor_list(base)
        for p, m in factors:
            pows[p] = sympy.expand(pows.get(p, 0) + m * e)
        q = sympy.Rational(q)
        if q != 1:
            if q < 0:
                pows[sympy.Integer(-1)] = sympy.expand(pows.get(sympy.Integer(-1), 0) + e)
                q = -q
            if q != 1:
                pows[q] = sympy.expand(pows.get(q, 0) + e)
    minus = sympy.Integer(-1)
    if minus in pows:
        # (−1)^e depends only on e mod 2 (e affine in the integer symbols, integer
        # coefficients): (1 − t0)^n (1 − t)^n and ((1 − t0)(1 − t))^n are one class
        parts = sympy.expand(pows[minus]).as_coefficients_dict()
        pows[minus] = sympy.Add(*[x * (int(a) % 2) for x, a in parts.items()])
    return facts, pows


def ratio(sig, ref):
    """The formula of `sig` divided by that of `ref` as a rational function, or None when it is
    not one (factorial arguments or exponents of one base that differ by a non-constant)."""
    facts = dict(sig[0])
    for x, m in ref[0].items():
        facts[x] = facts.get(x, 0) - m
    groups = {}
    for x, m in facts.items():
        if m == 0:
            continue
        const = x.as_coeff_Add()[0] if x.is_Add else (x if x.is_Integer else sympy.Integer(0))
        groups.setdefault(sympy.expand(x - const), []).append((int(const), m))
    out = sympy.Integer(1)
    for lin, members in groups.items():
        if lin == 0:  # constant arguments (≥ 0 on the domain): their factorials
            for c, m in members:
                out *= sympy.factorial(c) ** m
            continue
        if sum(m for _, m in members) != 0:
            return None
        lo = min(c for c, _ in members)
        for c, m in members:
            prod = sympy.Integer(1)
            for j in range(lo + 1, c + 1):
                prod *= lin + j
            out *= prod**m
    pows = dict(sig[1])
    for b, e in ref[1].items():
        pows[b] = sympy.expand(pows.get(b, 0) - e)
    for b, e in pows.items():
        if e == 0:
            continue
        if not e.is_Integer:
            return None
        out *= b**int(e)
    return out
