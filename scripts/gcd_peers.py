#!/usr/bin/env python3
"""The gcd of big naturals: casteljau's `exact::gcd::gcd`, dashu-int's and num-bigint's
(scripts/gcd_peers.rs) against gmpy2's `gcd` and Python's `math.gcd`, on the same pairs.

Groups: random pairs of 2 to 20 words (b bits each), a pair sharing a factor of half
their length, and an unbalanced pair (a of b bits, the other of 100). CPU time per gcd,
median of five batches; ratio = gmpy2 ÷ casteljau.

  cargo build --release --example gcd_peers && python3 scripts/gcd_peers.py [--bits 128,384]
"""

import argparse
import math
import random
import subprocess
import sys
import time
from pathlib import Path

from gmpy2 import gcd as mpz_gcd, mpz

ROOT = Path(__file__).resolve().parent.parent
PAIRS = 64


def groups(rng, bits):
    def n(b):
        return rng.getrandbits(b) | (1 << (b - 1))

    for b in bits:
        yield f"random {b}", [(n(b), n(b)) for _ in range(PAIRS)]
        shared = []
        for _ in range(PAIRS):
            c = n(b // 2)
            shared.append((c * n(b - b // 2), c * n(b - b // 2)))
        yield f"shared {b}", shared
        yield f"unbalanced {b}/100", [(n(b), n(100)) for _ in range(PAIRS)]


def per_gcd(f, pairs):
    once = time.process_time()
    f(pairs)
    once = max(time.process_time() - once, 1e-9)
    reps = max(1, int(0.02 / once))
    means = []
    for _ in range(5):
        start = time.process_time()
        for _ in range(reps):
            f(pairs)
        means.append((time.process_time() - start) / reps / len(pairs))
    means.sort()
    return means[2] * 1e9


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--bits", default="128,192,384,640,1280")
    ap.add_argument("--seed", type=int, default=47)
    args = ap.parse_args()
    rng = random.Random(args.seed)
    exe = ROOT / "target/release/examples/gcd_peers"
    proc = subprocess.Popen([str(exe)], stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
    print(f"{'pairs':<20}{'casteljau':>11}{'dashu':>9}{'num':>9}{'gmpy2':>9}{'math':>9}{'gmpy2/ours':>12}{'dashu/ours':>12}")
    for label, pairs in groups(rng, [int(b) for b in args.bits.split(",")]):
        proc.stdin.write(label + "\t" + " ".join(f"{a},{b}" for a, b in pairs) + "\n")
        proc.stdin.flush()
        _, ours, dashu, num = proc.stdout.readline().rstrip("\n").split("\t")
        ours, dashu, num = float(ours), float(dashu), float(num)
        mp = [(mpz(a), mpz(b)) for a, b in pairs]
        gm = per_gcd(lambda ps: [mpz_gcd(a, b) for a, b in ps], mp)
        py = per_gcd(lambda ps: [math.gcd(a, b) for a, b in ps], pairs)
        print(f"{label:<20}{ours:>9.0f}ns{dashu:>7.0f}ns{num:>7.0f}ns{gm:>7.0f}ns{py:>7.0f}ns{gm / ours:>12.2f}{dashu / ours:>12.2f}")
        sys.stdout.flush()
    proc.stdin.close()
    proc.wait()


if __name__ == "__main__":
    main()
