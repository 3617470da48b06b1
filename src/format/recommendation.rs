//! The model's recommendation ([`Reason`]) in words: the gist for narrow panes and the one-line
//! reason, for the explorer's regime pane and `solve`'s report alike.

use crate::model::recommend::{HysteresisChoice, RESTITUTION_TOLERANCE, Reason};

/// The gist of `reason`, for narrow screens.
pub fn gist(reason: &Reason) -> &'static str {
    match reason {
        Reason::Lossless => "nothing yields or is lost",
        Reason::NoYieldNoDent { .. } => "no yield, no dent",
        Reason::NoYieldLossesLikely => "no yield; losses likely",
        Reason::FullyPlastic => "beyond Hertz: all extrapolate",
        Reason::DentKept => "yield begins, a dent is kept",
        Reason::LossWithoutDent => "loss without a dent",
        Reason::SmallLosses(_) => "small losses",
        Reason::LargeLosses(_) => "large losses: faithful e",
    }
}

/// Why, in one line.
pub fn why(reason: &Reason) -> String {
    match reason {
        Reason::Lossless => "p₀ < 1.1·σ_y and e = 1: nothing yields and nothing is lost, elastic \
                             Hertz (eq 1) is the whole story"
            .into(),
        Reason::NoYieldNoDent { restitution } => format!(
            "p₀ < 1.1·σ_y and v₀ ≤ 10⁻⁵·√(E/ρ): no yield, no dent; elastic Hertz (eq 1) \
             gives the force, dry friction (eq 15, §4.1) adds the loss e = {} if it matters",
            short(*restitution)
        ),
        Reason::NoYieldLossesLikely => "p₀ < 1.1·σ_y: elastic Hertz (eq 1) gives the force, but \
                                        v₀ > 10⁻⁵·√(E/ρ): expect losses, which the dissipative \
                                        models (eqs 15, 19, 20) carry"
            .into(),
        Reason::FullyPlastic => "p₀ ≥ 2.8·σ_y: fully plastic, beyond Hertz theory: every model \
                                 extrapolates; the proposed model (eq 18), with its permanent \
                                 indentation, least"
            .into(),
        Reason::DentKept => "p₀ ≥ 1.1·σ_y: yield begins and the given x_pl > 0 says the surface \
                             keeps a dent: the proposed model (eq 18, §4.2) leaves it and exits \
                             near v₀e"
            .into(),
        Reason::LossWithoutDent => "p₀ ≥ 1.1·σ_y, but v₀ ≤ 10⁻⁵·√(E/ρ) and x_pl = 0: energy is \
                                    lost without a dent, as dry friction (eq 15, §4.1) models it"
            .into(),
        Reason::SmallLosses(choice) => format!(
            "p₀ ≥ 1.1·σ_y with e close to 1 and x_pl = 0: small losses, which hysteresis \
             damping was derived for; {}",
            hysteresis_clause(choice)
        ),
        Reason::LargeLosses(choice) => format!(
            "p₀ ≥ 1.1·σ_y and v₀ > 10⁻⁵·√(E/ρ) with e far from 1: {}; for the dent this regime \
             leaves, give x_pl > 0 (the proposed model, eq 18)",
            hysteresis_clause(choice)
        ),
    }
}

/// The clause naming the hysteresis law chosen and the e it realises, or the calibration.
fn hysteresis_clause(choice: &HysteresisChoice) -> String {
    match *choice {
        HysteresisChoice::Faithful {
            model,
            realised,
            restitution,
        } => format!(
            "{} realises e = {} for e = {} (within {} %)",
            model.label(),
            short(realised),
            short(restitution),
            RESTITUTION_TOLERANCE * 100.0
        ),
        HysteresisChoice::Calibrated { restitution, chi } => format!(
            "no χ(e) rule realises e = {} within {} %: calibrate Hunt–Crossley (χ = {}, solve --calibrate)",
            short(restitution),
            RESTITUTION_TOLERANCE * 100.0,
            chi.map_or("?".into(), |chi| format!("{chi:.4}"))
        ),
    }
}

