//! Sweep rows as chart lines: the chosen output against the swept value, one line per model (or
//! one for the quasistatic estimate), broken where a point failed rather than bridged.

use crate::model::ForceModel;
use crate::model::study::sweep::SweepRow;

use super::studies::SweepData;
use super::sweep_settings::SweepOutput;

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
