"""The helpers without numpy: every op's exact answer, `ulps(a, b)`, `assert_within_bound`,
and inputs of every exact kind."""

import math
import os
from decimal import Decimal
from fractions import Fraction

import pytest

from casteljau_oracle import Oracle, OracleError, OracleInputError, assert_within_bound, ulps
from _reference import de_casteljau


def test_every_op_has_a_helper(casteljau_oracle):
    o = casteljau_oracle
    assert o.elevate([[0, 0], [1, 2], [2, 0]]) == [
        [0, 0],
        [Fraction(2, 3), Fraction(4, 3)],
        [Fraction(4, 3), Fraction(4, 3)],
        [2, 0],
    ]
    assert o.elevate([[0], [1]], by=2) == [[0], [Fraction(1, 3)], [Fraction(2, 3)], [1]]
    assert o.split([[0], [1], [3]], Fraction(1, 2)) == (
        [[0], [Fraction(1, 2)], [Fraction(5, 4)]],
        [[Fraction(5, 4)], [2], [3]],
    )
    assert o.derivative([[0, 0], [1, 2], [3, 1]]) == [[2, 4], [4, -2]]
    assert o.derivative([[0, 0], [1, 2], [3, 1]], t=Fraction(1, 2)) == [3, 1]
    assert o.derivative([[0], [1], [3]], order=2) == [[2]]
    assert o.to_bezier([[0, 4, -4], [1, 0, 0]]) == [[0, 1], [2, 1], [0, 1]]
    assert o.rational_eval([[1, 0], [1, 1], [0, 1]], [1, 1, 2], Fraction(1, 2)) == [Fraction(3, 5), Fraction(4, 5)]
    net = [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]
    assert o.surface_eval(net, Fraction(1, 3), Fraction(3, 4)) == [Fraction(1, 3), Fraction(3, 4), Fraction(1, 4)]
    kind, implicit = o.conic([[-1, 1], [0, -1], [1, 1]], [1, Fraction(1, 2), 1])
    assert kind == "ellipse" and implicit == [4, 0, 3, 0, -10, 3]
    assert o.conic([[0, 0], [1, 1], [2, 2]], [1, 1, 1])[1] is None


def test_rational_and_surface_answers_are_judged(casteljau_oracle):
    j = casteljau_oracle.judge_rational([[1, 0], [1, 1], [0, 1]], [1, 1, 2], 0.5, [0.6, 0.8])
    assert j["within_bound"] == [True, True] and j["ulps"] == [0, 0]
    net = [[[0.0], [0.5]], [[1.0], [0.25]]]
    j = casteljau_oracle.judge_surface(net, 0.5, 0.5, [0.4375])
    assert j["ulps"] == [0] and j["within_bound"] == [True]


def test_exact_inputs_of_every_kind_are_sent_exactly(casteljau_oracle):
    o = casteljau_oracle
    for t in (Fraction(1, 10), Decimal("0.1"), "1/10", "0.1"):
        assert o.eval_exact([[0], [1]], t) == [Fraction(1, 10)], t
    assert o.eval_exact([[0], [1]], 0.1) == [Fraction(0.1)]  # the float, not 1/10
    assert o.eval_exact(((0,), (1,)), Decimal("1e-400")) == [Fraction(1, 10**400)]
    with pytest.raises(OracleInputError, match="Infinity is no input"):
        o.eval_exact([[0], [1]], Decimal("Infinity"))


def test_ulps_counts_floats_between():
    assert ulps(0.1, 0.1) == 0
    assert ulps(0.0, -0.0) == 0
    assert ulps(1.0, math.nextafter(1.0, 2.0)) == 1
    assert ulps(1.0, math.nextafter(math.nextafter(1.0, 0.0), 0.0)) == 2
    assert ulps(5e-324, -5e-324) == 2  # across zero
    assert ulps(math.inf, 1.7976931348623157e308) == 1
    assert ulps(0.0, math.inf) == 0x7FF0000000000000
    assert ulps(-math.inf, math.inf) == 2 * 0x7FF0000000000000
    assert ulps(math.nan, 1.0) is None
    assert ulps([1.0, 2.0], [1.0, math.nextafter(2.0, 3.0)]) == [0, 1]
    assert ulps([1.0, 1.0], 1.0) == [0, 0]
    with pytest.raises(OracleError):
        ulps("x", 1.0)


def test_assert_within_bound_passes_a_correct_answer_and_explains_a_wrong_one(casteljau_oracle):
    points = [[0.1, 1.0], [0.7, -2.0], [0.3, 0.5]]
    good = de_casteljau(points, 0.3)
    assert_within_bound(casteljau_oracle, points, 0.3, good)
    casteljau_oracle.assert_within_bound(points, [0.3, 0.6], [good, de_casteljau(points, 0.6)])
    j = casteljau_oracle.judge(points, 0.3, good)
    # moved twice its bound away from the exact value, in the first coordinate
    ulp = math.ulp(j["nearest"][0])
    bad = [good[0] + 2 * (j["bound"][0] + 1) * ulp, good[1]]
    with pytest.raises(AssertionError) as e:
        assert_within_bound(casteljau_oracle, points, 0.3, bad)
    message = str(e.value)
    jb = casteljau_oracle.judge(points, 0.3, bad)
    assert "de_casteljau at t = 0.3" in message and "1 of 2 coordinates" in message
    first = next(line for line in message.splitlines() if line.split()[:1] == ["0"])
    assert first.split()[1:4] == [repr(bad[0]), repr(jb["nearest"][0]), str(jb["ulps"][0])]
    assert f"{jb['bound'][0]:.4g}" in first and f"{jb['condition'][0]:.4g}" in first and first.endswith("NO")
    assert f"exact[0] = {jb['point'][0]}" in message and f"exact[1] = {jb['point'][1]}" in message
    # in a batch, the failing parameter is named
    with pytest.raises(AssertionError, match="at t = 0.3 "):
        casteljau_oracle.assert_within_bound(points, [0.6, 0.3], [de_casteljau(points, 0.6), bad])


def test_assert_within_bound_without_a_bound_is_an_oracle_error(casteljau_oracle):
    with pytest.raises(OracleError, match="no bound"):
        casteljau_oracle.assert_within_bound([[0.1], [0.2]], Fraction(1, 3), [0.125])


def test_arrays_true_without_numpy_or_a_bad_value_is_an_oracle_error(casteljau_oracle):
    with pytest.raises(OracleError, match="arrays"):
        Oracle(casteljau_oracle.binary, arrays="yes")
    try:
        import numpy  # noqa: F401
    except ImportError:
        with pytest.raises(OracleError, match="needs numpy"):
            Oracle(casteljau_oracle.binary, arrays=True)


def test_the_failure_message_quoted_in_the_docs_is_what_the_client_prints(casteljau_oracle):
    doc = os.path.join(os.path.dirname(__file__), "..", "..", "..", "docs", "oracle-python.md")
    if not os.path.exists(doc):
        pytest.skip("docs/oracle-python.md is not beside this suite")
    with pytest.raises(AssertionError) as e:
        assert_within_bound(casteljau_oracle, [[0.1, 1.0], [0.7, -2.0], [0.3, 0.5]], 0.3, [0.3010000000000001, -0.5])
    with open(doc, encoding="utf-8") as f:
        assert "```text\n" + str(e.value) + "\n```" in f.read()
