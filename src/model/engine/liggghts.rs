//! LIGGGHTS, `gran model hertz` (doc/gran_model_hertz.txt).
//!
//! - Law: Fₙ = kₙ·δₙ − γₙ·vₙ with kₙ = (4/3)·Y*·√(R*·δₙ), Sₙ = 2Y*·√(R*·δₙ),
//!   γₙ = −2√(5/6)·β·√(Sₙ·m*), β = ln e/√(ln² e + π²): Hertz with Tsuji's damping.
//! - Parameters: `youngsModulus` and `poissonsRatio` per atom type, `coefficientRestitution`
//!   per type pair (fix property/global).
//! - Combination: 1/Y* = (1 − ν₁²)/Y₁ + (1 − ν₂²)/Y₂, R* = R₁R₂/(R₁ + R₂), m* = m₁m₂/(m₁ + m₂).
//! - End of contact: `limitForce on` keeps the normal force from turning attractive (F ≥ 0);
//!   with it off (the default) tension is allowed and contact ends at δ = 0.

use super::error::EngineError;
use super::tsuji::{self, Family};
use super::{Engine, EngineScene, Fragment, Parameter, Translation, shown};

/// This engine's row of [`super::ENGINES`].
pub const ENGINE: Engine = Engine {
    id: "liggghts",
    name: "LIGGGHTS (gran model hertz)",
    source: "CFDEMproject/LIGGGHTS-PUBLIC: doc/gran_model_hertz.txt",
    translate,
};

fn translate(scene: &EngineScene) -> Result<Translation, EngineError> {
    let family = Family {
        engine: &ENGINE,
        model: tsuji::CLAMPED,
        parameter: "coefficientRestitution",
        stored: |x| x,
    };
    let notes = vec![
        "The fragment turns limitForce on (no attractive force, the physical end of contact); the input restitution is calibrated for it.".into(),
        "A plane is a mesh or primitive wall of the second atom type's material; walls have infinite mass and radius.".into(),
    ];
    tsuji::translate(&family, scene, |e| fragments(scene, e), notes)
}

fn fragments(scene: &EngineScene, e: &Parameter) -> Vec<Fragment> {
    let [b1, b2] = scene.bodies();
    let e = e.text();
    vec![Fragment {
        title: "LIGGGHTS input (type 1: body 1, type 2: body 2)",
        language: "text",
        text: format!(
            "pair_style gran model hertz tangential history limitForce on\npair_coeff * *\nfix m1 all property/global youngsModulus peratomtype {} {}\nfix m2 all property/global poissonsRatio peratomtype {} {}\nfix m3 all property/global coefficientRestitution peratomtypepair 2 {e} {e} {e} {e}\nfix m4 all property/global coefficientFriction peratomtypepair 2 0 0 0 0",
            shown(b1.material.youngs_modulus),
            shown(b2.material.youngs_modulus),
            shown(b1.material.poisson_ratio),
            shown(b2.material.poisson_ratio),
        ),
    }]
}
