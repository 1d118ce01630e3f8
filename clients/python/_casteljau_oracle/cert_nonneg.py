"""Certificates of inequalities for every value (`"relation": ">="` or `"<="`, `pieces` data
with `nonnegative`), written from the section "Inequalities for every value" of
docs/certificates.md.

The goal says `lhs ≥ rhs` at every integer point of its `for_all` ranges and every value of its
one real symbol in the closed `interval`. This checker evaluates `lhs − rhs` exactly at the
first `OPEN_VALUES` values of each open range (closed ranges in full) and at nine points of the
interval: a negative value refuses the file. Then, with SymPy, it proves the goal by its own
argument from the listed obligations: one piece whose region is the domain (its conditions are
the ranges' `v − from ≥ 0` and `to − v ≥ 0`, compared as expanded expressions); on it, `lhs − rhs` minus the sum of the listed terms
(each its coefficient × its factorials × its powers) is 0 as an identity (`gammasimp`); each
factor is ≥ 0 on the interval for the reason listed, its Bernstein coefficients computed here
from the factor's polynomial and compared with the listed ones; each factorial's argument and
each `exponent_nonneg` exponent is ≥ 0 on the region. A proof with several pieces, or a
`positive_monomials` coefficient, is "not re-checked" (**not done** here; none of the texts
has one).
"""

from fractions import Fraction
from math import comb

from .cert_eval import evaluate
from .cert_expr import parse
from .cert_hyper import OPEN_VALUES

__all__ = ["check_nonneg", "NonnegRefused", "goal_of"]

#: Points of the interval evaluated: a + k (b − a) / 8.
INTERVAL_POINTS = 9
#: Most integer points evaluated per file.
MAX_CASES = 2_000


class NonnegRefused(Exception):
    """An obligation of an inequality certificate that fails (the message names it)."""


def _need(cond, msg):
    if not cond:
        raise NonnegRefused(msg)


def _rational(s, where):
    _need(isinstance(s, str), f"{where}: not a string")
    try:
        v = Fraction(s)
    except (ValueError, ZeroDivisionError):
        raise NonnegRefused(f"{where}: {s!r} is not an exact rational")
    _need(str(v) == s, f"{where}: {s!r} is not written in lowest terms")
    return v


def goal_of(goal, where="goal"):
    """The goal read: `(real, ints, ranges, (a, b), lhs, rhs)`, `lhs ≥ rhs` (a `<=` goal's
    sides swapped); ranges are `(name, from, to or None)` texts."""
    _need(isinstance(goal, dict) and goal.get("relation") in (">=", "<="), f"{where}.relation: not >= or <=")
    syms = goal.get("symbols")
    _need(isinstance(syms, list) and all(isinstance(s, dict) for s in syms), f"{where}.symbols: not a list")
    reals = [s.get("name") for s in syms if s.get("sort") == "real"]
    ints = [s.get("name") for s in syms if s.get("sort") == "integer"]
    _need(len(reals) + len(ints) == len(syms), f"{where}.symbols: a sort that is not real or integer")
    _need(len(set(reals + ints)) == len(syms), f"{where}.symbols: a name declared twice")
    iv = goal.get("interval")
    _need(isinstance(iv, dict) and reals == [iv.get("name")], f"{where}.interval: not the one real symbol's")
    a, b = _rational(iv.get("from"), f"{where}.interval.from"), _rational(iv.get("to"), f"{where}.interval.to")
    _need(a < b, f"{where}.interval: [{a}, {b}] is empty or a point")
    ranges = goal.get("for_all")
    _need(isinstance(ranges, list) and len(ranges) == len(ints), f"{where}.for_all: one range per integer symbol")
    rs = []
    for k, r in enumerate(ranges):
        _need(isinstance(r, dict) and r.get("name") == ints[k], f"{where}.for_all[{k}]: not the integer symbol {k}")
        _need(isinstance(r.get("from"), str) and (r.get("to") is None or isinstance(r.get("to"), str)),
              f"{where}.for_all[{k}]: bounds are strings (to: null when open)")
        rs.append((r["name"], r["from"], r.get("to")))
    _need(any(to is None for _, _, to in rs), f"{where}.for_all: no open range")
    sides = goal.get("inequality")
    _need(isinstance(sides, dict) and isinstance(sides.get("lhs"), str) and isinstance(sides.get("rhs"), str),
          f"{where}.inequality: lhs and rhs strings")
    lhs, rhs = sides["lhs"], sides["rhs"]
    if goal["relation"] == "<=":
        lhs, rhs = rhs, lhs
    return reals[0], ints, rs, (a, b), lhs, rhs


def _int_value(text, env, where):
    v = evaluate(parse(text, strict=True), env)
    _need(isinstance(v, Fraction) and v.denominator == 1, f"{where}: {text!r} is not an integer here")
    return int(v)


