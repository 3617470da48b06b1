//! Two bodies in contact: which contact law applies, reduced mass and radius, elastic factor.

use super::body::{Body, Shape};
use super::error::{Domain, ModelError};

/// The supported combinations of shapes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PairKind {
    SphereSphere,
    SpherePlane,
    /// Parallel axes.
    CylinderCylinder,
    CylinderPlane,
}

impl PairKind {
    /// Point contact (spheres, eqs 1–10) as opposed to line contact (cylinders, eqs 11–14).
    pub fn is_point_contact(self) -> bool {
        matches!(self, PairKind::SphereSphere | PairKind::SpherePlane)
    }
}

/// A validated pair of bodies. Construction fails for unsupported shape combinations.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactPair {
    body1: Body,
    body2: Body,
    kind: PairKind,
}

impl ContactPair {
    /// Validates both bodies (errors name `body1.…` / `body2.…`) and the shape combination.
    pub fn new(body1: Body, body2: Body) -> Result<Self, ModelError> {
        body1.validate().map_err(|e| e.within("body1"))?;
        body2.validate().map_err(|e| e.within("body2"))?;
        use Shape::*;
        let kind = match (body1.shape, body2.shape) {
            (Sphere { .. }, Sphere { .. }) => PairKind::SphereSphere,
            (Sphere { .. }, Plane) | (Plane, Sphere { .. }) => PairKind::SpherePlane,
            (Cylinder { .. }, Cylinder { .. }) => PairKind::CylinderCylinder,
            (Cylinder { .. }, Plane) | (Plane, Cylinder { .. }) => PairKind::CylinderPlane,
            (a, b) => return Err(ModelError::UnsupportedPair([a.name(), b.name()])),
        };
        let pair = ContactPair { body1, body2, kind };
        if !pair.reduced_mass().is_finite() {
            return Err(ModelError::OutOfDomain {
                formula: "reduced mass",
                detail: Domain::InfiniteMasses,
            });
        }
        Ok(pair)
    }

    pub fn body1(&self) -> &Body {
        &self.body1
    }

    pub fn body2(&self) -> &Body {
        &self.body2
    }

    pub fn kind(&self) -> PairKind {
        self.kind
    }

    /// Reduced mass m = m₁m₂/(m₁ + m₂), kg; a body of infinite mass drops out (eq 4).
    pub fn reduced_mass(&self) -> f64 {
        harmonic_combination(self.body1.mass(), self.body2.mass())
    }

    /// Reduced radius R = R₁R₂/(R₁ + R₂), m; a plane drops out (eq 2).
    pub fn reduced_radius(&self) -> f64 {
        harmonic_combination(self.body1.shape.radius(), self.body2.shape.radius())
    }

    /// Elastic factors (η₁, η₂) of the two bodies, m²/N (eq 3).
    pub fn elastic_factors(&self) -> (f64, f64) {
        (
            self.body1.material.elastic_factor(),
            self.body2.material.elastic_factor(),
        )
    }

    /// Elastic factor η = η₁ + η₂, m²/N (eq 3).
    pub fn elastic_factor(&self) -> f64 {
        let (eta1, eta2) = self.elastic_factors();
        eta1 + eta2
    }

    /// Contact length L of a line contact, m: the shorter cylinder (parallel axes); `None` for spheres.
    pub fn contact_length(&self) -> Option<f64> {
        let length = |b: &Body| match b.shape {
            Shape::Cylinder { length, .. } => length,
            _ => f64::INFINITY,
        };
        let l = length(&self.body1).min(length(&self.body2));
        l.is_finite().then_some(l)
    }

    /// The lower yield stress of the two materials, Pa: the softer body yields first.
    pub fn yield_stress(&self) -> f64 {
        self.body1
            .material
            .yield_stress
            .min(self.body2.material.yield_stress)
    }

    /// The lower bar wave speed √(E/ρ) of the two materials, m/s.
    pub fn wave_speed(&self) -> f64 {
        self.body1
            .material
            .wave_speed()
            .min(self.body2.material.wave_speed())
    }
}

/// a·b/(a + b), with an infinite operand dropping out.
fn harmonic_combination(a: f64, b: f64) -> f64 {
    match (a.is_infinite(), b.is_infinite()) {
        (true, true) => f64::INFINITY,
        (true, false) => b,
        (false, true) => a,
        (false, false) => a * b / (a + b),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::material::tests::steel;

    fn body(shape: Shape) -> Body {
        Body {
            shape,
            material: steel(),
            mass: Some(1.0),
        }
    }

    #[test]
    fn sphere_on_plane_reduces_to_the_sphere() {
        let pair = ContactPair::new(
            body(Shape::Sphere { radius: 0.01 }),
            Body {
                mass: None,
                ..body(Shape::Plane)
            },
        )
        .unwrap();
        assert_eq!(pair.kind(), PairKind::SpherePlane);
        assert_eq!(pair.reduced_mass(), 1.0);
        assert_eq!(pair.reduced_radius(), 0.01);
        assert!((pair.elastic_factor() - 9.1e-12).abs() < 1e-16);
    }

    #[test]
    fn two_cylinders_halve_mass_and_radius() {
        // Table 2: two 1 kg cylinders give the reduced mass 0.5 kg.
        let cyl = |length| {
            body(Shape::Cylinder {
                radius: 0.02,
                length,
            })
        };
        let pair = ContactPair::new(cyl(0.1), cyl(0.2)).unwrap();
        assert_eq!(pair.kind(), PairKind::CylinderCylinder);
        assert_eq!(pair.reduced_mass(), 0.5);
        assert_eq!(pair.reduced_radius(), 0.01);
        assert_eq!(pair.contact_length(), Some(0.1));
    }

    #[test]
    fn mixed_shapes_are_refused_by_name() {
        let err = ContactPair::new(
            body(Shape::Sphere { radius: 0.01 }),
            body(Shape::Cylinder {
                radius: 0.01,
                length: 0.1,
            }),
        )
        .unwrap_err();
        assert!(
            err.to_string()
                .starts_with("sphere–cylinder contact is not supported"),
            "{err}"
        );
        let err = ContactPair::new(body(Shape::Plane), body(Shape::Plane)).unwrap_err();
        assert!(err.to_string().starts_with("plane–plane"), "{err}");
    }

    #[test]
    fn invalid_body_names_its_position() {
        let err = ContactPair::new(
            body(Shape::Sphere { radius: 0.01 }),
            body(Shape::Sphere { radius: -1.0 }),
        )
        .unwrap_err();
        assert!(err.to_string().starts_with("body2.radius"), "{err}");
    }
}
