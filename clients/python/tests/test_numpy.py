"""numpy in and out: arrays of any numeric dtype are sent exactly; results are arrays when
the input is one (or with arrays=True), and lists otherwise."""

import math
from fractions import Fraction

import pytest

from casteljau_oracle import Oracle, OracleInputError, ulps

np = pytest.importorskip("numpy")


def np_de_casteljau(points, t):
    """A numpy de Casteljau on an (n + 1, d) array, the convex form: the code under test."""
    column = np.array(points, dtype=np.float64)
    for r in range(1, len(column)):
        column = (1.0 - t) * column[:-1] + t * column[1:]
    return column[0]


@pytest.mark.parametrize("dtype", [np.int8, np.int32, np.int64, np.uint16, np.float16, np.float32, np.float64])
def test_arrays_of_every_numeric_dtype_are_sent_exactly(casteljau_oracle, dtype):
    points = np.array([[0, 1], [3, -2], [5, 7]]).astype(dtype)
    if np.issubdtype(dtype, np.unsignedinteger):
        points = np.array([[0, 1], [3, 2], [5, 7]], dtype=dtype)
    expected = casteljau_oracle.eval_exact(points.tolist(), Fraction(1, 3))
    got = casteljau_oracle.eval_exact(
        points, dtype(1) / dtype(3) if dtype in (np.float16, np.float32) else Fraction(1, 3)
    )
    assert isinstance(got, np.ndarray) and got.dtype == object and got.shape == (2,)
    if dtype in (np.float16, np.float32):
        # t is the float32 (or float16) nearest 1/3, exactly
        t = Fraction(float(dtype(1) / dtype(3)))
        assert got.tolist() == casteljau_oracle.eval_exact(points.tolist(), t)
    else:
        assert got.tolist() == expected


def test_a_float32_value_is_sent_as_itself_and_a_longdouble_exactly(casteljau_oracle):
    x = np.float32(0.1)
    assert casteljau_oracle.eval_exact([[x]], 0) == [Fraction(float(x))]
    assert Fraction(float(x)) != Fraction(0.1)
    y = np.longdouble(1) / np.longdouble(3)
    (got,) = casteljau_oracle.eval_exact([[y]], 0)
    p, q = y.as_integer_ratio()
    assert got == Fraction(p, q)
    with pytest.raises(OracleInputError):
        casteljau_oracle.eval_exact(np.array([[np.nan]]), 0)
    with pytest.raises(OracleInputError):
        casteljau_oracle.eval_exact(np.array([[1 + 2j]]), 0)


def test_results_are_arrays_for_array_input_and_lists_for_lists(casteljau_oracle):
    o = casteljau_oracle
    pts = np.array([[0.1, 1.0], [0.7, -2.0], [0.3, 0.5]])
    ts = np.array([0.25, 0.5, 0.75])
    assert isinstance(o.eval_exact(pts.tolist(), 0.5), list)
    batch = o.eval_exact_batch(pts, ts)
    assert batch.shape == (3, 2) and batch.dtype == object
    assert batch[1].tolist() == o.eval_exact(pts.tolist(), 0.5)
    assert o.bound(pts, 0.5).dtype == np.float64 and o.bound_batch(pts, ts).shape == (3, 2)
    assert o.elevate(pts, 2).shape == (5, 2)
    left, right = o.split(pts, 0.5)
    assert left.shape == right.shape == (3, 2) and left[-1].tolist() == right[0].tolist()
    assert o.derivative(pts).shape == (2, 2) and o.derivative(pts, t=0.5).shape == (2,)
    assert o.to_bezier(np.array([[0, 4, -4], [1, 0, 0]])).tolist() == [[0, 1], [2, 1], [0, 1]]
    net = np.array([[[0.0], [0.5]], [[1.0], [0.25]]])
    assert o.surface_eval(net, 0.5, 0.5).tolist() == [Fraction(7, 16)]


def test_judgements_come_back_as_arrays_and_batches_with_a_first_axis_over_t(casteljau_oracle):
    pts = np.array([[0.1, 1.0], [0.7, -2.0], [0.3, 0.5]])
    ts = np.linspace(0.0, 1.0, 11)
    approx = np.array([np_de_casteljau(pts, t) for t in ts])
    j = casteljau_oracle.judge_batch(pts, ts, approx)
    assert j["ulps"].shape == j["bound"].shape == j["within_bound"].shape == (11, 2)
    assert j["within_bound"].dtype == bool and j["within_bound"].all()
    assert j["point"].shape == (11, 2) and j["point"][0, 0] == Fraction(0.1)
    lists = casteljau_oracle.judge_batch(pts.tolist(), ts.tolist(), approx.tolist())
    assert j["ulps"].tolist() == [r["ulps"] for r in lists]
    one = casteljau_oracle.judge(pts, ts[3], approx[3])
    assert one["ulps"].tolist() == lists[3]["ulps"] and one["condition"].dtype == np.float64
    nan = casteljau_oracle.judge(pts, 0.3, np.array([np.nan, 1.0]))
    assert np.isnan(nan["ulps"][0]) and nan["verdict"][0].startswith("nan")
    casteljau_oracle.assert_within_bound(pts, ts, approx)


def test_arrays_option(casteljau_oracle):
    with Oracle(casteljau_oracle.binary, arrays=True) as o:
        assert isinstance(o.eval_exact([[1], [2]], 0), np.ndarray)
    with Oracle(casteljau_oracle.binary, arrays=False) as o:
        assert isinstance(o.eval_exact(np.array([[1], [2]]), 0), list)


def test_ulps_of_arrays_matches_ulps_of_floats():
    rng = np.random.default_rng(3)
    a = np.concatenate([rng.normal(size=200), [0.0, -0.0, 5e-324, -5e-324, np.inf, -np.inf, 1.7976931348623157e308]])
    b = np.concatenate([a[:200] + rng.normal(size=200) * 1e-15, [-0.0, 5e-324, -5e-324, 0.0, 1e308, np.inf, np.inf]])
    got = ulps(a, b)
    assert got.dtype == np.float64 and got.shape == a.shape
    assert got.tolist() == [float(ulps(float(x), float(y))) for x, y in zip(a, b)]
    assert np.isnan(ulps(np.array([np.nan]), 1.0)[0])
    f32 = np.float32(0.1)
    assert ulps(np.array([f32]), np.array([0.1]))[0] == ulps(float(f32), 0.1)
    assert ulps(np.array([1.0]), math.nextafter(1.0, 2))[0] == 1


def test_raw_requests_take_numpy_values_and_fractions(casteljau_oracle):
    pts = np.array([[0, 1], [3, 5]], dtype=np.int64)
    a = casteljau_oracle.request({"op": "eval", "points": pts, "t": np.float32(0.25)})
    assert a["point"] == ["3/4", "2"]
    a = casteljau_oracle.request({"op": "split", "points": [[np.float64(0.5)], [1]], "t": Fraction(1, 3)})
    assert a["left"][-1] == ["2/3"]
