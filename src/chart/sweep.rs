//! Sweep rows as chart lines: the chosen output against the swept value, one line per model (or
//! one for the quasistatic estimate), broken where a point failed rather than bridged.

use crate::chart::ticks::{NiceAxis, log_axis, nice_axis};
use crate::chart::{Chart, Hue, Ink, Rule, Series, model_glyph};
use crate::format::units::{self, Unit, key_symbol, key_unit};
use crate::model::ForceModel;
use crate::model::scene_key::SceneKey;
use crate::model::study::runner::SweepData;
use crate::model::study::sweep::SweepRow;

/// What the sweep chart draws against the parameter.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SweepOutput {
    /// Maximum contact pressure p₀ of the quasistatic estimate (the paper's Fig. 2).
    PeakPressure,
    /// Contact radius (point contact) or half-width (line contact) of the estimate.
    ContactSize,
    XMax,
    FMax,
    TContact,
    VOut,
    EOut,
}

impl SweepOutput {
    pub const ALL: [SweepOutput; 7] = [
        SweepOutput::PeakPressure,
        SweepOutput::ContactSize,
        SweepOutput::XMax,
        SweepOutput::FMax,
        SweepOutput::TContact,
        SweepOutput::VOut,
        SweepOutput::EOut,
    ];

    /// The symbol on the axis and in the form.
    pub fn symbol(self) -> &'static str {
        match self {
            SweepOutput::PeakPressure => "p₀",
            SweepOutput::ContactSize => "a | b",
            SweepOutput::XMax => "x_max",
            SweepOutput::FMax => "F_max",
            SweepOutput::TContact => "t_c",
            SweepOutput::VOut => "v_out",
            SweepOutput::EOut => "e_out",
        }
    }

    /// What it is, for the form.
    pub fn description(self) -> &'static str {
        match self {
            SweepOutput::PeakPressure => "max pressure (Hertz)",
            SweepOutput::ContactSize => "contact radius | half-width",
            SweepOutput::XMax => "max approach",
            SweepOutput::FMax => "max force",
            SweepOutput::TContact => "contact time",
            SweepOutput::VOut => "exit speed",
            SweepOutput::EOut => "realized restitution",
        }
    }

    pub fn unit(self) -> Unit {
        match self {
            SweepOutput::PeakPressure => units::PASCAL,
            SweepOutput::ContactSize | SweepOutput::XMax => units::METRE,
            SweepOutput::FMax => units::NEWTON,
            SweepOutput::TContact => units::SECOND,
            SweepOutput::VOut => units::METRE_PER_SECOND,
            SweepOutput::EOut => units::DIMENSIONLESS,
        }
    }

    /// Whether each model has its own value (else the quasistatic estimate has one per point).
    pub fn per_model(self) -> bool {
        !matches!(self, SweepOutput::PeakPressure | SweepOutput::ContactSize)
    }

    /// The quasistatic value at a row.
    pub fn estimate(self, row: &SweepRow) -> Option<f64> {
        let q = row.quasistatic.as_ref()?;
        match self {
            SweepOutput::PeakPressure => Some(q.p_max),
            SweepOutput::ContactSize => q.contact_radius.or(q.half_width),
            _ => None,
        }
    }

    /// The value of `model` at a row.
    pub fn of_model(self, row: &SweepRow, model: ForceModel) -> Option<f64> {
        let point = row.impacts.iter().find(|p| p.model == model)?;
        match self {
            SweepOutput::XMax => point.x_max,
            SweepOutput::FMax => point.f_max,
            SweepOutput::TContact => point.t_contact,
            SweepOutput::VOut => point.v_out,
            SweepOutput::EOut => point.e_out,
            SweepOutput::PeakPressure | SweepOutput::ContactSize => None,
        }
    }
}

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

/// One sweep on a chart: its data, and a name where several scenes share the chart (each then
/// drawn in its own hue and glyph).
pub struct SweepSet<'a> {
    pub name: Option<String>,
    pub data: &'a SweepData,
    /// σ_y of the pair: p₀ charts get the 1.1·σ_y (yield begins) and 2.8·σ_y (fully plastic)
    /// levels as horizontal rules, as the paper's Fig. 2 draws them.
    pub yield_stress: Option<f64>,
}

/// Hues and glyphs of the scenes after the first on a shared chart.
const SCENE_LOOKS: [(Hue, char); 5] = [
    (Hue::Blue, '+'),
    (Hue::Red, 'x'),
    (Hue::Green, '#'),
    (Hue::Magenta, '%'),
    (Hue::Cyan, '@'),
];

