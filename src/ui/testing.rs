//! Fixtures shared by the unit tests of the UI.

use crate::model::scene::Scene;

/// The paper's Fig. 5 scene: a steel sphere R = 10 mm on a steel plate, v₀ = 0.3 m/s, e = 0.6,
/// x_pl = 2.3 µm.
pub fn fig5_scene() -> Scene {
    Scene {
        name: "fig5".into(),
        ..crate::model::scene::tests::fig5_scene()
    }
}

pub(crate) use crate::model::scene::tests::fig5_params;
