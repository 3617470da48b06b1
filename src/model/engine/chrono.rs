//! Project Chrono, SMC contact with the Hertz model from material properties
//! (src/chrono/physics/ChContactSMC.h, `CalculateForce`; ChContactMaterialSMC.h).
//!
//! - Law: Fₙ = kₙ·δ − gₙ·vₙ with Sₙ = 2E_eff·√(R·δ), kₙ = (2/3)·Sₙ, β = ln e/√(ln² e + π²),
//!   gₙ = −2√(5/6)·β·√(Sₙ·m): Hertz with Tsuji's damping γ·δ^{1/4}·δ̇.
//! - Parameters: per material `SetYoungModulus`, `SetPoissonRatio`, `SetRestitution` (stored as
//!   `float`); `ChSystemSMC::SetContactForceModel(Hertz)`, `UseMaterialProperties(true)`.
//! - Combination: a composite material (E_eff from both materials' E, ν; restitution by the
//!   composition strategy); R is the collision pair's effective radius, m the reduced mass.
//! - End of contact: the core module clamps — `if (forceN < 0) forceN = 0` — so contact ends
//!   where F falls to 0. (Chrono::Multicore computes SMC forces in its own routine, not read
//!   here.)

use super::error::EngineError;
use super::tsuji::{self, Family};
use super::{Engine, EngineScene, Fragment, Parameter, Translation, shown};

/// This engine's row of [`super::ENGINES`].
pub const ENGINE: Engine = Engine {
    id: "chrono",
    name: "Project Chrono (SMC, Hertz)",
    source: "projectchrono/chrono: src/chrono/physics/ChContactSMC.h",
    translate,
};

/// Chrono keeps material properties in single precision.
fn single_precision(x: f64) -> f64 {
    x as f32 as f64
}

fn translate(scene: &EngineScene) -> Result<Translation, EngineError> {
    let family = Family {
        engine: &ENGINE,
        model: tsuji::CLAMPED,
        parameter: "SetRestitution",
        stored: single_precision,
    };
    let notes = vec![
        "Chrono stores the restitution as a float, so the realised e is that of the input rounded to single precision (about 1e-7).".into(),
        format!(
            "R is taken from the collision system's effective radius of the pair; the law above assumes R = {} m.",
            shown(scene.r_star)
        ),
    ];
    tsuji::translate(&family, scene, |e| fragments(scene, e), notes)
}

fn fragments(scene: &EngineScene, e: &Parameter) -> Vec<Fragment> {
    let [b1, b2] = scene.bodies();
    let material = |name: &str, m: &crate::model::Material| {
        format!(
            "auto {name} = chrono_types::make_shared<ChContactMaterialSMC>();  // {}\n{name}->SetYoungModulus({}f);\n{name}->SetPoissonRatio({}f);\n{name}->SetRestitution({}f);",
            m.name,
            shown(m.youngs_modulus),
            shown(m.poisson_ratio),
            e.text()
        )
    };
    vec![Fragment {
        title: "Chrono C++ (ChSystemSMC)",
        language: "cpp",
        text: format!(
            "ChSystemSMC sys;\nsys.SetContactForceModel(ChSystemSMC::ContactForceModel::Hertz);\nsys.UseMaterialProperties(true);\n{}\n{}",
            material("mat1", &b1.material),
            material("mat2", &b2.material)
        ),
    }]
}
