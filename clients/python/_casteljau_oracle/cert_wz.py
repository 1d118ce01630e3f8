"""Sums of symbolic length in the proof of `cert_pieces` (step 5), with the WZ certificates
`R` of the file (`pieces.certificates`).

- Sums of one length `L` (after shifting each to start at 0, and peeling the last terms off a
  sum longer by a constant) are compared term by term: `Σ_{w=0}^{L} (Σ bodies)(w) = 0` follows
  from the bodies' sum being 0 at every `0 ≤ w ≤ L` (a goal with one more integer symbol), and
  the closed terms must then sum to 0. This is sufficient, not necessary: if it fails, the WZ
  argument below is tried.
- A sum `S(n) = Σ_{k=lo}^{hi(n)} F(n, k)` against closed terms `r(n)` (`S = r`), or a sum
  nested in another one (then `r(n) = S(n₀)`, its value at the base), is proved by induction
  on a symbol `n` with `hi(n + 1) = hi(n) + 1`, `lo` free of `n`, every inequality of the
  domain increasing in `n` and one least value `n₀`. With `ρ = r(n + 1)/r(n)` (a rational
  function; 1 when `r` is free of `n`) and `G(n, k) = ρ·R(n, k)·F(n, k)`:
  (W) `F(n+1, k) − ρF(n, k) = G(n, k+1) − G(n, k)` for `lo ≤ k ≤ hi(n) − 1`;
  (S) `F(n+1, hi) + F(n+1, hi+1) − ρF(n, hi) + G(n, hi) − G(n, lo) = r(n+1) − ρ r(n)`
      (so `S(n+1) − r(n+1) = ρ·(S(n) − r(n))`, summing (W) over `lo ≤ k < hi`; needs
      `hi ≥ lo`);
  (B) `S(n₀) = r(n₀)`.
  Each is a goal proved by `Prover.prove` (pieces, boundary lines included). With `ρ`'s
  integer divisors nonzero on the domain, `S = r` follows for every `n ≥ n₀` at every real
  point off the zeros of `ρ`'s real divisors, hence everywhere (both sides are rational
  functions of the reals).
"""

import sympy

from .cert_eval import Unsupported
from .cert_pieces import Refuted, Undecided, _signature, ratio
from .cert_terms import Converter, Sum, Term, fresh

__all__ = ["Wz"]

#: Most terms peeled off a longer sum.
MAX_PEEL = 8


