//! Colliding bodies: a shape, a material and a mass.

use std::f64::consts::PI;
use std::fmt;

use super::error::{ModelError, require, require_positive};
use super::material::Material;

/// The geometry of a body near the contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Shape {
    Sphere {
        radius: f64,
    },
    /// A circular cylinder touching along a generator (parallel axes).
    Cylinder {
        radius: f64,
        length: f64,
    },
    /// A massive half-space: infinite radius of curvature and, unless a mass is given, infinite mass.
    Plane,
}

impl Shape {
    /// The word used in scene files and messages.
    pub fn name(&self) -> &'static str {
        match self {
            Shape::Sphere { .. } => "sphere",
            Shape::Cylinder { .. } => "cylinder",
            Shape::Plane => "plane",
        }
    }

    /// Radius of curvature at the contact, m (∞ for a plane).
    pub fn radius(&self) -> f64 {
        match *self {
            Shape::Sphere { radius } | Shape::Cylinder { radius, .. } => radius,
            Shape::Plane => f64::INFINITY,
        }
    }

    /// Volume, m³ (∞ for a plane).
    pub fn volume(&self) -> f64 {
        match *self {
            Shape::Sphere { radius } => 4.0 / 3.0 * PI * radius.powi(3),
            Shape::Cylinder { radius, length } => PI * radius * radius * length,
            Shape::Plane => f64::INFINITY,
        }
    }
}

impl fmt::Display for Shape {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// One of the two colliding bodies.
#[derive(Debug, Clone, PartialEq)]
pub struct Body {
    pub shape: Shape,
    pub material: Material,
    /// Mass in kg; `None` means density × volume (∞ for a plane).
    pub mass: Option<f64>,
}

impl Body {
    /// Checks the geometry, the mass if given, and the material; field names are relative to the body.
    pub fn validate(&self) -> Result<(), ModelError> {
        match self.shape {
            Shape::Sphere { radius } => {
                require_positive("radius", radius)?;
            }
            Shape::Cylinder { radius, length } => {
                require_positive("radius", radius)?;
                require_positive("length", length)?;
            }
            Shape::Plane => {}
        }
        // The material first: a derived mass is only meaningful with a valid density.
        self.material.validate().map_err(|e| e.within("material"))?;
        match (self.mass, self.shape) {
            (Some(mass), _) => {
                require_positive("mass", mass)?;
            }
            (None, Shape::Plane) => {}
            // density × volume can overflow or underflow even when each factor is valid.
            (None, _) => {
                require(
                    "mass",
                    self.mass(),
                    "finite and > 0 when derived from density × volume (give `mass`)",
                    |m| m > 0.0,
                )?;
            }
        }
        Ok(())
    }

    /// Mass in kg: the given one, else density × volume (∞ for a plane).
    pub fn mass(&self) -> f64 {
        self.mass
            .unwrap_or_else(|| self.material.density * self.shape.volume())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::material::tests::{aluminium, steel};

    fn sphere(radius: f64, material: Material) -> Body {
        Body {
            shape: Shape::Sphere { radius },
            material,
            mass: None,
        }
    }

    #[test]
    fn density_masses_round_to_table_1() {
        // Table 1 prints 0.004, 0.033 and 0.011 kg.
        assert!((sphere(0.005, steel()).mass() - 0.004).abs() < 0.0005);
        assert!((sphere(0.01, steel()).mass() - 0.033).abs() < 0.0005);
        assert!((sphere(0.01, aluminium()).mass() - 0.011).abs() < 0.0005);
    }

    #[test]
    fn given_mass_wins_and_plane_is_infinite() {
        let mut b = sphere(0.01, steel());
        b.mass = Some(1.0);
        assert_eq!(b.mass(), 1.0);
        let plane = Body {
            shape: Shape::Plane,
            material: steel(),
            mass: None,
        };
        assert!(plane.mass().is_infinite());
        assert!(plane.shape.radius().is_infinite());
    }

    #[test]
    fn a_derived_mass_that_overflows_names_the_mass() {
        let msg = sphere(1e300, steel()).validate().unwrap_err().to_string();
        assert!(
            msg.starts_with("mass must be finite and > 0 when derived from density × volume"),
            "{msg}"
        );
        let mut given = sphere(1e300, steel());
        given.mass = Some(1.0);
        assert!(given.validate().is_ok());
    }

    #[test]
    fn validation_names_the_field() {
        let msg = sphere(0.0, steel()).validate().unwrap_err().to_string();
        assert!(msg.starts_with("radius must be"), "{msg}");
        let mut m = steel();
        m.poisson_ratio = 0.7;
        let msg = sphere(0.01, m).validate().unwrap_err().to_string();
        assert!(msg.starts_with("material.poisson_ratio"), "{msg}");
        let cyl = Body {
            shape: Shape::Cylinder {
                radius: 0.02,
                length: -0.1,
            },
            material: steel(),
            mass: None,
        };
        let msg = cyl.validate().unwrap_err().to_string();
        assert!(msg.starts_with("length must be"), "{msg}");
    }
}
