"""The independent checker's proofs citing lemmas and by induction (`cert_lemmas`,
`cert_links`): the texts' 12 such files, and their tampered copies (a lemma's goal edited, a
lemma's file missing or refused, an induction's base or step changed, swapped sides)
refused or not re-checked, never re-checked."""

import copy
import glob
import json
import os

import pytest

from _casteljau_oracle.cert_check import NOT_RECHECKED, RECHECKED, REFUSED, check_certificate, check_path

pytest.importorskip("sympy")

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "..", "..", "tests", "certificates", "texts")

#: The files proved here: the two inductions and the 10 proofs citing lemmas.
PROVED = {
    "000-9-intermediate", "000-delta-closed-form", "000-1", "000-delta", "000-derivative-proof",
    "000-endpoints-object", "000-lemma-1.3-b00", "000-lemma-1.3-c1", "000-tangent-t0-point",
    "000-derivative-k-object", "000-lemma-1.3-c2", "000-lemma-1.3-proof",
}


def _by_id():
    docs = [json.load(open(f, encoding="utf-8")) for f in sorted(glob.glob(os.path.join(DATA, "*.json")))]
    return {d["id"]: d for d in docs}


def _resting(d):
    return "pieces" in d and (bool(d.get("lemmas")) or "induction" in d["pieces"])


def _run(tmp_path, *docs):
    for f in tmp_path.iterdir():
        f.unlink()
    for d in docs:
        (tmp_path / (d["id"] + ".json")).write_text(json.dumps(d), encoding="utf-8")
    return {o.id: o for o in check_path(str(tmp_path))}


def test_the_texts_resting_files(tmp_path):
    by_id = _by_id()
    resting = {i for i, d in by_id.items() if _resting(d)}
    assert resting == PROVED
    got = {o.id: o for o in check_path(DATA)}
    for cid in PROVED:
        assert got[cid].status == RECHECKED, got[cid].line()
    for cid in ("000-9-intermediate", "000-delta-closed-form"):
        assert got[cid].detail.startswith("by induction on "), got[cid].line()
        assert "the base" in got[cid].detail and "the step" in got[cid].detail, got[cid].line()
    for cid in PROVED - {"000-9-intermediate", "000-delta-closed-form"}:
        assert "its lemmas" in got[cid].detail and "re-checked here in their own files" in got[cid].detail, got[cid].line()
    # the file's WZ certificate R, naming the unit polygon's index __j, used as given
    assert "WZ inductions ((__j - __j*t - r + r*t)/" in got["000-lemma-1.3-proof"].detail
    proved = [o for o in got.values() if o.verdict in ("proved", "proved_in_range")]
    assert sum(o.status == RECHECKED for o in got.values()) == 155
    assert (sum(o.status == RECHECKED for o in proved), len(proved)) == (150, 150)
    assert not [o for o in got.values() if o.status == REFUSED]


def test_alone_an_induction_is_re_checked_a_proof_citing_lemmas_is_not():
    by_id = _by_id()
    assert check_certificate(by_id["000-9-intermediate"]).status == RECHECKED
    o = check_certificate(by_id["000-1"])
    assert o.status == NOT_RECHECKED and o.assumes == ["000-9-intermediate"], o.line()
    assert o.detail.endswith("re-checked only with its lemmas' files"), o.line()


def test_a_lemma_file_missing_or_not_re_checked(tmp_path):
    by_id = _by_id()
    cert, lemma = by_id["000-derivative-proof"], by_id["000-9-intermediate"]
    o = _run(tmp_path, cert, lemma)["000-derivative-proof"]
    assert o.status == NOT_RECHECKED and "rests on lemma 000-delta-closed-form, whose file was not given" in o.detail, o.line()
    # the lemma's file given, but its induction variable one this checker cannot use
    other = copy.deepcopy(by_id["000-delta-closed-form"])
    other["pieces"]["induction"] = "j"
    got = _run(tmp_path, cert, lemma, other)
    assert got["000-delta-closed-form"].status == NOT_RECHECKED, got["000-delta-closed-form"].line()
    o = got["000-derivative-proof"]
    assert o.status == NOT_RECHECKED and "whose file is not re-checked here" in o.detail, o.line()


def test_a_lemma_goal_edited_is_refused(tmp_path):
    by_id = _by_id()
    cert, lemma = by_id["000-1"], by_id["000-9-intermediate"]
    for where, new in (("rhs", "sum(j, 0, r, b[i + j]*B(j, r, t)) + 1/1000"), ("lhs", "b(i + 1, r, t)")):
        other = copy.deepcopy(cert)
        other["lemmas"][0]["goal"]["equalities"][0][where] = new
        # the goal listed is not the lemma file's: refused by the references
        o = _run(tmp_path, other, lemma)["000-1"]
        assert o.status == REFUSED and "states another goal" in o.detail, o.line()
        # the lemma's file edited the same way: the lemma is refused, so is the proof on it
        bad = copy.deepcopy(lemma)
        bad["goal"]["equalities"][0][where] = new
        got = _run(tmp_path, other, bad)
        if where == "rhs":
            assert got["000-9-intermediate"].status == REFUSED, got["000-9-intermediate"].line()
            assert got["000-1"].status == REFUSED and "which is refused" in got["000-1"].detail, got["000-1"].line()
        else:
            # an object of other arguments than symbols: not a goal this checker proves or
            # applies (the edit is false, but neither file is accepted)
            assert got["000-9-intermediate"].status == NOT_RECHECKED, got["000-9-intermediate"].line()
            assert got["000-1"].status == NOT_RECHECKED, got["000-1"].line()
    # swapped sides in the goal listed
    other = copy.deepcopy(cert)
    eq = other["lemmas"][0]["goal"]["equalities"][0]
    eq["lhs"], eq["rhs"] = eq["rhs"], eq["lhs"]
    o = _run(tmp_path, other, lemma)["000-1"]
    assert o.status == REFUSED and "states another goal" in o.detail, o.line()


