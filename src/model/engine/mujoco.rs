//! MuJoCo soft contact (doc/modeling.rst "Solver parameters"; doc/computation.rst "Soft
//! constraints").
//!
//! - Law: not a force law but a soft constraint. For a constraint violation r the solver's
//!   acceleration obeys a₁ + d·(b·ṙ + k·r) = (1 − d)·a₀ with the impedance d = d(r) from
//!   `solimp`, and from `solref` = (timeconst, dampratio): b = 2/(d_max·timeconst),
//!   k = d(r)/(d_max²·timeconst²·dampratio²); or, negative, solref = (−stiffness, −damping):
//!   b = damping/d_max, k = stiffness·d(r)/d_max².
//! - Parameters: `solref`, `solimp` per geom (or per contact pair), `timestep` in `<option>`.
//! - Combination: two geoms' solref/solimp are mixed by their `solmix` weights (equal values are
//!   kept).
//! - End of contact: the normal contact force is constrained to f ≥ 0 (a clamp).
//!
//! Assumptions of this translation, all stated in its notes: one frictionless contact (condim 1)
//! with no other force during the impact (a₀ = 0); constant impedance (solimp d_min = d_max), under
//! which d cancels and ẍ = −(K·x + B·ẋ) with K = 1/(timeconst·dampratio)², B = 2/timeconst;
//! continuous time (timestep ≪ timeconst).

use std::f64::consts::PI;

use crate::model::Shape;
use crate::model::error::ModelError;
use crate::model::force::{AnyLaw, ForceModel};
use crate::model::power_law::PowerLaw;

use super::error::EngineError;
use super::solve::{calibrated_damping, realise};
use super::{Engine, EngineScene, Fragment, Parameter, Translation, describe, shown};

/// This engine's row of [`super::ENGINES`].
pub const ENGINE: Engine = Engine {
    id: "mujoco",
    name: "MuJoCo (solref/solimp soft contact)",
    source: "google-deepmind/mujoco: doc/modeling.rst, doc/computation.rst",
    translate,
};

/// A constant impedance: d_min = d_max = 0.95, MuJoCo's default d_max.
const SOLIMP: &str = "0.95 0.95 0.001 0.5 2";

/// The law-table row of MuJoCo's contact: the linear spring–dashpot with the f ≥ 0 clamp.
const ROW: ForceModel = ForceModel::with_id("kelvin-voigt");

/// The largest damping ratio tried: far beyond critical, where the clamp has long ended contact.
const MAX_DAMPRATIO: f64 = 50.0;

/// MuJoCo's linear soft contact as a force on reduced mass m, for an impact at `v0`:
/// K = m·ω₀², c = 2ζ·ω₀·m, clamped at f ≥ 0.
fn law(scene: &EngineScene, omega: f64, zeta: f64, v0: f64) -> Result<AnyLaw, ModelError> {
    let elastic = PowerLaw {
        k: scene.mass * omega * omega,
        n: 1.0,
    };
    ROW.law_with_damping(&scene.params(elastic, v0), 2.0 * zeta * omega * scene.mass)
}

