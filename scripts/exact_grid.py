#!/usr/bin/env python3
"""Every exact operation over a grid of number sizes, degrees and parameters, against gmpy2
(and FLINT's fmpq_poly where FLINT has the operation).

Grid: digits {5, 30, 100, 300} x degree {3, 5, 20, 50, 200, 1000} x op x t {1/3, 20-digit,
100-digit}. A case is a planar curve whose coordinates are DIGITS-digit numerators (random
signs) over DIGITS-digit denominators, all distinct; t = p/q in (0, 1) with q of the given
size. Ops and peers:
  eval           gmpy2: the nested Bernstein sum over each coordinate's lcm of denominators
                 (exact_big.py's); FLINT: fmpq_poly evaluation of each coordinate's
                 power-basis polynomial at t (neither the conversion nor the fmpq_poly's
                 common denominator is timed); with --flint-from-fractions also
                 "prepared": the common denominator of the power-basis fractions (an fmpz
                 lcm loop in Python), the numerators over it and the evaluation
  split          gmpy2: de Casteljau's steps on mpq
  elevate        gmpy2: the elevation formula (7) on mpq (FLINT has no Bernstein elevation)
  derivative     gmpy2: n (b_{i+1} - b_i) on mpq
  to_power       gmpy2: the power-basis coefficients on integers over the common denominator
  rational_eval  positive DIGITS-digit weights; gmpy2: nested sums of w_i b_i and w_i, divided
  surface_eval   a net of degree (n, n), u = v = t; gmpy2: each row's nested sum, then the
                 column's
elevate, derivative and to_power do not depend on t: one cell each. Cells whose gmpy2 peer is
quadratic in the degree on numbers that grow with it (split, to_power) run up to degree 200,
surface_eval (n+1)^2 points up to degree 50; the rest are printed as "not run".

casteljau runs through the library, not the oracle: `cargo run --release --example
exact_grid` (scripts/exact_grid.rs) reads each case as text, parses it untimed, and times the
public generic method on BigRational. Both sides are CPU time (the Rust thread's, Python's
process_time; both clocks to the nanosecond), the median of five batch means (about 50 ms each
on the Rust side, 10 ms on Python's) after one run whose result is checked
equal (as text in lowest terms) before any time counts; an operation whose first run is
longer than ten batches is timed by that run on the Rust side, by the lesser of two more runs
on Python's. Cells run one after the other, casteljau then its peers: interleaved.

Each line prints the casteljau time, the peers' and the ratio peer / casteljau (above 1:
casteljau is faster); the end prints the worst cell against each peer.

  cargo build --release --example exact_grid
  python3 scripts/exact_grid.py [--digits 5,30] [--degrees 3,20] [--ops eval,elevate] [--ts 1/3]

Needs gmpy2; python-flint is optional (the FLINT column is left empty without it).
"""

import argparse
import os
import random
import subprocess
import sys
import time
from math import gcd

sys.set_int_max_str_digits(0)
HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)

import exact_big as eb  # noqa: E402  (the gmpy2 peers, shared with exact_big.py)
from gmpy2 import mpq  # noqa: E402

try:
    import flint
except ImportError:  # optional peer
    flint = None

DIGITS = (5, 30, 100, 300)
DEGREES = (3, 5, 20, 50, 200, 1000)
OPS = ("eval", "split", "elevate", "derivative", "to_power", "rational_eval", "surface_eval")
TS = ("1/3", "20", "100")
WITH_T = {"eval", "split", "rational_eval", "surface_eval"}
MAX_DEGREE = {"split": 200, "to_power": 200, "surface_eval": 50}
BATCH = 0.010
BATCHES = 5


def big(rng, digits):
    return rng.randrange(10 ** (digits - 1), 10**digits)


