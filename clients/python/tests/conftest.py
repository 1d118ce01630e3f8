"""Runs the suite from the folder too (without `pip install`): the packages next door, and
the plugin's fixture and options when the installed plugin is not loaded."""

import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), ".."))

from _casteljau_oracle import pytest_plugin
from _casteljau_oracle.pytest_plugin import casteljau_oracle  # noqa: F401


def pytest_addoption(parser, pluginmanager):
    if not pluginmanager.has_plugin(pytest_plugin.NAME):
        pytest_plugin.pytest_addoption(parser)


def pytest_report_header(config):
    import _casteljau_oracle

    return f"casteljau_oracle client under test: {os.path.dirname(_casteljau_oracle.__file__)}"
