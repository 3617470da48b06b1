//! The motion between impacts in closed form (docs/systems.md §2): ballistic flight over a table
//! moving as A·sin(ωt), and the damped linear oscillator ẍ + 2αẋ + ω₀²x = f·cos(ωt).
//!
//! Every quantity near a stop is computed as a difference from the flight's start, with the
//! sum-to-product and `expm1` forms, so that a gap of 1e-12 of the system's size is resolved even
//! after many periods (chatter, grazing).

use std::f64::consts::{PI, TAU};

use crate::model::system::{SystemKind, SystemModel};

/// Relative rounding of a gap evaluation, in units of its noise estimate.
const EPS: f64 = f64::EPSILON;

/// The equation of motion between impacts, per unit mass.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Law {
    /// ẍ = −g; the table (stop 0) moves as A·sin(ωt).
    Ball { gravity: f64, amplitude: f64 },
    /// ẍ + 2αẋ + ω₀²x = f·cos(ωt); fixed stops.
    Oscillator {
        alpha: f64,
        omega0_sq: f64,
        omega_d: f64,
        /// The periodic particular solution p(t) = pc·cos(ωt) + ps·sin(ωt).
        pc: f64,
        ps: f64,
        forcing: f64,
    },
}

/// A stop: the gap to it is g = σ·(x − s(t)) ≥ 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Stop {
    /// +1: the stop is below the body (table, stop at −second_gap); −1: above (stop at gap).
    pub sigma: f64,
    /// Its rest position, m (the table's mean level 0, gap, or −second_gap).
    pub position: f64,
}

/// A system's dynamics, resolved once from a [`SystemModel`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Dynamics {
    pub law: Law,
    pub omega: f64,
    pub period: f64,
    pub stops: [Stop; 2],
    pub stop_count: usize,
    /// Restitution e.
    pub restitution: f64,
    /// A speed that sets the scale of the system (bound on |ẍ| times a period), m/s.
    pub speed_scale: f64,
    /// A length that sets the scale of the system, m.
    pub length_scale: f64,
}

impl Dynamics {
    pub(crate) fn new(model: &SystemModel, restitution: f64) -> Dynamics {
        let spec = &model.spec;
        let omega = spec.omega();
        let period = TAU / omega;
        let (law, stops, stop_count, accel) = match spec.kind {
            SystemKind::BouncingBall {
                amplitude, gravity, ..
            } => (
                Law::Ball { gravity, amplitude },
                [
                    Stop {
                        sigma: 1.0,
                        position: 0.0,
                    },
                    Stop {
                        sigma: 1.0,
                        position: f64::NEG_INFINITY,
                    },
                ],
                1,
                gravity + amplitude * omega * omega,
            ),
            SystemKind::ImpactOscillator {
                gap, second_gap, ..
            } => {
                let c = spec.oscillator(model.mass).unwrap_or(
                    crate::model::system::OscillatorCoefficients {
                        omega0: 1.0,
                        zeta: 0.0,
                        forcing: 0.0,
                        omega,
                    },
                );
                let alpha = c.zeta * c.omega0;
                let omega0_sq = c.omega0 * c.omega0;
                // p = Re(P·e^{iωt}), P = f/(ω₀² − ω² + 2iαω).
                let (re, im) = (omega0_sq - omega * omega, 2.0 * alpha * omega);
                let d = re * re + im * im;
                let (p_re, p_im) = (c.forcing * re / d, -c.forcing * im / d);
                let law = Law::Oscillator {
                    alpha,
                    omega0_sq,
                    omega_d: c.omega0 * (1.0 - c.zeta * c.zeta).sqrt(),
                    pc: p_re,
                    ps: -p_im,
                    forcing: c.forcing,
                };
                let upper = Stop {
                    sigma: -1.0,
                    position: gap,
                };
                let lower = Stop {
                    sigma: 1.0,
                    position: -second_gap.unwrap_or(f64::INFINITY),
                };
                let amplitude = p_re.hypot(p_im);
                (
                    law,
                    [upper, lower],
                    if second_gap.is_some() { 2 } else { 1 },
                    omega * omega * amplitude + omega0_sq * gap.max(amplitude),
                )
            }
        };
        Dynamics {
            law,
            omega,
            period,
            stops,
            stop_count,
            restitution,
            speed_scale: accel * period,
            length_scale: accel * period * period,
        }
    }

    /// At rest at `t`: the ball riding on the table, the oscillator's body at x = 0.
    pub(crate) fn rest_state(&self, t: f64) -> crate::model::system::State {
        let (x, v) = match self.law {
            Law::Ball { .. } => {
                let (s, sv, _) = self.stop_motion(0, t);
                (s, sv)
            }
            Law::Oscillator { .. } => (0.0, 0.0),
        };
        crate::model::system::State { t, x, v }
    }

