#!/usr/bin/env python3
"""casteljau's exact operations beside Python's best and plainest exact arithmetic.

The cases are those of the criterion group `exact_big` (benches/exact.rs), drawn from the
same splitmix64 stream: planar curves of degree 20, 200 and 1000 whose coordinates are
30-digit numerators (random signs) over 30-digit denominators, and a 20-digit t in (0, 1).

Python peers, each timed in CPU time (time.process_time):
  gmpy2 nested   the Bernstein sum nested in t over one common denominator per coordinate
                 (lcm of the denominators, t = p/q as integers), one mpq at the end;
  gmpy2 mpq      de Casteljau's steps and the elevation formula (7) on mpq;
  fractions      the same steps on fractions.Fraction.
The other public exact operations, up to degree 200, each against its plain gmpy2 form:
  derivative     n (b_{i+1} - b_i) on mpq;
  derivative_at  the nested sum of the differences over their common denominator;
  to_power       a_j = C(n,j) sum_i (-1)^(j-i) C(j,i) x_i on integers over the common
                 denominator;
  rational_eval  nested sums of the homogeneous coordinates w_i b_i and of w_i, divided;
  from_power     b_i = sum_k C(i,k)/C(n,k) a_k on mpq, the case's points read as
                 power-basis coefficients;
  rational_derivative_at
                 x' = (P' w - P w') / w^2 from the nested sums of P = w x, w and their
                 derivatives (as derivative_at above);
  rational_split_at (degree 20) de Casteljau's steps on the homogeneous mpq points
                 (w_i b_i, w_i), each piece's points divided by their weights;
  surface_eval   on nets of degrees (10, 10) and (20, 20): each row's nested sum at v,
                 then the column's at u;
  surface_to_power  to_power above on each row, then on each column of the result;
  surface_derivative_u  m (b_{i+1,j} - b_{i,j}) on mpq;
  surface_split_u   de Casteljau's steps on each column, on mpq.
Every Python result is checked against the others before it counts.

With elevate, the table is followed by elevate's floor: the time to clone its result's
points (allocations and digits, no arithmetic), which any elevation returning BigRational
points spends at least, as a share of a fifth of the gmpy2 mpq time.

casteljau's figures are criterion's CPU-time estimates (mean and its 95% interval) from
<target>/criterion/exact_big; --bench runs the group first:

  python3 scripts/exact_big.py --bench           # runs cargo bench, then Python
  python3 scripts/exact_big.py                   # reads an earlier cargo bench run
  python3 scripts/exact_big.py --bench --ops elevate derivative --degrees 200
                                                 # only those operations and degrees

Ratios are peer CPU time / casteljau CPU time: above 1, casteljau is faster.
"""

import argparse
import json
import math
import os
import subprocess
import sys
import time
from fractions import Fraction

try:
    import gmpy2
    from gmpy2 import mpq, mpz
except ImportError:  # pragma: no cover - reported, not hidden
    gmpy2 = None

DEGREES = (20, 200, 1000)
MASK = (1 << 64) - 1
# de Casteljau's steps at degree 1000 run for minutes (on mpq, Fraction and in the bench):
# left out, and said so.
FRACTION_SPLIT_MAX_DEGREE = 200
# derivative, derivative_at, to_power and rational_eval: benched up to this degree.
OTHER_OPS_MAX_DEGREE = 200
# surface_eval on nets of degrees (m, m).
SURFACE_DEGREES = (10, 20)


class SplitMix:
    """splitmix64, as in benches/exact.rs."""

    def __init__(self, seed):
        self.state = seed & MASK

    def next(self):
        self.state = (self.state + 0x9E3779B97F4A7C15) & MASK
        z = self.state
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK
        return z ^ (z >> 31)

    def digits(self, k):
        low = 10 ** (k - 1)
        wide = (self.next() << 64) | self.next()
        return low + wide % (9 * low)


def big_case(n):
    """Coordinates as (numerator, denominator) pairs per point, and t = (p, q)."""
    rng = SplitMix(1000 + n)

    def coordinate():
        magnitude = rng.digits(30)
        numerator = -magnitude if rng.next() & 1 == 1 else magnitude
        return numerator, rng.digits(30)

    points = [[coordinate(), coordinate()] for _ in range(n + 1)]
    p, q = rng.digits(20), rng.digits(20)
    if p > q:
        p, q = q, p
    if p == q:
        q += 1
    return points, (p, q)


