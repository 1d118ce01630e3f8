#!/usr/bin/env python3
"""The oracle's exact operations on big fractions, timed against the degree: linear work must
take linear time.

Writes one request per (op, degree): a planar curve of the given degree whose coordinates are
random DIGITS-digit numerators over random, distinct DIGITS-digit denominators (a seeded
generator), and feeds each to `casteljau oracle` alone, measuring the child's CPU time (user +
system, getrusage). Python peers time the same arithmetic in process CPU time:
  fractions  json.loads of the request, the operation on fractions.Fraction, json.dumps of
             the answer;
  gmpy2      the same with mpq (skipped when gmpy2 is not installed).
The oracle's elevate answer is checked against fractions' before a ratio is printed.

  cargo build --release
  python3 scripts/oracle_linear.py [--digits 100] [--degrees 50,100,200,400] [--ops elevate,eval,split,derivative]
  python3 scripts/oracle_linear.py --digits 30 --degrees 200 --ops read --repeat 200

Standard library only (gmpy2 optional). One run per cell: the figures are single runs. With
--repeat N one oracle process answers the request N times (start-up subtracted, divided by N)
and each Python peer answers it N times in a loop: per-request times that a single run's
start-up and scheduling noise do not swamp.
"""

import argparse
import json
import os
import random
import resource
import subprocess
import sys
import time
from fractions import Fraction

sys.set_int_max_str_digits(0)
HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)

try:
    import gmpy2
except ImportError:  # optional peer
    gmpy2 = None


def big(rng, digits):
    return rng.randrange(10 ** (digits - 1), 10**digits)


def curve(rng, degree, digits, dim=2):
    """degree + 1 points, every coordinate over its own denominator (all distinct)."""
    seen = set()
    pts = []
    for _ in range(degree + 1):
        p = []
        for _ in range(dim):
            while True:
                q = big(rng, digits)
                if q not in seen:
                    seen.add(q)
                    break
            num = big(rng, digits) * rng.choice((-1, 1))
            p.append(f"{num}/{q}")
        pts.append(p)
    return pts


def request(op, pts, rng, digits):
    t = f"{big(rng, digits)}/{big(rng, digits) * 3}"
    if op == "elevate":
        return {"id": 1, "op": "elevate", "points": pts, "by": 1}
    if op == "eval":
        return {"id": 1, "op": "eval", "points": pts, "t": t}
    if op == "split":
        return {"id": 1, "op": "split", "points": pts, "t": t}
    if op == "derivative":
        return {"id": 1, "op": "derivative", "points": pts, "order": 1}
    if op == "read":
        return {"id": 1, "op": "eval", "points": pts, "t": "0"}
    raise ValueError(op)


def oracle_cpu(binary, line):
    """CPU seconds of one oracle process answering `line`, and its answer."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    out = subprocess.run([binary, "oracle"], input=line, capture_output=True, text=True, check=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    first = out.stdout.split("\n", 1)[0]
    return cpu, (json.loads(first) if first.strip() else None)


def empty_cpu(binary):
    return oracle_cpu(binary, "")[0]


# Operations whose Python peers are timed: linear work. eval and split at a big t are
# de Casteljau's triangle in Python (seconds to minutes at degree 200): the oracle alone.
PEERS = ("elevate", "derivative", "read")


def fmt(x):
    return f"{x.numerator}/{x.denominator}" if x.denominator != 1 else str(x.numerator)


def python_op_repeated(op, line, make, repeat):
    """python_op `repeat` times: CPU seconds per request, and the answer."""
    start = time.process_time()
    for _ in range(repeat):
        text = python_op(op, line, make)[1]
    return (time.process_time() - start) / repeat, text


def python_op(op, line, make):
    """The request answered on the number type `make` (Fraction or gmpy2.mpq): parse,
    compute, print."""
    start = time.process_time()
    req = json.loads(line)
    pts = [[make(c) for c in p] for p in req["points"]]
    n = len(pts) - 1
    if op == "elevate":
        m = n + 1
        out = [pts[0]]
        for i in range(1, m):
            a = make(i, m)
            b = 1 - a
            out.append([a * x + b * y for x, y in zip(pts[i - 1], pts[i])])
        out.append(pts[n])
        ans = {"points": out}
    elif op == "read":
        # eval at t = 0: the answer is the first point; what is timed is reading and printing.
        ans = {"point": pts[0]}
    elif op in ("eval", "split"):
        t = make(req["t"])
        s = 1 - t
        left, right = [pts[0]], [pts[n]]
        cur = pts
        while len(cur) > 1:
            cur = [[s * x + t * y for x, y in zip(p, q)] for p, q in zip(cur, cur[1:])]
            left.append(cur[0])
            right.append(cur[-1])
        ans = {"point": cur[0]} if op != "split" else {"left": left, "right": right[::-1]}
    elif op == "derivative":
        ans = {"points": [[n * (y - x) for x, y in zip(p, q)] for p, q in zip(pts, pts[1:])]}
    else:
        raise ValueError(op)

    def conv(v):
        if isinstance(v, list):
            return [conv(x) for x in v]
        return fmt(v)

    text = json.dumps({k: conv(v) for k, v in ans.items()})
    return time.process_time() - start, text


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--binary", default=os.path.join(ROOT, "target", "release", "casteljau"))
    ap.add_argument("--digits", type=int, default=100)
    ap.add_argument("--degrees", default="50,100,200,400")
    ap.add_argument("--ops", default="elevate,eval,split,derivative")
    ap.add_argument("--seed", type=int, default=47)
    ap.add_argument("--repeat", type=int, default=1, help="answers per timing (one process)")
    args = ap.parse_args()
    rng = random.Random(args.seed)
    base = empty_cpu(args.binary)
    print(f"oracle start-up (empty input): {base * 1e3:.1f} ms CPU, subtracted below")
    print(f"{'op':<11}{'degree':>7}{'oracle ms':>11}{'fractions':>11}{'gmpy2':>9}{'fr/or':>8}{'gm/or':>8}{'per-deg µs':>12}")
    for op in args.ops.split(","):
        for degree in [int(d) for d in args.degrees.split(",")]:
            pts = curve(rng, degree, args.digits)
            line = json.dumps(request(op, pts, rng, args.digits)) + "\n"
            cpu, ans = oracle_cpu(args.binary, line * args.repeat)
            if not ans.get("ok"):
                print(f"{op:<11}{degree:>7}  refused: {ans.get('error')}")
                continue
            cpu = max(cpu - base, 1e-6) / args.repeat
            if op not in PEERS:
                print(f"{op:<11}{degree:>7}{cpu * 1e3:>11.1f}{'':>11}{'':>9}{'':>8}{'':>8}{cpu / degree * 1e6:>12.0f}")
                continue
            fr, fr_text = python_op_repeated(op, line, Fraction, args.repeat)
            if op == "elevate" and json.loads(fr_text)["points"] != ans["points"]:
                sys.exit("elevate: the oracle's points differ from fractions'")
            gm = python_op_repeated(op, line, gmpy2.mpq, args.repeat)[0] if gmpy2 else float("nan")
            print(
                f"{op:<11}{degree:>7}{cpu * 1e3:>11.1f}{fr * 1e3:>11.1f}{gm * 1e3:>9.1f}"
                f"{fr / cpu:>8.2f}{gm / cpu:>8.2f}{cpu / degree * 1e6:>12.0f}"
            )


if __name__ == "__main__":
    main()
