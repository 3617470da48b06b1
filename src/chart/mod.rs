//! A chart as plain data, for any renderer: the explorer's terminal canvas or a figure file
//! ([`figure`]). The builders here turn model results into a [`Chart`]: an impact's curves
//! ([`sample`], [`kind`]) and each study's ([`work_precision`], [`stability`], [`sweep`],
//! [`restitution`]), on axes with round ticks ([`ticks`]); renderers place ticks, lines and labels.
//! Nothing here draws on a terminal, so the command line's `plot` uses the same builders.
//!
//! Coordinates are display values: SI divided by the axis's prefix and unit, and log₁₀ of that on
//! a log axis, so that a renderer maps them linearly onto its plot area.

pub mod continuation;
pub mod figure;
pub mod fit;
pub mod kind;
pub mod layout;
pub mod map;
pub mod restitution;
pub mod sample;
pub mod stability;
pub mod sweep;
pub mod system;
pub mod ticks;
pub mod work_precision;

/// The pattern of an ink's lines: a law's is on its row of the law table.
pub use crate::model::force::table::Dash;
/// The colour of an ink, by name: a law's hue is part of its row of the law table.
pub use crate::model::force::table::Hue;
pub use layout::{Placed, place_ticks};

use crate::model::ForceModel;
use crate::model::ode::Method;

/// Whose colour a piece of the chart takes. Renderers map inks to their palettes, so that a model
/// keeps its colour in every view and in figures.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ink {
    /// The terminal's own foreground (black in figures): references and estimates.
    Foreground,
    Model(ForceModel),
    Method(Method),
    /// Yield begins (v_y).
    Warning,
    /// Fully plastic (v_p), failures.
    Error,
    /// A line of its own hue (one scene among several).
    Plain(Hue),
}

impl Ink {
    /// The hue of this ink: a model or method keeps its hue everywhere. A model's hue is on its
    /// row of the law table; the seven methods take six hues and the foreground (radau5: never in
    /// the stability view, where the reference is the foreground).
    pub fn hue(self) -> Hue {
        match self {
            Ink::Foreground => Hue::Foreground,
            Ink::Model(m) => m.spec().style.hue,
            Ink::Method(m) => match m {
                Method::Dopri5 => Hue::Yellow,
                Method::Dop853 => Hue::Cyan,
                Method::Radau5 => Hue::Foreground,
                Method::Euler => Hue::Red,
                Method::SymplecticEuler => Hue::Green,
                Method::Verlet => Hue::Blue,
                Method::Rk4 => Hue::Magenta,
            },
            Ink::Warning => Hue::Yellow,
            Ink::Error => Hue::Red,
            Ink::Plain(hue) => hue,
        }
    }

    /// The pattern of this ink's curves: a model's is on its row of the law table; the methods
    /// that share the stability view's chart take three patterns, so that a method on top of the
    /// reference leaves it showing in its gaps.
    pub fn dash(self) -> Dash {
        match self {
            Ink::Model(m) => m.spec().style.dash,
            Ink::Method(m) => match m {
                Method::Radau5 | Method::Dopri5 | Method::SymplecticEuler => Dash::Solid,
                Method::Dop853 | Method::Verlet => Dash::Dashed,
                Method::Euler | Method::Rk4 => Dash::Dotted,
            },
            Ink::Foreground | Ink::Warning | Ink::Error | Ink::Plain(_) => Dash::Solid,
        }
    }
}

/// A tick: its place in display values and its label.
#[derive(Debug, Clone, PartialEq)]
pub struct Tick {
    pub at: f64,
    pub label: String,
}

/// One axis: its range in display values, ticks inside it, and its title with the unit.
#[derive(Debug, Clone, PartialEq)]
pub struct Axis {
    pub title: String,
    pub range: [f64; 2],
    /// The values are log₁₀ of the quantity (the labels show the quantity).
    pub log: bool,
    pub ticks: Vec<Tick>,
}

impl Axis {
    /// Where `value` falls along the axis, 0 at the start and 1 at the end (outside for values
    /// off the axis, NaN for non-finite ones).
    pub fn fraction(&self, value: f64) -> f64 {
        let [lo, hi] = self.range;
        if value.is_finite() && hi > lo {
            (value - lo) / (hi - lo)
        } else {
            f64::NAN
        }
    }
}

/// A curve: runs of points (a failed point breaks a run, never bridged).
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    pub name: String,
    pub ink: Ink,
    /// Marks the curve where colour cannot: at its peak and end, and along it without colour.
    pub glyph: char,
    pub runs: Vec<Vec<(f64, f64)>>,
    /// Drawn last and bold.
    pub focused: bool,
    /// The peak this chart shows (F_max, x_max), exact: marked with the glyph.
    pub peak: Option<(f64, f64)>,
    /// Each point is a step of a fixed-step method: every one is marked.
    pub steps: bool,
}

impl Series {
    /// The last point drawn, where the curve ends.
    pub fn end(&self) -> Option<(f64, f64)> {
        self.runs.iter().rev().find_map(|r| r.last().copied())
    }
}