def _cases(ranges):
    """The integer points of the first `OPEN_VALUES` values of each open range."""
    out = []

    def walk(k, env):
        if len(out) > MAX_CASES:
            return
        if k == len(ranges):
            out.append(dict(env))
            return
        name, lo, hi = ranges[k]
        lo = _int_value(lo, env, f"for_all[{k}].from")
        hi = lo + OPEN_VALUES - 1 if hi is None else _int_value(hi, env, f"for_all[{k}].to")
        for v in range(lo, hi + 1):
            env[name] = Fraction(v)
            walk(k + 1, env)
        env.pop(name, None)

    walk(0, {})
    _need(len(out) <= MAX_CASES, f"more than {MAX_CASES} integer points among the first values")
    return out


def _evaluate_first(real, ranges, ab, diff):
    a, b = ab
    ts = [a + (b - a) * Fraction(k, INTERVAL_POINTS - 1) for k in range(INTERVAL_POINTS)]
    cases = _cases(ranges)
    for env in cases:
        for t in ts:
            v = evaluate(diff, {**env, real: t})
            _need(isinstance(v, Fraction), "the goal's sides are not scalars")
            if v < 0:
                at = ", ".join(f"{k} = {x}" for k, x in env.items())
                raise NonnegRefused(f"the goal fails at {at}, {real} = {t}: lhs − rhs = {v} < 0")
    return len(cases) * len(ts)


def bernstein_coefficients(power, a, b):
    """The coefficients in the Bernstein basis of degree `len(power) − 1` on `[a, b]` of the
    polynomial with these power coefficients (lowest first)."""
    d = len(power) - 1
    # p(a + (b − a) s) in powers of s.
    local = [Fraction(0)] * (d + 1)
    h = b - a
    for k, c in enumerate(power):
        for j in range(k + 1):
            local[j] += c * comb(k, j) * a ** (k - j) * h ** j
    return [sum(local[k] * Fraction(comb(j, k), comb(d, k)) for k in range(j + 1)) for j in range(d + 1)]


def check_nonneg(doc):
    """Checks an inequality certificate: `(True, detail)` when proved here, `(False, reason)`
    when not re-checked; raises `NonnegRefused`."""
    real, ints, ranges, ab, lhs_text, rhs_text = goal_of(doc.get("goal"))
    _need(doc.get("verdict") == "proved", "verdict: an inequality for every value is proved")
    names = [real] + ints
    for text in (lhs_text, rhs_text):
        parse(text, names, strict=True)
    diff = parse(f"({lhs_text}) - ({rhs_text})", names, strict=True)
    points = _evaluate_first(real, ranges, ab, diff)
    data = doc.get("pieces")
    _need(isinstance(data, dict) and data.get("certificates") == [], "pieces.certificates: not an empty list")
    pieces = data.get("nonnegative")
    _need(isinstance(pieces, list) and pieces, "pieces.nonnegative: not a nonempty list")
    try:
        import sympy  # noqa: F401
    except ImportError:
        return False, f"evaluated at {points} points; the proof for every value needs SymPy"
    if len(pieces) != 1:
        return False, f"evaluated at {points} points; {len(pieces)} pieces: their cover of the domain is not checked here (not done)"
    return _prove(real, ints, ranges, ab, diff, pieces[0], points)


