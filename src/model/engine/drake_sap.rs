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

use std::f64::consts::PI;

use crate::model::power_law::PowerLaw;

use super::calibrate::solve_for_restitution;
use super::contact::{self, ContactLaw, EndRule, EngineDamping};
use super::error::EngineError;
use super::{Engine, EngineScene, Fragment, Parameter, Translation, realise, shown};

/// This engine's row of [`super::ENGINES`].
pub const ENGINE: Engine = Engine {
    id: "drake-sap",
    name: "Drake (SAP solver, point contact)",
    source: "drake: multibody/plant/contact_model_doxygen.h (SAP: relaxation_time)",
    translate,
};

/// The clamped Kelvin–Voigt law on reduced mass m with K = m·ω₀² and ζ.
fn law(mass: f64, omega: f64, zeta: f64) -> ContactLaw {
    ContactLaw {
        elastic: PowerLaw {
            k: mass * omega * omega,
            n: 1.0,
        },
        damping: EngineDamping::Viscous {
            c: 2.0 * zeta * omega * mass,
            p: 0.0,
        },
        end: EndRule::Clamp,
    }
}

fn translate(scene: &EngineScene) -> Result<Translation, EngineError> {
    let omega = PI / scene.t_contact;
    let e_of = |zeta: f64| {
        contact::solve(&law(scene.mass, omega, zeta), scene.mass, scene.v0).map(|r| r.e_out)
    };
    let zeta = solve_for_restitution(ENGINE.id, scene.restitution, 0.0, 50.0, e_of)?;
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
    let tau = Parameter::new(
        "relaxation_time",
        zeta / omega,
        "s",
        format!(
            "per geometry, half of τ = 2ζ/ω₀ (the two add): ζ = {} is the damping ratio whose clamped linear spring–dashpot realises the requested e at v₀ (Brent root on hertz-tui's solve)",
            shown(zeta)
        ),
    );
    let big_k = k.value / 2.0;
    let tau_total = 2.0 * tau.value;
    let law = ContactLaw {
        elastic: PowerLaw { k: big_k, n: 1.0 },
        damping: EngineDamping::Viscous {
            c: tau_total * big_k,
            p: 0.0,
        },
        end: EndRule::Clamp,
    };
    let (realised, e_of_v) = realise(&law, scene)?;
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
        end_rule: law.end,
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
