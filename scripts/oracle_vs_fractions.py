#!/usr/bin/env python3
"""`casteljau oracle` against a plain fractions.Fraction server on the same requests.

Writes request files of realistic requests (a seeded generator: curves of degree 3 to 20
in 2 or 3 dimensions whose coordinates are short decimals such as "-12.375" or small
fractions such as "-37/12", a parameter that is a short decimal or a small fraction, and
for elevate 1 to 3 steps), then feeds each file to

  casteljau oracle                       (the release binary)
  python3 scripts/fraction_oracle.py     (fractions.Fraction, standard library only)

and reports the CPU time (user + system, from getrusage of the child) of each, the
requests per CPU second and the ratio Python / casteljau. The two answer files must agree
byte for byte before a ratio is printed. fit_cubic requests (same kind of numbers) are
timed on the oracle alone: CPU time per request.

  cargo build --release
  python3 scripts/oracle_vs_fractions.py [--count 4000] [--runs 3] [--binary target/release/casteljau]

Standard library only.
"""

import argparse
import json
import os
import random
import resource
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def decimal(rng):
    places = rng.randint(0, 4)
    whole = rng.randint(-99999, 99999)
    if places == 0:
        return str(whole // 10)
    sign = "-" if whole < 0 else ""
    digits = str(abs(whole)).rjust(places + 1, "0")
    return f"{sign}{digits[:-places]}.{digits[-places:]}"


def fraction(rng):
    return f"{rng.randint(-999, 999)}/{rng.randint(1, 99)}"


def coordinate(rng, style):
    return decimal(rng) if style == "decimal" or (style == "mixed" and rng.random() < 0.5) else fraction(rng)


def parameter(rng):
    if rng.random() < 0.5:
        return f"0.{rng.randint(1, 999):03d}".rstrip("0")
    q = rng.randint(2, 99)
    return f"{rng.randint(1, q - 1)}/{q}"


def curve(rng):
    n = rng.randint(3, 20)
    dim = rng.choice((2, 2, 3))
    style = rng.choice(("decimal", "fraction", "mixed"))
    return [[coordinate(rng, style) for _ in range(dim)] for _ in range(n + 1)]


def requests(op, count, seed):
    rng = random.Random(seed)
    lines = []
    for i in range(count):
        if op == "split":
            r = {"id": i, "op": "split", "points": curve(rng), "t": parameter(rng)}
        elif op == "elevate":
            r = {"id": i, "op": "elevate", "points": curve(rng), "by": rng.randint(1, 3)}
        else:
            dim = rng.choice((2, 3))
            style = rng.choice(("decimal", "fraction", "mixed"))
            r = {"id": i, "op": "fit_cubic"}
            for name in ("x0", "x1", "xh", "d0", "d1"):
                r[name] = [coordinate(rng, style) for _ in range(dim)]
        lines.append(json.dumps(r, separators=(",", ":")))
    return "\n".join(lines) + "\n"


def run_cpu(cmd, request_path):
    """CPU seconds (user + system) of one child run, and its output."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    with open(request_path, "rb") as f:
        out = subprocess.run(cmd, stdin=f, stdout=subprocess.PIPE, check=True).stdout
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return cpu, out


def spread(times):
    times = sorted(times)
    return times[len(times) // 2], times[0], times[-1]


def fmt(seconds):
    return f"{seconds * 1e3:.1f} ms" if seconds < 10 else f"{seconds:.2f} s"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--count", type=int, default=4000, help="requests per op")
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--binary", default=None)
    args = parser.parse_args()
    target = os.environ.get("CARGO_TARGET_DIR") or os.path.join(ROOT, "target")
    binary = args.binary or os.path.join(target, "release", "casteljau")
    if not os.path.exists(binary):
        sys.exit(f"{binary} not found: cargo build --release first")
    oracle = [binary, "oracle"]
    python = [sys.executable, os.path.join(HERE, "fraction_oracle.py")]

    with tempfile.TemporaryDirectory() as tmp:
        print(f"{'op':<10} {'requests':>8}  {'casteljau CPU (median [min, max])':<34} {'fractions CPU':<28} {'ratio':>7}")
        for op, seed in (("split", 24), ("elevate", 25)):
            path = os.path.join(tmp, f"{op}.jsonl")
            with open(path, "w") as f:
                f.write(requests(op, args.count, seed))
            ours, theirs = [], []
            for _ in range(args.runs):
                cpu, ours_out = run_cpu(oracle, path)
                ours.append(cpu)
                cpu, theirs_out = run_cpu(python, path)
                theirs.append(cpu)
                if ours_out != theirs_out:
                    for a, b in zip(ours_out.splitlines(), theirs_out.splitlines()):
                        if a != b:
                            sys.exit(f"answers differ:\n casteljau: {a[:300]!r}\n fractions: {b[:300]!r}")
                    sys.exit("answers differ in length")
            (om, olo, ohi), (pm, plo, phi) = spread(ours), spread(theirs)
            print(
                f"{op:<10} {args.count:>8}  {fmt(om) + f' [{fmt(olo)}, {fmt(ohi)}]':<34} "
                f"{fmt(pm) + f' [{fmt(plo)}, {fmt(phi)}]':<28} {pm / om:>6.1f}×"
            )
        path = os.path.join(tmp, "fit.jsonl")
        with open(path, "w") as f:
            f.write(requests("fit_cubic", args.count, 26))
        times = []
        for _ in range(args.runs):
            cpu, out = run_cpu(oracle, path)
            times.append(cpu)
        answered = sum(1 for line in out.splitlines() if b'"ok":true' in line)
        m, lo, hi = spread(times)
        per = [t / args.count * 1e3 for t in (m, lo, hi)]
        print(
            f"fit_cubic  {args.count:>8}  {fmt(m)} [{fmt(lo)}, {fmt(hi)}]: {per[0]:.4f} ms CPU per request "
            f"[{per[1]:.4f}, {per[2]:.4f}] ({answered} answered ok, the rest singular)"
        )


if __name__ == "__main__":
    main()
