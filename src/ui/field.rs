//! The editable fields of the form panes: what each shows, how it parses, how it nudges.
//!
//! Numeric fields are the model's [`SceneKey`]s; the UI adds units, display prefixes and steps.

use crate::format::units::{self, Prefix, Unit};
use crate::model::body::Shape;
use crate::model::impact::{MethodChoice, SolveOptions, UnknownMethod};
use crate::model::ode::Method;
use crate::model::scene::Scene;
use crate::model::scene_key::{BodyField, BodyIndex, SceneKey};
use crate::model::system::SystemSpec;

/// One row of a form pane.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Field {
    Shape(BodyIndex),
    Number(SceneKey),
    Method,
    Rtol,
    /// The step of fixed-step methods (`auto`: the solver's t_c/1000 of the elastic estimate).
    Dt,
}

/// The pane a field belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Section {
    Body(BodyIndex),
    Impact,
}

impl Section {
    pub const ALL: [Section; 3] = [
        Section::Body(BodyIndex::One),
        Section::Body(BodyIndex::Two),
        Section::Impact,
    ];
}

/// Up or down, for nudges.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Nudge {
    Up,
    Down,
}

/// Dimensions a body remembers while it is a plane, so that switching shapes back restores them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dims {
    pub radius: f64,
    pub length: f64,
}

/// Length given to a body that becomes a cylinder without a remembered length, m.
const DEFAULT_LENGTH: f64 = 0.1;
/// Radius given to a body that becomes curved without a remembered radius, m.
const DEFAULT_RADIUS: f64 = 0.01;

impl Dims {
    pub fn of(shape: Shape) -> Dims {
        match shape {
            Shape::Sphere { radius } => Dims {
                radius,
                length: DEFAULT_LENGTH,
            },
            Shape::Cylinder { radius, length } => Dims { radius, length },
            Shape::Plane => Dims {
                radius: DEFAULT_RADIUS,
                length: DEFAULT_LENGTH,
            },
        }
    }
}

/// What the forms edit: the scene, the solver options and the remembered dimensions, and the
/// scene's `[system]` table (edited by the system view): one value, so that `u` undoes an edit of
/// either and `s` saves both.
#[derive(Debug, Clone, PartialEq)]
pub struct Draft {
    pub scene: Scene,
    pub options: SolveOptions,
    pub dims: [Dims; 2],
    pub system: Option<SystemSpec>,
}

impl Draft {
    pub fn new(scene: Scene, options: SolveOptions) -> Draft {
        let dims = [Dims::of(scene.body1.shape), Dims::of(scene.body2.shape)];
        Draft {
            scene,
            options,
            dims,
            system: None,
        }
    }

    /// The draft with `system` as its `[system]` table.
    pub fn with_system(mut self, system: Option<SystemSpec>) -> Draft {
        self.system = system;
        self
    }
}

/// Choices of the method field, in nudge order.
pub fn method_choices() -> Vec<MethodChoice> {
    std::iter::once(MethodChoice::Auto)
        .chain(Method::ALL.into_iter().map(MethodChoice::Integrator))
        .collect()
}

/// The word of the solver's own step.
const DT_AUTO: &str = "auto";

const SHAPES: [&str; 3] = ["sphere", "cylinder", "plane"];

/// The words that clear a given mass back to density × volume.
const MASS_FROM_DENSITY: [&str; 3] = ["auto", "density", "ρ"];

/// Whether the chosen method steps at a fixed size (so takes a step, not a tolerance).
pub fn is_fixed_step(method: MethodChoice) -> bool {
    matches!(method, MethodChoice::Integrator(m) if !m.is_adaptive())
}

