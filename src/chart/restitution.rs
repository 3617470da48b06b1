//! The restitution view's charts as plain descriptions (docs/physics.md §6.4): realised e against
//! requested e with the identity line, and realised e against v₀ with the damping coefficient held,
//! v_y and v_p as rules.

use crate::chart::ticks::{NiceAxis, log_axis, nice_axis};
use crate::chart::{Chart, Ink, Rule, Series, model_glyph};
use crate::format::units::{DIMENSIONLESS, METRE_PER_SECOND, engineering};
use crate::model::ForceModel;
use crate::model::pressure::YieldOnset;
use crate::model::study::runner::RestitutionData;

/// The glyph of the identity line e_out = e.
const IDENTITY_GLYPH: char = '=';

fn series(
    curves: &[(ForceModel, Vec<(f64, f64)>)],
    focused: ForceModel,
    x: &NiceAxis,
    y: &NiceAxis,
) -> Vec<Series> {
    let mut series: Vec<Series> = curves
        .iter()
        .map(|(model, points)| Series {
            name: model.name().to_string(),
            ink: Ink::Model(*model),
            glyph: model_glyph(*model),
            runs: vec![
                points
                    .iter()
                    .filter(|p| p.0.is_finite() && p.1.is_finite())
                    .map(|&(px, py)| (x.to_display(px), y.to_display(py)))
                    .collect(),
            ],
            focused: *model == focused,
            peak: None,
            steps: false,
        })
        .collect();
    series.sort_by_key(|s| s.focused);
    series
}

/// Realised against requested e over (0, 1), at most `max_x` × `max_y` tick labels.
pub fn realised_chart(
    data: &RestitutionData,
    focused: ForceModel,
    (max_x, max_y): (usize, usize),
) -> Chart {
    let x = nice_axis(0.0, 1.0, DIMENSIONLESS, max_x.min(6));
    let y = nice_axis(0.0, 1.0, DIMENSIONLESS, max_y.min(6));
    let mut all = vec![Series {
        name: "e_out = e".to_string(),
        ink: Ink::Foreground,
        glyph: IDENTITY_GLYPH,
        runs: vec![vec![(0.0, 0.0), (1.0, 1.0)]],
        focused: false,
        peak: None,
        steps: false,
    }];
    all.extend(series(&data.realised, focused, &x, &y));
    Chart::new(
        "realised e against requested e".to_string(),
        x.chart_axis("e requested".to_string()),
        y.chart_axis("e_out".to_string()),
        all,
    )
}

/// Realised e against v₀ over four decades around the scene's, the damping coefficient held;
/// the yield-onset velocities as vertical rules where they fall on the axis.
pub fn velocity_chart(
    data: &RestitutionData,
    focused: ForceModel,
    onset: Option<YieldOnset>,
    (max_x, max_y): (usize, usize),
) -> Chart {
    let x = log_axis(data.v0 / 100.0, data.v0 * 100.0, METRE_PER_SECOND, max_x);
    let y = nice_axis(0.0, 1.0, DIMENSIONLESS, max_y.min(6));
    let mut rules = Vec::new();
    if let Some(onset) = onset {
        for (v, ink, label) in [
            (onset.v_yield, Ink::Warning, "v_y"),
            (onset.v_plastic, Ink::Error, "v_p"),
        ] {
            let at = x.to_display(v);
            if at.is_finite() && at >= x.bounds[0] && at <= x.bounds[1] {
                rules.push(Rule {
                    at,
                    horizontal: false,
                    ink,
                    label: label.into(),
                });
            }
        }
    }
    let unit = format!("{}{}", x.prefix.symbol, METRE_PER_SECOND.symbol);
    // The damping set from e at the scene's v₀ and held (view 4's sweep re-derives it at each v₀
    // instead, where Hunt–Crossley's e_out is flat).
    let title = format!(
        "e_out against v₀ · damping set at v₀ = {} and held (α for Hunt–Crossley)",
        engineering(data.v0, METRE_PER_SECOND, 3)
    );
    let series = series(&data.velocity, focused, &x, &y);
    Chart {
        rules,
        ..Chart::new(
            title,
            x.chart_axis(format!("v₀ [{unit}]")),
            y.chart_axis("e_out".to_string()),
            series,
        )
    }
}
