//! What a law may need to know about the bodies beyond F = k·xⁿ and the reduced mass: the yield
//! pressure and elastic constants of a point contact (Thornton, docs/physics.md §6.6) and the
//! yield pressure and eq 13/14 geometry of a line contact (the exact line-contact law, §6.7). Built from the scene's
//! pair; parameters assembled by hand carry [`Contact::Unspecified`], and the laws that need the
//! bodies refuse it by name.

use crate::model::body::Shape;
use crate::model::cylinder::LineContact;
use crate::model::error::{ModelError, require_positive};
use crate::model::pair::{ContactPair, PairKind};
use crate::model::pressure::YIELD_FACTOR;

/// The bodies behind an impact, as far as a law needs them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Contact {
    /// Parameters given as k, n and m alone, without a scene.
    Unspecified,
    /// Spheres, or a sphere on a plane.
    Point(PointContact),
    /// Parallel cylinders, or a cylinder on a plane.
    Line {
        line: LineContact,
        /// Limiting contact pressure p_y = 1.1·σ_y of the softer body on the strip's maximum
        /// pressure p₀, Pa (eq 12; Thornton's law on a line contact, docs/physics.md §6.6).
        yield_pressure: f64,
        /// Which bodies are cylinders, for messages ("body1 is a cylinder").
        bodies: &'static str,
    },
}

/// A point contact's limiting pressure and Hertz constants.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PointContact {
    /// Limiting contact pressure p_y = 1.1·σ_y of the softer body, Pa: the paper's yield onset,
    /// which puts the factor on the maximum pressure p₀ (docs/physics.md §2, §6.6).
    pub yield_pressure: f64,
    /// Reduced modulus E* = 1/η, Pa (eq 3).
    pub modulus: f64,
    /// Reduced radius R, m (eq 2).
    pub radius: f64,
}

impl Contact {
    /// The contact of a validated pair.
    pub fn of(pair: &ContactPair) -> Contact {
        let line = |bodies| match LineContact::of(pair) {
            Ok(line) => Contact::Line {
                line,
                yield_pressure: YIELD_FACTOR * pair.yield_stress(),
                bodies,
            },
            Err(_) => Contact::Unspecified,
        };
        match pair.kind() {
            PairKind::SphereSphere | PairKind::SpherePlane => Contact::Point(PointContact {
                yield_pressure: YIELD_FACTOR * pair.yield_stress(),
                modulus: 1.0 / pair.elastic_factor(),
                radius: pair.reduced_radius(),
            }),
            PairKind::CylinderCylinder => line("body1 and body2 are cylinders"),
            PairKind::CylinderPlane => match pair.body1().shape {
                Shape::Cylinder { .. } => line("body1 is a cylinder"),
                _ => line("body2 is a cylinder"),
            },
        }
    }

    /// A point contact's constants finite and positive (hand-built ones are checked too).
    pub fn validate(&self) -> Result<(), ModelError> {
        match self {
            Contact::Point(p) => {
                require_positive("contact.yield_pressure", p.yield_pressure)?;
                require_positive("contact.modulus", p.modulus)?;
                require_positive("contact.radius", p.radius)?;
            }
            Contact::Line { yield_pressure, .. } => {
                require_positive("contact.yield_pressure", *yield_pressure)?;
            }
            Contact::Unspecified => {}
        }
        Ok(())
    }
}
