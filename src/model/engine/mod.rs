//! Contact parameters for the engine a user simulates in (docs/physics.md §7).
//!
//! Each engine is one file holding its documented law (source named in its doc comment), the rule
//! that maps the scene to its parameters, and its input fragment; [`ENGINES`] lists them. The
//! engine's law is a law of hertz-tui's table ([`crate::model::force::LAWS`]; a row added where
//! the table lacked one), solved and calibrated as every law is ([`solve`]), so the translation
//! states what the engine will really give: realised restitution at v₀ and over a range of v₀,
//! peak force, contact time and the largest stable explicit step.
#![warn(missing_docs)]

use serde::Serialize;

use crate::format::round_trip;

use super::error::ModelError;
use super::force::{ContactRule, ForceModel};
use super::power_law::PowerLaw;
use super::{Body, Scene, Shape};

pub mod adams;
pub mod chrono;
pub mod drake;
pub mod drake_sap;
pub mod error;
pub mod lammps;
pub mod lammps_tsuji;
pub mod liggghts;
pub mod mujoco;
pub mod regime;
pub mod run;
pub mod simbody;
pub mod solve;
pub mod tsuji;
pub mod yade;

pub use error::EngineError;
pub use regime::RegimeWarning;
pub use run::Run;
pub use solve::{EngineImpact, realise};

/// One engine: its `--engine` id, its name, and how it translates a scene.
#[derive(Debug, Clone, Copy)]
pub struct Engine {
    /// The `--engine` id, e.g. `drake`.
    pub id: &'static str,
    /// The engine's name, e.g. `Drake`.
    pub name: &'static str,
    /// The documentation or source file its law was read from.
    pub source: &'static str,
    /// Its translation of a scene.
    pub translate: fn(&EngineScene) -> Result<Translation, EngineError>,
}

/// Every engine hertz-tui translates for; adding one is a file and a row here.
pub const ENGINES: [Engine; 10] = [
    drake::ENGINE,
    drake_sap::ENGINE,
    simbody::ENGINE,
    chrono::ENGINE,
    liggghts::ENGINE,
    lammps::ENGINE,
    lammps_tsuji::ENGINE,
    yade::ENGINE,
    adams::ENGINE,
    mujoco::ENGINE,
];

/// The engine with `id`.
pub fn find(id: &str) -> Result<&'static Engine, EngineError> {
    ENGINES.iter().find(|e| e.id == id).ok_or_else(|| {
        let ids: Vec<_> = ENGINES.iter().map(|e| e.id).collect();
        EngineError::UnknownEngine(id.to_string(), ids.join(", "))
    })
}

/// Translates `scene` for the engine `id`.
///
/// Drake's Hunt–Crossley point contact for the paper's Fig. 5 scene: its stiffness is chosen so
/// that π·√(m/k) is the Hertz contact time (k = k₁/2, Drake combining two equal geometries), and
/// its dissipation so that the engine's law, solved here, rebounds at the scene's e = 0.6:
///
/// ```
/// use std::f64::consts::PI;
///
/// use hertz_tui::model::engine::translate;
/// use hertz_tui::model::presets::{DEFAULT_SCENE, Registry};
///
/// let scene = Registry::builtin()?.scene(DEFAULT_SCENE)?;
/// let hertz = scene.quasistatic()?;
/// let drake = translate("drake", &scene)?;
///
/// let k1 = drake
///     .parameters
///     .iter()
///     .find(|p| p.name == "point_contact_stiffness")
///     .map(|p| p.value)
///     .unwrap();
/// let k = k1 / 2.0;
/// assert!((PI * (hertz.reduced_mass / k).sqrt() / hertz.t_contact - 1.0).abs() < 1e-9);
/// assert_eq!(drake.e_requested, 0.6);
/// assert!((drake.realised.e_out - 0.6).abs() < 1e-8);
/// assert!(drake.fragments[0].text.contains(&drake.parameters[0].text()));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn translate(id: &str, scene: &Scene) -> Result<Translation, EngineError> {
    let engine = find(id)?;
    (engine.translate)(&EngineScene::new(scene)?)
}

/// [`translate`] with [`Translation::e_of_v`] at `velocities` (m/s, e.g. those of measured
/// restitution): the engine's constants calibrated at the scene's v₀, held at every velocity.
pub fn translate_at(
    id: &str,
    scene: &Scene,
    velocities: &[f64],
) -> Result<Translation, EngineError> {
    let engine = find(id)?;
    let mut engine_scene = EngineScene::new(scene)?;
    engine_scene.velocities = velocities.to_vec();
    (engine.translate)(&engine_scene)
}

/// A translation with what running it takes and gives: the script, its step and claim, the
/// engine version it was run in, and the scene's regime warnings.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct EngineRun {
    /// The translation.
    #[serde(flatten)]
    pub translation: Translation,
    /// Where the scene leaves what the engine's law describes.
    pub warnings: Vec<RegimeWarning>,
    /// The script, its step and what it gives.
    pub run: Run,
}

