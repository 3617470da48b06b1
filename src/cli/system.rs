//! `hertz-tui system`: a system scene simulated with the stops asked for, its recorded impacts
//! and detected period as a table, JSON or CSV; and what `orbit`, `bifurcation` and the system
//! charts of `plot` share: the system model of a scene, the contacts, the run's budgets.

use serde::Serialize;

use crate::format::csv;
use crate::format::verdict as words;
use crate::model::presets::Registry;
use crate::model::system::compliant::verdict::{Verdict, verdict_of};
use crate::model::system::{
    self, CompliantDamping, Contact, Dents, EndReason, History, ImpactKind, ImpactRecord,
    RunOptions, Stick, SystemError, SystemModel, SystemSample,
};

use super::args::{
    ContactArgs, ContactChoice, DampingChoice, Format, RunArgs, SceneSelection, SystemArgs,
};
use super::error::CliError;
use super::json;
use super::layout::columns;
use super::solve::load_scene;
use super::units::{compact_number, engineering};

/// Rows of impacts the table shows: the last ones recorded (csv and json give all).
const TABLE_IMPACTS: usize = 12;

/// The system model of a scene with a `[system]` table (after `--set`); a scene without one is a
/// usage error that says where systems are.
pub fn load_system(source: &SceneSelection, registry: &Registry) -> Result<SystemModel, CliError> {
    let scene = load_scene(source, registry)?;
    let spec = registry
        .scene_system(&source.scene, &source.overrides)?
        .ok_or_else(|| {
            CliError::Usage(format!(
                "{}: the scene has no [system] table; a system scene puts its two bodies in a \
                 machine (presets bouncing-ball, impact-oscillator, impact-oscillator-clearance; \
                 docs/systems.md)",
                source.scene
            ))
        })?;
    Ok(SystemModel::from_scene(&scene, &spec)?)
}

/// The stops `args` asks for on `model`: rigid with the scene's e, the compliant law, or both;
/// `--damping fitted` needs the scene's `[fit]` to be of the compliant law.
pub fn contacts(args: &ContactArgs, model: &SystemModel) -> Result<Vec<Contact>, CliError> {
    let rigid = Contact::rigid(model.restitution);
    let compliant = Contact::Compliant {
        model: args.law,
        damping: match args.damping {
            DampingChoice::PerImpact => CompliantDamping::PerImpact,
            DampingChoice::Calibrated => CompliantDamping::CalibratedTo(model.restitution),
            DampingChoice::Constant(value) => CompliantDamping::Constant(value),
            DampingChoice::Fitted => {
                let fit = model.scene.as_ref().and_then(|s| s.fit.as_ref());
                match fit {
                    Some(fit) if fit.kind.model() == Some(args.law) => {
                        CompliantDamping::Fitted(fit.value)
                    }
                    _ => {
                        return Err(CliError::Usage(format!(
                            "--damping fitted: the scene has no [fit] of {} ({}); write one with hertz-tui fit --write-scene, or give --law its fitted law",
                            args.law,
                            fit.map_or("no [fit] table".to_string(), |f| format!(
                                "its [fit] is {}",
                                f.kind
                            ))
                        )));
                    }
                }
            }
        },
    };
    Ok(match args.contact {
        ContactChoice::Rigid => vec![rigid],
        ContactChoice::Compliant => vec![compliant],
        ContactChoice::Both => vec![rigid, compliant],
    })
}

/// How a contact is named in every output: `rigid` or the law's id.
pub fn contact_label(contact: &Contact) -> String {
    match contact {
        Contact::Rigid { .. } => "rigid".to_string(),
        Contact::Compliant { model, .. } => model.to_string(),
    }
}

/// The run the budgets ask for, with `samples_per_period` dense samples for drawing.
pub fn run_options(args: &RunArgs, samples_per_period: usize) -> RunOptions {
    RunOptions {
        transient_impacts: args.transient,
        recorded_impacts: args.recorded as usize,
        max_periods: args.max_periods,
        max_impacts: args.max_impacts,
        samples_per_period,
        initial: None,
    }
}

