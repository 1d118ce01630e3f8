"""Certificates of for-every proofs with `pieces` data (methods `pieces` and `wz`), written
from the section "Methods `pieces` and `wz`: goals for every integer value" of
docs/certificates.md.

Such a goal says `lhs = rhs` for every integer point of its `for_all` ranges (each open range
unbounded) and every real value of its real symbols, for every values of its symbolic control
polygon or net. This checker first checks the goal well formed (every integer symbol has one
range, the equalities form a chain, the names are the goal's) and evaluates it exactly
(`Fraction`) at every integer point of the first `OPEN_VALUES` values of each open range (closed
ranges in full), at `REAL_POINTS` values of each real symbol and generic rational control
points: a goal false there is refused. Then, with SymPy, it proves the goal for every value by
its own argument (`cert_pieces`, `cert_wz`): re-checked when every obligation holds, refused
when a necessary one fails (named), otherwise "not re-checked" with the reason. Without SymPy
the file is "not re-checked (needs SymPy)".
"""

import itertools
from fractions import Fraction

from .cert_eval import Unsupported, evaluate
from .cert_expr import free_names, parse

__all__ = ["check_pieces", "OPEN_VALUES", "REAL_POINTS"]

#: The values of each open range evaluated: its least value and the next ones.
OPEN_VALUES = 4
#: Rational values of each real symbol (distinct, away from 0 and 1 where Bernstein
#: conventions are special).
REAL_POINTS = (Fraction(1, 3), Fraction(5, 7))
#: Most integer points evaluated per file.
MAX_CASES = 2_000


class PiecesRefused(Exception):
    """An obligation of a `pieces` certificate that fails (the message names it)."""


def _need(cond, msg):
    if not cond:
        raise PiecesRefused(msg)


def _int_value(text, env, where):
    _need(isinstance(text, str), f"{where}: not a string")
    v = evaluate(parse(text, strict=True), env)
    _need(isinstance(v, Fraction) and v.denominator == 1, f"{where}: {text!r} is not an integer here")
    return int(v)


def _read(doc, parse_sides=True):
    goal = doc.get("goal")
    _need(isinstance(goal, dict) and goal.get("relation") == "=", "goal: missing, or its relation is not '='")
    syms = goal.get("symbols")
    _need(isinstance(syms, list) and all(isinstance(s, dict) for s in syms), "goal.symbols: not a list")
    reals = [s.get("name") for s in syms if s.get("sort") == "real"]
    ints = [s.get("name") for s in syms if s.get("sort") == "integer"]
    _need(len(reals) + len(ints) == len(syms), "goal.symbols: a sort that is not real or integer")
    _need(len(set(reals + ints)) == len(syms), "goal.symbols: a name declared twice")
    ranges = goal.get("for_all")
    _need(isinstance(ranges, list), "goal.for_all: not a list")
    _need([r.get("name") for r in ranges] == ints, "goal.for_all: not one range per integer symbol, in order")
    _need(any(r.get("to") is None for r in ranges), "goal.for_all: no open range (to: null)")
    eqs = goal.get("equalities")
    _need(isinstance(eqs, list) and eqs, "goal.equalities: none")
    for i in range(1, len(eqs)):
        _need(eqs[i].get("lhs") == eqs[i - 1].get("rhs"), f"goal.equalities[{i}]: not a chain")
    polygon, net = goal.get("polygon"), goal.get("net")
    _need(polygon is None or net is None, "goal: both a polygon and a net")
    known = [o["name"] for o in (polygon, net) if isinstance(o, dict) and isinstance(o.get("name"), str)]
    names = set(reals) | set(ints)
    sides = []
    for i, eq in enumerate(eqs if parse_sides else ()):
        pair = []
        for key in ("lhs", "rhs"):
            e = parse(eq.get(key), known, strict=True)
            extra = free_names(e) - names
            _need(not extra, f"goal.equalities[{i}].{key}: names {sorted(extra)} are not symbols of the goal")
            pair.append(e)
        sides.append(pair)
    data = doc.get("pieces")
    _need(isinstance(data, dict) and isinstance(data.get("certificates"), list), "pieces.certificates: not a list")
    return reals, ranges, sides, polygon, net


