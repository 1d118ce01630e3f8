"""OraclePool: the same answers as one oracle, in order, from several processes."""

import random
from fractions import Fraction

import pytest

from casteljau_oracle import OracleError, OracleInputError, OraclePool


def test_a_pool_answers_like_one_oracle_in_order(casteljau_oracle):
    rng = random.Random(11)
    reqs = [
        {"op": "eval", "points": [[rng.uniform(-1, 1)] for _ in range(rng.randint(1, 9))], "t": rng.random()}
        for _ in range(3000)
    ]
    with OraclePool(3, casteljau_oracle.binary) as pool:
        assert len({o._proc.pid for o in pool.oracles}) == 3
        answers = pool.requests(reqs, chunk=100)
        used = [next(o._ids) for o in pool.oracles]
    assert answers == casteljau_oracle.requests(reqs)
    # every process took part: each numbered some of the 30 chunks
    assert all(n > 1 for n in used), used


def test_map_runs_a_function_on_the_pools_oracles(casteljau_oracle):
    cases = [([[0], [k]], Fraction(1, 2)) for k in range(50)]
    with OraclePool(2, casteljau_oracle.binary) as pool:
        got = pool.map(lambda o, c: o.eval_exact(*c), cases)
    assert got == [[Fraction(k, 2)] for k in range(50)]


def test_an_error_in_a_task_is_an_oracle_error_and_the_pool_goes_on(casteljau_oracle):
    with OraclePool(2, casteljau_oracle.binary) as pool:
        with pytest.raises(OracleError, match="empty"):
            pool.map(lambda o, c: o.eval_exact(c, 0), [[[1]], [], [[2]]])
        assert pool.map(lambda o, c: o.eval_exact(c, 0), [[[1]], [[2]]]) == [[1], [2]]
    with pytest.raises(OracleInputError):
        OraclePool(0, casteljau_oracle.binary)
    with pytest.raises(OracleError, match="cannot run"):
        OraclePool(2, "/no/such/casteljau")