/// A contact's run, or why it failed, naming the contact.
pub fn simulate(
    model: &SystemModel,
    contact: &Contact,
    options: &RunOptions,
) -> Result<History, CliError> {
    system::simulate(model, contact, options).map_err(|e| failed(contact, e))
}

/// A contact's error, naming the contact.
pub fn failed(contact: &Contact, e: SystemError) -> CliError {
    CliError::System {
        contact: contact_label(contact),
        source: Box::new(e),
    }
}

/// The dimensionless groups of the system, where it has them.
#[derive(Debug, Clone, Serialize)]
pub struct GroupsRow {
    /// Γ = Aω²/g (bouncing ball).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gamma: Option<f64>,
    /// ω/ω₀ (oscillator).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub frequency_ratio: Option<f64>,
    /// ζ (oscillator).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub damping_ratio: Option<f64>,
    /// gap over the static deflection (oscillator).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gap_ratio: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub second_gap_ratio: Option<f64>,
}

impl GroupsRow {
    pub fn of(model: &SystemModel) -> GroupsRow {
        let g = model.spec.groups(model.mass);
        GroupsRow {
            gamma: g.gamma,
            frequency_ratio: g.frequency_ratio,
            damping_ratio: g.damping_ratio,
            gap_ratio: g.gap_ratio,
            second_gap_ratio: g.second_gap_ratio,
        }
    }

    /// `Γ = Aω²/g = 1.61`, `ω/ω₀ = 0.9 · ζ = 0.05 · gap = 0.32 δ_st`: one line.
    pub fn line(&self) -> String {
        let n = |v: f64| compact_number(v, 4);
        let mut parts = Vec::new();
        if let Some(g) = self.gamma {
            parts.push(format!("Γ = Aω²/g = {}", n(g)));
        }
        if let Some(r) = self.frequency_ratio {
            parts.push(format!("ω/ω₀ = {}", n(r)));
        }
        if let Some(z) = self.damping_ratio {
            parts.push(format!("ζ = {}", n(z)));
        }
        if let Some(g) = self.gap_ratio {
            parts.push(format!("gap = {} × static deflection", n(g)));
        }
        if let Some(g) = self.second_gap_ratio {
            parts.push(format!("second gap = {} × static deflection", n(g)));
        }
        parts.join(" · ")
    }
}

/// A detected period: n impacts every m forcing periods.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct PeriodRow {
    pub impacts: u32,
    pub forcing_periods: u32,
}

/// One contact's run.
#[derive(Debug, Clone, Serialize)]
pub struct RunReport {
    /// `rigid` or the law's id.
    pub contact: String,
    /// The recorded impacts repeat with this period (none: not periodic within 128 impacts).
    pub period: Option<PeriodRow>,
    pub end: EndReason,
    /// Impacts simulated in all, transient and chatter included.
    pub impacts_total: usize,
    /// The run reached --max-periods before its transient impacts were done, still impacting in
    /// its last tenth (the map's `unsettled`, docs/maps.md §2).
    pub transient_unfinished: bool,
    /// The time of the last impact, transient included, s (none: no impact).
    pub last_impact: Option<f64>,
    pub impacts: Vec<ImpactRecord>,
    pub sticks: Vec<Stick>,
    /// The permanent dents the recorded contacts left, not carried (a plastic law's).
    #[serde(skip_serializing_if = "no_dents")]
    pub dents: Dents,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub samples: Vec<SystemSample>,
}

fn no_dents(d: &Dents) -> bool {
    d.contacts == 0
}

/// The warning of a run whose law left permanent dents the stop does not carry.
pub fn dent_warning(contact: &str, dents: &Dents) -> Option<String> {
    (dents.contacts > 0).then(|| {
        format!(
            "warning: {contact} leaves a permanent dent at {} of the recorded contacts (up to {}, \
             {} in all), which the stop does not carry: every contact starts from an undeformed \
             stop (docs/compliant.md §1)",
            dents.contacts,
            engineering(dents.largest, "m"),
            engineering(dents.total, "m"),
        )
    })
}