def _cases(ranges, skip_empty=False):
    """Every integer point of the ranges, open ones cut after `OPEN_VALUES` values.
    `skip_empty`: a range empty at a value evaluated has no point there (a goal this checker
    derived, the step of an induction at its last value), instead of being refused."""

    def walk(k, env):
        if k == len(ranges):
            yield dict(env)
            return
        r = ranges[k]
        lo = _int_value(r.get("from"), env, f"goal.for_all[{k}].from")
        hi = lo + OPEN_VALUES - 1 if r.get("to") is None else _int_value(r.get("to"), env, f"goal.for_all[{k}].to")
        # docs/certificates.md: a range empty at a value evaluated is refused (a claim over
        # an empty range says nothing), as the program refuses it
        if hi < lo and skip_empty:
            return
        _need(hi >= lo, f"goal.for_all[{k}]: the range {r['name']} = {lo}..={hi} is empty at {_show(env) or 'the start'}")
        for v in range(lo, hi + 1):
            env[r["name"]] = Fraction(v)
            yield from walk(k + 1, env)
        env.pop(r["name"], None)

    return walk(0, {})


def _control_points(polygon, net, env):
    """Generic rational control points at this integer point: `b[i] = 1/(i + 2) + i²/3`, a
    net's `b[i, j] = 1/(i + 2j + 3) + ij/5` (distinct, not affine in the index)."""
    if polygon is not None:
        n = _int_value(polygon.get("degree"), env, "goal.polygon.degree")
        _need(n >= 0, f"goal.polygon.degree: {n} at {_show(env)}")
        return {polygon["name"]: [Fraction(1, i + 2) + Fraction(i * i, 3) for i in range(n + 1)]}
    if net is not None:
        d = net.get("degree")
        _need(isinstance(d, list) and len(d) == 2, "goal.net.degree: not two expressions")
        m, n = (_int_value(x, env, "goal.net.degree") for x in d)
        _need(m >= 0 and n >= 0, f"goal.net.degree: ({m}, {n}) at {_show(env)}")
        pts = {(i, j): Fraction(1, i + 2 * j + 3) + Fraction(i * j, 5) for i in range(m + 1) for j in range(n + 1)}
        return {net["name"]: pts}
    return {}


def _show(env):
    return ", ".join(f"{k} = {v}" for k, v in env.items())


def check_ranges(doc):
    """The goal's ranges and polygon at the values `check_pieces` evaluates: raises
    `PiecesRefused` for a range empty there or a polygon (net) of negative degree."""
    _, ranges, _, polygon, net = _read(doc, parse_sides=False)
    for ints in _cases(ranges):
        _control_points(polygon, net, ints)


def check_pieces(doc, skip_empty=False):
    """A `pieces` certificate checked: returns `(proved, detail)` (`proved` only when the whole
    argument of `cert_pieces` went through), or raises `PiecesRefused` naming the first point
    where the sides differ or the first obligation that fails. `skip_empty`: see `_cases`."""
    reals, ranges, sides, polygon, net = _read(doc)
    count = 0
    for ints in _cases(ranges, skip_empty):
        objects = _control_points(polygon, net, ints)
        for values in itertools.product(REAL_POINTS, repeat=len(reals)):
            env = dict(ints)
            env.update(zip(reals, values))
            count += 1
            _need(count <= MAX_CASES, f"more than {MAX_CASES} evaluations")
            for i, (lhs, rhs) in enumerate(sides):
                lv, rv = evaluate(lhs, env, objects), evaluate(rhs, env, objects)
                _need(lv == rv, f"goal.equalities[{i}]: at {_show(env)} the sides are {lv} and {rv}")
    evaluated = f"the goal holds at its first values ({count} evaluations, the first {OPEN_VALUES} values of each open range)"
    try:
        import sympy  # noqa: F401
    except ImportError:
        return False, f"for-every proof: not re-checked (needs SymPy); {evaluated}"
    from .cert_pieces import Refuted, Undecided
    from .cert_wz import prove_goal

    try:
        return True, prove_goal(doc)
    except Refuted as e:
        raise PiecesRefused(str(e)) from None
    except (Undecided, Unsupported) as e:
        return False, f"for-every proof not completed here: {e}; {evaluated}"
    except Exception as e:  # noqa: BLE001 — SymPy failing on a term: the proof is not done, never a verdict
        return False, f"for-every proof not completed here: {type(e).__name__}: {e}; {evaluated}"
