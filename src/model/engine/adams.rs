//! MSC Adams / Altair MotionSolve, the `IMPACT` function (Adams/Solver function reference,
//! IMPACT; MotionSolve `Force_Contact` cnf_type="IMPACT").
//!
//! - Law: IMPACT(x, ẋ, x₁, k, e, c_max, d) = max(0, k·(x₁ − x)^e − STEP(x, x₁ − d, c_max, x₁, 0)·ẋ)
//!   for x < x₁, else 0: with the penetration δ = x₁ − x, F = k·δ^e + c(δ)·δ̇, where the cubic
//!   STEP raises the damping from 0 at δ = 0 to c_max at δ = d.
//! - Parameters: stiffness k (N/m^e), exponent e, maximum damping c_max (N·s/m), penetration d at
//!   which it is reached (m); the user writes them into the function expression.
//! - Combination: none — one expression per body pair; k is the pair's own.
//! - End of contact: max(0, …) clamps the force, so contact ends where F falls to 0.
//!
//! As a hertz-tui law: the `adams-impact` row, calibrated with the printed d.

use crate::model::force::adams_impact::{AdamsImpact, DEPTH_FRACTION};
use crate::model::force::{AnyLaw, ForceModel};
use crate::model::power_law::PowerLaw;

use super::error::EngineError;
use super::solve::{calibrated_damping, realise};
use super::{Engine, EngineScene, Fragment, Parameter, Translation, shown};

/// This engine's row of [`super::ENGINES`].
pub const ENGINE: Engine = Engine {
    id: "adams",
    name: "Adams / MotionSolve (IMPACT)",
    source: "MSC Adams/Solver function reference: IMPACT; Altair MotionSolve Force_Contact (IMPACT)",
    translate,
};

/// The law-table row of IMPACT.
const ROW: ForceModel = ForceModel::with_id("adams-impact");

/// The IMPACT law with stiffness k, exponent n, c_max and d for an impact at `v0`.
fn law(scene: &EngineScene, elastic: PowerLaw, c_max: f64, depth: f64, v0: f64) -> AnyLaw {
    AnyLaw::AdamsImpact(AdamsImpact::new(
        ROW,
        &scene.params(elastic, v0),
        c_max,
        depth,
    ))
}

fn translate(scene: &EngineScene) -> Result<Translation, EngineError> {
    let PowerLaw { k, n } = scene.elastic;
    let stiffness = Parameter::new(
        "k",
        k,
        "N/m^e",
        "the scene's Hertz stiffness (eq 2), or the fitted law for cylinders",
    );
    let exponent = Parameter::new("e", n, "", "the scene's exponent n (3/2 for spheres)");
    let depth = Parameter::new(
        "d",
        DEPTH_FRACTION * scene.x_max,
        "m",
        format!(
            "a tenth of the elastic maximum approach x_max = {} m",
            shown(scene.x_max)
        ),
    );
    let elastic = PowerLaw {
        k: stiffness.value,
        n: exponent.value,
    };
    // The tangent spring's critical damping at x_max sets the scale of c_max.
    let critical = 2.0 * (scene.mass * scene.elastic.tangent_stiffness(scene.x_max)).sqrt();
    let c_max = calibrated_damping(ENGINE.id, ROW, scene, elastic, 0.0..=1e3 * critical, |c| {
        Ok(law(scene, elastic, c, depth.value, scene.v0))
    })?;
    let c_max = Parameter::new(
        "cmax",
        c_max,
        "N·s/m",
        "the maximum damping whose realised e at v₀ is the requested e, F ≥ 0 clamp included (hertz-tui's calibration of adams-impact)",
    );
    let (realised, e_of_v) = realise(scene, |v0| {
        Ok(law(scene, elastic, c_max.value, depth.value, v0))
    })?;
    let notes = vec![
        "The model must be in SI units (m, N, s); x is the distance between the markers, x₁ its value at first touch (e.g. the sphere's radius above a plane through its centre marker).".into(),
        "With a fixed c_max and d, e depends on v₀ (see e(v₀)).".into(),
    ];
    let fragments = vec![Fragment {
        title: "Adams/Solver SFORCE function (translational, along the contact normal; I, J your markers, x1 the marker distance at first touch)",
        language: "text",
        text: format!(
            "FUNCTION = IMPACT(DZ(I,J,J), VZ(I,J,J,J), x1, {}, {}, {}, {})",
            stiffness.text(),
            exponent.text(),
            c_max.text(),
            depth.text()
        ),
    }];
    Ok(Translation {
        engine: ENGINE.id,
        name: ENGINE.name,
        source: ENGINE.source,
        law: format!(
            "F = max(0, k·δ^e + STEP(δ; 0, 0, d, c_max)·δ̇) with k = {} N/m^{}, c_max = {} N·s/m, d = {} m",
            stiffness.text(),
            exponent.text(),
            c_max.text(),
            depth.text()
        ),
        hertz_tui_law: format!(
            "Hertz with a STEP-ramped viscous damper (adams-impact), c_max = {} N·s/m, d = {} m, {}",
            c_max.text(),
            depth.text(),
            ROW.spec().contact.describe()
        ),
        model: ROW,
        end_rule: ROW.spec().contact,
        approximation: None,
        parameters: vec![stiffness, exponent, c_max, depth],
        fragments,
        notes,
        v0: scene.v0,
        e_requested: scene.restitution,
        realised,
        e_of_v,
    })
}