/// A restitution as the reason prints it: up to three significant digits.
fn short(e: f64) -> String {
    let text = format!("{e:.3}");
    text.trim_end_matches('0').trim_end_matches('.').to_string()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::ForceModel;
    use crate::model::recommend::recommend;
    use crate::model::scene::tests::fig5_scene;
    use crate::model::scene::{ImpactConditions, Scene};

    /// The reason for the Fig. 5 scene (steel sphere R = 10 mm on a steel plate) at v₀, e, x_pl.
    fn why_at(v0: f64, restitution: f64, plastic_indentation: f64) -> String {
        let scene = Scene {
            impact: ImpactConditions {
                v0,
                restitution,
                plastic_indentation,
            },
            ..fig5_scene()
        };
        let q = scene.quasistatic().unwrap();
        why(&recommend(&scene, &q).reason)
    }

    #[test]
    fn the_reasons_name_the_criterion_and_the_numbers() {
        // Fig. 4's scene: below yield and the wave limit, the loss e = 0.9 named.
        assert_eq!(
            why_at(0.03, 0.9, 0.0),
            "p₀ < 1.1·σ_y and v₀ ≤ 10⁻⁵·√(E/ρ): no yield, no dent; elastic Hertz (eq 1) gives \
             the force, dry friction (eq 15, §4.1) adds the loss e = 0.9 if it matters"
        );
        assert!(why_at(0.3, 0.6, 2.3e-6).contains("keeps a dent"));
        // Hunt–Crossley's own rule realises 0.9524 for e = 0.95, within 2 %.
        assert!(
            why_at(0.2, 0.95, 0.0)
                .ends_with("; Hunt–Crossley (eq 19) realises e = 0.952 for e = 0.95 (within 2 %)"),
            "{}",
            why_at(0.2, 0.95, 0.0)
        );
        assert!(why_at(0.2, 0.3, 0.0).contains("give x_pl > 0"));
        // No rule realises 0.5: Hunt–Crossley calibrated, χ = 1.4328.
        assert!(
            why_at(0.2, 0.5, 0.0).contains(
                "no χ(e) rule realises e = 0.5 within 2 %: calibrate Hunt–Crossley (χ = 1.4328, solve --calibrate)"
            ),
            "{}",
            why_at(0.2, 0.5, 0.0)
        );
        assert!(why_at(1.0, 0.6, 2.3e-6).contains("beyond Hertz"));
    }

    #[test]
    fn the_calibration_clause_says_when_there_is_no_chi() {
        let choice = HysteresisChoice::Calibrated {
            restitution: 0.25,
            chi: None,
        };
        assert_eq!(
            hysteresis_clause(&choice),
            "no χ(e) rule realises e = 0.25 within 2 %: calibrate Hunt–Crossley (χ = ?, solve --calibrate)"
        );
        let faithful = HysteresisChoice::Faithful {
            model: ForceModel::LankaraniNikravesh,
            realised: 0.9012,
            restitution: 0.9,
        };
        assert!(hysteresis_clause(&faithful).contains("realises e = 0.901 for e = 0.9"));
    }

    #[test]
    fn every_reason_has_a_gist_and_a_reason() {
        for v0 in [0.005, 0.02, 0.04, 0.1, 0.3, 0.5, 2.0] {
            for e in [0.3, 0.6, 0.9, 1.0] {
                for x_pl in [0.0, 1e-6] {
                    let reason = why_at(v0, e, x_pl);
                    assert!(reason.starts_with("p₀ "), "{reason}");
                    assert!(!reason.contains("NaN"), "{reason}");
                }
            }
        }
        assert_eq!(gist(&Reason::DentKept), "yield begins, a dent is kept");
    }
}
