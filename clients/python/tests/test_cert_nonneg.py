"""The inequality `000-basis-nonneg` (a `>=` goal for every value with each live term's
nonnegativity obligation) and the facts `000-convex-hull` and `000-affine` that cite it and
`000-partition-of-unity` as lemmas, re-checked by this checker's own means; tampered copies are
refused (docs/certificates.md, "Inequalities for every value" and "Method `computation`")."""

import copy
import json
import os

import pytest

from _casteljau_oracle.cert_check import RECHECKED, REFUSED, check_certificate, check_path

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "..", "..", "tests", "certificates", "texts")
NONNEG, UNITY = "000-basis-nonneg", "000-partition-of-unity"


def _doc(cid):
    with open(os.path.join(DATA, cid + ".json"), encoding="utf-8") as f:
        return json.load(f)


def _with_lemmas(tmp_path, doc, nonneg=None):
    for f in tmp_path.iterdir():
        f.unlink()
    for d in (doc, nonneg or _doc(NONNEG), _doc(UNITY)):
        (tmp_path / (d["id"] + ".json")).write_text(json.dumps(d), encoding="utf-8")
    return {o.id: o for o in check_path(str(tmp_path))}[doc["id"]]


def _edit(doc, path, value):
    d = copy.deepcopy(doc)
    at = d
    for k in path[:-1]:
        at = at[k]
    if value is _DROP:
        del at[path[-1]]
    else:
        at[path[-1]] = value
    return d


_DROP = object()
_POWERS = ("pieces", "nonnegative", 0, "terms", 0, "powers")


def test_the_three_are_re_checked_here():
    pytest.importorskip("sympy")
    o = check_certificate(_doc(NONNEG))
    assert o.status == RECHECKED and "one piece covering the domain" in o.detail, o.line()
    for cid in ("000-convex-hull", "000-affine"):
        o = check_certificate(_doc(cid))
        assert o.status == RECHECKED, o.line()


def test_tampered_inequalities_are_refused():
    pytest.importorskip("sympy")
    doc = _doc(NONNEG)
    mutants = [
        ("flipped", _edit(doc, ("goal", "relation"), "<=")),
        ("widened to [0, 2]", _edit(doc, ("goal", "interval", "to"), "2")),
        ("widened to [-1, 1]", _edit(doc, ("goal", "interval", "from"), "-1")),
        ("right side 1", _edit(doc, ("goal", "inequality", "rhs"), "1")),
        ("a factorial dropped", _edit(doc, ("pieces", "nonnegative", 0, "terms", 0, "factorials", 2), _DROP)),
        ("an exponent lowered", _edit(doc, _POWERS + (1, "exponent"), "-i + n - 1")),
        ("a base changed", _edit(doc, _POWERS + (0, "factor"), "(t + 1)")),
        ("a reason changed", _edit(doc, _POWERS + (1, "why"), "bernstein_positive")),
        ("the region narrowed", _edit(doc, ("pieces", "nonnegative", 0, "region"), "n - 1 ≥ 0, i ≥ 0, -i + n ≥ 0")),
        ("the terms dropped", _edit(doc, ("pieces", "nonnegative", 0, "terms"), [])),
        ("a WZ certificate", _edit(doc, ("pieces", "certificates"), ["1"])),
    ]
    for p, power in enumerate(doc["pieces"]["nonnegative"][0]["terms"][0]["powers"]):
        for k, c in enumerate(power["bernstein"]):
            flipped = "-1" if c == "0" else "-" + c
            mutants.append(("a Bernstein coefficient's sign", _edit(doc, _POWERS + (p, "bernstein", k), flipped)))
    assert len(mutants) >= 15
    for label, m in mutants:
        o = check_certificate(m)
        assert o.status == REFUSED, (label, o.line())
    # On [0, 2]: B_0^1(2) = 1 − 2 < 0, found by exact evaluation.
    assert "< 0" in check_certificate(mutants[1][1]).detail


def test_tampered_lemma_facts_are_refused(tmp_path):
    pytest.importorskip("sympy")  # the lemma's own data is proved with it
    hull, affine = _doc("000-convex-hull"), _doc("000-affine")
    assert _with_lemmas(tmp_path, hull).status == RECHECKED
    assert _with_lemmas(tmp_path, affine).status == RECHECKED
    cases = []
    for doc in (hull, affine):
        last = len(doc["lemmas"]) - 1
        cases += [
            ("a lemma dropped", _edit(doc, ("lemmas", last), _DROP), None),
            ("the lemmas dropped", _edit(doc, ("lemmas",), _DROP), None),
            ("another sum lemma", _edit(doc, ("computation", "facts", 0, "sum_one"), "000-basis-recursion"), None),
            ("a negative degree", _edit(doc, ("computation", "facts", 0, "degrees", "from"), "-1"), None),
            ("rests_on emptied", _edit(doc, ("rests_on",), []), None),
            ("the cited sum edited", _edit(doc, ("lemmas", last, "goal", "equalities", 0, "rhs"), "2"), None),
        ]
    widened = _edit(hull, ("lemmas", 0, "goal", "interval", "to"), "2")
    cases.append(("the cited interval widened", widened, None))
    lemma = _edit(_doc(NONNEG), ("goal", "interval", "to"), "2")
    cases.append(("widened in both files", widened, lemma))
    lemma = _edit(_doc(NONNEG), _POWERS + (0, "bernstein", 1), "-1")
    cases.append(("the lemma's data tampered", hull, lemma))
    for label, m, nonneg in cases:
        o = _with_lemmas(tmp_path, m, nonneg)
        assert o.status == REFUSED, (label, o.line())
