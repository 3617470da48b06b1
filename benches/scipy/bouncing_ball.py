#!/usr/bin/env python3
"""The bouncing-ball bifurcation diagram of `cargo bench --bench systems`, done by scipy.

The steel sphere R = 10 mm on a steel plate (the `steel-sphere-r10-plate` preset's bodies) bounces
under gravity g = 9.81 m/s² on a table moving as A·sin(ωt); e = 0.5; Γ = Aω²/g from 0.9 to 3.5 in
`--values` steps (default 1000), `--transient` impacts (500) then `--recorded` (200) per value, each
value starting from where the previous one ended (the attractor followed), the forcing frequency set
so that the elastic contact at the period-1 orbit's impact speed gT/(1+e) lasts 1 % of the period
(eq 7), as the Rust benchmark does.

Two stops, as in the Rust benchmark:
- `--stop rigid`: flight by solve_ivp (DOP853) with a terminal event on the gap y − A·sin(ωt),
  Newton's restitution at the event; chatter whose accumulation time 2v/(a(1 − e)) (a = g + s̈) is
  under 1e-6 of a period is summed in closed form, and the ball rides the table until its
  acceleration −Aω²·sin(ωt) drops below −g (a closed-form arcsin), or for ever — as hertz-tui
  does (docs/systems.md §4). A hop lower than the flights' absolute tolerance on the height (which
  solve_ivp's event cannot resolve: the ball would fall through the table) lands in closed form
  after 2v/a at the speed it left, for both stops; a value that ends with the ball on the table
  starts the next there.
- `--stop hunt-crossley`: flights as above; each contact by solve_ivp (DOP853) in the table's frame,
  δ̈ = s̈ + g − F/m with F = k·δⁿ·(1 + α·δ̇) and α = χ/v_in, χ the exact χ(e) (its realised e is
  e: ln((1 + χ)/(1 − χ·e)) = χ·(1 + e)), a terminal event at δ = 0 (and at F = 0, the
  compressive-only cutoff); a contact held for 4 periods ends the value (the ball rests).

Tolerances: rtol 1e-8 on both (atol 1e-8 of the contact's x_e and v_in, of g·T² and g·T in flight),
as `cargo bench --bench systems` runs hertz-tui. Prints impacts, wall and CPU time, µs per impact.
`--every K` runs only every K-th Γ value (the diagram's per-impact cost from a sample of it: the full
diagram takes scipy hours; `--every 20`, 50 values, gives tens of thousands of impacts). `--csv FILE` writes (Γ, impact speed) of the recorded impacts.

Standard scipy; not run by CI. See docs/performance.md ("Vibro-impact diagrams").
"""

import argparse
import math
import time

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

# Bodies of the preset: steel (E = 200 GPa, ν = 0.3, ρ = 7800 kg/m³) sphere R = 10 mm on a steel
# plane; eqs 2–4.
E_YOUNG, NU, RHO, R = 200e9, 0.3, 7800.0, 0.01
E_STAR = E_YOUNG / (2.0 * (1.0 - NU**2))
K = 4.0 / 3.0 * E_STAR * math.sqrt(R)
N = 1.5
MASS = RHO * 4.0 / 3.0 * math.pi * R**3
G = 9.81
E_REST = 0.5
RTOL = 1e-8
CONTACT_RATIO = 0.01
HELD_PERIODS = 4.0


def contact_time(v):
    """Eq 7: t_c = (2·x_max/v)·B(1/(n+1), 1/2)/(n+1)."""
    a = 1.0 / (N + 1.0)
    x_max = ((N + 1.0) * MASS * v * v / (2.0 * K)) ** a
    beta = math.gamma(a) * math.gamma(0.5) / math.gamma(a + 0.5)
    return 2.0 * x_max / v * a * beta


def frequency():
    """The f at which the contact at gT/(1+e) lasts CONTACT_RATIO of T (t_c ∝ v^(−1/5))."""
    c1 = contact_time(1.0)
    return (CONTACT_RATIO / c1 * (G / (1.0 + E_REST)) ** 0.2) ** (5.0 / 6.0)


def exact_chi(e):
    """χ with ln((1 + χ)/(1 − χ·e)) = χ·(1 + e) (docs/physics.md §6.4)."""
    return brentq(lambda c: math.log((1.0 + c) / (1.0 - c * e)) - c * (1.0 + e), 1e-3, 1.0 / e - 1e-12)


