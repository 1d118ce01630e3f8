"""The certificate checker's expression layer: the book grammar, exact evaluation with
Fraction, degree bounds, and the SymPy translation (those tests skip without SymPy)."""

import random
from fractions import Fraction as F

import pytest

from _casteljau_oracle.cert_degree import cleared_degree, degree
from _casteljau_oracle.cert_eval import Curve, EvalError, Pole, Surface, Unsupported, evaluate
from _casteljau_oracle.cert_expr import ParseError, parse, show


@pytest.mark.parametrize(
    "text, shown",
    [
        ("-(2t - 1)^2 + 1", "-(2*t - 1)^2 + 1"),
        ("4/3 B(1, 3, t)", "4/3*B(1, 3, t)"),
        ("3k/8 d0", "3*k/8*d0"),
        ("1/2t", "1/2*t"),
        ("-t^2", "-t^2"),
        ("t^-1", "t^(-1)"),
        ("2^3^2", "2^(3^2)"),
        ("(1-t)(1+t)", "(1 - t)*(1 + t)"),
        ("st", "s*t"),
        ("xy^2", "x*y^2"),
        ("n!", "n!"),
        ("(n-i)!", "(n - i)!"),
        ("sum(r, 0, n, C(n, r) b[r])", "sum(r, 0, n, C(n, r)*b[r])"),
        ("[a, b; c, d]", "[a, b; c, d]"),
        ("(x, y)", "(x, y)"),
        ("(x,)", "(x,)"),
        ("x_uv(u, v)", "x_uv(u, v)"),
        ("b''(t)", "b''(t)"),
        ("t(1 - t)", "t*(1 - t)"),
        ("2 − 3·t × 4", "2 - 3*t*4"),
        ("0.25", "1/4"),
    ],
)
def test_book_forms_parse_as_the_grammar_says(text, shown):
    assert show(parse(text, known=["d0"])) == shown


def test_the_certificate_grammar_is_strict():
    assert parse("ab*t0_x", strict=True) == ("mul", ("var", "ab"), ("var", "t0_x"))
    assert parse("b(t)", strict=True)[0] == "call"
    for bad in ("2t", "(1 - t)(1 + t)", "2 − t", "b[1]"):
        with pytest.raises(ParseError):
            parse(bad, strict=True)


def test_known_names_are_not_split_and_calls_are_calls():
    assert parse("ab", known=["ab"]) == ("var", "ab")
    assert parse("ab") == ("mul", ("var", "a"), ("var", "b"))
    assert parse("foo(t)")[0] == "call"
    assert parse("b(t)")[0] == "mul"  # an undeclared one-letter name before ( is a product
    assert parse("b(t)", known=["b"])[0] == "call"


@pytest.mark.parametrize(
    "bad",
    ["", "1 +", "(1", "1)", "B(1, 2)", "sum(1, 0, 2, t)", "C", "[]", "[1, 2; 3]", "t $ 2", "1..2", "f[]", 3],
)
def test_bad_expressions_are_parse_errors(bad):
    with pytest.raises(ParseError):
        parse(bad)


def test_random_text_is_parsed_or_refused_with_a_parse_error():
    rng = random.Random(43)
    alphabet = "tnkB C(),+-*/^![];0123 sum"
    for _ in range(3000):
        text = "".join(rng.choice(alphabet) for _ in range(rng.randint(1, 14)))
        try:
            e = parse(text)
        except ParseError:
            continue
        assert parse(show(e)) == e, text


def test_deep_nesting_is_refused_not_a_crash():
    with pytest.raises(ParseError):
        parse("(" * 2000 + "t" + ")" * 2000)
    with pytest.raises(ParseError):
        parse("t" * 30_000)
    with pytest.raises(ParseError):
        parse(" + ".join(["t"] * 5000))
    assert evaluate(parse(" + ".join(["t"] * 3000)), {"t": F(1, 3)}) == 1000


def test_exact_evaluation_keeps_the_conventions():
    ev = lambda s, **env: evaluate(parse(s), {k: F(v) for k, v in env.items()})  # noqa: E731
    assert ev("B(1, 3, t)", t=F(1, 3)) == F(4, 9)
    assert ev("B(4, 3, t)", t=F(1, 3)) == 0 and ev("B(-1, 3, t)", t=F(1, 3)) == 0
    assert ev("C(5, 2)") == 10 and ev("C(5, 6)") == 0 and ev("C(5, -1)") == 0
    assert ev("sum(k, 3, 2, 1)") == 0
    assert ev("sum(k, 0, n, C(n, k))", n=9) == 512
    assert ev("5!/3!") == 20
    assert ev("t^-2", t=F(2, 3)) == F(9, 4)
    assert ev("det([1, 2; 3, 4])") == -2
    assert ev("dot((1, 2), (3, 4))") == 11
    assert ev("comp((1, 2, 3), 2)") == 2
    assert ev("C(-2, 3)") == 0
    assert ev("__dB(1, 3, t, 1)", t=F(1, 3)) == 3 * (1 - 4 * F(1, 3) + 3 * F(1, 9))
    assert ev("__dpow(t, 3, 2)", t=F(1, 2)) == 3
    assert ev("__dpow(t, 2, 3)", t=F(1, 2)) == 0
    assert ev("__dpow(t, -1, 1)", t=F(1, 2)) == -4
    assert ev("sqrt(9/4)") == F(3, 2)
    with pytest.raises(Pole):
        ev("1/(t - 1)", t=1)
    with pytest.raises(Unsupported):
        ev("sqrt(2)")
    with pytest.raises(EvalError):
        ev("(-1)!")
    with pytest.raises(EvalError):
        ev("t^(1/2)", t=4)
    with pytest.raises(EvalError):
        ev("u", t=1)


