//! The `[system]` table of a scene resolved to SI units: which machine the two bodies sit in.
#![warn(missing_docs)]

use std::f64::consts::PI;

use crate::model::error::{ModelError, require, require_positive};

/// Standard gravity, m/s² (the default of `system.gravity`).
pub const STANDARD_GRAVITY: f64 = 9.80665;

/// A vibro-impact system: the machine the scene's body 1 moves in, body 2 being its stop.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SystemSpec {
    /// Which system, with its parameters in SI units.
    pub kind: SystemKind,
}

/// The systems hertz-tui knows (docs/systems.md).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SystemKind {
    /// A ball bouncing under gravity on a table that moves as s(t) = A·sin(ωt).
    BouncingBall {
        /// Table amplitude A, m.
        amplitude: f64,
        /// Forcing frequency f = ω/2π, Hz.
        frequency: f64,
        /// Gravity g, m/s².
        gravity: f64,
    },
    /// A body of mass m on a spring k and a damper c, forced harmonically as cos(ωt), with a stop
    /// at x = gap and optionally a second at x = −second_gap (a clearance). x is the body's
    /// displacement from its rest position (relative to the moving frame under base forcing).
    ImpactOscillator {
        /// Spring stiffness k, N/m.
        stiffness: f64,
        /// Viscous damping, as the file gave it.
        damping: Damping,
        /// Harmonic force on the body or harmonic motion of the frame.
        forcing: Forcing,
        /// Forcing frequency f = ω/2π, Hz.
        frequency: f64,
        /// Distance from rest to the stop on the positive side, m (> 0).
        gap: f64,
        /// Distance from rest to a stop on the negative side, m (> 0), if there is one.
        second_gap: Option<f64>,
    },
}

/// Viscous damping of the oscillator: a ratio ζ = c/(2√(km)) or a coefficient c.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Damping {
    /// ζ, dimensionless (`system.damping_ratio`).
    Ratio(f64),
    /// c, N·s/m (`system.damping`).
    Coefficient(f64),
}

/// The oscillator's harmonic excitation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Forcing {
    /// A force F₀·cos(ωt) on the body; amplitude F₀ in N.
    Force {
        /// F₀, N.
        amplitude: f64,
    },
    /// The frame (spring, damper and stops) moves as B·cos(ωt); amplitude B in m. In the frame
    /// this is the force m·B·ω²·cos(ωt).
    Base {
        /// B, m.
        amplitude: f64,
    },
}

/// The dimensionless groups a specialist reads (None where the system has no such group).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Groups {
    /// Γ = A·ω²/g (bouncing ball).
    pub gamma: Option<f64>,
    /// ω/ω₀ with ω₀ = √(k/m) (oscillator).
    pub frequency_ratio: Option<f64>,
    /// ζ = c/(2√(km)) (oscillator).
    pub damping_ratio: Option<f64>,
    /// gap / (amplitude of the free linear response at ω = 0: F₀/k, or B): the gap in units of
    /// the static deflection (oscillator).
    pub gap_ratio: Option<f64>,
    /// second_gap in the same units (oscillator with a clearance).
    pub second_gap_ratio: Option<f64>,
}

/// The oscillator's equation of motion per unit mass: ẍ + 2ζω₀ẋ + ω₀²x = f·cos(ωt).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OscillatorCoefficients {
    /// ω₀ = √(k/m), rad/s.
    pub omega0: f64,
    /// ζ.
    pub zeta: f64,
    /// f, m/s² (F₀/m, or B·ω²).
    pub forcing: f64,
    /// ω, rad/s.
    pub omega: f64,
}

impl SystemSpec {
    /// The forcing angular frequency ω = 2πf, rad/s.
    pub fn omega(&self) -> f64 {
        2.0 * PI * self.frequency()
    }

    /// The forcing frequency f, Hz.
    pub fn frequency(&self) -> f64 {
        match self.kind {
            SystemKind::BouncingBall { frequency, .. }
            | SystemKind::ImpactOscillator { frequency, .. } => frequency,
        }
    }

    /// The forcing period 1/f, s.
    pub fn period(&self) -> f64 {
        1.0 / self.frequency()
    }

