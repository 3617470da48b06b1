//! The exact elastic line-contact law: eq 13/14 inverted for F at each approach x, beside the
//! paper's fit k·xⁿ that the other laws integrate on cylinders (docs/physics.md §6.7). On spheres
//! Hertz's F = k·x^{3/2} (eq 1) is itself exact, and the law is elastic Hertz.

use lambert_w::lambert_wm1;

use crate::model::cylinder::LineContact;
use crate::model::error::{Domain, ModelError};
use crate::model::exact::{ExactImpact, elastic::elastic};

use super::law::{ContactEnd, ForceLaw, Phase, abs_pow_nm1, signed_pow_n};
use super::{Contact, ForceModel, ImpactParams};

/// The elastic law of the contact: eqs 13–14 for cylinders, eq 1 for spheres.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HertzLineExact {
    params: ImpactParams,
    model: ForceModel,
    /// The line contact's x(F) = F·(A − B·ln F); `None` on a point contact (Hertz, eq 1).
    line: Option<LogLinear>,
}

/// x(F) = F·(A − B·ln F), the form eq 13 and eq 14 both take (b ∝ √F in eq 13 makes ln b affine
/// in ln F), with F in N and x in m.
#[derive(Debug, Clone, Copy, PartialEq)]
struct LogLinear {
    /// A, m/N: x/F at F = 1 N.
    a: f64,
    /// B, m/N: −d(x/F)/d(ln F), (η/L) for eq 14 and η/(πL) for eq 13.
    b: f64,
    /// e^{−A/B}/B, 1/m: x·this is the argument −z of W₋₁.
    z_per_x: f64,
}

impl LogLinear {
    /// A and B read off the contact's own x(F) at two forces: exact, since x/F is affine in ln F.
    fn of(line: &LineContact) -> Result<Self, ModelError> {
        let limit = line.force_limit();
        let (f1, f2) = (1e-6 * limit, 1e-2 * limit);
        let (q1, q2) = (line.approach(f1)? / f1, line.approach(f2)? / f2);
        let b = (q1 - q2) / (f2 / f1).ln();
        let a = q1 + b * f1.ln();
        Ok(LogLinear {
            a,
            b,
            z_per_x: (-a / b).exp() / b,
        })
    }

    /// x(F), m, for F > 0.
    fn approach(&self, f: f64) -> f64 {
        f * (self.a - self.b * f.ln())
    }

    /// dx/dF = A − B·ln F − B, m/N.
    fn slope(&self, f: f64) -> f64 {
        self.a - self.b * f.ln() - self.b
    }

    /// F(x) for x > 0: x = F·(A − B·ln F) is (−s·ln s) = x·e^{−A/B}/B with F = e^{A/B}·s, so
    /// F = x/(B·(−W₋₁(−z))), z = x·e^{−A/B}/B, on the branch where x grows with F (s < 1/e); one
    /// Newton step on x(F) polishes W₋₁'s last bits. Past the branch point (x beyond the largest
    /// approach the formula gives) z is clamped and F = x/B is no law: `build` refuses every
    /// impact whose energy could reach it.
    fn force(&self, x: f64) -> f64 {
        let z = (x * self.z_per_x).min(std::f64::consts::E.recip());
        let f = x / (self.b * -lambert_wm1(-z));
        let slope = self.slope(f);
        if slope > 0.0 {
            f - (self.approach(f) - x) / slope
        } else {
            f
        }
    }

    /// The stored energy E(F) = ∫₀^F f·x′(f) df = F·x(F)/2 − B·F²/4, J (eq 13/14 integrated by parts).
    fn energy(&self, f: f64) -> f64 {
        if f > 0.0 {
            0.5 * f * self.approach(f) - 0.25 * self.b * f * f
        } else {
            0.0
        }
    }
}

impl HertzLineExact {
    /// The table's builder: eqs 13–14 inverted for a line contact, eq 1 for a point contact;
    /// parameters without a scene are refused (the fit's k, n cannot give the formulas back), and
    /// an impact whose energy exceeds what eq 13/14 store over their domain is refused too.
    pub fn build(
        model: ForceModel,
        params: &ImpactParams,
        _damping: Option<f64>,
    ) -> Result<Self, ModelError> {
        let line = match params.contact {
            Contact::Point(_) => None,
            Contact::Line { line, .. } => {
                let log_linear = LogLinear::of(&line)?;
                let limit = line.force_limit();
                let energy = 0.5 * params.mass * params.v0 * params.v0;
                if log_linear.energy(limit) <= energy {
                    return Err(ModelError::LineContactEnergy {
                        energy,
                        stored: log_linear.energy(limit),
                        force_limit: limit,
                    });
                }
                Some(log_linear)
            }
            Contact::Unspecified => {
                return Err(ModelError::OutOfDomain {
                    formula: "exact contact law (eqs 1, 13–14)",
                    detail: Domain::ExactNeedsBodies,
                });
            }
        };
        Ok(HertzLineExact {
            params: *params,
            model,
            line,
        })
    }

