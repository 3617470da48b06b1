#!/usr/bin/env python3
"""The Hunt–Crossley restitution sweep of `hertz-tui sweep`, done by scipy's DOP853.

Same scene (the Fig. 5 preset: steel sphere R = 10 mm on a steel plate at v₀ = 0.3 m/s), same law
F = k·xⁿ·(1 + α·ẋ) with α = 3(1 − e)/(2·v₀) (eq 19), same evenly spaced e from 0.05 to 0.95
(`--points N`, default 2000: each a different impact in scaled variables, which a v₀ sweep of this
law is not — hertz-tui scales one solve to every v₀, docs/physics.md §6.9), same rtol (1e-8, hertz-tui's default; atol 1e-8 of x_e and v₀, as
hertz-tui scales it), same numbers out (x_max, F_max, t_c, v_out, e_out; CSV on stdout). Ends of
contact and the force peak are located as events, as hertz-tui does on its integrators.

Not run by CI or `cargo bench`; `benches/scipy/compare.py` times it against hertz-tui's sweep.
`--compare SCIPY.csv OURS.csv` prints the largest relative difference per quantity between its
CSV and `hertz-tui sweep … --model hunt-crossley --format csv` at the same points.
"""

import csv
import math
import sys

import numpy as np
from scipy.integrate import solve_ivp

# The Fig. 5 preset: eqs 2–4 for a sphere on a plane of the same steel.
E, NU, RHO, R, V0 = 200e9, 0.3, 7800.0, 0.01, 0.3
E_STAR = E / (2.0 * (1.0 - NU**2))
K = 4.0 / 3.0 * E_STAR * math.sqrt(R)
N = 1.5
MASS = RHO * 4.0 / 3.0 * math.pi * R**3
RTOL = 1e-8


def impact(e, v0=V0):
    alpha = 1.5 * (1.0 - e) / v0
    x_e = ((N + 1.0) * MASS * v0**2 / (2.0 * K)) ** (1.0 / (N + 1.0))
    t_e = x_e / v0

    def force(x, v):
        return K * max(x, 0.0) ** N * (1.0 + alpha * v)

    def rhs(_, y):
        return [y[1], -force(y[0], y[1]) / MASS]

    def separation(_, y):
        return y[0]

    separation.terminal, separation.direction = True, -1.0

    def deepest(_, y):
        return y[1]

    deepest.direction = -1.0

    def force_peak(_, y):
        # dF/dt = k·(n·xⁿ⁻¹·v·(1 + αv) + xⁿ·α·a), a = −F/m.
        x, v = max(y[0], 1e-300), y[1]
        f = force(x, v)
        return K * (N * x ** (N - 1.0) * v * (1.0 + alpha * v) - x**N * alpha * f / MASS)

    force_peak.direction = -1.0
    sol = solve_ivp(
        rhs,
        (0.0, 100.0 * t_e),
        [0.0, v0],
        method="DOP853",
        rtol=RTOL,
        atol=[RTOL * x_e, RTOL * v0],
        events=[separation, deepest, force_peak],
    )
    (t_end,), (y_deep, *_), peaks = sol.t_events[0], sol.y_events[1], sol.y_events[2]
    f_max = max(force(y[0], y[1]) for y in peaks)
    v_out = -sol.y_events[0][0][1]
    return y_deep[0], f_max, t_end, v_out, v_out / v0


def sweep(points):
    out = csv.writer(sys.stdout, lineterminator="\n")
    out.writerow(["impact.restitution", "x_max", "f_max", "t_contact", "v_out", "e_out"])
    for e in np.linspace(0.05, 0.95, points):
        out.writerow([repr(float(e))] + [repr(float(q)) for q in impact(e)])


def compare(scipy_csv, ours_csv):
    """Largest relative difference per quantity between the two sweeps' CSVs."""
    with open(scipy_csv) as f:
        theirs = list(csv.DictReader(f))
    with open(ours_csv) as f:
        ours = list(csv.DictReader(f))
    assert len(theirs) == len(ours), (len(theirs), len(ours))
    for field in ["x_max", "f_max", "t_contact", "v_out", "e_out"]:
        worst = max(
            abs(float(a[field]) / float(b[f"hunt-crossley.{field}"]) - 1.0)
            for a, b in zip(theirs, ours)
        )
        print(f"{field}: worst relative difference {worst:.1e}")


if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[1] == "--compare":
        compare(sys.argv[2], sys.argv[3])
    elif len(sys.argv) == 3 and sys.argv[1] == "--points":
        sweep(int(sys.argv[2]))
    elif len(sys.argv) == 1:
        sweep(2000)
    else:
        sys.exit("usage: hc_sweep.py [--points N] | --compare SCIPY.csv OURS.csv")
