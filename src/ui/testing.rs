//! Fixtures shared by the unit tests of the UI.

use crate::model::body::{Body, Shape};
use crate::model::material::tests::steel;
use crate::model::scene::{ImpactConditions, Scene};

/// The paper's Fig. 5 scene: a steel sphere R = 10 mm on a steel plate, v₀ = 0.3 m/s, e = 0.6,
/// x_pl = 2.3 µm.
pub fn fig5_scene() -> Scene {
    Scene {
        name: "fig5".into(),
        body1: Body {
            shape: Shape::Sphere { radius: 0.01 },
            material: steel(),
            mass: None,
        },
        body2: Body {
            shape: Shape::Plane,
            material: steel(),
            mass: None,
        },
        impact: ImpactConditions {
            v0: 0.3,
            restitution: 0.6,
            plastic_indentation: 2.3e-6,
        },
    }
}
