//! The two-parameter map of a system's motion (docs/maps.md): one scatter per kind of motion, each
//! cell a point at its (x, y), in the kind's hue and glyph. The terminal drawing of `hertz-tui
//! map` uses the same glyphs ([`look`]).

use crate::chart::ticks::nice_axis;
use crate::chart::{Chart, Hue, Ink, Series};
use crate::format::units;

/// How one kind of motion is drawn.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Look {
    pub glyph: char,
    pub hue: Hue,
    /// The legend's words.
    pub name: String,
}

/// The look of a cell by its motion's name (or a difference map's `same`, `differs`, `unknown`)
/// and, for periodic motion, its impacts per period n.
pub fn look(motion: &str, impacts: Option<u32>) -> Look {
    let l = |glyph, hue, name: &str| Look {
        glyph,
        hue,
        name: name.to_string(),
    };
    match (motion, impacts) {
        ("periodic", Some(n)) if n < 10 => Look {
            glyph: char::from_digit(n, 10).unwrap_or('+'),
            hue: match n {
                1 => Hue::Green,
                2 => Hue::Cyan,
                _ => Hue::Blue,
            },
            name: format!(
                "periodic, n = {n} impact{} an orbit (n:m in the file)",
                if n == 1 { "" } else { "s" }
            ),
        },
        ("periodic", _) => l('+', Hue::Blue, "periodic, n ≥ 10 impacts an orbit"),
        ("quasi-periodic", _) => l('~', Hue::Yellow, "quasi-periodic (λ ≈ 0)"),
        ("chaotic", _) => l('#', Hue::Red, "chaotic (λ > 0)"),
        ("long-period", _) => l('L', Hue::Magenta, "long period or slow transient (λ < 0)"),
        ("chattering", _) => l('c', Hue::Magenta, "chattering"),
        ("sticking", _) => l('s', Hue::Foreground, "sticking"),
        ("no-impact", _) => l('.', Hue::Foreground, "no impact"),
        ("unsettled", _) => l('u', Hue::Yellow, "unsettled (transient never ended)"),
        ("same", _) => l('=', Hue::Green, "same motion"),
        ("differs", _) => l('X', Hue::Red, "different motion"),
        ("failed", _) => l('!', Hue::Red, "run failed"),
        ("unknown", _) => l(
            '?',
            Hue::Foreground,
            "unknown (a run failed or is unsettled)",
        ),
        _ => l('?', Hue::Foreground, "unresolved"),
    }
}

/// One cell to draw: SI values and its look.
#[derive(Debug, Clone, PartialEq)]
pub struct MapPoint {
    pub x: f64,
    pub y: f64,
    pub look: Look,
}

/// The map as a chart: a scatter series per look, in the order they first appear. Axes are the
/// keys' SI values (`unit` their SI unit, "" if none).
pub fn motion_map(
    title: String,
    (x_key, x_unit, x_span): (&str, &str, (f64, f64)),
    (y_key, y_unit, y_span): (&str, &str, (f64, f64)),
    points: &[MapPoint],
    (max_x, max_y): (usize, usize),
) -> Chart {
    let (x0, x1) = (x_span.0.min(x_span.1), x_span.0.max(x_span.1));
    let (y0, y1) = (y_span.0.min(y_span.1), y_span.0.max(y_span.1));
    let x = nice_axis(x0, x1, units::DIMENSIONLESS, max_x);
    let y = nice_axis(y0, y1, units::DIMENSIONLESS, max_y);
    let mut series: Vec<Series> = Vec::new();
    for p in points {
        let at = (x.to_display(p.x), y.to_display(p.y));
        match series.iter_mut().find(|s| s.name == p.look.name) {
            Some(s) => s.runs.push(vec![at]),
            None => series.push(Series {
                name: p.look.name.clone(),
                ink: Ink::Plain(p.look.hue),
                glyph: p.look.glyph,
                runs: vec![vec![at]],
                focused: false,
                peak: None,
                steps: false,
            }),
        }
    }
    let title_of = |key: &str, prefix: &str, unit: &str| {
        let unit = format!("{prefix}{unit}");
        if unit.is_empty() {
            key.to_string()
        } else {
            format!("{key} [{unit}]")
        }
    };
    let x_title = title_of(x_key, x.prefix.symbol, x_unit);
    let y_title = title_of(y_key, y.prefix.symbol, y_unit);
    Chart::new(title, x.chart_axis(x_title), y.chart_axis(y_title), series)
}
