//! The fit's verdict ([`crate::model::fit::Verdict`]) in plain words with its numbers, for the
//! command line, the explorer and figures alike: which law the data supports, by how much, and
//! which laws the data cannot tell apart.

use crate::model::fit::{Candidate, FitReport, Indistinguishable, LawFit};

use super::{Zeros, significant};

/// A number with `digits` significant digits, trailing zeros trimmed.
fn num(value: f64, digits: usize) -> String {
    significant(value, digits, Zeros::Trim)
}

/// `a = 0.2 s/m (95 % CI 0.19–0.21)` for every parameter of a fit.
pub fn parameters(fit: &LawFit) -> String {
    fit.params
        .iter()
        .map(|p| {
            let unit = if p.spec.unit == "1" {
                String::new()
            } else {
                format!(" {}", p.spec.unit)
            };
            format!(
                "{} = {}{unit} ({} % CI {}–{})",
                p.spec.symbol,
                num(p.value, 4),
                num(100.0 * p.level, 3),
                num(p.ci.0, 3),
                num(p.ci.1, 3)
            )
        })
        .collect::<Vec<_>>()
        .join(", ")
}

/// `a, b and c`.
fn list(members: &[Candidate]) -> String {
    let ids: Vec<&str> = members.iter().map(|c| c.id()).collect();
    match ids.as_slice() {
        [] => String::new(),
        [one] => (*one).to_string(),
        [init @ .., last] => format!("{} and {last}", init.join(", ")),
    }
}

/// One sentence on a group the data cannot tell apart.
fn group(report: &FitReport, g: &Indistinguishable) -> String {
    let name = report.criterion.name();
    let (lo, hi) = report.verdict.v_range;
    let mut s = format!(
        "The data cannot tell {} apart: Δ{name} ≤ {}{} and their curves differ by at most {} over v = {}–{} m/s, against a noise of {}.",
        list(&g.members),
        num(g.max_delta.max(0.0), 2),
        if g.max_delta < 2.0 { " (< 2)" } else { "" },
        num(g.max_gap, 2),
        num(lo, 3),
        num(hi, 3),
        num(g.noise, 2),
    );
    if !g.identical.is_empty() {
        s.push_str(&format!(
            " {} {} the same e(v) as {} on any data.",
            list(&g.identical),
            if g.identical.len() == 1 { "is" } else { "are" },
            g.members[0].id()
        ));
    }
    s
}

/// The verdict in words: the best law with its parameters and weight, the runner-up's Δ, and
/// every group the data cannot tell apart.
pub fn verdict_text(report: &FitReport) -> String {
    let v = &report.verdict;
    let name = report.criterion.name();
    let Some(best) = report.fits.first() else {
        return "No law could be fitted.".into();
    };
    let mut out = format!(
        "Best by {name}: {}, {} (Akaike weight {}).",
        best.candidate.id(),
        parameters(best),
        num(v.best_weight, 2)
    );
    if let Some((runner, delta)) = v.runner_up {
        out.push_str(&format!(
            " Next distinguishable: {} at Δ{name} = {}{}.",
            runner.id(),
            num(delta, 3),
            if delta > 10.0 {
                ", essentially no support"
            } else {
                ""
            }
        ));
    }
    for g in &v.groups {
        out.push(' ');
        out.push_str(&group(report, g));
    }
    out
}
