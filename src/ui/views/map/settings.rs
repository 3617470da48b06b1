//! What the map view computes: its two keys with their ranges and points, where rows start, the
//! run of each cell, and which map is shown. Unset, a key's range is half to one and a half times
//! its value and the points fit the pane (a cell one or two terminal cells), capped at
//! [`MAX_CELLS`] so that a compliant map stays a few seconds.

use crate::format::units::{self, Unit};
use crate::model::scene_key::SceneKey;
use crate::model::study::map::Start;
use crate::model::system::map::{Axis, Grid, MapOptions};
use crate::model::system::{Param, SystemKey, SystemKind, SystemModel};
use crate::ui::views::system::settings::unit as key_unit;

/// Cells of a map at most unless set: a compliant cell costs about 20 ms of CPU at the defaults
/// (docs/maps.md §5), so 300 cells are a few seconds on two cores.
pub const MAX_CELLS: usize = 300;

/// Cells at most unless set, with the rigid stop only: a rigid cell costs about 0.3 ms.
pub const MAX_RIGID_CELLS: usize = 5000;

/// Points of an axis at most, typed or stepped.
pub const MAX_POINTS: usize = 400;

/// Which axis.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Which {
    X,
    Y,
}

/// A row of the form.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Row {
    Key(Which),
    From(Which),
    To(Which),
    Points(Which),
    Start,
    Stops,
    Shown,
}

/// Every row, in order.
pub const ROWS: [Row; 11] = [
    Row::Key(Which::X),
    Row::From(Which::X),
    Row::To(Which::X),
    Row::Points(Which::X),
    Row::Key(Which::Y),
    Row::From(Which::Y),
    Row::To(Which::Y),
    Row::Points(Which::Y),
    Row::Start,
    Row::Stops,
    Row::Shown,
];

impl Row {
    pub fn label(self) -> &'static str {
        match self {
            Row::Key(Which::X) => "x key",
            Row::From(Which::X) => "x from",
            Row::To(Which::X) => "x to",
            Row::Points(Which::X) => "x points",
            Row::Key(Which::Y) => "y key",
            Row::From(Which::Y) => "y from",
            Row::To(Which::Y) => "y to",
            Row::Points(Which::Y) => "y points",
            Row::Start => "rows start",
            Row::Stops => "stops",
            Row::Shown => "map shown",
        }
    }
}

/// The map on screen (`c` steps through them).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Shown {
    #[default]
    Rigid,
    Compliant,
    Difference,
}

impl Shown {
    pub fn name(self) -> &'static str {
        match self {
            Shown::Rigid => "rigid",
            Shown::Compliant => "compliant",
            Shown::Difference => "difference",
        }
    }

    pub fn next(self) -> Shown {
        match self {
            Shown::Rigid => Shown::Compliant,
            Shown::Compliant => Shown::Difference,
            Shown::Difference => Shown::Rigid,
        }
    }

    fn previous(self) -> Shown {
        self.next().next()
    }
}

/// One axis as set: `None` fields take their defaults.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct AxisSetting {
    pub key: Option<Param>,
    pub range: Option<(f64, f64)>,
    pub points: Option<usize>,
}

/// The view's settings.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Settings {
    pub x: AxisSetting,
    pub y: AxisSetting,
    pub start: Start,
    /// The rigid stop only: no compliant map (nor difference), a map in a fraction of the time.
    pub rigid_only: bool,
    pub shown: Shown,
    /// Transient, recorded and exponent impacts of each cell; `None`: those of `hertz-tui map`
    /// (300, 64, 200).
    pub budget: Option<(usize, usize, usize)>,
}

/// The keys a map can take for `model`: the system's, then the stop's e.
pub fn keys(model: &SystemModel) -> Vec<Param> {
    SystemKey::ALL
        .into_iter()
        .map(Param::System)
        .chain([Param::Scene(SceneKey::Restitution)])
        .filter(|p| p.get(model).is_ok())
        .collect()
}

/// The unit a key is typed and shown in.
pub fn unit(param: Param, model: &SystemModel) -> Unit {
    key_unit(param, model)
}

/// Points of each axis that fit a map of `columns` × `rows` terminal cells: a cell two columns
/// (about square) or one, at most `cap` cells in all.
pub fn fitted_points(columns: u16, rows: u16, cap: usize) -> (usize, usize) {
    let (mut nx, mut ny) = (
        (usize::from(columns) / 2).max(2),
        usize::from(rows).max(2),
    );
    if nx * ny > cap {
        let shrink = (cap as f64 / (nx * ny) as f64).sqrt();
        nx = ((nx as f64 * shrink).floor() as usize).max(2);
        ny = ((ny as f64 * shrink).floor() as usize).max(2);
    }
    (nx, ny)
}

impl Settings {
    fn axis(&self, which: Which) -> &AxisSetting {
        match which {
            Which::X => &self.x,
            Which::Y => &self.y,
        }
    }