/// The sweep chart of `output` over `sets` (all sweeping the same key), with at most
/// `max_x` × `max_y` tick labels; `focused` is drawn last and bold. A v₀ sweep of one scene gets
/// the yield-onset velocities as vertical rules.
pub fn chart(
    sets: &[SweepSet],
    output: SweepOutput,
    focused: Option<ForceModel>,
    (max_x, max_y): (usize, usize),
) -> Chart {
    let Some(first) = sets.first() else {
        return Chart::new(
            String::new(),
            nice_axis(0.0, 1.0, units::DIMENSIONLESS, 2).chart_axis(String::new()),
            nice_axis(0.0, 1.0, units::DIMENSIONLESS, 2).chart_axis(String::new()),
            Vec::new(),
        );
    };
    let spec = &first.data.spec;
    let x_unit = key_unit(spec.key);
    let y_unit = output.unit();
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for set in sets {
        let s = &set.data.spec;
        lo = lo.min(s.from.min(s.to));
        hi = hi.max(s.from.max(s.to));
    }
    let x = axis(lo, hi, x_unit, spec.log, max_x);
    let per_set: Vec<Vec<SweepLine>> = sets.iter().map(|s| lines(s.data, output)).collect();
    let levels: Vec<(usize, f64, &str)> = sets
        .iter()
        .enumerate()
        .filter(|_| output == SweepOutput::PeakPressure)
        .filter_map(|(i, s)| s.yield_stress.map(|sy| (i, sy)))
        .flat_map(|(i, sy)| [(i, 1.1 * sy, "1.1·σ_y"), (i, 2.8 * sy, "2.8·σ_y")])
        .collect();
    // The y axis includes 0, as the explorer's do: outputs are sizes, times, speeds, ratios.
    let (mut y_lo, mut y_hi) = (0.0f64, 0.0f64);
    let values = per_set
        .iter()
        .flatten()
        .flat_map(|l| l.runs.iter().flatten().map(|p| p.1))
        .chain(levels.iter().map(|l| l.1));
    for v in values {
        y_lo = y_lo.min(v);
        y_hi = y_hi.max(v);
    }
    let y = nice_axis(y_lo, y_hi, y_unit, max_y);
    let to_display = |(px, py): &(f64, f64)| (x.to_display(*px), y.to_display(*py));
    let look_of = |i: usize, of: LineOf| {
        let (name, ink, glyph) = of.look();
        match (&sets[i].name, i) {
            (None, _) => (name, ink, glyph),
            (Some(scene), 0) => (format!("{scene}: {name}"), ink, glyph),
            (Some(scene), _) => {
                let (hue, glyph) = SCENE_LOOKS[(i - 1) % SCENE_LOOKS.len()];
                (format!("{scene}: {name}"), Ink::Plain(hue), glyph)
            }
        }
    };
    let mut series: Vec<Series> = Vec::new();
    for (i, set_lines) in per_set.iter().enumerate() {
        for line in set_lines {
            let (name, ink, glyph) = look_of(i, line.of);
            series.push(Series {
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
            });
        }
    }
    series.sort_by_key(|s| s.focused);
    let mut rules = Vec::new();
    if sets.len() == 1
        && spec.key == SceneKey::V0
        && let Some((v_yield, v_plastic)) = onset(first.data)
    {
        for (v, ink, label) in [
            (v_yield, Ink::Warning, "v_y"),
            (v_plastic, Ink::Error, "v_p"),
        ] {
            rules.push(Rule {
                at: x.to_display(v),
                horizontal: false,
                ink,
                label: label.into(),
            });
        }
    }
    for (i, level, label) in levels {
        let ink = if sets.len() == 1 {
            Ink::Foreground
        } else {
            look_of(i, LineOf::Estimate).1
        };
        let label = match &sets[i].name {
            Some(scene) if sets.len() > 1 => format!("{label} {scene}"),
            _ => label.to_string(),
        };
        rules.push(Rule {
            at: y.to_display(level),
            horizontal: true,
            ink,
            label,
        });
    }
    let symbol = key_symbol(spec.key);
    // Each point is a scene of its own: every law's damping is set from e by its rule there
    // (view 5 holds it instead, and its e_out against v₀ falls where this one is flat).
    let title = format!(
        "{} against {} · damping from e at each {symbol} · {} points, {}",
        output.symbol(),
        symbol,
        spec.points,
        if spec.log { "log" } else { "linear" }
    );
    Chart {
        rules,
        ..Chart::new(
            title,
            x.chart_axis(axis_title(&symbol, &x, x_unit)),
            y.chart_axis(axis_title(output.symbol(), &y, y_unit)),
            series,
        )
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

    #[test]
    fn outputs_read_the_estimate_or_each_model() {
        let row = SweepRow {
            value: 0.3,
            quasistatic: Some(QuasistaticPoint {
                p_max: 2.1e9,
                contact_radius: Some(3e-4),
                half_width: None,
                v_yield: 0.03,
                v_plastic: 0.33,
            }),
            impacts: vec![ImpactPoint {
                model: ForceModel::Proposed,
                x_max: Some(7.6e-6),
                f_max: Some(326.0),
                t_contact: Some(8.3e-5),
                v_out: Some(0.18),
                e_out: Some(0.62),
                error: None,
            }],
            error: None,
        };
        assert_eq!(SweepOutput::PeakPressure.estimate(&row), Some(2.1e9));
        assert_eq!(SweepOutput::ContactSize.estimate(&row), Some(3e-4));
        assert_eq!(
            SweepOutput::EOut.of_model(&row, ForceModel::Proposed),
            Some(0.62)
        );
        assert_eq!(
            SweepOutput::EOut.of_model(&row, ForceModel::HuntCrossley),
            None
        );
        assert!(!SweepOutput::PeakPressure.per_model() && SweepOutput::VOut.per_model());
    }
}
