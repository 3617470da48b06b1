//! Results that are computed correctly but should not be trusted as physics or as numbers: the
//! scene has left a hypothesis of the theory, or a reported quantity is ill-conditioned. The
//! numbers stay; the warning says why they mean less than they seem to.

use serde::Serialize;
use thiserror::Error;

use super::cylinder::{LineContact, line_contact_impact};
use super::force::{ForceModel, ImpactParams};
use super::impact::ImpactSummary;
use super::pair::ContactPair;
use super::quasistatic::{ContactGeometry, Quasistatic};

/// Hertz's first hypothesis, a ≪ R, is taken as broken beyond a/R = 0.1 (then x/R = a²/R² > 1 %),
/// the usual limit of the small-strain theory (docs/physics.md §1).
pub const MAX_CONTACT_RATIO: f64 = 0.1;

/// The impact of the fitted line-contact law (what the integrators use for cylinders) is flagged
/// where its x_max, F_max or t_c departs from the exact eq 13/14 law's by more than this.
pub const MAX_FIT_DEPARTURE: f64 = 0.01;

/// The proposed model's end time and exit speed are flagged beyond this condition number (their
/// relative error over the integrator's relative error).
pub const MAX_END_CONDITION: f64 = 10.0;

/// Why a result should be read with care.
#[derive(Debug, Clone, PartialEq, Serialize, Error)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum ModelWarning {
    /// The contact is not small against the sphere (Hertz's first hypothesis).
    #[error(
        "contact radius a = {contact_radius:.3e} m is {ratio:.2} of the sphere radius {radius:.3e} m \
         (x_max = {x_max:.3e} m): Hertz's theory assumes a ≪ R (a/R ≤ 0.1), so these numbers are \
         outside its range"
    )]
    LargeContact {
        contact_radius: f64,
        radius: f64,
        x_max: f64,
        ratio: f64,
    },
    /// The cylinders' fitted law a·xⁿ gives an elastic impact that departs from the exact eq 13/14
    /// law's ([`crate::model::cylinder::line_contact_impact`]).
    #[error(
        "the fitted law a·xⁿ's impact departs from the exact eq 13/14 law's by {departure:.2} % \
         (x_max {x_max:+.2} %, F_max {f_max:+.2} %, t_c {t_contact:+.2} %)"
    )]
    FitDeparts {
        departure: f64,
        x_max: f64,
        f_max: f64,
        t_contact: f64,
    },
    /// The proposed model's contact ends where F = k·xⁿ + b·xⁿ⁻¹·ẋ grazes zero: the bodies creep
    /// apart along F ≈ 0 and the end time depends on digits the integration does not have.
    #[error(
        "{model}: the end of contact is ill-conditioned (condition number {condition:.2e}: e_out = \
         {e_out:.3}, x_pl/x_e = {x_pl_ratio:.3e}); t_contact and v_out may be off by that multiple \
         of the tolerance"
    )]
    IllConditionedEnd {
        model: ForceModel,
        condition: f64,
        e_out: f64,
        x_pl_ratio: f64,
    },
}

/// Warnings about the scene itself: a sphere whose contact radius at the elastic F_max (eq 8) is
/// not small against the smallest sphere radius of the pair; cylinders whose fitted law's impact
/// departs from the exact line-contact law's by more than [`MAX_FIT_DEPARTURE`].
pub fn scene_warnings(pair: &ContactPair, q: &Quasistatic) -> Vec<ModelWarning> {
    let ContactGeometry::Point { contact_radius } = q.geometry else {
        return fit_warning(pair, q).into_iter().collect();
    };
    let radius = pair.body1().shape.radius().min(pair.body2().shape.radius());
    let ratio = contact_radius / radius;
    if ratio.is_finite() && ratio > MAX_CONTACT_RATIO {
        vec![ModelWarning::LargeContact {
            contact_radius,
            radius,
            x_max: q.x_max,
            ratio,
        }]
    } else {
        Vec::new()
    }
}

/// The [`ModelWarning::FitDeparts`] of a line contact, if its departure exceeds the limit.
fn fit_warning(pair: &ContactPair, q: &Quasistatic) -> Option<ModelWarning> {
    let line = LineContact::of(pair).ok()?;
    // v₀ from the estimate's own energy balance, ½m·v₀² = k·x_max^{n+1}/(n+1) (eq 5 inverted).
    let stored = q.k * q.x_max.powf(q.n + 1.0) / (q.n + 1.0);
    let v0 = (2.0 * stored / q.reduced_mass).sqrt();
    let exact = line_contact_impact(&line, &q.law(), q.reduced_mass, v0).ok()?;
    let departure = exact.fit_error();
    (departure > MAX_FIT_DEPARTURE).then_some(ModelWarning::FitDeparts {
        departure: 100.0 * departure,
        x_max: 100.0 * exact.fit_error_x_max,
        f_max: 100.0 * exact.fit_error_f_max,
        t_contact: 100.0 * exact.fit_error_t_contact,
    })
}

/// Warnings about one solved impact.
///
/// The proposed model ends at g = k·x + b·ẋ = 0 (F/xⁿ⁻¹), which g crosses at the rate
/// k·ẋ (F = 0 there, so ẍ = 0). An error δg ≈ rtol·(k·x_e + b·v₀) in g moves the end by
/// δg/(k·v_out); relative to t_c that is rtol·(x_e + x_pl/e)/(v_out·t_c), whose factor is the
/// condition number reported.
pub fn impact_warnings(params: &ImpactParams, summary: &ImpactSummary) -> Vec<ModelWarning> {
    end_warning(params, summary.model, summary.v_out, summary.t_contact)
        .into_iter()
        .collect()
}

/// The ill-conditioned-end warning of [`impact_warnings`] from the three numbers it needs (exit
/// speed m/s, contact time s), for callers that keep only those.
pub fn end_warning(
    params: &ImpactParams,
    model: ForceModel,
    v_out: f64,
    t_contact: f64,
) -> Option<ModelWarning> {
    if model != ForceModel::Proposed || params.plastic_indentation <= 0.0 {
        return None;
    }
    let x_e = params.law.max_approach(params.mass, params.v0);
    let reach = x_e + params.plastic_indentation / params.restitution;
    let condition = reach / (v_out * t_contact);
    (condition.is_nan() || condition > MAX_END_CONDITION).then_some(
        ModelWarning::IllConditionedEnd {
            model,
            condition,
            e_out: v_out / params.v0,
            x_pl_ratio: params.plastic_indentation / x_e,
        },
    )
}
