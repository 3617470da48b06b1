//! Fixtures shared by the unit tests of the UI.

use crate::model::ImpactParams;
use crate::model::power_law::PowerLaw;
use crate::model::scene::Scene;

/// The paper's Fig. 5 scene: a steel sphere R = 10 mm on a steel plate, v₀ = 0.3 m/s, e = 0.6,
/// x_pl = 2.3 µm.
pub fn fig5_scene() -> Scene {
    Scene {
        name: "fig5".into(),
        ..crate::model::scene::tests::fig5_scene()
    }
}

/// Impact parameters of the Fig. 5 scene (m = 32.7 g, k = 1.465e10 N/m^1.5, e = 0.6, x_pl = 2.3 µm)
/// at pre-impact velocity `v0`.
pub fn fig5_params(v0: f64) -> ImpactParams {
    ImpactParams {
        mass: 0.0327,
        law: PowerLaw {
            k: 1.465e10,
            n: 1.5,
        },
        v0,
        restitution: 0.6,
        plastic_indentation: 2.3e-6,
        contact: crate::model::force::Contact::Unspecified,
    }
}
