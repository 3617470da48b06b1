//! What the sweep view sweeps and draws: the parameter (any applicable [`SceneKey`]), the output,
//! the range and scale, and the number of points (by default, as many as the chart can show).

use crate::model::ForceModel;
use crate::model::impact::SolveOptions;
use crate::model::scene::Scene;
use crate::format::units::{self, key_unit};
use crate::model::scene_key::SceneKey;
use crate::chart::sweep::SweepOutput;
use crate::model::study::sweep::{SweepRange, SweepSpec, default_range, sweepable_keys};
use crate::ui::field::{Nudge, nudged};

/// The rows of the sweep form, in cursor order.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SweepField {
    Parameter,
    Output,
    From,
    To,
    Points,
    Scale,
}

impl SweepField {
    pub const ALL: [SweepField; 6] = [
        SweepField::Parameter,
        SweepField::Output,
        SweepField::From,
        SweepField::To,
        SweepField::Points,
        SweepField::Scale,
    ];

    pub fn label(self) -> &'static str {
        match self {
            SweepField::Parameter => "param",
            SweepField::Output => "output",
            SweepField::From => "from",
            SweepField::To => "to",
            SweepField::Points => "points",
            SweepField::Scale => "scale",
        }
    }

    /// Whether Enter opens a line editor (else it steps the choice).
    pub fn is_typed(self) -> bool {
        matches!(self, SweepField::From | SweepField::To | SweepField::Points)
    }

    /// The next or previous row, wrapping.
    pub fn step(self, forward: bool) -> SweepField {
        let n = SweepField::ALL.len();
        let i = SweepField::ALL
            .iter()
            .position(|&f| f == self)
            .unwrap_or_default();
        SweepField::ALL[if forward {
            (i + 1) % n
        } else {
            (i + n - 1) % n
        }]
    }
}

/// Everything the sweep form sets.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepSettings {
    pub key: SceneKey,
    pub output: SweepOutput,
    /// A range the user set; `None` follows the scene (see [`default_range`]).
    pub custom: Option<SweepRange>,
    /// A number of points the user set; `None` sizes the sweep to the chart.
    pub points: Option<usize>,
}

impl Default for SweepSettings {
    /// e_out against v₀: how each model's losses follow the impact speed.
    fn default() -> Self {
        SweepSettings {
            key: SceneKey::V0,
            output: SweepOutput::EOut,
            custom: None,
            points: None,
        }
    }
}

/// Fewest points of a sweep (a line needs two).
pub const MIN_POINTS: usize = 2;

impl SweepSettings {
    /// The range swept in `scene`: the user's, else the default; `None` if the key does not apply.
    pub fn range(&self, scene: &Scene) -> Option<SweepRange> {
        self.custom.or_else(|| default_range(self.key, scene))
    }

    /// The number of points for a chart that shows `max` of them distinctly.
    pub fn effective_points(&self, max: usize) -> usize {
        let max = max.max(MIN_POINTS);
        self.points.unwrap_or(max).clamp(MIN_POINTS, max)
    }

    /// The sweep of `models` in `scene`, or why there is none.
    pub fn spec(
        &self,
        scene: &Scene,
        models: Vec<ForceModel>,
        options: SolveOptions,
        max_points: usize,
    ) -> Result<SweepSpec, String> {
        let range = self.range(scene).ok_or_else(|| {
            format!(
                "{} does not apply to this scene: pick another parameter",
                self.key
            )
        })?;
        Ok(SweepSpec {
            key: self.key,
            from: range.from,
            to: range.to,
            points: self.effective_points(max_points),
            log: range.log,
            models,
            options,
        })
    }

    /// The value shown in the form.
    pub fn display(&self, field: SweepField, scene: &Scene, max_points: usize) -> String {
        match field {
            SweepField::Parameter => self.key.path(),
            SweepField::Output => {
                format!("{} {}", self.output.symbol(), self.output.description())
            }
            SweepField::Points => match self.points {
                None => format!("auto ({})", self.effective_points(max_points)),
                Some(_) => format!(
                    "{} (chart shows ≤ {})",
                    self.effective_points(max_points),
                    max_points.max(MIN_POINTS)
                ),
            },
            SweepField::Scale => match self.range(scene) {
                Some(r) if r.log => "log".into(),
                Some(_) => "linear".into(),
                None => "—".into(),
            },
            SweepField::From | SweepField::To => self.edit_text(field, scene),
        }
    }

