//! The stability view's charts: each fixed-step method at the chosen step, its step points
//! marked, under the reference drawn on top (so a method that tracks it shows as the reference's
//! line with the method's steps on it, and one that departs shows beside it).

use crate::chart::kind::ChartKind;
use crate::chart::sample::{Look, Series, plot};
use crate::chart::{Chart, Ink, REFERENCE_GLYPH, method_glyph};
use crate::format::units::sig;
use crate::model::ode::Method;
use crate::model::study::runner::{MethodRun, StabilityData};
use crate::model::study::stability::Verdict;

/// Whose curve: the reference or a fixed-step method.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Curve {
    Reference,
    Method(Method),
}

/// Step points are marked one by one up to this many a curve; more would cover the line.
const MAX_MARKED_STEPS: usize = 60;

/// The step points of a fixed-step run: every dt from first contact and again from maximum
/// compression, where the solver starts its second phase.
fn step_samples(run: &MethodRun) -> Option<Series<Curve>> {
    let solution = run.run.solution.as_ref()?;
    let dt = run.run.dt;
    let s = &solution.summary;
    let end = solution.trajectory.t_end();
    let steps = (end / dt).ceil();
    if dt <= 0.0 || !steps.is_finite() || steps as usize > MAX_MARKED_STEPS {
        return None;
    }
    let mut times: Vec<f64> = (0..)
        .map(|k| f64::from(k) * dt)
        .take_while(|&t| t < s.t_x_max)
        .collect();
    times.extend(
        (0..)
            .map(|k| s.t_x_max + f64::from(k) * dt)
            .take_while(|&t| t < end),
    );
    times.push(end);
    let mut series = Series::sample(Curve::Method(run.run.method), solution, 2);
    series.samples = times.iter().map(|&t| solution.trajectory.at(t)).collect();
    Some(series)
}

/// The chart of `kind` with at most `max_x` × `max_y` tick labels: the methods that finished
/// (their step points marked where few), the reference last, and why the others have no curve.
pub fn chart(
    data: &StabilityData,
    kind: ChartKind,
    columns: u16,
    (max_x, max_y): (usize, usize),
) -> Chart {
    let n = 2 * usize::from(columns).max(50);
    let mut series = Vec::new();
    let mut stepped = Vec::new();
    for r in &data.runs {
        let Some(solution) = r.run.solution.as_ref() else {
            continue;
        };
        match step_samples(r) {
            Some(steps) => {
                // The straight segments between steps are what the method computed: drawn as
                // such, each step marked.
                stepped.push(r.run.method);
                series.push(steps);
            }
            None => series.push(Series::sample(Curve::Method(r.run.method), solution, n)),
        }
    }
    series.push(Series::sample(Curve::Reference, &data.reference, n));
    let drawn = data
        .runs
        .iter()
        .filter(|r| r.run.solution.is_some())
        .count();
    let title = format!(
        "{} · {drawn} of {} methods drawn",
        kind.title(),
        data.runs.len()
    );
    let mut chart = plot(kind, &series, max_x, max_y).into_chart(title, |c| match c {
        Curve::Reference => Look {
            name: "reference".to_string(),
            ink: Ink::Foreground,
            glyph: REFERENCE_GLYPH,
            focused: true,
            steps: false,
        },
        Curve::Method(m) => Look {
            name: m.to_string(),
            ink: Ink::Method(m),
            glyph: method_glyph(m),
            focused: false,
            steps: stepped.contains(&m),
        },
    });
    chart.notes = data
        .runs
        .iter()
        .filter(|r| r.run.solution.is_none())
        .map(|r| match &r.run.verdict {
            Verdict::Diverged { t, .. } => format!(
                "✗ {}: diverged at t = {}",
                r.run.method,
                crate::format::units::engineering(*t, crate::format::units::SECOND, 3)
            ),
            Verdict::Failed { reason } => format!("✗ {}: {reason}", r.run.method),
            _ => format!("✗ {}: no curve", r.run.method),
        })
        .collect();
    chart
}

/// The headline errors of a run against the reference, signed, in full and short:
/// (`x_max −3 % · F_max −57 % · v_out +12 %`, `x −3% F −57% v +12%`).
pub fn errors_text(run: &MethodRun, data: &StabilityData) -> Option<(String, String)> {
    let s = &run.run.solution.as_ref()?.summary;
    let r = &data.reference.summary;
    let signed = |value: f64, reference: f64, gap: &str| {
        let e = (value - reference) / reference.abs().max(f64::MIN_POSITIVE) * 100.0;
        format!("{}{}{gap}%", if e >= 0.0 { "+" } else { "" }, sig(e, 2))
    };
    let full = format!(
        "x_max {} · F_max {} · v_out {}",
        signed(s.x_max, r.x_max, " "),
        signed(s.f_max, r.f_max, " "),
        signed(s.v_out, r.v_out, " ")
    );
    let short = format!(
        "x {} F {} v {}",
        signed(s.x_max, r.x_max, ""),
        signed(s.f_max, r.f_max, ""),
        signed(s.v_out, r.v_out, "")
    );
    Some((full, short))
}
