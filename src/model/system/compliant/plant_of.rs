//! The systems of [`SystemSpec`](super::super::SystemSpec) as the compliant solver's [`Plant`].

use std::f64::consts::PI;

use super::super::{SystemKind, SystemModel};
use super::plant::{Plant, StopMotion};

/// A system's motion out of contact and its stops, with the constants evaluated once.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SystemPlant {
    /// ẍ = −g; the table s = A·sin(ωt) below the ball.
    Ball {
        mass: f64,
        amplitude: f64,
        omega: f64,
        gravity: f64,
    },
    /// ẍ = −2ζω₀ẋ − ω₀²x + f·cos(ωt) (in the frame for base forcing); stops at x = gap (the body
    /// below it) and x = −second_gap (the body above it).
    Oscillator {
        mass: f64,
        omega0: f64,
        zeta: f64,
        forcing: f64,
        omega: f64,
        gap: f64,
        second_gap: Option<f64>,
    },
}

impl SystemPlant {
    pub fn of(model: &SystemModel) -> SystemPlant {
        let spec = &model.spec;
        match spec.kind {
            SystemKind::BouncingBall {
                amplitude, gravity, ..
            } => SystemPlant::Ball {
                mass: model.mass,
                amplitude,
                omega: spec.omega(),
                gravity,
            },
            SystemKind::ImpactOscillator {
                gap, second_gap, ..
            } => {
                // `oscillator` is Some for every oscillator kind.
                let c = spec.oscillator(model.mass);
                let (omega0, zeta, forcing, omega) = c.map_or((0.0, 0.0, 0.0, spec.omega()), |c| {
                    (c.omega0, c.zeta, c.forcing, c.omega)
                });
                SystemPlant::Oscillator {
                    mass: model.mass,
                    omega0,
                    zeta,
                    forcing,
                    omega,
                    gap,
                    second_gap,
                }
            }
        }
    }

    /// The forcing angular frequency ω, rad/s.
    pub fn omega(&self) -> f64 {
        match *self {
            SystemPlant::Ball { omega, .. } | SystemPlant::Oscillator { omega, .. } => omega,
        }
    }
}

impl Plant for SystemPlant {
    fn mass(&self) -> f64 {
        match *self {
            SystemPlant::Ball { mass, .. } | SystemPlant::Oscillator { mass, .. } => mass,
        }
    }

    #[inline]
    fn free_accel(&self, t: f64, x: f64, v: f64) -> f64 {
        match *self {
            SystemPlant::Ball { gravity, .. } => -gravity,
            SystemPlant::Oscillator {
                omega0,
                zeta,
                forcing,
                omega,
                ..
            } => -2.0 * zeta * omega0 * v - omega0 * omega0 * x + forcing * (omega * t).cos(),
        }
    }

    fn stop_count(&self) -> usize {
        match self {
            SystemPlant::Oscillator {
                second_gap: Some(_),
                ..
            } => 2,
            _ => 1,
        }
    }

    #[inline]
    fn stop(&self, i: usize, t: f64) -> StopMotion {
        match *self {
            SystemPlant::Ball {
                amplitude, omega, ..
            } => {
                let (sin, cos) = (omega * t).sin_cos();
                StopMotion {
                    side: 1.0,
                    s: amplitude * sin,
                    sd: amplitude * omega * cos,
                    sdd: -amplitude * omega * omega * sin,
                }
            }
            SystemPlant::Oscillator {
                gap, second_gap, ..
            } => {
                let (side, s) = match (i, second_gap) {
                    (1, Some(g2)) => (1.0, -g2),
                    _ => (-1.0, gap),
                };
                StopMotion {
                    side,
                    s,
                    sd: 0.0,
                    sdd: 0.0,
                }
            }
        }
    }

    fn period(&self) -> f64 {
        2.0 * PI / self.omega()
    }

    fn accel_scale(&self) -> f64 {
        match *self {
            SystemPlant::Ball {
                amplitude,
                omega,
                gravity,
                ..
            } => gravity.max(amplitude * omega * omega),
            SystemPlant::Oscillator {
                omega0,
                forcing,
                gap,
                ..
            } => forcing.abs().max(omega0 * omega0 * gap),
        }
    }
}
