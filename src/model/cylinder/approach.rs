//! Approach of a line contact as a function of force: eq 13 (two cylinders) and eq 14 (cylinder on
//! a plane), with the force range where each formula holds and is invertible.

use std::f64::consts::PI;

use super::super::body::Shape;
use super::super::error::{Domain, ModelError, require_positive};
use super::super::pair::{ContactPair, PairKind};
use super::root;

/// The constant 0.407 of eq 13.
const EQ_13_CONSTANT: f64 = 0.407;

/// d/dF of F·(ln(2R/b) + 0.407) is ln(2R/b) + 0.407 − ½ because b ∝ √F (eq 11); eq 13 therefore
/// stops increasing where the η-weighted ln(2Rᵢ/b) falls to ½ − 0.407.
const EQ_13_SLOPE_OFFSET: f64 = 0.5 - EQ_13_CONSTANT;

/// What eqs 13–14 need to know about a pair: elastic factors, radii and the contact length L.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LineContact {
    /// Two parallel cylinders (eq 13): each body keeps its own ηᵢ (m²/N) and Rᵢ (m).
    TwoCylinders {
        eta1: f64,
        radius1: f64,
        eta2: f64,
        radius2: f64,
        length: f64,
    },
    /// A cylinder of radius R on a plane (eq 14 with the hole radius R₁ → ∞); η = η₁ + η₂.
    OnPlane { eta: f64, radius: f64, length: f64 },
}

impl LineContact {
    /// The line contact of `pair`; a point contact (spheres) is refused by name.
    pub fn of(pair: &ContactPair) -> Result<Self, ModelError> {
        let (eta1, eta2) = pair.elastic_factors();
        let length = pair.contact_length();
        match (pair.kind(), length) {
            (PairKind::CylinderCylinder, Some(length)) => Ok(LineContact::TwoCylinders {
                eta1,
                radius1: pair.body1().shape.radius(),
                eta2,
                radius2: pair.body2().shape.radius(),
                length,
            }),
            (PairKind::CylinderPlane, Some(length)) => Ok(LineContact::OnPlane {
                eta: eta1 + eta2,
                radius: cylinder_radius(pair),
                length,
            }),
            _ => Err(ModelError::OutOfDomain {
                formula: "eqs 13–14 (line contact)",
                detail: Domain::PointContact([
                    pair.body1().shape.name(),
                    pair.body2().shape.name(),
                ]),
            }),
        }
    }

    /// Contact length L, m.
    pub fn length(&self) -> f64 {
        match *self {
            LineContact::TwoCylinders { length, .. } | LineContact::OnPlane { length, .. } => {
                length
            }
        }
    }

    /// Elastic factor η = η₁ + η₂, m²/N (eq 3).
    pub fn eta(&self) -> f64 {
        match *self {
            LineContact::TwoCylinders { eta1, eta2, .. } => eta1 + eta2,
            LineContact::OnPlane { eta, .. } => eta,
        }
    }

    /// Radius R of eqs 11–12, m: R₁R₂/(R₁ + R₂) for two cylinders, the cylinder's for a plane.
    pub fn reduced_radius(&self) -> f64 {
        match *self {
            LineContact::TwoCylinders {
                radius1, radius2, ..
            } => radius1 * radius2 / (radius1 + radius2),
            LineContact::OnPlane { radius, .. } => radius,
        }
    }

    /// Upper end of the force domain, N; eqs 13–14 hold and increase strictly for 0 < F < this.
    ///
    /// Eq 13: both logarithms must stay positive, b < 2R₁ and b < 2R₂, and x must still increase,
    /// Σηᵢ·(ln(2Rᵢ/b) − 0.093) > 0, i.e. b < exp(Σηᵢ·ln(2Rᵢ)/η − 0.093); the force is where b
    /// (eq 11) reaches the smallest of the three. Eq 14: dx/dF = (η/L)·ln(L³/(F·R·η)) > 0, i.e.
    /// F < L³/(R·η).
    pub fn force_limit(&self) -> f64 {
        match *self {
            LineContact::TwoCylinders {
                eta1,
                radius1,
                eta2,
                radius2,
                ..
            } => {
                let eta = eta1 + eta2;
                let monotone = ((eta1 * (2.0 * radius1).ln() + eta2 * (2.0 * radius2).ln()) / eta
                    - EQ_13_SLOPE_OFFSET)
                    .exp();
                let b_max = (2.0 * radius1).min(2.0 * radius2).min(monotone);
                self.force_at_half_width(b_max)
            }
            LineContact::OnPlane {
                eta,
                radius,
                length,
            } => length.powi(3) / (radius * eta),
        }
    }

