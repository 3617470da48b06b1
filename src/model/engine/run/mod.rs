//! How to run a translation in its engine (docs/engines.md): a complete script that runs as
//! printed and prints the rebound, the step it takes with what the engine's stepping realises
//! there (or the continuous limit it claims), the engine version it was run in, and what changes
//! across versions.
//!
//! Each engine with a script is one file here, holding its script and its law as the engine
//! computes it from the printed input (stepped by [`stepping`]); [`RUNNERS`] lists them.

use serde::Serialize;

use crate::model::Shape;

use super::error::EngineError;
use super::{EngineScene, Fragment, Translation, shown};

pub mod drake;
pub mod drake_sap;
pub mod lammps;
pub mod liggghts;
pub mod mujoco;
pub mod opensim;
pub mod stepping;
pub mod yade;

pub use stepping::{Scheme, StepChoice, SteppedImpact};

/// The default relative tolerance of the printed step on e, F_max and the contact time.
pub const DEFAULT_TOLERANCE: f64 = 0.01;

/// The relative accuracy claimed in e where the engine integrates the continuous law with error
/// control.
pub const CONTINUOUS_TOLERANCE: f64 = 1e-3;

/// What `translate` claims the printed script gives.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum Claim {
    /// The engine integrates the continuous law with error control: the translation's realised
    /// numbers, e to [`CONTINUOUS_TOLERANCE`].
    Continuous {
        /// The integrator the script selects.
        integrator: &'static str,
        /// The relative accuracy claimed in e.
        tolerance: f64,
    },
    /// A fixed step: the printed step and what the engine's stepping gives there.
    Stepped(StepChoice),
    /// Only the continuous law is claimed; how the engine steps it is not modelled here.
    ContinuousOnly {
        /// Why no step is claimed.
        reason: String,
    },
}

/// A script that runs as printed in its engine.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Script {
    /// A file name for it.
    pub file: &'static str,
    /// Its language, for a fenced block: python, text.
    pub language: &'static str,
    /// The command that runs it.
    pub command: &'static str,
    /// The script.
    pub text: String,
}

/// How to run a translation, and what running it gives (serialised with [`Run::checked`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Run {
    /// The engine release the script was run in by hertz-tui's engine checks (`None`: not run in
    /// the engine, checked against its source's formulas only).
    pub checked_in: Option<&'static str>,
    /// What the script gives, per hertz-tui.
    pub claim: Claim,
    /// Further claims the script makes when run another way (e.g. Drake's discrete plant).
    pub other_claims: Vec<(String, Claim)>,
    /// The script (`None` with the reason in `no_script`).
    pub script: Option<Script>,
    /// Why there is no script.
    pub no_script: Option<String>,
    /// What changes across the engine's versions.
    pub versions: Vec<String>,
    /// The fragments as the script uses them, replacing the translation's (empty: those stand).
    pub fragments: Vec<Fragment>,
}

impl Run {
    /// What the claim rests on, in words: the release the scripts were run in (`checked_in`), for
    /// this scene or (without a script) for spheres only, every way of running it (with other
    /// claims: Drake's continuous and discrete plants); or the source's formulas alone.
    pub fn checked(&self) -> String {
        match (self.checked_in, &self.script) {
            (None, _) => {
                "not run in the engine: checked against the formulas of its source (named above)"
                    .into()
            }
            (Some(release), None) => {
                format!("scripts are run in {release} for spheres; not this scene")
            }
            (Some(release), Some(_)) if self.other_claims.is_empty() => {
                format!("run in {release} by hertz-tui's engine checks")
            }
            (Some(release), Some(_)) => {
                format!("run in {release} by hertz-tui's engine checks (continuous and discrete)")
            }
        }
    }

    /// A run whose script was run in release `checked_in` by the engine checks, with no other
    /// claim: what every engine but Drake (which claims its discrete plant too) builds.
    pub fn run_in(
        checked_in: &'static str,
        claim: Claim,
        script: Script,
        versions: Vec<String>,
        fragments: Vec<Fragment>,
    ) -> Run {
        Run {
            checked_in: Some(checked_in),
            claim,
            other_claims: Vec::new(),
            script: Some(script),
            no_script: None,
            versions,
            fragments,
        }
    }
}