    /// [`Self::display`], or where it is wider than `width` columns a shorter form that keeps
    /// the value whole: the output's symbol alone, the count of points alone.
    pub fn display_within(
        &self,
        field: SweepField,
        scene: &Scene,
        max_points: usize,
        width: usize,
    ) -> String {
        let full = self.display(field, scene, max_points);
        if full.chars().count() <= width {
            return full;
        }
        match field {
            SweepField::Output => self.output.symbol().to_string(),
            SweepField::Points => self.effective_points(max_points).to_string(),
            _ => full,
        }
    }

    /// The text an edit starts from.
    pub fn edit_text(&self, field: SweepField, scene: &Scene) -> String {
        let unit = key_unit(self.key);
        match (field, self.range(scene)) {
            (SweepField::From, Some(r)) => units::engineering(r.from, unit, 4),
            (SweepField::To, Some(r)) => units::engineering(r.to, unit, 4),
            (SweepField::Points, _) => match self.points {
                Some(n) => n.to_string(),
                None => "auto".into(),
            },
            _ => String::new(),
        }
    }

    /// Parses `text` into a typed field: a bound in the key's unit, or a count (or `auto`).
    pub fn apply(&mut self, field: SweepField, text: &str, scene: &Scene) -> Result<(), String> {
        match field {
            SweepField::Points => {
                let text = text.trim();
                if text == "auto" {
                    self.points = None;
                    return Ok(());
                }
                let n: usize = text
                    .parse()
                    .map_err(|_| format!("'{text}' is not a count: type a whole number or auto"))?;
                if n < MIN_POINTS {
                    return Err(format!("a sweep needs at least {MIN_POINTS} points"));
                }
                self.points = Some(n);
                Ok(())
            }
            SweepField::From | SweepField::To => {
                let value = units::parse(text, key_unit(self.key))?;
                let mut range = self
                    .range(scene)
                    .ok_or_else(|| format!("{} does not apply to this scene", self.key))?;
                if field == SweepField::From {
                    range.from = value;
                } else {
                    range.to = value;
                }
                self.custom = Some(range);
                Ok(())
            }
            SweepField::Parameter | SweepField::Output | SweepField::Scale => {
                self.nudge(field, Nudge::Up, scene, usize::MAX);
                Ok(())
            }
        }
    }

    /// Steps a field: the next key or output, the other scale, a bound by its second digit, the
    /// points halved or doubled. Returns whether anything changed.
    pub fn nudge(
        &mut self,
        field: SweepField,
        direction: Nudge,
        scene: &Scene,
        max_points: usize,
    ) -> bool {
        let before = self.clone();
        match field {
            SweepField::Parameter => {
                let keys = sweepable_keys(scene);
                if keys.is_empty() {
                    return false;
                }
                self.key = cycle(&keys, self.key, direction);
                // A new parameter starts from its own default range.
                self.custom = None;
            }
            SweepField::Output => self.output = cycle(&SweepOutput::ALL, self.output, direction),
            SweepField::Scale => {
                if let Some(mut range) = self.range(scene) {
                    range.log = !range.log;
                    self.custom = Some(range);
                }
            }
            SweepField::From | SweepField::To => {
                if let Some(mut range) = self.range(scene) {
                    let bound = if field == SweepField::From {
                        &mut range.from
                    } else {
                        &mut range.to
                    };
                    if let Some(next) = nudged(*bound, direction, 0.01 * range_scale(self.key)) {
                        *bound = next;
                        self.custom = Some(range);
                    }
                }
            }
            SweepField::Points => {
                let current = self.effective_points(max_points);
                let next = match direction {
                    Nudge::Up => current.saturating_mul(2),
                    Nudge::Down => current / 2,
                };
                self.points = Some(next.clamp(MIN_POINTS, max_points.max(MIN_POINTS)));
            }
        }
        *self != before
    }
}

/// The order of magnitude of a key's values in SI, for stepping a bound away from zero.
fn range_scale(key: SceneKey) -> f64 {
    match key {
        SceneKey::PlasticIndentation => 1e-5,
        _ => 1.0,
    }
}