    /// The stop's position, velocity and acceleration at `t`.
    pub(crate) fn stop_motion(&self, stop: usize, t: f64) -> (f64, f64, f64) {
        match self.law {
            Law::Ball { amplitude, .. } => {
                let (s, c) = (self.omega * t).sin_cos();
                let w = self.omega;
                (amplitude * s, amplitude * w * c, -amplitude * w * w * s)
            }
            Law::Oscillator { .. } => (self.stops[stop].position, 0.0, 0.0),
        }
    }

    /// The free acceleration at (t, x, v).
    pub(crate) fn accel(&self, t: f64, x: f64, v: f64) -> f64 {
        match self.law {
            Law::Ball { gravity, .. } => -gravity,
            Law::Oscillator {
                alpha,
                omega0_sq,
                forcing,
                ..
            } => forcing * (self.omega * t).cos() - 2.0 * alpha * v - omega0_sq * x,
        }
    }

    /// The acceleration pressing a body at rest on `stop` into it, as c₀ + c₁·cos(ωt) + c₂·sin(ωt):
    /// the contact force over m while it sticks (docs/systems.md §4).
    pub(crate) fn pressing(&self, stop: usize) -> (f64, f64, f64) {
        let Stop { sigma, position } = self.stops[stop];
        match self.law {
            // a = g + s̈ = g − Aω²·sin(ωt)
            Law::Ball { gravity, amplitude } => {
                (gravity, 0.0, -amplitude * self.omega * self.omega)
            }
            // a = −σ·(f·cos(ωt) − ω₀²·s)
            Law::Oscillator {
                omega0_sq, forcing, ..
            } => (sigma * omega0_sq * position, -sigma * forcing, 0.0),
        }
    }

    /// The pressing acceleration at `t`.
    pub(crate) fn pressing_at(&self, stop: usize, t: f64) -> f64 {
        let (c0, c1, c2) = self.pressing(stop);
        let (s, c) = (self.omega * t).sin_cos();
        c0 + c1 * c + c2 * s
    }

    /// When a body stuck on `stop` since `t` leaves it: the first time ≥ t where the pressing
    /// acceleration turns negative (the contact force would turn tensile), and how long it stays
    /// negative from there (∞ if for ever). None: it never leaves.
    pub(crate) fn release(&self, stop: usize, t: f64) -> Option<(f64, f64)> {
        let (c0, c1, c2) = self.pressing(stop);
        let r = c1.hypot(c2);
        if c0 >= r {
            return None;
        }
        if c0 <= -r {
            return Some((t, f64::INFINITY));
        }
        // c₁cos θ' + c₂ sin θ' = r·cos(θ' − ψ): a = c₀ + r·cos θ with θ = ωt − ψ.
        let psi = c2.atan2(c1);
        let theta_r = (-c0 / r).acos();
        let theta = (self.omega * t - psi).rem_euclid(TAU);
        let window = (TAU - 2.0 * theta_r) / self.omega;
        if theta >= theta_r && theta < TAU - theta_r {
            return Some((t, (TAU - theta_r - theta) / self.omega));
        }
        let ahead = (theta_r - theta).rem_euclid(TAU) / self.omega;
        Some((t + ahead, window))
    }

    /// The longest a lift-off from rest at a stop is certainly free while the pressing
    /// acceleration stays negative: ∞ for the ball, half a damped period for the oscillator
    /// (its impulse response is positive there; docs/systems.md §4).
    pub(crate) fn liftoff_horizon(&self) -> f64 {
        match self.law {
            Law::Ball { .. } => f64::INFINITY,
            Law::Oscillator { omega_d, .. } => PI / omega_d,
        }
    }

    /// The free flight from (t0, x0, v0).
    pub(crate) fn flight(&self, t0: f64, x0: f64, v0: f64) -> Flight {
        let (gaps0, bounds) = {
            let mut gaps = [0.0; 2];
            for (j, g) in gaps.iter_mut().enumerate().take(self.stop_count) {
                let (s, _, _) = self.stop_motion(j, t0);
                *g = self.stops[j].sigma * (x0 - s);
            }
            (gaps, [0.0; 2])
        };
        let mut flight = Flight {
            t0,
            x0,
            v0,
            omega: self.omega,
            law: self.law,
            stops: self.stops,
            stop_count: self.stop_count,
            gaps0,
            bounds,
            h0: 0.0,
            b: 0.0,
            phase0: 0.0,
        };
        flight.phase0 = self.omega * t0;
        match self.law {
            Law::Ball { gravity, amplitude } => {
                flight.bounds = [gravity + amplitude * self.omega * self.omega; 2];
            }
            Law::Oscillator {
                alpha,
                omega0_sq,
                omega_d,
                pc,
                ps,
                ..
            } => {
                let (s, c) = flight.phase0.sin_cos();
                let p = pc * c + ps * s;
                let pd = self.omega * (-pc * s + ps * c);
                flight.h0 = x0 - p;
                flight.b = (v0 - pd + alpha * flight.h0) / omega_d;
                let r = flight.h0.hypot(flight.b);
                // |ẍ| ≤ ω²·|P| + ω₀²·R: the particular and the decaying homogeneous parts.
                let bound = self.omega * self.omega * pc.hypot(ps) + omega0_sq * r;
                flight.bounds = [bound; 2];
            }
        }
        flight
    }
}

