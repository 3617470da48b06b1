#!/usr/bin/env python3
"""Two builds of hertz-tui on the same sweep, run in interleaved pairs: CPU time and work per law.

Runs the v₀ sweep of the Fig. 5 scene (0.01–1 m/s, log-spaced, CSV to /dev/null) with every law,
alternately by the binary `--old` and the binary `--new`, `--pairs` times, each whole process
under `nice`, and prints the load average before and after, each run's wall time and its user
and system CPU time (its own child rusage, so the machine's load stretches the wall time more
than these), the median new/old ratios of user and wall time, and per integrated law both binaries' accepted and rejected
steps and force evaluations on the scene at v₀ = 0.01, 0.3 and 1 m/s (`solve --format json`:
deterministic, independent of load).

    cargo build --release && cp target/release/hertz-tui /tmp/hertz-tui-new
    git stash && cargo build --release && cp target/release/hertz-tui /tmp/hertz-tui-old && git stash pop
    python3 benches/sweep_pair.py --old /tmp/hertz-tui-old --new /tmp/hertz-tui-new

The 10⁶-point sweep of docs/performance.md, writing its 2.3 GB of CSV to a file as a user would:

    python3 benches/sweep_pair.py --old /tmp/hertz-tui-old --new /tmp/hertz-tui-new \
        --points 1000000 --pairs 1 --csv sweep.csv

Options: `--points N` (default 100000), `--pairs K` (default 3), `--csv PATH` (where each run
writes its CSV, overwritten and removed at the end; default /dev/null). Standard library only; at
the default size each run takes 3–12 s of CPU (this build and the one before the scaling).
"""

import argparse
import json
import os
import statistics
import subprocess
import sys
import time

SCENE = "fig5-steel-sphere-r10-plate"
V0S = ("0.01", "0.3", "1")


def run(binary, points, csv):
    """(user s, system s, wall s) of one whole sweep process."""
    command = [
        "nice", binary, "sweep", "--scene", SCENE, "--param", "impact.v0", "--from", "0.01",
        "--to", "1", "--points", str(points), "--log", "--format", "csv",
    ]
    start = time.monotonic()
    with open(csv, "w") as out:
        child = subprocess.Popen(command, stdout=out)
        _, status, usage = os.wait4(child.pid, 0)
    wall = time.monotonic() - start
    if status != 0:
        sys.exit(f"{binary} sweep failed with status {status}")
    return usage.ru_utime, usage.ru_stime, wall


def work(binary, v0):
    """{law: (steps, rejected, force evaluations)} of the integrated laws at `v0`."""
    impacts = json.loads(
        subprocess.run(
            [binary, "solve", "--scene", SCENE, "--set", f"impact.v0={v0}", "--format", "json"],
            capture_output=True, check=True, text=True,
        ).stdout
    )["impacts"]
    return {
        i["model"]: (i["steps"], i["rejected_steps"], i["force_evals"])
        for i in impacts
        if i["method"] != "exact"
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--old", required=True)
    parser.add_argument("--new", required=True)
    parser.add_argument("--points", type=int, default=100_000)
    parser.add_argument("--pairs", type=int, default=3)
    parser.add_argument("--csv", default=os.devnull)
    args = parser.parse_args()
    for binary in (args.old, args.new):
        if not os.path.exists(binary):
            sys.exit(f"{binary} not found")
    load_before = os.getloadavg()
    ratios, walls = [], []
    print(f"{args.points} points, every law, CSV to {args.csv}; wall s, and CPU s (user, system) "
          "of each whole process")
    print(f"{'pair':>4} {'old wall':>9} {'user':>8} {'sys':>6} {'new wall':>9} {'user':>8} "
          f"{'sys':>6} {'user new/old':>13} {'wall new/old':>13}")
    for k in range(args.pairs):
        old = run(args.old, args.points, args.csv)
        new = run(args.new, args.points, args.csv)
        ratios.append(new[0] / old[0])
        walls.append(new[2] / old[2])
        print(f"{k + 1:>4} {old[2]:>9.2f} {old[0]:>8.2f} {old[1]:>6.2f} {new[2]:>9.2f} "
              f"{new[0]:>8.2f} {new[1]:>6.2f} {ratios[-1]:>13.3f} {walls[-1]:>13.3f}")
    if args.csv != os.devnull:
        os.remove(args.csv)
    load_after = os.getloadavg()
    print(f"median new/old: user time {statistics.median(ratios):.3f}, wall time "
          f"{statistics.median(walls):.3f}; load average before {load_before[0]:.2f}, after "
          f"{load_after[0]:.2f} (1 min); {os.cpu_count()} cores")
    print(f"{'law':<24} {'v0':>5} {'old steps/rej/evals':>20} {'new steps/rej/evals':>20}")
    for v0 in V0S:
        old, new = work(args.old, v0), work(args.new, v0)
        for law in old:
            o, n = old[law], new.get(law, (0, 0, 0))
            print(f"{law:<24} {v0:>5} {'/'.join(map(str, o)):>20} {'/'.join(map(str, n)):>20}")


if __name__ == "__main__":
    main()
