"""`prove_identity` against the built binary ($CASTELJAU_BIN)."""

import pytest

from casteljau_oracle import OracleError, find_binary
from casteljau_oracle.prove import prove_identity


@pytest.fixture(scope="module")
def binary():
    try:
        return find_binary()
    except OracleError:
        pytest.skip("no casteljau binary (set CASTELJAU_BIN)")


def test_a_binomial_sum_is_proved_for_every_n(binary):
    r = prove_identity("sum(k, 0, n, C(n, k)) = 2^n", for_=["n = 0.."], binary=binary)
    assert r["verdict"] == "proved"
    assert r["scope"] == "every value"
    assert r["certificate"].startswith("for every n ≥ 0")
    assert r["counterexample"] is None


def test_a_false_identity_gives_its_counterexample(binary):
    r = prove_identity("sum(k, 0, n, C(n, k)) = 3^n", for_="n = 0..", binary=binary)
    assert r["verdict"] == "fails"
    assert r["counterexample"] == "at n = 1: left side = 2, right side = 3"
    assert r["certificate"] is None and r["scope"] is None


def test_a_finite_range_and_parameters(binary):
    r = prove_identity("B(i, n, t) = B(n - i, n, 1 - t)", for_=["n = 0..=4", "i = 0..=n"], vars=["t"], binary=binary)
    assert r["verdict"] == "proved_in_range"
    assert r["scope"] == "n = 0..=4, i = 0..=n"
    assert prove_identity("B(1, 2, t) = 2t(1 - t)", binary=binary)["verdict"] == "proved"


def test_bad_and_undecidable_identities_raise(binary):
    with pytest.raises(OracleError, match="no '=' between two sides"):
        prove_identity("t^2", binary=binary)
    with pytest.raises(OracleError, match="unknown name 'x'"):
        prove_identity("x = x", vars=["t"], binary=binary)