/// One free flight in closed form.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Flight {
    pub t0: f64,
    pub x0: f64,
    pub v0: f64,
    omega: f64,
    law: Law,
    stops: [Stop; 2],
    pub stop_count: usize,
    /// σ·(x0 − s(t0)) per stop.
    gaps0: [f64; 2],
    /// Bounds on |g''| over the flight, per stop.
    pub bounds: [f64; 2],
    /// Oscillator: homogeneous part h(τ) = e^{−ατ}(h0·cos ω_dτ + b·sin ω_dτ).
    h0: f64,
    b: f64,
    phase0: f64,
}

/// The flight evaluated at τ = t − t0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Point {
    /// x − x0.
    pub dx: f64,
    /// ẋ.
    pub v: f64,
    /// s(t) − s(t0) of the table (0 for fixed stops).
    pub ds: f64,
    /// ṡ(t) of the table.
    pub sv: f64,
    /// An estimate of the rounding in the gaps, m.
    pub noise: f64,
}

impl Flight {
    /// x(t0 + τ) − x0, ẋ, and the table's displacement since t0.
    pub(crate) fn at(&self, tau: f64) -> Point {
        let w = self.omega;
        let half = 0.5 * w * tau;
        let (sh, ch) = half.sin_cos();
        let (sm, cm) = (self.phase0 + half).sin_cos();
        // sin/cos of ωt = (ωt0 + ωτ/2) + ωτ/2.
        let (st, ct) = (sm * ch + cm * sh, cm * ch - sm * sh);
        let phase_noise = EPS * (self.phase0.abs() + w * tau.abs());
        match self.law {
            Law::Ball { gravity, amplitude } => {
                let dx = self.v0 * tau - 0.5 * gravity * tau * tau;
                // sin(ωt) − sin(ωt0) = 2·cos(ωt0 + ωτ/2)·sin(ωτ/2)
                let ds = 2.0 * amplitude * cm * sh;
                Point {
                    dx,
                    v: self.v0 - gravity * tau,
                    ds,
                    sv: amplitude * w * ct,
                    noise: 4.0 * EPS * (self.v0.abs() * tau + 0.5 * gravity * tau * tau + ds.abs())
                        + 2.0 * amplitude * phase_noise,
                }
            }
            Law::Oscillator {
                alpha,
                omega_d,
                pc,
                ps,
                ..
            } => {
                // p(t) − p(t0) by sum-to-product; ṗ(t) directly.
                let dp = 2.0 * sh * (-pc * sm + ps * cm);
                let pv = w * (-pc * st + ps * ct);
                let decay = (-alpha * tau).exp();
                let (sd, cd) = (omega_d * tau).sin_cos();
                let half_d = (0.5 * omega_d * tau).sin();
                // e^{−ατ}·cos(ω_dτ) − 1 = expm1(−ατ)·cos + (cos − 1), cos − 1 = −2·sin²(ω_dτ/2)
                let dh = self.h0 * ((-alpha * tau).exp_m1() * cd - 2.0 * half_d * half_d)
                    + self.b * decay * sd;
                let hv = decay
                    * ((-alpha * self.h0 + omega_d * self.b) * cd
                        - (alpha * self.b + omega_d * self.h0) * sd);
                let amplitude = pc.hypot(ps);
                Point {
                    dx: dp + dh,
                    v: pv + hv,
                    ds: 0.0,
                    sv: 0.0,
                    noise: 8.0 * EPS * (amplitude + self.h0.abs() + self.b.abs())
                        + 2.0 * amplitude * phase_noise,
                }
            }
        }
    }

    /// The gap to `stop` and its rate at a point.
    pub(crate) fn gap(&self, stop: usize, p: &Point) -> (f64, f64) {
        let sigma = self.stops[stop].sigma;
        (
            self.gaps0[stop] + sigma * (p.dx - p.ds),
            sigma * (p.v - p.sv),
        )
    }

    /// The state transition matrix ∂(x, ẋ)(t0+τ)/∂(x0, ẋ0) (docs/systems.md §5).
    pub(crate) fn transition(&self, tau: f64) -> [[f64; 2]; 2] {
        match self.law {
            Law::Ball { .. } => [[1.0, tau], [0.0, 1.0]],
            Law::Oscillator {
                alpha,
                omega0_sq,
                omega_d,
                ..
            } => {
                let decay = (-alpha * tau).exp();
                let (s, c) = (omega_d * tau).sin_cos();
                [
                    [decay * (c + alpha / omega_d * s), decay * s / omega_d],
                    [
                        -decay * omega0_sq / omega_d * s,
                        decay * (c - alpha / omega_d * s),
                    ],
                ]
            }
        }
    }
}
