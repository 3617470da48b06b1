//! Which force models suit the scene's regime, and why: the reading of the regime line.
//!
//! The numbers (yield-onset velocities, wave limit, regime) all come from the model layer; this
//! only phrases the paper's guidance (§2, §4 and the conclusion) for the velocity at hand.

use crate::model::pressure::Regime;
use crate::model::{ForceModel, Quasistatic};

/// The regime of an impact and the models that fit it.
#[derive(Debug, Clone, PartialEq)]
pub struct Advice {
    pub regime: Regime,
    /// v₀ ≤ 10⁻⁵·√(E/ρ): the conclusion's criterion for no permanent indentation.
    pub within_wave_limit: bool,
    /// Models valid in this regime, simplest first.
    pub fits: Vec<ForceModel>,
    /// The gist of the reason, for narrow screens.
    pub gist: &'static str,
    /// Why those models.
    pub why: &'static str,
}

/// The advice for `quasistatic` at pre-impact velocity `v0`.
pub fn advise(quasistatic: &Quasistatic, v0: f64) -> Advice {
    let regime = quasistatic.regime(v0);
    let within_wave_limit = v0 <= quasistatic.onset.v_wave_limit;
    let (fits, gist, why) = match (regime, within_wave_limit) {
        (Regime::Elastic, true) => (
            vec![ForceModel::Quasistatic, ForceModel::DryFriction],
            "elastic Hertz suffices",
            "p₀ < 1.1·σ_y and v₀ within the wave limit: elastic Hertz (eq 1) holds; \
             dry friction (eq 15) adds a loss (e < 1) without permanent indentation",
        ),
        (Regime::Elastic, false) => (
            vec![
                ForceModel::Quasistatic,
                ForceModel::DryFriction,
                ForceModel::HuntCrossley,
                ForceModel::LankaraniNikravesh,
            ],
            "Hertz holds; losses likely",
            "p₀ < 1.1·σ_y: elastic Hertz (eq 1) holds, but v₀ is past the wave limit: \
             expect losses, which the dissipative models (eqs 15, 19, 20) carry",
        ),
        (Regime::YieldBegins, _) => (
            vec![
                ForceModel::Proposed,
                ForceModel::HuntCrossley,
                ForceModel::LankaraniNikravesh,
            ],
            "needs a dissipative model",
            "p₀ ≥ 1.1·σ_y: yield begins, energy is lost and the surface keeps a dent: \
             a dissipative model is needed; the proposed model (eq 18) also leaves the \
             permanent indentation x_pl",
        ),
        (Regime::FullyPlastic, _) => (
            vec![ForceModel::Proposed],
            "beyond Hertz: all extrapolate",
            "p₀ ≥ 2.8·σ_y: fully plastic, beyond Hertz theory: every model here \
             extrapolates; the proposed model (eq 18), with its permanent indentation, least",
        ),
    };
    Advice {
        regime,
        within_wave_limit,
        fits,
        gist,
        why,
    }
}

/// A short name of a regime for the regime line.
pub fn regime_name(regime: Regime) -> &'static str {
    match regime {
        Regime::Elastic => "elastic",
        Regime::YieldBegins => "yield begins",
        Regime::FullyPlastic => "fully plastic",
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ui::testing::fig5_scene;

    fn advice_at(v0: f64) -> Advice {
        let mut scene = fig5_scene();
        scene.impact.v0 = v0;
        let q = scene.quasistatic().unwrap();
        advise(&q, v0)
    }

    #[test]
    fn follows_the_yield_onset_velocities_of_table_1() {
        // Steel on steel: v_y = 0.032 m/s, v_p = 0.326 m/s; wave limit ≈ 0.0506 m/s.
        let slow = advice_at(0.01);
        assert_eq!(slow.regime, Regime::Elastic);
        assert!(slow.within_wave_limit);
        assert_eq!(slow.fits[0], ForceModel::Quasistatic);
        assert!(!slow.fits.contains(&ForceModel::Proposed));

        let fig5 = advice_at(0.3);
        assert_eq!(fig5.regime, Regime::YieldBegins);
        assert!(!fig5.within_wave_limit);
        assert!(!fig5.fits.contains(&ForceModel::Quasistatic));
        assert!(fig5.fits.contains(&ForceModel::Proposed));

        let fast = advice_at(1.0);
        assert_eq!(fast.regime, Regime::FullyPlastic);
        assert_eq!(fast.fits, [ForceModel::Proposed]);
        assert!(fast.why.contains("beyond Hertz"));
    }
}