    /// F at approach x ≥ 0, N.
    fn force_at(&self, x: f64) -> f64 {
        match self.line {
            Some(line) if x > 0.0 => line.force(x),
            Some(_) => 0.0,
            None => self.params.law.k * signed_pow_n(x, self.params.law.n),
        }
    }
}

impl ForceLaw for HertzLineExact {
    fn model(&self) -> ForceModel {
        self.model
    }

    fn params(&self) -> &ImpactParams {
        &self.params
    }

    /// F(x) of eq 13/14 inverted (eq 1 on spheres), continued oddly to x < 0.
    fn phase_force(&self, x: f64, _v: f64, _phase: Phase) -> f64 {
        x.signum() * self.force_at(x.abs())
    }

    fn dissipative_force(&self, _x: f64, _v: f64, _phase: Phase) -> f64 {
        0.0
    }

    /// dF/dx = 1/x′(F) (eq 13/14 differentiated; n·k·xⁿ⁻¹ on spheres), even in x.
    fn partials(&self, x: f64, _v: f64, _phase: Phase) -> (f64, f64) {
        let law = self.params.law;
        let stiffness = match self.line {
            Some(line) => {
                let f = self.force_at(x.abs());
                if f > 0.0 { 1.0 / line.slope(f) } else { 0.0 }
            }
            None => law.n * law.k * abs_pow_nm1(x, law.n),
        };
        (stiffness, 0.0)
    }

    /// F depends on x alone: ∮F dx is exact from the stored energy.
    fn rate_independent(&self) -> bool {
        true
    }

    /// E(F(x)) = F·x/2 − B·F²/4 (k·x^{n+1}/(n+1) on spheres).
    fn stored_energy(&self, x: f64, _phase: Phase) -> f64 {
        match self.line {
            Some(line) => line.energy(self.force_at(x.max(0.0))),
            None => {
                let law = self.params.law;
                law.k * x * x * abs_pow_nm1(x, law.n) / (law.n + 1.0)
            }
        }
    }

    fn contact_end(&self) -> ContactEnd {
        ContactEnd::ApproachZero
    }

    fn may_turn_tensile(&self) -> bool {
        false
    }

    fn tension(&self, _x: f64, _v: f64) -> f64 {
        1.0
    }

    /// Eq 1's closed form on spheres; the line contact is integrated.
    fn exact(&self, _rtol: f64) -> Option<ExactImpact> {
        self.line.is_none().then(|| elastic(&self.params))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::exact::quadrature::tanh_sinh;
    use crate::model::presets::Registry;

    fn law(scene: &str) -> (HertzLineExact, LineContact) {
        let scene = Registry::builtin().unwrap().scene(scene).unwrap();
        let params = scene.impact_params(&scene.quasistatic().unwrap());
        let Contact::Line { line, .. } = params.contact else {
            panic!("{} is a line contact", scene.name);
        };
        let law =
            HertzLineExact::build(ForceModel::with_id("hertz-line-exact"), &params, None).unwrap();
        (law, line)
    }

    #[test]
    fn the_inverse_matches_the_formulas_newton_inverse_and_stores_their_energy() {
        for scene in ["steel-cylinders-r20-l100", "steel-cylinder-r20-l100-plate"] {
            let (law, line) = law(scene);
            let log_linear = law.line.unwrap();
            let x_top = line.approach(0.5 * line.force_limit()).unwrap();
            for fraction in [1e-9, 1e-5, 1e-3, 0.1, 0.7, 1.0] {
                let x = fraction * x_top;
                let f = law.phase_force(x, 0.0, Phase::Loading);
                // Against LineContact's bracketed Newton (1e-14) on eq 13/14 directly.
                let newton = line.force_at(x).unwrap();
                assert!(
                    (f / newton - 1.0).abs() < 1e-13,
                    "{scene} {x}: {f} vs {newton}"
                );
                assert!((line.approach(f).unwrap() / x - 1.0).abs() < 1e-13);
                assert_eq!(law.phase_force(-x, 0.0, Phase::Loading), -f);
                // E(F) = ∫₀^x F dx, by tanh-sinh in x.
                let work = tanh_sinh(|s, _, _| law.force_at(s), 0.0, x, 1e-13);
                let stored = law.stored_energy(x, Phase::Loading);
                assert!(
                    (stored / work - 1.0).abs() < 1e-11,
                    "{scene} {x}: {stored} vs {work}"
                );
                // dF/dx against a central difference.
                let h = 1e-6 * x;
                let fd = (law.force_at(x + h) - law.force_at(x - h)) / (2.0 * h);
                let (dfdx, _) = law.partials(x, 0.0, Phase::Loading);
                assert!(
                    (dfdx / fd - 1.0).abs() < 1e-8,
                    "{scene} {x}: {dfdx} vs {fd}"
                );
                assert!(log_linear.slope(f) > 0.0);
            }
        }
    }
}
