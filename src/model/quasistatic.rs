//! The quasistatic Hertz estimate of an impact (the paper's §2–3, Tables 1–2).
#![warn(missing_docs)]

use serde::Serialize;

use super::cylinder::{self, PowerFit};
use super::error::{Domain, ModelError, require_positive};
use super::force::Contact;
use super::pair::ContactPair;
use super::power_law::PowerLaw;
use super::pressure::{PressureLaw, Regime, YieldOnset};
use super::sphere;

/// Contact-area result that depends on the geometry.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(untagged)]
pub enum ContactGeometry {
    /// Sphere contact: radius of the circular contact area at F_max, m (eq 8).
    Point {
        /// a, m.
        contact_radius: f64,
    },
    /// Cylinder contact: half-width of the strip at F_max, m (eq 11), and the fitted law.
    Line {
        /// b, m.
        half_width: f64,
        /// The power law F = a·xⁿ + c fitted to eq 13/14.
        fit: PowerFit,
    },
}

/// Everything the quasistatic model says about one impact, SI units.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Quasistatic {
    /// η = η₁ + η₂, m²/N (eq 3).
    pub eta: f64,
    /// k of F = k·xⁿ used downstream, N/mⁿ (eq 2, or the fitted a for cylinders).
    pub k: f64,
    /// n of F = k·xⁿ (3/2 for spheres, the fitted n for cylinders).
    pub n: f64,
    /// Reduced mass m, kg (eq 4).
    pub reduced_mass: f64,
    /// Maximum approach x_max at v₀, m (eq 5).
    pub x_max: f64,
    /// Peak force F_max at v₀, N (eq 6).
    pub f_max: f64,
    /// Contact time t_c at v₀, s (eq 7).
    pub t_contact: f64,
    /// Maximum pressure p₀ at F_max, Pa (eq 9 or 12).
    pub p_max: f64,
    /// The velocities at which yield begins and becomes fully plastic, and the wave limit.
    #[serde(flatten)]
    pub onset: YieldOnset,
    /// The contact area at F_max.
    #[serde(flatten)]
    pub geometry: ContactGeometry,
    /// The bodies as the laws that need more than k and n see them (force::Contact).
    #[serde(skip)]
    pub contact: Contact,
}

impl Quasistatic {
    /// The elastic law F = k·xⁿ this estimate uses.
    pub fn law(&self) -> PowerLaw {
        PowerLaw {
            k: self.k,
            n: self.n,
        }
    }

    /// The yield regime of an impact at `v0`: elastic, yield begins, or fully plastic (§2).
    pub fn regime(&self, v0: f64) -> Regime {
        self.onset.regime(v0)
    }
}

/// Evaluates the quasistatic model of `pair` hit at relative velocity `v0` (eqs 1–14).
pub fn evaluate(pair: &ContactPair, v0: f64) -> Result<Quasistatic, ModelError> {
    PairEstimate::new(pair.clone()).at(v0)
}

/// The part of the quasistatic estimate the pair alone fixes: evaluated once, it gives the estimate
/// at any v₀ ([`PairEstimate::at`]) with the same numbers as [`evaluate`], which a sweep of v₀, e
/// or x_pl reuses at every point.
#[derive(Debug, Clone, PartialEq)]
pub struct PairEstimate {
    pair: ContactPair,
    eta: f64,
    radius: f64,
    mass: f64,
    shape: PairLaw,
    contact: Contact,
}

/// What of the elastic law a pair fixes: all of it for a point contact (eqs 2, 9), only the
/// contact length for a line contact, whose power-law fit spans the forces v₀ reaches (eqs 13–14).
#[derive(Debug, Clone, Copy, PartialEq)]
enum PairLaw {
    Point {
        law: PowerLaw,
        pressure: PressureLaw,
        onset: YieldOnset,
    },
    Line {
        length: f64,
    },
}

impl PairEstimate {
    /// The part of the estimate that `pair` alone fixes.
    pub fn new(pair: ContactPair) -> Self {
        let eta = pair.elastic_factor();
        let radius = pair.reduced_radius();
        let mass = pair.reduced_mass();
        let shape = match pair.contact_length() {
            None => {
                let law = sphere::hertz_law(&pair);
                let pressure = sphere::pressure_law(eta, radius);
                PairLaw::Point {
                    law,
                    pressure,
                    onset: onset(&pair, &law, &pressure, mass),
                }
            }
            Some(length) => PairLaw::Line { length },
        };
        PairEstimate {
            contact: Contact::of(&pair),
            pair,
            eta,
            radius,
            mass,
            shape,
        }
    }

