//! Sweep rows as chart lines: the chosen output against the swept value, one line per model (or
//! one for the quasistatic estimate), broken where a point failed rather than bridged.

use crate::model::ForceModel;
use crate::model::study::sweep::SweepRow;

use crate::chart::{Chart, Ink, Rule, Series, model_glyph};
use crate::model::scene_key::SceneKey;

use super::studies::SweepData;
use super::sweep_settings::{SweepOutput, key_symbol, key_unit};
use super::ticks::{NiceAxis, log_axis, nice_axis};
use super::units::{self, Unit};

/// Whose line it is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LineOf {
    /// The quasistatic (Hertz) estimate.
    Estimate,
    Model(ForceModel),
}

/// One line in SI units, as runs of consecutive valid points.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepLine {
    pub of: LineOf,
    pub runs: Vec<Vec<(f64, f64)>>,
}

fn runs(rows: &[SweepRow], value: impl Fn(&SweepRow) -> Option<f64>) -> Vec<Vec<(f64, f64)>> {
    let mut runs: Vec<Vec<(f64, f64)>> = Vec::new();
    let mut run = Vec::new();
    for row in rows {
        match value(row).filter(|v| v.is_finite()) {
            Some(v) => run.push((row.value, v)),
            None if !run.is_empty() => runs.push(std::mem::take(&mut run)),
            None => {}
        }
    }
    if !run.is_empty() {
        runs.push(run);
    }
    runs
}

/// The lines of `output` over the sweep.
pub fn lines(data: &SweepData, output: SweepOutput) -> Vec<SweepLine> {
    if !output.per_model() {
        return vec![SweepLine {
            of: LineOf::Estimate,
            runs: runs(&data.rows, |row| output.estimate(row)),
        }];
    }
    data.spec
        .models
        .iter()
        .map(|&model| SweepLine {
            of: LineOf::Model(model),
            runs: runs(&data.rows, |row| output.of_model(row, model)),
        })
        .collect()
}

/// The yield-onset velocities (v_y, v_p) of the swept scene: they do not depend on v₀.
pub fn onset(data: &SweepData) -> Option<(f64, f64)> {
    data.rows
        .iter()
        .find_map(|r| r.quasistatic.map(|q| (q.v_yield, q.v_plastic)))
}

impl LineOf {
    /// The line's name, ink and glyph.
    pub fn look(self) -> (String, Ink, char) {
        match self {
            LineOf::Estimate => ("Hertz estimate".to_string(), Ink::Foreground, 'o'),
            LineOf::Model(m) => (m.name().to_string(), Ink::Model(m), model_glyph(m)),
        }
    }
}

fn axis(lo: f64, hi: f64, unit: Unit, log: bool, max_labels: usize) -> NiceAxis {
    if log {
        log_axis(lo, hi, unit, max_labels)
    } else {
        nice_axis(lo, hi, unit, max_labels)
    }
}

/// `symbol [unit]`, or the bare symbol of a dimensionless quantity.
fn axis_title(symbol: &str, axis: &NiceAxis, unit: Unit) -> String {
    let text = format!("{}{}", axis.prefix.symbol, unit.symbol);
    if text.is_empty() {
        symbol.to_string()
    } else {
        format!("{symbol} [{text}]")
    }
}

/// The sweep chart of `output`, with at most `max_x` × `max_y` tick labels; `focused` is drawn
/// last and bold. A v₀ sweep gets the yield-onset velocities as rules.
pub fn chart(
    data: &SweepData,
    output: SweepOutput,
    focused: Option<ForceModel>,
    (max_x, max_y): (usize, usize),
) -> Chart {
    let spec = &data.spec;
    let lines = lines(data, output);
    let x_unit = key_unit(spec.key);
    let y_unit = output.unit();
    let (lo, hi) = (spec.from.min(spec.to), spec.from.max(spec.to));
    let x = axis(lo, hi, x_unit, spec.log, max_x);
    // The y axis includes 0, as the explorer's do: outputs are sizes, times, speeds, ratios.
    let (mut y_lo, mut y_hi) = (0.0f64, 0.0f64);
    for (_, v) in lines.iter().flat_map(|l| l.runs.iter().flatten()) {
        y_lo = y_lo.min(*v);
        y_hi = y_hi.max(*v);
    }
    let y = nice_axis(y_lo, y_hi, y_unit, max_y);
    let to_display = |(px, py): &(f64, f64)| (x.to_display(*px), y.to_display(*py));
    let mut series: Vec<Series> = lines
        .iter()
        .map(|line| {
            let (name, ink, glyph) = line.of.look();
            Series {
                name,
                ink,
                glyph,
                runs: line
                    .runs
                    .iter()
                    .map(|run| run.iter().map(to_display).collect())
                    .collect(),
                focused: matches!(line.of, LineOf::Model(m) if Some(m) == focused),
                peak: None,
                steps: false,
            }
        })
        .collect();
    series.sort_by_key(|s| s.focused);
    let mut rules = Vec::new();
    if spec.key == SceneKey::V0
        && let Some((v_yield, v_plastic)) = onset(data)
    {
        rules.push(Rule {
            x: x.to_display(v_yield),
            ink: Ink::Warning,
            label: "v_y".into(),
        });
        rules.push(Rule {
            x: x.to_display(v_plastic),
            ink: Ink::Error,
            label: "v_p".into(),
        });
    }
    let symbol = key_symbol(spec.key);
    Chart {
        title: format!(
            "{} against {} · {} points, {}",
            output.symbol(),
            symbol,
            spec.points,
            if spec.log { "log" } else { "linear" }
        ),
        x: x.chart_axis(axis_title(&symbol, &x, x_unit)),
        y: y.chart_axis(axis_title(output.symbol(), &y, y_unit)),
        series,
        marks: Vec::new(),
        rules,
        notes: Vec::new(),
    }
}

