#!/usr/bin/env python3
"""The conformance survey of docs/peers.md: float Bézier libraries judged by the oracle.

    python3 scripts/survey.py [--seed 44] [--curves 1000] [--pool 2] [--json out.json]
    python3 scripts/survey.py --dask local            # or --dask tcp://scheduler:8786

Builds the oracle and the Rust half (`cargo build --release --bin casteljau --example
peers_survey`), then for every library and op draws `--curves` seeded cases
(`casteljau_oracle.survey.case`: degrees 1–12 planar and 3-D for numpy and `bezier`, 1–3
planar for kurbo and lyon_geom; half ordinary, half ill-conditioned), has the library
answer them in f64 (numpy and `bezier` here, kurbo and lyon_geom in
scripts/peers_survey.rs) and has an `OraclePool` judge every answer against the exact one.
Prints the Markdown table of docs/peers.md (and with --json every record). With --dask the
cases are judged in partitions on a Dask cluster, each task with its own `OraclePool`: the
same table.

Needs numpy and the PyPI package `bezier` (`pip install numpy bezier`).
"""

import argparse
import datetime
import json
import os
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "clients", "python"))

from casteljau_oracle import OraclePool, survey  # noqa: E402


def rust_answers(example):
    def answers(lib, op, cases):
        lines = [json.dumps({"id": c["id"], "lib": lib, "op": op, "points": c["points"], "t": c["t"]}) for c in cases]
        out = subprocess.run([example], input="\n".join(lines) + "\n", capture_output=True, text=True, check=True)
        replies = [json.loads(line) for line in out.stdout.splitlines()]
        if len(replies) != len(cases):
            raise SystemExit(f"peers_survey answered {len(replies)} of {len(cases)} cases")
        for c, r in zip(cases, replies):
            if "error" in r:
                raise SystemExit(f"peers_survey: {r['error']} (case {c['id']}, {lib} {op})")
            # the crate computed on exactly the floats sent
            if r["id"] != c["id"] or r["points"] != c["points"]:
                raise SystemExit(f"peers_survey read case {c['id']} as {r['points']}, not {c['points']}")
        return [r["approx"] for r in replies]

    return answers


def on_dask(args, jobs, binary, example):
    from dask.distributed import Client, LocalCluster

    # the workers import this checkout's client
    here = os.path.join(ROOT, "clients", "python")
    os.environ["PYTHONPATH"] = os.pathsep.join(filter(None, [here, os.environ.get("PYTHONPATH")]))
    if args.dask == "local":
        cluster = LocalCluster(n_workers=args.pool, threads_per_worker=1, dashboard_address=None)
        client = Client(cluster)
    else:
        cluster, client = None, Client(args.dask)
    try:
        return [
            r
            for lib, op in jobs
            for r in survey.run_on_dask(
                client, lib, op, args.seed, args.curves, args.partitions, binary=binary, rust_answers=example
            )
        ]
    finally:
        client.close()
        if cluster is not None:
            cluster.close()


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--seed", type=int, default=44)
    ap.add_argument("--curves", type=int, default=1000, help="cases per library and op")
    ap.add_argument("--pool", type=int, default=2, help="oracle processes")
    ap.add_argument("--libs", default="numpy,bezier,kurbo,lyon")
    ap.add_argument("--json", help="write every record here")
    ap.add_argument("--no-build", action="store_true", help="use target/release as it is")
    ap.add_argument(
        "--dask",
        metavar="ADDRESS",
        help="run on a Dask cluster: a scheduler's address, or 'local' for a local cluster of --pool workers "
        "(the workers need this checkout's binaries at the same paths)",
    )
    ap.add_argument("--partitions", type=int, default=8, help="Dask tasks per library and op")
    args = ap.parse_args()

    unknown = [lib for lib in args.libs.split(",") if lib not in survey.LIBRARIES]
    if unknown or args.curves < 1 or args.pool < 1 or args.partitions < 1:
        ap.error(f"--libs is a list of {', '.join(survey.LIBRARIES)}; --curves, --pool, --partitions at least 1")
    if not args.no_build:
        subprocess.run(
            ["cargo", "build", "--release", "--bin", "casteljau", "--example", "peers_survey"], cwd=ROOT, check=True
        )
    binary = os.path.join(ROOT, "target", "release", "casteljau")
    example = rust_answers(os.path.join(ROOT, "target", "release", "examples", "peers_survey"))
    started = time.process_time(), time.time()
    records = []
    jobs = [(lib, op) for lib in args.libs.split(",") for op in survey.LIBRARIES[lib][1]]
    if args.dask:
        records = on_dask(args, jobs, binary, example)
    else:
        with OraclePool(args.pool, binary) as pool:
            for lib, op in jobs:
                records += survey.run(lib, op, args.seed, 0, args.curves, rust_answers=example, pool=pool)
    cpu, wall = time.process_time() - started[0], time.time() - started[1]
    print(
        f"<!-- python3 scripts/survey.py --seed {args.seed} --curves {args.curves}"
        f"{f' --dask {args.dask}' if args.dask else ''}; "
        f"{datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d %H:%M} UTC; "
        f"{len(records)} answers judged in {wall:.0f} s wall ({cpu:.0f} s CPU in Python) -->"
    )
    print(survey.markdown(survey.summary(records)))
    if args.json:
        with open(args.json, "w") as f:
            json.dump(records, f)


if __name__ == "__main__":
    main()
