//! Adams' IMPACT contact: Hertz with a viscous damper ramped in by a cubic STEP,
//! F = k·xⁿ + c_max·STEP(x; 0, 0, d, 1)·ẋ, clamped at F ≥ 0 (MSC Adams/Solver function reference,
//! IMPACT; docs/physics.md §6.8).

use crate::model::error::ModelError;
use crate::model::exact::ExactImpact;

use super::kelvin_voigt::damping_ratio;
use super::law::{ContactEnd, ForceLaw, Phase, abs_pow_nm1, signed_pow_n};
use super::{ForceModel, ImpactParams};

/// The penetration d at which the damping reaches c_max, as a fraction of the elastic x_max: the
/// damper is fully in within the first tenth of the compression (docs/physics.md §6.8).
pub const DEPTH_FRACTION: f64 = 0.1;

/// Adams' cubic STEP from 0 at u = 0 to 1 at u = 1: u²(3 − 2u), held at 0 below and 1 beyond.
pub fn cubic_step(u: f64) -> f64 {
    let u = u.clamp(0.0, 1.0);
    u * u * (3.0 - 2.0 * u)
}

/// d/du of [`cubic_step`]: 6u(1 − u) on [0, 1], 0 outside.
fn cubic_step_slope(u: f64) -> f64 {
    if (0.0..=1.0).contains(&u) {
        6.0 * u * (1.0 - u)
    } else {
        0.0
    }
}

/// F = k·xⁿ + c_max·STEP(x/d)·ẋ, contact ending where F falls to 0 (Adams' max(0, …)).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AdamsImpact {
    params: ImpactParams,
    model: ForceModel,
    c_max: f64,
    depth: f64,
}

impl AdamsImpact {
    /// The law with maximum damping `c_max` (N·s/m) reached at penetration `depth` (m).
    pub fn new(model: ForceModel, params: &ImpactParams, c_max: f64, depth: f64) -> Self {
        AdamsImpact {
            params: *params,
            model,
            c_max,
            depth,
        }
    }

    /// The table's builder: c_max given, or from e by [`AdamsImpact::default_c_max`]; d is
    /// [`DEPTH_FRACTION`] of the elastic x_max.
    pub fn build(
        model: ForceModel,
        params: &ImpactParams,
        c_max: Option<f64>,
    ) -> Result<Self, ModelError> {
        Ok(Self::new(
            model,
            params,
            c_max.unwrap_or_else(|| Self::default_c_max(params)),
            Self::default_depth(params),
        ))
    }

    /// d = x_e/10, x_e the elastic x_max (eq 5), m.
    pub fn default_depth(params: &ImpactParams) -> f64 {
        DEPTH_FRACTION * params.law.max_approach(params.mass, params.v0)
    }

    /// c_max = 2ζ(e)·√(m·n·k·x_eⁿ⁻¹): the linear oscillator's damping ratio for e (§6.3) on the
    /// tangent stiffness at the elastic x_max. A starting rule, not a calibration: on Fig. 5 it
    /// realises 0.549 for 0.6 asked (docs/physics.md §6.8).
    pub fn default_c_max(params: &ImpactParams) -> f64 {
        let x_e = params.law.max_approach(params.mass, params.v0);
        let tangent = params.law.tangent_stiffness(x_e);
        2.0 * damping_ratio(params.restitution) * (params.mass * tangent).sqrt()
    }

    /// The maximum damping c_max, N·s/m.
    pub fn c_max(&self) -> f64 {
        self.c_max
    }

    /// The penetration d at which the damping reaches c_max, m.
    pub fn depth(&self) -> f64 {
        self.depth
    }

    fn ramp(&self, x: f64) -> f64 {
        cubic_step(x / self.depth)
    }
}

impl ForceLaw for AdamsImpact {
    fn model(&self) -> ForceModel {
        self.model
    }

    fn params(&self) -> &ImpactParams {
        &self.params
    }

    /// F = k·xⁿ + c_max·STEP(x/d)·ẋ (Adams IMPACT).
    fn phase_force(&self, x: f64, v: f64, _phase: Phase) -> f64 {
        let law = self.params.law;
        law.k * signed_pow_n(x, law.n) + self.c_max * self.ramp(x) * v
    }

    fn dissipative_force(&self, x: f64, v: f64, _phase: Phase) -> f64 {
        self.c_max * self.ramp(x) * v
    }

    fn partials(&self, x: f64, v: f64, _phase: Phase) -> (f64, f64) {
        let (k, n) = (self.params.law.k, self.params.law.n);
        (
            n * k * abs_pow_nm1(x, n)
                + self.c_max * cubic_step_slope(x / self.depth) / self.depth * v,
            self.c_max * self.ramp(x),
        )
    }

