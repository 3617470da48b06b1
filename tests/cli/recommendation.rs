//! `solve`'s recommendation held against the numbers beside it: for every preset over a grid of
//! v₀, e and x_pl (the preset's own, given as 0, given as a dent), each sentence of its reason is
//! checked against the impact rows and the quasistatic estimate of the same report.

use hertz_tui::cli::args::{Cli, Command};
use hertz_tui::cli::solve::{ImpactRow, SolveReport, report};
use hertz_tui::model::ForceModel;
use hertz_tui::model::presets::Registry;

use clap::Parser;

const THORNTON: ForceModel = ForceModel::with_id("thornton");

/// The report of `solve --scene preset --set …`, as the command computes it.
fn solve(preset: &str, sets: &[String], registry: &Registry) -> SolveReport {
    let mut argv = vec!["hertz-tui", "solve", "--scene", preset];
    for set in sets {
        argv.extend(["--set", set.as_str()]);
    }
    let Some(Command::Solve(args)) = Cli::try_parse_from(&argv).unwrap().command else {
        panic!("not a solve: {argv:?}");
    };
    report(&args, registry).unwrap_or_else(|e| panic!("{argv:?}: {e}"))
}

fn row(report: &SolveReport, model: ForceModel) -> &ImpactRow {
    report.impacts.iter().find(|r| r.model == model).unwrap()
}

/// The number after `prefix` in `text` (up to a space, comma, parenthesis or semicolon).
fn number_after<'t>(text: &'t str, prefix: &str) -> Option<&'t str> {
    let start = text.find(prefix)? + prefix.len();
    let rest = &text[start..];
    let end = rest.find([' ', ',', ')', ';']).unwrap_or(rest.len());
    Some(&rest[..end])
}

/// `shown` (three decimals at most, as the reason prints a restitution) is `value` rounded.
fn same_restitution(shown: &str, value: f64) -> bool {
    shown
        .parse::<f64>()
        .is_ok_and(|s| (s - value).abs() <= 0.0005 + 1e-12)
}

/// `shown` (`620 N`, `1.23 kN`, three significant digits) is `value` N to three digits.
fn same_force(shown: &str, value: f64) -> bool {
    let (number, unit) = shown.split_once(' ').unwrap_or((shown, "N"));
    let scale = match unit {
        "mN" => 1e-3,
        "N" => 1.0,
        "kN" => 1e3,
        "MN" => 1e6,
        _ => return false,
    };
    number
        .parse::<f64>()
        .is_ok_and(|n| (n * scale / value - 1.0).abs() < 0.006)
}

