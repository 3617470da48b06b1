//! The parameter a bifurcation diagram varies: a `[system]` key, `impact.restitution` or a body key.
#![warn(missing_docs)]

use std::fmt;
use std::str::FromStr;

use crate::model::scene_key::SceneKey;

use super::error::SystemError;
use super::model::SystemModel;
use super::spec::{Damping, Forcing, SystemKind};

/// A `[system]` key that takes a number, plus the derived Γ.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SystemKey {
    /// `system.amplitude` (m).
    Amplitude,
    /// `system.gamma`: Γ = Aω²/g, set through the amplitude (dimensionless).
    Gamma,
    /// `system.frequency` (Hz).
    Frequency,
    /// `system.gravity` (m/s²).
    Gravity,
    /// `system.stiffness` (N/m).
    Stiffness,
    /// `system.damping_ratio`.
    DampingRatio,
    /// `system.damping` (N·s/m).
    Damping,
    /// `system.forcing_amplitude` (N or m).
    ForcingAmplitude,
    /// `system.gap` (m).
    Gap,
    /// `system.second_gap` (m).
    SecondGap,
}

/// What a diagram varies.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Param {
    /// A `[system]` key.
    System(SystemKey),
    /// A scene key (`impact.restitution`, `body1.mass`, …): the model is rebuilt from its scene.
    Scene(SceneKey),
}

impl SystemKey {
    /// Every key, in the order of the scene file.
    pub const ALL: [SystemKey; 10] = [
        SystemKey::Amplitude,
        SystemKey::Gamma,
        SystemKey::Frequency,
        SystemKey::Gravity,
        SystemKey::Stiffness,
        SystemKey::DampingRatio,
        SystemKey::Damping,
        SystemKey::ForcingAmplitude,
        SystemKey::Gap,
        SystemKey::SecondGap,
    ];

    /// The key's name in the `[system]` table.
    pub fn name(self) -> &'static str {
        match self {
            SystemKey::Amplitude => "amplitude",
            SystemKey::Gamma => "gamma",
            SystemKey::Frequency => "frequency",
            SystemKey::Gravity => "gravity",
            SystemKey::Stiffness => "stiffness",
            SystemKey::DampingRatio => "damping_ratio",
            SystemKey::Damping => "damping",
            SystemKey::ForcingAmplitude => "forcing_amplitude",
            SystemKey::Gap => "gap",
            SystemKey::SecondGap => "second_gap",
        }
    }

    /// SI unit of the value ("" for dimensionless; the forcing amplitude's depends on the forcing).
    pub fn unit(self) -> &'static str {
        match self {
            SystemKey::Amplitude | SystemKey::Gap | SystemKey::SecondGap => "m",
            SystemKey::Gamma | SystemKey::DampingRatio => "",
            SystemKey::Frequency => "Hz",
            SystemKey::Gravity => "m/s²",
            SystemKey::Stiffness => "N/m",
            SystemKey::Damping => "N·s/m",
            SystemKey::ForcingAmplitude => "N or m",
        }
    }
}

impl Param {
    /// The dotted path (`system.gap`, `impact.restitution`).
    pub fn path(self) -> String {
        match self {
            Param::System(key) => format!("system.{}", key.name()),
            Param::Scene(key) => key.path(),
        }
    }

