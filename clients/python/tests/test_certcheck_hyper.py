"""The independent checker on the for-every certificates (`pieces` data, methods `pieces`
and `wz`) without SymPy: never reported re-checked (the proof, `cert_pieces`, needs SymPy;
test_certcheck_pieces.py tests it), each goal evaluated exactly at its first values, and
tampered goals refused when they are false there."""

import collections
import glob
import json
import os
import sys

import pytest

from _casteljau_oracle.cert_check import NOT_RECHECKED, REFUSED, check_certificate

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "..", "..", "tests", "certificates", "texts")


def _docs():
    docs = [json.load(open(f, encoding="utf-8")) for f in sorted(glob.glob(os.path.join(DATA, "*.json")))]
    return [d for d in docs if "pieces" in d]


@pytest.fixture(autouse=True)
def _no_sympy(monkeypatch):
    monkeypatch.setitem(sys.modules, "sympy", None)


def _edits(s):
    """Each digit run incremented, each ' + ' and ' - ' flipped, the whole side plus one."""
    out, i = [], 0
    while i < len(s):
        if s[i].isdigit():
            j = i
            while j < len(s) and s[j].isdigit():
                j += 1
            out.append(s[:i] + str(int(s[i:j]) + 1) + s[j:])
            i = j
        else:
            i += 1
    for a, b in ((" + ", " - "), (" - ", " + ")):
        k = s.find(a)
        while k >= 0:
            out.append(s[:k] + b + s[k + len(a) :])
            k = s.find(a, k + 1)
    out.append(f"{s} + 1")
    return out


def test_every_pieces_certificate_holds_at_its_first_values():
    docs = _docs()
    assert len(docs) >= 26
    for d in docs:
        o = check_certificate(d)
        assert o.status == NOT_RECHECKED and "needs SymPy" in o.detail, o.line()
        assert "the goal holds at its first values" in o.detail, o.line()


def test_an_edited_goal_with_its_data_kept_is_refused():
    d = next(d for d in _docs() if d["id"] == "000-partition-of-unity")
    d["goal"]["equalities"][0]["rhs"] = "2"
    o = check_certificate(d)
    assert o.status == REFUSED and "the sides are" in o.detail, o.line()


def test_tampered_goals_are_refused_or_true_at_their_first_values():
    counts = collections.Counter()
    for d in _docs():
        for i, eq in enumerate(d["goal"]["equalities"]):
            for key in ("lhs", "rhs"):
                for e in _edits(eq[key]):
                    m = json.loads(json.dumps(d))
                    m["goal"]["equalities"][i][key] = e
                    o = check_certificate(m)
                    assert o.status in (REFUSED, NOT_RECHECKED), o.line()
                    counts[o.status] += 1
        for i, r in enumerate(d["goal"]["for_all"]):
            for key in ("from", "to"):
                if isinstance(r[key], str):
                    for e in _edits(r[key]):
                        m = json.loads(json.dumps(d))
                        m["goal"]["for_all"][i][key] = e
                        counts[check_certificate(m).status] += 1
    total = sum(counts.values())
    print(f"\n{total} mutants of for-every goals: {dict(counts)}")
    # a goal edited at a number or sign is false at its first values far more often than not
    assert counts[REFUSED] > counts[NOT_RECHECKED]
    assert total >= 500, total
