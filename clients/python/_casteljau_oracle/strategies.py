"""Hypothesis strategies for Bézier inputs: curves, rational curves, surfaces, parameters,
and ill-conditioned cases (curves evaluated near a multiple root).

    from hypothesis import given
    from casteljau_oracle.strategies import curves, parameters

    @given(curves(max_degree=8), parameters())
    def test_my_eval(casteljau_oracle, points, t):
        casteljau_oracle.assert_within_bound(points, t, my_eval(points, t))

Every value is a finite Python float (subnormals included unless `elements` says
otherwise), so the oracle gives a bound for each case. Needs hypothesis
(`pip install "./clients/python[hypothesis]"`).
"""

try:
    from hypothesis import strategies as st
except ImportError as e:  # pragma: no cover - depends on the environment
    raise ImportError(
        'casteljau_oracle.strategies needs hypothesis (pip install "casteljau-oracle[hypothesis]")'
    ) from e

__all__ = [
    "coordinates",
    "curves",
    "ill_conditioned",
    "parameters",
    "rational_curves",
    "surfaces",
    "weights",
]

#: a magnitude far inside the f64 range: de Casteljau's sums and the bounds stay finite
DEFAULT_MAX_MAGNITUDE = 1e100


def coordinates(max_magnitude=DEFAULT_MAX_MAGNITUDE, allow_subnormal=True):
    """One finite coordinate: any float of magnitude at most `max_magnitude`, with 0, ±1,
    the smallest subnormal and the extremes drawn often."""
    edges = [0.0, -0.0, 1.0, -1.0, 0.5, max_magnitude, -max_magnitude]
    if allow_subnormal:
        edges += [5e-324, -5e-324, 2.2250738585072014e-308]
    return st.one_of(
        st.sampled_from(edges),
        st.floats(
            min_value=-max_magnitude,
            max_value=max_magnitude,
            allow_nan=False,
            allow_infinity=False,
            allow_subnormal=allow_subnormal,
        ),
    )


def parameters(allow_subnormal=True):
    """A float t in [0, 1], with 0, 1, 1/2, the neighbours of 1 and of 0 drawn often."""
    edges = [0.0, 1.0, 0.5, 1.0 - 2.0**-53, 2.0**-53, 0.1, 0.9]
    if allow_subnormal:
        edges.append(5e-324)
    return st.one_of(
        st.sampled_from(edges),
        st.floats(min_value=0.0, max_value=1.0, allow_nan=False, allow_subnormal=allow_subnormal),
    )


def _dims(dim):
    return st.just(dim) if isinstance(dim, int) else st.sampled_from(list(dim))


def curves(min_degree=1, max_degree=12, dim=(1, 2, 3), elements=None):
    """Control points [[x, y, …], …] of a curve of degree min_degree..max_degree in `dim`
    dimensions (an int, or a collection to draw from)."""
    if not 0 <= min_degree <= max_degree:
        raise ValueError(f"degrees must satisfy 0 <= min_degree <= max_degree, not {min_degree}, {max_degree}")
    elements = coordinates() if elements is None else elements

    @st.composite
    def build(draw):
        d = draw(_dims(dim))
        n = draw(st.integers(min_degree, max_degree))
        return [draw(st.lists(elements, min_size=d, max_size=d)) for _ in range(n + 1)]

    return build()


def weights(count, min_value=2.0**-10, max_value=2.0**10):
    """`count` positive float weights."""
    return st.lists(
        st.floats(min_value=min_value, max_value=max_value, allow_nan=False, allow_infinity=False),
        min_size=count,
        max_size=count,
    )


def rational_curves(min_degree=1, max_degree=8, dim=(2, 3), elements=None, min_weight=2.0**-10, max_weight=2.0**10):
    """(points, weights) of a rational curve with positive weights."""

    @st.composite
    def build(draw):
        points = draw(curves(min_degree, max_degree, dim, elements))
        return points, draw(weights(len(points), min_weight, max_weight))

    return build()


def surfaces(max_degree_u=5, max_degree_v=5, dim=(1, 3), elements=None):
    """A control net of a tensor-product surface: rows i = 0..m, each of n + 1 points."""
    elements = coordinates() if elements is None else elements

    @st.composite
    def build(draw):
        d = draw(_dims(dim))
        m = draw(st.integers(0, max_degree_u))
        n = draw(st.integers(0, max_degree_v))
        point = st.lists(elements, min_size=d, max_size=d)
        return [draw(st.lists(point, min_size=n + 1, max_size=n + 1)) for _ in range(m + 1)]

    return build()


def _bernstein_of_power(root, n):
    """The Bézier coefficients of (t − root)^n, in floats: b_i = (−root)^(n−i) (1 − root)^i."""
    return [[(-root) ** (n - i) * (1.0 - root) ** i] for i in range(n + 1)]


def ill_conditioned(min_degree=3, max_degree=12):
    """(points, t): the curve (t − r)^n with its coefficients rounded to floats, at a float
    t near the n-fold root r, where Σ|b_i||B_i(t)| / |b(t)| is huge: answers there are
    far from correctly rounded even within their bound."""

    @st.composite
    def build(draw):
        n = draw(st.integers(min_degree, max_degree))
        root = draw(st.floats(min_value=0.25, max_value=0.75))
        offset = draw(st.floats(min_value=-1e-3, max_value=1e-3))
        return _bernstein_of_power(root, n), root + offset

    return build()
