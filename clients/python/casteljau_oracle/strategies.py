"""Hypothesis strategies for Bézier inputs (defined in `_casteljau_oracle.strategies`)."""

from _casteljau_oracle.strategies import *  # noqa: F403
from _casteljau_oracle.strategies import __all__, __doc__  # noqa: F401