/// Which approach the system needs (with `--contact both` or `compliant`): the model's verdict
/// and its sentence.
#[derive(Debug, Clone, Serialize)]
pub struct VerdictRow {
    pub sentence: String,
    #[serde(flatten)]
    pub verdict: Verdict,
}

/// The JSON document of `system`.
#[derive(Debug, Clone, Serialize)]
pub struct SystemReport {
    pub scene: String,
    /// bouncing-ball or impact-oscillator.
    pub kind: &'static str,
    /// Forcing frequency, Hz.
    pub frequency: f64,
    pub groups: GroupsRow,
    pub runs: Vec<RunReport>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub verdict: Option<VerdictRow>,
}

/// Simulates every contact asked for.
pub fn report(args: &SystemArgs, registry: &Registry) -> Result<SystemReport, CliError> {
    let model = load_system(&args.source, registry)?;
    let samples = args.history.map_or(0, |n| n as usize);
    let options = run_options(&args.run, samples);
    let period = model.spec.period();
    let histories = contacts(&args.contact, &model)?
        .into_iter()
        .map(|contact| Ok((contact, simulate(&model, &contact, &options)?)))
        .collect::<Result<Vec<_>, CliError>>()?;
    // The verdict weighs the compliant run just made against the rigid one (if asked for too).
    let verdict = match histories.last() {
        Some((
            contact @ Contact::Compliant {
                model: law,
                damping: _,
            },
            compliant,
        )) => {
            let rigid = histories
                .iter()
                .find(|(c, _)| matches!(c, Contact::Rigid { .. }))
                .map(|(_, h)| h);
            let v = verdict_of(&model, *law, &options, compliant, rigid)
                .map_err(|e| failed(contact, e))?;
            Some(VerdictRow {
                sentence: words::sentence(&v),
                verdict: v,
            })
        }
        _ => None,
    };
    let runs = histories
        .into_iter()
        .map(|(contact, h)| RunReport {
            contact: contact_label(&contact),
            period: h.period(period).map(|(n, m)| PeriodRow {
                impacts: n,
                forcing_periods: m,
            }),
            end: h.end,
            impacts_total: h.impacts_total,
            transient_unfinished: h.transient_unfinished(&options, period),
            last_impact: h.last_impact,
            impacts: h.impacts,
            sticks: h.sticks,
            dents: h.dents,
            samples: h.samples,
        })
        .collect();
    Ok(SystemReport {
        verdict,
        scene: model
            .scene
            .as_ref()
            .map_or_else(String::new, |s| s.name.clone()),
        kind: model.spec.kind_name(),
        frequency: model.spec.frequency(),
        groups: GroupsRow::of(&model),
        runs,
    })
}

/// Runs `system` and renders it.
pub fn run(args: &SystemArgs, registry: &Registry) -> Result<String, CliError> {
    let report = report(args, registry)?;
    match args.format {
        Format::Json => json(&report),
        Format::Csv if args.history.is_some() => Ok(history_csv(&report)),
        Format::Csv => Ok(impacts_csv(&report)),
        Format::Table => Ok(table(&report, args.run.transient)),
    }
}

/// How a period reads: `period-1: 1 impact every forcing period`.
pub fn period_words(period: Option<PeriodRow>, end: EndReason) -> String {
    match (period, end) {
        (_, EndReason::StuckForever) => "sticks to the stop for ever (no more impacts)".into(),
        (Some(p), _) => format!(
            "period-{}: {} impact{} every {} forcing period{}",
            p.forcing_periods,
            p.impacts,
            if p.impacts == 1 { "" } else { "s" },
            p.forcing_periods,
            if p.forcing_periods == 1 { "" } else { "s" },
        ),
        (None, EndReason::TimeLimit) => "the run reached --max-periods first".into(),
        (None, _) => "no period within 128 impacts (quasi-periodic or chaotic)".into(),
    }
}

