//! `b` in the system view: the periodic orbit the run settles on, continued over the diagram's
//! range (docs/continuation.md §8) as a study on the studies' queue, drawn over the brute-force
//! diagram (stable solid, unstable dotted, each stop in its own ink) with its special points
//! marked by their letter and listed with their values in the notes; and the doubled branch born
//! at its period doubling, in the doubled branch's look (stable dashed, its own glyph).

use crate::chart::Chart;
use crate::chart::continuation::{self as plot, BranchCurve};
use crate::chart::system::{Approach, Branch as DiagramBranch, DiagramAxes};
use crate::format::units::sig;
use crate::model::study::continuation::{ContinuationStudy, ContinuedBranches};
use crate::model::study::runner::{StudyKind, StudySpec};
use crate::model::study::system::DiagramData;
use crate::model::system::continuation::{Branch, ContinuationOptions, SpecialKind};
use crate::model::system::{Contact, OrbitGuess, SystemModel};
use crate::ui::app::App;
use crate::ui::rebind;
use crate::ui::style::Role;

use super::settings::{self, Settings};

/// The letter a special point is marked with on the chart and named by in the notes.
pub fn letter(kind: SpecialKind) -> &'static str {
    if kind.is_grazing() {
        "G"
    } else if kind == SpecialKind::Fold {
        "F"
    } else if kind == SpecialKind::PeriodDoubling {
        "PD"
    } else {
        kind.label()
    }
}

/// The key that shows and hides the branch (`b`, or the config file's `[keys] branch`).
fn key() -> String {
    rebind::key_for('b')
}

/// `b`: the branch on or off.
pub fn toggle(app: &mut App) {
    let on = !app.views.system.branch;
    app.views.system.branch = on;
    let key = key();
    let text = if on {
        format!("continuing the orbit over the diagram's range ({key} hides it)")
    } else {
        format!("continued branch hidden ({key} shows it)")
    };
    app.say(text, false);
}

/// The continuation the view asks for while the branch is on: the orbit the attractor run
/// settles on (its period found as the run's), over the diagram's key and range, every stop the
/// diagram draws. An edit changes the study's inputs, which supersedes the running one.
pub fn spec(settings: &Settings, model: &SystemModel, contacts: &[Contact]) -> StudySpec {
    StudySpec::Continuation(Box::new(ContinuationStudy {
        model: model.clone(),
        contacts: contacts.to_vec(),
        param: settings.diagram_key(model),
        range: settings.range(model),
        guess: OrbitGuess {
            forcing_cycles: 0,
            impacts: 0,
            start: None,
            attractor: settings::diagram_options(settings).run,
        },
        options: ContinuationOptions::default(),
    }))
}

/// The branches to draw: the view's branch is on and the result continues the diagram's key.
pub fn shown<'a>(app: &'a App, diagram: &DiagramData) -> Option<&'a ContinuedBranches> {
    if !app.views.system.branch {
        return None;
    }
    app.studies
        .continuation()
        .map(|c| &**c)
        .filter(|c| c.param == diagram.param)
}

/// Dashes of a doubled branch's stable stretch across the chart on a terminal: a plot about 50
/// cells wide shows each dash two cells long.
pub const TERMINAL_DASHES: usize = 16;

/// A half of a branch (or a doubled branch: `doubled`) as the chart draws it: every impact's v_in
/// against the key, by stability, with its special points marked by their letter.
fn curve(half: &Branch, doubled: bool) -> BranchCurve {
    let mut c = BranchCurve {
        label: format!("period-{}", half.cycles),
        doubled,
        dashes: TERMINAL_DASHES,
        ..BranchCurve::default()
    };
    for k in 0..half.stops.len() {
        let points: Vec<(f64, f64, bool)> = half
            .points
            .iter()
            .filter_map(|p| Some((*p.values.first()?, p.points.get(k)?.v_in, p.stable)))
            .collect();
        c.push_impact(&points);
    }
    for s in &half.specials {
        if let (Some(&x), Some(q)) = (s.point.values.first(), s.point.points.first()) {
            c.specials.push((x, q.v_in, letter(s.kind).to_string()));
        }
    }
    c
}

/// Dots of an unstable stretch kept on a terminal: one in this many of [`plot::branch`]'s, which
/// are denser than braille can show apart (the dotted line would read as solid).
pub const TERMINAL_THINNING: usize = 6;

/// The diagram is drawn under the branches up to this many times their largest impact speed: a
/// diagram that reaches far higher (a stop that realises e near 1 bounces ever higher) would
/// squeeze the branches, and the doubled branch beside the one it was born on, into one row.
pub const HEADROOM: f64 = 1.5;

/// The diagram's columns with the points above `limit` left out, and how many were.
fn clipped(columns: &[(f64, Vec<f64>)], limit: f64) -> (DiagramBranch, usize) {
    let mut dropped = 0;
    let columns = columns
        .iter()
        .map(|(k, points)| {
            let kept: Vec<f64> = points.iter().copied().filter(|v| *v <= limit).collect();
            dropped += points.len() - kept.len();
            (*k, kept)
        })
        .collect();
    (DiagramBranch { columns }, dropped)
}

