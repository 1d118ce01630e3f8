"""The installed pytest plugin in someone else's project: it never touches the project's own
`casteljau_oracle` module, and `--casteljau-bin` names the binary."""

import os
import subprocess
import sys
import tempfile

import pytest


def installed_plugin():
    """Whether this interpreter, started afresh outside the repository (as the projects
    below run it), has the client installed, with its pytest11 entry point."""
    probe = (
        "from importlib import metadata\n"
        "try:\n"
        "    d = metadata.distribution('casteljau-oracle')\n"
        "    print(any(ep.group == 'pytest11' for ep in d.entry_points))\n"
        "except metadata.PackageNotFoundError:\n"
        "    print(False)\n"
    )
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    r = subprocess.run(
        [sys.executable, "-c", probe], cwd=tempfile.gettempdir(), env=env, capture_output=True, text=True, check=False
    )
    return r.stdout.strip() == "True"


pytestmark = pytest.mark.skipif(
    not installed_plugin(), reason="the client is not installed (pip install ./clients/python)"
)


def their_project(tmp_path):
    """A project with its own `casteljau_oracle.py` and tests that import it, and one test
    that uses this client's fixture."""
    (tmp_path / "casteljau_oracle.py").write_text("def answer():\n    return 42\n")
    (tmp_path / "test_theirs.py").write_text(
        "import casteljau_oracle\n\n"
        "def test_their_module():\n"
        "    assert casteljau_oracle.answer() == 42\n\n"
        "def test_the_fixture(casteljau_oracle):\n"
        "    from fractions import Fraction\n"
        "    assert casteljau_oracle.eval_exact([[0], [2]], Fraction(1, 2)) == [Fraction(1)]\n"
    )
    return tmp_path


def run_pytest(project, *args, python_args=()):
    env = {k: v for k, v in os.environ.items() if k not in ("CASTELJAU_BIN", "PYTHONPATH")}
    env["PATH"] = os.path.dirname(sys.executable)  # no casteljau on it
    return subprocess.run(
        [sys.executable, *python_args, "-m", "pytest", "-q", "-p", "no:cacheprovider", "-rs", *args],
        cwd=project,
        env=env,
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )


@pytest.mark.parametrize(
    "python_args",
    # `python -m pytest` puts the project first on sys.path; `-P` (Python 3.11) does not, as
    # the `pytest` script does: either way the project's module is its own
    [(), ("-P",)] if sys.version_info >= (3, 11) else [()],
)
def test_a_project_with_its_own_casteljau_oracle_module_runs_its_suite(casteljau_oracle, tmp_path, python_args):
    project = their_project(tmp_path)
    r = run_pytest(project, "--casteljau-bin", casteljau_oracle.binary, python_args=python_args)
    assert r.returncode == 0, r.stdout + r.stderr
    assert "2 passed" in r.stdout, r.stdout


def test_without_a_binary_the_fixture_skips_and_says_why(tmp_path):
    r = run_pytest(their_project(tmp_path))
    assert r.returncode == 0, r.stdout + r.stderr
    assert "1 passed, 1 skipped" in r.stdout and "casteljau not found" in r.stdout, r.stdout


def test_a_named_binary_that_cannot_run_is_an_error_not_a_skip(tmp_path):
    r = run_pytest(their_project(tmp_path), "--casteljau-bin", str(tmp_path / "no-such-casteljau"))
    assert r.returncode == 1, r.stdout + r.stderr
    assert "cannot run" in r.stdout and "1 error" in r.stdout, r.stdout


def test_the_timeout_option_reaches_the_fixture(casteljau_oracle, tmp_path):
    (tmp_path / "test_timeout.py").write_text(
        "def test_timeout(casteljau_oracle):\n    assert casteljau_oracle.timeout == 0.75\n"
    )
    r = run_pytest(tmp_path, "--casteljau-bin", casteljau_oracle.binary, "--casteljau-timeout", "0.75")
    assert r.returncode == 0 and "1 passed" in r.stdout, r.stdout + r.stderr
