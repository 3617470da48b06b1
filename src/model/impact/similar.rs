//! Dynamic similarity: a law whose damping the scene's e sets so that, in the solver's scaled
//! variables x/x_e, ẋ/v₀, t·v₀/x_e, its impact depends on n, e and its contact rule alone is
//! solved once and scaled to every other v₀, m and k (docs/physics.md §6.9).

use crate::model::force::{AnyLaw, ForceLaw, ForceModel, ImpactParams};

use super::scale::Scales;
use super::{
    ImpactError, ImpactSolution, ImpactSummary, SolveOptions, TensileCutoff, solve_impact,
};

/// One impact of a similar law, ready to be scaled to other parameters with the same n and e.
#[derive(Debug, Clone)]
pub struct SimilarImpact {
    summary: ImpactSummary,
    params: ImpactParams,
    scales: Scales,
}

impl SimilarImpact {
    /// `model`'s impact under `params`, to be scaled: `None` when the law is not similar
    /// ([`crate::model::force::LawSpec::similar`]) or `opts` fixes a step in seconds, which would
    /// not scale.
    pub fn solve(
        model: ForceModel,
        params: &ImpactParams,
        opts: &SolveOptions,
    ) -> Option<Result<Self, ImpactError>> {
        if !model.spec().similar || opts.dt.is_some() {
            return None;
        }
        Some(
            solve_impact(model, params, opts).map(|solution| SimilarImpact {
                summary: solution.summary,
                params: *params,
                scales: Scales::new(params),
            }),
        )
    }

    /// The impact under `params` by scaling (by x_e, v₀, x_e/v₀, k·x_eⁿ), when they share n and
    /// e with the solved one (`None` otherwise: solve it); a solve under `params` takes the same
    /// steps and gives the same numbers, to rounding.
    pub fn at(&self, params: &ImpactParams) -> Option<Result<ImpactSummary, ImpactError>> {
        if !movable(&self.params, params) {
            return None;
        }
        if let Err(e) = params.validate() {
            return Some(Err(e.into()));
        }
        let ratios = Ratios::between(&self.scales, &Scales::new(params));
        Some(Ok(moved(&self.summary, &ratios)))
    }
}

impl ImpactSolution {
    /// This solution moved to `law`: the same row of a similar law under parameters with the same
    /// n and e (docs/physics.md §6.9), as solving `law` with the same options would give it, to
    /// rounding. `None` when the row is not similar, n or e differ, or `law` is another row. The
    /// caller vouches that both laws take their damping from e by the row's rule and that the
    /// options fix no step in seconds.
    pub fn similar_at(&self, law: &AnyLaw) -> Option<ImpactSolution> {
        let own = self.trajectory.law();
        let same = law.model() == own.model()
            && law.model().spec().similar
            && movable(own.params(), law.params());
        if !same {
            return None;
        }
        let (from, to) = (Scales::of_law(own), Scales::of_law(law));
        let ratios = Ratios::between(&from, &to);
        Some(ImpactSolution {
            summary: moved(&self.summary, &ratios),
            trajectory: self.trajectory.rescaled(*law, to, &ratios),
        })
    }

    /// The ratios of `other`'s scales to this solution's: what moves this one onto `other` when
    /// [`ImpactSolution::similar_at`] made it.
    pub fn ratios_to(&self, other: &ImpactSolution) -> Ratios {
        Ratios::between(
            &Scales::new(self.trajectory.law().params()),
            &Scales::new(other.trajectory.law().params()),
        )
    }
}

/// Whether a similar row's impact under `from` moves to `to`: the same n and e, to the bit.
fn movable(from: &ImpactParams, to: &ImpactParams) -> bool {
    from.law.n.to_bits() == to.law.n.to_bits()
        && from.restitution.to_bits() == to.restitution.to_bits()
}

/// What a similar law's impact is multiplied by to move it (docs/physics.md §6.9): time, approach,
/// velocity, force and energy.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ratios {
    /// Of x_e/v₀.
    pub t: f64,
    /// Of x_e (eq 5).
    pub x: f64,
    /// Of v₀.
    pub v: f64,
    /// Of k·x_eⁿ (eq 6).
    pub f: f64,
    /// Of m·v₀².
    pub energy: f64,
}

impl Ratios {
    /// The ratios of scales `to` to scales `from`.
    pub(crate) fn between(from: &Scales, to: &Scales) -> Ratios {
        Ratios {
            t: to.t / from.t,
            x: to.x / from.x,
            v: to.v / from.v,
            f: to.f / from.f,
            energy: (to.mass * to.v * to.v) / (from.mass * from.v * from.v),
        }
    }
}

