#!/usr/bin/env python3
"""Two builds of hertz-tui on the same sweep, run in interleaved pairs: CPU time and work per law.

Runs the v₀ sweep of the Fig. 5 scene (0.01–1 m/s, log-spaced, CSV to /dev/null) with every law,
alternately by the binary `--old` and the binary `--new`, `--pairs` times, each whole process
under `nice`, and prints the load average before and after, each run's user and system CPU time
(its own child rusage, so the machine's load stretches the wall time more than these), the
median new/old ratio of user time, and per integrated law both binaries' accepted and rejected
steps and force evaluations on the scene at v₀ = 0.01, 0.3 and 1 m/s (`solve --format json`:
deterministic, independent of load).

    cargo build --release && cp target/release/hertz-tui /tmp/hertz-tui-new
    git stash && cargo build --release && cp target/release/hertz-tui /tmp/hertz-tui-old && git stash pop
    python3 benches/sweep_pair.py --old /tmp/hertz-tui-old --new /tmp/hertz-tui-new

Options: `--points N` (default 100000), `--pairs K` (default 3). Standard library only; at the
default size each run takes about 10 s of CPU.
"""

import argparse
import json
import os
import statistics
import subprocess
import sys

SCENE = "fig5-steel-sphere-r10-plate"
V0S = ("0.01", "0.3", "1")


def run_cpu(binary, points):
    """(user s, system s) of one whole sweep process."""
    command = [
        "nice", binary, "sweep", "--scene", SCENE, "--param", "impact.v0", "--from", "0.01",
        "--to", "1", "--points", str(points), "--log", "--format", "csv",
    ]
    with open(os.devnull, "w") as out:
        child = subprocess.Popen(command, stdout=out)
        _, status, usage = os.wait4(child.pid, 0)
    if status != 0:
        sys.exit(f"{binary} sweep failed with status {status}")
    return usage.ru_utime, usage.ru_stime


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
    args = parser.parse_args()
    for binary in (args.old, args.new):
        if not os.path.exists(binary):
            sys.exit(f"{binary} not found")
    load_before = os.getloadavg()
    ratios = []
    print(f"{args.points} points, every law; CPU s (user + system) of each whole process")
    print(f"{'pair':>4} {'old user':>9} {'old sys':>8} {'new user':>9} {'new sys':>8} {'new/old':>8}")
    for k in range(args.pairs):
        old = run_cpu(args.old, args.points)
        new = run_cpu(args.new, args.points)
        ratios.append(new[0] / old[0])
        print(f"{k + 1:>4} {old[0]:>9.2f} {old[1]:>8.2f} {new[0]:>9.2f} {new[1]:>8.2f} "
              f"{ratios[-1]:>8.3f}")
    load_after = os.getloadavg()
    print(f"median new/old user time {statistics.median(ratios):.3f}; load average before "
          f"{load_before[0]:.2f}, after {load_after[0]:.2f} (1 min); {os.cpu_count()} cores")
    print(f"{'law':<24} {'v0':>5} {'old steps/rej/evals':>20} {'new steps/rej/evals':>20}")
    for v0 in V0S:
        old, new = work(args.old, v0), work(args.new, v0)
        for law in old:
            o, n = old[law], new.get(law, (0, 0, 0))
            print(f"{law:<24} {v0:>5} {'/'.join(map(str, o)):>20} {'/'.join(map(str, n)):>20}")


if __name__ == "__main__":
    main()