impl Serialize for Run {
    /// The fields in order, with `checked` after `checked_in`; the pattern names every field, so a
    /// new one is not left out.
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeStruct;
        let Run {
            checked_in,
            claim,
            other_claims,
            script,
            no_script,
            versions,
            fragments,
        } = self;
        let mut run = serializer.serialize_struct("Run", 8)?;
        run.serialize_field("checked_in", checked_in)?;
        run.serialize_field("checked", &self.checked())?;
        run.serialize_field("claim", claim)?;
        run.serialize_field("other_claims", other_claims)?;
        run.serialize_field("script", script)?;
        run.serialize_field("no_script", no_script)?;
        run.serialize_field("versions", versions)?;
        run.serialize_field("fragments", fragments)?;
        run.end()
    }
}

/// Builds an engine's run from its translation: `tolerance` is asked of the printed step.
pub type Runner = fn(&EngineScene, &Translation, f64) -> Result<Run, EngineError>;

/// The engines with a runnable script, by `--engine` id; the others are not run in the engine.
pub const RUNNERS: [(&str, Runner); 8] = [
    ("drake", drake::run),
    ("drake-sap", drake_sap::run),
    ("simbody", opensim::run),
    ("mujoco", mujoco::run),
    ("lammps", lammps::run),
    ("lammps-tsuji", lammps::run_tsuji),
    ("liggghts", liggghts::run),
    ("yade", yade::run),
];

/// The run of `translation` (for the engine it names).
pub fn run(
    scene: &EngineScene,
    translation: &Translation,
    tolerance: f64,
) -> Result<Run, EngineError> {
    let runner = RUNNERS.iter().find(|(id, _)| *id == translation.engine);
    match runner {
        Some((_, runner)) => runner(scene, translation, tolerance),
        None => Ok(Run {
            checked_in: None,
            claim: Claim::ContinuousOnly {
                reason: "no package of this engine is available here to run it".into(),
            },
            other_claims: Vec::new(),
            script: None,
            no_script: Some("not run in the engine: no package of it is available here, so only the fragment above is given".into()),
            versions: Vec::new(),
            fragments: Vec::new(),
        }),
    }
}

/// The value of the translation's parameter `name`, as printed.
pub fn parameter(t: &Translation, name: &str) -> Result<f64, EngineError> {
    t.parameters
        .iter()
        .find(|p| p.name == name)
        .map(|p| p.value)
        .ok_or(EngineError::MissingParameter {
            engine: t.engine,
            name: name.to_string(),
        })
}

/// The bodies of a scene a script can build: a sphere on a plate or on another sphere.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Bodies {
    /// A sphere (radius, mass) hitting a fixed plate.
    OnPlate {
        /// Radius, m.
        radius: f64,
        /// Mass, kg.
        mass: f64,
    },
    /// Sphere 1 (moving) hitting sphere 2 (at rest), both free.
    Spheres {
        /// Radius and mass of the moving sphere, m and kg.
        moving: (f64, f64),
        /// Radius and mass of the sphere at rest, m and kg.
        other: (f64, f64),
    },
}

impl Bodies {
    /// The scene's bodies, or why a script cannot build them.
    pub fn of(scene: &EngineScene) -> Result<Self, String> {
        let [moving, other] = scene.bodies();
        let Shape::Sphere { radius } = moving.shape else {
            return Err(format!(
                "the scripts build sphere impacts; this scene's moving body is a {}",
                moving.shape.name()
            ));
        };
        match other.shape {
            Shape::Plane => Ok(Bodies::OnPlate {
                radius,
                mass: moving.mass(),
            }),
            Shape::Sphere { radius: r2 } if other.mass().is_finite() => Ok(Bodies::Spheres {
                moving: (radius, moving.mass()),
                other: (r2, other.mass()),
            }),
            _ => Err(format!(
                "the scripts build a sphere on a plate or on a free sphere; this scene's other body is a {}",
                other.shape.name()
            )),
        }
    }

    /// The moving sphere's radius, m.
    pub fn radius(&self) -> f64 {
        match *self {
            Bodies::OnPlate { radius, .. } => radius,
            Bodies::Spheres { moving, .. } => moving.0,
        }
    }
}

