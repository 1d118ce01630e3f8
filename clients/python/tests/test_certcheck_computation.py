"""Method `computation` (docs/certificates.md): the conic types re-derived here from the
listed inputs by the documented rules; a wrong type, coefficients that are not the equation's,
or a computation missing from rests_on are refused."""

import copy

from _casteljau_oracle.cert_check import RECHECKED, REFUSED, check_certificate
from _casteljau_oracle.cert_computation import implicit_kind, weights_kind
from fractions import Fraction as F


def _cert(fact, rests):
    return {
        "format": "casteljau-certificate", "version": 1, "id": "c", "verdict": "proved",
        "method": "computation", "rests_on": rests, "range": None, "summary": "", "check": "kernel",
        "computation": {"facts": [fact]},
    }


CIRCLE = {"computation": "ImplicitConic::kind", "lhs": "x^2 + y^2", "rhs": "1",
          "coefficients": ["1", "0", "1", "0", "0", "-1"], "kind": "ellipse"}
ARC = {"computation": "classify_conic", "points": [["1", "0"], ["1", "1"], ["0", "1"]],
       "weights": ["1", "1", "2"], "kind": "ellipse"}


def test_the_rules():
    assert implicit_kind(F(1), F(0), F(1), F(0), F(0), F(-1)) == "ellipse"
    assert implicit_kind(F(1), F(0), F(1), F(0), F(0), F(1)) == "imaginary ellipse (no real points)"
    assert implicit_kind(F(1), F(0), F(-1), F(0), F(0), F(-1)) == "hyperbola"
    assert implicit_kind(F(1), F(0), F(0), F(0), F(-1), F(0)) == "parabola"
    assert implicit_kind(F(1), F(0), F(-1), F(0), F(0), F(0)) == "degenerate"
    assert weights_kind([[F(0)] * 2, [F(1), F(0)], [F(0), F(1)]], [F(1), F(1), F(1)]) == "parabola"
    assert weights_kind([[F(0)] * 2, [F(1), F(1)], [F(2), F(2)]], [F(1), F(3), F(1)]) == "degenerate (collinear control points)"
    assert weights_kind([[F(0)] * 2, [F(1), F(0)], [F(0), F(1)]], [F(-1), F(1), F(1)]) == "hyperbola"


def test_conic_facts_are_re_derived_and_tampering_refused():
    assert check_certificate(_cert(CIRCLE, ["ImplicitConic::kind"])).status == RECHECKED
    assert check_certificate(_cert(ARC, ["classify_conic"])).status == RECHECKED
    for fact, rests in ((CIRCLE, ["ImplicitConic::kind"]), (ARC, ["classify_conic"])):
        wrong = dict(fact, kind="hyperbola")
        assert check_certificate(_cert(wrong, rests)).status == REFUSED
        assert check_certificate(_cert(fact, [])).status == REFUSED
    edited = dict(CIRCLE, rhs="2")  # the coefficients kept: F is now -2
    o = check_certificate(_cert(edited, ["ImplicitConic::kind"]))
    assert o.status == REFUSED and "coefficients" in o.detail, o.line()
    cubic = dict(CIRCLE, lhs="x^3 + y^2")
    assert check_certificate(_cert(cubic, ["ImplicitConic::kind"])).status == REFUSED
    other = copy.deepcopy(CIRCLE)
    other["lhs"] = "x^2 + z^2"
    assert check_certificate(_cert(other, ["ImplicitConic::kind"])).status == REFUSED


TEXTS = __import__("os").path.join(__import__("os").path.dirname(__file__), "..", "..", "..", "tests", "certificates", "texts")


def _text(name):
    import json
    import os

    with open(os.path.join(TEXTS, name + ".json"), encoding="utf-8") as f:
        return json.load(f)


def test_a_square_root_is_an_exact_irrational_and_keeps_its_sign():
    doc = _text("001-ex2-weights")
    assert check_certificate(doc).status == RECHECKED
    for radicand in ("4", "1", "0", "8"):  # √d rational, or d not square-free
        bad = copy.deepcopy(doc)
        bad["computation"]["facts"][0]["points"][0][1]["radicand"] = radicand
        o = check_certificate(bad)
        assert o.status == REFUSED and "radicand" in o.detail, o.line()
    # the conic's points collinear: 2√2 written on both sides of the axis as the same point
    bad = copy.deepcopy(doc)
    pts = bad["computation"]["facts"][0]["points"]
    pts[1] = ["3", {"rational": "0", "irrational": "0", "radicand": "2"}]
    assert check_certificate(bad).status == REFUSED
    pts[1] = ["3", {"rational": "0", "irrational": "1", "radicand": "2"}]  # (3, √2): collinear
    o = check_certificate(bad)
    assert o.status == REFUSED and "collinear" in o.detail, o.line()


def test_a_fit_is_re_derived_from_its_curve():
    for name in ("004-plane-fit-circle", "004-space-fit-example"):
        doc = _text(name)
        assert check_certificate(doc).status == RECHECKED
        fact = doc["computation"]["facts"][0]
        for key, value, said in (("k", "1", "normal equations"), ("l", "0", "normal equations"), ("delta2", "1", "delta2")):
            bad = copy.deepcopy(doc)
            bad["computation"]["facts"][0][key] = value
            o = check_certificate(bad)
            assert o.status == REFUSED and said in o.detail, (name, key, o.line())
        # the same numbers claimed for another curve: its data differ
        bad = copy.deepcopy(doc)
        bad["computation"]["facts"][0]["points"][0][0] = str(F(fact["points"][0][0]) + 1)
        o = check_certificate(bad)
        assert o.status == REFUSED and "data" in o.detail, o.line()
        # a consistent system that is not the curve's (right side edited with the data kept)
        bad = copy.deepcopy(doc)
        bad["computation"]["facts"][0]["normal_equations"]["rhs"][0] = "7"
        assert check_certificate(bad).status == REFUSED


def test_bounded_evidence_is_re_derived_and_stays_verified():
    doc = _text("000-thm-1.2")
    o = check_certificate(doc)
    assert o.status == RECHECKED and o.detail.startswith("verified") and "not a proof" in o.detail, o.line()
    bad = copy.deepcopy(doc)
    bad["convergence"]["curves"][0]["distances"][3] = "1/1000"
    o = check_certificate(bad)
    assert o.status == REFUSED and "r = 3" in o.detail, o.line()
    bad = copy.deepcopy(doc)
    bad["verdict"] = "proved"
    assert check_certificate(bad).status == REFUSED


def test_counterexamples_of_implications_and_on_control_points():
    for name in ("004-8", "004-10"):
        doc = _text(name)
        assert check_certificate(doc).status == RECHECKED
        bad = copy.deepcopy(doc)
        bad["fails"]["at"]["k"] = "1"  # the premise no longer holds there
        o = check_certificate(bad)
        assert o.status == REFUSED and "premise" in o.detail, o.line()
        bad = copy.deepcopy(doc)
        del bad["fails"]["premise"]
        assert check_certificate(bad).status == REFUSED
    doc = _text("003-two-stage")
    assert check_certificate(doc).status == RECHECKED
    for polygon in (0, 1, 3, 4, 5, None):
        bad = copy.deepcopy(doc)
        bad["fails"]["polygon"] = polygon
        assert check_certificate(bad).status == REFUSED, polygon