    fn axis_mut(&mut self, which: Which) -> &mut AxisSetting {
        match which {
            Which::X => &mut self.x,
            Which::Y => &mut self.y,
        }
    }

    /// The key of an axis: the one set, else the forcing frequency across and its amplitude up.
    pub fn key(&self, which: Which, model: &SystemModel) -> Param {
        match self.axis(which).key {
            Some(key) if key.get(model).is_ok() => key,
            _ => match (which, model.spec.kind) {
                (Which::X, _) => Param::System(SystemKey::Frequency),
                (Which::Y, SystemKind::BouncingBall { .. }) => Param::System(SystemKey::Amplitude),
                (Which::Y, SystemKind::ImpactOscillator { .. }) => {
                    Param::System(SystemKey::ForcingAmplitude)
                }
            },
        }
    }

    /// The range of an axis: the one set, else half to one and a half times the key's value.
    pub fn range(&self, which: Which, model: &SystemModel) -> (f64, f64) {
        if let Some(range) = self.axis(which).range {
            return range;
        }
        let v = self.key(which, model).get(model).unwrap_or(1.0);
        (0.5 * v, 1.5 * v)
    }

    /// The points of an axis: those set, else `fitted`'s.
    pub fn points(&self, which: Which, fitted: (usize, usize)) -> usize {
        self.axis(which).points.unwrap_or(match which {
            Which::X => fitted.0,
            Which::Y => fitted.1,
        })
    }

    /// The grid for `model`, with `fitted` points where none are set.
    pub fn grid(&self, model: &SystemModel, fitted: (usize, usize)) -> Grid {
        let axis = |which| {
            let (from, to) = self.range(which, model);
            Axis {
                param: self.key(which, model),
                from,
                to,
                points: self.points(which, fitted),
            }
        };
        Grid {
            x: axis(Which::X),
            y: axis(Which::Y),
        }
    }

    /// Every cell's run: `hertz-tui map`'s defaults, or the budget set.
    pub fn options(&self) -> MapOptions {
        let mut options = MapOptions::default();
        if let Some((transient, recorded, lyapunov)) = self.budget {
            options.run.transient_impacts = transient;
            options.run.recorded_impacts = recorded;
            options.lyapunov_impacts = lyapunov;
            // As `hertz-tui map` reads its --recorded.
            options.tolerances.max_period_impacts = (recorded / 2).clamp(1, 64);
        }
        options
    }

    /// The value of `row` as the form shows it.
    pub fn show(&self, row: Row, model: &SystemModel, fitted: (usize, usize)) -> String {
        let value = |which: Which, v: f64| {
            units::engineering(v, unit(self.key(which, model), model), 4)
        };
        match row {
            Row::Key(w) => self.key(w, model).path(),
            Row::From(w) => value(w, self.range(w, model).0),
            Row::To(w) => value(w, self.range(w, model).1),
            Row::Points(w) => {
                let n = self.points(w, fitted);
                match self.axis(w).points {
                    Some(_) => n.to_string(),
                    None => format!("{n} (fits the pane)"),
                }
            }
            Row::Start => match self.start {
                Start::Rest => "at rest".into(),
                Start::PeriodOne => "on the period-1 orbit".into(),
            },
            Row::Stops => if self.rigid_only {
                "rigid only".into()
            } else {
                "rigid and compliant".into()
            },
            Row::Shown => self.shown.name().into(),
        }
    }

    /// The text an editor opens with.
    pub fn edit_text(&self, row: Row, model: &SystemModel, fitted: (usize, usize)) -> String {
        match row {
            Row::Points(w) => self.points(w, fitted).to_string(),
            Row::Start => match self.start {
                Start::Rest => "rest".into(),
                Start::PeriodOne => "period-1".into(),
            },
            Row::Stops => if self.rigid_only { "rigid" } else { "both" }.into(),
            _ => self.show(row, model, fitted),
        }
    }