def twenty_digit_parameter(rng):
    p, q = rng.digits(20), rng.digits(20)
    if p > q:
        p, q = q, p
    if p == q:
        q += 1
    return p, q


def thirty_digit_fraction(rng):
    magnitude = rng.digits(30)
    numerator = -magnitude if rng.next() & 1 == 1 else magnitude
    return numerator, rng.digits(30)


def rational_weights(n):
    """Positive 30-digit weights over 30-digit denominators, as in benches/exact.rs."""
    rng = SplitMix(2000 + n)
    return [(abs(a), d) for a, d in (thirty_digit_fraction(rng) for _ in range(n + 1))]


def surface_case(m):
    """A net of (m+1)^2 planar 30-digit fractions and 20-digit u, v."""
    rng = SplitMix(3000 + m)
    net = [[[thirty_digit_fraction(rng), thirty_digit_fraction(rng)] for _ in range(m + 1)] for _ in range(m + 1)]
    return net, twenty_digit_parameter(rng), twenty_digit_parameter(rng)


def cpu_seconds(f, budget=2.0, max_runs=20):
    """Median, min and max CPU time of f over runs repeated within about `budget` seconds
    (one run when a single one takes longer)."""
    times = []
    spent = 0.0
    while not times or (spent < budget and len(times) < max_runs):
        start = time.process_time()
        f()
        elapsed = time.process_time() - start
        times.append(elapsed)
        spent += elapsed
    times.sort()
    return times[len(times) // 2], times[0], times[-1]


# --- gmpy2 -----------------------------------------------------------------------------


def nested_gmpy2(coords, p, q):
    """b(t) of one coordinate: Σ C(n,i) p^i s^(n-i) x_i over D q^n, s = q - p."""
    n = len(coords) - 1
    den = mpz(1)
    for _, d in coords:
        den = gmpy2.lcm(den, d)
    x = [mpz(a) * (den // d) for a, d in coords]
    p, q = mpz(p), mpz(q)
    s = q - p
    acc, c = x[0], mpz(1)
    for i in range(1, n + 1):
        c = c * (n - i + 1) // i * p
        acc = acc * s + c * x[i]
    return mpq(acc, den * q**n)


def over_common_denominator(coords):
    """Integers x_i over one denominator D (the lcm) for (numerator, denominator) pairs."""
    den = mpz(1)
    for _, d in coords:
        den = gmpy2.lcm(den, d)
    return [mpz(a) * (den // d) for a, d in coords], den


def nested_integers(x, p, q):
    """Σ C(n,i) p^i s^(n-i) x_i for integers x_i, s = q - p (the numerator over q^n)."""
    n = len(x) - 1
    p, q = mpz(p), mpz(q)
    s = q - p
    acc, c = x[0], mpz(1)
    for i in range(1, n + 1):
        c = c * (n - i + 1) // i * p
        acc = acc * s + c * x[i]
    return acc


def pairs(values):
    return [(v.numerator, v.denominator) for v in values]


def derivative_mpq(b):
    """The hodograph's control points n (b_{i+1} - b_i) on mpq."""
    n = len(b) - 1
    return [n * (b[i + 1] - b[i]) for i in range(n)]


def derivative_at_gmpy2(coords, p, q):
    """b'(t) of one coordinate: n Σ Δx_i B_i^{n-1}(t) over D q^(n-1), by the nested sum."""
    x, den = over_common_denominator(coords)
    n = len(x) - 1
    diffs = [x[i + 1] - x[i] for i in range(n)]
    return mpq(n * nested_integers(diffs, p, q), den * mpz(q) ** (n - 1))


def to_power_gmpy2(coords):
    """a_j = C(n,j) Σ_i (-1)^(j-i) C(j,i) b_i over the common denominator, on integers."""
    x, den = over_common_denominator(coords)
    n = len(x) - 1
    out = []
    cn = mpz(1)
    for j in range(n + 1):
        acc, cj = mpz(0), mpz(1)
        for i in range(j, -1, -1):
            acc += cj * x[i] if (j - i) % 2 == 0 else -cj * x[i]
            cj = cj * i // (j - i + 1)
        out.append(mpq(cn * acc, den))
        cn = cn * (n - j) // (j + 1)
    return out


def rational_eval_gmpy2(points, weights, p, q):
    """x(t) = Σ w_i b_i B_i(t) / Σ w_i B_i(t): nested sums of the homogeneous coordinates,
    each over its common denominator (q^n cancels)."""
    w = [mpq(a, d) for a, d in weights]
    big_w = nested_gmpy2(weights, p, q)
    out = []
    for k in range(2):
        h = [w[i] * mpq(*points[i][k]) for i in range(len(points))]
        out.append(nested_gmpy2(pairs(h), p, q) / big_w)
    return out


def surface_eval_gmpy2(net, u, v):
    """b(u, v): each row's nested sum at v, then the column's at u."""
    out = []
    for k in range(2):
        rows = [nested_gmpy2([pt[k] for pt in row], *v) for row in net]
        out.append(nested_gmpy2(pairs(rows), *u))
    return out


def from_power_mpq(a):
    """Bernstein points b_i = sum_{k<=i} C(i,k)/C(n,k) a_k of the power-basis a_k."""
    n = len(a) - 1
    return [sum((mpq(math.comb(i, k), math.comb(n, k)) * a[k] for k in range(i + 1)), mpq(0)) for i in range(n + 1)]


def rational_derivative_at_gmpy2(points, weights, p, q):
    """x'(t) = (P'(t) w(t) - P(t) w'(t)) / w(t)^2, each sum nested over its common denominator."""
    w = [mpq(a, d) for a, d in weights]
    big_w, big_dw = nested_gmpy2(weights, p, q), derivative_at_gmpy2(weights, p, q)
    out = []
    for k in range(2):
        h = pairs([w[i] * mpq(*points[i][k]) for i in range(len(points))])
        out.append((derivative_at_gmpy2(h, p, q) * big_w - nested_gmpy2(h, p, q) * big_dw) / big_w**2)
    return out


def rational_split_mpq(points, weights, t):
    """Both pieces' points and weights: de Casteljau on (w_i b_i, w_i), then divided."""
    w = [mpq(a, d) for a, d in weights]
    columns = [[w[i] * mpq(*points[i][k]) for i in range(len(points))] for k in range(2)] + [w]
    pieces = [casteljau_split(c, t) for c in columns]
    out = []
    for side in range(2):
        ws = pieces[2][side]
        out.append(([[pieces[k][side][i] / ws[i] for k in range(2)] for i in range(len(ws))], ws))
    return out


def surface_to_power_gmpy2(net):
    """to_power on each row (in v), then on each column of the result (in u)."""
    out = []
    for k in range(2):
        rows = [to_power_gmpy2([pt[k] for pt in row]) for row in net]
        columns = [to_power_gmpy2(pairs([r[j] for r in rows])) for j in range(len(rows[0]))]
        out.append(columns)
    return out


def surface_derivative_u_mpq(net):
    """m (b_{i+1,j} - b_{i,j}) on mpq."""
    m = len(net) - 1
    return [[[m * (net[i + 1][j][k] - net[i][j][k]) for k in range(2)] for j in range(len(net[0]))] for i in range(m)]


def surface_split_u_mpq(net, u):
    """Each column split at u by de Casteljau's steps, per coordinate."""
    return [[casteljau_split([row[j][k] for row in net], u) for k in range(2)] for j in range(len(net[0]))]


def casteljau_split(b, t):
    """Left and right control points of the split at t, by de Casteljau's steps."""
    b = list(b)
    n = len(b) - 1
    left = [b[0]]
    for r in range(1, n + 1):
        for i in range(n + 1 - r):
            b[i] = b[i] + t * (b[i + 1] - b[i])
        left.append(b[0])
    right = [b[n - r] for r in range(n, -1, -1)]
    return left, right


def elevate(b, one):
    """One step of degree elevation (7)."""
    n = len(b) - 1
    step = one / (n + 1)
    out = [b[0]]
    for i in range(1, n + 1):
        w = step * i
        out.append(w * b[i - 1] + (one - w) * b[i])
    out.append(b[n])
    return out


def per_coordinate(points, make):
    return [[make(*pt[k]) for pt in points] for k in range(2)]


# --- casteljau's side ------------------------------------------------------------------


def target_dir():
    return os.environ.get("CARGO_TARGET_DIR") or os.path.join(os.path.dirname(__file__), "..", "target")


def casteljau_estimate(op, n):
    path = os.path.join(target_dir(), "criterion", "exact_big", op, str(n), "new", "estimates.json")
    try:
        with open(path) as f:
            mean = json.load(f)["mean"]
    except OSError:
        return None
    ci = mean["confidence_interval"]
    return mean["point_estimate"] / 1e9, ci["lower_bound"] / 1e9, ci["upper_bound"] / 1e9


CURVE_OPS = (
    "eval",
    "split_at",
    "elevate",
    "derivative",
    "derivative_at",
    "to_power",
    "from_power",
    "rational_eval",
    "rational_split_at",
    "rational_derivative_at",
)
SURFACE_OPS = ("surface_eval", "surface_to_power", "surface_derivative_u", "surface_split_u")


def run_bench(ops, degrees):
    """The criterion group exact_big, only its benchmarks of the operations and degrees asked."""
    surface_degrees = [m for m in SURFACE_DEGREES if any(op in ops for op in SURFACE_OPS)]
    sizes = "|".join(str(n) for n in sorted(set(degrees) | set(surface_degrees)))
    # elevate's floor runs with it (see the note under the table)
    names = "|".join(list(ops) + (["elevate_output_floor"] if "elevate" in ops else []))
    cmd = ["cargo", "bench", "--bench", "exact", "--", f"exact_big/({names})/({sizes})$"]
    cmd += ["--warm-up-time", "1", "--measurement-time", "2"]
    print("running:", " ".join(cmd), file=sys.stderr)
    subprocess.run(cmd, check=True, cwd=os.path.join(os.path.dirname(__file__), ".."))


def fmt_time(seconds):
    if seconds is None:
        return "-"
    if seconds >= 1:
        return f"{seconds:.3g} s"
    if seconds >= 1e-3:
        return f"{seconds * 1e3:.3g} ms"
    return f"{seconds * 1e6:.3g} µs"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--bench", action="store_true", help="run the criterion group exact_big first")
    parser.add_argument("--degrees", type=int, nargs="*", default=list(DEGREES))
    parser.add_argument(
        "--ops",
        nargs="*",
        default=list(CURVE_OPS + SURFACE_OPS),
        metavar="OP",
        help="only these operations: " + ", ".join(CURVE_OPS + SURFACE_OPS),
    )
    args = parser.parse_args()
    unknown = [op for op in args.ops if op not in CURVE_OPS + SURFACE_OPS]
    if unknown:
        sys.exit(f"unknown operation(s) {', '.join(unknown)}; known: {', '.join(CURVE_OPS + SURFACE_OPS)}")
    if gmpy2 is None:
        sys.exit("gmpy2 is not installed: pip install gmpy2")
    if args.bench:
        run_bench(args.ops, args.degrees)

    rows = []
    for n in args.degrees if any(op in args.ops for op in CURVE_OPS) else []:
        points, (p, q) = big_case(n)
        dens = {d for pt in points for _, d in pt}
        assert len(dens) == 2 * (n + 1), "denominators must be distinct"
        t_mpq, t_frac = mpq(p, q), Fraction(p, q)
        as_mpq = per_coordinate(points, mpq)
        as_frac = per_coordinate(points, Fraction)
        coord_pairs = [[pt[k] for pt in points] for k in range(2)]

        # Every peer must agree before its time counts.
        nested = [nested_gmpy2(c, p, q) for c in coord_pairs]
        if n <= FRACTION_SPLIT_MAX_DEGREE:
            split = [casteljau_split(c, t_mpq) for c in as_mpq]
            assert [s[0][-1] for s in split] == nested, "gmpy2 split and nested sum disagree"
        elevated = [elevate(c, mpq(1)) for c in as_mpq]

        peers = {
            "eval": [
                ("gmpy2 nested", lambda: [nested_gmpy2(c, p, q) for c in coord_pairs]),
                ("gmpy2 mpq", lambda: [casteljau_split(c, t_mpq)[0][-1] for c in as_mpq]),
                ("fractions", lambda: [casteljau_split(c, t_frac)[0][-1] for c in as_frac]),
            ],
            "split_at": [
                ("gmpy2 mpq", lambda: [casteljau_split(c, t_mpq) for c in as_mpq]),
                ("fractions", lambda: [casteljau_split(c, t_frac) for c in as_frac]),
            ],
            "elevate": [
                ("gmpy2 mpq", lambda: [elevate(c, mpq(1)) for c in as_mpq]),
                ("fractions", lambda: [elevate(c, Fraction(1)) for c in as_frac]),
            ],
        }
        if n <= OTHER_OPS_MAX_DEGREE:
            weights = rational_weights(n)
            derivative = [derivative_mpq(c) for c in as_mpq]
            at = [derivative_at_gmpy2(c, p, q) for c in coord_pairs]
            assert at == [nested_gmpy2(pairs(d), p, q) for d in derivative], "derivative peers disagree"
            power = [to_power_gmpy2(c) for c in coord_pairs]
            assert [sum(a * t_mpq**j for j, a in enumerate(cs)) for cs in power] == nested, "power basis disagrees"
            rational = rational_eval_gmpy2(points, weights, p, q)
            homogeneous = [[mpq(*w) * mpq(*pt[k]) for pt, w in zip(points, weights)] for k in range(2)]
            if n <= 20:
                w_t = casteljau_split([mpq(*w) for w in weights], t_mpq)[0][-1]
                assert rational == [casteljau_split(h, t_mpq)[0][-1] / w_t for h in homogeneous], "rational peers disagree"
            peers["derivative"] = [("gmpy2 mpq", lambda: [derivative_mpq(c) for c in as_mpq])]
            peers["derivative_at"] = [("gmpy2 nested", lambda: [derivative_at_gmpy2(c, p, q) for c in coord_pairs])]
            peers["to_power"] = [("gmpy2 integers", lambda: [to_power_gmpy2(c) for c in coord_pairs])]
            peers["rational_eval"] = [("gmpy2 nested", lambda: rational_eval_gmpy2(points, weights, p, q))]
            coefficients = [[mpq(*c) for c in pt] for pt in points]
            bernstein = [from_power_mpq([c[k] for c in coefficients]) for k in range(2)]
            # Back to the power basis: the coefficients again.
            assert [to_power_gmpy2(pairs(b)) for b in bernstein] == [[c[k] for c in coefficients] for k in range(2)], "from_power disagrees"
            peers["from_power"] = [("gmpy2 mpq", lambda: [from_power_mpq([c[k] for c in coefficients]) for k in range(2)])]
            r_prime = rational_derivative_at_gmpy2(points, weights, p, q)
            if n <= 20:
                # The quotient rule by de Casteljau's last two columns, against the nested sums.
                w_left = casteljau_split([mpq(*w) for w in weights], t_mpq)[0]
                h_left = [casteljau_split(h, t_mpq)[0] for h in homogeneous]
                # x' = n (h1 w0 - h0 w1) / w^2 with h0, h1 (w0, w1) the last-but-one column.
                cols = [casteljau_split(h, t_mpq) for h in homogeneous + [[mpq(*w) for w in weights]]]
                last = [(c[0][-2], c[1][1]) for c in cols]
                w0, w1 = last[2]
                w_t = w_left[-1]
                assert r_prime == [n * (h1 * w0 - h0 * w1) / w_t**2 for h0, h1 in last[:2]], "rational derivative peers disagree"
                split = rational_split_mpq(points, weights, t_mpq)
                assert split[0][0][-1] == [h[-1] / w_t for h in h_left], "rational split disagrees"
                peers["rational_split_at"] = [("gmpy2 mpq", lambda: rational_split_mpq(points, weights, t_mpq))]
            peers["rational_derivative_at"] = [("gmpy2 nested", lambda: rational_derivative_at_gmpy2(points, weights, p, q))]
        frac_elevated = [elevate(c, Fraction(1)) for c in as_frac]
        assert all(mpq(f.numerator, f.denominator) == g for fs, gs in zip(frac_elevated, elevated) for f, g in zip(fs, gs))
        for op, entries in peers.items():
            if op not in args.ops:
                continue
            ours = casteljau_estimate(op, n)
            for name, f in entries:
                slow = name != "gmpy2 nested" and op in ("eval", "split_at") and n > FRACTION_SPLIT_MAX_DEGREE
                if slow:
                    rows.append((op, n, name, None, ours))
                    continue
                median, low, high = cpu_seconds(f)
                rows.append((op, n, name, (median, low, high), ours))
                print(f"  {op} n={n} {name}: {fmt_time(median)}", file=sys.stderr)

    for m in SURFACE_DEGREES if any(op in args.ops for op in SURFACE_OPS) else []:
        net, u, v = surface_case(m)
        value = surface_eval_gmpy2(net, u, v)
        # v first then u, against u first then v.
        columns = [[nested_gmpy2([net[i][j][k] for i in range(m + 1)], *u) for j in range(m + 1)] for k in range(2)]
        assert value == [nested_gmpy2(pairs(col), *v) for col in columns], "surface peers disagree"
        net_mpq = [[[mpq(*c) for c in pt] for pt in row] for row in net]
        u_mpq = mpq(*u)
        power = surface_to_power_gmpy2(net)
        # The power form at (u, v) is the surface's value.
        at = [sum(power[k][j][i] * u_mpq**i * mpq(*v) ** j for i in range(m + 1) for j in range(m + 1)) for k in range(2)]
        assert at == value, "surface power basis disagrees"
        split = surface_split_u_mpq(net_mpq, u_mpq)
        assert [nested_gmpy2(pairs([split[j][k][0][-1] for j in range(m + 1)]), *v) for k in range(2)] == value, "surface split disagrees"
        derivative = surface_derivative_u_mpq(net_mpq)
        assert derivative[0][0][0] == m * (net_mpq[1][0][0] - net_mpq[0][0][0])
        for op, name, f in (
            ("surface_eval", "gmpy2 nested", lambda: surface_eval_gmpy2(net, u, v)),
            ("surface_to_power", "gmpy2 integers", lambda: surface_to_power_gmpy2(net)),
            ("surface_derivative_u", "gmpy2 mpq", lambda: surface_derivative_u_mpq(net_mpq)),
            ("surface_split_u", "gmpy2 mpq", lambda: surface_split_u_mpq(net_mpq, u_mpq)),
        ):
            if op not in args.ops:
                continue
            median, low, high = cpu_seconds(f)
            rows.append((op, m, name, (median, low, high), casteljau_estimate(op, m)))
            print(f"  {op} m={m}: {fmt_time(median)}", file=sys.stderr)

    print(f"{'operation':<22} {'n':>5}  {'casteljau (CPU, mean [95%])':<32} {'peer':<15} {'peer CPU (median [min, max])':<32} {'ratio':>8}")
    for op, n, name, theirs, ours in rows:
        ours_text = "not measured" if ours is None else f"{fmt_time(ours[0])} [{fmt_time(ours[1])}, {fmt_time(ours[2])}]"
        if theirs is None:
            theirs_text, ratio = "skipped (minutes)", "-"
        else:
            theirs_text = f"{fmt_time(theirs[0])} [{fmt_time(theirs[1])}, {fmt_time(theirs[2])}]"
            ratio = "-" if ours is None else f"{theirs[0] / ours[0]:.2f}×"
        print(f"{op:<22} {n:>5}  {ours_text:<32} {name:<15} {theirs_text:<32} {ratio:>8}")
    floors = [(n, theirs, casteljau_estimate("elevate_output_floor", n)) for op, n, name, theirs, _ in rows
              if op == "elevate" and name == "gmpy2 mpq" and theirs is not None]
    for n, theirs, floor in floors:
        if floor is not None:
            print(f"elevate n={n}: the result's points cloned, no arithmetic (elevate_output_floor): "
                  f"{fmt_time(floor[0])}, {floor[0] / (theirs[0] / 5):.2f} of gmpy2 mpq / 5 ({fmt_time(theirs[0] / 5)})")


if __name__ == "__main__":
    main()