/// The visible rows of a section, in order (a plane has no radius, only a cylinder a length;
/// a fixed-step method has a step, the others a tolerance).
pub fn fields_of(section: Section, draft: &Draft) -> Vec<Field> {
    let scene = &draft.scene;
    match section {
        Section::Body(index) => {
            let body = match index {
                BodyIndex::One => &scene.body1,
                BodyIndex::Two => &scene.body2,
            };
            let key = |field| Field::Number(SceneKey::Body(index, field));
            let mut rows = vec![Field::Shape(index)];
            match body.shape {
                Shape::Sphere { .. } => rows.push(key(BodyField::Radius)),
                Shape::Cylinder { .. } => {
                    rows.push(key(BodyField::Radius));
                    rows.push(key(BodyField::Length));
                }
                Shape::Plane => {}
            }
            rows.extend(
                [
                    BodyField::Mass,
                    BodyField::YoungsModulus,
                    BodyField::PoissonRatio,
                    BodyField::YieldStress,
                    BodyField::Density,
                ]
                .map(key),
            );
            rows
        }
        Section::Impact => vec![
            Field::Number(SceneKey::V0),
            Field::Number(SceneKey::Restitution),
            Field::Number(SceneKey::PlasticIndentation),
            Field::Method,
            if is_fixed_step(draft.options.method) {
                Field::Dt
            } else {
                Field::Rtol
            },
        ],
    }
}

/// Every visible row, sections in order.
pub fn all_fields(draft: &Draft) -> Vec<Field> {
    Section::ALL
        .iter()
        .flat_map(|&s| fields_of(s, draft))
        .collect()
}

pub(super) fn body(scene: &Scene, index: BodyIndex) -> &crate::model::Body {
    match index {
        BodyIndex::One => &scene.body1,
        BodyIndex::Two => &scene.body2,
    }
}

pub(super) fn body_mut(scene: &mut Scene, index: BodyIndex) -> &mut crate::model::Body {
    match index {
        BodyIndex::One => &mut scene.body1,
        BodyIndex::Two => &mut scene.body2,
    }
}

fn slot(index: BodyIndex) -> usize {
    match index {
        BodyIndex::One => 0,
        BodyIndex::Two => 1,
    }
}

impl Field {
    pub fn section(self) -> Section {
        match self {
            Field::Shape(index) | Field::Number(SceneKey::Body(index, _)) => Section::Body(index),
            Field::Number(_) | Field::Method | Field::Rtol | Field::Dt => Section::Impact,
        }
    }

