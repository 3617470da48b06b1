//! The model's recommendation ([`Reason`]) in words: the gist for narrow panes and the one-line
//! reason, for the explorer's regime pane and `solve`'s report alike.

use crate::format::units::{METRE, NEWTON, PASCAL, engineering};
use crate::model::body::{Body, Shape};
use crate::model::pressure::Regime;
use crate::model::recommend::{
    HysteresisChoice, Outcome, RESTITUTION_TOLERANCE, Reason, Recommendation, Yielding,
};
use crate::model::scene::Scene;

/// The gist of `reason`, for narrow screens.
pub fn gist(reason: &Reason) -> &'static str {
    match reason {
        Reason::Lossless => "nothing yields or is lost",
        Reason::NoYieldNoDent { .. } => "no yield, no dent",
        Reason::NoYieldLossesLikely => "no yield; losses likely",
        Reason::FullyPlastic => "fully plastic: yield from σ_y",
        Reason::DentKept => "yield begins, a dent is kept",
        Reason::LossWithoutDent => "loss without a dent",
        Reason::SmallLosses(_) => "small losses",
        Reason::LargeLosses(_) => "large losses: faithful e",
    }
}

/// Why, in one line: the clauses of [`why_clauses`] joined.
pub fn why(advice: &Recommendation, scene: &Scene) -> String {
    why_clauses(advice, scene).join("; ")
}

/// Why, clause by clause, the most needed first: the case of the guidance with the numbers that
/// decided it and the body that yields; which inputs were assumed rather than given; what the
/// recommended law (and, once the contact yields, Thornton's) realises on the scene.
pub fn why_clauses(advice: &Recommendation, scene: &Scene) -> Vec<String> {
    let e = advice.restitution;
    let x_pl = advice.plastic_indentation;
    let who = yielding_body(advice, scene);
    let mut clauses: Vec<String> = vec![match &advice.reason {
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
        Reason::FullyPlastic => format!(
            "p₀ ≥ 2.8·σ_y of {who}: fully plastic, beyond Hertz theory, and no dent given; \
             Thornton's elastic–plastic law models the yield from σ_y"
        ),
        Reason::DentKept => format!(
            "p₀ ≥ {}·σ_y of {who}: {}; the given x_pl = {} keeps a dent, which the proposed \
             model (eq 18, §4.2) leaves",
            onset_factor(advice),
            regime_words(advice),
            length(x_pl)
        ),
        Reason::LossWithoutDent => format!(
            "p₀ ≥ 1.1·σ_y of {who}: yield begins, but v₀ ≤ 10⁻⁵·√(E/ρ) and no dent given: \
             energy is lost without a dent, as dry friction (eq 15, §4.1) models it"
        ),
        Reason::SmallLosses(choice) => format!(
            "p₀ ≥ {}·σ_y of {who}: {}, with e close to 1 and no dent given: small losses, \
             which hysteresis damping was derived for; {}",
            onset_factor(advice),
            regime_words(advice),
            hysteresis_clause(choice)
        ),
        Reason::LargeLosses(choice) => format!(
            "p₀ ≥ {}·σ_y of {who}: {}, v₀ > 10⁻⁵·√(E/ρ) with e far from 1 and no dent \
             given: {}; for the dent this regime leaves, give x_pl > 0 (the proposed model, eq 18)",
            onset_factor(advice),
            regime_words(advice),
            hysteresis_clause(choice)
        ),
    }];
    if advice.assumed.plastic_indentation && x_pl > 0.0 && advice.regime != Regime::Elastic {
        clauses.push(format!(
            "x_pl = {} was not given (a stand-in): nothing here rests on it; give \
             impact.plastic_indentation for the dent",
            length(x_pl)
        ));
    }
    if advice.assumed.restitution && e < 1.0 {
        clauses.push(format!(
            "e = {} was not given (a stand-in): what rests on e rests on it",
            short(e)
        ));
    }
    if let Some(outcome) = advice.outcome {
        clauses.extend(outcome_clause(advice, &outcome));
    }
    if let Some(thornton) = advice.thornton {
        clauses.push(thornton_clause(advice, &thornton));
    }
    clauses
}