class Wz:
    def __init__(self, certs, ints, reals):
        self.certs = certs  # [(text, tree)]
        self.ints, self.reals = ints, reals
        self.used = []
        # the unit polygon's (net's) symbolic indices of the case being proved: a file's `R`
        # names them `__j` (`__k`), as the program's translation does (proofs/README.md)
        self.unit = None

    def sums(self, pv, dom, terms, sums):
        if any(isinstance(y, Sum) for s in sums for y in s.body):
            reduced = []
            for s in sums:
                reduced.extend(self._reduce(pv, dom, s))
            pv.prove(dom, terms + reduced)
            return
        try:
            self._termwise(pv, dom, terms, sums)
            return
        except (Refuted, Undecided) as e:
            why = f"term by term: {e}"
        try:
            self._against(pv, dom, terms, sums)
        except Undecided as e:
            raise Undecided(f"{e}; {why}") from None

    # --- sums of one length ----------------------------------------------------------

    def _termwise(self, pv, dom, terms, sums):
        groups = {}
        for s in sums:
            groups.setdefault(sympy.expand(s.hi - s.lo), []).append(s)
        lengths = sorted(groups, key=lambda L: (len(L.free_symbols), str(L)))
        closed = list(terms)
        merged = {}
        for L in lengths:
            base = next((M for M in merged if (L - M).is_Integer and 0 < L - M <= MAX_PEEL), None)
            if base is not None and dom.implies(base + 1):
                for s in groups[L]:
                    for j in range(1, int(L - base) + 1):
                        closed.extend(x.subs({s.var: s.lo + base + j}) for x in s.body)
                merged[base].extend(groups[L])
            else:
                merged[L] = list(groups[L])
        for L, group in merged.items():
            w = fresh("%w")
            body = [x.subs({s.var: s.lo + w}) for s in group for x in s.body]
            pv.prove(dom.with_(w, L - w, add_syms=[w]), body)
        pv.prove(dom, closed)

    # --- the WZ argument -------------------------------------------------------------

    def _cert(self, text, tree, dom, s):
        conv = Converter(self.ints, self.reals)
        conv.env[s.name] = s.var
        for name, u in zip(("__j", "__k"), self.unit or ()):
            conv.env[name] = u
        try:
            r = conv.pure(tree, "a WZ certificate")
        except Unsupported as e:
            raise Undecided(f"the WZ certificate {text}: {e}") from None
        return r.xreplace(dom.sub)

    def _inductions(self, dom, s):
        """Candidates (n, n₀, step domain) for the induction of sum `s` on `dom`. An upper
        bound of `n` (an inequality decreasing in n, `n ≤ m`) keeps the values of `n` an
        interval from n₀: the step is proved where both n and n + 1 lie in `dom`."""
        out = []
        length = sympy.expand(s.hi - s.lo)
        for n in dom.syms:
            if length.coeff(n) != 1 or s.lo.has(n) or (length - n).has(n):
                continue
            lows, ups, ok = [], [], True
            for x in dom.ineqs:
                a = sympy.expand(x).coeff(n)
                if a > 0 and a != 1:
                    ok = False
                elif a == 1:
                    lows.append(sympy.expand(n - x))
                elif a < 0:
                    ups.append(sympy.expand(x.xreplace({n: n + 1})))
            if not ok or not lows:
                continue
            n0 = next((a for a in lows if all(dom.implies(a - b) for b in lows)), None)
            if n0 is not None:
                out.append((n, n0, dom.with_(*ups) if ups else dom))
        return out

    def _step(self, pv, dom, s, R, n, rho, r):
        """Obligations (W) and (S) for sum `s`, certificate `R`, against closed terms `r`."""
        k, F = s.var, s.body
        if not dom.implies(s.hi - s.lo):
            raise Undecided(f"a sum that may be empty ({s.hi} < {s.lo}) in the WZ step")
        up = {n: n + 1}
        g = rho * R
        w_items = [t.subs(up) for t in F] + [t.scaled(-rho) for t in F]
        w_items += [t.scaled(-g, lazy=True).subs({k: k + 1}) for t in F] + [t.scaled(g, lazy=True) for t in F]
        try:
            pv.prove(dom.with_(k - s.lo, s.hi - 1 - k, add_syms=[k]), w_items)
        except Refuted as e:
            raise Refuted(f"the WZ equation F(n+1, k) - F(n, k) = G(n, k+1) - G(n, k) with R = {R}, n = {n}: {e}") from None
        hi, lo = s.hi, s.lo
        s_items = [t.subs({n: n + 1, k: hi}) for t in F] + [t.subs({n: n + 1, k: hi + 1}) for t in F]
        s_items += [t.scaled(-rho).subs({k: hi}) for t in F]
        s_items += [t.scaled(g, lazy=True).subs({k: hi}) for t in F] + [t.scaled(-g, lazy=True).subs({k: lo}) for t in F]
        s_items += [t.scaled(-1).subs(up) for t in r] + [t.scaled(rho) for t in r]
        try:
            pv.prove(dom, s_items)
        except Refuted as e:
            raise Refuted(f"the telescoped ends of the WZ sum with R = {R}, n = {n}: {e}") from None

    def _rho(self, dom, r, n):
        if not any(_mentions(t, n) for t in r):
            return sympy.Integer(1)
        if len(r) != 1:
            raise Undecided("a sum against several closed terms")
        t = r[0]
        q = ratio(_signature(t.subs({n: n + 1})), _signature(t))
        if q is None:
            raise Undecided("the closed side's ratio r(n+1)/r(n) is not rational")
        rho = sympy.cancel(t.c.xreplace({n: n + 1}) / t.c * q)
        syms = set(dom.syms)
        _, den = sympy.fraction(sympy.together(rho))
        for f, _ in sympy.factor_list(den)[1]:
            if f.free_symbols & syms:
                if not f.free_symbols <= syms or dom.sign(f) not in (1, -1):
                    raise Undecided(f"r(n+1)/r(n) = {rho} may divide by zero")
        return rho

    def _try(self, pv, dom, s, body_fn, r=None):
        """Each certificate of the file, then one proposed by Gosper's algorithm, for each
        induction symbol in turn; the first whose obligations hold. `body_fn(R, n, n0, step)`,
        `step` the domain of the step (n and n + 1 in `dom`)."""
        first = None
        for n, n0, step in self._inductions(dom, s):
            def cands():
                # the file's certificates when it gives any (a wrong one is refused, not
                # replaced); a file without proposes its own by Gosper's algorithm
                for text, tree in self.certs:
                    yield text, lambda: self._cert(text, tree, dom, s)
                if not self.certs:
                    yield "found by Gosper's algorithm", lambda: self._gosper(dom, s, n, r)

            for text, make in cands():
                try:
                    R = make()
                    if R is None:
                        continue
                    out = body_fn(R, n, n0, step)
                    if not self.certs:
                        text = f"R = {R.xreplace({s.var: sympy.Symbol(s.name)})}, {text}"
                    self.used.append(text)
                    return out
                except (Refuted, Undecided) as e:
                    if first is None or (isinstance(e, Refuted) and not isinstance(first, Refuted)):
                        first = e
        if first is None:
            raise Undecided(f"no induction symbol or certificate for the sum over {s.name} ({s.lo}..{s.hi})")
        raise first

    def _gosper(self, dom, s, n, r):
        """A certificate `R` proposed for sum `s` by Gosper's algorithm on
        `h(k) = F(n+1, k) − ρ F(n, k)` (a search: what it proposes is checked by (W), (S), (B)),
        or None."""
        if len(s.body) != 1 or not isinstance(s.body[0], Term):
            return None
        try:
            rho = self._rho(dom, r or [], n)
            t, k = s.body[0], s.var
            up = ratio(_signature(t.subs({n: n + 1})), _signature(t))
            step = ratio(_signature(t.subs({k: k + 1})), _signature(t))
            if up is None or step is None:
                return None
            q = sympy.cancel(t.c.xreplace({n: n + 1}) / t.c * up - rho)
            if q == 0:
                return None
            hk = sympy.cancel(q.xreplace({k: k + 1}) / q * t.c.xreplace({k: k + 1}) / t.c * step)
            g = _gosper_term(hk, k)
            if g is None:
                return None
            return sympy.cancel(g * q / rho)
        except (Undecided, ValueError, ZeroDivisionError, sympy.PolynomialError):
            return None

    def _against(self, pv, dom, terms, sums):
        s0 = sums[0]
        body = []
        for s in sums:
            if sympy.expand(s.lo - s0.lo) != 0 or sympy.expand(s.hi - s0.hi) != 0:
                raise Undecided("sums of different ranges against closed terms")
            body.extend(x.subs({s.var: s0.var}) for x in s.body)
        s = Sum(s0.var, s0.lo, s0.hi, body, s0.name)
        r = [t.scaled(-1) for t in terms]

        def attempt(R, n, n0, step):
            rho = self._rho(dom, r, n)
            self._step(pv, step, s, R, n, rho, r)
            base = dom.substitute(n, n0)
            pv.prove(base, [x.subs({n: n0}) for x in [s] + terms])

        self._try(pv, dom, s, attempt, r)

    def _reduce(self, pv, dom, s):
        """`s` with each innermost sum of its body replaced by its value at the base."""
        inner = dom.with_(s.var - s.lo, s.hi - s.var, add_syms=[s.var])
        body = []
        for x in s.body:
            if isinstance(x, Sum) and any(isinstance(y, Sum) for y in x.body):
                body.extend(self._reduce(pv, inner, x))
            elif isinstance(x, Sum):
                body.extend(self._constant(pv, inner, x))
            else:
                body.append(x)
        return [Sum(s.var, s.lo, s.hi, body, s.name)]

    def _constant(self, pv, dom, s):
        def attempt(R, n, n0, step):
            at = s.subs({n: n0})
            length = sympy.expand(at.hi - at.lo)
            if not length.is_Integer or length > 64:
                raise Undecided(f"the sum over {s.name} at its base has symbolic length")
            r = [x.subs({at.var: at.lo + j}) for j in range(int(length) + 1) for x in at.body]
            self._step(pv, step, s, R, n, sympy.Integer(1), [])
            return r

        return self._try(pv, dom, s, attempt)