    /// The short label shown left of the value.
    pub fn label(self) -> &'static str {
        match self {
            Field::Shape(_) => "shape",
            Field::Method => "method",
            Field::Rtol => "rtol",
            Field::Dt => "dt",
            Field::Number(key) => units::key_label(key),
        }
    }

    /// What the field means, for the help line under the form.
    pub fn description(self) -> &'static str {
        match self {
            Field::Shape(_) => "sphere, cylinder (parallel axes) or plane",
            Field::Method => "solution path: auto picks exact, then explicit, then implicit",
            Field::Rtol => "relative tolerance of adaptive methods",
            Field::Dt => "step of fixed-step methods; `auto` for t_c/1000 of the elastic estimate",
            Field::Number(key) => match key {
                SceneKey::V0 => "pre-impact relative velocity",
                SceneKey::Restitution => "coefficient of restitution, in (0, 1]",
                SceneKey::PlasticIndentation => "plastic indentation of the proposed model",
                SceneKey::Body(_, field) => match field {
                    BodyField::Radius => "radius of curvature at the contact",
                    BodyField::Length => "cylinder length",
                    BodyField::Mass => "mass; `auto` for density × volume",
                    BodyField::YoungsModulus => "Young's modulus",
                    BodyField::PoissonRatio => "Poisson's ratio, in [0, 0.5)",
                    BodyField::YieldStress => "uniaxial yield stress",
                    BodyField::Density => "density",
                },
            },
        }
    }

    /// The unit of the field's value.
    pub fn unit(self) -> Unit {
        match self {
            Field::Shape(_) | Field::Method | Field::Rtol => units::DIMENSIONLESS,
            Field::Dt => units::SECOND,
            Field::Number(key) => units::key_unit(key),
        }
    }

    /// The prefix values are shown in; `None` picks an engineering prefix per value.
    fn display_prefix(self) -> Option<Prefix> {
        match self {
            Field::Number(SceneKey::PlasticIndentation) => Some(units::MICRO),
            Field::Number(SceneKey::Body(_, field)) => match field {
                BodyField::Radius | BodyField::Length => Some(units::MILLI),
                BodyField::Mass => None,
                BodyField::YoungsModulus => Some(units::GIGA),
                BodyField::YieldStress => Some(units::MEGA),
                BodyField::PoissonRatio | BodyField::Density => Some(units::NONE),
            },
            _ => Some(units::NONE),
        }
    }

    fn format(self, value_si: f64) -> String {
        if matches!(
            self,
            Field::Number(SceneKey::Restitution | SceneKey::Body(_, BodyField::PoissonRatio))
        ) {
            // Every digit, so that an edit starts from the value itself: ν = 0.4999999999 is
            // valid, the 0.5 six digits would show is not.
            return crate::format::round_trip(value_si);
        }
        match self.display_prefix() {
            Some(prefix) => units::with_prefix(value_si, self.unit(), prefix, 6),
            None => units::engineering(value_si, self.unit(), 6),
        }
    }

    /// The value as the pane shows it, e.g. `10 mm`, `200 GPa`, `32.6726 g (from ρ)`.
    pub fn display(self, draft: &Draft) -> String {
        match self {
            Field::Number(SceneKey::Body(index, BodyField::Mass)) => {
                let body = body(&draft.scene, index);
                match body.mass {
                    Some(mass) => self.format(mass),
                    None => format!("{} (from ρ)", self.format(body.mass())),
                }
            }
            _ => self.edit_text(draft),
        }
    }

    /// The text an edit starts from.
    pub fn edit_text(self, draft: &Draft) -> String {
        match self {
            Field::Shape(index) => body(&draft.scene, index).shape.name().to_string(),
            Field::Method => draft.options.method.to_string(),
            Field::Rtol => units::sig(draft.options.rtol, 3),
            Field::Dt => match draft.options.dt {
                Some(dt) => units::engineering(dt, units::SECOND, 4),
                None => DT_AUTO.to_string(),
            },
            Field::Number(SceneKey::Body(index, BodyField::Mass))
                if body(&draft.scene, index).mass.is_none() =>
            {
                MASS_FROM_DENSITY[0].to_string()
            }
            Field::Number(key) => match key.get(&draft.scene) {
                Some(value) => self.format(value),
                None => String::new(),
            },
        }
    }

    /// Parses `text` and stores it in the draft. Validation is the model's job, afterwards.
    pub fn apply(self, text: &str, draft: &mut Draft) -> Result<(), String> {
        match self {
            Field::Shape(index) => {
                let word = text.trim().to_lowercase();
                let shape = SHAPES
                    .iter()
                    .find(|s| !word.is_empty() && s.starts_with(&word))
                    .ok_or_else(|| {
                        format!("unknown shape '{}' (sphere, cylinder, plane)", text.trim())
                    })?;
                set_shape(draft, index, shape);
                Ok(())
            }
            Field::Method => {
                draft.options.method = text
                    .trim()
                    .parse()
                    .map_err(|e: UnknownMethod| e.to_string())?;
                Ok(())
            }
            Field::Rtol => {
                let rtol = units::parse(text, units::DIMENSIONLESS)?;
                if !(rtol > 0.0 && rtol < 1.0) {
                    return Err(format!(
                        "rtol must be > 0 and < 1 (a relative tolerance), got {}",
                        units::sig(rtol, 4)
                    ));
                }
                draft.options.rtol = rtol;
                Ok(())
            }
            Field::Dt => {
                if text.trim().eq_ignore_ascii_case(DT_AUTO) {
                    draft.options.dt = None;
                    return Ok(());
                }
                let dt = units::parse(text, units::SECOND)?;
                if !(dt > 0.0 && dt.is_finite()) {
                    return Err(format!(
                        "dt must be > 0 and finite (a step size), got {}",
                        units::sig(dt, 4)
                    ));
                }
                draft.options.dt = Some(dt);
                Ok(())
            }
            Field::Number(SceneKey::Body(index, BodyField::Mass))
                if MASS_FROM_DENSITY.contains(&text.trim()) =>
            {
                body_mut(&mut draft.scene, index).mass = None;
                Ok(())
            }
            Field::Number(key) => {
                let value = units::parse(text, self.unit())?;
                key.set(&mut draft.scene, value)
                    .map_err(|e| e.to_string())?;
                remember(draft);
                Ok(())
            }
        }
    }

    /// Steps the value up or down: to the next choice, or by a step of the value's second
    /// significant digit (0.3 → 0.31, 10 mm → 11 mm); the rtol by decades, the dt by halves.
    /// Returns whether it changed.
    pub fn nudge(self, direction: Nudge, draft: &mut Draft) -> bool {
        match self {
            Field::Shape(index) => {
                let current = body(&draft.scene, index).shape.name();
                let next = cycle(&SHAPES, &current, direction);
                set_shape(draft, index, next);
                true
            }
            Field::Method => {
                let choices = method_choices();
                let next = cycle(&choices, &draft.options.method, direction);
                draft.options.method = *next;
                true
            }
            Field::Rtol => {
                let rtol = draft.options.rtol;
                if !(rtol > 0.0 && rtol < 1.0) {
                    // Not reachable by typing (refused): never a jump from a bad value.
                    return false;
                }
                let exponent = rtol.log10().round() as i32
                    + match direction {
                        Nudge::Up => 1,
                        Nudge::Down => -1,
                    };
                let next = 10f64.powi(exponent.clamp(-14, -1));
                let changed = next != rtol;
                draft.options.rtol = next;
                changed
            }
            Field::Dt => {
                // `auto` has no value here: the caller seeds it with the solver's default first.
                let Some(dt) = draft.options.dt else {
                    return false;
                };
                let next = match direction {
                    Nudge::Up => dt * 2.0,
                    Nudge::Down => dt / 2.0,
                };
                if !(dt > 0.0 && dt.is_finite() && next > 0.0 && next.is_finite()) {
                    return false;
                }
                draft.options.dt = Some(next);
                true
            }
            Field::Number(key) => {
                let current = match key {
                    SceneKey::Body(index, BodyField::Mass) => body(&draft.scene, index).mass(),
                    _ => match key.get(&draft.scene) {
                        Some(value) => value,
                        None => return false,
                    },
                };
                let Some(next) = nudged(current, direction, self.zero_step()) else {
                    return false;
                };
                let changed = key.set(&mut draft.scene, next).is_ok();
                remember(draft);
                changed
            }
        }
    }

    /// The step of a field whose value is zero (only x_pl may be).
    fn zero_step(self) -> f64 {
        match self {
            Field::Number(SceneKey::PlasticIndentation) => 1e-7,
            _ => 0.01,
        }
    }
}