/// `s` moved by `r`: x scales by x_e, ẋ by v₀, t by x_e/v₀, F by k·x_eⁿ (eqs 5–7) and energy
/// by m·v₀²; the step counts stay.
fn moved(s: &ImpactSummary, r: &Ratios) -> ImpactSummary {
    let (x, v, t, f) = (r.x, r.v, r.t, r.f);
    ImpactSummary {
        x_max: s.x_max * x,
        t_x_max: s.t_x_max * t,
        f_max: s.f_max * f,
        t_f_max: s.t_f_max * t,
        t_contact: s.t_contact * t,
        v_out: s.v_out * v,
        x_residual: s.x_residual * x,
        energy_dissipated: s.energy_dissipated * r.energy,
        tensile_cutoff: s.tensile_cutoff.map(|c| TensileCutoff {
            t: c.t * t,
            x: c.x * x,
            v: c.v * v,
        }),
        ..s.clone()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::impact::Sample;
    use crate::model::scene::tests::fig5_scene;

    /// The Fig. 5 scene's parameters, or those of a steel cylinder on its plate, with v₀, m and
    /// k changed by the given factors.
    fn varied(cylinder: bool, v0: f64, mass: f64, k: f64) -> ImpactParams {
        let mut scene = fig5_scene();
        if cylinder {
            scene.body1.shape = crate::model::body::Shape::Cylinder {
                radius: 0.02,
                length: 0.1,
            };
            scene.body1.mass = Some(1.0);
        }
        let mut params = scene.impact_params(&scene.quasistatic().unwrap());
        params.v0 *= v0;
        params.mass *= mass;
        params.law.k *= k;
        params
    }

    /// The largest relative difference of the numbers between a direct solve and the scaled one,
    /// but t_f_max's, and t_f_max's: a flat peak's dF/dt = 0 places it only to about √ε of the
    /// contact time, so that rounding moves it by 1e-8.
    fn worst(a: &ImpactSummary, b: &ImpactSummary) -> (f64, f64) {
        let rel = |x: f64, y: f64| {
            if x == y {
                0.0
            } else {
                (x - y).abs() / x.abs().max(y.abs())
            }
        };
        let others = [
            rel(a.x_max, b.x_max),
            rel(a.t_x_max, b.t_x_max),
            rel(a.f_max, b.f_max),
            rel(a.t_contact, b.t_contact),
            rel(a.v_out, b.v_out),
            rel(a.e_out, b.e_out),
            rel(a.energy_dissipated, b.energy_dissipated),
        ];
        let peak = rel(a.t_f_max, b.t_f_max) / (a.t_contact / a.t_f_max);
        (others.into_iter().fold(0.0, f64::max), peak)
    }

    /// Every law the table calls similar, on a sphere and on a cylinder, solved at v₀ 30 times
    /// smaller and larger, mass and stiffness changed too, equals its one solve scaled, to
    /// rounding (1e-12; the adaptive solver's own error is 1e-8 here); every law it does not call
    /// similar differs by more than that on one of them, so the flag is neither missing nor wrong.
    #[test]
    fn the_similar_laws_scale_and_the_others_do_not() {
        let opts = SolveOptions::default();
        for model in ForceModel::ALL {
            let spec = model.spec();
            let mut worst_of_all: f64 = 0.0;
            let mut worst_peak: f64 = 0.0;
            for cylinder in [false, true] {
                let base = varied(cylinder, 1.0, 1.0, 1.0);
                let reference = SimilarImpact {
                    summary: solve_impact(model, &base, &opts).unwrap().summary,
                    params: base,
                    scales: Scales::new(&base),
                };
                for (v0, mass, k) in [(1.0 / 30.0, 1.0, 1.0), (30.0, 1.0, 1.0), (0.5, 7.0, 0.2)] {
                    let p = varied(cylinder, v0, mass, k);
                    let direct = solve_impact(model, &p, &opts).unwrap().summary;
                    let scaled = reference.at(&p).unwrap().unwrap();
                    let (others, peak) = worst(&direct, &scaled);
                    worst_of_all = worst_of_all.max(others);
                    worst_peak = worst_peak.max(peak);
                }
            }
            if spec.similar {
                assert!(worst_of_all < 1e-12, "{}: {worst_of_all:e}", spec.id);
                assert!(worst_peak < 1e-7, "{}: t_f_max {worst_peak:e}", spec.id);
            } else {
                assert!(
                    worst_of_all > 1e-6,
                    "{}: {worst_of_all:e} (similar after all?)",
                    spec.id
                );
            }
        }
    }

    /// A solution moved to another v₀, m and k has the numbers and the curves of a solve there:
    /// its chart curves and its 1e-9 curves sample by sample within 1e-7 of each quantity's scale
    /// (a wrong scale is off by its ratio, here 1/6 to 3), whether its curves were integrated
    /// before the move or after; another n, e or row is refused.
    #[test]
    fn a_solution_moves_with_its_curves() {
        let opts = SolveOptions::default();
        let base = varied(false, 1.0, 1.0, 1.0);
        for model in ForceModel::ALL.into_iter().filter(|m| m.spec().similar) {
            for integrated_before in [false, true] {
                let solved = solve_impact(model, &base, &opts).unwrap();
                if integrated_before {
                    solved.trajectory.drawn_samples(50);
                    solved.trajectory.samples(50);
                }
                for p in [
                    varied(false, 1.0 / 6.0, 1.0, 1.0),
                    varied(false, 3.0, 2.0, 0.5),
                ] {
                    let law = model.law(&p).unwrap();
                    let moved = solved.similar_at(&law).unwrap();
                    let direct = solve_impact(model, &p, &opts).unwrap();
                    assert!(
                        worst(&moved.summary, &direct.summary).0 < 1e-12,
                        "{model:?}"
                    );
                    let s = &direct.summary;
                    let scale =
                        |q: &Sample| [q.t / s.t_contact, q.x / s.x_max, q.v / p.v0, q.f / s.f_max];
                    let apart = |a: &Sample, b: &Sample| {
                        (scale(a).iter().zip(scale(b)))
                            .map(|(u, w)| (u - w).abs())
                            .fold(0.0, f64::max)
                    };
                    // Sample by sample, both the chart curves and the 1e-9 ones: 1e-7, as a flat
                    // force peak's time moves by about √ε with rounding (along the curve).
                    let drawn = |sol: &ImpactSolution| sol.trajectory.drawn_samples(200);
                    let fine = |sol: &ImpactSolution| sol.trajectory.samples(200);
                    for pick in [drawn, fine] {
                        let (ours, theirs) = (pick(&moved), pick(&direct));
                        assert_eq!(ours.len(), theirs.len());
                        for (a, b) in ours.iter().zip(&theirs) {
                            assert!(
                                apart(a, b) < 1e-7,
                                "{model:?} {integrated_before}: {a:?} vs {b:?}"
                            );
                        }
                    }
                }
            }
            let law = |e: f64, model: ForceModel| {
                let mut p = base;
                p.restitution = e;
                model.law(&p).unwrap()
            };
            let solved = solve_impact(model, &base, &opts).unwrap();
            assert!(solved.similar_at(&law(0.3, model)).is_none());
            assert!(
                solved
                    .similar_at(&law(base.restitution, ForceModel::Proposed))
                    .is_none()
            );
        }
    }

    #[test]
    fn only_similar_laws_with_a_scaling_step_are_solved_for_scaling() {
        let params = varied(false, 1.0, 1.0, 1.0);
        let mut opts = SolveOptions::default();
        assert!(
            SimilarImpact::solve(ForceModel::with_id("hertz-viscous"), &params, &opts).is_some()
        );
        assert!(SimilarImpact::solve(ForceModel::Proposed, &params, &opts).is_none());
        opts.dt = Some(1e-7);
        assert!(
            SimilarImpact::solve(ForceModel::with_id("hertz-viscous"), &params, &opts).is_none()
        );
    }

    #[test]
    fn another_n_or_e_or_an_invalid_v0_is_not_scaled() {
        let params = varied(false, 1.0, 1.0, 1.0);
        let opts = SolveOptions::default();
        let solved = SimilarImpact::solve(ForceModel::with_id("kuwabara-kono"), &params, &opts)
            .unwrap()
            .unwrap();
        let mut other = params;
        other.restitution = 0.5;
        assert!(solved.at(&other).is_none());
        let mut other = params;
        other.law.n = 1.0;
        assert!(solved.at(&other).is_none());
        let mut other = params;
        other.v0 = -1.0;
        assert!(matches!(
            solved.at(&other),
            Some(Err(ImpactError::InvalidInput(_)))
        ));
    }
}