fn table(report: &SystemReport, transient: usize) -> String {
    let mut out = format!(
        "{} ({}, forcing {})\n  {}\n",
        report.scene,
        report.kind,
        engineering(report.frequency, "Hz"),
        report.groups.line()
    );
    for run in &report.runs {
        let words = if run.transient_unfinished {
            format!(
                "the transient never ended: the run reached --max-periods after {} of its \
                 {transient} transient impacts",
                run.impacts_total
            )
        } else {
            period_words(run.period, run.end)
        };
        out.push_str(&format!(
            "\n{}: {}; {} impacts recorded after {transient}, {} in all\n",
            run.contact,
            words,
            run.impacts.len(),
            run.impacts_total
        ));
        let mut rows = vec![
            ["t", "φ [rad]", "v_in", "v_out", "F_peak", "t_c", "ΔE", ""]
                .map(String::from)
                .to_vec(),
        ];
        let shown = run.impacts.len().saturating_sub(TABLE_IMPACTS);
        for i in &run.impacts[shown..] {
            let (force, note) = match (i.peak_force, i.peak_force_estimate) {
                (Some(f), _) => (engineering(f, "N"), ""),
                (None, Some(f)) => (engineering(f, "N"), "Hertz estimate"),
                (None, None) => ("—".into(), ""),
            };
            rows.push(vec![
                engineering(i.t, "s"),
                compact_number(i.phase, 4),
                engineering(i.v_in, "m/s"),
                engineering(i.v_out, "m/s"),
                force,
                i.contact_time
                    .map_or_else(|| "—".into(), |t| engineering(t, "s")),
                engineering(i.energy_lost, "J"),
                match i.kind {
                    ImpactKind::ChatterEnd => "chatter ends: sticks".into(),
                    ImpactKind::Rest => "comes to rest on the stop".into(),
                    ImpactKind::Impact => note.into(),
                },
            ]);
        }
        out.push_str(&columns(&rows, "  "));
        if shown > 0 {
            out.push_str(&format!(
                "  … the last {TABLE_IMPACTS} of {}; --format csv gives all\n",
                run.impacts.len()
            ));
        }
        if let Some(warning) = dent_warning(&run.contact, &run.dents) {
            out.push_str(&format!("  {warning}\n"));
        }
    }
    if let Some(v) = &report.verdict {
        out.push_str(&format!(
            "\nwhich approach: {}: {}\n",
            words::gist(&v.verdict),
            v.sentence
        ));
    }
    out
}

/// `value,` or `,` for a missing number, in Rust's shortest round-trip form.
fn number(out: &mut String, value: Option<f64>) {
    if let Some(v) = value {
        out.push_str(&format!("{v:e}"));
    }
    out.push(',');
}

fn impacts_csv(report: &SystemReport) -> String {
    let mut out = String::from(
        "contact,t,phase,x,stop,v_in,v_out,peak_force,peak_force_estimate,contact_time,energy_lost,kind\n",
    );
    for run in &report.runs {
        for i in &run.impacts {
            out.push_str(&csv::field(&run.contact));
            out.push(',');
            for v in [i.t, i.phase, i.x] {
                number(&mut out, Some(v));
            }
            out.push_str(&format!("{},", i.stop));
            number(&mut out, Some(i.v_in));
            number(&mut out, Some(i.v_out));
            number(&mut out, i.peak_force);
            number(&mut out, i.peak_force_estimate);
            number(&mut out, i.contact_time);
            number(&mut out, Some(i.energy_lost));
            out.push_str(match i.kind {
                ImpactKind::Impact => "impact",
                ImpactKind::ChatterEnd => "chatter-end",
                ImpactKind::Rest => "rest",
            });
            out.push('\n');
        }
    }
    out
}

fn history_csv(report: &SystemReport) -> String {
    let mut out = String::from("contact,t,x,v,stop\n");
    for run in &report.runs {
        for s in &run.samples {
            out.push_str(&csv::field(&run.contact));
            out.push(',');
            number(&mut out, Some(s.t));
            number(&mut out, Some(s.x));
            number(&mut out, Some(s.v));
            out.push_str(&format!("{:e}\n", s.stop));
        }
    }
    out
}
