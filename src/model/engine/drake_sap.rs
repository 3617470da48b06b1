//! Drake's SAP solver on point contact (multibody/plant/contact_model_doxygen.h, "Modeling
//! Dissipation"; multibody/contact_solvers/sap).
//!
//! - Law: SAP ignores `hunt_crossley_dissipation` and uses the linear Kelvin–Voigt dissipation of
//!   `relaxation_time` τ: fₙ = (K·x + τ·K·ẋ)₊, clamped at F ≥ 0 (measured in Drake 1.51: with no
//!   τ the impact is perfectly inelastic).
//! - Parameters: per geometry `point_contact_stiffness` k (N/m) and `relaxation_time` (s).
//! - Combination: K = k₁k₂/(k₁ + k₂); the two relaxation times add (measured in Drake 1.51:
//!   τ/2 on each geometry realises the law with τ to 1e-13).
//! - End of contact: the clamp, where F falls to 0 with x > 0.
//!
//! As a hertz-tui law: the linear spring–dashpot with the F ≥ 0 clamp (as MuJoCo), ζ = τ·ω₀/2.

use crate::model::error::ModelError;
use crate::model::force::{AnyLaw, ForceModel};
use crate::model::power_law::PowerLaw;

use super::error::EngineError;
use super::solve::{calibrated_damping, realise};
use super::{Engine, EngineScene, Fragment, Parameter, Translation, shown};

/// This engine's row of [`super::ENGINES`].
pub const ENGINE: Engine = Engine {
    id: "drake-sap",
    name: "Drake (SAP solver, point contact)",
    source: "drake: multibody/plant/contact_model_doxygen.h (SAP: relaxation_time)",
    translate,
};

/// The law-table row of SAP's point contact: the linear spring–dashpot with the F ≥ 0 clamp.
const ROW: ForceModel = ForceModel::with_id("kelvin-voigt");

/// The largest damping ratio tried: far beyond critical, where the clamp has long ended contact.
const MAX_DAMPING_RATIO: f64 = 50.0;

/// SAP's law as a force on the reduced mass for an impact at `v0`: K·x + c·ẋ, clamped.
fn law(scene: &EngineScene, big_k: f64, c: f64, v0: f64) -> Result<AnyLaw, ModelError> {
    let elastic = PowerLaw { k: big_k, n: 1.0 };
    ROW.law_with_damping(&scene.params(elastic, v0), c)
}

fn translate(scene: &EngineScene) -> Result<Translation, EngineError> {
    let k = Parameter::new(
        "point_contact_stiffness",
        2.0 * scene.linear_stiffness(),
        "N/m",
        format!(
            "per geometry, 2K: two equal values combine to K = m·(π/t_c)² = {} N/m, whose undamped contact time is the Hertz t_c = {} s",
            shown(scene.linear_stiffness()),
            shown(scene.t_contact)
        ),
    );
    let big_k = k.value / 2.0;
    let critical = 2.0 * (scene.mass * big_k).sqrt();
    let c = calibrated_damping(
        ENGINE.id,
        ROW,
        scene,
        PowerLaw { k: big_k, n: 1.0 },
        0.0..=MAX_DAMPING_RATIO * critical,
        |c| law(scene, big_k, c, scene.v0),
    )?;
    // c = τ·K, τ = τ₁ + τ₂: half on each geometry.
    let tau = Parameter::new(
        "relaxation_time",
        c / big_k / 2.0,
        "s",
        format!(
            "per geometry, half of τ = c/K (the two add): c = {} N·s/m, damping ratio ζ = τω₀/2 = {}, is the damping whose clamped linear spring–dashpot realises the requested e at v₀ (hertz-tui's calibration of kelvin-voigt)",
            shown(c),
            shown(c / critical)
        ),
    );
    let tau_total = 2.0 * tau.value;
    let c = tau_total * big_k;
    let (realised, e_of_v) = realise(scene, |v0| Ok(law(scene, big_k, c, v0)?))?;
    let notes = vec![
        "SAP ignores hunt_crossley_dissipation; the Hunt–Crossley translation (--engine drake) is for TAMSI, Similar, Lagged or the continuous plant.".into(),
        format!(
            "A linear spring cannot match Hertz in both force and time: with K from the contact time, F_max is {} N against Hertz's {} N.",
            shown(realised.f_max),
            shown(scene.elastic.force(scene.x_max))
        ),
        "The damping is a constant c = τK, so e changes with v₀ only through the clamp (see e(v₀)).".into(),
    ];
    let fragments = vec![Fragment {
        title: "SDFormat proximity properties (both collisions)",
        language: "xml",
        text: format!(
            "<drake:proximity_properties>\n  <drake:point_contact_stiffness>{}</drake:point_contact_stiffness>\n  <drake:relaxation_time>{}</drake:relaxation_time>\n</drake:proximity_properties>",
            k.text(),
            tau.text()
        ),
    }];
    Ok(Translation {
        engine: ENGINE.id,
        name: ENGINE.name,
        source: ENGINE.source,
        law: format!(
            "fₙ = (K·x + τ·K·ẋ)₊ with K = {} N/m, τ = {} s",
            shown(big_k),
            shown(tau_total)
        ),
        hertz_tui_law: "linear spring–dashpot (kelvin-voigt) with the F ≥ 0 clamp".into(),
        model: ROW,
        end_rule: ROW.spec().contact,
        approximation: None,
        parameters: vec![k, tau],
        fragments,
        notes,
        v0: scene.v0,
        e_requested: scene.restitution,
        realised,
        e_of_v,
    })
}
