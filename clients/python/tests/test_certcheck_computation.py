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