def fractions(rng, count, digits, positive=False):
    """`count` (numerator, denominator) pairs, denominators distinct."""
    seen, out = set(), []
    while len(out) < count:
        d = big(rng, digits)
        if d in seen:
            continue
        seen.add(d)
        n = big(rng, digits) * (1 if positive else rng.choice((-1, 1)))
        g = gcd(n, d)
        out.append((n // g, d // g))
    return out


def parameter(rng, kind):
    if kind == "1/3":
        return 1, 3
    q = big(rng, int(kind))
    p = rng.randrange(1, q)
    g = gcd(p, q)
    return p // g, q // g


def fmt(x):
    """An mpq, Fraction or FLINT fmpq as casteljau prints it."""
    n, d = (int(x.p), int(x.q)) if flint is not None and isinstance(x, flint.fmpq) else (x.numerator, x.denominator)
    return str(n) if d == 1 else f"{n}/{d}"


def text_point(pt):
    return ",".join(f"{n}/{d}" for n, d in pt)


def transpose(per_coordinate):
    """Point-major order from per-coordinate lists."""
    return [c for point in zip(*per_coordinate) for c in point]


def timed(f):
    """Median, min, max CPU seconds of f (batches of about BATCH), and its result."""
    start = time.process_time()
    result = f()
    once = max(time.process_time() - start, 1e-9)
    if once > 10 * BATCH:
        # a long run is timed twice more and the least counts: one pause (the collector,
        # the machine) must not make a cell
        again = []
        for _ in range(2):
            start = time.process_time()
            f()
            again.append(time.process_time() - start)
        return (min(again), min(again), max(again)), result
    reps = max(1, int(BATCH / once))
    means = []
    for _ in range(BATCHES):
        start = time.process_time()
        for _ in range(reps):
            f()
        means.append((time.process_time() - start) / reps)
    means.sort()
    return (means[len(means) // 2], means[0], means[-1]), result


def case(rng, op, n, digits, t_kind, from_fractions=False):
    """The request line for the Rust side and the peers as closures returning output
    coordinates in casteljau's order."""
    p, q = parameter(rng, t_kind)
    t = mpq(p, q)
    if op == "surface_eval":
        net = [fractions(rng, 2 * (n + 1), digits) for _ in range(n + 1)]
        net = [[(row[2 * j], row[2 * j + 1]) for j in range(n + 1)] for row in net]
        data = " | ".join("; ".join(text_point(pt) for pt in row) for row in net)
        peers = {"gmpy2": lambda: eb.surface_eval_gmpy2(net, (p, q), (p, q))}
        return f"{op}\t{p}/{q}\t{data}", peers
    coords = fractions(rng, 2 * (n + 1), digits)
    points = [(coords[2 * i], coords[2 * i + 1]) for i in range(n + 1)]
    data = "; ".join(text_point(pt) for pt in points)
    per = [[pt[k] for pt in points] for k in range(2)]
    peers = {}
    if op == "eval":
        peers["gmpy2"] = lambda: [eb.nested_gmpy2(c, p, q) for c in per]
        if flint is not None:
            coefficients = [[flint.fmpq(int(a.numerator), int(a.denominator)) for a in eb.to_power_gmpy2(c)] for c in per]
            polys = [flint.fmpq_poly(c) for c in coefficients]
            ft = flint.fmpq(p, q)
            peers["flint"] = lambda: [poly(ft) for poly in polys]
            if from_fractions:

                def prepared():
                    # the common denominator of each coordinate's power-basis coefficients
                    # and its numerators, as a python-flint user builds them, then evaluation
                    out = []
                    for c in coefficients:
                        den = flint.fmpz(1)
                        for a in c:
                            den = den.lcm(a.q)
                        poly = flint.fmpq_poly(flint.fmpz_poly([a.p * (den // a.q) for a in c]), den)
                        out.append(poly(ft))
                    return out

                peers["flint_prepared"] = prepared
    elif op == "split":
        cols = [[mpq(a, d) for a, d in c] for c in per]

        def split():
            pieces = [eb.casteljau_split(c, t) for c in cols]
            return transpose([pc[0] for pc in pieces]) + transpose([pc[1] for pc in pieces])

        peers["gmpy2"] = split
    elif op == "elevate":
        cols = [[mpq(a, d) for a, d in c] for c in per]
        peers["gmpy2"] = lambda: transpose([eb.elevate(c, mpq(1)) for c in cols])
    elif op == "derivative":
        cols = [[mpq(a, d) for a, d in c] for c in per]
        peers["gmpy2"] = lambda: transpose([eb.derivative_mpq(c) for c in cols])
    elif op == "to_power":
        peers["gmpy2"] = lambda: transpose([eb.to_power_gmpy2(c) for c in per])
    elif op == "rational_eval":
        weights = fractions(rng, n + 1, digits, positive=True)
        data += " # " + ", ".join(f"{a}/{d}" for a, d in weights)
        peers["gmpy2"] = lambda: eb.rational_eval_gmpy2(points, weights, p, q)
    return f"{op}\t{p}/{q}\t{data}", peers


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--digits", default=",".join(map(str, DIGITS)))
    ap.add_argument("--degrees", default=",".join(map(str, DEGREES)))
    ap.add_argument("--ops", default=",".join(OPS))
    ap.add_argument("--ts", default=",".join(TS), help="1/3, 20 or 100 (digits of t's denominator)")
    ap.add_argument("--seed", type=int, default=47)
    ap.add_argument("--example", default=os.path.join(ROOT, "target", "release", "examples", "exact_grid"))
    ap.add_argument("--cases", action="store_true", help="print the cases' lines for the example, run nothing")
    ap.add_argument(
        "--flint-from-fractions",
        action="store_true",
        help="eval: also time FLINT from the power-basis fractions (common denominator included)",
    )
    args = ap.parse_args()
    rng = random.Random(args.seed)
    if args.cases:
        for digits in [int(d) for d in args.digits.split(",")]:
            for n in [int(d) for d in args.degrees.split(",")]:
                for op in args.ops.split(","):
                    for t_kind in args.ts.split(",") if op in WITH_T else ["-"]:
                        if n <= MAX_DEGREE.get(op, n):
                            print(case(rng, op, n, digits, "1/3" if t_kind == "-" else t_kind)[0])
        return
    rust = subprocess.Popen([args.example], stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True, bufsize=1)
    worst = {}
    names = ("gmpy2", "flint") + (("flint_prepared",) if args.flint_from_fractions else ())
    extra = f"{'prepared':>11}{'ratio':>8}" if args.flint_from_fractions else ""
    print(f"{'op':<14}{'digits':>7}{'degree':>7}{'t':>5}{'casteljau':>12}{'gmpy2':>11}{'ratio':>8}{'spread':>14}{'flint':>11}{'ratio':>8}{extra}")
    for digits in [int(d) for d in args.digits.split(",")]:
        for n in [int(d) for d in args.degrees.split(",")]:
            for op in args.ops.split(","):
                for t_kind in args.ts.split(",") if op in WITH_T else ["-"]:
                    label = f"{op:<14}{digits:>7}{n:>7}{t_kind:>5}"
                    if n > MAX_DEGREE.get(op, n):
                        print(f"{label}  not run")
                        continue
                    line, peers = case(rng, op, n, digits, "1/3" if t_kind == "-" else t_kind, args.flint_from_fractions)
                    rust.stdin.write(line + "\n")
                    fields = rust.stdout.readline().rstrip("\n").split("\t")
                    ours = [int(x) * 1e-9 for x in fields[:3]]
                    answer = fields[4].split(" ")
                    row = f"{label}{fmt_time(ours[0]):>12}"
                    for name in names:
                        if name not in peers:
                            row += f"{'':>11}{'':>8}" + (f"{'':>14}" if name == "gmpy2" else "")
                            continue
                        (median, low, high), result = timed(peers[name])
                        if [fmt(x) for x in result] != answer:
                            sys.exit(f"{label}: {name} differs from casteljau")
                        ratio = median / ours[0]
                        # the ratio's spread: the slowest peer batch over our fastest, and back
                        spread = f"[{low / ours[2]:.2f}, {high / ours[1]:.2f}]"
                        row += f"{fmt_time(median):>11}{ratio:>8.2f}"
                        if name == "gmpy2":
                            row += f"{spread:>14}"
                        key = name
                        if key not in worst or ratio < worst[key][0]:
                            worst[key] = (ratio, label.split())
                    print(row, flush=True)
    rust.stdin.close()
    rust.wait()
    for name, (ratio, label) in worst.items():
        print(f"worst cell against {name}: {' '.join(label)}: {ratio:.2f}x")


def fmt_time(seconds):
    for unit, scale in (("s", 1), ("ms", 1e-3), ("µs", 1e-6)):
        if seconds >= scale:
            return f"{seconds / scale:.3g} {unit}"
    return f"{seconds * 1e9:.3g} ns"


if __name__ == "__main__":
    main()