    /// Applies typed `text` to `row`; the reason, naming the row or key, if refused.
    pub fn apply(&mut self, row: Row, text: &str, model: &SystemModel) -> Result<(), String> {
        let text = text.trim();
        match row {
            Row::Key(w) => {
                let param: Param = text.parse().map_err(|e: crate::model::system::SystemError| {
                    format!("{}: {e}", row.label())
                })?;
                param.get(model).map_err(|e| format!("{}: {e}", row.label()))?;
                let axis = self.axis_mut(w);
                axis.key = Some(param);
                axis.range = None;
                Ok(())
            }
            Row::From(w) | Row::To(w) => {
                let param = self.key(w, model);
                let value = units::parse(text, unit(param, model))
                    .map_err(|e| format!("{} ({}): {e}", row.label(), param.path()))?;
                self.set(row, value, model)
            }
            Row::Points(_) => {
                let n: f64 = text.parse().map_err(|_| {
                    format!("{}: \"{text}\" is not a whole number", row.label())
                })?;
                self.set(row, n, model)
            }
            Row::Start => {
                self.start = match text {
                    "rest" | "at rest" => Start::Rest,
                    "period-1" | "orbit" | "on the period-1 orbit" => Start::PeriodOne,
                    _ => {
                        return Err(format!(
                            "rows start: \"{text}\" is not rest or period-1"
                        ));
                    }
                };
                Ok(())
            }
            Row::Stops => {
                self.rigid_only = match text {
                    "rigid" | "rigid only" => true,
                    "both" | "rigid and compliant" => false,
                    _ => {
                        return Err(format!("stops: \"{text}\" is not rigid or both"));
                    }
                };
                Ok(())
            }
            Row::Shown => {
                self.shown = match text {
                    "rigid" => Shown::Rigid,
                    "compliant" => Shown::Compliant,
                    "difference" => Shown::Difference,
                    _ => {
                        return Err(format!(
                            "map shown: \"{text}\" is not rigid, compliant or difference"
                        ));
                    }
                };
                Ok(())
            }
        }
    }

    /// Sets a numeric `row` to `value` (SI); the reason, naming the key, if refused.
    pub fn set(&mut self, row: Row, value: f64, model: &SystemModel) -> Result<(), String> {
        match row {
            Row::From(w) | Row::To(w) => {
                let param = self.key(w, model);
                param
                    .apply(model, value)
                    .map_err(|e| format!("{}: {e}", row.label()))?;
                let (from, to) = self.range(w, model);
                let range = if matches!(row, Row::From(_)) {
                    (value, to)
                } else {
                    (from, value)
                };
                if range.0 == range.1 {
                    return Err(format!(
                        "{}: from and to of {} must differ",
                        row.label(),
                        param.path()
                    ));
                }
                self.axis_mut(w).range = Some(range);
                Ok(())
            }
            Row::Points(w) => {
                if !(value.fract() == 0.0 && (2.0..=MAX_POINTS as f64).contains(&value)) {
                    return Err(format!(
                        "{}: a whole number 2…{MAX_POINTS}, got {value}",
                        row.label()
                    ));
                }
                self.axis_mut(w).points = Some(value as usize);
                Ok(())
            }
            _ => Ok(()),
        }
    }

    /// ← → on `row`: the next key, 5 % up or down, twice or half the points, the other start or
    /// map.
    pub fn nudge(
        &mut self,
        row: Row,
        up: bool,
        model: &SystemModel,
        fitted: (usize, usize),
    ) -> Result<(), String> {
        let factor = if up { 1.05 } else { 1.0 / 1.05 };
        match row {
            Row::Key(w) => {
                let keys = keys(model);
                let here = self.key(w, model);
                let n = keys.len().max(1);
                let i = keys.iter().position(|&k| k == here).unwrap_or(0);
                let j = if up { (i + 1) % n } else { (i + n - 1) % n };
                if let Some(&key) = keys.get(j) {
                    let axis = self.axis_mut(w);
                    axis.key = Some(key);
                    axis.range = None;
                }
                Ok(())
            }
            Row::From(w) => {
                let v = self.range(w, model).0;
                self.set(row, v * factor, model)
            }
            Row::To(w) => {
                let v = self.range(w, model).1;
                self.set(row, v * factor, model)
            }
            Row::Points(w) => {
                let n = self.points(w, fitted) as f64;
                let n = if up { n * 2.0 } else { (n / 2.0).floor() };
                self.set(row, n.clamp(2.0, MAX_POINTS as f64), model)
            }
            Row::Start => {
                self.start = match self.start {
                    Start::Rest => Start::PeriodOne,
                    Start::PeriodOne => Start::Rest,
                };
                Ok(())
            }
            Row::Stops => {
                self.rigid_only = !self.rigid_only;
                Ok(())
            }
            Row::Shown => {
                self.shown = if up {
                    self.shown.next()
                } else {
                    self.shown.previous()
                };
                Ok(())
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fitted_points_make_a_cell_two_columns_and_stay_under_the_cap() {
        assert_eq!(fitted_points(40, 12, MAX_CELLS), (20, 12));
        assert_eq!(fitted_points(100, 30, MAX_RIGID_CELLS), (50, 30));
        for (w, h) in [(120, 40), (200, 60), (80, 20)] {
            let (nx, ny) = fitted_points(w, h, MAX_CELLS);
            assert!(nx * ny <= MAX_CELLS, "{w}×{h}: {nx}×{ny}");
            assert!(usize::from(w) / nx >= 2 && usize::from(h) / ny >= 1);
            // The shape is kept: a cell about as wide (in columns) as twice its height.
            let aspect = (f64::from(w) / nx as f64) / (f64::from(h) / ny as f64);
            assert!((aspect - 2.0).abs() < 0.5, "{w}×{h}: {nx}×{ny}");
        }
    }
}