def test_a_lemma_applied_outside_its_ranges_is_not_accepted(tmp_path):
    by_id = _by_id()
    cert, lemma = copy.deepcopy(by_id["000-1"]), copy.deepcopy(by_id["000-9-intermediate"])
    # the lemma narrowed to i = 0..=n - r - 1 (its file and the goal listed alike): 000-1
    # applies it at i + 1 = n - r + 1, outside; the lemma itself still holds (and is proved)
    lemma["goal"]["for_all"][2]["to"] = "n - r - 1"
    lemma["goal"]["for_all"][0]["from"] = "1"
    lemma["goal"]["for_all"][1]["to"] = "n - 1"
    cert["lemmas"][0]["goal"] = copy.deepcopy(lemma["goal"])
    got = _run(tmp_path, cert, lemma)
    assert got["000-9-intermediate"].status == RECHECKED, got["000-9-intermediate"].line()
    o = got["000-1"]
    assert o.status == NOT_RECHECKED and "not shown within its ranges" in o.detail, o.line()


@pytest.mark.parametrize(
    "cid, field, old, new",
    [
        # the base changed: false at r = 0 only (C(0, r) is 1 there, else 0)
        ("000-9-intermediate", "rhs", "B(j, r, t))", "B(j, r, t)) + C(0, r)*b[i]"),
        # the step changed: the base k = 0 still holds, the step does not
        ("000-delta-closed-form", "rhs", "(-1)^(k - i)", "(-2)^(k - i)"),
        ("000-9-intermediate", "rhs", "B(j, r, t)", "B(j, r + 1, t)"),
    ],
)
def test_an_induction_changed_is_refused(cid, field, old, new):
    d = copy.deepcopy(_by_id()[cid])
    eq = d["goal"]["equalities"][0]
    assert old in eq[field]
    eq[field] = eq[field].replace(old, new)
    o = check_certificate(d)
    assert o.status == REFUSED, o.line()


def test_an_induction_false_beyond_its_first_values_is_not_accepted():
    # false from k = 5 on: the first values pass; the step's terms do not cancel where
    # k ≥ 5, which the prover reports undecided (a sum compared term by term), not refuted
    d = copy.deepcopy(_by_id()["000-delta-closed-form"])
    eq = d["goal"]["equalities"][0]
    eq["rhs"] = eq["rhs"].replace("b[j + i])", "b[j + i]) + C(k, 5)*b[j]")
    o = check_certificate(d)
    assert o.status == NOT_RECHECKED and "k - 5 >= 0" in o.detail, o.line()


def test_an_induction_with_swapped_sides_or_another_variable_is_not_accepted():
    for cid in ("000-9-intermediate", "000-delta-closed-form"):
        d = copy.deepcopy(_by_id()[cid])
        eq = d["goal"]["equalities"][0]
        eq["lhs"], eq["rhs"] = eq["rhs"], eq["lhs"]
        assert check_certificate(d).status != RECHECKED
        d = copy.deepcopy(_by_id()[cid])
        d["pieces"]["induction"] = "n"
        assert check_certificate(d).status != RECHECKED


@pytest.mark.parametrize("cid", sorted(PROVED - {"000-9-intermediate", "000-delta-closed-form"}))
def test_a_proof_citing_lemmas_edited_is_refused(tmp_path, cid):
    by_id = _by_id()
    doc = copy.deepcopy(by_id[cid])
    lemmas = [by_id[lid] for lid, in ((r["id"],) for r in doc["lemmas"])]
    eq = doc["goal"]["equalities"][-1]
    eq["rhs"] = f"({eq['rhs']}) + 1/1000" if not eq["rhs"].startswith("(") or "," not in eq["rhs"] else eq["rhs"].replace(")", ") + 1/1000", 1)
    got = _run(tmp_path, doc, *lemmas)
    assert got[cid].status == REFUSED, got[cid].line()
    # swapped sides of the last equality (of a chain, the chain broken)
    doc = copy.deepcopy(by_id[cid])
    eq = doc["goal"]["equalities"][-1]
    eq["lhs"], eq["rhs"] = eq["rhs"], eq["lhs"]
    got = _run(tmp_path, doc, *lemmas)
    if len(doc["goal"]["equalities"]) > 1:
        assert got[cid].status == REFUSED, got[cid].line()
    else:
        # a true equality read the other way: proved, as it holds
        assert got[cid].status in (RECHECKED, NOT_RECHECKED), got[cid].line()