/// The branches over the diagram: [`plot::branch`] with the diagram's axes and range, the
/// diagram's points above [`HEADROOM`] times the branches' largest speed left out (a note says
/// how many), one dot in `thinning` of its unstable stretches kept, the rigid stop's marks drawn
/// last (over the compliant ones' labels where they meet).
pub fn chart(
    diagram: &DiagramData,
    branches: &ContinuedBranches,
    model: &SystemModel,
    budget: (usize, usize),
    thinning: usize,
) -> Chart {
    let curves: Vec<(Approach, BranchCurve)> = branches
        .branches
        .iter()
        .flat_map(|b| {
            let approach = Approach::of(&b.contact);
            let halves = b.halves.iter().flatten().map(|h| curve(h, false));
            let doubled = b.doubled.iter().flatten().map(|d| curve(d, true));
            halves.chain(doubled).map(move |c| (approach, c))
        })
        .collect();
    let top = curves
        .iter()
        .flat_map(|(_, c)| c.runs.iter().flat_map(|r| r.1.iter().map(|p| p.1)))
        .filter(|v| v.is_finite())
        .fold(0.0, f64::max);
    let limit = if top > 0.0 {
        HEADROOM * top
    } else {
        f64::INFINITY
    };
    let mut dropped = 0;
    let columns: Vec<(Approach, DiagramBranch)> = diagram
        .branches
        .iter()
        .map(|b| {
            let (kept, n) = clipped(&DiagramBranch::of(&b.columns).columns, limit);
            dropped += n;
            (Approach::of(&b.contact), kept)
        })
        .collect();
    let mut axes = DiagramAxes::impact_speeds(diagram.param, model);
    axes.range = super::value_span(&diagram.values);
    let drawn: Vec<(Approach, &BranchCurve)> = curves.iter().map(|(a, c)| (*a, c)).collect();
    let under: Vec<(Approach, &DiagramBranch)> = columns.iter().map(|(a, d)| (*a, d)).collect();
    let mut chart = plot::branch(&drawn, &under, &axes, budget);
    let every = thinning.max(1);
    for series in chart.series.iter_mut().filter(|s| s.name.ends_with("unstable")) {
        let last = series.runs.len().saturating_sub(1);
        let runs = std::mem::take(&mut series.runs);
        series.runs = runs
            .into_iter()
            .enumerate()
            .filter(|(i, _)| i % every == 0 || *i == last)
            .map(|(_, r)| r)
            .collect();
    }
    let rigid = Approach::Rigid.look().1;
    chart.marks.sort_by_key(|m| m.ink == rigid);
    chart.title = format!("branch over the diagram of {}", axes.key);
    if dropped > 0 {
        chart.notes.push(format!(
            "{dropped} diagram point(s) above v_in = {} m/s left out",
            sig(limit, 3)
        ));
    }
    chart
}

/// `rigid` or the law's name, as the notes name a stop.
fn stop_name(contact: &Contact) -> String {
    match contact {
        Contact::Rigid { .. } => "rigid".into(),
        Contact::Compliant { model, .. } => model.name().to_string(),
    }
}

/// The special points of `branches` by value, each with its letter, the key to 7 digits and the
/// impact speed there; or `no special point`.
fn listed(branches: &[&Branch], key: &str) -> String {
    let mut specials: Vec<(f64, String)> = branches
        .iter()
        .flat_map(|h| &h.specials)
        .filter_map(|s| {
            let x = *s.point.values.first()?;
            let v = s.point.points.first().map_or(f64::NAN, |q| q.v_in);
            let speed = if v.is_finite() {
                format!(" (v_in {} m/s)", sig(v, 4))
            } else {
                String::new()
            };
            Some((x, format!("{} {key} = {}{speed}", letter(s.kind), sig(x, 7))))
        })
        .collect();
    specials.sort_by(|a, b| a.0.total_cmp(&b.0));
    if specials.is_empty() {
        "no special point".to_string()
    } else {
        specials
            .into_iter()
            .map(|(_, t)| t)
            .collect::<Vec<_>>()
            .join(" · ")
    }
}

/// `period-m, n impact(s), N points` of a branch made of `parts`.
fn described(parts: &[&Branch]) -> Option<String> {
    let first = parts.first()?;
    let points: usize = parts.iter().map(|h| h.points.len()).sum();
    Some(format!(
        "period-{}, {} impact(s), {points} points",
        first.cycles,
        first.stops.len()
    ))
}

/// What the notes say of the branch: per stop its orbit, its special points with their values
/// (the key to 7 digits, the impact speed there), or why it failed; then the doubled branch born
/// at its period doubling, the same way.
pub fn notes(app: &App) -> Vec<(String, Role)> {
    if !app.views.system.branch {
        return Vec::new();
    }
    let b_key = key();
    let running = app.studies.is_pending(StudyKind::Continuation);
    let Some(data) = app.studies.continuation() else {
        return vec![(format!("branch ({b_key}): continuing…"), Role::Muted)];
    };
    let key = data.param.path();
    let mut texts = Vec::new();
    for b in &data.branches {
        let name = stop_name(&b.contact);
        let halves: Vec<&Branch> = match &b.halves {
            Ok(halves) => halves.iter().collect(),
            Err(e) => {
                texts.push((format!("✗ branch, {name}: {e}"), Role::Error));
                continue;
            }
        };
        if let Some(orbit) = described(&halves) {
            texts.push((
                format!(
                    "branch ({b_key}), {name}: {orbit}: {}",
                    listed(&halves, &key)
                ),
                Role::Normal,
            ));
        }
        for doubled in &b.doubled {
            match doubled {
                Ok(d) => {
                    let orbit = described(&[d]).unwrap_or_default();
                    texts.push((
                        format!(
                            "doubled branch, {name}: {orbit}: {}",
                            listed(&[d], &key)
                        ),
                        Role::Normal,
                    ));
                }
                Err(e) => texts.push((format!("✗ doubled branch, {name}: {e}"), Role::Error)),
            }
        }
    }
    if running {
        texts.push((format!("branch ({b_key}): continuing…"), Role::Muted));
    }
    texts
}