def _prove(real, ints, ranges, ab, diff, piece, points):
    import sympy

    from .cert_domain import Domain
    from .cert_sympy import to_sympy

    syms = {n: sympy.Symbol(n, integer=True) for n in ints}
    t = sympy.Symbol(real)
    local = {**syms, real: t}

    def sym(text, where):
        _need(isinstance(text, str), f"{where}: not a string")
        try:
            return sympy.sympify(text.replace("^", "**"), locals=local)
        except (sympy.SympifyError, SyntaxError, TypeError) as e:
            raise NonnegRefused(f"{where}: {text!r} is not an expression ({e})")

    domain_ineqs = []
    for name, lo, hi in ranges:
        domain_ineqs.append(syms[name] - sym(lo, f"for_all {name}.from"))
        if hi is not None:
            domain_ineqs.append(sym(hi, f"for_all {name}.to") - syms[name])
    domain = Domain([syms[n] for n in ints], domain_ineqs)
    _need(isinstance(piece, dict) and isinstance(piece.get("region"), str), "pieces.nonnegative[0].region: missing")
    region = []
    for part in piece["region"].split(", "):
        _need(part.endswith(" ≥ 0"), f"region: {part!r} is not 'e ≥ 0'")
        region.append(sym(part[: -len(" ≥ 0")], "region"))
    # The one piece is the domain itself: its conditions are the ranges', as the program
    # prints them (a piece that merely contains the domain is not what the program proved).
    same = {sympy.expand(x) for x in region} == {sympy.expand(x) for x in domain_ineqs}
    _need(same, f"region: {piece['region']} is not the domain of the ranges (one piece must be the domain)")
    for r in region:
        _need(domain.implies(r), f"region: {r} ≥ 0 does not hold on the whole domain")
    on_piece = Domain([syms[n] for n in ints], region)
    terms = piece.get("terms")
    _need(isinstance(terms, list), "pieces.nonnegative[0].terms: not a list")
    a, b = ab
    total = sympy.Integer(0)
    for k, term in enumerate(terms):
        at = f"term {k}"
        _need(isinstance(term, dict), f"{at}: not an object")
        value, why = _factor(term.get("coefficient"), None, f"{at}.coefficient", sym, t, ab, on_piece)
        if why is not None:
            return False, f"evaluated at {points} points; {at}: {why}"
        for j, f in enumerate(term.get("factorials") or []):
            _need(isinstance(f, str), f"{at}.factorials[{j}]: not a string")
            inverse = f.startswith("1/")
            body = f[2:] if inverse else f
            _need(body.startswith("(") and body.endswith(")!"), f"{at}.factorials[{j}]: not (a)! or 1/(a)!")
            arg = sym(body[1:-2], f"{at}.factorials[{j}]")
            _need(on_piece.implies(arg), f"{at}.factorials[{j}]: {arg} ≥ 0 is not shown on the region")
            value *= sympy.factorial(arg) ** (-1 if inverse else 1)
        powers = term.get("powers")
        _need(isinstance(powers, list), f"{at}.powers: not a list")
        for j, p in enumerate(powers):
            v, why = _factor(p, True, f"{at}.powers[{j}]", sym, t, ab, on_piece)
            if why is not None:
                return False, f"evaluated at {points} points; {at}: {why}"
            value *= v
        total += value
    goal = to_sympy(diff, ints={n: None for n in ints}, reals=[real])
    goal = goal.subs({sympy.Symbol(n, integer=True): syms[n] for n in ints}).subs(sympy.Symbol(real), t)
    rest = sympy.gammasimp(sympy.expand(goal - total))
    _need(sympy.simplify(rest) == 0, f"lhs − rhs is not the sum of the listed terms on the piece ({rest} remains)")
    return True, (
        f"evaluated at {points} points; one piece covering the domain, lhs − rhs = the sum of its "
        f"{len(terms)} listed terms, each a product of factors ≥ 0 on [{a}, {b}] (Bernstein coefficients computed here)"
    )


def _factor(f, is_power, at, sym, t, ab, on_piece):
    """One factor's value (SymPy) and `None`, or `(None, reason)` when its reason is not
    checked here; refuses a reason that does not hold."""
    import sympy

    _need(isinstance(f, dict) and isinstance(f.get("why"), str), f"{at}: not an object with a reason")
    base = sym(f.get("factor"), f"{at}.factor")
    why = f["why"]
    listed = f.get("bernstein")
    _need(isinstance(listed, list), f"{at}.bernstein: not a list")
    listed = [_rational(x, f"{at}.bernstein") for x in listed]
    _need(("exponent" in f) == bool(is_power), f"{at}: an exponent exactly for a power")
    exponent = sym(f.get("exponent"), f"{at}.exponent") if is_power else None
    value = base ** exponent if is_power else base
    if why == "positive_constant":
        _need(base.is_Rational and base > 0 and not listed, f"{at}: not a positive constant")
        return value, None
    if why in ("bernstein", "bernstein_positive", "exponent_nonneg"):
        _need(base.free_symbols <= {t}, f"{at}: {base} is not a polynomial in {t}")
        poly = sympy.Poly(base, t)
        power = [Fraction(int(c.p), int(c.q)) for c in reversed(poly.all_coeffs())]
        mine = bernstein_coefficients(power, *ab)
        _need(listed == mine, f"{at}.bernstein: {[str(x) for x in listed]}, computed here {[str(x) for x in mine]}")
        _need(all(c >= 0 for c in mine), f"{at}: a Bernstein coefficient is negative: not shown ≥ 0 on the interval")
        if why == "bernstein_positive":
            _need(mine[0] > 0 and mine[-1] > 0, f"{at}: an end coefficient is not > 0")
        elif why == "exponent_nonneg":
            _need(is_power and on_piece.implies(exponent), f"{at}: the exponent {exponent} ≥ 0 is not shown on the region")
        else:
            _need(not is_power, f"{at}: 'bernstein' is a coefficient's reason")
        return value, None
    if why == "affine_on_piece":
        _need(not listed and not is_power and on_piece.implies(base), f"{at}: {base} ≥ 0 is not shown on the region")
        return value, None
    return None, f"the reason {why!r} is not checked here (not done)"

