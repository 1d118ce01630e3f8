"""The message of a failed `assert_within_bound`: everything needed to tell a bug from an
ill-conditioned input, per coordinate."""

_MAX_EXACT = 2000


def _exact_text(q):
    s = str(q)
    if len(s) <= _MAX_EXACT:
        return s
    return f"{s[: _MAX_EXACT // 2]}…{s[-40:]} ({len(s)} characters)"


def within_bound_message(method, t, approx, j):
    """Per coordinate: the answer, the correctly rounded value, ulps, error in ulps, the
    bound, the condition number, whether it is within; then each exact value."""
    n = len(j["point"])
    cond = j.get("condition", [None] * n)
    lines = [
        (
            f"the answer is outside the a priori error bound of {method} at t = {t!r} "
            f"({sum(1 for w in j['within_bound'] if not w)} of {n} coordinates):"
        ),
        (
            f"  {'coord':>5}  {'approx':>24}  {'correctly rounded':>24}  {'ulps':>20}  {'error_ulps':>11}  "
            f"{'bound':>11}  {'condition':>10}  within"
        ),
    ]
    for k in range(n):
        ulps = j["ulps"][k]
        lines.append(
            f"  {k:>5}  {approx[k]!r:>24}  {j['nearest'][k]!r:>24}  {'nan' if ulps is None else ulps:>20}  "
            f"{j['error_ulps'][k]:>11.4g}  {j['bound'][k]:>11.4g}  "
            f"{'-' if cond[k] is None else format(cond[k], '.4g'):>10}  {'yes' if j['within_bound'][k] else 'NO'}"
        )
        if j.get("verdict") and j["verdict"][k]:
            lines.append(f"         {j['verdict'][k]}")
    for k in range(n):
        lines.append(f"  exact[{k}] = {_exact_text(j['point'][k])}")
    lines.append("  (ulps: floats from the correctly rounded value; bound and error_ulps: in ulps of the exact value)")
    return "\n".join(lines)
