"""The Hypothesis strategies: the shapes they promise, correct float code passes on them,
and a wrong evaluator is found."""

import math

import pytest

hypothesis = pytest.importorskip("hypothesis")

from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

from casteljau_oracle.strategies import (  # noqa: E402
    curves,
    ill_conditioned,
    parameters,
    rational_curves,
    surfaces,
)
from _reference import de_casteljau  # noqa: E402

SETTINGS = settings(deadline=None, max_examples=150, derandomize=True, database=None)


def sloppy(points, t):
    """A wrong evaluator: 1 − t computed as 1 − t − 2^−40."""
    return de_casteljau_with(points, t, 1.0 - t - 2.0**-40)


def de_casteljau_with(points, t, s):
    column = [list(p) for p in points]
    for r in range(1, len(points)):
        for i in range(len(points) - r):
            column[i] = [s * a + t * b for a, b in zip(column[i], column[i + 1])]
    return column[0]


@SETTINGS
@given(curves(min_degree=2, max_degree=4, dim=3), curves(dim=(1, 2)), rational_curves(), surfaces(2, 3, dim=2))
def test_shapes(c, d, rc, net):
    assert 3 <= len(c) <= 5 and all(len(p) == 3 for p in c)
    assert len({len(p) for p in d}) == 1 and len(d[0]) in (1, 2) and 2 <= len(d) <= 13
    points, w = rc
    assert len(w) == len(points) and all(x > 0 for x in w)
    assert 1 <= len(net) <= 3 and len({len(row) for row in net}) == 1 and all(len(p) == 2 for row in net for p in row)
    for v in [x for p in c + d + points for x in p] + [x for row in net for p in row for x in p]:
        assert isinstance(v, float) and math.isfinite(v)


@SETTINGS
@given(parameters())
def test_parameters_are_floats_in_the_unit_interval(t):
    assert isinstance(t, float) and 0.0 <= t <= 1.0


@SETTINGS
@given(points=curves(max_degree=8), t=parameters())
def test_a_float_de_casteljau_is_within_its_bound_on_every_curve(casteljau_oracle, points, t):
    casteljau_oracle.assert_within_bound(points, t, de_casteljau(points, t))


@SETTINGS
@given(curve=rational_curves(max_degree=5), t=parameters())
def test_a_float_rational_de_casteljau_is_within_its_bound(casteljau_oracle, curve, t):
    points, w = curve
    den = de_casteljau([[x] for x in w], t)[0]
    num = de_casteljau([[x * wi for x in p] for p, wi in zip(points, w)], t)
    j = casteljau_oracle.judge_rational(points, w, t, [x / den for x in num])
    assert all(j["within_bound"]), j


@SETTINGS
@given(net=surfaces(3, 3), u=parameters(), v=parameters())
def test_a_float_surface_evaluation_is_within_its_bound(casteljau_oracle, net, u, v):
    rows = [de_casteljau(row, v) for row in net]
    j = casteljau_oracle.judge_surface(net, u, v, de_casteljau(rows, u))
    assert all(j["within_bound"]), j


@SETTINGS
@given(case=ill_conditioned())
def test_ill_conditioned_cases_are_ill_conditioned_and_still_within_the_bound(casteljau_oracle, case):
    points, t = case
    j = casteljau_oracle.judge(points, t, de_casteljau(points, t))
    assert j["within_bound"] == [True]
    assert j["condition"][0] > 1e6, j["condition"]


def test_a_wrong_evaluator_is_found(casteljau_oracle):
    found = hypothesis.find(
        st.tuples(curves(min_degree=3, max_degree=3, dim=1), parameters()),
        lambda c: not casteljau_oracle.within_bound(c[0], c[1], sloppy(*c)),
        settings=settings(deadline=None, max_examples=500, derandomize=True, database=None),
    )
    points, t = found
    assert not casteljau_oracle.within_bound(points, t, sloppy(points, t))