/// What the recommended law realises, where the reason does not already say it.
fn outcome_clause(advice: &Recommendation, outcome: &Outcome) -> Option<String> {
    let e = advice.restitution;
    let name = outcome.model.label();
    match advice.reason {
        Reason::DentKept if outcome.realises(e) => Some(format!(
            "{name} realises e = {} for e = {} and leaves x_res = {}",
            short(outcome.e_out),
            short(e),
            length(outcome.x_residual)
        )),
        Reason::DentKept => Some(format!(
            "{name} realises e = {} for e = {} ({:+.0} %, not within {} %): to realise e, \
             calibrate b (C, solve --calibrate) or give the x_pl measured with this e",
            short(outcome.e_out),
            short(e),
            (outcome.e_out / e - 1.0) * 100.0,
            RESTITUTION_TOLERANCE * 100.0
        )),
        Reason::LossWithoutDent => Some(format!(
            "{name} realises e = {} for e = {}",
            short(outcome.e_out),
            short(e)
        )),
        _ => None,
    }
}

/// Thornton's outcome beside elastic Hertz's peak, and against the scene's e.
fn thornton_clause(advice: &Recommendation, thornton: &Outcome) -> String {
    let e = advice.restitution;
    let mut clause = format!(
        "{} (yield from σ_y, not from e) gives F_max = {} and e = {} (elastic Hertz: F_max = {})",
        thornton.model.label(),
        force(thornton.f_max),
        short(thornton.e_out),
        force(advice.hertz_f_max)
    );
    if !thornton.realises(e) {
        clause.push_str(&format!(
            ", not the scene's e = {}: to impose e, calibrate its v_y (C, solve --calibrate)",
            short(e)
        ));
    }
    clause
}

/// The yield-onset factor of the regime: 2.8 fully plastic, else 1.1.
fn onset_factor(advice: &Recommendation) -> &'static str {
    match advice.regime {
        Regime::FullyPlastic => "2.8",
        _ => "1.1",
    }
}

fn regime_words(advice: &Recommendation) -> &'static str {
    match advice.regime {
        Regime::FullyPlastic => "fully plastic, beyond Hertz theory",
        _ => "yield begins",
    }
}

/// The body that yields (the softer), named with its material and σ_y: "body 2, the
/// aluminium-alloy plate (σ_y = 340 MPa)", or both.
fn yielding_body(advice: &Recommendation, scene: &Scene) -> String {
    let stress = engineering(advice.yield_stress, PASCAL, 3);
    let body = |n: u8, body: &Body| {
        let shape = match body.shape {
            Shape::Plane => "plate".to_string(),
            other => other.name().to_string(),
        };
        format!(
            "body {n}, the {} {shape} (σ_y = {stress})",
            body.material.name
        )
    };
    match advice.yielding {
        Yielding::Body1 => body(1, &scene.body1),
        Yielding::Body2 => body(2, &scene.body2),
        Yielding::Both => format!("both bodies (σ_y {stress})"),
    }
}

fn length(x: f64) -> String {
    engineering(x, METRE, 3)
}

fn force(f: f64) -> String {
    engineering(f, NEWTON, 3)
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
        why(&recommend(&scene, &q), &scene)
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
                .contains("; Hunt–Crossley (eq 19) realises e = 0.952 for e = 0.95 (within 2 %); "),
            "{}",
            why_at(0.2, 0.95, 0.0)
        );
        // Once the contact yields, Thornton's law is solved beside, and the body that yields named.
        assert!(
            why_at(0.2, 0.95, 0.0)
                .contains("of both bodies (σ_y 780 MPa): yield begins, with e close to 1"),
            "{}",
            why_at(0.2, 0.95, 0.0)
        );
        assert!(why_at(0.2, 0.95, 0.0).contains("Thornton 1997 (yield from σ_y, not from e)"));
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
        // Fully plastic without a dent: Thornton, never the proposed model's dent.
        let plastic = why_at(1.0, 0.6, 0.0);
        assert!(
            plastic.contains("Thornton's elastic–plastic law models the yield"),
            "{plastic}"
        );
        assert!(!plastic.contains("indentation"), "{plastic}");
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