    /// Eq 11 solved for F: F = π·b²·L/(4·η·R), N.
    fn force_at_half_width(&self, b: f64) -> f64 {
        PI * b * b * self.length() / (4.0 * self.eta() * self.reduced_radius())
    }

    /// Approach x(F), m, without domain checks: eq 13 or eq 14.
    pub(super) fn approach_unchecked(&self, f: f64) -> f64 {
        match *self {
            LineContact::TwoCylinders {
                eta1,
                radius1,
                eta2,
                radius2,
                length,
            } => {
                let ln_b = self.half_width(f).ln();
                // Eq 13: x = (2/π)(F/L)[η₁(ln(2R₁/b) + 0.407) + η₂(ln(2R₂/b) + 0.407)].
                2.0 / PI * f / length
                    * (eta1 * ((2.0 * radius1).ln() - ln_b + EQ_13_CONSTANT)
                        + eta2 * ((2.0 * radius2).ln() - ln_b + EQ_13_CONSTANT))
            }
            LineContact::OnPlane {
                eta,
                radius,
                length,
            } => {
                // Eq 14 with (R₁ − R₂)/(R₁R₂) → 1/R: x = (F/L)·η·[ln(L³/(F·R·η)) + 1].
                f / length * eta * ((length.powi(3) / (f * radius * eta)).ln() + 1.0)
            }
        }
    }

    /// Slope dx/dF, m/N, without domain checks: eq 13 or 14 differentiated.
    pub(super) fn slope_unchecked(&self, f: f64) -> f64 {
        match *self {
            LineContact::TwoCylinders {
                eta1,
                radius1,
                eta2,
                radius2,
                length,
            } => {
                let ln_b = self.half_width(f).ln();
                // d/dF of eq 13, with d(ln b)/dF = 1/(2F) from eq 11.
                2.0 / PI / length
                    * (eta1 * ((2.0 * radius1).ln() - ln_b - EQ_13_SLOPE_OFFSET)
                        + eta2 * ((2.0 * radius2).ln() - ln_b - EQ_13_SLOPE_OFFSET))
            }
            LineContact::OnPlane {
                eta,
                radius,
                length,
            } => {
                // d/dF of eq 14: (η/L)·ln(L³/(F·R·η)).
                eta / length * (length.powi(3) / (f * radius * eta)).ln()
            }
        }
    }

    /// Half-width b = √((4/π)·η·(F/L)·R), m (eq 11).
    pub fn half_width(&self, f: f64) -> f64 {
        super::half_width(self.eta(), self.reduced_radius(), self.length(), f)
    }

    /// Approach x(F), m: eq 13 or 14, for 0 < F < [`force_limit`](Self::force_limit) (and F not
    /// so small that x underflows).
    pub fn approach(&self, f: f64) -> Result<f64, ModelError> {
        require_positive("contact force F", f)?;
        let limit = self.force_limit();
        if f >= limit {
            return Err(self.force_out_of_domain(f, limit));
        }
        let x = self.approach_unchecked(f);
        if x > 0.0 && x.is_finite() {
            Ok(x)
        } else {
            Err(ModelError::OutOfDomain {
                formula: self.formula(),
                detail: Domain::ForceTooSmall {
                    force: f,
                    approach: x,
                },
            })
        }
    }

