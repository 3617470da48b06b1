//! Typed access to the numeric keys of a scene by their dotted names (`impact.v0`, `body1.radius`, …).

use std::fmt;
use std::str::FromStr;

use super::body::{Body, Shape};
use super::scene::{ImpactConditions, Scene};

/// Which body a key addresses.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum BodyIndex {
    One,
    Two,
}

/// A numeric field of a body.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum BodyField {
    Radius,
    Length,
    Mass,
    YoungsModulus,
    PoissonRatio,
    YieldStress,
    Density,
}

/// A numeric scene key: the parameter a sweep varies or a form field edits.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SceneKey {
    V0,
    Restitution,
    PlasticIndentation,
    Body(BodyIndex, BodyField),
}

impl SceneKey {
    /// The dotted path used in scene files, `--set` and `--param`.
    pub fn path(self) -> String {
        match self {
            SceneKey::V0 => "impact.v0".into(),
            SceneKey::Restitution => "impact.restitution".into(),
            SceneKey::PlasticIndentation => "impact.plastic_indentation".into(),
            SceneKey::Body(index, field) => {
                let body = match index {
                    BodyIndex::One => "body1",
                    BodyIndex::Two => "body2",
                };
                let field = match field {
                    BodyField::Radius => "radius",
                    BodyField::Length => "length",
                    BodyField::Mass => "mass",
                    BodyField::YoungsModulus => "material.youngs_modulus",
                    BodyField::PoissonRatio => "material.poisson_ratio",
                    BodyField::YieldStress => "material.yield_stress",
                    BodyField::Density => "material.density",
                };
                format!("{body}.{field}")
            }
        }
    }

    /// SI unit of the key's value.
    pub fn unit(self) -> &'static str {
        match self {
            SceneKey::V0 => "m/s",
            SceneKey::Restitution => "",
            SceneKey::PlasticIndentation => "m",
            SceneKey::Body(_, field) => match field {
                BodyField::Radius | BodyField::Length => "m",
                BodyField::Mass => "kg",
                BodyField::YoungsModulus | BodyField::YieldStress => "Pa",
                BodyField::PoissonRatio => "",
                BodyField::Density => "kg/m³",
            },
        }
    }

    /// The current value, or `None` where the scene has no such value (a plane's radius, a derived mass).
    pub fn get(self, scene: &Scene) -> Option<f64> {
        match self {
            SceneKey::V0 => Some(scene.impact.v0),
            SceneKey::Restitution => Some(scene.impact.restitution),
            SceneKey::PlasticIndentation => Some(scene.impact.plastic_indentation),
            SceneKey::Body(index, field) => {
                let body = body(scene, index);
                match (field, body.shape) {
                    (BodyField::Radius, Shape::Sphere { radius })
                    | (BodyField::Radius, Shape::Cylinder { radius, .. }) => Some(radius),
                    (BodyField::Length, Shape::Cylinder { length, .. }) => Some(length),
                    (BodyField::Radius | BodyField::Length, _) => None,
                    (BodyField::Mass, _) => body.mass,
                    (BodyField::YoungsModulus, _) => Some(body.material.youngs_modulus),
                    (BodyField::PoissonRatio, _) => Some(body.material.poisson_ratio),
                    (BodyField::YieldStress, _) => Some(body.material.yield_stress),
                    (BodyField::Density, _) => Some(body.material.density),
                }
            }
        }
    }

    /// Sets the value; validation is left to the model (`Scene::quasistatic`), which names the field.
    pub fn set(self, scene: &mut Scene, value: f64) -> Result<(), SceneKeyError> {
        match self {
            SceneKey::V0 | SceneKey::Restitution | SceneKey::PlasticIndentation => {
                if let Some(condition) = self.impact_condition(&mut scene.impact) {
                    *condition = value;
                }
                // A value set is given, no longer the preset's stand-in.
                let path = self.path();
                if let Some(key) = path.strip_prefix("impact.") {
                    scene.assumed.set(key, false);
                }
            }
            SceneKey::Body(index, field) => {
                let body = body_mut(scene, index);
                match (field, &mut body.shape) {
                    (BodyField::Radius, Shape::Sphere { radius })
                    | (BodyField::Radius, Shape::Cylinder { radius, .. }) => *radius = value,
                    (BodyField::Length, Shape::Cylinder { length, .. }) => *length = value,
                    (BodyField::Radius | BodyField::Length, shape) => {
                        return Err(SceneKeyError::NotApplicable {
                            key: self,
                            shape: shape.name(),
                        });
                    }
                    (BodyField::Mass, _) => body.mass = Some(value),
                    (BodyField::YoungsModulus, _) => body.material.youngs_modulus = value,
                    (BodyField::PoissonRatio, _) => body.material.poisson_ratio = value,
                    (BodyField::YieldStress, _) => body.material.yield_stress = value,
                    (BodyField::Density, _) => body.material.density = value,
                }
            }
        }
        Ok(())
    }

    /// The impact condition this key names (`impact.*`), `None` for a key of the bodies: a sweep
    /// of an impact condition leaves the bodies, and what they fix, unchanged.
    pub fn impact_condition(self, impact: &mut ImpactConditions) -> Option<&mut f64> {
        match self {
            SceneKey::V0 => Some(&mut impact.v0),
            SceneKey::Restitution => Some(&mut impact.restitution),
            SceneKey::PlasticIndentation => Some(&mut impact.plastic_indentation),
            SceneKey::Body(..) => None,
        }
    }

    /// Every numeric key.
    pub fn all() -> Vec<SceneKey> {
        let fields = [
            BodyField::Radius,
            BodyField::Length,
            BodyField::Mass,
            BodyField::YoungsModulus,
            BodyField::PoissonRatio,
            BodyField::YieldStress,
            BodyField::Density,
        ];
        let mut keys = vec![
            SceneKey::V0,
            SceneKey::Restitution,
            SceneKey::PlasticIndentation,
        ];
        for index in [BodyIndex::One, BodyIndex::Two] {
            keys.extend(fields.iter().map(|&f| SceneKey::Body(index, f)));
        }
        keys
    }
}

