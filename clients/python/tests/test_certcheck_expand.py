"""Method `expansion` (docs/certificates.md): the checker expands both sides itself with its
own Fraction polynomials; a true goal with any representation of its sides is re-checked, a
false goal is refused even when its data is made consistent with it, and a goal edited while
its data is kept is refused."""

import copy
import json
import os

from _casteljau_oracle.cert_check import RECHECKED, REFUSED, check_certificate

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "..", "..", "tests", "certificates", "texts")


def _load(name):
    with open(os.path.join(DATA, name + ".json"), encoding="utf-8") as f:
        return json.load(f)


def _cert(lhs, rhs, vars_, entries):
    return {
        "format": "casteljau-certificate", "version": 1, "id": "x", "verdict": "proved",
        "method": "expansion", "rests_on": [], "range": None, "summary": "", "check": "kernel",
        "goal": {"relation": "=", "symbols": [{"name": v, "sort": "real"} for v in vars_],
                 "equalities": [{"ints": {}, "lhs": lhs, "rhs": rhs}]},
        "expansion": {"equalities": [{"vars": vars_, "entries": entries}]},
    }


ONE = [["1", [0, 0]]]
SQUARE = [["1", [2, 0]], ["2", [1, 1]], ["1", [0, 2]]]  # x^2 + 2xy + y^2


def test_a_hand_written_expansion_is_re_checked_in_any_representation():
    entry = {"lhs": {"num": SQUARE, "den": ONE}, "rhs": {"num": SQUARE, "den": ONE}}
    assert check_certificate(_cert("(x + y)^2", "x^2 + 2*x*y + y^2", ["x", "y"], [entry])).status == RECHECKED
    # the same rational function written over the denominator 2: still that side
    doubled = [[str(2 * int(c)), e] for c, e in SQUARE]
    entry = {"lhs": {"num": doubled, "den": [["2", [0, 0]]]}, "rhs": {"num": SQUARE, "den": ONE}}
    assert check_certificate(_cert("(x + y)^2", "x^2 + 2*x*y + y^2", ["x", "y"], [entry])).status == RECHECKED
    # a quotient: x^2/(x*y) = x/y
    entry = {"lhs": {"num": [["1", [2, 0]]], "den": [["1", [1, 1]]]}, "rhs": {"num": [["1", [1, 0]]], "den": [["1", [0, 1]]]}}
    assert check_certificate(_cert("x^2/(x*y)", "x/y", ["x", "y"], [entry])).status == RECHECKED


def test_a_false_goal_is_refused_even_with_data_that_matches_it():
    wrong = [["1", [2, 0]], ["1", [0, 2]]]
    entry = {"lhs": {"num": SQUARE, "den": ONE}, "rhs": {"num": wrong, "den": ONE}}
    o = check_certificate(_cert("(x + y)^2", "x^2 + y^2", ["x", "y"], [entry]))
    assert o.status == REFUSED and "not the zero rational function" in o.detail, o.line()
    entry = {"lhs": {"num": SQUARE, "den": ONE}, "rhs": {"num": SQUARE, "den": [["0", [0, 0]]]}}
    o = check_certificate(_cert("(x + y)^2", "x^2 + 2*x*y + y^2", ["x", "y"], [entry]))
    assert o.status == REFUSED, o.line()
    entry = {"lhs": {"num": SQUARE, "den": ONE}, "rhs": {"num": SQUARE + [["1", [2, 0]]], "den": ONE}}
    o = check_certificate(_cert("(x + y)^2", "x^2 + 2*x*y + y^2", ["x", "y"], [entry]))
    assert o.status == REFUSED and "listed twice" in o.detail, o.line()


def test_the_texts_expansions_are_re_checked_and_edits_refused():
    for name in ("004-13", "004-plane-delta-zero", "001-classification-nondegenerate"):
        doc = _load(name)
        assert doc["method"] == "expansion" and check_certificate(doc).status == RECHECKED, name
        edited = copy.deepcopy(doc)
        eq = edited["goal"]["equalities"][0]
        eq["lhs"] = f"({eq['lhs']})*2"
        # doubled, 004-plane-delta-zero's side (0, 0) is still the zero vector: still true
        still_true = name == "004-plane-delta-zero"
        assert check_certificate(edited).status == (RECHECKED if still_true else REFUSED), name
        # the data of one side replaced by another polynomial
        changed = copy.deepcopy(doc)
        x = changed["expansion"]["equalities"][0]
        x["entries"][0]["lhs"]["num"] = [["12345/7", [0] * len(x["vars"])]]
        assert check_certificate(changed).status == REFUSED, name
        # a variable missing from vars
        dropped = copy.deepcopy(doc)
        x = dropped["expansion"]["equalities"][0]
        x["vars"] = x["vars"][:-1]
        assert check_certificate(dropped).status == REFUSED, name
