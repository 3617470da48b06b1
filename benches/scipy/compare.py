#!/usr/bin/env python3
"""Per-impact cost of hertz-tui's Hunt–Crossley sweep against scipy's DOP853 doing the same sweep.

The sweep is over e (0.05–0.95 at v₀ = 0.3 m/s), so that every point is an impact of its own:
over v₀ hertz-tui would solve one and scale it (docs/physics.md §6.9), which is not a solver's
cost.

Runs `hertz-tui sweep … --model hunt-crossley` (the best of five runs) and `hc_sweep.py` at the
same point counts, each as a whole process on one core (hertz-tui with RAYON_NUM_THREADS=1; scipy
is single-threaded), and prints for each N the CPU time of each (user + system of the child), the cost
per impact and their ratio, then the marginal cost per impact between the smallest and largest N
(start-up cancels there), the load average before and after, and how far the two sweeps' numbers
are apart at the largest N.

    python3 -m venv /tmp/scipy-venv && /tmp/scipy-venv/bin/pip install scipy
    cargo build --release
    /tmp/scipy-venv/bin/python benches/scipy/compare.py

Options: `--points N …` (default 1000 4000 16000), `--bin PATH` (default
$CARGO_TARGET_DIR/release/hertz-tui or target/release/hertz-tui). With the defaults it runs
about a minute, nearly all of it scipy's (about 2.5 ms an impact).
"""

import argparse
import os
import resource
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
OUR_REPEATS = 5


def default_bin():
    target = os.environ.get("CARGO_TARGET_DIR", os.path.join(HERE, "..", "..", "target"))
    return os.path.join(target, "release", "hertz-tui")


def child_cpu():
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def timed(command, out_path, env=None):
    """CPU seconds (user + system) of one child process writing its stdout to `out_path`."""
    before = child_cpu()
    with open(out_path, "w") as out:
        subprocess.run(command, stdout=out, check=True, env=env)
    return child_cpu() - before


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, nargs="+", default=[1000, 4000, 16000])
    parser.add_argument("--bin", default=default_bin())
    args = parser.parse_args()
    if not os.path.exists(args.bin):
        sys.exit(f"{args.bin} not found: run `cargo build --release` first (or pass --bin)")
    one_core = dict(os.environ, RAYON_NUM_THREADS="1")
    load_before = os.getloadavg()
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        ours_csv, scipy_csv = os.path.join(tmp, "ours.csv"), os.path.join(tmp, "scipy.csv")
        for n in sorted(args.points):
            # The best of five: a run of a few milliseconds is easily doubled by one interruption.
            ours = min(
                timed(
                    [
                        args.bin, "sweep", "--scene", "fig5-steel-sphere-r10-plate",
                        "--param", "impact.restitution", "--from", "0.05", "--to", "0.95",
                        "--points", str(n), "--format", "csv", "--model", "hunt-crossley",
                    ],
                    ours_csv,
                    env=one_core,
                )
                for _ in range(OUR_REPEATS)
            )
            theirs = timed(
                [sys.executable, os.path.join(HERE, "hc_sweep.py"), "--points", str(n)], scipy_csv
            )
            rows.append((n, ours, theirs))
        load_after = os.getloadavg()
        print(f"load average before {load_before[0]:.2f}, after {load_after[0]:.2f} (1 min)")
        print(f"{'points':>8} {'hertz-tui s':>12} {'scipy s':>9} {'µs/impact':>10} "
              f"{'scipy µs/impact':>16} {'ratio':>7}")
        for n, ours, theirs in rows:
            print(f"{n:>8} {ours:>12.3f} {theirs:>9.2f} {1e6 * ours / n:>10.2f} "
                  f"{1e6 * theirs / n:>16.0f} {theirs / ours:>6.0f}×")
        (n0, ours0, theirs0), (n1, ours1, theirs1) = rows[0], rows[-1]
        if n1 > n0:
            ours_m = (ours1 - ours0) / (n1 - n0)
            theirs_m = (theirs1 - theirs0) / (n1 - n0)
            ratio = f"{theirs_m / ours_m:.0f}×" if ours_m > 0 else "n/a (below timer resolution)"
            print(f"marginal cost {n0}→{n1} points: hertz-tui {1e6 * ours_m:.2f} µs, "
                  f"scipy {1e6 * theirs_m:.0f} µs an impact: {ratio}")
        print(f"agreement at {n1} points:")
        sys.stdout.flush()
        subprocess.run(
            [sys.executable, os.path.join(HERE, "hc_sweep.py"), "--compare", scipy_csv, ours_csv],
            check=True,
        )


if __name__ == "__main__":
    main()
