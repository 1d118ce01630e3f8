"""The client against the built binary ($CASTELJAU_BIN), as a user's CI would use it."""

import math
import random
from fractions import Fraction

import pytest

from casteljau_oracle import METHODS, Oracle, OracleError
from _reference import de_casteljau


def de_casteljau_lerp(points, t):
    """The same in the lerp form a + t·(b − a)."""
    column = [list(p) for p in points]
    for r in range(1, len(points)):
        for i in range(len(points) - r):
            column[i] = [a + t * (b - a) for a, b in zip(column[i], column[i + 1])]
    return column[0]


def sloppy(points, t):
    """A wrong evaluator: the convex form with 1 − t computed as 1 − t − 2^−40."""
    s = 1.0 - t - 2.0**-40
    column = [list(p) for p in points]
    for r in range(1, len(points)):
        for i in range(len(points) - r):
            column[i] = [s * a + t * b for a, b in zip(column[i], column[i + 1])]
    return column[0]


def random_curve(rng, degree, dim=2, scale=1.0):
    return [[scale * rng.uniform(-1, 1) for _ in range(dim)] for _ in range(degree + 1)]


def test_exact_values(casteljau_oracle):
    assert casteljau_oracle.eval_exact([[0, 0], [1, 2], [2, 0]], Fraction(1, 3)) == [
        Fraction(2, 3),
        Fraction(8, 9),
    ]
    # a float t is that float exactly: b(0.1) of the line 0..1 is the float 0.1 exactly
    assert casteljau_oracle.eval_exact([[0], [1]], 0.1) == [Fraction(0.1)]
    ts = [Fraction(k, 7) for k in range(8)]
    batch = casteljau_oracle.eval_exact_batch([[0], [1], [3]], ts)
    assert batch == [casteljau_oracle.eval_exact([[0], [1], [3]], t) for t in ts]
    assert batch[7] == [Fraction(3)]


def test_a_float_de_casteljau_passes_the_way_a_users_ci_checks_it(casteljau_oracle):
    rng = random.Random(2024)
    for _ in range(200):
        points = random_curve(rng, rng.choice([1, 2, 3, 5, 8]))
        t = rng.random()
        approx = de_casteljau(points, t)
        assert casteljau_oracle.within_bound(points, t, approx), (points, t)
        # the lerp form has its own bound
        assert casteljau_oracle.within_bound(points, t, de_casteljau_lerp(points, t), method="lerp")
    # at the edges of the range too: subnormal coefficients and parameters, near 1e308
    for points, t in [
        ([[3e-323], [2e-323], [3.5e-323]], 0.3),
        ([[5e-324], [0.0]], 0.5),
        ([[1.0], [-1.0], [1.0]], 5e-324),
        ([[1e308], [-1e308], [1.7e308]], 0.3),
    ]:
        assert casteljau_oracle.within_bound(points, t, de_casteljau(points, t)), (points, t)


def test_a_wrong_evaluator_is_caught(casteljau_oracle):
    rng = random.Random(7)
    caught = 0
    for _ in range(50):
        points = random_curve(rng, 3)
        t = rng.uniform(0.2, 0.8)
        if not casteljau_oracle.within_bound(points, t, sloppy(points, t)):
            caught += 1
    assert caught >= 45


def test_judgements_give_ulps_bounds_and_condition(casteljau_oracle):
    points = [[0.1], [0.7]]
    j = casteljau_oracle.judge(points, 0.5, [0.39999999999999997])
    assert j["ulps"] == [0] and j["within_bound"] == [True]
    assert j["bound"][0] > 0 and j["condition"][0] >= 1.0
    two_up = math.nextafter(math.nextafter(0.39999999999999997, 1.0), 1.0)
    assert casteljau_oracle.ulps(points, 0.5, [two_up]) == [2]
    for method in METHODS:
        assert casteljau_oracle.bound(points, 0.5, method=method)[0] > 0
    bounds = casteljau_oracle.bound_batch(points, [0.25, 0.5], method="horner")
    assert len(bounds) == 2
    ts = [0.1, 0.2, 0.3]
    approxes = [de_casteljau(points, t) for t in ts]
    batch = casteljau_oracle.judge_batch(points, ts, approxes)
    assert [b["within_bound"] for b in batch] == [[True]] * 3


def test_an_overflowed_answer_is_judged(casteljau_oracle):
    points = [[7e307]] * 6
    j = casteljau_oracle.judge(points, 0.5, [math.inf])
    assert j["within_bound"] == [False]
    assert j["verdict"][0].startswith("overflow")
    j = casteljau_oracle.judge(points, 0.5, [math.nan])
    assert j["ulps"] == [None] and j["verdict"][0].startswith("nan")


def test_errors_are_raised_with_the_oracles_message(casteljau_oracle):
    with pytest.raises(OracleError, match="unknown method"):
        casteljau_oracle.bound([[0], [1]], 0.5, method="bogus")
    with pytest.raises(OracleError, match="empty"):
        casteljau_oracle.eval_exact([], 0)
    # the oracle goes on after an error
    assert casteljau_oracle.eval_exact([[1]], 0) == [Fraction(1)]


def test_many_large_requests_do_not_deadlock(casteljau_oracle):
    # far more than a pipe buffer each way, sent in one go
    rng = random.Random(3)
    points = random_curve(rng, 40, dim=8)
    reqs = [{"op": "eval", "points": points, "t": rng.random()} for _ in range(300)]
    answers = casteljau_oracle.requests(reqs)
    assert len(answers) == 300 and all(a["ok"] for a in answers)


def test_a_second_oracle_starts_and_closes(casteljau_oracle):
    with Oracle(casteljau_oracle.binary) as o:
        assert o.eval_exact([[2]], 0) == [Fraction(2)]


def test_rational_and_surface_answers_at_the_edges_are_within_their_bounds(casteljau_oracle):
    # homogeneous de Casteljau then one division, and rows then the column, in floats,
    # on subnormal, tiny and huge data: every correct answer is within the oracle's bound
    rng = random.Random(5)
    reqs = []
    for _ in range(300):
        n = rng.choice([1, 2, 3, 5])
        scale = rng.choice([1e-320, 1e-310, 1.0, 1e300])
        pts = [[rng.uniform(-1, 1) * scale, rng.uniform(-1, 1) * scale] for _ in range(n + 1)]
        w = [rng.uniform(0.5, 2) for _ in range(n + 1)]
        t = rng.choice([rng.random(), 5e-324, 1e-300])
        den = de_casteljau([[x] for x in w], t)[0]
        num = de_casteljau([[p[0] * wi, p[1] * wi] for p, wi in zip(pts, w)], t)
        approx = [x / den for x in num]
        reqs.append({"op": "rational_eval", "points": pts, "weights": w, "t": t, "approx": approx})
        net = [[[rng.uniform(-1, 1) * scale] for _ in range(n + 1)] for _ in range(3)]
        u, v = rng.choice([rng.random(), 5e-324]), rng.random()
        rows = [de_casteljau(row, v) for row in net]
        reqs.append({"op": "surface_eval", "net": net, "u": u, "v": v, "approx": de_casteljau(rows, u)})
    answers = casteljau_oracle.requests(reqs)
    assert all(all(a["within_bound"]) for a in answers)
