//! A translation for one simulation engine as text: what the engine integrates, the regime
//! warnings, its parameters, what its law gives, the time step and what the engine realises there,
//! the caveats and versions, and last the script to run (or the fragments, for an engine with no
//! script). Shared by `hertz-tui translate` and the explorer's engine panel.

use std::fmt::Write;

use crate::model::engine::run::{Claim, StepChoice};
use crate::model::engine::{EngineRun, Translation};

use super::{Zeros, engineering, significant};

/// The translation with its run as text; the script (or the fragments) last, so it can be copied
/// whole.
pub fn render_run(scene: &str, t: &EngineRun) -> String {
    let mut out = String::new();
    let tr = &t.translation;
    header(&mut out, scene, tr);
    if !t.warnings.is_empty() {
        let _ = writeln!(out, "\nWarnings: what the engine's law cannot do here");
        for w in &t.warnings {
            let _ = writeln!(out, "  ! {w}");
        }
    }
    parameters(&mut out, tr);
    realised(&mut out, tr);
    let _ = writeln!(out, "\nTime step and what the engine gives");
    claim(&mut out, "", &t.run.claim);
    for (how, other) in &t.run.other_claims {
        claim(&mut out, &format!("{how}: "), other);
    }
    velocity_table(&mut out, tr);
    if !tr.notes.is_empty() {
        let _ = writeln!(out, "\nNotes");
        for note in &tr.notes {
            let _ = writeln!(out, "  - {note}");
        }
    }
    let _ = writeln!(out, "\nVersions");
    let _ = writeln!(out, "  - {}", t.run.checked());
    for v in &t.run.versions {
        let _ = writeln!(out, "  - {v}");
    }
    match &t.run.script {
        Some(script) => {
            let _ = writeln!(
                out,
                "\nScript ({}; save as {} or write it with --script {}, run: {}):\n{}",
                script.language,
                script.file,
                script.file,
                script.command,
                script.text.trim_end()
            );
        }
        None => {
            if let Some(why) = &t.run.no_script {
                let _ = writeln!(out, "\nNo script: {why}");
            }
            for fragment in &tr.fragments {
                let _ = writeln!(
                    out,
                    "\n{} ({}):\n{}",
                    fragment.title, fragment.language, fragment.text
                );
            }
        }
    }
    out
}

fn header(out: &mut String, scene: &str, t: &Translation) {
    let _ = writeln!(out, "{} — {scene}", t.name);
    let _ = writeln!(out, "source          {}", t.source);
    let _ = writeln!(out, "engine law      {}", t.law);
    let _ = writeln!(out, "as hertz-tui    {}", t.hertz_tui_law);
    let _ = writeln!(out, "end of contact  {}", t.end_rule.describe());
    if let Some(approximation) = &t.approximation {
        let _ = writeln!(out, "approximation   {approximation}");
    }
}

fn parameters(out: &mut String, t: &Translation) {
    let _ = writeln!(out, "\nParameters");
    for p in &t.parameters {
        let unit = if p.unit.is_empty() {
            String::new()
        } else {
            format!(" {}", p.unit)
        };
        let _ = writeln!(out, "  {} = {}{unit}\n      {}", p.name, p.text(), p.rule);
    }
}

fn realised(out: &mut String, t: &Translation) {
    let r = &t.realised;
    let _ = writeln!(
        out,
        "\nWhat the engine's law gives at v₀ = {} (continuous time)",
        engineering(t.v0, "m/s", 4, Zeros::Trim)
    );
    let rows = [
        (
            "e_out",
            format!(
                "{} (requested {})",
                significant(r.e_out, 10, Zeros::Trim),
                significant(t.e_requested, 10, Zeros::Trim)
            ),
        ),
        ("F_max", engineering(r.f_max, "N", 4, Zeros::Trim)),
        (
            "contact time",
            engineering(r.t_contact, "s", 4, Zeros::Trim),
        ),
        ("x_max", engineering(r.x_max, "m", 4, Zeros::Trim)),
        (
            "x at separation",
            engineering(r.x_residual, "m", 4, Zeros::Trim),
        ),
    ];
    for (label, value) in rows {
        let _ = writeln!(out, "  {label:<21} {value}");
    }
}

fn claim(out: &mut String, prefix: &str, claim: &Claim) {
    match claim {
        Claim::Continuous {
            integrator,
            tolerance,
        } => {
            let _ = writeln!(
                out,
                "  {prefix}no fixed step: {integrator}; the engine gives the numbers above, e within {} (relative)",
                significant(*tolerance, 2, Zeros::Trim)
            );
        }
        Claim::Stepped(choice) => stepped(out, prefix, choice),
        Claim::ContinuousOnly { reason } => {
            let _ = writeln!(
                out,
                "  {prefix}only the continuous limit above is claimed: {reason}"
            );
        }
    }
}

fn stepped(out: &mut String, prefix: &str, c: &StepChoice) {
    let s = &c.at_step;
    let _ = writeln!(
        out,
        "  {prefix}step {} (t_c/{}), the largest that keeps e, F_max and contact time within {} %\n      of the law's, in hertz-tui's model of the engine's {}",
        engineering(c.step, "s", 4, Zeros::Trim),
        significant(c.steps_per_contact, 4, Zeros::Trim),
        significant(c.tolerance * 100.0, 3, Zeros::Trim),
        c.scheme.describe()
    );
    let _ = writeln!(
        out,
        "      at that step: e_out {}, F_max {}, contact time {}",
        significant(s.e_out, 6, Zeros::Trim),
        engineering(s.f_max, "N", 4, Zeros::Trim),
        engineering(s.t_contact, "s", 4, Zeros::Trim)
    );
}

fn velocity_table(out: &mut String, t: &Translation) {
    let _ = writeln!(out, "\ne_out against v₀ (same parameters, continuous time)");
    for p in &t.e_of_v {
        let _ = writeln!(
            out,
            "  {:>12}  {}",
            engineering(p.v0, "m/s", 4, Zeros::Trim),
            significant(p.e_out, 6, Zeros::Trim)
        );
    }
}
