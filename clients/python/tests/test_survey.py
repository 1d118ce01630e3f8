"""The conformance survey (casteljau_oracle.survey): seeded cases, the numpy reference
judged by the oracle, and the same survey on a local Dask cluster."""

import math
import os

import pytest

from casteljau_oracle import OracleError, OraclePool, survey

from _reference import de_casteljau

np = pytest.importorskip("numpy")


def test_a_case_depends_on_its_seed_and_number_only():
    a = survey.cases(7, 0, 40, "eval")
    assert survey.cases(7, 25, 40, "eval") == a[25:]
    assert survey.cases(8, 0, 40, "eval") != a
    assert {c["kind"] for c in a} == set(survey.KINDS)
    assert all(1 <= c["degree"] <= 12 and c["dim"] in (2, 3) for c in a)
    assert all(len(c["points"]) == c["degree"] + 1 and len(c["points"][0]) == c["dim"] for c in a)
    assert all(c["t"] == 0.5 for c in survey.cases(7, 0, 40, "subdivide"))
    assert all(c["t"] is None for c in survey.cases(7, 0, 40, "elevate"))
    with pytest.raises(OracleError, match="no library 'cairo'"):
        survey.library_cases("cairo", "eval", 7, 0, 1)
    with pytest.raises(OracleError, match="kurbo has no specialize"):
        survey.library_cases("kurbo", "specialize", 7, 0, 1)


def test_the_numpy_reference_is_the_tests_de_casteljau_and_splits_at_the_point():
    for c in survey.cases(3, 0, 60, "split"):
        value = survey.numpy_answer("eval", c["points"], c["t"])
        assert value == de_casteljau(c["points"], c["t"])
        halves = survey.numpy_answer("split", c["points"], c["t"])
        assert halves["left"][-1] == halves["right"][0] == value
        assert halves["left"][0] == c["points"][0] and halves["right"][-1] == c["points"][-1]


def _one(pool, op, c, approx):
    return survey.judge(pool, "numpy", op, [dict(c, approx=approx)], survey.capabilities(pool))[0]


def test_a_correctly_rounded_answer_is_0_ulps_and_a_moved_one_is_caught(casteljau_oracle):
    c = next(c for c in survey.cases(5, 0, 50, "eval") if c["kind"] == "ordinary" and c["degree"] >= 3)
    with OraclePool(1, casteljau_oracle.binary) as pool:
        exact = casteljau_oracle.eval_exact(c["points"], c["t"])
        nearest = [float(x) for x in exact]
        r = _one(pool, "eval", c, nearest)
        assert r["ulps"] == 0 and r["error_ulps"] <= 0.5 and r["outside"] == 0
        # the bound is a few ulps of the points' size: 2^-30 relative is far past it
        moved = [x + abs(x) * 2.0**-30 + 2.0**-40 for x in nearest]
        r = _one(pool, "eval", c, moved)
        assert r["outside"] >= 1 and r["bound_used"] > 1 and r["ulps"] > 1000
        # one float step in one control point of a split is 1 ulp
        left, right = casteljau_oracle.split(c["points"], c["t"])
        halves = {"left": [[float(x) for x in p] for p in left], "right": [[float(x) for x in p] for p in right]}
        assert _one(pool, "split", c, halves)["ulps"] == 0
        halves["right"][1][0] = math.nextafter(halves["right"][1][0], math.inf)
        assert _one(pool, "split", c, halves)["ulps"] == 1


def test_the_numpy_reference_evaluates_within_de_casteljaus_bound(casteljau_oracle):
    records = survey.run("numpy", "eval", 44, 0, 300, binary=casteljau_oracle.binary)
    assert [r["id"] for r in records] == list(range(300))
    assert all(r["outside"] == 0 and r["bound_method"] == "de_casteljau" for r in records)
    assert {r["kind"] for r in records} == set(survey.KINDS)
    row = survey.summary(records)[0]
    assert row["judged"] == 300 and row["outside"] == 0 and 0 < row["bound_used"] <= 1
    assert "| numpy | eval | 300 |" in survey.markdown([row])


def test_the_survey_on_a_local_dask_cluster_gives_the_serial_records(casteljau_oracle, monkeypatch):
    pytest.importorskip("dask")
    distributed = pytest.importorskip("distributed")
    # the worker processes import this client as the test does
    here = os.path.join(os.path.dirname(__file__), "..")
    monkeypatch.setenv("PYTHONPATH", os.pathsep.join(filter(None, [here, os.environ.get("PYTHONPATH")])))
    binary = casteljau_oracle.binary
    with distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
    ) as cluster, distributed.Client(cluster) as client:
        assert len(client.scheduler_info()["workers"]) == 2
        for op in ("eval", "elevate"):
            on_dask = survey.run_on_dask(client, "numpy", op, 44, 400, partitions=4, binary=binary)
            serial = survey.run("numpy", op, 44, 0, 400, binary=binary)
            assert [r["id"] for r in on_dask] == list(range(400))
            assert on_dask == serial
        assert survey.run_on_dask(client, "numpy", "eval", 44, 0, partitions=4, binary=binary) == []
        with pytest.raises(OracleError, match="partitions"):
            survey.run_on_dask(client, "numpy", "eval", 44, 10, partitions=0, binary=binary)
    assert all(r["outside"] == 0 for r in serial if r["outside"] is not None)


def test_the_oracles_split_bound_is_each_sub_curves_evaluation_bound(casteljau_oracle):
    cs = survey.answer_cases("numpy", "split", survey.library_cases("numpy", "split", 9, 0, 150))
    with OraclePool(2, casteljau_oracle.binary) as pool:
        caps = survey.capabilities(pool)
        assert caps == {"eval": True, "split": True, "elevate": True, "derivative": True}
        native = survey.judge(pool, "numpy", "split", cs, caps)
        by_points = survey.judge(pool, "numpy", "split", cs, {"eval": True})
    strip = [{k: v for k, v in r.items() if k != "request"} for r in native]
    assert strip == [{k: v for k, v in r.items() if k != "request"} for r in by_points]
    assert "approx" in native[0]["request"] and all(r["outside"] == 0 for r in native)
    assert max(r["bound_used"] for r in native) > 0.1


def test_without_approx_on_an_op_the_ulps_are_counted_here_and_no_bound_is_claimed(casteljau_oracle):
    cs = survey.answer_cases("numpy", "elevate", survey.library_cases("numpy", "elevate", 9, 0, 100))
    with OraclePool(1, casteljau_oracle.binary) as pool:
        native = survey.judge(pool, "numpy", "elevate", cs, survey.capabilities(pool))
        local = survey.judge(pool, "numpy", "elevate", cs, {})
    assert [r["ulps"] for r in local] == [r["ulps"] for r in native]
    assert [r["error_ulps"] for r in local] == pytest.approx([r["error_ulps"] for r in native], rel=1e-9)
    assert max(r["ulps"] for r in local) > 0
    assert all(r["outside"] is None and r["bound_used"] is None for r in local)
    assert "no bound" in survey.markdown(survey.summary(local))