    /// Force F(x), N: eq 13 or 14 inverted by a bracketed Newton solve, for
    /// 0 < x < x(`force_limit`).
    pub fn force_at(&self, x: f64) -> Result<f64, ModelError> {
        require_positive("approach x", x)?;
        let f_limit = self.force_limit();
        let x_limit = self.approach_unchecked(f_limit);
        if x >= x_limit {
            return Err(ModelError::OutOfDomain {
                formula: self.formula(),
                detail: Domain::ApproachBeyondLimit {
                    approach: x,
                    x_limit,
                    f_limit,
                },
            });
        }
        // x(F)/F decreases (x is concave), so the secant through the domain's end starts at or
        // right of the root; Newton then stays on the left and climbs monotonically.
        let guess = f_limit * (x / x_limit);
        root::solve_increasing(
            |f| (self.approach_unchecked(f), self.slope_unchecked(f)),
            x,
            0.0,
            f_limit,
            guess,
        )
        .filter(|f| *f > 0.0)
        .ok_or_else(|| ModelError::OutOfDomain {
            formula: self.formula(),
            detail: Domain::NoForceAt { approach: x },
        })
    }

    /// The equation this contact uses, for messages.
    pub(super) fn formula(&self) -> &'static str {
        match self {
            LineContact::TwoCylinders { .. } => "eq 13 (two cylinders)",
            LineContact::OnPlane { .. } => "eq 14 (cylinder on a plane)",
        }
    }

    /// The error for a force at or beyond the domain limit, saying what bounds it.
    pub(super) fn force_out_of_domain(&self, f: f64, limit: f64) -> ModelError {
        let bound = match self {
            LineContact::TwoCylinders { .. } => {
                "where the half-width b of eq 11 reaches the smaller cylinder diameter 2R or \
                 x(F) stops increasing"
            }
            LineContact::OnPlane { .. } => "F = L³/(R·η), where x(F) stops increasing",
        };
        ModelError::OutOfDomain {
            formula: self.formula(),
            detail: Domain::ForceBeyondLimit {
                force: f,
                limit,
                bound,
            },
        }
    }
}