def test_curves_are_evaluated_in_bernstein_form():
    b = Curve([[0, 0], ["4/3", "-4/3"], ["4/3", "4/3"], [0, 0]])
    at = lambda s, t: evaluate(parse(s, ["b"]), {"t": F(t)}, {"b": b})  # noqa: E731
    # 000-ex4: the points of (-u^2 + 1, -u^3 + u) on [-1, 1]
    for t in (F(0), F(1, 3), F(2, 3), F(1), F(5, 7)):
        u = 2 * t - 1
        assert at("b(t)", t) == (1 - u * u, u - u**3)
        assert at("b'(t)", t) == (-4 * u, 2 * (1 - 3 * u * u))
        assert at("b(0, 3, t)", t) == at("b(t)", t)
    x = Curve([[-1, 1], [0, -1], [1, 1]], [1, "1/2", 1])
    for t in (F(0), F(2, 7), F(1), F(-3)):
        px, py = evaluate(parse("x(t)", ["x"]), {"t": t}, {"x": x})
        assert 4 * px * px + 3 * py * py - 10 * py + 3 == 0  # 001 例3
    s = Surface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]])
    assert evaluate(parse("x_uv(u, v)", ["x"]), {"u": F(1, 2), "v": F(1, 3)}, {"x": s}) == (0, 0, 1)


def _random_tree(rng, depth):
    if depth == 0 or rng.random() < 0.25:
        return rng.choice([("var", "t"), ("var", "s"), ("num", F(rng.randint(0, 5), rng.randint(1, 3)))])
    kind = rng.choice(["add", "sub", "mul", "div", "pow", "neg", "B"])
    if kind == "neg":
        return ("neg", _random_tree(rng, depth - 1))
    if kind == "pow":
        return ("pow", _random_tree(rng, depth - 1), ("num", F(rng.randint(0, 3))))
    if kind == "B":
        n = rng.randint(0, 4)
        i = rng.randint(-1, n + 1)
        ix = ("num", F(i)) if i >= 0 else ("neg", ("num", F(1)))
        return ("call", "B", (ix, ("num", F(n)), _random_tree(rng, depth - 1)))
    return (kind, _random_tree(rng, depth - 1), _random_tree(rng, depth - 1))


def test_degree_bounds_cover_the_true_degree_and_show_round_trips():
    sympy = pytest.importorskip("sympy")
    from _casteljau_oracle.cert_sympy import to_sympy

    rng = random.Random(7)
    t = sympy.Symbol("t")
    checked = 0
    for _ in range(300):
        e = _random_tree(rng, 4)
        assert show(parse(show(e))) == show(e)
        v = sympy.cancel(sympy.together(to_sympy(e)))
        if v.has(sympy.zoo, sympy.nan):
            continue
        num, den = sympy.fraction(v)
        p, q = degree(e, "t")
        assert sympy.degree(num, t) <= p and sympy.degree(den, t) <= q, show(e)
        # exact evaluation agrees with SymPy wherever both are defined
        for tv, sv in ((F(1, 3), F(2)), (F(-5, 2), F(1, 7))):
            try:
                got = evaluate(e, {"t": tv, "s": sv})
            except Pole:
                continue
            want = v.subs({t: sympy.Rational(tv.numerator, tv.denominator), sympy.Symbol("s"): sympy.Rational(sv.numerator, sv.denominator)})
            if want.has(sympy.zoo, sympy.nan):
                continue
            assert sympy.Rational(got.numerator, got.denominator) == want, show(e)
            checked += 1
    assert checked > 200


def test_cleared_degree_of_the_texts_first_example():
    lhs, rhs = parse("-(2t - 1)^2 + 1"), parse("4/3 B(1, 3, t) + 4/3 B(2, 3, t)")
    assert cleared_degree(lhs, rhs, "t") == 3
    assert degree(parse("1/(1+t) + t^2/(2-t)"), "t") == (3, 2)
    assert degree(parse("sum(i, 0, n, B(i, n, t^2))"), "t", {"n": 4}) == (8, 0)
    with pytest.raises(Unsupported):
        degree(parse("t^n"), "t")


def test_sympy_translation_proves_and_refuses():
    pytest.importorskip("sympy")
    from _casteljau_oracle.cert_sympy import same, to_sympy

    lhs = to_sympy(parse("-(2t - 1)^2 + 1"))
    assert same(lhs, to_sympy(parse("4/3 B(1, 3, t) + 4/3 B(2, 3, t)")))
    assert not same(to_sympy(parse("(2t-1)^3 + (2t-1)")), to_sympy(parse("-4/3 B(1, 3, t) + 4/3 B(2, 3, t)")))
    assert same(to_sympy(parse("sum(i, 0, n, B(i, n, t))"), {"n": 7}), 1)
    assert same(to_sympy(parse("integral(B(i, n, t), t, 0, 1)"), {"i": 2, "n": 5}), to_sympy(parse("1/6")))
    assert same(to_sympy(parse("diff(t^3 s, t, 2)")), to_sympy(parse("6 t s")))