    fn contact_end(&self) -> ContactEnd {
        if self.c_max == 0.0 {
            ContactEnd::ApproachZero
        } else {
            ContactEnd::ForceZero
        }
    }

    fn may_turn_tensile(&self) -> bool {
        self.c_max > 0.0
    }

    /// F/xⁿ = k + c_max·STEP(x/d)·ẋ/xⁿ, regular as x → 0 (STEP ~ 3x²/d² there, n < 2).
    fn tension(&self, x: f64, v: f64) -> f64 {
        let (k, n) = (self.params.law.k, self.params.law.n);
        if x <= 0.0 {
            return k;
        }
        k + self.c_max * self.ramp(x) * v / x.powf(n)
    }

    fn damping_value(&self) -> Option<f64> {
        Some(self.c_max)
    }

    /// The STEP's second derivative jumps at x = d: adaptive methods restart there.
    fn loading_breakpoint(&self) -> Option<f64> {
        (self.depth > 0.0).then_some(self.depth)
    }

    /// No closed form: the adaptive solver integrates it.
    fn exact(&self, _rtol: f64) -> Option<ExactImpact> {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::force::AnyLaw;
    use crate::model::impact::{MethodChoice, SolveOptions, solve_impact, solve_law};
    use crate::model::ode::Method;
    use crate::model::scene::tests::fig5_params;

    const ROW: ForceModel = ForceModel::with_id("adams-impact");

    #[test]
    fn the_step_and_the_force_as_adams_defines_them() {
        // STEP(x; 0, 0, d, 1) = u²(3 − 2u): 0, 1/2 and 1 at u = 0, 1/2, 1, held beyond.
        assert_eq!(cubic_step(0.0), 0.0);
        assert_eq!(cubic_step(0.5), 0.5);
        assert_eq!(cubic_step(1.0), 1.0);
        assert_eq!((cubic_step(-1.0), cubic_step(3.0)), (0.0, 1.0));
        let p = fig5_params(0.3);
        let law = AdamsImpact::new(ROW, &p, 7.0, 2e-6);
        let (x, v) = (1e-6, 0.2);
        let f = law.phase_force(x, v, Phase::Loading);
        assert!((f - (p.law.k * x.powf(1.5) + 7.0 * 0.5 * v)).abs() < 1e-9 * f);
        assert!(
            (law.tension(x, -v) - law.phase_force(x, -v, Phase::Unloading) / x.powf(1.5)).abs()
                < 1e-6 * p.law.k
        );
        // ∂F/∂x against a central difference, inside the ramp.
        let h = 1e-12;
        let fd = (law.phase_force(x + h, v, Phase::Loading)
            - law.phase_force(x - h, v, Phase::Loading))
            / (2.0 * h);
        assert!((law.partials(x, v, Phase::Loading).0 / fd - 1.0).abs() < 1e-5);
    }

    #[test]
    fn without_damping_it_is_hertz_and_damped_it_ends_at_f_zero() {
        let p = fig5_params(0.3);
        let tight = SolveOptions {
            method: MethodChoice::Integrator(Method::Dop853),
            rtol: 1e-12,
            ..SolveOptions::default()
        };
        let elastic = solve_law(&ROW.law_with_damping(&p, 0.0).unwrap(), &tight)
            .unwrap()
            .summary;
        let hertz = solve_impact(ForceModel::Quasistatic, &p, &tight)
            .unwrap()
            .summary;
        assert!((elastic.e_out - 1.0).abs() < 1e-10, "{}", elastic.e_out);
        assert!((elastic.f_max / hertz.f_max - 1.0).abs() < 1e-10);
        assert!((elastic.t_contact / hertz.t_contact - 1.0).abs() < 1e-10);
        // The row's own c_max for e = 0.6 damps, ends where F = 0 with x > 0, and realises 0.549:
        // the tangent stiffness at x_max is the stiffest the impact meets, so its critical damping
        // overshoots, more than the STEP and the clamp give back.
        let damped = solve_impact(ROW, &p, &tight).unwrap().summary;
        assert!((damped.e_out - 0.549).abs() < 1e-3, "{}", damped.e_out);
        assert!(damped.x_residual > 0.0);
        let law = ROW.law(&p).unwrap();
        let AnyLaw::AdamsImpact(adams) = law else {
            panic!("{law:?}")
        };
        assert_eq!(adams.depth(), 0.1 * p.law.max_approach(p.mass, p.v0));
    }
}
