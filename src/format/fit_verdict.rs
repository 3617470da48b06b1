//! A restitution fit's ranking in words, with its numbers, for the command line and the explorer
//! alike: the verdict (which law, how well supported, which laws the data cannot tell apart) and
//! the cells of a fitted parameter.

use crate::model::fit::{LawFit, Verdict};

use super::{Zeros, significant};

/// A number for tables: 4 significant digits, never NaN (`-` where undetermined).
pub fn num(x: f64) -> String {
    if x.is_finite() {
        significant(x, 4, Zeros::Keep)
    } else if x.is_nan() {
        "-".to_string()
    } else {
        "∞".to_string()
    }
}

/// A measured or stated number: 4 significant digits, trailing zeros dropped.
pub fn given(x: f64) -> String {
    significant(x, 4, Zeros::Trim)
}

/// `a = 1.203 s/m` with its interval `[1.18, 1.23]`; several parameters joined by `; `.
pub fn parameter_cells(fit: &LawFit) -> (String, String) {
    let mut values = Vec::new();
    let mut cis = Vec::new();
    for p in &fit.params {
        let unit = if p.spec.unit == "1" {
            String::new()
        } else {
            format!(" {}", p.spec.unit)
        };
        values.push(format!("{} = {}{unit}", p.spec.symbol, num(p.value)));
        cis.push(if p.ci.0.is_finite() && p.ci.1.is_finite() {
            format!("[{}, {}]", num(p.ci.0), num(p.ci.1))
        } else {
            "undetermined".to_string()
        });
    }
    (values.join("; "), cis.join("; "))
}

/// The verdict in plain words, with its numbers (`trace`: the unit of a trace's values, whose
/// noise is in it and whose range is no velocity range).
pub fn verdict_words(v: &Verdict, trace: Option<&str>) -> String {
    let c = v.criterion.name();
    let mut out = if let Some(unit) = trace {
        format!(
            "Best: {} by {c} (Akaike weight {}), noise {} {unit}.",
            v.best,
            significant(v.best_weight, 3, Zeros::Keep),
            given(v.noise)
        )
    } else {
        format!(
            "Best: {} by {c} (Akaike weight {}) over v0 = {} to {} m/s, noise {}.",
            v.best,
            significant(v.best_weight, 3, Zeros::Keep),
            given(v.v_range.0),
            given(v.v_range.1),
            given(v.noise)
        )
    };
    match v.runner_up {
        Some((next, delta)) => out.push_str(&format!(
            "\nNext distinguishable: {next}, Δ{c} = {}: {}.",
            num(delta),
            support(delta)
        )),
        None => out.push_str("\nNo other law fitted is distinguishable from it."),
    }
    for group in &v.groups {
        let members: Vec<&str> = group.members.iter().map(|c| c.id()).collect();
        out.push_str(&format!(
            "\nThe data cannot tell apart {}: their e(v) differ by at most {} over the data, within the noise {} (Δ{c} up to {})",
            members.join(", "),
            num(group.max_gap),
            given(group.noise),
            num(group.max_delta)
        ));
        if !group.identical.is_empty() {
            let same: Vec<&str> = group.identical.iter().map(|c| c.id()).collect();
            out.push_str(&format!(
                "; {} the same e(v) as {} on any data",
                same.join(", "),
                members[0]
            ));
        }
        out.push('.');
    }
    out
}

/// Burnham & Anderson's reading of a Δ (Model Selection and Multimodel Inference, 2002, §2.6).
fn support(delta: f64) -> &'static str {
    if delta <= 2.0 {
        "about as well supported"
    } else if delta <= 7.0 {
        "considerably less supported"
    } else if delta <= 10.0 {
        "much less supported"
    } else {
        "essentially no support"
    }
}
