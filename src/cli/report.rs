//! `solve --format table`: the scene, the quasistatic estimate and the impacts as aligned text.

use crate::model::body::{Body, Shape};
use crate::model::quasistatic::ContactGeometry;
use crate::model::{Quasistatic, Scene};

use super::layout::columns;
use super::solve::{ImpactRow, SolveReport};
use super::units::{
    NOT_A_NUMBER, compact, compact_number, count, engineering, exact_number, scientific,
    significant,
};

/// The whole report as text.
pub fn render(report: &SolveReport) -> String {
    let mut out = String::new();
    out.push_str(&scene_section(&report.scene));
    out.push('\n');
    out.push_str(&quasistatic_section(
        &report.quasistatic,
        report.scene.impact.v0,
    ));
    out.push_str(&format!(
        "Recommended: {} — {}\n",
        report.recommendation.model, report.recommendation.why
    ));
    if !report.impacts.is_empty() {
        out.push('\n');
        out.push_str(&impact_section(&report.impacts));
    }
    if !report.warnings.is_empty() {
        out.push('\n');
        for w in &report.warnings {
            out.push_str(&format!("warning: {}\n", w.message));
        }
    }
    out
}

fn body_line(body: &Body) -> String {
    let m = &body.material;
    let geometry = match body.shape {
        Shape::Sphere { radius } => format!("sphere R = {}", compact(radius, "m")),
        Shape::Cylinder { radius, length } => format!(
            "cylinder R = {}, L = {}",
            compact(radius, "m"),
            compact(length, "m")
        ),
        Shape::Plane => "plane".to_string(),
    };
    let mass = match (body.mass, body.shape) {
        (Some(mass), _) => format!(", m = {}", compact(mass * 1e3, "g")),
        (None, Shape::Plane) => String::new(),
        (None, _) => format!(
            ", m = {} (from density)",
            engineering(body.mass() * 1e3, "g")
        ),
    };
    format!(
        "{geometry}{mass}; {} (E = {}, ν = {}, σy = {}, ρ = {} kg/m³)",
        m.name,
        compact(m.youngs_modulus, "Pa"),
        exact_number(m.poisson_ratio),
        compact(m.yield_stress, "Pa"),
        compact_number(m.density, 6)
    )
}

fn scene_section(scene: &Scene) -> String {
    let i = &scene.impact;
    let rows = vec![
        vec!["body1".to_string(), body_line(&scene.body1)],
        vec!["body2".to_string(), body_line(&scene.body2)],
        vec![
            "impact".to_string(),
            format!(
                "v0 = {}, e = {}{}, x_pl = {}{}",
                compact(i.v0, "m/s"),
                exact_number(i.restitution),
                assumed(scene.assumed.restitution),
                compact(i.plastic_indentation, "m"),
                assumed(scene.assumed.plastic_indentation)
            ),
        ],
    ];
    format!("Scene: {}\n{}", scene.name, columns(&rows, "  "))
}

/// Said after a value the scene's user did not give (a preset's stand-in).
fn assumed(is: bool) -> &'static str {
    if is { " (assumed)" } else { "" }
}

fn row(label: &str, value: String, note: &str) -> Vec<String> {
    vec![label.to_string(), value, note.to_string()]
}

fn quasistatic_section(q: &Quasistatic, v0: f64) -> String {
    let k_unit = format!("N/m^{}", compact_number(q.n, 4));
    let point = matches!(q.geometry, ContactGeometry::Point { .. });
    let (k_note, notes, p_note) = if point {
        ("F = k·x^1.5, eq 2", ["eq 5", "eq 6", "eq 7"], "eq 9")
    } else {
        let general = "fitted law, general n";
        ("F = k·xⁿ: the fitted a", [general; 3], "eq 12")
    };
    let mut rows = vec![
        row("η = η1 + η2", scientific(q.eta, "m²/N"), "eq 3"),
        row("k", scientific(q.k, &k_unit), k_note),
        row("n", significant(q.n, 4), ""),
        row(
            "reduced mass",
            engineering(q.reduced_mass * 1e3, "g"),
            "eq 4",
        ),
        row("x_max", engineering(q.x_max, "m"), notes[0]),
        row("F_max", engineering(q.f_max, "N"), notes[1]),
        row("contact time", engineering(q.t_contact, "s"), notes[2]),
        row("p0 at F_max", engineering(q.p_max, "Pa"), p_note),
    ];
    match q.geometry {
        ContactGeometry::Point { contact_radius } => {
            rows.push(row(
                "contact radius a",
                engineering(contact_radius, "m"),
                "eq 8",
            ));
        }
        ContactGeometry::Line { half_width, fit } => {
            rows.push(row("half-width b", engineering(half_width, "m"), "eq 11"));
            rows.push(row(
                "fit F = a·xⁿ + c",
                format!(
                    "a = {}, n = {}, c = {}",
                    scientific(fit.a, ""),
                    significant(fit.n, 4),
                    engineering(fit.c, "N")
                ),
                &format!(
                    "eq 13/14 over {} … {}, worst error {} %",
                    engineering(fit.f_min, "N"),
                    engineering(fit.f_max, "N"),
                    significant(fit.max_rel_error * 100.0, 2)
                ),
            ));
        }
    }
    let o = &q.onset;
    rows.extend([
        row(
            "v0y (p0 = 1.1 σy)",
            engineering(o.v_yield, "m/s"),
            "yield begins (paper: maximum pressure)",
        ),
        row(
            "v0p (p0 = 2.8 σy)",
            engineering(o.v_plastic, "m/s"),
            "full plasticity (paper)",
        ),
        row(
            "v0y (pm = 1.1 σy)",
            engineering(o.v_yield_mean_pressure, "m/s"),
            "textbook convention: mean pressure",
        ),
        row(
            "v0p (pm = 2.8 σy)",
            engineering(o.v_plastic_mean_pressure, "m/s"),
            "textbook convention: mean pressure",
        ),
        row(
            "wave limit",
            engineering(o.v_wave_limit, "m/s"),
            "10⁻⁵·√(E/ρ), conclusion",
        ),
    ]);
    let regime = match q.regime(v0) {
        crate::model::pressure::Regime::Elastic => "elastic: p0 < 1.1 σy",
        crate::model::pressure::Regime::YieldBegins => "yield begins: 1.1 σy ≤ p0 < 2.8 σy",
        crate::model::pressure::Regime::FullyPlastic => {
            "fully plastic: p0 ≥ 2.8 σy, Hertz no longer holds"
        }
    };
    rows.push(row("regime at v0", regime.to_string(), ""));
    format!("Quasistatic Hertz estimate\n{}", columns(&rows, "  "))
}

