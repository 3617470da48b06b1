//! `b` in the system view: the periodic orbit the run settles on, continued over the diagram's
//! range (docs/continuation.md §8) as a study on the studies' queue, drawn over the brute-force
//! diagram (stable solid, unstable dotted, each stop in its own ink) with its special points
//! marked by their letter and listed with their values in the notes.

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
use crate::ui::style::Role;

use super::settings::{self, Settings};

/// The letter a special point is marked with on the chart and named by in the notes.
pub fn letter(kind: SpecialKind) -> &'static str {
    match kind {
        SpecialKind::Fold => "F",
        SpecialKind::PeriodDoubling => "PD",
        SpecialKind::GrazingImpact | SpecialKind::GrazingFlight => "G",
    }
}

/// `b`: the branch on or off.
pub fn toggle(app: &mut App) {
    let on = !app.views.system.branch;
    app.views.system.branch = on;
    let text = if on {
        "continuing the orbit over the diagram's range (b hides it)"
    } else {
        "continued branch hidden (b shows it)"
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

/// A half of a branch as the chart draws it: every impact's v_in against the key, by stability,
/// with its special points marked by their letter.
fn curve(half: &Branch) -> BranchCurve {
    let mut c = BranchCurve {
        label: format!("period-{}", half.cycles),
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

/// The branches over the diagram: [`plot::branch`] with the diagram's axes and range, one dot in
/// `thinning` of its unstable stretches kept, the rigid stop's marks drawn last (over the
/// compliant ones' labels where they meet).
pub fn chart(
    diagram: &DiagramData,
    branches: &ContinuedBranches,
    model: &SystemModel,
    budget: (usize, usize),
    thinning: usize,
) -> Chart {
    let columns: Vec<(Approach, DiagramBranch)> = diagram
        .branches
        .iter()
        .map(|b| (Approach::of(&b.contact), DiagramBranch::of(&b.columns)))
        .collect();
    let curves: Vec<(Approach, BranchCurve)> = branches
        .branches
        .iter()
        .flat_map(|b| {
            let approach = Approach::of(&b.contact);
            b.halves
                .iter()
                .flatten()
                .map(move |h| (approach, curve(h)))
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
    chart
}

/// `rigid` or the law's name, as the notes name a stop.
fn stop_name(contact: &Contact) -> String {
    match contact {
        Contact::Rigid { .. } => "rigid".into(),
        Contact::Compliant { model, .. } => model.name().to_string(),
    }
}

/// What the notes say of the branch: per stop its orbit, its special points with their values
/// (the key to 7 digits, the impact speed there) and how it ended, or why it failed.
pub fn notes(app: &App) -> Vec<(String, Role)> {
    if !app.views.system.branch {
        return Vec::new();
    }
    let running = app.studies.is_pending(StudyKind::Continuation);
    let Some(data) = app.studies.continuation() else {
        return vec![("branch (b): continuing…".into(), Role::Muted)];
    };
    let key = data.param.path();
    let mut texts = Vec::new();
    for b in &data.branches {
        let name = stop_name(&b.contact);
        let halves = match &b.halves {
            Ok(halves) => halves,
            Err(e) => {
                texts.push((format!("✗ branch, {name}: {e}"), Role::Error));
                continue;
            }
        };
        let Some(first) = halves.first() else {
            continue;
        };
        let points: usize = halves.iter().map(|h| h.points.len()).sum();
        let mut specials: Vec<(f64, String)> = halves
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
        let listed = if specials.is_empty() {
            "no special point".to_string()
        } else {
            specials
                .into_iter()
                .map(|(_, t)| t)
                .collect::<Vec<_>>()
                .join(" · ")
        };
        texts.push((
            format!(
                "branch (b), {name}: period-{}, {} impact(s), {points} points: {listed}",
                first.cycles,
                first.stops.len()
            ),
            Role::Normal,
        ));
    }
    if running {
        texts.push(("branch (b): continuing…".into(), Role::Muted));
    }
    texts
}
