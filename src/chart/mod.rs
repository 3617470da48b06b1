//! A chart as plain data, for any renderer: the explorer's terminal canvas or a figure file
//! ([`figure`]). The builders here turn model results into a [`Chart`]: an impact's curves
//! ([`sample`], [`kind`]) and each study's ([`work_precision`], [`stability`], [`sweep`],
//! [`restitution`]), on axes with round ticks ([`ticks`]); renderers place ticks, lines and labels.
//! Nothing here draws on a terminal, so the command line's `plot` uses the same builders.
//!
//! Coordinates are display values: SI divided by the axis's prefix and unit, and log₁₀ of that on
//! a log axis, so that a renderer maps them linearly onto its plot area.

pub mod figure;
pub mod kind;
pub mod layout;
pub mod restitution;
pub mod sample;
pub mod stability;
pub mod sweep;
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

/// The data cursor's reading, in a long and a short form per curve, so that the renderer can fit
/// it into its row without cutting a number.
#[derive(Debug, Clone, PartialEq)]
pub struct Readout {
    /// Where the cursor stands, e.g. `t = 59 µs`.
    pub at: String,
    /// Per curve: the long reading (`proposed F 291.7 N`) and the short one (the curve's glyph
    /// and its values in the axis's unit, `* 291.7`).
    pub curves: Vec<(String, String)>,
}

impl Readout {
    /// The most explicit form that fits in `width` columns: every curve long; else every curve
    /// short; else as many short readings as fit, then `+N` for the curves left out.
    pub fn fit(&self, width: usize) -> String {
        let join = |parts: Vec<&str>| {
            std::iter::once(self.at.as_str())
                .chain(parts)
                .collect::<Vec<_>>()
                .join(" · ")
        };
        let long = join(self.curves.iter().map(|c| c.0.as_str()).collect());
        if long.chars().count() <= width {
            return long;
        }
        let short = join(self.curves.iter().map(|c| c.1.as_str()).collect());
        if short.chars().count() <= width {
            return short;
        }
        for shown in (0..self.curves.len()).rev() {
            let more = format!("+{}", self.curves.len() - shown);
            let mut parts: Vec<&str> = self.curves[..shown].iter().map(|c| c.1.as_str()).collect();
            parts.push(&more);
            let text = join(parts);
            if text.chars().count() <= width {
                return text;
            }
        }
        self.at.clone()
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

    #[test]
    fn a_readout_shortens_whole_readings_and_never_cuts_one() {
        let readout = Readout {
            at: "t = 59 µs".into(),
            curves: vec![
                ("proposed F 171.8 N".into(), "*171.8".into()),
                ("H–C F 181.2 N".into(), "x181.2".into()),
                ("L–N F 201.6 N".into(), "#201.6".into()),
            ],
        };
        let long = "t = 59 µs · proposed F 171.8 N · H–C F 181.2 N · L–N F 201.6 N";
        assert_eq!(readout.fit(80), long);
        assert_eq!(readout.fit(long.chars().count()), long);
        let short = "t = 59 µs · *171.8 · x181.2 · #201.6";
        assert_eq!(readout.fit(long.chars().count() - 1), short);
        assert_eq!(readout.fit(short.chars().count()), short);
        assert_eq!(
            readout.fit(short.chars().count() - 1),
            "t = 59 µs · *171.8 · x181.2 · +1"
        );
        assert_eq!(readout.fit(23), "t = 59 µs · *171.8 · +2");
        assert_eq!(readout.fit(22), "t = 59 µs · +3");
        assert_eq!(readout.fit(5), "t = 59 µs");
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