/// The run for a scene whose bodies no script builds: the claim stands, the script is missing.
pub fn without_script(checked_in: &'static str, claim: Claim, reason: String) -> Run {
    Run {
        checked_in: Some(checked_in),
        claim,
        other_claims: Vec::new(),
        script: None,
        no_script: Some(reason),
        versions: Vec::new(),
        fragments: Vec::new(),
    }
}

/// The LAMMPS-family loop (LAMMPS and LIGGGHTS share its input language) that steps the impact
/// one step at a time and prints `RESULT e_out … F_max … contact_time …`: the rebound speed
/// `v_rel` (an equal-style expression) over `v0`, the largest |F_z| on the ball, and the steps with
/// a force times the step.
pub fn measure_loop(v_rel: &str, max_steps: u64, v0: impl std::fmt::Display) -> String {
    format!(
        r#"variable fa equal abs(fz[1])
variable vrel equal {v_rel}
variable fmax equal 0
variable nc equal 0
variable touched equal 0
variable i loop {max_steps}
label step
run 1 pre no post no
if "${{fa}} > ${{fmax}}" then "variable fmax equal ${{fa}}"
if "${{fa}} != 0" then "variable nc equal ${{nc}}+1" "variable touched equal 1"
if "${{touched}} == 1 && ${{fa}} == 0 && ${{vrel}} > 0" then "jump SELF done"
next i
jump SELF step
label done
variable e_out equal v_vrel/{v0}
variable contact_time equal v_nc*dt
print "RESULT e_out ${{e_out}} F_max ${{fmax}} contact_time ${{contact_time}}"
"#
    )
}

/// The comment lines a LAMMPS-family input opens with: the command that printed it, the release
/// and command it runs as printed in, and what hertz-tui's model of its velocity-Verlet stepping
/// (`choice`) gives.
pub fn verlet_header(
    t: &Translation,
    scene: &EngineScene,
    checked_in: &str,
    command: &str,
    choice: &StepChoice,
) -> String {
    format!(
        "# hertz-tui translate --engine {engine}: {name}\n# Runs as printed in {checked_in}: {command}\n# One sphere impact, no gravity, velocity Verlet (fix nve/sphere) at the step hertz-tui chose:\n# its model of this stepping gives e = {e}, F_max = {f} N, contact time {tc} s.",
        engine = t.engine,
        name = scene.scene.name,
        e = num(choice.at_step.e_out),
        f = num(choice.at_step.f_max),
        tc = num(choice.at_step.t_contact),
    )
}

/// The number of steps a script runs at most: 200 continuous contact times.
pub fn max_steps(scene: &EngineScene, step: f64) -> u64 {
    (200.0 * scene.t_contact / step).ceil() as u64
}

/// The moving body's height above touch at the start of a stepped script, m
/// ([`stepping::start_gap`]).
pub fn gap(scene: &EngineScene, step: f64) -> f64 {
    stepping::start_gap(scene.v0, step)
}

/// A number as a script prints it (10 significant digits, shortest form).
pub fn num(x: f64) -> String {
    shown(x)
}

/// The Python lines every script ends with: the measured rebound, peak force and contact time in
/// one line the engine checks read.
pub const PY_RESULT: &str =
    "print(f\"RESULT e_out {e_out:.12g} F_max {f_max:.12g} contact_time {contact_time:.12g}\")";

/// The stepped claim for `force` (the engine's law from the printed input) under `scheme`, at a
/// step no longer than `max_step` (an engine's own limit; ∞ for none).
pub fn stepped(
    scene: &EngineScene,
    translation: &Translation,
    scheme: Scheme,
    tolerance: f64,
    max_step: f64,
    force: &dyn Fn(f64, f64) -> f64,
) -> Result<StepChoice, EngineError> {
    let r = &translation.realised;
    stepping::choose_step(
        scheme,
        tolerance,
        (r.e_out, r.f_max, r.t_contact),
        max_step,
        |h| {
            let x0 = -stepping::start_gap(scene.v0, h);
            stepping::step_impact(scheme, force, scene.mass, scene.v0, h, x0, scene.t_contact)
        },
    )
}
