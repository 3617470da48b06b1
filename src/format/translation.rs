//! A translation for one simulation engine as text: what the engine integrates, its parameters,
//! what it realises, the caveats, and last the fragments to paste. Shared by `hertz-tui translate`
//! and the explorer's engine panel.

use std::fmt::Write;

use crate::model::engine::Translation;

use super::{Zeros, engineering, significant};

/// The translation as text: what the engine integrates, its parameters, what it realises, the
/// caveats, and the fragments to paste (last, so they can be copied whole).
pub fn render(scene: &str, t: &Translation) -> String {
    let mut out = String::new();
    let r = &t.realised;
    let _ = writeln!(out, "{} — {scene}", t.name);
    let _ = writeln!(out, "source          {}", t.source);
    let _ = writeln!(out, "engine law      {}", t.law);
    let _ = writeln!(out, "as hertz-tui    {}", t.hertz_tui_law);
    let _ = writeln!(out, "end of contact  {}", t.end_rule.describe());
    if let Some(approximation) = &t.approximation {
        let _ = writeln!(out, "approximation   {approximation}");
    }
    let _ = writeln!(out, "\nParameters");
    for p in &t.parameters {
        let unit = if p.unit.is_empty() {
            String::new()
        } else {
            format!(" {}", p.unit)
        };
        let _ = writeln!(out, "  {} = {}{unit}\n      {}", p.name, p.text(), p.rule);
    }
    let _ = writeln!(
        out,
        "\nWhat the engine gives at v₀ = {}",
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
        (
            "stable explicit step",
            format!(
                "{} (h·ω_max < 2, undamped)",
                engineering(r.dt_stable, "s", 4, Zeros::Trim)
            ),
        ),
    ];
    for (label, value) in rows {
        let _ = writeln!(out, "  {label:<21} {value}");
    }
    let _ = writeln!(out, "\ne_out against v₀ (same parameters)");
    for p in &t.e_of_v {
        let _ = writeln!(
            out,
            "  {:>12}  {}",
            engineering(p.v0, "m/s", 4, Zeros::Trim),
            significant(p.e_out, 6, Zeros::Trim)
        );
    }
    if !t.notes.is_empty() {
        let _ = writeln!(out, "\nNotes");
        for note in &t.notes {
            let _ = writeln!(out, "  - {note}");
        }
    }
    for fragment in &t.fragments {
        let _ = writeln!(
            out,
            "\n{} ({}):\n{}",
            fragment.title, fragment.language, fragment.text
        );
    }
    out
}
