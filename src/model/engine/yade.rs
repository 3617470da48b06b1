//! Yade, Hertz–Mindlin (pkg/dem/HertzMindlin.cpp: `Ip2_FrictMat_FrictMat_MindlinPhys`,
//! `Law2_ScGeom_MindlinPhys_Mindlin`).
//!
//! - Law: Fₙ = kₙ₀·uₙ^{3/2} − cₙ·u̇ₙ, kₙ₀ = (4/3)·E·√R, cₙ = α·√m·uₙ^{1/4} with
//!   α = −2√(5/6)·ln eₙ/√(ln² eₙ + π²)·√(2E√R) (Tsuji 1992; Antypov 2011 eq. 17): Hertz with
//!   Tsuji's damping, the same β-map as Chrono and LIGGGHTS.
//! - Parameters: `FrictMat(young, poisson)` per body; `en` (a MatchMaker) of the Ip2 functor.
//! - Combination: E = EₐE_b/((1 − νₐ²)E_b + (1 − ν_b²)Eₐ), R = RₐR_b/(Rₐ + R_b) from the ScGeom's
//!   reference radii, m the reduced mass (the dynamic body's mass against a static one).
//! - End of contact: without adhesion the total normal force is set to 0 when the viscous part
//!   would make it attractive (F ≥ 0 clamp).

use super::error::EngineError;
use super::tsuji::{self, Family};
use super::{Engine, EngineScene, Fragment, Parameter, Translation, shown};

/// This engine's row of [`super::ENGINES`].
pub const ENGINE: Engine = Engine {
    id: "yade",
    name: "Yade (Hertz–Mindlin, en)",
    source: "yade: pkg/dem/HertzMindlin.cpp",
    translate,
};

fn translate(scene: &EngineScene) -> Result<Translation, EngineError> {
    let family = Family {
        engine: &ENGINE,
        model: tsuji::CLAMPED,
        parameter: "en",
        stored: |x| x,
    };
    let notes = vec![format!(
        "Yade takes R from the ScGeom's reference radii; where one side reports no radius (refR1 ≤ 0) HertzMindlin.cpp uses the other twice, R = R₂/2. The law above assumes R = {} m.",
        shown(scene.r_star)
    )];
    tsuji::translate(&family, scene, |e| fragments(scene, e), notes)
}

fn fragments(scene: &EngineScene, e: &Parameter) -> Vec<Fragment> {
    let [b1, b2] = scene.bodies();
    let material = |m: &crate::model::Material| {
        format!(
            "FrictMat(young={}, poisson={}, density={}, frictionAngle=0)",
            shown(m.youngs_modulus),
            shown(m.poisson_ratio),
            shown(m.density)
        )
    };
    vec![Fragment {
        title: "Yade Python",
        language: "python",
        text: format!(
            "mat1 = O.materials.append({})\nmat2 = O.materials.append({})\nO.engines = [\n    ForceResetter(),\n    InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb(), Bo1_Wall_Aabb()]),\n    InteractionLoop(\n        [Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()],\n        [Ip2_FrictMat_FrictMat_MindlinPhys(en=MatchMaker(algo='val', val={}))],\n        [Law2_ScGeom_MindlinPhys_Mindlin()],\n    ),\n    NewtonIntegrator(damping=0),\n]",
            material(&b1.material),
            material(&b2.material),
            e.text()
        ),
    }]
}