/// The onset velocities as a note: `v_y = … yield begins …, v_p = … fully plastic …`.
pub fn onset_note(v_yield: f64, v_plastic: f64) -> String {
    format!(
        "v_y = {} yield begins (p₀ = 1.1·σ_y), v_p = {} fully plastic (2.8·σ_y)",
        units::engineering(v_yield, units::METRE_PER_SECOND, 3),
        units::engineering(v_plastic, units::METRE_PER_SECOND, 3)
    )
}

/// How many points (or model solves) failed, and the first reason.
pub fn failures(data: &SweepData) -> Option<(usize, String)> {
    let mut count = 0;
    let mut first = None;
    for row in &data.rows {
        let reasons = row
            .error
            .iter()
            .chain(row.impacts.iter().filter_map(|p| p.error.as_ref()));
        for reason in reasons {
            count += 1;
            first.get_or_insert_with(|| reason.clone());
        }
    }
    first.map(|reason| (count, reason))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::impact::SolveOptions;
    use crate::model::scene_key::SceneKey;
    use crate::model::study::sweep::{ImpactPoint, QuasistaticPoint, SweepSpec};

    fn point(model: ForceModel, e_out: Option<f64>) -> ImpactPoint {
        ImpactPoint {
            model,
            x_max: e_out,
            f_max: e_out,
            t_contact: e_out,
            v_out: e_out,
            e_out,
            error: e_out.is_none().then(|| "no separation".to_string()),
        }
    }

    fn row(value: f64, e_out: Option<f64>) -> SweepRow {
        SweepRow {
            value,
            quasistatic: Some(QuasistaticPoint {
                p_max: value * 10.0,
                contact_radius: Some(1e-4),
                half_width: None,
                v_yield: 0.03,
                v_plastic: 0.3,
            }),
            impacts: vec![point(ForceModel::Proposed, e_out)],
            error: None,
        }
    }

    fn data() -> SweepData {
        SweepData {
            spec: SweepSpec {
                key: SceneKey::V0,
                from: 0.1,
                to: 0.5,
                points: 5,
                log: false,
                models: vec![ForceModel::Proposed],
                options: SolveOptions::default(),
            },
            rows: vec![
                row(0.1, Some(0.9)),
                row(0.2, Some(0.8)),
                row(0.3, None),
                row(0.4, Some(f64::NAN)),
                row(0.5, Some(0.6)),
            ],
        }
    }

    #[test]
    fn failed_points_break_the_line() {
        let d = data();
        let lines = lines(&d, SweepOutput::EOut);
        assert_eq!(lines.len(), 1);
        assert_eq!(lines[0].of, LineOf::Model(ForceModel::Proposed));
        assert_eq!(
            lines[0].runs,
            [vec![(0.1, 0.9), (0.2, 0.8)], vec![(0.5, 0.6)]]
        );
        assert_eq!(failures(&d), Some((1, "no separation".to_string())));
        assert_eq!(onset(&d), Some((0.03, 0.3)));
    }

    #[test]
    fn estimates_are_one_line_for_all_models() {
        let lines = lines(&data(), SweepOutput::PeakPressure);
        assert_eq!(lines.len(), 1);
        assert_eq!(lines[0].of, LineOf::Estimate);
        assert_eq!(lines[0].runs[0].len(), 5);
        assert!((lines[0].runs[0][2].1 - 3.0).abs() < 1e-12);
    }
}
