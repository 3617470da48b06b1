//! Simbody `HuntCrossleyForce`, and OpenSim's `HuntCrossleyForce` built on it
//! (Simbody/include/simbody/internal/HuntCrossleyForce.h).
//!
//! - Law: f = k·x^{3/2}·(1 + (3/2)·c·ẋ), k = (4/3)·√R·E, for sphere–sphere and sphere–half-space.
//! - Parameters: per surface `stiffness` E (a plane-strain modulus, Pa) and `dissipation` c (s/m).
//! - Combination: R = R₁R₂/(R₁ + R₂); s₁ = E₂^{2/3}/(E₁^{2/3} + E₂^{2/3}), E = (s₁·E₁^{2/3})^{3/2},
//!   c = c₁·s₁ + c₂·(1 − s₁). Two equal stiffnesses E₀ combine to E₀/2^{3/2}, not Hertz's
//!   E₀/2: each surface is taken as a Hertz spring of its own, in series.
//! - End of contact: 1 + (3/2)·c·ẋ never reaches 0 during an impact (exact::hysteresis), so
//!   contact ends at x = 0 whether or not a tensile total is dropped.
//!
//! As a hertz-tui law: the `hunt-crossley` row (the Hunt–Crossley family) with n = 3/2 and
//! χ = (3/2)·c·v₀, solved exactly and calibrated by the family's exact relation.

use std::f64::consts::SQRT_2;

use crate::model::force::ForceModel;
use crate::model::power_law::PowerLaw;

use super::error::EngineError;
use super::solve::{hunt_crossley, hunt_crossley_chi, realise};
use super::{Engine, EngineScene, Fragment, Parameter, Translation, shown};

/// This engine's row of [`super::ENGINES`].
pub const ENGINE: Engine = Engine {
    id: "simbody",
    name: "Simbody / OpenSim (HuntCrossleyForce)",
    source: "simbody: Simbody/include/simbody/internal/HuntCrossleyForce.h",
    translate,
};

/// 2^{3/2}: two equal surface stiffnesses E₀ combine to E₀/2^{3/2}.
const SERIES_FACTOR: f64 = 2.0 * SQRT_2;

fn translate(scene: &EngineScene) -> Result<Translation, EngineError> {
    scene.require_point_contact(ENGINE.id)?;
    let stiffness = Parameter::new(
        "stiffness",
        SERIES_FACTOR * scene.e_star,
        "Pa",
        format!(
            "per surface, 2^(3/2)·E*: two equal values combine to Hertz's E* = {} Pa, so k = (4/3)√R·E* is the scene's Hertz k",
            shown(scene.e_star)
        ),
    );
    let e_combined = stiffness.value / SERIES_FACTOR;
    let elastic = PowerLaw {
        k: 4.0 / 3.0 * scene.r_star.sqrt() * e_combined,
        n: 1.5,
    };
    let chi = hunt_crossley_chi(ENGINE.id, scene, elastic)?;
    let dissipation = Parameter::new(
        "dissipation",
        2.0 * chi / (3.0 * scene.v0),
        "s/m",
        format!(
            "per surface, equal on both: c = 2χ/(3v₀) with χ = {} the root of ln((1 + χ)/(1 − χe)) = χ(1 + e)",
            shown(chi)
        ),
    );
    let (realised, e_of_v) = realise(scene, |v0| {
        Ok(hunt_crossley(
            scene,
            elastic,
            v0,
            1.5 * dissipation.value * v0,
        )?)
    })?;
    let [b1, b2] = scene.bodies();
    let documented =
        |m: &crate::model::Material| m.youngs_modulus / (1.0 - m.poisson_ratio.powi(2));
    let (p1, p2) = (documented(&b1.material), documented(&b2.material));
    let series = (p1.powf(-2.0 / 3.0) + p2.powf(-2.0 / 3.0)).powf(-1.5);
    let notes = vec![
        format!(
            "Giving each surface its own plane-strain modulus E/(1 − ν²), as the Simbody documentation suggests, combines to {} Pa instead of E* = {} Pa: k {} by a factor {}.",
            shown(series),
            shown(scene.e_star),
            if series < scene.e_star { "falls" } else { "rises" },
            shown(series / scene.e_star)
        ),
        "c is a constant, so e falls as v₀ rises (see e(v₀)); Simbody's own guide (e ≈ 1 − c·v) holds only for small c·v.".into(),
    ];
    let fragments = vec![
        Fragment {
            title: "Simbody C++ (surfaces of one contact set)",
            language: "cpp",
            text: format!(
                "HuntCrossleyForce hc(forces, contacts, contactSet);\n// stiffness (Pa), dissipation (s/m), static, dynamic, viscous friction\nhc.setBodyParameters(ContactSurfaceIndex(0), {s}, {c}, 0, 0, 0);\nhc.setBodyParameters(ContactSurfaceIndex(1), {s}, {c}, 0, 0, 0);",
                s = stiffness.text(),
                c = dissipation.text()
            ),
        },
        Fragment {
            title: "OpenSim model XML (in <ForceSet><objects>; name your two ContactGeometry objects in <geometry>)",
            language: "xml",
            text: format!(
                "<HuntCrossleyForce name=\"impact\">\n  <HuntCrossleyForce::ContactParametersSet name=\"contact_parameters\">\n    <objects>\n      <HuntCrossleyForce::ContactParameters>\n        <geometry>body1_contact body2_contact</geometry>\n        <stiffness>{s}</stiffness>\n        <dissipation>{c}</dissipation>\n        <static_friction>0</static_friction>\n        <dynamic_friction>0</dynamic_friction>\n        <viscous_friction>0</viscous_friction>\n      </HuntCrossleyForce::ContactParameters>\n    </objects>\n  </HuntCrossleyForce::ContactParametersSet>\n</HuntCrossleyForce>",
                s = stiffness.text(),
                c = dissipation.text()
            ),
        },
    ];
    Ok(Translation {
        engine: ENGINE.id,
        name: ENGINE.name,
        source: ENGINE.source,
        law: format!(
            "f = k·x^(3/2)·(1 + 1.5·c·ẋ) with k = {} N/m^1.5, c = {} s/m",
            shown(elastic.k),
            dissipation.text()
        ),
        hertz_tui_law: format!(
            "Hunt–Crossley family F = k·xⁿ·(1 + χ·ẋ/v₀), n = 3/2, χ = {}",
            shown(1.5 * dissipation.value * scene.v0)
        ),
        model: ForceModel::HuntCrossley,
        end_rule: ForceModel::HuntCrossley.spec().contact,
        approximation: None,
        parameters: vec![stiffness, dissipation],
        fragments,
        notes,
        v0: scene.v0,
        e_requested: scene.restitution,
        realised,
        e_of_v,
    })
}