def _mentions(t, n):
    fields = [t.c, *t.conds, *t.eqs, *t.musts] + [x for a, b, _ in t.binoms for x in (a, b)]
    fields += [x for b, e in t.pows for x in (b, e)]
    return any(sympy.sympify(x).has(n) for x in fields)


def prove_goal(doc):
    """The whole proof of a for-every goal (see the module documentation of `cert_pieces`):
    returns what was proved, or raises `Refuted` / `Undecided` / `Unsupported`."""
    from .cert_domain import Domain
    from .cert_expr import parse
    from .cert_pieces import Prover

    goal = doc["goal"]
    ints = {s["name"]: sympy.Symbol(s["name"]) for s in goal["symbols"] if s["sort"] == "integer"}
    reals = {s["name"]: sympy.Symbol(s["name"]) for s in goal["symbols"] if s["sort"] == "real"}
    polygon, net = goal.get("polygon"), goal.get("net")
    obj = polygon or net
    known = [obj["name"]] if obj else []
    base = Converter(ints, reals)
    ineqs = []
    for r in goal["for_all"]:
        v = ints[r["name"]]
        ineqs.append(v - base.affine(parse(r["from"], strict=True)))
        if r.get("to") is not None:
            ineqs.append(base.affine(parse(r["to"], strict=True)) - v)
    dom = Domain(list(ints.values()), ineqs)
    certs = [(c, parse(c, strict=True)) for c in doc["pieces"]["certificates"]]
    wz = Wz(certs, ints, reals)
    pv = Prover(reals.values(), wz)
    cases = [(None, dom)]
    if obj:
        degs = [obj["degree"]] if polygon else list(obj["degree"])
        unit = tuple(fresh("%u") for _ in degs)
        bounds = []
        for k, d in zip(unit, degs):
            deg = base.affine(parse(d, strict=True))
            if not dom.implies(deg):
                raise Undecided(f"goal.{'polygon' if polygon else 'net'}.degree {d} may be negative")
            bounds += [k, deg - k]
        cases = [(unit, dom.with_(*bounds, add_syms=unit)), (None, dom)]
    for i, eq in enumerate(goal["equalities"]):
        lhs, rhs = parse(eq["lhs"], known, strict=True), parse(eq["rhs"], known, strict=True)
        pairs = [(lhs, rhs)]
        if lhs[0] == "tuple" or rhs[0] == "tuple":
            if not (lhs[0] == rhs[0] == "tuple" and len(lhs[1]) == len(rhs[1])):
                raise Unsupported(f"goal.equalities[{i}]: sides of different shapes")
            pairs = list(zip(lhs[1], rhs[1]))
        for unit, d in cases:
            wz.unit = unit
            conv = Converter(ints, reals, obj["name"] if obj else None, unit)
            for j, (a, b) in enumerate(pairs):
                items = conv.items(a) + [Converter._neg(x) for x in conv.items(b)]
                where = f"goal.equalities[{i}]" + (f" entry {j}" if len(pairs) > 1 else "")
                where += "" if not obj else " (unit polygon)" if unit else " (zero polygon)"
                try:
                    pv.prove(d, items)
                except Refuted as e:
                    raise Refuted(f"{where}: {e}") from None
                except Undecided as e:
                    raise Undecided(f"{where}: {e}") from None
    what = f"proved for every value: {pv.pieces} pieces"
    if wz.used:
        what += f", {len(wz.used)} WZ inductions ({', '.join(sorted(set(wz.used)))})"
    return what