    /// The kind's name in scene files: `bouncing-ball` or `impact-oscillator`.
    pub fn kind_name(&self) -> &'static str {
        match self.kind {
            SystemKind::BouncingBall { .. } => "bouncing-ball",
            SystemKind::ImpactOscillator { .. } => "impact-oscillator",
        }
    }

    /// How many stops the body can hit (1 or 2).
    pub fn stops(&self) -> usize {
        match self.kind {
            SystemKind::ImpactOscillator {
                second_gap: Some(_),
                ..
            } => 2,
            _ => 1,
        }
    }

    /// The oscillator's coefficients per unit mass for a body of `mass` kg; None for the ball.
    pub fn oscillator(&self, mass: f64) -> Option<OscillatorCoefficients> {
        match self.kind {
            SystemKind::BouncingBall { .. } => None,
            SystemKind::ImpactOscillator {
                stiffness,
                damping,
                forcing,
                ..
            } => {
                let omega0 = (stiffness / mass).sqrt();
                let zeta = match damping {
                    Damping::Ratio(zeta) => zeta,
                    Damping::Coefficient(c) => c / (2.0 * (stiffness * mass).sqrt()),
                };
                let omega = self.omega();
                let forcing = match forcing {
                    Forcing::Force { amplitude } => amplitude / mass,
                    Forcing::Base { amplitude } => amplitude * omega * omega,
                };
                Some(OscillatorCoefficients {
                    omega0,
                    zeta,
                    forcing,
                    omega,
                })
            }
        }
    }

    /// The dimensionless groups for a body of `mass` kg.
    pub fn groups(&self, mass: f64) -> Groups {
        match self.kind {
            SystemKind::BouncingBall {
                amplitude, gravity, ..
            } => Groups {
                gamma: Some(amplitude * self.omega().powi(2) / gravity),
                ..Groups::default()
            },
            SystemKind::ImpactOscillator {
                stiffness,
                forcing,
                gap,
                second_gap,
                ..
            } => {
                let Some(c) = self.oscillator(mass) else {
                    return Groups::default();
                };
                let deflection = match forcing {
                    Forcing::Force { amplitude } => amplitude / stiffness,
                    Forcing::Base { amplitude } => amplitude,
                };
                Groups {
                    gamma: None,
                    frequency_ratio: Some(c.omega / c.omega0),
                    damping_ratio: Some(c.zeta),
                    gap_ratio: Some(gap / deflection),
                    second_gap_ratio: second_gap.map(|g| g / deflection),
                }
            }
        }
    }

    /// Checks every parameter; errors name the scene key (`system.gap`, `system.frequency`, …).
    pub fn validate(&self) -> Result<(), ModelError> {
        require_positive("system.frequency", self.frequency())?;
        match self.kind {
            SystemKind::BouncingBall {
                amplitude, gravity, ..
            } => {
                require(
                    "system.amplitude",
                    amplitude,
                    "a finite number ≥ 0",
                    |a| a >= 0.0,
                )?;
                require_positive("system.gravity", gravity)?;
            }
            SystemKind::ImpactOscillator {
                stiffness,
                damping,
                forcing,
                gap,
                second_gap,
                ..
            } => {
                require_positive("system.stiffness", stiffness)?;
                match damping {
                    // The rigid solver's flight is the underdamped closed form (docs/systems.md §2).
                    Damping::Ratio(zeta) => require(
                        "system.damping_ratio",
                        zeta,
                        "in [0, 1) (underdamped)",
                        |z| (0.0..1.0).contains(&z),
                    )?,
                    Damping::Coefficient(c) => {
                        require("system.damping", c, "a finite number ≥ 0", |c| c >= 0.0)?
                    }
                };
                let amplitude = match forcing {
                    Forcing::Force { amplitude } | Forcing::Base { amplitude } => amplitude,
                };
                require(
                    "system.forcing_amplitude",
                    amplitude,
                    "a finite number",
                    |_| true,
                )?;
                require(
                    "system.gap",
                    gap,
                    "> 0 (the body starts at rest at x = 0; a gap ≤ 0 starts it inside the stop)",
                    |g| g > 0.0,
                )?;
                if let Some(second) = second_gap {
                    require(
                        "system.second_gap",
                        second,
                        "> 0 (the body starts at rest at x = 0; a gap ≤ 0 starts it inside the stop)",
                        |g| g > 0.0,
                    )?;
                }
            }
        }
        Ok(())
    }

    /// [`SystemSpec::validate`] plus what needs the body's mass: an underdamped coefficient `c`.
    pub fn validate_with_mass(&self, mass: f64) -> Result<(), ModelError> {
        self.validate()?;
        if let SystemKind::ImpactOscillator {
            damping: Damping::Coefficient(c),
            ..
        } = self.kind
            && let Some(coefficients) = self.oscillator(mass)
            && coefficients.zeta >= 1.0
        {
            return Err(ModelError::InvalidParameter {
                field: "system.damping".into(),
                requirement: "below critical damping 2·√(k·m) (the rigid solver's flight is the underdamped closed form)",
                value: c,
            });
        }
        Ok(())
    }
}