    /// The current value in `model`, or why the system has none.
    pub fn get(self, model: &SystemModel) -> Result<f64, SystemError> {
        let spec = &model.spec;
        let na = |why| SystemError::KeyNotApplicable {
            key: self.path(),
            why,
        };
        match (self, spec.kind) {
            (Param::Scene(SceneKey::Restitution), _) => Ok(model.restitution),
            (Param::Scene(key), _) => model
                .scene
                .as_ref()
                .ok_or(na("the model has no scene"))
                .and_then(|s| key.get(s).ok_or(na("the scene has no such value"))),
            (Param::System(SystemKey::Frequency), _) => Ok(spec.frequency()),
            (
                Param::System(key),
                SystemKind::BouncingBall {
                    amplitude, gravity, ..
                },
            ) => match key {
                SystemKey::Amplitude => Ok(amplitude),
                SystemKey::Gravity => Ok(gravity),
                SystemKey::Gamma => Ok(spec.groups(model.mass).gamma.unwrap_or(0.0)),
                _ => Err(na("not a key of the bouncing ball")),
            },
            (
                Param::System(key),
                SystemKind::ImpactOscillator {
                    stiffness,
                    damping,
                    forcing,
                    gap,
                    second_gap,
                    ..
                },
            ) => match key {
                SystemKey::Stiffness => Ok(stiffness),
                SystemKey::DampingRatio => match damping {
                    Damping::Ratio(z) => Ok(z),
                    Damping::Coefficient(_) => Err(na("the scene gives `damping`, not a ratio")),
                },
                SystemKey::Damping => match damping {
                    Damping::Coefficient(c) => Ok(c),
                    Damping::Ratio(_) => Err(na("the scene gives `damping_ratio`")),
                },
                SystemKey::ForcingAmplitude => match forcing {
                    Forcing::Force { amplitude } | Forcing::Base { amplitude } => Ok(amplitude),
                },
                SystemKey::Gap => Ok(gap),
                SystemKey::SecondGap => second_gap.ok_or(na("the system has one stop")),
                _ => Err(na("not a key of the impact oscillator")),
            },
        }
    }

    /// `model` with this parameter set to `value` (validated; errors name the key).
    pub fn apply(self, model: &SystemModel, value: f64) -> Result<SystemModel, SystemError> {
        if !value.is_finite() {
            return Err(SystemError::NotFinite {
                key: self.path(),
                value,
            });
        }
        self.get(model)?;
        let mut out = model.clone();
        match self {
            Param::Scene(SceneKey::Restitution) if model.scene.is_none() => {
                out.restitution = value;
            }
            Param::Scene(key) => {
                let mut scene = model.scene.clone().ok_or(SystemError::KeyNotApplicable {
                    key: self.path(),
                    why: "the model has no scene",
                })?;
                key.set(&mut scene, value)
                    .map_err(|_| SystemError::KeyNotApplicable {
                        key: self.path(),
                        why: "the scene has no such value",
                    })?;
                out = SystemModel::from_scene(&scene, &model.spec)?;
            }
            Param::System(key) => {
                let omega = model.spec.omega();
                match &mut out.spec.kind {
                    SystemKind::BouncingBall {
                        amplitude,
                        frequency,
                        gravity,
                    } => match key {
                        SystemKey::Amplitude => *amplitude = value,
                        SystemKey::Gamma => *amplitude = value * *gravity / (omega * omega),
                        SystemKey::Frequency => *frequency = value,
                        SystemKey::Gravity => *gravity = value,
                        // Refused by `get` above: not a key of this kind.
                        _ => {}
                    },
                    SystemKind::ImpactOscillator {
                        stiffness,
                        damping,
                        forcing,
                        frequency,
                        gap,
                        second_gap,
                    } => match key {
                        SystemKey::Stiffness => *stiffness = value,
                        SystemKey::DampingRatio => *damping = Damping::Ratio(value),
                        SystemKey::Damping => *damping = Damping::Coefficient(value),
                        SystemKey::ForcingAmplitude => match forcing {
                            Forcing::Force { amplitude } | Forcing::Base { amplitude } => {
                                *amplitude = value
                            }
                        },
                        SystemKey::Frequency => *frequency = value,
                        SystemKey::Gap => *gap = value,
                        SystemKey::SecondGap => *second_gap = Some(value),
                        // Refused by `get` above: not a key of this kind.
                        _ => {}
                    },
                }
                out.validate()?;
            }
        }
        if let Param::Scene(SceneKey::Restitution) = self {
            out.validate()?;
        }
        Ok(out)
    }
}

impl fmt::Display for Param {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.path())
    }
}

impl FromStr for Param {
    type Err = SystemError;

    fn from_str(s: &str) -> Result<Param, SystemError> {
        if let Some(name) = s.strip_prefix("system.") {
            return SystemKey::ALL
                .into_iter()
                .find(|k| k.name() == name)
                .map(Param::System)
                .ok_or_else(|| SystemError::UnknownKey(s.to_string()));
        }
        s.parse::<SceneKey>()
            .map(Param::Scene)
            .map_err(|_| SystemError::UnknownKey(s.to_string()))
    }
}