/// A single point with its own glyph and, where given, a label beside it.
#[derive(Debug, Clone, PartialEq)]
pub struct Mark {
    pub at: (f64, f64),
    pub ink: Ink,
    pub glyph: char,
    pub label: Option<String>,
}

/// A line across the plot at a value of x (vertical, labelled at its top) or of y (horizontal,
/// labelled at its right end).
#[derive(Debug, Clone, PartialEq)]
pub struct Rule {
    pub at: f64,
    pub horizontal: bool,
    pub ink: Ink,
    pub label: String,
}

impl Rule {
    /// Its two ends in display values, across the whole plot of `chart`.
    pub fn ends(&self, chart: &Chart) -> [(f64, f64); 2] {
        if self.horizontal {
            [(chart.x.range[0], self.at), (chart.x.range[1], self.at)]
        } else {
            [(self.at, chart.y.range[0]), (self.at, chart.y.range[1])]
        }
    }
}

/// Everything one chart shows.
#[derive(Debug, Clone, PartialEq)]
pub struct Chart {
    pub title: String,
    pub x: Axis,
    pub y: Axis,
    /// In drawing order: the focused series last.
    pub series: Vec<Series>,
    pub marks: Vec<Mark>,
    pub rules: Vec<Rule>,
    /// Why something is missing ("proposed: step budget exhausted at t = …"), shown with the chart.
    pub notes: Vec<String>,
    /// The data cursor's reading (each curve's value where it stands), shown above the plot.
    pub readout: Option<Readout>,
}

impl Chart {
    /// A chart of `series` on `x` and `y`, with no marks, rules, notes or reading (set those by
    /// struct update where a chart has them).
    pub fn new(title: String, x: Axis, y: Axis, series: Vec<Series>) -> Self {
        Chart {
            title,
            x,
            y,
            series,
            marks: Vec::new(),
            rules: Vec::new(),
            notes: Vec::new(),
            readout: None,
        }
    }
}

/// The data cursor's reading: where it stands and each curve's values there, with the curve's
/// names from the longest to the shortest, so that the renderer can fit it without cutting a
/// number or naming a curve by its glyph.
#[derive(Debug, Clone, PartialEq)]
pub struct Readout {
    /// Where the cursor stands, e.g. `t = 59 µs`.
    pub at: String,
    pub curves: Vec<ReadoutCurve>,
}

/// One curve's reading at the data cursor.
#[derive(Debug, Clone, PartialEq)]
pub struct ReadoutCurve {
    /// The curve's names, longest first (`Hunt–Crossley`, `hunt-crossley`, `H–C`); never empty.
    pub names: Vec<String>,
    pub ink: Ink,
    /// Its values where the cursor stands, in the axis's unit, the most digits first:
    /// `171.8 N`, or `171.8 / 150 N` where the curve passes twice (loading and unloading).
    pub values: Vec<String>,
}

impl ReadoutCurve {
    /// The name and the values of form `form`: the names shorten first, then the values; past
    /// the last form, the shortest.
    fn parts(&self, form: usize) -> (&str, &str) {
        let names = self.names.len().max(1);
        let name = self
            .names
            .get(form.min(names - 1))
            .map_or("", String::as_str);
        let values = form.saturating_sub(names - 1);
        let value = self
            .values
            .get(values.min(self.values.len().saturating_sub(1)))
            .map_or("", String::as_str);
        (name, value)
    }

    /// Forms from the longest to the shortest.
    fn forms(&self) -> usize {
        self.names.len().max(1) + self.values.len().max(1) - 1
    }

    /// `name values` in form `form`: the names shorten first, then the values.
    pub fn text(&self, form: usize) -> String {
        let (name, value) = self.parts(form);
        format!("{name} {value}")
    }

    /// Characters of the name in [`ReadoutCurve::text`].
    pub fn name_len(&self, form: usize) -> usize {
        self.parts(form).0.chars().count()
    }
}

impl Readout {
    /// Forms tried, longest first (names, then values, shorten).
    pub fn forms(&self) -> usize {
        self.curves
            .iter()
            .map(ReadoutCurve::forms)
            .max()
            .unwrap_or(1)
    }

    /// The reading on one line of `width` columns, every curve named alike in the longest form
    /// that fits (`t = 59 µs · proposed 171.8 N · H–C 181.2 N`), and its name form; `None` when
    /// not even the shortest names fit.
    pub fn line(&self, width: usize) -> Option<(String, usize)> {
        (0..self.forms()).find_map(|form| {
            let text = std::iter::once(self.at.clone())
                .chain(self.curves.iter().map(|c| c.text(form)))
                .collect::<Vec<_>>()
                .join(" · ");
            (text.chars().count() <= width).then_some((text, form))
        })
    }