fn optional(value: Option<f64>, format: impl Fn(f64) -> String) -> String {
    value.map_or(NOT_A_NUMBER.to_string(), format)
}

fn impact_section(impacts: &[ImpactRow]) -> String {
    let mut rows = vec![
        [
            "model",
            "method",
            "x_max",
            "F_max",
            "t_contact",
            "v_out",
            "e_out",
            "damping",
            "x_residual",
            "dissipated",
            "energy err",
            "steps",
            "rejected",
            "F evals",
        ]
        .map(String::from)
        .to_vec(),
    ];
    let mut errors = String::new();
    for r in impacts {
        if let Some(error) = &r.error {
            rows.push(vec![
                r.model.to_string(),
                r.method.clone(),
                "failed (see below)".into(),
            ]);
            errors.push_str(&format!("  {}: {error}\n", r.model));
            continue;
        }
        rows.push(vec![
            r.model.to_string(),
            r.method.clone(),
            optional(r.x_max, |x| engineering(x, "m")),
            optional(r.f_max, |x| engineering(x, "N")),
            optional(r.t_contact, |x| engineering(x, "s")),
            optional(r.v_out, |x| engineering(x, "m/s")),
            optional(r.e_out, |x| significant(x, 4)),
            damping_cell(r),
            optional(r.x_residual, |x| engineering(x, "m")),
            optional(r.energy_dissipated, |x| engineering(x, "J")),
            optional(r.energy_residual, |x| scientific(x, "")),
            count(r.steps),
            count(r.rejected_steps),
            count(r.force_evals),
        ]);
    }
    let mut out = format!(
        "Impact (m·ẍ = −F from x = 0, ẋ = v0)\n{}",
        columns(&rows, "  ")
    );
    if !errors.is_empty() {
        out.push_str("Failures:\n");
        out.push_str(&errors);
    }
    let cutoffs: Vec<String> = impacts
        .iter()
        .filter_map(|r| {
            r.tensile_cutoff.map(|c| {
                format!(
                    "  {}: the force turned tensile at t = {}, x = {}: contact ended there\n",
                    r.model,
                    engineering(c.t, "s"),
                    engineering(c.x, "m")
                )
            })
        })
        .collect();
    if !cutoffs.is_empty() {
        out.push_str("Compressive-only rule:\n");
        out.push_str(&cutoffs.concat());
    }
    let calibration: Vec<String> = impacts
        .iter()
        .filter_map(|r| {
            r.calibration_error
                .as_ref()
                .map(|why| format!("  {why}: the scene's damping is shown\n"))
        })
        .collect();
    if !calibration.is_empty() {
        out.push_str("Not calibrated:\n");
        out.push_str(&calibration.concat());
    }
    out
}

/// `χ = 0.9749` (`*` when calibrated), or `-` for a law without damping.
fn damping_cell(r: &ImpactRow) -> String {
    r.damping.as_ref().map_or("-".into(), |d| {
        let unit = if d.unit == "1" {
            String::new()
        } else {
            format!(" {}", d.unit)
        };
        let mark = if r.calibrated {
            "*"
        } else if r.fitted {
            " (fit)"
        } else {
            ""
        };
        format!(
            "{} = {}{unit}{mark}",
            d.symbol,
            scientific_or_plain(d.value)
        )
    })
}

fn scientific_or_plain(x: f64) -> String {
    if x != 0.0 && !(1e-3..1e4).contains(&x.abs()) {
        scientific(x, "")
    } else {
        significant(x, 4)
    }
}
