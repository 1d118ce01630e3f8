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
    # an inequality's goal (`>=`) has its own test: test_cert_nonneg.py
    return [d for d in docs if "pieces" in d and d["goal"]["relation"] == "="]


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


def _rests(d):
    """A proof citing lemmas or by induction (its objects are not evaluated here)."""
    return bool(d.get("lemmas")) or "induction" in d["pieces"]


def test_every_pieces_certificate_holds_at_its_first_values():
    docs = [d for d in _docs() if not _rests(d)]
    assert len(docs) >= 26
    for d in docs:
        o = check_certificate(d)
        assert o.status == NOT_RECHECKED and "needs SymPy" in o.detail, o.line()
        assert "the goal holds at its first values" in o.detail, o.line()


def test_lemma_references_are_checked_among_the_files_given(tmp_path):
    from _casteljau_oracle.cert_check import check_path

    resting = [d for d in _docs() if _rests(d)]
    assert len(resting) == 12
    for d in resting:
        o = check_certificate(d)
        assert o.status == NOT_RECHECKED and "resting on" in o.detail, o.line()
    by_id = {d["id"]: d for d in _docs()}

    def run(*docs):
        for f in tmp_path.iterdir():
            f.unlink()
        for d in docs:
            (tmp_path / (d["id"] + ".json")).write_text(json.dumps(d), encoding="utf-8")
        return {o.id: o for o in check_path(str(tmp_path))}

    cert, lemma = by_id["000-1"], by_id["000-9-intermediate"]
    o = run(cert, lemma)["000-1"]
    # without SymPy the induction 000-9-intermediate is not re-checked: nor is what rests on it
    assert o.status == NOT_RECHECKED and "whose file is not re-checked here" in o.detail, o.line()
    o = run(cert)["000-1"]
    assert o.status == NOT_RECHECKED and "rests on lemma 000-9-intermediate, whose file was not given" in o.detail
    other = json.loads(json.dumps(cert))
    other["lemmas"][0]["goal"]["for_all"][1]["to"] = "n + 1"
    o = run(other, lemma)["000-1"]
    assert o.status == REFUSED and "states another goal" in o.detail, o.line()
    # a cycle: the induction also cites the proof citing it
    cyclic = json.loads(json.dumps(lemma))
    cyclic["lemmas"] = [{"id": "000-1", "goal": cert["goal"]}]
    got = run(cert, cyclic)
    for cid in ("000-1", "000-9-intermediate"):
        assert got[cid].status == REFUSED and "cycle" in got[cid].detail, got[cid].line()
    twice = json.loads(json.dumps(cert))
    twice["lemmas"].append(twice["lemmas"][0])
    assert check_certificate(twice).status == REFUSED


def test_an_edited_goal_with_its_data_kept_is_refused():
    d = next(d for d in _docs() if d["id"] == "000-partition-of-unity")
    d["goal"]["equalities"][0]["rhs"] = "2"
    o = check_certificate(d)
    assert o.status == REFUSED and "the sides are" in o.detail, o.line()


def test_tampered_goals_are_refused_or_true_at_their_first_values():
    counts = collections.Counter()
    for d in (d for d in _docs() if not _rests(d)):
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
