//! The charts of a vibro-impact system (docs/systems.md): its time history with the stops, its
//! phase portrait, its impact map and its bifurcation diagram, each with the rigid and the
//! compliant answer overlaid, every approach in its own ink and glyph (the rigid stop in the
//! foreground with [`RIGID_GLYPH`], a compliant stop in its law's hue and glyph).
//!
//! The builders take plain data in SI units ([`Motion`], [`Branch`]), so that the explorer and
//! `hertz-tui plot` draw the same charts from whatever the model gives.

use std::f64::consts::TAU;

use crate::chart::ticks::{NiceAxis, axis_title, nice_axis, span};
use crate::chart::{Chart, Ink, Rule, Series, model_glyph};
use crate::format::units::{self, Unit, key_label, key_unit};
use crate::model::ForceModel;
use crate::model::system::{Column, Contact, History, Param, SystemKey, SystemModel};

/// The glyph of the rigid (instantaneous-impact) answer: none of the laws' glyphs.
pub const RIGID_GLYPH: char = 'R';

/// The glyph and ink of a stop drawn as a curve (a table that moves).
const STOP_GLYPH: char = '=';

/// Whose answer a curve is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Approach {
    /// Instantaneous impacts, Newton's restitution.
    Rigid,
    /// A contact force through the impact, by this law of the table.
    Compliant(ForceModel),
}

impl Approach {
    /// Its name, ink and glyph on every chart.
    pub fn look(self) -> (String, Ink, char) {
        match self {
            Approach::Rigid => ("rigid".to_string(), Ink::Foreground, RIGID_GLYPH),
            Approach::Compliant(m) => (m.name().to_string(), Ink::Model(m), model_glyph(m)),
        }
    }
}

/// One approach's motion: samples (t, x, v) of the body and the impacts' (phase, incoming
/// speed), SI units, the phase ωt mod 2π in radians.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Motion {
    pub samples: Vec<(f64, f64, f64)>,
    pub impacts: Vec<(f64, f64)>,
}

/// Where the stops are: fixed positions (an oscillator's gaps), or a stop that moves, sampled
/// (t, position) (the bouncing ball's table).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Stops {
    pub fixed: Vec<f64>,
    pub moving: Vec<(f64, f64)>,
}

/// One approach's bifurcation diagram: per parameter value (SI), the recorded points (SI).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Branch {
    pub columns: Vec<(f64, Vec<f64>)>,
}

/// What the diagram's points are and the parameter it is drawn over.
#[derive(Debug, Clone, PartialEq)]
pub struct DiagramAxes {
    /// The parameter's symbol, e.g. `A` or `Γ`.
    pub key: String,
    pub key_unit: Unit,
    /// The recorded quantity's symbol, e.g. `v_in`.
    pub quantity: String,
    pub quantity_unit: Unit,
    /// The parameter's span drawn, SI (every value asked for, while the columns fill it in);
    /// `None`: the columns'.
    pub range: Option<(f64, f64)>,
}

impl Approach {
    /// The approach of a model's contact.
    pub fn of(contact: &Contact) -> Approach {
        match contact {
            Contact::Rigid { .. } => Approach::Rigid,
            Contact::Compliant { model, .. } => Approach::Compliant(*model),
        }
    }
}

impl Motion {
    /// The samples of `history` from `from` s on, and all its impacts.
    pub fn of(history: &History, from: f64) -> Motion {
        Motion {
            samples: history
                .samples
                .iter()
                .filter(|s| s.t >= from)
                .map(|s| (s.t, s.x, s.v))
                .collect(),
            impacts: history.impacts.iter().map(|i| (i.phase, i.v_in)).collect(),
        }
    }
}

impl Stops {
    /// The stops of `model`: the oscillator's fixed gaps, or the bouncing ball's table as `history`
    /// sampled it from `from` s on.
    pub fn of(model: &SystemModel, history: Option<&History>, from: f64) -> Stops {
        use crate::model::system::SystemKind;
        match model.spec.kind {
            SystemKind::BouncingBall { .. } => Stops {
                fixed: Vec::new(),
                moving: history
                    .map(|h| {
                        h.samples
                            .iter()
                            .filter(|s| s.t >= from)
                            .map(|s| (s.t, s.stop))
                            .collect()
                    })
                    .unwrap_or_default(),
            },
            SystemKind::ImpactOscillator {
                gap, second_gap, ..
            } => Stops {
                fixed: std::iter::once(gap).chain(second_gap.map(|g| -g)).collect(),
                moving: Vec::new(),
            },
        }
    }
}

