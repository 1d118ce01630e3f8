"""The pytest plugin: a session fixture `casteljau_oracle` and the options
`--casteljau-bin` and `--casteljau-timeout`.

Registered as the `pytest11` entry point named `casteljau-oracle` (a name no module can
have) from this module of the private package `_casteljau_oracle`: loading it imports
nothing named `casteljau_oracle`, so a project with its own `casteljau_oracle.py` (or its
own plugin of that name) loads and imports its module, not this client. Disable it with
`-p no:casteljau-oracle`.
"""

import pytest

from .errors import OracleError
from .oracle import DEFAULT_TIMEOUT, Oracle, find_binary

#: the name the plugin is registered under (the entry point's name)
NAME = "casteljau-oracle"


def pytest_addoption(parser):
    group = parser.getgroup("casteljau-oracle", "casteljau oracle (the casteljau_oracle fixture)")
    group.addoption(
        "--casteljau-bin",
        metavar="PATH",
        default=None,
        help="the casteljau executable for the casteljau_oracle fixture (else $CASTELJAU_BIN, else PATH)",
    )
    group.addoption(
        "--casteljau-timeout",
        metavar="SECONDS",
        type=float,
        default=DEFAULT_TIMEOUT,
        help=f"the longest wait for any one oracle answer (default {DEFAULT_TIMEOUT} s)",
    )


@pytest.fixture(scope="session")
def casteljau_oracle(request):
    """A running `casteljau oracle`, closed at the end of the session. Skipped, with the
    reason, when no binary is named or found; an error when the named one cannot run."""
    try:
        binary = find_binary(request.config.getoption("casteljau_bin"))
    except OracleError as e:
        pytest.skip(str(e))
    with Oracle(binary, timeout=request.config.getoption("casteljau_timeout")) as oracle:
        yield oracle