fn translate(scene: &EngineScene) -> Result<Translation, EngineError> {
    // ω₀ from the scene's elastic contact time, the same rule as every linear engine here.
    let omega = PI / scene.t_contact;
    let critical = 2.0 * omega * scene.mass;
    let elastic = PowerLaw {
        k: scene.mass * omega * omega,
        n: 1.0,
    };
    let c = calibrated_damping(
        ENGINE.id,
        ROW,
        scene,
        elastic,
        0.0..=MAX_DAMPRATIO * critical,
        |c| law(scene, omega, c / critical, scene.v0),
    )?;
    let zeta = c / critical;
    if zeta <= 0.0 {
        return Err(EngineError::Unreachable {
            engine: ENGINE.id,
            requested: scene.restitution,
            reason: "solref (timeconst, dampratio) always damps (b = 2/timeconst); give solref = (−stiffness, 0) for an elastic contact".into(),
        });
    }
    let dampratio = Parameter::new(
        "dampratio",
        zeta,
        "",
        "the damping ratio whose realised e at v₀ is the requested e with the f ≥ 0 clamp (hertz-tui's calibration of kelvin-voigt)",
    );
    let timeconst = Parameter::new(
        "timeconst",
        1.0 / (omega * dampratio.value),
        "s",
        format!(
            "1/(ω₀·dampratio), ω₀ = π/t_c = {} rad/s: the undamped contact lasts the Hertz contact time t_c = {} s",
            shown(omega),
            shown(scene.t_contact)
        ),
    );
    let omega = 1.0 / (timeconst.value * dampratio.value);
    let stiffness = Parameter::new(
        "-solref[0] (stiffness)",
        omega * omega,
        "1/s²",
        "direct form: K = 1/(timeconst·dampratio)²",
    );
    let damping = Parameter::new(
        "-solref[1] (damping)",
        2.0 / timeconst.value,
        "1/s",
        "direct form: B = 2/timeconst",
    );
    let (realised, e_of_v) = realise(scene, |v0| Ok(law(scene, omega, dampratio.value, v0)?))?;
    let unclamped = (-PI * dampratio.value / (1.0 - dampratio.value.powi(2)).sqrt()).exp();
    let timestep = timeconst.value / 10.0;
    let mut notes = vec![
        "Assumed: one frictionless contact (condim 1), no gravity or other force during the impact (a₀ = 0), solimp with d_min = d_max (then the impedance cancels), continuous time.".into(),
        format!(
            "The numbers above are the continuous-time limit. The step must follow the contact time, not timeconst: at timeconst/10 = {} s a lightly damped contact gains energy. The step printed below is hertz-tui's model of MuJoCo's Euler stepping, and stays under timeconst/2 = {} s, below which MuJoCo would raise timeconst (refsafe).",
            shown(timestep),
            shown(timeconst.value / 2.0)
        ),
    ];
    if dampratio.value < 1.0 {
        notes.push(format!(
            "Without the f ≥ 0 clamp this dampratio would give exp(−πζ/√(1 − ζ²)) = {}: the clamp ends contact early and raises e, so a dampratio taken from that formula overshoots (0.75 asked gives 0.763 in continuous time; larger gaps users report come from effects outside this translation, such as the time step or a position-dependent impedance).",
            shown(unclamped)
        ));
    }
    let fragments = vec![
        Fragment {
            title: "MJCF (solref = timeconst dampratio)",
            language: "xml",
            text: mjcf(
                scene,
                timestep,
                &format!("{} {}", timeconst.text(), dampratio.text()),
            ),
        },
        Fragment {
            title: "MJCF, direct form (solref = -stiffness -damping), same law",
            language: "xml",
            text: format!(
                "<geom condim=\"1\" solref=\"-{} -{}\" solimp=\"{SOLIMP}\"/>",
                stiffness.text(),
                damping.text()
            ),
        },
    ];
    Ok(Translation {
        engine: ENGINE.id,
        name: ENGINE.name,
        source: ENGINE.source,
        law: format!(
            "ẍ = −(K·x + B·ẋ), f ≥ 0, K = {} 1/s², B = {} 1/s (solref {} {})",
            stiffness.text(),
            damping.text(),
            timeconst.text(),
            dampratio.text()
        ),
        hertz_tui_law: "linear spring–dashpot (kelvin-voigt) with the F ≥ 0 clamp".into(),
        model: ROW,
        end_rule: ROW.spec().contact,
        approximation: Some(
            "MuJoCo's soft constraint read as a continuous-time linear spring–dashpot (constant impedance, no other forces)".into(),
        ),
        parameters: vec![timeconst, dampratio, stiffness, damping],
        fragments,
        notes,
        v0: scene.v0,
        e_requested: scene.restitution,
        realised,
        e_of_v,
    })
}

fn mjcf(scene: &EngineScene, timestep: f64, solref: &str) -> String {
    let geom = |shape: &Shape, mass: f64| match *shape {
        Shape::Sphere { radius } => format!(
            "type=\"sphere\" size=\"{}\" mass=\"{}\"",
            shown(radius),
            shown(mass)
        ),
        Shape::Cylinder { radius, length } => format!(
            "type=\"cylinder\" size=\"{} {}\" mass=\"{}\"",
            shown(radius),
            shown(length / 2.0),
            shown(mass)
        ),
        Shape::Plane => "type=\"plane\" size=\"1 1 0.1\"".into(),
    };
    let [moving, other] = scene.bodies();
    let other_geom = if other.mass().is_finite() {
        format!(
            "<body name=\"body2\"><freejoint/><geom {}/></body>",
            geom(&other.shape, other.mass())
        )
    } else {
        format!("<geom name=\"body2\" {}/>", geom(&other.shape, 0.0))
    };
    format!(
        "<mujoco>\n  <option timestep=\"{}\" gravity=\"0 0 0\"/>\n  <default><geom condim=\"1\" solref=\"{solref}\" solimp=\"{SOLIMP}\"/></default>\n  <worldbody>\n    <!-- body 2: {} -->\n    {other_geom}\n    <!-- body 1: {} -->\n    <body name=\"body1\" pos=\"0 0 0.1\"><freejoint/><geom {}/></body>\n  </worldbody>\n</mujoco>",
        shown(timestep),
        describe(&other.shape),
        describe(&moving.shape),
        geom(&moving.shape, moving.mass())
    )
}
