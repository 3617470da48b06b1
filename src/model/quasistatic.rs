//! The quasistatic Hertz estimate of an impact (the paper's §2–3, Tables 1–2).

use serde::Serialize;

use super::cylinder::{self, PowerFit};
use super::error::{ModelError, require_positive};
use super::pair::ContactPair;
use super::power_law::PowerLaw;
use super::pressure::{Regime, YieldOnset};
use super::sphere;

/// Contact-area result that depends on the geometry.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(untagged)]
pub enum ContactGeometry {
    /// Sphere contact: radius of the circular contact area at F_max, m (eq 8).
    Point { contact_radius: f64 },
    /// Cylinder contact: half-width of the strip at F_max, m (eq 11), and the fitted law.
    Line { half_width: f64, fit: PowerFit },
}

/// Everything the quasistatic model says about one impact, SI units.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Quasistatic {
    /// η = η₁ + η₂, m²/N (eq 3).
    pub eta: f64,
    /// k of F = k·xⁿ used downstream, N/mⁿ (eq 2, or the fitted a for cylinders).
    pub k: f64,
    pub n: f64,
    pub reduced_mass: f64,
    pub x_max: f64,
    pub f_max: f64,
    pub t_contact: f64,
    /// Maximum pressure p₀ at F_max, Pa (eq 9 or 12).
    pub p_max: f64,
    #[serde(flatten)]
    pub onset: YieldOnset,
    #[serde(flatten)]
    pub geometry: ContactGeometry,
}

impl Quasistatic {
    /// The elastic law F = k·xⁿ this estimate uses.
    pub fn law(&self) -> PowerLaw {
        PowerLaw {
            k: self.k,
            n: self.n,
        }
    }

    pub fn regime(&self, v0: f64) -> Regime {
        self.onset.regime(v0)
    }
}

/// Evaluates the quasistatic model of `pair` hit at relative velocity `v0` (eqs 1–14).
pub fn evaluate(pair: &ContactPair, v0: f64) -> Result<Quasistatic, ModelError> {
    require_positive("impact.v0", v0)?;
    let eta = pair.elastic_factor();
    let radius = pair.reduced_radius();
    let mass = pair.reduced_mass();
    let (law, pressure, fit) = match pair.contact_length() {
        None => (
            sphere::hertz_law(pair),
            sphere::pressure_law(eta, radius),
            None,
        ),
        Some(length) => {
            let fit = cylinder::scene_fit(pair, v0)?;
            (
                PowerLaw::new(fit.a, fit.n)?,
                cylinder::pressure_law(eta, radius, length),
                Some((fit, length)),
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
        onset: YieldOnset::new(
            &law,
            &pressure,
            mass,
            pair.yield_stress(),
            pair.wave_speed(),
        ),
        geometry: match fit {
            None => ContactGeometry::Point {
                contact_radius: sphere::contact_radius(eta, radius, f_max),
            },
            Some((fit, length)) => ContactGeometry::Line {
                half_width: cylinder::half_width(eta, radius, length, f_max),
                fit,
            },
        },
    })
}