    /// The reading as rows of a box `width` columns wide: where the cursor stands, then one row
    /// per curve, named alike in the longest form with which every row fits; a row that still
    /// does not fit ends in `…`. The name form is returned with the rows.
    pub fn rows(&self, width: usize) -> (Vec<String>, usize) {
        let fits = |form: usize| {
            self.curves
                .iter()
                .all(|c| c.text(form).chars().count() <= width)
        };
        let form = (0..self.forms())
            .find(|&f| fits(f))
            .unwrap_or(self.forms() - 1);
        let cut = |text: String| {
            if text.chars().count() <= width {
                text
            } else {
                let mut kept: String = text.chars().take(width.saturating_sub(1)).collect();
                kept.push('…');
                kept
            }
        };
        let rows = std::iter::once(self.at.clone())
            .chain(self.curves.iter().map(|c| c.text(form)))
            .map(cut)
            .collect();
        (rows, form)
    }
}

/// The glyph of a force model, from its row of the law table: each its own.
pub fn model_glyph(model: ForceModel) -> char {
    model.spec().style.glyph
}

/// The glyph of an integration method: each its own.
pub fn method_glyph(method: Method) -> char {
    match method {
        Method::Dopri5 => 'o',
        Method::Dop853 => '*',
        Method::Radau5 => '+',
        Method::Euler => 'x',
        Method::SymplecticEuler => '#',
        Method::Verlet => '%',
        Method::Rk4 => '@',
    }
}

/// The glyph of a reference curve (drawn over the methods it judges).
pub const REFERENCE_GLYPH: char = '=';

#[cfg(test)]
mod tests {
    use super::*;

    fn curve(names: [&str; 3], values: &str) -> ReadoutCurve {
        ReadoutCurve {
            names: names.iter().map(|n| n.to_string()).collect(),
            ink: Ink::Foreground,
            values: vec![values.into()],
        }
    }

    /// On one line while it fits, the curves named alike in the longest form that fits; else in
    /// rows, each named, with its values whole: never a glyph for a name, never `+N`.
    #[test]
    fn a_readout_names_every_curve_and_shows_every_value() {
        let readout = Readout {
            at: "t = 59 µs".into(),
            curves: vec![
                curve(["proposed", "proposed", "prop"], "171.8 N"),
                curve(["Hunt–Crossley", "hunt-crossley", "H–C"], "181.2 N"),
                curve(
                    ["Lankarani–Nikravesh", "lankarani-nikravesh", "L–N"],
                    "201.6 N",
                ),
            ],
        };
        let long =
            "t = 59 µs · proposed 171.8 N · Hunt–Crossley 181.2 N · Lankarani–Nikravesh 201.6 N";
        assert_eq!(readout.line(100), Some((long.to_string(), 0)));
        let short = "t = 59 µs · prop 171.8 N · H–C 181.2 N · L–N 201.6 N";
        assert_eq!(
            readout.line(short.chars().count()),
            Some((short.to_string(), 2))
        );
        assert_eq!(readout.line(short.chars().count() - 1), None);
        let (rows, form) = readout.rows(30);
        assert_eq!(form, 0);
        assert_eq!(
            rows,
            [
                "t = 59 µs",
                "proposed 171.8 N",
                "Hunt–Crossley 181.2 N",
                "Lankarani–Nikravesh 201.6 N"
            ]
        );
        let (rows, form) = readout.rows(12);
        assert_eq!((rows[2].as_str(), form), ("H–C 181.2 N", 2));
        // Too narrow for any name and value: cut with `…`, never silently.
        let (rows, _) = readout.rows(8);
        assert_eq!(rows[1], "prop 17…");
        // Fewer digits before a cut.
        let mut two = readout.clone();
        two.curves[0].values = vec![
            "0.08134 / -0.07435 m/s".into(),
            "0.0813 / -0.0744 m/s".into(),
        ];
        let (rows, form) = two.rows(25);
        assert_eq!((rows[1].as_str(), form), ("prop 0.0813 / -0.0744 m/s", 3));
    }

    #[test]
    fn glyphs_tell_every_model_and_method_apart() {
        for (i, a) in ForceModel::ALL.iter().enumerate() {
            assert_ne!(model_glyph(*a), REFERENCE_GLYPH);
            for b in &ForceModel::ALL[i + 1..] {
                assert_ne!(model_glyph(*a), model_glyph(*b));
            }
        }
        for (i, a) in Method::ALL.iter().enumerate() {
            assert_ne!(method_glyph(*a), REFERENCE_GLYPH);
            for b in &Method::ALL[i + 1..] {
                assert_ne!(method_glyph(*a), method_glyph(*b));
            }
        }
    }

    #[test]
    fn fractions_along_an_axis() {
        let axis = Axis {
            title: String::new(),
            range: [-1.0, 3.0],
            log: false,
            ticks: Vec::new(),
        };
        assert_eq!(axis.fraction(-1.0), 0.0);
        assert_eq!(axis.fraction(1.0), 0.5);
        assert_eq!(axis.fraction(5.0), 1.5);
        assert!(axis.fraction(f64::NAN).is_nan());
    }
}
