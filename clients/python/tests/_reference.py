"""Float evaluators the tests judge: plain Python, the code under test of a user's library."""


def de_casteljau(points, t):
    """A small float de Casteljau, the convex form (1 − t)·a + t·b: the code under test."""
    s = 1.0 - t
    column = [list(p) for p in points]
    for r in range(1, len(points)):
        for i in range(len(points) - r):
            column[i] = [s * a + t * b for a, b in zip(column[i], column[i + 1])]
    return column[0]