fn cycle<'a, T: PartialEq>(choices: &'a [T], current: &T, direction: Nudge) -> &'a T {
    let n = choices.len();
    let i = choices.iter().position(|c| c == current).unwrap_or(0);
    let j = match direction {
        Nudge::Up => (i + 1) % n,
        Nudge::Down => (i + n - 1) % n,
    };
    &choices[j]
}

/// `value` moved by one unit of its second significant digit, rounded onto that grid. Going down
/// uses the grid of the value just below, so that up then down returns to the start.
pub fn nudged(value: f64, direction: Nudge, zero_step: f64) -> Option<f64> {
    if !value.is_finite() {
        return None;
    }
    let probe = match direction {
        Nudge::Up => value.abs(),
        Nudge::Down => value.abs() * (1.0 - 1e-9),
    };
    let exponent = if probe > 0.0 {
        probe.log10().floor() as i32 - 1
    } else {
        zero_step.log10().round() as i32
    };
    let moved = |v: f64| match direction {
        Nudge::Up => v + 1.0,
        Nudge::Down => v - 1.0,
    };
    // Integer steps on a decimal grid: k·10^p, computed so that 0.31 prints as 0.31.
    let next = if exponent < 0 {
        let scale = 10f64.powi(-exponent);
        moved((value * scale).round()) / scale
    } else {
        let step = 10f64.powi(exponent);
        moved((value / step).round()) * step
    };
    Some(next)
}