impl Branch {
    /// The impact speeds of every column.
    pub fn of(columns: &[Column]) -> Branch {
        Branch {
            columns: columns
                .iter()
                .map(|c| (c.value, c.velocities.clone()))
                .collect(),
        }
    }
}

impl DiagramAxes {
    /// A diagram of the impact speeds over `param` of `model` (the forcing amplitude is a force or
    /// a base motion by the model's forcing).
    pub fn impact_speeds(param: Param, model: &SystemModel) -> DiagramAxes {
        use crate::model::system::{Forcing, SystemKind};
        let (key, key_unit) = match param {
            Param::Scene(key) => (key_label(key).to_string(), key_unit(key)),
            Param::System(key) => {
                let base = matches!(
                    model.spec.kind,
                    SystemKind::ImpactOscillator {
                        forcing: Forcing::Base { .. },
                        ..
                    }
                );
                let symbol = match key {
                    SystemKey::Amplitude => "A",
                    SystemKey::Gamma => "Γ",
                    SystemKey::Frequency => "f",
                    SystemKey::Gravity => "g",
                    SystemKey::Stiffness => "k",
                    SystemKey::DampingRatio => "ζ",
                    SystemKey::Damping => "c",
                    SystemKey::ForcingAmplitude if base => "B",
                    SystemKey::ForcingAmplitude => "F₀",
                    SystemKey::Gap => "gap",
                    SystemKey::SecondGap => "second gap",
                };
                (symbol.to_string(), units::system_key_unit(key, base))
            }
        };
        DiagramAxes {
            key,
            key_unit,
            quantity: "v_in".into(),
            quantity_unit: units::METRE_PER_SECOND,
            range: None,
        }
    }
}

/// A series of `approach` over `runs` of display points; the rigid answer is drawn last and
/// bold (it is the reference the compliant stops are read against).
fn series(approach: Approach, runs: Vec<Vec<(f64, f64)>>) -> Series {
    let (name, ink, glyph) = approach.look();
    Series {
        name,
        ink,
        glyph,
        runs,
        focused: approach == Approach::Rigid,
        peak: None,
        steps: false,
    }
}

/// A chart on `x` and `y` with its series, compliant ones first.
fn assemble(
    title: String,
    (x, x_title): (NiceAxis, String),
    (y, y_title): (NiceAxis, String),
    mut series: Vec<Series>,
) -> Chart {
    series.sort_by_key(|s| s.focused);
    Chart::new(title, x.chart_axis(x_title), y.chart_axis(y_title), series)
}

/// x(t) of every approach with the stops: fixed stops as horizontal rules, a moving one as a
/// curve of its own. At most `max_x` × `max_y` tick labels.
pub fn time_history(
    motions: &[(Approach, &Motion)],
    stops: &Stops,
    (max_x, max_y): (usize, usize),
) -> Chart {
    let ts = motions
        .iter()
        .flat_map(|(_, m)| m.samples.iter().map(|s| s.0));
    let (t0, t1) = span(ts.chain(stops.moving.iter().map(|s| s.0))).unwrap_or((0.0, 1.0));
    let xs = motions
        .iter()
        .flat_map(|(_, m)| m.samples.iter().map(|s| s.1));
    let (x0, x1) = span(
        xs.chain(stops.fixed.iter().copied())
            .chain(stops.moving.iter().map(|s| s.1)),
    )
    .unwrap_or((0.0, 1.0));
    let tx = nice_axis(t0, t1, units::SECOND, max_x);
    let xx = nice_axis(x0, x1, units::METRE, max_y);
    let display = |(t, x): (f64, f64)| (tx.to_display(t), xx.to_display(x));
    let mut all: Vec<Series> = motions
        .iter()
        .map(|(a, m)| {
            let run = m.samples.iter().map(|s| display((s.0, s.1))).collect();
            series(*a, vec![run])
        })
        .collect();
    if !stops.moving.is_empty() {
        all.insert(
            0,
            Series {
                name: "stop".into(),
                ink: Ink::Warning,
                glyph: STOP_GLYPH,
                runs: vec![stops.moving.iter().map(|&p| display(p)).collect()],
                focused: false,
                peak: None,
                steps: false,
            },
        );
    }
    let x_title = axis_title("t", &tx, units::SECOND);
    let y_title = axis_title("x", &xx, units::METRE);
    let mut chart = assemble(
        "x(t) time history".into(),
        (tx, x_title),
        (xx.clone(), y_title),
        all,
    );
    chart.rules = stops
        .fixed
        .iter()
        .map(|&s| Rule {
            at: xx.to_display(s),
            horizontal: true,
            ink: Ink::Warning,
            label: "stop".into(),
        })
        .collect();
    chart
}