class Ball:
    def __init__(self, gamma, freq, stop):
        self.omega = 2.0 * math.pi * freq
        self.period = 1.0 / freq
        self.amp = gamma * G / self.omega**2
        self.stop = stop
        self.chi = exact_chi(E_REST)

    def table(self, t):
        s = math.sin(self.omega * t)
        c = math.cos(self.omega * t)
        return self.amp * s, self.amp * self.omega * c, -self.amp * self.omega**2 * s

    def fly(self, t0, y0, v0, t_limit):
        """Flight to the next impact: (t, y, v) there, or None at t_limit."""
        amp, omega = self.amp, self.omega

        def gap(t, y):
            return y[0] - amp * math.sin(omega * t)

        gap.terminal, gap.direction = True, -1.0
        scale = G * self.period**2
        t, y, v = t0, y0, v0
        while t < t_limit:
            sol = solve_ivp(
                lambda _t, z: (z[1], -G),
                (t, t_limit),
                (y, v),
                method="DOP853",
                rtol=RTOL,
                atol=(RTOL * scale, RTOL * G * self.period),
                events=gap,
                max_step=self.period / 32.0,
            )
            if sol.t_events[0].size == 0:
                return None
            te = sol.t_events[0][0]
            ye, ve = sol.y_events[0][0]
            closing = ve - self.amp * omega * math.cos(omega * te) < 0.0
            if te > t or closing:
                return te, ye, ve
            # An event at the start itself on a gap that opens: step off the surface.
            dt = 1e-9 * self.period
            t, y, v = t + dt, y + v * dt - 0.5 * G * dt * dt, v - G * dt
        return None

    def stick_release(self, t):
        """The first time after t at which −Aω²·sin(ωt) < −g, or None (Γ ≤ 1)."""
        ratio = G / (self.amp * self.omega**2)
        if ratio >= 1.0:
            return None
        phase0 = math.asin(ratio)  # sin = ratio: release at ωt = phase0 (mod 2π)
        k = math.ceil((self.omega * t - phase0) / (2.0 * math.pi))
        tr = (phase0 + 2.0 * math.pi * k) / self.omega
        return tr if tr > t else tr + self.period

    def contact(self, t0, v_in, t_limit):
        """Hunt–Crossley contact in the table's frame from δ = 0, δ̇ = v_in: (t, δ̇) at its end."""
        amp, omega = self.amp, self.omega
        # Below the speed whose x_max is the static deflection under the larger of g and Aω², a
        # contact is a settling: α and the scales are taken there, as hertz-tui does.
        x_static = (MASS * max(G, amp * omega**2) / K) ** (1.0 / N)
        v_static = math.sqrt(2.0 * K * x_static ** (N + 1.0) / ((N + 1.0) * MASS))
        v_s = max(v_in, v_static)
        alpha = self.chi / v_s
        x_e = ((N + 1.0) * MASS * v_s * v_s / (2.0 * K)) ** (1.0 / (N + 1.0))

        def rhs(t, z):
            d, dd = z
            force = K * math.copysign(abs(d) ** N, d) * (1.0 + alpha * dd)
            sdd = -amp * omega**2 * math.sin(omega * t)
            return (dd, sdd + G - force / MASS)

        def separation(_t, z):
            return z[0]

        def tension(_t, z):
            return 1.0 + alpha * z[1]

        separation.terminal, separation.direction = True, -1.0
        tension.terminal, tension.direction = True, -1.0
        sol = solve_ivp(
            rhs,
            (t0, t_limit),
            (0.0, v_in),
            method="DOP853",
            rtol=RTOL,
            atol=(RTOL * x_e, RTOL * v_s),
            events=(separation, tension),
            max_step=contact_time(v_s) / 4.0,
        )
        if sol.status != 1:
            return None
        ends = [ev for ev in sol.t_events if ev.size]
        t_end = min(ev[0] for ev in ends)
        return t_end, sol.y[:, -1]

    def release_from(self, t):
        """The ball riding the table from t: the state just after it leaves, or None (Γ ≤ 1)."""
        release = self.stick_release(t)
        if release is None:
            return None
        # Riding the table until release, then off it: after δ = T/1000 the free ball is above the
        # table by about jerk·δ³/6, far above rounding.
        s_r, sd_r, _ = self.table(release)
        dt = 1e-3 * self.period
        return release + dt, s_r + sd_r * dt - 0.5 * G * dt * dt, sd_r - G * dt

    def run(self, state, transient, recorded, speeds):
        """One value: `transient` then `recorded` impacts from state (t, y, v); the end state."""
        t, y, v = state
        t_limit = t + 10000.0 * self.period
        impacts = 0
        low = RTOL * G * self.period**2  # the flights' absolute tolerance on the height, m
        while impacts < transient + recorded:
            s, sd, sdd = self.table(t)
            rise, press = v - sd, G + sdd
            if abs(y - s) <= 1e-9 * self.amp and rise >= 0.0 and press > 0.0 and rise * rise <= 2.0 * press * low:
                # A hop lower than the flights' tolerance (or the ball resting on the table) is
                # below what solve_ivp's event resolves: it lands after 2v/a at the speed it left.
                t = t + 2.0 * rise / press
                s, sd, _ = self.table(t)
                hit = (t, s, sd - rise)
            else:
                # A flight longer than 64 periods means the ball left for good (or sank in): stop.
                hit = self.fly(t, y, v, min(t_limit, t + 64.0 * self.period))
            if hit is None:
                return (t, y, v), impacts
            t, y, v = hit
            s, sd, sdd = self.table(t)
            v_in = sd - v
            impacts += 1
            if impacts > transient:
                speeds.append(v_in)
            if self.stop == "rigid":
                v_out = E_REST * v_in
                # Chatter: flights of 2v/a, 2ev/a, … accumulate at 2v/(a(1 − e)) with the table
                # pressing the ball at a = g + s̈; once that is under 1e-6 of a period it is summed
                # in closed form and the ball rides the table, as hertz-tui does
                # (docs/systems.md §4).
                press = G + sdd
                if press > 0.0 and 2.0 * v_out <= 1e-6 * self.period * press * (1.0 - E_REST):
                    t_acc = t + 2.0 * v_out / (press * (1.0 - E_REST))
                    off = self.release_from(t_acc)
                    if off is None:
                        s, sd, _ = self.table(t_acc)
                        return (t_acc, s, sd), impacts
                    t, y, v = off
                    continue
                y, v = s, sd + v_out
            else:
                end = self.contact(t, v_in, t + HELD_PERIODS * self.period)
                if end is None:
                    return (t, y, v), impacts
                t, (d, dd) = end
                s, sd, _ = self.table(t)
                # Exactly on the surface where the contact ended at δ = 0 (its event lands within
                # rounding of it, possibly inside: the flight's falling-gap event would then miss a
                # hop shorter than its first step), as hertz-tui does.
                if abs(d) < 1e-12:
                    d = 0.0
                y, v = s - d, sd - dd
        return (t, y, v), impacts


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--stop", choices=("rigid", "hunt-crossley"), default="rigid")
    parser.add_argument("--values", type=int, default=1000)
    parser.add_argument("--transient", type=int, default=500)
    parser.add_argument("--recorded", type=int, default=200)
    parser.add_argument("--every", type=int, default=1)
    parser.add_argument("--csv")
    parser.add_argument("--progress", action="store_true", help="a line per value")
    args = parser.parse_args()
    freq = frequency()
    gammas = np.linspace(0.9, 3.5, args.values)[:: args.every]
    wall, cpu = time.perf_counter(), time.process_time()
    state = (0.0, 0.0, 0.0)  # (t, gap over the table, speed relative to it)
    total = 0
    rows = []
    for gamma in gammas:
        ball = Ball(gamma, freq, args.stop)
        # The state carried to the new table at the same gap and speed relative to it (as
        # hertz-tui's diagram does): the tables differ in amplitude.
        t, gap, rise = state
        s, sd, _ = ball.table(t)
        speeds = []
        end, impacts = ball.run((t, s + gap, sd + rise), args.transient, args.recorded, speeds)
        total += impacts
        rows.extend((gamma, v) for v in speeds)
        s, sd, _ = ball.table(end[0])
        if impacts < args.transient + args.recorded:
            # The ball came to rest: the next value starts from rest on the table.
            state = (end[0], 0.0, 0.0)
        else:
            state = (end[0], max(end[1] - s, 0.0), end[2] - sd)
        if args.progress:
            used = time.process_time() - cpu
            print(
                f"  Γ = {gamma:.4f}: {impacts} impacts; so far {total} impacts, CPU {used:.2f} s, "
                f"{1e6 * used / max(total, 1):.1f} µs per impact",
                flush=True,
            )
    wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
    print(
        f"scipy {args.stop}: f = {freq:.3f} Hz, {len(gammas)} values (every {args.every}th of "
        f"{args.values}), {total} impacts, "
        f"wall {wall:.2f} s, CPU {cpu:.2f} s, {1e6 * cpu / max(total, 1):.1f} µs CPU per impact"
    )
    if args.csv:
        with open(args.csv, "w") as out:
            out.write("gamma,v_in\n")
            for gamma, s in rows:
                out.write(f"{gamma!r},{s!r}\n")


if __name__ == "__main__":
    main()
