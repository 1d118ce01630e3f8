"""A pytest fixture: `casteljau_oracle`, one `Oracle` for the whole session.

Installed with the package (entry point `pytest11`); the binary comes from
$CASTELJAU_BIN or PATH. Tests are skipped, with the reason, when there is none.
"""

import pytest

from . import Oracle, OracleError, find_binary


@pytest.fixture(scope="session")
def casteljau_oracle():
    """A running `casteljau oracle`, closed at the end of the session."""
    try:
        binary = find_binary()
    except OracleError as e:
        pytest.skip(str(e))
    with Oracle(binary) as oracle:
        yield oracle