/// v(x) of every approach: the phase portrait, the fixed stops as vertical rules.
pub fn phase_portrait(
    motions: &[(Approach, &Motion)],
    stops: &Stops,
    (max_x, max_y): (usize, usize),
) -> Chart {
    let xs = motions
        .iter()
        .flat_map(|(_, m)| m.samples.iter().map(|s| s.1));
    let (x0, x1) = span(xs.chain(stops.fixed.iter().copied())).unwrap_or((0.0, 1.0));
    let vs = motions
        .iter()
        .flat_map(|(_, m)| m.samples.iter().map(|s| s.2));
    let (v0, v1) = span(vs).unwrap_or((-1.0, 1.0));
    let xx = nice_axis(x0, x1, units::METRE, max_x);
    let vx = nice_axis(v0, v1, units::METRE_PER_SECOND, max_y);
    let all = motions
        .iter()
        .map(|(a, m)| {
            let run = m
                .samples
                .iter()
                .map(|s| (xx.to_display(s.1), vx.to_display(s.2)))
                .collect();
            series(*a, vec![run])
        })
        .collect();
    let x_title = axis_title("x", &xx, units::METRE);
    let y_title = axis_title("v", &vx, units::METRE_PER_SECOND);
    let mut chart = assemble(
        "v(x) phase portrait".into(),
        (xx.clone(), x_title),
        (vx, y_title),
        all,
    );
    chart.rules = stops
        .fixed
        .iter()
        .map(|&s| Rule {
            at: xx.to_display(s),
            horizontal: false,
            ink: Ink::Warning,
            label: "stop".into(),
        })
        .collect();
    chart
}

/// Each point alone in a run of its own: a scatter, never joined.
fn scatter(points: impl Iterator<Item = (f64, f64)>) -> Vec<Vec<(f64, f64)>> {
    points
        .filter(|p| p.0.is_finite() && p.1.is_finite())
        .map(|p| vec![p])
        .collect()
}

/// The impact map: each recorded impact's incoming speed against its phase ωt mod 2π (a
/// Poincaré section at the impacts; a periodic orbit is a few points, chaos a cloud).
pub fn impact_map(motions: &[(Approach, &Motion)], (max_x, max_y): (usize, usize)) -> Chart {
    let speeds = motions
        .iter()
        .flat_map(|(_, m)| m.impacts.iter().map(|i| i.1));
    let (lo, hi) = span(speeds).unwrap_or((0.0, 1.0));
    let phase = nice_axis(0.0, TAU, units::DIMENSIONLESS, max_x);
    let speed = nice_axis(lo.min(0.0), hi.max(0.0), units::METRE_PER_SECOND, max_y);
    let all = motions
        .iter()
        .map(|(a, m)| {
            let points = m
                .impacts
                .iter()
                .map(|&(p, v)| (phase.to_display(p), speed.to_display(v)));
            series(*a, scatter(points))
        })
        .collect();
    let y_title = axis_title("v_in", &speed, units::METRE_PER_SECOND);
    assemble(
        "impact map".into(),
        (phase, "φ = ωt mod 2π [rad]".into()),
        (speed, y_title),
        all,
    )
}