    /// The estimate of the pair hit at relative velocity `v0` (eqs 1–14).
    pub fn at(&self, v0: f64) -> Result<Quasistatic, ModelError> {
        require_positive("impact.v0", v0)?;
        let (eta, radius, mass) = (self.eta, self.radius, self.mass);
        let (law, pressure, onset, fit) = match self.shape {
            PairLaw::Point {
                law,
                pressure,
                onset,
            } => (law, pressure, onset, None),
            PairLaw::Line { length } => {
                let (law, pressure, fit) = self.line_law(v0, length)?;
                (
                    law,
                    pressure,
                    onset(&self.pair, &law, &pressure, mass),
                    Some(fit),
                )
            }
        };
        let f_max = law.max_force(mass, v0);
        Ok(Quasistatic {
            eta,
            k: law.k,
            n: law.n,
            reduced_mass: mass,
            x_max: law.max_approach(mass, v0),
            f_max,
            t_contact: law.contact_time(mass, v0),
            p_max: pressure.pressure(f_max),
            onset,
            geometry: match fit {
                None => ContactGeometry::Point {
                    contact_radius: sphere::contact_radius(eta, radius, f_max),
                },
                Some((fit, length)) => ContactGeometry::Line {
                    half_width: cylinder::half_width(eta, radius, length, f_max),
                    fit,
                },
            },
            contact: self.contact,
        })
    }

    /// The power law fitted to eq 13/14 over the forces an impact at `v0` reaches, its pressure law
    /// (eq 12), and the fit; refused where eqs 11–14 no longer hold.
    fn line_law(
        &self,
        v0: f64,
        length: f64,
    ) -> Result<(PowerLaw, PressureLaw, (PowerFit, f64)), ModelError> {
        let fit = cylinder::scene_fit(&self.pair, v0)?;
        // Eq 13/14 give 1 < n < 1.5 (the paper's §3); a fit outside that range comes from the
        // end of their domain, where x(F) flattens, and would extrapolate nonsense.
        if !(1.0..=1.5).contains(&fit.n) {
            return Err(ModelError::OutOfDomain {
                formula: "line contact (eqs 11–14)",
                detail: Domain::FitExponent {
                    f_min: fit.f_min,
                    f_max: fit.f_max,
                    n: fit.n,
                },
            });
        }
        let law = PowerLaw::new(fit.a, fit.n)?;
        let f_max = law.max_force(self.mass, v0);
        let limit = cylinder::LineContact::of(&self.pair)?.force_limit();
        if f_max >= limit {
            return Err(ModelError::OutOfDomain {
                formula: "line contact (eqs 11–14)",
                detail: Domain::PeakBeyondLimit { v0, f_max, limit },
            });
        }
        let pressure = cylinder::pressure_law(self.eta, self.radius, length);
        Ok((law, pressure, (fit, length)))
    }
}

/// The yield-onset velocities of `law` on `pair` (the paper's §2 conventions).
fn onset(pair: &ContactPair, law: &PowerLaw, pressure: &PressureLaw, mass: f64) -> YieldOnset {
    YieldOnset::new(law, pressure, mass, pair.yield_stress(), pair.wave_speed())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::body::{Body, Shape};
    use crate::model::material::tests::steel;

    fn cylinder() -> Body {
        Body {
            shape: Shape::Cylinder {
                radius: 0.02,
                length: 0.1,
            },
            material: steel(),
            mass: Some(1.0),
        }
    }

    #[test]
    fn a_line_contact_beyond_eq_13_is_refused_naming_v0() {
        let pair = ContactPair::new(cylinder(), cylinder()).unwrap();
        // Table 2's scene at 1 m/s is well inside eq 13's domain (b = 0.2 mm ≪ 2R = 40 mm) …
        assert!(evaluate(&pair, 1.0).is_ok());
        // … 1 km/s still is (b = 7.9 mm), but at 100 km/s the extrapolated law would give
        // b ≈ 0.1 m > 2R = 40 mm.
        assert!(evaluate(&pair, 1e3).is_ok());
        let msg = evaluate(&pair, 1e5).unwrap_err().to_string();
        assert!(
            msg.starts_with("line contact (eqs 11–14): impact.v0 = 100000 m/s"),
            "{msg}"
        );
    }

    #[test]
    fn sphere_results_are_finite_and_consistent() {
        let sphere = Body {
            shape: Shape::Sphere { radius: 0.01 },
            material: steel(),
            mass: None,
        };
        let plane = Body {
            shape: Shape::Plane,
            material: steel(),
            mass: None,
        };
        let q = evaluate(&ContactPair::new(sphere, plane).unwrap(), 0.3).unwrap();
        // F_max = k·x_maxⁿ (eq 6 from eq 5) and p₀ at F_max from eq 9.
        assert!((q.f_max / (q.k * q.x_max.powf(q.n)) - 1.0).abs() < 1e-14);
        assert!(matches!(q.geometry, ContactGeometry::Point { .. }));
        assert_eq!(q.regime(0.3), Regime::YieldBegins);
    }
}