/// Radius of the cylinder of a cylinder–plane pair, m.
fn cylinder_radius(pair: &ContactPair) -> f64 {
    match (pair.body1().shape, pair.body2().shape) {
        (Shape::Cylinder { radius, .. }, _) | (_, Shape::Cylinder { radius, .. }) => radius,
        // `LineContact::of` only calls this for a cylinder–plane pair; the plane's radius is ∞.
        _ => pair.reduced_radius(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::body::Body;
    use crate::model::material::Material;
    use crate::model::material::tests::{aluminium, steel};

    const ETA_STEEL: f64 = 9.1e-12;

    fn cylinder(radius: f64, length: f64, material: Material) -> Body {
        Body {
            shape: Shape::Cylinder { radius, length },
            material,
            mass: Some(1.0),
        }
    }

    fn plane(material: Material) -> Body {
        Body {
            shape: Shape::Plane,
            material,
            mass: None,
        }
    }

    fn rel(a: f64, b: f64) -> f64 {
        (a / b - 1.0).abs()
    }

    #[test]
    fn eq_13_equal_radii_and_materials_in_closed_form() {
        // R₁ = R₂ = R, η₁ = η₂ = η/2: x = (2/π)(F/L)·η·(ln(2R/b) + 0.407), b from eq 11 with R/2.
        let pair =
            ContactPair::new(cylinder(0.02, 0.1, steel()), cylinder(0.02, 0.1, steel())).unwrap();
        let contact = LineContact::of(&pair).unwrap();
        let f = 4.004e4;
        let b = (4.0 / PI * ETA_STEEL * f / 0.1 * 0.01).sqrt();
        let exact = 2.0 / PI * f / 0.1 * ETA_STEEL * ((0.04 / b).ln() + 0.407);
        let x = contact.approach(f).unwrap();
        assert!(rel(x, exact) < 1e-12, "{x} vs {exact}");
        // Table 2 lists x_max = 1.306e-5 m at F_max = 4.004e4 N for v₀ = 1 m/s.
        assert!(rel(x, 1.306e-5) < 5e-4, "{x}");
    }

    #[test]
    fn eq_13_is_symmetric_in_the_two_bodies() {
        let a = cylinder(0.02, 0.1, steel());
        let b = cylinder(0.005, 0.3, aluminium());
        let forward = LineContact::of(&ContactPair::new(a.clone(), b.clone()).unwrap()).unwrap();
        let backward = LineContact::of(&ContactPair::new(b, a).unwrap()).unwrap();
        for f in [1.0, 1e3, 1e5] {
            let (x1, x2) = (forward.approach(f).unwrap(), backward.approach(f).unwrap());
            assert!(rel(x1, x2) < 1e-14, "{x1} vs {x2}");
        }
        assert!(rel(forward.force_limit(), backward.force_limit()) < 1e-14);
        assert_eq!(forward.length(), 0.1);
    }

    #[test]
    fn eq_13_unequal_bodies_weight_each_log_by_its_own_eta() {
        // Hand-evaluated eq 13 with per-body factors, not the mean η.
        let (e1, r1, e2, r2, l, f) = (3e-12, 0.01, 8e-12, 0.05, 0.2, 2.5e3);
        let contact = LineContact::TwoCylinders {
            eta1: e1,
            radius1: r1,
            eta2: e2,
            radius2: r2,
            length: l,
        };
        let r = r1 * r2 / (r1 + r2);
        let b = (4.0 / PI * (e1 + e2) * f / l * r).sqrt();
        let exact = 2.0 / PI * f / l
            * (e1 * ((2.0 * r1 / b).ln() + 0.407) + e2 * ((2.0 * r2 / b).ln() + 0.407));
        assert!(rel(contact.approach(f).unwrap(), exact) < 1e-13);
    }

    #[test]
    fn eq_14_in_closed_form() {
        let pair = ContactPair::new(cylinder(0.02, 0.1, steel()), plane(steel())).unwrap();
        let contact = LineContact::of(&pair).unwrap();
        let f = 2.95e4;
        let exact = f / 0.1 * ETA_STEEL * ((1e-3 / (f * 0.02 * ETA_STEEL)).ln() + 1.0);
        let x = contact.approach(f).unwrap();
        assert!(rel(x, exact) < 1e-13, "{x} vs {exact}");
        // The plane may come first: same contact.
        let swapped = ContactPair::new(plane(steel()), cylinder(0.02, 0.1, steel())).unwrap();
        assert_eq!(LineContact::of(&swapped).unwrap(), contact);
    }

    #[test]
    fn slopes_match_central_differences_and_are_positive() {
        let contacts = [
            LineContact::TwoCylinders {
                eta1: 4.55e-12,
                radius1: 0.02,
                eta2: 1.2e-11,
                radius2: 0.004,
                length: 0.1,
            },
            LineContact::OnPlane {
                eta: ETA_STEEL,
                radius: 0.02,
                length: 0.1,
            },
        ];
        for contact in contacts {
            let limit = contact.force_limit();
            for frac in [1e-9, 1e-5, 1e-2, 0.5, 0.9] {
                let f = frac * limit;
                let h = f * 1e-6;
                let numeric = (contact.approach_unchecked(f + h)
                    - contact.approach_unchecked(f - h))
                    / (2.0 * h);
                let slope = contact.slope_unchecked(f);
                assert!(slope > 0.0, "{contact:?} at {f}");
                assert!(rel(slope, numeric) < 1e-6, "{slope} vs {numeric}");
            }
        }
    }

    #[test]
    fn slope_vanishes_at_the_force_limit() {
        // Equal radii: the monotone limit b = 2R·e^{−0.093} binds before b = 2R.
        let equal = LineContact::TwoCylinders {
            eta1: 4.55e-12,
            radius1: 0.02,
            eta2: 4.55e-12,
            radius2: 0.02,
            length: 0.1,
        };
        let limit = equal.force_limit();
        assert!(equal.slope_unchecked(limit).abs() < 1e-12 * equal.slope_unchecked(1.0));
        assert!(rel(equal.half_width(limit), 0.04 * (-0.093f64).exp()) < 1e-12);
        // Eq 14: F = L³/(R·η).
        let on_plane = LineContact::OnPlane {
            eta: ETA_STEEL,
            radius: 0.02,
            length: 0.1,
        };
        assert!(rel(on_plane.force_limit(), 1e-3 / (0.02 * ETA_STEEL)) < 1e-14);
        assert_eq!(on_plane.slope_unchecked(on_plane.force_limit()), 0.0);
    }

    #[test]
    fn very_unequal_radii_are_bounded_by_the_smaller_diameter() {
        // A thin stiff wire on a fat soft roller: the log of the wire turns negative (b > 2R₁)
        // while the weighted slope is still positive, so b < 2R₁ is what binds.
        let contact = LineContact::TwoCylinders {
            eta1: 1e-13,
            radius1: 0.001,
            eta2: 1e-10,
            radius2: 1.0,
            length: 0.1,
        };
        assert!(rel(contact.half_width(contact.force_limit()), 0.002) < 1e-12);
        assert!(contact.slope_unchecked(contact.force_limit()) > 0.0);
    }

    #[test]
    fn forces_outside_the_domain_are_refused_with_the_formula_named() {
        let on_plane = LineContact::OnPlane {
            eta: ETA_STEEL,
            radius: 0.02,
            length: 0.1,
        };
        let msg = on_plane.approach(1e10).unwrap_err().to_string();
        assert!(
            msg.starts_with("eq 14 (cylinder on a plane): force F = 1e10 N"),
            "{msg}"
        );
        assert!(msg.contains("L³/(R·η)"), "{msg}");
        let two = LineContact::TwoCylinders {
            eta1: 4.55e-12,
            radius1: 0.02,
            eta2: 4.55e-12,
            radius2: 0.02,
            length: 0.1,
        };
        let msg = two.approach(two.force_limit()).unwrap_err().to_string();
        assert!(msg.starts_with("eq 13 (two cylinders)"), "{msg}");
        for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            let msg = two.approach(bad).unwrap_err().to_string();
            assert!(msg.starts_with("contact force F must be"), "{msg}");
        }
        let msg = two.approach(1e-320).unwrap_err().to_string();
        assert!(msg.contains("too small"), "{msg}");
    }

    #[test]
    fn force_at_inverts_approach_to_machine_precision() {
        let contacts = [
            LineContact::TwoCylinders {
                eta1: 4.55e-12,
                radius1: 0.02,
                eta2: 1.3e-11,
                radius2: 0.007,
                length: 0.05,
            },
            LineContact::OnPlane {
                eta: ETA_STEEL,
                radius: 0.02,
                length: 0.1,
            },
        ];
        for contact in contacts {
            let limit = contact.force_limit();
            for frac in [1e-14, 1e-8, 1e-4, 0.1, 0.5, 0.99, 0.999_999] {
                let f = frac * limit;
                let x = contact.approach(f).unwrap();
                let back = contact.force_at(x).unwrap();
                // Rounding of x is amplified by the relative condition number x/(F·dx/dF),
                // which grows without bound towards the domain limit.
                let condition = x / (f * contact.slope_unchecked(f));
                assert!(
                    rel(back, f) < 1e-14 * condition.max(10.0),
                    "{contact:?}: {back} vs {f}, condition {condition}"
                );
                // and x(F(x)) = x
                assert!(rel(contact.approach(back).unwrap(), x) < 1e-14);
            }
        }
    }

    #[test]
    fn approaches_outside_the_domain_are_refused() {
        let on_plane = LineContact::OnPlane {
            eta: ETA_STEEL,
            radius: 0.02,
            length: 0.1,
        };
        // The largest approach of eq 14 is x(L³/(Rη)) = L²/R = 0.5 m.
        let msg = on_plane.force_at(0.500_001).unwrap_err().to_string();
        assert!(
            msg.starts_with("eq 14 (cylinder on a plane): approach x = 5.00001e-1 m"),
            "{msg}"
        );
        assert!(on_plane.force_at(0.499).is_ok());
        for bad in [0.0, -1e-6, f64::NAN, f64::NEG_INFINITY] {
            let msg = on_plane.force_at(bad).unwrap_err().to_string();
            assert!(msg.starts_with("approach x must be"), "{msg}");
        }
    }

    #[test]
    fn point_contacts_are_refused() {
        let sphere = Body {
            shape: Shape::Sphere { radius: 0.01 },
            material: steel(),
            mass: Some(1.0),
        };
        let pair = ContactPair::new(sphere, plane(steel())).unwrap();
        let msg = LineContact::of(&pair).unwrap_err().to_string();
        assert!(msg.contains("sphere–plane is a point contact"), "{msg}");
    }
}