/// Translates `scene` for the engine `id` with a runnable script whose step keeps e, F_max and the
/// contact time within `tolerance` (relative) of the engine's continuous law.
///
/// MuJoCo on the Fig. 5 scene: the printed step is a fraction of the contact time, not of
/// MuJoCo's timeconst, and hertz-tui's model of MuJoCo's stepping realises the requested e = 0.6
/// within 1 % there; the script sets it:
///
/// ```
/// use hertz_tui::model::engine::run::{Claim, DEFAULT_TOLERANCE};
/// use hertz_tui::model::engine::{shown, translate_run};
/// use hertz_tui::model::presets::{DEFAULT_SCENE, Registry};
///
/// let scene = Registry::builtin()?.scene(DEFAULT_SCENE)?;
/// let mujoco = translate_run("mujoco", &scene, DEFAULT_TOLERANCE)?;
/// let Claim::Stepped(choice) = &mujoco.run.claim else { panic!("MuJoCo steps") };
/// assert!(choice.steps_per_contact >= 10.0);
/// assert!((choice.at_step.e_out / 0.6 - 1.0).abs() <= 0.01);
/// let script = &mujoco.run.script.as_ref().unwrap().text;
/// assert!(script.contains(&format!("timestep=\"{}\"", shown(choice.step))));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn translate_run(id: &str, scene: &Scene, tolerance: f64) -> Result<EngineRun, EngineError> {
    if !(tolerance > 0.0 && tolerance < 1.0) {
        return Err(EngineError::Tolerance(tolerance));
    }
    let engine = find(id)?;
    let engine_scene = EngineScene::new(scene)?;
    let mut translation = (engine.translate)(&engine_scene)?;
    let run = run::run(&engine_scene, &translation, tolerance)?;
    if !run.fragments.is_empty() {
        translation.fragments = run.fragments.clone();
    }
    Ok(EngineRun {
        translation,
        warnings: regime::regime_warnings(scene)?,
        run,
    })
}

/// What every engine needs of a scene, SI units.
#[derive(Debug, Clone, PartialEq)]
pub struct EngineScene {
    /// The scene itself.
    pub scene: Scene,
    /// Reduced mass m, kg (eq 4).
    pub mass: f64,
    /// Impact velocity v₀, m/s.
    pub v0: f64,
    /// The requested restitution e.
    pub restitution: f64,
    /// The scene's elastic law F = k·xⁿ (Hertz for spheres, the fitted law for cylinders).
    pub elastic: PowerLaw,
    /// Effective modulus E* = 1/η, Pa (eq 3).
    pub e_star: f64,
    /// Reduced radius R, m (eq 2; ∞ for two planes).
    pub r_star: f64,
    /// Whether the pair touches at a point (spheres), as most engines' laws assume.
    pub point_contact: bool,
    /// Elastic contact time at v₀, s (eq 7).
    pub t_contact: f64,
    /// Elastic maximum approach at v₀, m (eq 5).
    pub x_max: f64,
    /// The impact velocities of [`Translation::e_of_v`], m/s: [`VELOCITY_FACTORS`]·v₀, or the
    /// velocities of measured data ([`translate_at`]).
    pub velocities: Vec<f64>,
}

impl EngineScene {
    /// The engines' view of `scene`, from its quasistatic estimate; fails as that does.
    pub fn new(scene: &Scene) -> Result<Self, ModelError> {
        let quasistatic = scene.quasistatic()?;
        let pair = scene.pair()?;
        Ok(EngineScene {
            scene: scene.clone(),
            mass: quasistatic.reduced_mass,
            v0: scene.impact.v0,
            restitution: scene.impact.restitution,
            elastic: quasistatic.law(),
            e_star: 1.0 / pair.elastic_factor(),
            r_star: pair.reduced_radius(),
            point_contact: pair.kind().is_point_contact(),
            t_contact: quasistatic.t_contact,
            x_max: quasistatic.x_max,
            velocities: VELOCITY_FACTORS
                .iter()
                .map(|f| f * scene.impact.v0)
                .collect(),
        })
    }

    /// Refuses line contact for an engine whose law is Hertz's point contact.
    pub fn require_point_contact(&self, engine: &'static str) -> Result<(), EngineError> {
        if self.point_contact {
            Ok(())
        } else {
            Err(EngineError::NeedsPointContact {
                engine,
                pair: format!(
                    "{}–{}",
                    self.scene.body1.shape.name(),
                    self.scene.body2.shape.name()
                ),
            })
        }
    }

    /// The linear stiffness whose undamped contact time π√(m/K) equals the scene's elastic Hertz
    /// contact time t_c (eq 7): K = m·(π/t_c)², N/m. The rule every linear engine here uses.
    pub fn linear_stiffness(&self) -> f64 {
        self.mass * (std::f64::consts::PI / self.t_contact).powi(2)
    }

