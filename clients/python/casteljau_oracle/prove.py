"""`prove_identity`: one identity checked by `casteljau prove --identity … --format json`.

    prove_identity("sum(k, 0, n, C(n, k)) = 2^n", for_=["n = 0.."])
    # {'verdict': 'proved', 'scope': 'every value', 'certificate': 'for every n ≥ 0: …',
    #  'counterexample': None, 'range_bound': None}

The verdict is decided by the binary in exact arithmetic, exactly as for a claim file.
"""

import json
import subprocess

from . import OracleError, find_binary

__all__ = ["prove_identity"]


def prove_identity(identity, for_=(), vars=None, binary=None, timeout=None):
    """Checks `lhs = rhs` (or a chain `a = b = c`) for every value of its parameters.

    `for_`: integer ranges, e.g. `["n = 0.."]` (every n) or `["n = 0..=10", "i = 0..=n"]`;
    `vars`: the continuous parameters, e.g. `["t", "u"]` (default: the free one-letter names).

    Returns a dict: `verdict` ("proved", "proved_in_range" or "fails"), `scope` ("every
    value" or the ranges proved, e.g. "n = 0..=10"; None when it fails), `certificate` (what was established;
    None when it fails), `counterexample` (the exact point where the sides differ, or None)
    and `range_bound` (why a finite range stays range-bound, or None). An identity that
    cannot be decided, or bad input, raises `OracleError` with the binary's message.
    """
    args = [find_binary(binary), "prove", "--identity", identity, "--format", "json"]
    for r in [for_] if isinstance(for_, str) else for_:
        args += ["--for", r]
    if vars:
        args += ["--vars", ",".join([vars] if isinstance(vars, str) else vars)]
    run = subprocess.run(args, capture_output=True, text=True, timeout=timeout)
    # 0: proved, 1: fails (the report is still on stdout), 2: bad input or undecided
    if run.returncode not in (0, 1) or not run.stdout.strip():
        message = run.stderr.strip() or run.stdout.strip()
        if run.stdout.strip():
            try:
                claim = json.loads(run.stdout)["claims"][0]
                message = claim["certificate"]
            except (ValueError, KeyError, IndexError):
                pass
        raise OracleError(message or f"casteljau exited with status {run.returncode}")
    claim = json.loads(run.stdout)["claims"][0]
    verdict = claim["verdict"]
    if verdict not in ("proved", "proved_in_range", "fails"):
        raise OracleError(claim.get("certificate", f"undecided: {verdict}"))
    fails = verdict == "fails"
    return {
        "verdict": verdict,
        "scope": None if fails else claim.get("range") or "every value",
        "certificate": None if fails else claim["certificate"],
        "counterexample": claim["certificate"] if fails else None,
        "range_bound": claim.get("range_bound"),
    }