fn set_shape(draft: &mut Draft, index: BodyIndex, name: &str) {
    let dims = draft.dims[slot(index)];
    let shape = match name {
        "sphere" => Shape::Sphere {
            radius: dims.radius,
        },
        "cylinder" => Shape::Cylinder {
            radius: dims.radius,
            length: dims.length,
        },
        _ => Shape::Plane,
    };
    body_mut(&mut draft.scene, index).shape = shape;
}

/// Records the current radius and length of both bodies for later shape switches.
fn remember(draft: &mut Draft) {
    for index in [BodyIndex::One, BodyIndex::Two] {
        let dims = &mut draft.dims[slot(index)];
        match body(&draft.scene, index).shape {
            Shape::Sphere { radius } => dims.radius = radius,
            Shape::Cylinder { radius, length } => {
                dims.radius = radius;
                dims.length = length;
            }
            Shape::Plane => {}
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ui::testing::fig5_scene;

    fn draft() -> Draft {
        Draft::new(fig5_scene(), SolveOptions::default())
    }

    const V0: Field = Field::Number(SceneKey::V0);
    const R1: Field = Field::Number(SceneKey::Body(BodyIndex::One, BodyField::Radius));
    const MASS1: Field = Field::Number(SceneKey::Body(BodyIndex::One, BodyField::Mass));

    #[test]
    fn displays_carry_units() {
        let d = draft();
        assert_eq!(R1.display(&d), "10 mm");
        assert_eq!(V0.display(&d), "0.3 m/s");
        assert_eq!(
            Field::Number(SceneKey::PlasticIndentation).display(&d),
            "2.3 µm"
        );
        let e1 = Field::Number(SceneKey::Body(BodyIndex::One, BodyField::YoungsModulus));
        assert_eq!(e1.display(&d), "200 GPa");
        assert!(
            MASS1.display(&d).ends_with("g (from ρ)"),
            "{}",
            MASS1.display(&d)
        );
        assert_eq!(MASS1.edit_text(&d), "auto");
        assert_eq!(Field::Rtol.display(&d), "1e-8");
        assert_eq!(Field::Method.display(&d), "auto");
    }

    #[test]
    fn poisson_ratio_and_restitution_show_every_digit() {
        let mut d = draft();
        let nu1 = Field::Number(SceneKey::Body(BodyIndex::One, BodyField::PoissonRatio));
        let e = Field::Number(SceneKey::Restitution);
        assert_eq!(
            (nu1.display(&d), e.display(&d)),
            ("0.3".into(), "0.6".into())
        );
        // Six digits would show 0.5, which the model refuses, and an edit would start from it.
        nu1.apply("0.4999999999", &mut d).unwrap();
        e.apply("0.99999999", &mut d).unwrap();
        assert_eq!(nu1.edit_text(&d), "0.4999999999");
        assert_eq!(e.edit_text(&d), "0.99999999");
        let before = d.clone();
        nu1.apply(&nu1.edit_text(&d), &mut d).unwrap();
        assert_eq!(d, before, "the text reads back as the value");
    }

    #[test]
    fn apply_parses_units_and_prefixes() {
        let mut d = draft();
        R1.apply("12 mm", &mut d).unwrap();
        assert_eq!(d.scene.body1.shape, Shape::Sphere { radius: 0.012 });
        V0.apply("500m", &mut d).unwrap();
        assert_eq!(d.scene.impact.v0, 0.5);
        MASS1.apply("40 g", &mut d).unwrap();
        assert_eq!(d.scene.body1.mass, Some(0.04));
        MASS1.apply("auto", &mut d).unwrap();
        assert_eq!(d.scene.body1.mass, None);
        Field::Method.apply("radau5", &mut d).unwrap();
        assert_eq!(d.options.method, MethodChoice::Integrator(Method::Radau5));
        assert!(Field::Method.apply("magic", &mut d).is_err());
        let before = d.clone();
        assert_eq!(
            V0.apply("fast", &mut d).unwrap_err(),
            "'fast' is not a number"
        );
        assert_eq!(d, before, "a failed parse leaves the draft alone");
    }

    #[test]
    fn shapes_switch_and_remember_dimensions() {
        let mut d = draft();
        let shape1 = Field::Shape(BodyIndex::One);
        shape1.apply("cyl", &mut d).unwrap();
        assert_eq!(
            d.scene.body1.shape,
            Shape::Cylinder {
                radius: 0.01,
                length: 0.1
            }
        );
        assert!(
            fields_of(Section::Body(BodyIndex::One), &d).contains(&Field::Number(SceneKey::Body(
                BodyIndex::One,
                BodyField::Length
            )))
        );
        R1.apply("20 mm", &mut d).unwrap();
        shape1.apply("plane", &mut d).unwrap();
        assert!(!fields_of(Section::Body(BodyIndex::One), &d).contains(&R1));
        shape1.nudge(Nudge::Up, &mut d);
        assert_eq!(d.scene.body1.shape, Shape::Sphere { radius: 0.02 });
        assert!(shape1.apply("cube", &mut d).is_err());
    }

    #[test]
    fn nudges_step_the_second_digit_and_reverse() {
        assert_eq!(nudged(0.3, Nudge::Up, 0.01), Some(0.31));
        assert_eq!(nudged(0.3, Nudge::Down, 0.01), Some(0.29));
        assert_eq!(nudged(0.1, Nudge::Down, 0.01), Some(0.099));
        assert_eq!(nudged(0.099, Nudge::Up, 0.01), Some(0.1));
        assert_eq!(nudged(0.1, Nudge::Up, 0.01), Some(0.11));
        assert_eq!(nudged(0.11, Nudge::Down, 0.01), Some(0.1));
        assert_eq!(nudged(2e11, Nudge::Up, 0.01), Some(2.1e11));
        assert_eq!(nudged(0.0, Nudge::Up, 1e-7), Some(1e-7));
        assert_eq!(nudged(f64::INFINITY, Nudge::Up, 0.01), None);
        let mut d = draft();
        assert!(V0.nudge(Nudge::Up, &mut d));
        assert_eq!(d.scene.impact.v0, 0.31);
        for bad in ["0", "-1e-6", "1", "3", "nan"] {
            let before = d.options.rtol;
            let error = Field::Rtol.apply(bad, &mut d).unwrap_err();
            assert!(
                error.contains("rtol") || error.contains("number"),
                "{bad}: {error}"
            );
            assert_eq!(
                d.options.rtol, before,
                "{bad} is refused, the last rtol stays"
            );
        }
        for bad in [0.0, -1.0, f64::NAN] {
            let mut d = draft();
            d.options.rtol = bad;
            assert!(
                !Field::Rtol.nudge(Nudge::Down, &mut d),
                "← from {bad} does not jump"
            );
            assert!(d.options.rtol == bad || bad.is_nan());
        }
        assert!(Field::Rtol.nudge(Nudge::Down, &mut d));
        assert_eq!(d.options.rtol, 1e-9);
        // The derived mass becomes a given one when nudged.
        assert!(MASS1.nudge(Nudge::Up, &mut d));
        assert!(d.scene.body1.mass.is_some());
    }

    #[test]
    fn rows_follow_the_shapes() {
        let d = draft();
        let rows = all_fields(&d);
        // Sphere: shape, R, mass, 4 material rows; plane: shape, mass, 4; impact: 5.
        assert_eq!(rows.len(), 7 + 6 + 5);
        assert_eq!(rows[0], Field::Shape(BodyIndex::One));
        assert!(rows.iter().all(|f| !f.label().is_empty()));
    }
}
