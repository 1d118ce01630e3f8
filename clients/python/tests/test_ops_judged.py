"""split, elevate, derivative and to_bezier judged: the caller's float answers against the
a priori bound of the algorithm they name, per point and coordinate, in lists or arrays."""

from fractions import Fraction

import pytest


def de_casteljau_split(b, t):
    """A float split of one curve (a list of points), the convex form."""
    left, right, level = [b[0]], [b[-1]], [list(p) for p in b]
    while len(level) > 1:
        level = [[(1.0 - t) * x + t * y for x, y in zip(p, q)] for p, q in zip(level, level[1:])]
        left.append(level[0])
        right.append(level[-1])
    return left, right[::-1]


CURVE = [[0.1, 0.0], [0.7, 1.0], [0.3, 0.25], [-0.4, 2.0]]


def test_a_float_split_is_within_its_bound_and_a_wrong_one_is_not(casteljau_oracle):
    left, right = de_casteljau_split(CURVE, 0.3)
    j = casteljau_oracle.split(CURVE, 0.3, approx=(left, right))
    assert j["method"] == "de_casteljau"
    for half in ("left", "right"):
        assert all(all(p) for p in j[half]["within_bound"])
        assert len(j[half]["ulps"]) == 4 and len(j[half]["ulps"][0]) == 2
    exact_left, _ = casteljau_oracle.split(CURVE, 0.3)
    assert j["left"]["points"] == exact_left
    wrong = [list(p) for p in left]
    wrong[2][1] *= 1.0 + 1e-12
    j = casteljau_oracle.split(CURVE, 0.3, approx={"left": wrong, "right": right}, method="de_casteljau")
    assert j["left"]["within_bound"][2] == [True, False]
    assert j["left"]["ulps"][2][1] > 1000


def test_elevate_derivative_and_to_bezier_are_judged(casteljau_oracle):
    b = [p[0] for p in CURVE]
    n = len(b) - 1
    elevated = [b[0]] + [(i * b[i - 1] + (n + 1 - i) * b[i]) / (n + 1) for i in range(1, n + 1)] + [b[n]]
    j = casteljau_oracle.elevate([[x] for x in b], 1, approx=[[x] for x in elevated])
    assert j["method"] == "formula" and all(w == [True] for w in j["within_bound"])
    assert j["bound"][0] == [0.0]
    d = [[n * (b[i + 1] - b[i])] for i in range(n)]
    j = casteljau_oracle.derivative([[x] for x in b], 1, approx=d, method="differences")
    assert all(w == [True] for w in j["within_bound"])
    j = casteljau_oracle.to_bezier([[1.0, 2.0, 3.0]], approx=[[1.0], [2.0], [6.0]])
    assert j["ulps"] == [[0], [0], [0]]
    # the bound alone
    j = casteljau_oracle.elevate([[x] for x in b], 2, method="formula")
    assert "within_bound" not in j and len(j["bound"]) == n + 3


def test_judged_answers_are_arrays_for_arrays(casteljau_oracle):
    np = pytest.importorskip("numpy")
    pts = np.array(CURVE)
    left, right = de_casteljau_split(CURVE, 0.3)
    j = casteljau_oracle.split(pts, 0.3, approx=(np.array(left), np.array(right)))
    assert j["left"]["ulps"].shape == (4, 2) and j["right"]["within_bound"].dtype == bool
    assert j["left"]["points"][0, 0] == Fraction(0.1)
    d = np.diff(pts, axis=0) * 3
    j = casteljau_oracle.derivative(pts, 1, approx=d)
    assert j["within_bound"].all() and j["bound"].shape == (3, 2)
