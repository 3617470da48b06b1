#!/usr/bin/env python3
"""Where a default (every-law) `hertz-tui sweep` spends its time, law by law.

Runs the v₀ sweep of the Fig. 5 scene (0.01–1 m/s, log-spaced, CSV to a temporary file) once with
every law and once per law (`--model`), all with the same release binary in one run, and prints
the load average before and after, the whole sweep's wall and CPU time, and per law: how it is
solved (exact or the integrator `auto` picks), its accepted and rejected steps on the scene itself
(`solve --format json`), its CPU time per impact, its share of the per-law sum and its cost
against the elastic closed form's (`quasistatic`).

    cargo build --release
    python3 benches/sweep_laws.py                  # 100 000 points: about 6 s of CPU
    python3 benches/sweep_laws.py --points 1000000 # the 10⁶-point sweep: ten times that

Options: `--points N` (default 100000), `--bin PATH` (default $CARGO_TARGET_DIR/release/hertz-tui
or target/release/hertz-tui). Standard library only.
"""

import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SCENE = "fig5-steel-sphere-r10-plate"


def default_bin():
    target = os.environ.get("CARGO_TARGET_DIR", os.path.join(HERE, "..", "target"))
    return os.path.join(target, "release", "hertz-tui")


def child_cpu():
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def sweep(binary, points, models, out_path):
    """(wall s, CPU s) of one sweep with `models` (every law when empty)."""
    command = [
        binary, "sweep", "--scene", SCENE, "--param", "impact.v0", "--from", "0.01",
        "--to", "1", "--points", str(points), "--log", "--format", "csv",
    ]
    for model in models:
        command += ["--model", model]
    cpu0, wall0 = child_cpu(), time.perf_counter()
    with open(out_path, "w") as out:
        subprocess.run(command, stdout=out, check=True)
    return time.perf_counter() - wall0, child_cpu() - cpu0


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=100_000)
    parser.add_argument("--bin", default=default_bin())
    args = parser.parse_args()
    if not os.path.exists(args.bin):
        sys.exit(f"{args.bin} not found: run `cargo build --release` first (or pass --bin)")
    solved = json.loads(
        subprocess.run(
            [args.bin, "solve", "--scene", SCENE, "--format", "json"],
            capture_output=True, check=True, text=True,
        ).stdout
    )["impacts"]
    load_before = os.getloadavg()
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "sweep.csv")
        wall, cpu = sweep(args.bin, args.points, [], out)
        per_law = [(i, sweep(args.bin, args.points, [i["model"]], out)[1]) for i in solved]
    load_after = os.getloadavg()
    print(f"load average before {load_before[0]:.2f}, after {load_after[0]:.2f} (1 min); "
          f"{os.cpu_count()} cores")
    print(f"every law, {args.points} points: {wall:.2f} s wall, {cpu:.2f} s CPU")
    total = sum(c for _, c in per_law)
    elastic = next(c for i, c in per_law if i["model"] == "quasistatic")
    print(f"{'law':<24} {'method':<8} {'steps':>5} {'rejected':>9} {'µs/point':>9} "
          f"{'share':>6} {'× elastic':>9}")
    for impact, c in per_law:
        steps, rejected = impact["steps"], impact["rejected_steps"]
        tried = steps + rejected
        rate = f"{rejected} ({100 * rejected / tried:.0f} %)" if tried else "–"
        print(f"{impact['model']:<24} {impact['method']:<8} {steps:>5} {rate:>9} "
              f"{1e6 * c / args.points:>9.2f} {100 * c / total:>5.1f}% {c / elastic:>9.1f}")


if __name__ == "__main__":
    main()
