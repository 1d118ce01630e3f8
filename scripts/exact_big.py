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
Every Python result is checked against the others before it counts.

casteljau's figures are criterion's CPU-time estimates (mean and its 95% interval) from
<target>/criterion/exact_big; --bench runs the group first:

  python3 scripts/exact_big.py --bench           # runs cargo bench, then Python
  python3 scripts/exact_big.py                   # reads an earlier cargo bench run

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


def run_bench():
    cmd = ["cargo", "bench", "--bench", "exact", "--", "exact_big", "--warm-up-time", "1", "--measurement-time", "2"]
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
    args = parser.parse_args()
    if gmpy2 is None:
        sys.exit("gmpy2 is not installed: pip install gmpy2")
    if args.bench:
        run_bench()

    rows = []
    for n in args.degrees:
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
        frac_elevated = [elevate(c, Fraction(1)) for c in as_frac]
        assert all(mpq(f.numerator, f.denominator) == g for fs, gs in zip(frac_elevated, elevated) for f, g in zip(fs, gs))
        for op, entries in peers.items():
            ours = casteljau_estimate(op, n)
            for name, f in entries:
                slow = name != "gmpy2 nested" and op in ("eval", "split_at") and n > FRACTION_SPLIT_MAX_DEGREE
                if slow:
                    rows.append((op, n, name, None, ours))
                    continue
                median, low, high = cpu_seconds(f)
                rows.append((op, n, name, (median, low, high), ours))
                print(f"  {op} n={n} {name}: {fmt_time(median)}", file=sys.stderr)

    print(f"{'operation':<10} {'n':>5}  {'casteljau (CPU, mean [95%])':<32} {'peer':<13} {'peer CPU (median [min, max])':<32} {'ratio':>8}")
    for op, n, name, theirs, ours in rows:
        ours_text = "not measured" if ours is None else f"{fmt_time(ours[0])} [{fmt_time(ours[1])}, {fmt_time(ours[2])}]"
        if theirs is None:
            theirs_text, ratio = "skipped (minutes)", "-"
        else:
            theirs_text = f"{fmt_time(theirs[0])} [{fmt_time(theirs[1])}, {fmt_time(theirs[2])}]"
            ratio = "-" if ours is None else f"{theirs[0] / ours[0]:.2f}×"
        print(f"{op:<10} {n:>5}  {ours_text:<32} {name:<13} {theirs_text:<32} {ratio:>8}")


if __name__ == "__main__":
    main()
