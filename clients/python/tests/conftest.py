"""Runs the suite from the folder too (without `pip install`): the package next door, and
its fixture."""

import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), ".."))

from casteljau_oracle.pytest_plugin import casteljau_oracle  # noqa: E402,F401
