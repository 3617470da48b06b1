//! LAMMPS `pair_style granular`, `hertz/material` with `damping coeff_restitution`
//! (doc/src/pair_granular.rst; src/GRANULAR/gran_sub_mod_damping.cpp).
//!
//! - Law: F = (4/3)·E·√R·δ^{3/2} − η·vₙ, η = damp·√(m_eff·F_ne/δ) with, for Hertzian models,
//!   damp = −√(3/2)·2√(5/6)·ln e/√(π² + ln² e): with F_ne/δ = (4/3)E√(Rδ) this is Tsuji's
//!   γ·δ^{1/4} with the same β-map as Chrono, LIGGGHTS and Yade.
//! - Parameters: `pair_coeff i j hertz/material E e ν … damping coeff_restitution`.
//! - Combination: E_eff = ((1 − νᵢ²)/Eᵢ + (1 − νⱼ²)/Eⱼ)⁻¹ when mixing per-type coefficients,
//!   R = RᵢRⱼ/(Rᵢ + Rⱼ), m_eff the reduced mass; a `fix wall/gran` is infinitely massive and flat.
//! - End of contact: the damping may pull (tension allowed) unless `limit_damping` is given.

use crate::model::Shape;

use super::error::EngineError;
use super::tsuji::{self, Family};
use super::{Engine, EngineScene, Fragment, Translation, shown};

/// This engine's row of [`super::ENGINES`].
pub const ENGINE: Engine = Engine {
    id: "lammps",
    name: "LAMMPS (granular, damping coeff_restitution)",
    source: "lammps/lammps: doc/src/pair_granular.rst, src/GRANULAR/gran_sub_mod_damping.cpp",
    translate,
};

fn translate(scene: &EngineScene) -> Result<Translation, EngineError> {
    let family = Family {
        engine: &ENGINE,
        model: tsuji::TENSION,
        parameter: "e (hertz/material, damping coeff_restitution)",
        stored: |x| x,
    };
    let notes = vec![
        "Calibrated for LAMMPS's default end of contact (tension allowed); adding limit_damping changes the realised e as stated above.".into(),
    ];
    tsuji::translate(
        &family,
        scene,
        |e| lines(scene, &e.text(), "coeff_restitution"),
        notes,
    )
}

/// The `pair_coeff` (and `fix wall/gran`) lines for input coefficient `coefficient` under the
/// damping model `damping`; shared with the tsuji variant.
pub fn lines(scene: &EngineScene, coefficient: &str, damping: &str) -> Vec<Fragment> {
    let [b1, b2] = scene.bodies();
    let model = |m: &crate::model::Material| {
        format!(
            "hertz/material {} {coefficient} {} tangential linear_nohistory 0 0 damping {damping}",
            shown(m.youngs_modulus),
            shown(m.poisson_ratio)
        )
    };
    let text = if b2.shape == Shape::Plane {
        // One (E, ν) serves both sides of a wall: E = 2(1 − ν²)·E* makes E_eff = E*.
        let nu = b1.material.poisson_ratio;
        let wall = format!(
            "hertz/material {} {coefficient} {} tangential linear_nohistory 0 0 damping {damping}",
            shown(2.0 * (1.0 - nu * nu) * scene.e_star),
            shown(nu)
        );
        format!(
            "pair_style granular\npair_coeff 1 1 {}\nfix plate all wall/gran granular {wall} zplane 0.0 NULL",
            model(&b1.material)
        )
    } else {
        format!(
            "pair_style granular\npair_coeff 1 1 {}\npair_coeff 2 2 {}",
            model(&b1.material),
            model(&b2.material)
        )
    };
    vec![Fragment {
        title: "LAMMPS input (type 1: body 1, type 2 or the wall: body 2)",
        language: "text",
        text,
    }]
}