def _gosper_term(ratio_k, k):
    """Gosper's algorithm (as SymPy's `gosper_term`, from the term ratio `h(k+1)/h(k)`): a
    rational `y(k)` with `y(k+1)h(k+1) − y(k)h(k) = h(k)`, or None."""
    from sympy.concrete.gosper import gosper_normal

    p, q = sympy.fraction(sympy.cancel(ratio_k))
    A, B, C = gosper_normal(p, q, k)
    B = B.shift(-1)
    N, M, K = sympy.S(A.degree()), sympy.S(B.degree()), sympy.S(C.degree())
    if N != M or A.LC() != B.LC():
        D = {K - max(N, M)}
    elif not N:
        D = {K - N + 1, sympy.S.Zero}
    else:
        D = {K - N + 1, (B.nth(N - 1) - A.nth(N - 1)) / A.LC()}
    D = [d for d in D if d.is_Integer and d >= 0]
    if not D:
        return None
    d = max(D)
    if d > 8:
        return None
    coeffs = sympy.symbols(f"c:{d + 1}", cls=sympy.Dummy)
    x = sympy.Poly(coeffs, k, domain=A.get_domain().inject(*coeffs))
    H = A * x.shift(1) - B * x - C
    sol = sympy.solve(H.coeffs(), coeffs, dict=True)
    if not sol:
        return None
    xe = x.as_expr().subs(sol[0])
    xe = xe.subs({c: 0 for c in coeffs})
    if xe == 0:
        return None
    return B.as_expr() * xe / C.as_expr()
