"""The independent checker's proof of the for-every certificates (`pieces` data, methods
`pieces` and `wz`; `cert_pieces`, `cert_wz`): every such file of the texts re-checked, and
its tampered copies (`_mutants.mutants`: numbers, signs, swapped sides, an edited goal, the
WZ certificates `R`, the range ends) refused whenever the tampered goal is false; never
re-checked then."""

import collections
import glob
import json
import os
import random
import sys
from fractions import Fraction

import pytest

from _casteljau_oracle import cert_hyper
from _casteljau_oracle.cert_check import NOT_RECHECKED, RECHECKED, REFUSED, check_certificate
from _casteljau_oracle.cert_eval import evaluate
from _mutants import mutants

pytest.importorskip("sympy")

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "..", "..", "tests", "certificates", "texts")
#: Mutants checked per file (a deterministic sample), and all those of a certificate `R`.
PER_FILE = 5


def _docs():
    docs = [json.load(open(f, encoding="utf-8")) for f in sorted(glob.glob(os.path.join(DATA, "*.json")))]
    # the proofs citing lemmas and the inductions are not proved here (docs/certificates.md)
    # an inequality's goal (`>=`) has its own test: test_cert_nonneg.py
    return [d for d in docs if "pieces" in d and d["check"] == "kernel" and not _resting(d) and d["goal"]["relation"] == "="]


def _resting(doc):
    return bool(doc.get("lemmas")) or "induction" in doc["pieces"]


def _false_somewhere(doc):
    """Whether the goal is false (or undefined) at a point of its first 7 values of each open
    range, three real values and generic control points: evaluated exactly, apart from the
    checker under test."""
    saved = cert_hyper.OPEN_VALUES
    cert_hyper.OPEN_VALUES = 7
    try:
        reals, ranges, sides, polygon, net = cert_hyper._read(doc)
        for ints in cert_hyper._cases(ranges):
            objects = cert_hyper._control_points(polygon, net, ints)
            for values in ((Fraction(1, 3), Fraction(5, 7), Fraction(-2, 9)),):
                env = dict(ints)
                env.update(zip(reals, values * 2))
                for lhs, rhs in sides:
                    if evaluate(lhs, env, objects) != evaluate(rhs, env, objects):
                        return True
        return False
    except Exception:  # a malformed or undefined goal counts as false
        return True
    finally:
        cert_hyper.OPEN_VALUES = saved


def test_every_pieces_and_wz_certificate_is_proved():
    docs = _docs()
    assert len(docs) == 26, len(docs)
    methods = collections.Counter(d["method"] for d in docs)
    assert methods == {"pieces": 21, "wz": 5}, methods
    for d in docs:
        o = check_certificate(d)
        assert o.status == RECHECKED and o.detail.startswith("proved for every value"), o.line()


def test_without_sympy_they_are_not_re_checked(monkeypatch):
    d = next(d for d in _docs() if d["id"] == "000-partition-of-unity")
    monkeypatch.setitem(sys.modules, "sympy", None)
    o = check_certificate(d)
    assert o.status == NOT_RECHECKED and "needs SymPy" in o.detail, o.line()


def test_a_wrong_wz_certificate_is_refused_not_replaced():
    d = next(d for d in _docs() if d["id"] == "000-partition-of-unity")
    d["pieces"]["certificates"][0] = "-(1 - t)*i/(n + 2 - i)"
    o = check_certificate(d)
    assert o.status == REFUSED and "WZ" in o.detail, o.line()


def test_a_goal_false_beyond_its_first_values_is_refused():
    # true for n = 0..4, false from n = 5 on: the first values pass, the proof must refuse
    d = next(d for d in _docs() if d["id"] == "000-basis-recursion")
    d["goal"]["equalities"][0]["rhs"] = "(1 - t)*B(i, n - 1, t) + t*B(i - 1, n - 1, t) + C(n - 1, 4)*C(4, n - 1)*B(i, n, t)"
    assert cert_hyper.OPEN_VALUES <= 4
    o = check_certificate(d)
    assert o.status == REFUSED, o.line()


def test_a_goal_undefined_beyond_its_first_values_is_refused():
    # SymPy would cancel (n - 10)/(n - 10) to 1: the goal divides by zero at n = 10
    d = next(d for d in _docs() if d["id"] == "000-basis-recursion")
    d["goal"]["equalities"][0]["rhs"] += " + (n - 10)/(n - 10) - 1"
    o = check_certificate(d)
    assert o.status == REFUSED and "division by zero" in o.detail and "n = 10" in o.detail, o.line()


def test_tampered_pieces_and_wz_certificates():
    counts = collections.Counter()
    for doc in _docs():
        ms = mutants(doc)
        cert = [m for m in ms if m[0] == "certificate"]
        rest = [m for m in ms if m[0] != "certificate"]
        rest = random.Random(doc["id"]).sample(rest, min(PER_FILE, len(rest)))
        for kind, where, make in cert + rest:
            mutant = make()
            o = check_certificate(mutant)
            false = _false_somewhere(mutant)
            counts[kind, "false" if false else "true", o.status] += 1
            if false:
                assert o.status == REFUSED, (doc["id"], kind, where, o.line())
            if kind == "certificate":
                # a wrong R is refused even where the goal stays true (not replaced by another)
                assert o.status == REFUSED, (doc["id"], kind, where, o.line())
    total = sum(counts.values())
    print(f"\n{total} mutants of pieces/wz files: " + ", ".join(f"{k} ({t}) {s}: {n}" for (k, t, s), n in sorted(counts.items())))
    assert total >= 150, total