/// The bifurcation diagram: every recorded point of every column against the parameter, a
/// scatter per approach.
pub fn bifurcation(
    branches: &[(Approach, &Branch)],
    axes: &DiagramAxes,
    (max_x, max_y): (usize, usize),
) -> Chart {
    let values = branches
        .iter()
        .flat_map(|(_, b)| b.columns.iter().map(|c| c.0));
    let (k0, k1) = axes.range.or_else(|| span(values)).unwrap_or((0.0, 1.0));
    let points = branches
        .iter()
        .flat_map(|(_, b)| b.columns.iter().flat_map(|c| c.1.iter().copied()));
    let (p0, p1) = span(points).unwrap_or((0.0, 1.0));
    let kx = nice_axis(k0, k1, axes.key_unit, max_x);
    let py = nice_axis(p0.min(0.0), p1.max(0.0), axes.quantity_unit, max_y);
    let all = branches
        .iter()
        .map(|(a, b)| {
            let points = b.columns.iter().flat_map(|(k, ps)| {
                ps.iter()
                    .map(|&p| (kx.to_display(*k), py.to_display(p)))
                    .collect::<Vec<_>>()
            });
            series(*a, scatter(points))
        })
        .collect();
    let x_title = axis_title(&axes.key, &kx, axes.key_unit);
    let y_title = axis_title(&axes.quantity, &py, axes.quantity_unit);
    assemble(
        format!("bifurcation diagram over {}", axes.key),
        (kx, x_title),
        (py, y_title),
        all,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn motion(shift: f64) -> Motion {
        Motion {
            samples: (0..=100)
                .map(|i| {
                    let t = f64::from(i) * 1e-3;
                    (t, 1e-3 * (t * 50.0).sin() + shift, 0.05 * (t * 50.0).cos())
                })
                .collect(),
            impacts: vec![(1.0, 0.3), (4.0, 0.31)],
        }
    }

    #[test]
    fn the_rigid_answer_is_drawn_last_in_its_own_look_and_laws_in_theirs() {
        let (rigid, soft) = (motion(0.0), motion(1e-5));
        let law = ForceModel::HuntCrossley;
        let chart = time_history(
            &[(Approach::Rigid, &rigid), (Approach::Compliant(law), &soft)],
            &Stops {
                fixed: vec![1.2e-3],
                moving: Vec::new(),
            },
            (6, 6),
        );
        assert_eq!(chart.series.len(), 2);
        assert_eq!(chart.series[1].glyph, RIGID_GLYPH);
        assert!(chart.series[1].focused);
        assert_eq!(chart.series[0].ink, Ink::Model(law));
        assert_eq!(chart.series[0].glyph, model_glyph(law));
        for m in ForceModel::ALL {
            assert_ne!(model_glyph(m), RIGID_GLYPH, "{m}");
        }
        // The stop is a rule at its height, in the y axis's display unit (mm here).
        assert_eq!(chart.rules.len(), 1);
        assert!((chart.rules[0].at - 1.2).abs() < 1e-12, "{:?}", chart.rules);
        assert_eq!(chart.y.title, "x [mm]");
    }

    #[test]
    fn a_moving_stop_is_a_curve_and_impacts_are_points_never_joined() {
        let m = motion(0.0);
        let stops = Stops {
            fixed: Vec::new(),
            moving: vec![(0.0, 0.0), (0.1, 1e-4)],
        };
        let chart = time_history(&[(Approach::Rigid, &m)], &stops, (6, 6));
        assert_eq!(chart.series[0].name, "stop");
        let map = impact_map(&[(Approach::Rigid, &m)], (6, 6));
        assert_eq!(map.series[0].runs, [vec![(1.0, 0.3)], vec![(4.0, 0.31)]]);
        assert!(map.x.range[0] <= 0.0 && map.x.range[1] >= TAU);
    }

    #[test]
    fn a_diagram_places_each_point_at_its_value() {
        let branch = Branch {
            columns: vec![
                (2e-4, vec![0.1, 0.2]),
                (3e-4, vec![]),
                (4e-4, vec![f64::NAN, 0.4]),
            ],
        };
        let axes = DiagramAxes {
            key: "A".into(),
            key_unit: units::METRE,
            quantity: "v_in".into(),
            quantity_unit: units::METRE_PER_SECOND,
            range: None,
        };
        let chart = bifurcation(&[(Approach::Rigid, &branch)], &axes, (6, 6));
        assert_eq!(chart.x.title, "A [µm]");
        let points: Vec<(f64, f64)> = chart.series[0].runs.iter().map(|r| r[0]).collect();
        let expected = [(200.0, 0.1), (200.0, 0.2), (400.0, 0.4)];
        assert_eq!(points.len(), 3, "the NaN point is dropped");
        for (p, e) in points.iter().zip(expected) {
            assert!(
                (p.0 - e.0).abs() < 1e-9 && (p.1 - e.1).abs() < 1e-12,
                "{p:?}"
            );
        }
    }
}
