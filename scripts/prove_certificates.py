#!/usr/bin/env python3
"""What do certificates cost? `casteljau prove` against `prove --certificates DIR` over the
texts' claims, and `casteljau check DIR` over the certificates written, in CPU time.

Runs, interleaved per round: `prove`, `prove --certificates` into a new empty folder, and
`check` of that folder; checks that every run exits 0, and prints each run's CPU time (user +
system of the child, getrusage, every thread counted), the medians, and the ratio of the
certificate run's median to the plain one's with the spread [min, max] of the certificate
runs over the plain median.

  cargo build --release
  python3 scripts/prove_certificates.py [--rounds 7] [--binary target/release/casteljau]

Standard library only.
"""

import argparse
import pathlib
import resource
import statistics
import subprocess
import tempfile


def cpu_seconds(args: list) -> float:
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    run = subprocess.run(args, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if run.returncode != 0:
        raise SystemExit(f"{' '.join(args)} exited {run.returncode}: {run.stderr.decode()[-500:]}")
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--rounds", type=int, default=7)
    parser.add_argument("--binary", default="target/release/casteljau")
    args = parser.parse_args()
    times = {"prove": [], "certificates": [], "check": []}
    with tempfile.TemporaryDirectory() as tmp:
        for k in range(args.rounds):
            out = pathlib.Path(tmp) / f"run{k}"
            times["prove"].append(cpu_seconds([args.binary, "prove"]))
            times["certificates"].append(cpu_seconds([args.binary, "prove", "--certificates", str(out)]))
            times["check"].append(cpu_seconds([args.binary, "check", str(out)]))
    plain = statistics.median(times["prove"])
    for name, ts in times.items():
        runs = " ".join(f"{x:.3f}" for x in ts)
        print(f"{name:12} {runs}  median {statistics.median(ts):.3f} s")
    cert = times["certificates"]
    print(
        f"prove --certificates / prove: {statistics.median(cert) / plain:.3f} "
        f"[{min(cert) / plain:.3f}, {max(cert) / plain:.3f}]"
    )


if __name__ == "__main__":
    main()