    /// The two bodies, the moving one (a body of finite mass) first.
    pub fn bodies(&self) -> [&Body; 2] {
        let (b1, b2) = (&self.scene.body1, &self.scene.body2);
        if b1.mass().is_finite() || !b2.mass().is_finite() {
            [b1, b2]
        } else {
            [b2, b1]
        }
    }
}

/// One parameter as the engine takes it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Parameter {
    /// The engine's own name for it.
    pub name: &'static str,
    /// The value printed in the fragment (rounded to 10 significant digits).
    pub value: f64,
    /// Its SI unit, as the engine documents it.
    pub unit: &'static str,
    /// How it was obtained.
    pub rule: String,
}

impl Parameter {
    /// A parameter with `value` rounded as the fragment prints it ([`pasteable`]).
    pub fn new(
        name: &'static str,
        value: f64,
        unit: &'static str,
        rule: impl Into<String>,
    ) -> Self {
        Parameter {
            name,
            value: pasteable(value),
            unit,
            rule: rule.into(),
        }
    }

    /// The value as the fragment prints it.
    pub fn text(&self) -> String {
        shown(self.value)
    }
}

/// `x` rounded to 10 significant digits: what a fragment prints, and what the realised numbers
/// are computed from, so that pasting reproduces them.
pub fn pasteable(x: f64) -> f64 {
    format!("{x:.9e}").parse().unwrap_or(x)
}

/// `x` as prose and fragments show it: [`pasteable`], shortest text.
pub fn shown(x: f64) -> String {
    round_trip(pasteable(x))
}

/// Ready-to-paste engine input.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Fragment {
    /// What it is (e.g. "SDF collision element").
    pub title: &'static str,
    /// Its language, for a fenced block: xml, cpp, python, text.
    pub language: &'static str,
    /// The input itself.
    pub text: String,
}

/// The realised restitution at one impact velocity.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct VelocityPoint {
    /// Impact velocity, m/s.
    pub v0: f64,
    /// Realised restitution v_out/v₀ of the engine's law.
    pub e_out: f64,
}

/// The translation of a scene for one engine.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Translation {
    /// The engine's id ([`Engine::id`]).
    pub engine: &'static str,
    /// The engine's name.
    pub name: &'static str,
    /// Where its law was read ([`Engine::source`]).
    pub source: &'static str,
    /// The engine's law with its parameters, in words.
    pub law: String,
    /// The same law among hertz-tui's.
    pub hertz_tui_law: String,
    /// The row of hertz-tui's law table the engine's law is (`--model` id in JSON).
    pub model: ForceModel,
    /// How the engine's contact ends: the row's rule.
    pub end_rule: ContactRule,
    /// Where the translation approximates the engine (`None`: the engine's law exactly).
    pub approximation: Option<String>,
    /// The engine's parameters, as it takes them.
    pub parameters: Vec<Parameter>,
    /// Ready-to-paste input.
    pub fragments: Vec<Fragment>,
    /// Assumptions and caveats.
    pub notes: Vec<String>,
    /// The scene's impact velocity, m/s.
    pub v0: f64,
    /// The scene's requested restitution.
    pub e_requested: f64,
    /// What the engine's law gives at the scene's v₀.
    pub realised: EngineImpact,
    /// Realised restitution over v₀/10 … 10·v₀ (or at [`EngineScene::velocities`]).
    pub e_of_v: Vec<VelocityPoint>,
}

/// The factors of v₀ at which [`Translation::e_of_v`] is evaluated: two decades around the scene.
pub const VELOCITY_FACTORS: [f64; 7] = [0.1, 0.2, 0.5, 1.0, 2.0, 5.0, 10.0];

/// How a body's geometry reads in prose ("sphere R = 0.01 m").
pub fn describe(shape: &Shape) -> String {
    match *shape {
        Shape::Sphere { radius } => format!("sphere R = {} m", round_trip(radius)),
        Shape::Cylinder { radius, length } => format!(
            "cylinder R = {} m, L = {} m",
            round_trip(radius),
            round_trip(length)
        ),
        Shape::Plane => "plane".into(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_engine_is_found_by_its_id_and_ids_are_unique() {
        for engine in &ENGINES {
            assert_eq!(find(engine.id).map(|e| e.name), Ok(engine.name));
        }
        let mut ids: Vec<_> = ENGINES.iter().map(|e| e.id).collect();
        ids.sort_unstable();
        ids.dedup();
        assert_eq!(ids.len(), ENGINES.len());
        let err = find("bullet").map(|e| e.id).unwrap_err().to_string();
        assert!(
            err.contains("unknown engine 'bullet'") && err.contains("mujoco"),
            "{err}"
        );
    }

    #[test]
    fn pasteable_keeps_ten_significant_digits() {
        assert_eq!(pasteable(0.123456789012345), 0.1234567890);
        assert_eq!(pasteable(2e11), 2e11);
    }
}
