//! `hertz-tui orbit`: a periodic orbit of a system's impact map found by Newton (from a guess or
//! from the attractor after the transient), its impacts, Floquet multipliers and stability.

use serde::Serialize;

use crate::format::csv;
use crate::model::presets::Registry;
use crate::model::system::{self, GuessStart, Orbit, OrbitGuess, OrbitOptions};

use super::args::{Format, OrbitArgs, OrbitStartArgs, RunArgs};
use super::error::CliError;
use super::json;
use super::layout::columns;
use super::system::{GroupsRow, contact_label, contacts, failed, load_system, run_options};
use super::units::{compact_number, engineering};

/// One contact's orbit.
#[derive(Debug, Clone, Serialize)]
pub struct OrbitRow {
    pub contact: String,
    #[serde(flatten)]
    pub orbit: Orbit,
    /// |λ| of each multiplier, in the order of `multipliers`.
    pub moduli: Vec<f64>,
}

/// The JSON document of `orbit`.
#[derive(Debug, Clone, Serialize)]
pub struct OrbitReport {
    pub scene: String,
    pub groups: GroupsRow,
    pub orbits: Vec<OrbitRow>,
}

/// Newton's guess from the arguments: the given first impact, or the attractor of `run`.
pub fn guess(start: &OrbitStartArgs, run: &RunArgs) -> OrbitGuess {
    OrbitGuess {
        // 0: the period the run settles on (the model's orbit search detects it).
        forcing_cycles: start.period.unwrap_or(0),
        impacts: start.impacts.unwrap_or(0),
        start: match (start.phase, start.speed) {
            (Some(phase), Some(v_in)) => Some(GuessStart {
                phase,
                v_in,
                stop: 0,
            }),
            _ => None,
        },
        attractor: run_options(run, 0),
    }
}

/// The orbit of every contact asked for.
pub fn report(args: &OrbitArgs, registry: &Registry) -> Result<OrbitReport, CliError> {
    let model = load_system(&args.source, registry)?;
    let options = OrbitOptions {
        max_impacts: args.run.max_impacts,
        ..OrbitOptions::default()
    };
    let guess = guess(&args.start, &args.run);
    let orbits = contacts(&args.contact, &model)?
        .iter()
        .map(|contact| {
            let orbit = system::find_orbit(&model, contact, &guess, &options)
                .map_err(|e| failed(contact, e))?;
            Ok(OrbitRow {
                contact: contact_label(contact),
                moduli: orbit.multipliers.iter().map(|z| z.norm()).collect(),
                orbit,
            })
        })
        .collect::<Result<Vec<_>, CliError>>()?;
    Ok(OrbitReport {
        scene: model
            .scene
            .as_ref()
            .map_or_else(String::new, |s| s.name.clone()),
        groups: GroupsRow::of(&model),
        orbits,
    })
}

/// Runs `orbit` and renders it.
pub fn run(args: &OrbitArgs, registry: &Registry) -> Result<String, CliError> {
    let report = report(args, registry)?;
    Ok(match args.format {
        Format::Json => json(&report)?,
        Format::Csv => points_csv(&report),
        Format::Table => table(&report),
    })
}

/// `0.25 + 0.1i`, or the real number alone.
fn complex(re: f64, im: f64) -> String {
    if im == 0.0 {
        compact_number(re, 6)
    } else {
        let sign = if im < 0.0 { '−' } else { '+' };
        format!(
            "{} {sign} {}i",
            compact_number(re, 6),
            compact_number(im.abs(), 6)
        )
    }
}

fn table(report: &OrbitReport) -> String {
    let mut out = format!("{}\n  {}\n", report.scene, report.groups.line());
    for row in &report.orbits {
        let o = &row.orbit;
        out.push_str(&format!(
            "\n{}: period-{} orbit, {} impact{} per period, {} ({} Newton iterations)\n",
            row.contact,
            o.period_forcing_cycles,
            o.impacts_per_period,
            if o.impacts_per_period == 1 { "" } else { "s" },
            if o.stable { "stable" } else { "unstable" },
            o.iterations
        ));
        let mut rows = vec![
            ["impact", "t", "φ [rad]", "stop", "v_in", "v_out"]
                .map(String::from)
                .to_vec(),
        ];
        for (i, p) in o.points.iter().enumerate() {
            rows.push(vec![
                (i + 1).to_string(),
                engineering(p.t, "s"),
                compact_number(p.phase, 6),
                p.stop.to_string(),
                engineering(p.v_in, "m/s"),
                engineering(p.v_out, "m/s"),
            ]);
        }
        out.push_str(&columns(&rows, "  "));
        let mut rows = vec![vec!["multiplier".to_string(), "λ".into(), "|λ|".into()]];
        for (k, (z, m)) in o.multipliers.iter().zip(&row.moduli).enumerate() {
            rows.push(vec![
                format!("λ{}", k + 1),
                complex(z.re, z.im),
                compact_number(*m, 6),
            ]);
        }
        rows.push(vec![
            "det J".into(),
            compact_number(o.jacobian_det, 6),
            String::new(),
        ]);
        out.push_str(&columns(&rows, "  "));
    }
    out
}

fn points_csv(report: &OrbitReport) -> String {
    let mut out = String::from("contact,impact,t,phase,x,stop,v_in,v_out\n");
    for row in &report.orbits {
        for (i, p) in row.orbit.points.iter().enumerate() {
            out.push_str(&format!(
                "{},{},{:e},{:e},{:e},{},{:e},{:e}\n",
                csv::field(&row.contact),
                i + 1,
                p.t,
                p.phase,
                p.x,
                p.stop,
                p.v_in,
                p.v_out
            ));
        }
    }
    out
}
