"""The independent checker on the goals in Q(√d) (docs/certificates.md, "Square roots"): the
five text-001 example-2 files re-checked with SymPy, and their tampered copies refused: a
coefficient of √2 or the radicand of a value, a sample point, a value, the degree bound, the
goal's `sqrt(2)` made `sqrt(8)` (not square-free), `sqrt(t)`, or `sqrt(3)` in one place."""

import copy
import json
import os

import pytest

from _casteljau_oracle.cert_check import RECHECKED, REFUSED, check_certificate

pytest.importorskip("sympy")

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "tests", "certificates", "texts")
FILES = ["001-ex2", "001-ex2-hyperbola", "001-proj-ex2-p", "001-proj-ex2-x", "001-proj-ex2-hyperbola"]


def _doc(name):
    with open(os.path.join(DATA, name + ".json"), encoding="utf-8") as f:
        return json.load(f)


def _refused(doc, reason):
    o = check_certificate(doc)
    assert o.status == REFUSED, o.line()
    assert reason in o.detail, o.line()


@pytest.mark.parametrize("name", FILES)
def test_a_goal_in_q_sqrt_2_is_re_checked(name):
    o = check_certificate(_doc(name))
    assert o.status == RECHECKED, o.line()
    assert "in Q(√2)" in o.detail, o.line()


def _irrational_value(doc):
    rows = doc["sampling"]["equalities"][0]["values"]
    for k, row in enumerate(rows):
        for j, x in enumerate(row["lhs"]):
            if isinstance(x, dict):
                return k, j
    return None


@pytest.mark.parametrize("name", FILES)
def test_its_mutants_are_refused(name):
    doc = _doc(name)
    eq = doc["sampling"]["equalities"][0]

    def edit(f):
        m = copy.deepcopy(doc)
        f(m)
        return m

    at = _irrational_value(doc)
    if at is not None:
        k, j = at

        def value(m, side):
            return m["sampling"]["equalities"][0]["values"][k][side][j]

        b = value(doc, "lhs")["irrational"]
        _refused(edit(lambda m: value(m, "lhs").update(irrational=b + "1")), "lhs is")
        _refused(edit(lambda m: value(m, "rhs").update(radicand="3")), "the goal is in Q(√2)")
        _refused(edit(lambda m: value(m, "lhs").update(rational="1/0")), "not an exact rational")
    first = eq["values"][0]["lhs"][0]
    assert isinstance(first, str)
    _refused(edit(lambda m: m["sampling"]["equalities"][0]["values"][0]["lhs"].__setitem__(0, "1/1000")), "lhs is")
    _refused(edit(lambda m: m["sampling"]["equalities"][0]["params"][0]["points"].__setitem__(0, "1/1000")), "grid point")
    _refused(edit(lambda m: m["sampling"]["equalities"][0]["params"][0].update(degree=eq["params"][0]["degree"] - 1)), "degree")
    goal = doc["goal"]["equalities"][0]
    side = "lhs" if "sqrt(2)" in goal["lhs"] else "rhs"
    text = goal[side]
    _refused(edit(lambda m: m["goal"]["equalities"][0].update({side: text.replace("sqrt(2)", "sqrt(8)")})), "not square-free")
    _refused(edit(lambda m: m["goal"]["equalities"][0].update({side: text.replace("sqrt(2)", "sqrt(t)")})), "not an integer d >= 2")
    mixed = edit(lambda m: m["goal"]["equalities"][0].update({side: text.replace("sqrt(2)", "sqrt(3)", 1)}))
    other = goal["rhs" if side == "lhs" else "lhs"]
    if text.count("sqrt(2)") > 1 or "sqrt(2)" in other:
        _refused(mixed, "mixes sqrt(")
    else:
        assert check_certificate(mixed).status == REFUSED
    # The sides swapped: the same equality, accepted exactly when the degree bounds agree.
    swapped = edit(lambda m: m["goal"]["equalities"][0].update(lhs=goal["rhs"], rhs=goal["lhs"]))
    p = eq["params"][0]
    want = RECHECKED if p["lhs_degree"] == p["rhs_degree"] else REFUSED
    assert check_certificate(swapped).status == want


def test_a_value_in_q_sqrt_d_for_a_rational_goal_is_refused():
    doc = _doc("001-ex3")
    m = copy.deepcopy(doc)
    m["sampling"]["equalities"][0]["values"][0]["lhs"][0] = {"rational": "-1", "irrational": "1", "radicand": "2"}
    assert check_certificate(m).status == REFUSED