fn body(scene: &Scene, index: BodyIndex) -> &Body {
    match index {
        BodyIndex::One => &scene.body1,
        BodyIndex::Two => &scene.body2,
    }
}

fn body_mut(scene: &mut Scene, index: BodyIndex) -> &mut Body {
    match index {
        BodyIndex::One => &mut scene.body1,
        BodyIndex::Two => &mut scene.body2,
    }
}

impl fmt::Display for SceneKey {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.path())
    }
}

impl FromStr for SceneKey {
    type Err = SceneKeyError;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        SceneKey::all()
            .into_iter()
            .find(|k| k.path() == s)
            .ok_or_else(|| SceneKeyError::Unknown(s.to_string()))
    }
}

/// A key that does not name a numeric scene value, or does not apply to the body's shape.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SceneKeyError {
    #[error(
        "unknown numeric scene key '{0}' (e.g. impact.v0, impact.restitution, impact.plastic_indentation, body1.radius, body2.material.youngs_modulus)"
    )]
    Unknown(String),
    #[error("{key} does not apply: the body is a {shape}")]
    NotApplicable { key: SceneKey, shape: &'static str },
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::scene::tests::fig5_scene;

    #[test]
    fn every_key_round_trips_through_its_path() {
        for key in SceneKey::all() {
            assert_eq!(key.path().parse::<SceneKey>(), Ok(key));
        }
        assert!(matches!(
            "impact.vo".parse::<SceneKey>(),
            Err(SceneKeyError::Unknown(_))
        ));
    }

    #[test]
    fn set_then_get_and_shape_checks() {
        let mut s = fig5_scene();
        let radius: SceneKey = "body1.radius".parse().unwrap();
        radius.set(&mut s, 0.02).unwrap();
        assert_eq!(radius.get(&s), Some(0.02));
        let e: SceneKey = "body2.material.youngs_modulus".parse().unwrap();
        e.set(&mut s, 7e10).unwrap();
        assert_eq!(s.body2.material.youngs_modulus, 7e10);
        let plane_radius: SceneKey = "body2.radius".parse().unwrap();
        assert_eq!(plane_radius.get(&s), None);
        let err = plane_radius.set(&mut s, 1.0).unwrap_err();
        assert_eq!(
            err.to_string(),
            "body2.radius does not apply: the body is a plane"
        );
    }
}