fn cycle<T: Copy + PartialEq>(choices: &[T], current: T, direction: Nudge) -> T {
    let n = choices.len();
    let i = choices.iter().position(|&c| c == current).unwrap_or(0);
    choices[match direction {
        Nudge::Up => (i + 1) % n,
        Nudge::Down => (i + n - 1) % n,
    }]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::scene_key::{BodyField, BodyIndex};
    use crate::ui::testing::fig5_scene;

    #[test]
    fn v0_sweeps_two_decades_down_and_one_up_on_a_log_scale() {
        let scene = fig5_scene();
        let settings = SweepSettings::default();
        let spec = settings
            .spec(
                &scene,
                vec![ForceModel::Proposed],
                SolveOptions::default(),
                240,
            )
            .unwrap();
        assert_eq!(spec.key, SceneKey::V0);
        assert!((spec.from - 0.003).abs() < 1e-15 && (spec.to - 3.0).abs() < 1e-12);
        assert!(spec.log);
        assert_eq!(spec.points, 240, "as many points as the chart shows");
        assert_eq!(spec.models, [ForceModel::Proposed]);
    }

    #[test]
    fn only_keys_that_apply_to_the_shapes_are_offered() {
        let scene = fig5_scene();
        let keys = sweepable_keys(&scene);
        let radius2 = SceneKey::Body(BodyIndex::Two, BodyField::Radius);
        let mass2 = SceneKey::Body(BodyIndex::Two, BodyField::Mass);
        let mass1 = SceneKey::Body(BodyIndex::One, BodyField::Mass);
        assert!(!keys.contains(&radius2), "the plane has no radius");
        assert!(!keys.contains(&mass2), "the plane's mass is infinite");
        assert!(
            keys.contains(&mass1),
            "a derived mass sweeps from its value"
        );
        assert!(!keys.contains(&SceneKey::Body(BodyIndex::One, BodyField::Length)));
        // Cycling the parameter visits them in order and resets the range.
        let mut s = SweepSettings {
            custom: Some(SweepRange {
                from: 1.0,
                to: 2.0,
                log: false,
            }),
            ..SweepSettings::default()
        };
        assert!(s.nudge(SweepField::Parameter, Nudge::Up, &scene, 100));
        assert_eq!(s.key, SceneKey::Restitution);
        assert_eq!(s.custom, None);
        assert_eq!(
            s.range(&scene),
            Some(SweepRange {
                from: 0.05,
                to: 1.0,
                log: false
            })
        );
        assert!(s.nudge(SweepField::Parameter, Nudge::Down, &scene, 100));
        assert!(s.nudge(SweepField::Parameter, Nudge::Down, &scene, 100));
        assert_eq!(s.key, *keys.last().unwrap(), "wraps backwards");
    }

    #[test]
    fn bounds_take_units_and_points_stay_within_the_chart() {
        let scene = fig5_scene();
        let mut s = SweepSettings::default();
        s.apply(SweepField::From, "10 mm/s", &scene).unwrap();
        let range = s.range(&scene).unwrap();
        assert!((range.from - 0.01).abs() < 1e-15);
        assert!((range.to - 3.0).abs() < 1e-12, "the other bound is kept");
        assert!(s.apply(SweepField::To, "fast", &scene).is_err());
        assert_eq!(s.edit_text(SweepField::From, &scene), "0.01 m/s");
        assert!(s.apply(SweepField::Points, "1", &scene).is_err());
        s.apply(SweepField::Points, "1000", &scene).unwrap();
        assert_eq!(
            s.effective_points(300),
            300,
            "never more than the chart shows"
        );
        assert_eq!(
            s.display(SweepField::Points, &scene, 300),
            "300 (chart shows ≤ 300)"
        );
        assert!(s.nudge(SweepField::Points, Nudge::Down, &scene, 300));
        assert_eq!(s.points, Some(150));
        s.apply(SweepField::Points, "auto", &scene).unwrap();
        assert_eq!(s.display(SweepField::Points, &scene, 300), "auto (300)");
        assert_eq!(s.display_within(SweepField::Points, &scene, 300, 10), "auto (300)");
        assert_eq!(s.display_within(SweepField::Points, &scene, 300, 9), "300");
        s.output = SweepOutput::EOut;
        assert_eq!(
            s.display_within(SweepField::Output, &scene, 300, 26),
            "e_out realized restitution"
        );
        assert_eq!(s.display_within(SweepField::Output, &scene, 300, 25), "e_out");
        assert!(s.nudge(SweepField::Scale, Nudge::Up, &scene, 300));
        assert_eq!(s.display(SweepField::Scale, &scene, 300), "linear");
    }
}
