//! Drake, compliant point contact (multibody/plant/contact_model_doxygen.h, "Modeling of Forces"
//! and "Modeling Dissipation").
//!
//! - Law: fₙ = k·(x)₊·(1 + d·ẋ)₊: linear in the penetration x, Hunt–Crossley dissipation d (s/m).
//! - Parameters: per geometry `point_contact_stiffness` k (N/m) and `hunt_crossley_dissipation`
//!   d (s/m), as `<drake:proximity_properties>` in SDFormat/URDF.
//! - Combination: k = k₁k₂/(k₁ + k₂), d = k₂/(k₁ + k₂)·d₁ + k₁/(k₁ + k₂)·d₂.
//! - End of contact: both factors are clamped at 0 (F ≥ 0); the Hunt–Crossley factor 1 + d·ẋ
//!   never reaches 0 during an impact (exact::hysteresis), so contact ends at x = 0.
//!
//! As a hertz-tui law: the `hunt-crossley` row (the Hunt–Crossley family) with n = 1 and
//! χ = d·v₀, solved exactly and calibrated by the family's exact relation.

use crate::model::Shape;
use crate::model::force::ForceModel;
use crate::model::power_law::PowerLaw;

use super::error::EngineError;
use super::solve::{hunt_crossley, hunt_crossley_chi, realise};
use super::{Engine, EngineScene, Fragment, Parameter, Translation, describe, shown};

/// This engine's row of [`super::ENGINES`].
pub const ENGINE: Engine = Engine {
    id: "drake",
    name: "Drake (compliant point contact)",
    source: "drake: multibody/plant/contact_model_doxygen.h",
    translate,
};

/// Above this the Drake documentation calls d unphysical and numerically harmful, s/m.
const UNPHYSICAL_DISSIPATION: f64 = 500.0;

fn translate(scene: &EngineScene) -> Result<Translation, EngineError> {
    let k = Parameter::new(
        "point_contact_stiffness",
        2.0 * scene.linear_stiffness(),
        "N/m",
        format!(
            "per geometry, 2K: the combination k₁k₂/(k₁ + k₂) of two equal values gives K = m·(π/t_c)² = {} N/m, whose undamped contact time π√(m/K) is the Hertz contact time t_c = {} s",
            shown(scene.linear_stiffness()),
            shown(scene.t_contact)
        ),
    );
    let elastic = PowerLaw {
        k: k.value / 2.0,
        n: 1.0,
    };
    let chi = hunt_crossley_chi(ENGINE.id, scene, elastic)?;
    let d = Parameter::new(
        "hunt_crossley_dissipation",
        chi / scene.v0,
        "s/m",
        format!(
            "per geometry, equal on both (then d combines to itself): d = χ/v₀ with χ = {} the root of ln((1 + χ)/(1 − χe)) = χ(1 + e)",
            shown(chi)
        ),
    );
    let (realised, e_of_v) = realise(scene, |v0| {
        Ok(hunt_crossley(scene, elastic, v0, d.value * v0)?)
    })?;
    let mut notes = vec![
        format!(
            "A linear spring cannot match Hertz in both force and time: with K from the contact time, F_max is {} N against Hertz's {} N.",
            shown(realised.f_max),
            shown(scene.elastic.force(scene.x_max))
        ),
        "d is a constant, so e falls as v₀ rises (see e(v₀)); the rebound speed never exceeds 1/d.".into(),
        "Numbers are for the continuous law (MultibodyPlant time_step = 0). TAMSI, Similar and Lagged step through it (the step below); SAP ignores hunt_crossley_dissipation and comes out perfectly inelastic with these parameters: use --engine drake-sap for SAP.".into(),
    ];
    if d.value > UNPHYSICAL_DISSIPATION {
        notes.push(format!(
            "d = {} s/m exceeds the 500 s/m the Drake documentation calls unphysical and harmful to its solvers.",
            shown(d.value)
        ));
    }
    let fragments = vec![Fragment {
        title: "SDFormat: one <collision> per body (drake namespace)",
        language: "xml",
        text: scene
            .bodies()
            .iter()
            .enumerate()
            .map(|(i, body)| collision(i + 1, &body.shape, &k, &d))
            .collect::<Vec<_>>()
            .join("\n"),
    }];
    Ok(Translation {
        engine: ENGINE.id,
        name: ENGINE.name,
        source: ENGINE.source,
        law: format!(
            "fₙ = k·x·(1 + d·ẋ)₊ with k = {} N/m, d = {} s/m",
            shown(elastic.k),
            d.text()
        ),
        hertz_tui_law: format!(
            "Hunt–Crossley family F = k·xⁿ·(1 + χ·ẋ/v₀), n = 1, χ = {}",
            shown(d.value * scene.v0)
        ),
        model: ForceModel::HuntCrossley,
        end_rule: ForceModel::HuntCrossley.spec().contact,
        approximation: None,
        parameters: vec![k, d],
        fragments,
        notes,
        v0: scene.v0,
        e_requested: scene.restitution,
        realised,
        e_of_v,
    })
}

fn collision(index: usize, shape: &Shape, k: &Parameter, d: &Parameter) -> String {
    let geometry = match *shape {
        Shape::Sphere { radius } => format!("<sphere><radius>{}</radius></sphere>", shown(radius)),
        Shape::Cylinder { radius, length } => format!(
            "<cylinder><radius>{}</radius><length>{}</length></cylinder>",
            shown(radius),
            shown(length)
        ),
        Shape::Plane => "<plane><normal>0 0 1</normal><size>1 1</size></plane>".into(),
    };
    format!(
        "<!-- body {index}: {} -->\n<collision name=\"contact_{index}\">\n  <geometry>{geometry}</geometry>\n  <drake:proximity_properties>\n    <drake:point_contact_stiffness>{}</drake:point_contact_stiffness>\n    <drake:hunt_crossley_dissipation>{}</drake:hunt_crossley_dissipation>\n  </drake:proximity_properties>\n</collision>",
        describe(shape),
        k.text(),
        d.text()
    )
}