/// Every claim of the reason, against the report's own numbers.
fn check(report: &SolveReport, label: &str) {
    let why = &report.recommendation.why;
    let scene = &report.scene;
    let (e, x_pl) = (scene.impact.restitution, scene.impact.plastic_indentation);
    let onset = &report.quasistatic.onset;
    let v0 = scene.impact.v0;
    let context = format!("{label}\n{why}");
    // The regime named is the estimate's.
    let fully_plastic = v0 >= onset.v_plastic;
    let yields = v0 >= onset.v_yield;
    assert_eq!(why.contains("p₀ ≥ 2.8·σ_y"), fully_plastic, "{context}");
    assert_eq!(why.starts_with("p₀ <"), !yields, "{context}");
    // The recommended law leads the fits, and was solved.
    let advice = &report.recommendation;
    assert_eq!(advice.fits[0], advice.model, "{context}");
    assert!(row(report, advice.model).error.is_none(), "{context}");
    // No permanent indentation is ever claimed without a given one.
    let dent_given = x_pl > 0.0 && !scene.assumed.plastic_indentation;
    assert!(!why.contains("permanent indentation"), "{context}");
    if !dent_given {
        assert_ne!(advice.model, ForceModel::Proposed, "{context}");
        assert!(!advice.fits.contains(&ForceModel::Proposed), "{context}");
        assert!(!why.contains("keeps a dent"), "{context}");
    }
    if scene.assumed.plastic_indentation && x_pl > 0.0 && yields {
        assert!(why.contains("was not given"), "{context}");
    }
    if scene.assumed.restitution && e < 1.0 {
        assert!(
            why.contains(&format!("e = {} was not given", short(e))),
            "{context}"
        );
    }
    if why.contains("elastic Hertz (eq 1) is the whole story") {
        assert_eq!(e, 1.0, "{context}");
    }
    // The body that yields, by its σ_y.
    if yields {
        let (s1, s2) = (
            scene.body1.material.yield_stress,
            scene.body2.material.yield_stress,
        );
        let said = if why.contains("of both bodies") {
            0
        } else if why.contains("of body 1, the ") {
            1
        } else if why.contains("of body 2, the ") {
            2
        } else {
            panic!("no yielding body named: {context}")
        };
        let softer = if s1 < s2 {
            1
        } else if s2 < s1 {
            2
        } else {
            0
        };
        assert_eq!(said, softer, "{context}");
        if softer > 0 {
            let body = if softer == 1 {
                &scene.body1
            } else {
                &scene.body2
            };
            assert!(
                why.contains(&format!("the {} ", body.material.name)),
                "{context}"
            );
        }
    }
    // Every "<law> realises e = A for e = B" against that law's row.
    for model in ForceModel::ALL {
        let claim = format!("{} realises e = ", model.label());
        let Some(shown) = number_after(why, &claim) else {
            continue;
        };
        let r = row(report, model);
        let e_out = r
            .e_out
            .unwrap_or_else(|| panic!("{model} unsolved: {context}"));
        assert!(
            same_restitution(shown, e_out),
            "{model}: {shown} beside {e_out}: {context}"
        );
        let rest = &why[why.find(&claim).unwrap() + claim.len()..];
        assert!(
            rest.starts_with(&format!("{shown} for e = {}", short(e))),
            "{context}"
        );
        let faithful = (e_out / e - 1.0).abs() <= 0.02;
        let sentence = rest.split(';').next().unwrap();
        assert_eq!(
            sentence.contains("not within"),
            !faithful,
            "{model} e_out {e_out} for {e}: {context}"
        );
        if let Some(x_res) = number_after(sentence, "leaves x_res = ") {
            assert!(r.x_residual.unwrap() > 0.0, "{context}");
            assert!(x_res != "0", "{context}");
        }
    }
    // "no χ(e) rule realises e": no row of the Hunt–Crossley family does.
    if why.contains("no χ(e) rule realises") {
        for r in &report.impacts {
            if r.model.spec().chi.is_some()
                && let Some(e_out) = r.e_out
            {
                assert!((e_out / e - 1.0).abs() > 0.02, "{}: {context}", r.model);
            }
        }
    }
    // Thornton's numbers against its row and elastic Hertz's estimate.
    let thornton_claim = format!(
        "{} (yield from σ_y, not from e) gives F_max = ",
        THORNTON.label()
    );
    match number_after(why, &thornton_claim) {
        Some(_) => {
            let r = row(report, THORNTON);
            let start = why.find(&thornton_claim).unwrap() + thornton_claim.len();
            let sentence = why[start..].split(';').next().unwrap();
            let f_shown = sentence.split(" and e = ").next().unwrap();
            assert!(same_force(f_shown, r.f_max.unwrap()), "{context}");
            let e_shown = number_after(sentence, " and e = ").unwrap();
            assert!(same_restitution(e_shown, r.e_out.unwrap()), "{context}");
            let hertz = number_after(sentence, "(elastic Hertz: F_max = ").unwrap();
            let hertz_unit = sentence
                .split("(elastic Hertz: F_max = ")
                .nth(1)
                .unwrap()
                .split(')')
                .next()
                .unwrap();
            assert!(
                same_force(hertz_unit, report.quasistatic.f_max),
                "{hertz}: {context}"
            );
            let faithful = (r.e_out.unwrap() / e - 1.0).abs() <= 0.02;
            assert_eq!(
                sentence.contains("not the scene's e"),
                !faithful,
                "{context}"
            );
        }
        // Once the contact yields, Thornton's law is checked (where it solves).
        None if yields && row(report, THORNTON).error.is_none() => {
            panic!("Thornton not checked: {context}")
        }
        None => {}
    }
    if fully_plastic && !dent_given && row(report, THORNTON).error.is_none() {
        assert_eq!(advice.model, THORNTON, "{context}");
    }
}

/// A restitution as the reason prints it.
fn short(e: f64) -> String {
    let text = format!("{e:.3}");
    text.trim_end_matches('0').trim_end_matches('.').to_string()
}

#[test]
fn every_sentence_of_the_recommendation_agrees_with_the_numbers_beside_it() {
    let registry = Registry::builtin().unwrap();
    let mut checked = 0;
    for preset in registry.scenes() {
        for v0 in ["0.02", "0.3", "2"] {
            for e in [None, Some("0.4"), Some("0.7"), Some("0.95"), Some("1")] {
                for x_pl in [None, Some("0"), Some("2.3e-6")] {
                    let mut sets = vec![format!("impact.v0={v0}")];
                    sets.extend(e.map(|e| format!("impact.restitution={e}")));
                    sets.extend(x_pl.map(|x| format!("impact.plastic_indentation={x}")));
                    let report = solve(&preset.name, &sets, &registry);
                    check(&report, &format!("{} {sets:?}", preset.name));
                    checked += 1;
                }
            }
        }
    }
    assert!(checked >= 7 * 45, "{checked}");
}

/// The question: a steel ball of 20 mm diameter at 1 m/s on a thick aluminium plate, e =
/// 0.7 asked. The preset's x_pl is Fig. 5's, not given: the advice does not rest on it, names the
/// aluminium plate as the body that yields, and checks Thornton's law.
#[test]
fn a_steel_ball_on_aluminium_is_not_advised_on_a_borrowed_dent() {
    let registry = Registry::builtin().unwrap();
    let sets = [
        "body2.material=aluminium-alloy".to_string(),
        "impact.restitution=0.7".to_string(),
    ];
    let report = solve("steel-sphere-r10-plate", &sets, &registry);
    let why = &report.recommendation.why;
    assert_ne!(report.recommendation.model, ForceModel::Proposed, "{why}");
    assert!(
        why.contains("of body 2, the aluminium-alloy plate"),
        "{why}"
    );
    assert!(why.contains("x_pl = 2.3 µm was not given"), "{why}");
    assert!(why.contains(THORNTON.label()), "{why}");
    assert!(!why.contains("e = 0.7 was not given"), "{why}");
    check(&report, "steel on aluminium");
}
