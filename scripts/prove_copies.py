#!/usr/bin/env python3
"""Is `casteljau prove` linear in the number of claims? One copy of the texts' claims
(`proofs/*.toml`) against 16 copies, in CPU time.

Writes, in a temporary folder, `one/` (the claim files as they are), `distinct/` (16
copies whose ids, and every quoted reference to an id — `uses`, `corrects` — carry a
suffix `-cK`, so that no two claims share an id) and `same/` (16 plain copies: ids
repeated across files). Then runs `casteljau prove DIR` on each, interleaved (one,
distinct, one, same, per round), checks that every run exits 0 (every verdict as the
files expect), and prints each run's CPU time (user + system of the child, getrusage,
every thread of the pool counted) and the ratio of each median to the median of `one`,
with the spread [min, max] of the ratios.

  cargo build --release
  python3 scripts/prove_copies.py [--rounds 4] [--binary target/release/casteljau]

Standard library only.
"""

import argparse
import pathlib
import re
import resource
import statistics
import subprocess
import tempfile

COPIES = 16


def write_copies(root: pathlib.Path, proofs: pathlib.Path) -> None:
    files = sorted(proofs.glob("*.toml"))
    ids = set()
    for f in files:
        ids |= set(re.findall(r'^id = "([^"]+)"', f.read_text(), flags=re.M))
    for name in ("one", "distinct", "same"):
        (root / name).mkdir()
    for f in files:
        text = f.read_text()
        (root / "one" / f.name).write_text(text)
        for k in range(COPIES):
            renamed = re.sub(
                r'"([^"\n]+)"',
                lambda m: f'"{m.group(1)}-c{k}"' if m.group(1) in ids else m.group(0),
                text,
            )
            (root / "distinct" / f"c{k:02}_{f.name}").write_text(renamed)
            (root / "same" / f"c{k:02}_{f.name}").write_text(text)


def cpu_seconds(binary: str, folder: pathlib.Path) -> float:
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    run = subprocess.run([binary, "prove", str(folder)], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if run.returncode != 0:
        raise SystemExit(f"prove {folder} exited {run.returncode}: {run.stderr.decode()[-500:]}")
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--rounds", type=int, default=4)
    parser.add_argument("--binary", default="target/release/casteljau")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        root = pathlib.Path(tmp)
        write_copies(root, pathlib.Path("proofs"))
        times = {"one": [], "distinct": [], "same": []}
        for _ in range(args.rounds):
            for name in ("one", "distinct", "one", "same"):
                times[name].append(cpu_seconds(args.binary, root / name))
    one = statistics.median(times["one"])
    for name, ts in times.items():
        runs = " ".join(f"{x:.3f}" for x in ts)
        print(
            f"{name:9} {runs}  median {statistics.median(ts):.3f} s  "
            f"ratio {statistics.median(ts) / one:.2f} [{min(ts) / one:.2f}, {max(ts) / one:.2f}]"
        )


if __name__ == "__main__":
    main()
