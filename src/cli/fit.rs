//! `hertz-tui fit`: every law (or those asked for) fitted to measured restitution e(v₀), ranked by
//! an information criterion with the parameters' confidence intervals, the verdict in words, the
//! residuals; `--write-scene` puts the chosen law in a scene's `[fit]`, `--engines` compares each
//! engine's realised e(v₀) with the data (docs/fitting.md).

use std::path::Path;

use serde::Serialize;

use crate::format::csv::field;
use crate::format::fit_csv::parse_restitution_csv;
use crate::format::trace_csv::parse_trace_csv;
use crate::format::{Zeros, round_trip, significant};
use crate::model::ForceModel;
use crate::model::Scene;
use crate::model::engine::{self, ENGINES};
use crate::model::fit::trace::{TraceData, TraceFitOptions, TraceQuantity, fit_trace};
use crate::model::fit::{
    Candidate, FitOptions, FitReport, LawFit, LsqOptions, RestitutionData, Verdict, candidates,
    fit_restitution,
};
use crate::model::presets::Registry;
use crate::model::scene_file::to_toml_with_system;
use crate::model::scene_fit::{FittedLaw, constant_of};

use super::args::{FitArgs, Format};
use super::error::CliError;
use super::layout::columns;
use super::solve::load_scene;

/// An engine is said to reproduce the data when its RMS residual is within this many times the
/// data's noise (the RMS of the given sd, or the best law's residual standard deviation).
pub const REPRODUCES_WITHIN: f64 = 1.5;

/// Reads restitution data from `path`; errors name the file and line.
pub fn read_restitution(path: &Path) -> Result<RestitutionData, CliError> {
    let file = path.display().to_string();
    let text = std::fs::read_to_string(path)
        .map_err(|e| CliError::Usage(format!("{file}: cannot read the data: {e}")))?;
    parse_restitution_csv(&text, &file).map_err(|e| CliError::Usage(e.to_string()))
}

/// Whether `text` is a trace (its header's first column is time: `t, F` or `t, x`) rather than
/// restitution data (`v, e`).
fn is_trace(text: &str) -> bool {
    let header = text
        .lines()
        .map(|l| l.find('#').map_or(l, |i| &l[..i]).trim())
        .find(|l| !l.is_empty());
    header.is_some_and(|h| {
        let first = h.split(',').next().unwrap_or("");
        let name = first.split(['(', '[']).next().unwrap_or("").trim();
        matches!(name.to_ascii_lowercase().as_str(), "t" | "time")
    })
}

/// The laws a trace is fitted with: those `--law` names, else every law with a material constant
/// (one per distinct law) and elastic Hertz, whose place in the ranking says whether the trace
/// shows damping at all.
fn trace_laws(laws: &[String]) -> Result<Vec<ForceModel>, CliError> {
    if laws.is_empty() {
        return Ok(std::iter::once(ForceModel::Quasistatic)
            .chain(candidates().into_iter().filter_map(Candidate::model))
            .collect());
    }
    laws.iter()
        .map(|id| {
            id.parse::<ForceModel>().map_err(|e| {
                CliError::Usage(format!("--law: a trace is fitted by force laws: {e}"))
            })
        })
        .collect()
}

/// Fits a force or displacement trace (the file's text `text`) and renders it.
fn run_trace(
    args: &FitArgs,
    registry: &Registry,
    scene: &Scene,
    text: &str,
) -> Result<String, CliError> {
    let file = args.data.display().to_string();
    let data = parse_trace_csv(text, &file).map_err(|e| CliError::Usage(e.to_string()))?;
    let options = TraceFitOptions {
        fit: FitOptions {
            criterion: args.criterion,
            lsq: LsqOptions {
                level: args.level,
                ..LsqOptions::default()
            },
            parallel: true,
        },
        ..TraceFitOptions::default()
    };
    let report = fit_trace(scene, &data, &trace_laws(&args.laws)?, &options)
        .map_err(|e| CliError::Usage(format!("{file}: {e}")))?;
    if args.engines {
        return Err(CliError::Usage(
            "--engines compares engines with e(v0) data; fit the trace, --write-scene, then hertz-tui translate".into(),
        ));
    }
    let fitted = fitted_scene(scene, &report, &file)?;
    let wrote = match &args.write_scene {
        Some(out) => Some(write_scene(args, registry, &fitted, out)?),
        None => None,
    };
    let (t0, t1) = (
        data.samples.first().map_or(0.0, |s| s.t),
        data.samples.last().map_or(0.0, |s| s.t),
    );
    let output = FitOutput {
        scene: scene.name.clone(),
        data: file,
        points: data.samples.len(),
        v_range: (t0, t1),
        verdict_text: verdict_words(
            &report.verdict,
            Some(match data.quantity {
                TraceQuantity::Force => "N",
                TraceQuantity::Displacement => "m",
            }),
        ),
        report,
        engines: Vec::new(),
        wrote,
    };
    match args.format {
        Format::Table => Ok(render_trace_table(&output, &data, &fitted)),
        Format::Json => super::json(&output),
        Format::Csv => Ok(render_csv(&output.report)),
    }
}

/// The candidates `--law` names, or every default one.
fn chosen(laws: &[String]) -> Result<Vec<Candidate>, CliError> {
    if laws.is_empty() {
        return Ok(candidates());
    }
    let mut out = Vec::new();
    for id in laws {
        let candidate = Candidate::from_id(id).ok_or_else(|| {
            let ids: Vec<&str> = std::iter::once(Candidate::ConstantE)
                .chain(
                    candidates()
                        .into_iter()
                        .filter(|c| *c != Candidate::ConstantE),
                )
                .map(Candidate::id)
                .collect();
            CliError::Usage(format!(
                "--law: unknown law '{id}' (expected constant-e or a law id, e.g. {})",
                ids.join(", ")
            ))
        })?;
        if !out.contains(&candidate) {
            out.push(candidate);
        }
    }
    Ok(out)
}

/// Everything `fit` computed; serialized as the JSON output.
#[derive(Debug, Serialize)]
pub struct FitOutput {
    /// The scene's name (its bodies give k, n and m).
    pub scene: String,
    /// The data file, as given.
    pub data: String,
    pub points: usize,
    /// The velocity range of the data, m/s.
    pub v_range: (f64, f64),
    #[serde(flatten)]
    pub report: FitReport,
    /// The verdict in words.
    pub verdict_text: String,
    /// Each engine against the data (`--engines`).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub engines: Vec<EngineAgainstData>,
    /// Where `--write-scene` wrote the fitted scene.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub wrote: Option<String>,
}

/// Fits, writes the scene where asked, and renders the result.
pub fn run(args: &FitArgs, registry: &Registry) -> Result<String, CliError> {
    let scene = load_scene(&args.source, registry)?;
    let file = args.data.display().to_string();
    let text = std::fs::read_to_string(&args.data)
        .map_err(|e| CliError::Usage(format!("{file}: cannot read the data: {e}")))?;
    if is_trace(&text) {
        return run_trace(args, registry, &scene, &text);
    }
    let data = parse_restitution_csv(&text, &file).map_err(|e| CliError::Usage(e.to_string()))?;
    let options = FitOptions {
        criterion: args.criterion,
        lsq: LsqOptions {
            level: args.level,
            ..LsqOptions::default()
        },
        parallel: true,
    };
    let report = fit_restitution(&scene, &data, &chosen(&args.laws)?, &options)
        .map_err(|e| CliError::Usage(format!("{file}: {e}")))?;
    let fitted = fitted_scene(&scene, &report, &file)?;
    let engines = if args.engines {
        engines_against(&fitted, &data, report.verdict.noise)
    } else {
        Vec::new()
    };
    let wrote = match &args.write_scene {
        Some(out) => Some(write_scene(args, registry, &fitted, out)?),
        None => None,
    };
    let output = FitOutput {
        scene: scene.name.clone(),
        data: file,
        points: data.len(),
        v_range: data.v_range(),
        verdict_text: verdict_words(&report.verdict, None),
        report,
        engines,
        wrote,
    };
    match args.format {
        Format::Table => Ok(render_table(&output, &data, &fitted, args.residuals)),
        Format::Json => super::json(&output),
        Format::Csv => Ok(render_csv(&output.report)),
    }
}

/// The scene with the best-ranked fit (of those asked for) as its `[fit]`, e set from it at v₀.
pub fn fitted_scene(scene: &Scene, report: &FitReport, file: &str) -> Result<Scene, CliError> {
    let best = &report.fits[0];
    let key = constant_of(best.candidate).map(|c| c.0);
    let Some(constant) = best.params.iter().find(|p| Some(p.spec.key) == key) else {
        return Ok(scene.clone());
    };
    let mut fitted = scene.clone();
    fitted.fit = Some(FittedLaw {
        kind: best.candidate,
        value: constant.value,
        source: Some(file.to_string()),
        note: Some(format!(
            "ranked first of {} by {} (weight {}) over {} points",
            report.fits.len(),
            report.criterion.name(),
            significant(best.weight, 3, Zeros::Keep),
            best.n_points
        )),
    });
    fitted
        .apply_fit()
        .map_err(|e| CliError::Usage(format!("the fitted {}: {e}", best.candidate)))?;
    Ok(fitted)
}

/// Writes `fitted` with the source scene's description, view and `[system]`; says so.
fn write_scene(
    args: &FitArgs,
    registry: &Registry,
    fitted: &Scene,
    out: &Path,
) -> Result<String, CliError> {
    let name = &args.source.scene;
    let description = registry.scene_description(name)?;
    let mut view = registry.scene_view(name)?;
    // The fitted law checked and focused in the explorer.
    if let Some(model) = fitted.fit.as_ref().and_then(|f| f.kind.model()) {
        view.models.retain(|m| *m != model);
        view.models.insert(0, model);
    }
    let system = registry.scene_system(name, &args.source.overrides)?;
    let text = to_toml_with_system(fitted, description.as_deref(), Some(&view), system.as_ref());
    std::fs::write(out, text).map_err(|e| {
        CliError::Usage(format!(
            "--write-scene: cannot write {}: {e}",
            out.display()
        ))
    })?;
    Ok(out.display().to_string())
}

/// A number for tables: 4 significant digits, never NaN (`-` where undetermined).
fn num(x: f64) -> String {
    if x.is_finite() {
        significant(x, 4, Zeros::Keep)
    } else if x.is_nan() {
        "-".to_string()
    } else {
        "∞".to_string()
    }
}

/// A measured or stated number: 4 significant digits, trailing zeros dropped.
fn given(x: f64) -> String {
    significant(x, 4, Zeros::Trim)
}

/// `a = 1.203 s/m` with its interval `[1.18, 1.23]`; several parameters joined by `; `.
fn parameter_cells(fit: &LawFit) -> (String, String) {
    let mut values = Vec::new();
    let mut cis = Vec::new();
    for p in &fit.params {
        let unit = if p.spec.unit == "1" {
            String::new()
        } else {
            format!(" {}", p.spec.unit)
        };
        values.push(format!("{} = {}{unit}", p.spec.symbol, num(p.value)));
        cis.push(if p.ci.0.is_finite() && p.ci.1.is_finite() {
            format!("[{}, {}]", num(p.ci.0), num(p.ci.1))
        } else {
            "undetermined".to_string()
        });
    }
    (values.join("; "), cis.join("; "))
}

/// The verdict in plain words, with its numbers (`trace`: the unit of a trace's values, whose
/// noise is in it and whose range is no velocity range).
pub fn verdict_words(v: &Verdict, trace: Option<&str>) -> String {
    let c = v.criterion.name();
    let mut out = if let Some(unit) = trace {
        format!(
            "Best: {} by {c} (Akaike weight {}), noise {} {unit}.",
            v.best,
            significant(v.best_weight, 3, Zeros::Keep),
            given(v.noise)
        )
    } else {
        format!(
            "Best: {} by {c} (Akaike weight {}) over v0 = {} to {} m/s, noise {}.",
            v.best,
            significant(v.best_weight, 3, Zeros::Keep),
            given(v.v_range.0),
            given(v.v_range.1),
            given(v.noise)
        )
    };
    match v.runner_up {
        Some((next, delta)) => out.push_str(&format!(
            "\nNext distinguishable: {next}, Δ{c} = {}: {}.",
            num(delta),
            support(delta)
        )),
        None => out.push_str("\nNo other law fitted is distinguishable from it."),
    }
    for group in &v.groups {
        let members: Vec<&str> = group.members.iter().map(|c| c.id()).collect();
        out.push_str(&format!(
            "\nThe data cannot tell apart {}: their e(v) differ by at most {} over the data, within the noise {} (Δ{c} up to {})",
            members.join(", "),
            num(group.max_gap),
            given(group.noise),
            num(group.max_delta)
        ));
        if !group.identical.is_empty() {
            let same: Vec<&str> = group.identical.iter().map(|c| c.id()).collect();
            out.push_str(&format!(
                "; {} the same e(v) as {} on any data",
                same.join(", "),
                members[0]
            ));
        }
        out.push('.');
    }
    out
}

/// Burnham & Anderson's reading of a Δ (Model Selection and Multimodel Inference, 2002, §2.6).
fn support(delta: f64) -> &'static str {
    if delta <= 2.0 {
        "about as well supported"
    } else if delta <= 7.0 {
        "considerably less supported"
    } else if delta <= 10.0 {
        "much less supported"
    } else {
        "essentially no support"
    }
}

fn render_table(
    output: &FitOutput,
    data: &RestitutionData,
    fitted: &Scene,
    every_residual: bool,
) -> String {
    let report = &output.report;
    let mut out = format!(
        "Fit of e(v0) to {}: {} point{}, v0 = {} to {} m/s{}; k, n, m from {}\n",
        output.data,
        output.points,
        if output.points == 1 { "" } else { "s" },
        given(output.v_range.0),
        given(output.v_range.1),
        if report.weighted {
            ", weighted by the given sd"
        } else {
            ""
        },
        output.scene
    );
    out.push_str(&ranking(report));
    out.push_str(&format!("{}\n", output.verdict_text));
    let best = &report.fits[0];
    if !every_residual {
        out.push_str(&residual_summary(best, data));
    } else {
        out.push_str(&format!(
            "Residuals of {} (e law − e measured):\n",
            best.candidate
        ));
        out.push_str(&residual_rows(best, data));
    }
    out.push_str(&scene_line(fitted));
    if !output.engines.is_empty() {
        out.push_str(&render_engines(&output.engines));
    }
    if let Some(path) = &output.wrote {
        out.push_str(&format!("wrote {path}\n"));
    }
    out
}

/// `Residuals of … (e law − e measured): RMS …, largest … at v0 = … m/s`.
fn residual_summary(best: &LawFit, data: &RestitutionData) -> String {
    let n = best.residuals.len().max(1) as f64;
    let rms = (best.residuals.iter().map(|r| r * r).sum::<f64>() / n).sqrt();
    let largest = best
        .residuals
        .iter()
        .zip(&data.points)
        .max_by(|a, b| a.0.abs().total_cmp(&b.0.abs()));
    let mut out = format!(
        "Residuals of {} (e law − e measured): RMS {}",
        best.candidate,
        num(rms)
    );
    if let Some((r, p)) = largest {
        out.push_str(&format!(
            ", largest {} at v0 = {} m/s (each: --residuals)",
            num(*r),
            given(p.v)
        ));
    }
    out.push('\n');
    out
}

/// The best law's residual at every point.
fn residual_rows(best: &LawFit, data: &RestitutionData) -> String {
    let mut rows = vec![
        ["v0 (m/s)", "e measured", "sd", "e law", "residual"]
            .map(String::from)
            .to_vec(),
    ];
    for (p, r) in data.points.iter().zip(&best.residuals) {
        rows.push(vec![
            given(p.v),
            given(p.e),
            p.sd.map_or("-".to_string(), given),
            num(p.e + r),
            num(*r),
        ]);
    }
    columns(&rows, "  ")
}

/// The ranking of a trace fit, the verdict and what the scene would carry.
fn render_trace_table(output: &FitOutput, data: &TraceData, fitted: &Scene) -> String {
    let report = &output.report;
    let what = match data.quantity {
        TraceQuantity::Force => "F(t)",
        TraceQuantity::Displacement => "x(t)",
    };
    let mut out = format!(
        "Fit of the trace {what} in {}: {} samples over t = {} to {} s; k, n, m and v0 from {}\n",
        output.data,
        output.points,
        given(output.v_range.0),
        given(output.v_range.1),
        output.scene
    );
    out.push_str(&ranking(report));
    out.push_str(&format!("{}\n", output.verdict_text));
    out.push_str(&scene_line(fitted));
    if let Some(path) = &output.wrote {
        out.push_str(&format!("wrote {path}\n"));
    }
    out
}

/// The ranking table: rank, law, parameters and intervals, misfit, criterion, Δ, weight; then
/// the laws not fitted.
fn ranking(report: &FitReport) -> String {
    let c = report.criterion.name();
    let level = report.fits[0].params.first().map_or(0.95, |p| p.level);
    let misfit = if report.weighted { "χ²" } else { "RSS" };
    let mut rows = vec![vec![
        "rank".to_string(),
        "law".to_string(),
        "parameter".to_string(),
        format!("{} % CI", significant(level * 100.0, 3, Zeros::Trim)),
        misfit.to_string(),
        c.to_string(),
        format!("Δ{c}"),
        "weight".to_string(),
    ]];
    for (i, f) in report.fits.iter().enumerate() {
        let (value, ci) = parameter_cells(f);
        rows.push(vec![
            (i + 1).to_string(),
            f.candidate.id().to_string(),
            value,
            ci,
            num(f.chi2.unwrap_or(f.rss)),
            num(f.score(report.criterion)),
            num(f.delta),
            num(f.weight),
        ]);
    }
    let mut out = columns(&rows, "  ");
    if !report.failed.is_empty() {
        out.push_str("Not fitted:\n");
        for (candidate, why) in &report.failed {
            out.push_str(&format!("  {candidate}: {why}\n"));
        }
    }
    out
}

/// `As a scene: [fit] law = "…", a = … s/m; at its v0 = … m/s, e = …`, or nothing.
fn scene_line(fitted: &Scene) -> String {
    let Some(fit) = &fitted.fit else {
        return String::new();
    };
    let (key, _, unit) = fit.constant();
    format!(
        "As a scene: [fit] law = \"{}\", {key} = {} {unit}; at its v0 = {} m/s, e = {}\n",
        fit.kind,
        num(fit.value),
        given(fitted.impact.v0),
        num(fitted.impact.restitution)
    )
}

fn render_csv(report: &FitReport) -> String {
    let mut out = String::from(
        "rank,law,parameter,unit,value,std_error,ci_low,ci_high,level,rss,chi2,aic,aicc,bic,delta,weight\n",
    );
    let opt = |x: f64| {
        if x.is_finite() {
            x.to_string()
        } else {
            String::new()
        }
    };
    for (i, f) in report.fits.iter().enumerate() {
        let p = &f.params[0];
        out.push_str(&format!(
            "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n",
            i + 1,
            f.candidate,
            p.spec.key,
            field(p.spec.unit),
            round_trip(p.value),
            opt(p.std_error),
            opt(p.ci.0),
            opt(p.ci.1),
            round_trip(p.level),
            round_trip(f.rss),
            f.chi2.map_or(String::new(), opt),
            opt(f.aic),
            opt(f.aicc),
            opt(f.bic),
            opt(f.delta),
            opt(f.weight),
        ));
    }
    out
}

/// One engine's realised e(v₀) against measured restitution.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct EngineAgainstData {
    /// The engine's id.
    pub engine: &'static str,
    /// Its law among hertz-tui's.
    pub law: String,
    /// The engine's e at each measured velocity, in the data's order (empty when it failed).
    pub e: Vec<f64>,
    /// RMS of e_engine − e_measured.
    pub rms: Option<f64>,
    /// Whether the RMS is within [`REPRODUCES_WITHIN`]·noise.
    pub reproduces: Option<bool>,
    /// Why the engine could not be evaluated.
    pub error: Option<String>,
}

/// Each engine translated for `scene` (its constants calibrated at v₀ to the scene's e) and
/// evaluated at the data's velocities.
pub fn engines_against(
    scene: &Scene,
    data: &RestitutionData,
    noise: f64,
) -> Vec<EngineAgainstData> {
    ENGINES
        .iter()
        .map(|e| engine_against(e.id, scene, data, noise))
        .collect()
}

/// [`engines_against`] for one engine.
pub fn engine_against(
    id: &'static str,
    scene: &Scene,
    data: &RestitutionData,
    noise: f64,
) -> EngineAgainstData {
    let velocities: Vec<f64> = data.points.iter().map(|p| p.v).collect();
    match engine::translate_at(id, scene, &velocities) {
        Ok(t) => {
            let e: Vec<f64> = t.e_of_v.iter().map(|p| p.e_out).collect();
            let n = e.len().max(1) as f64;
            let rms = (e
                .iter()
                .zip(&data.points)
                .map(|(m, p)| (m - p.e).powi(2))
                .sum::<f64>()
                / n)
                .sqrt();
            EngineAgainstData {
                engine: id,
                law: t.model.to_string(),
                e,
                rms: Some(rms),
                reproduces: Some(rms <= REPRODUCES_WITHIN * noise),
                error: None,
            }
        }
        Err(err) => EngineAgainstData {
            engine: id,
            law: String::new(),
            e: Vec::new(),
            rms: None,
            reproduces: None,
            error: Some(err.to_string()),
        },
    }
}

/// The engines' table: RMS residual and the answer in words.
pub fn render_engines(engines: &[EngineAgainstData]) -> String {
    let mut rows = vec![
        ["engine", "its law", "RMS e − data", "these measurements"]
            .map(String::from)
            .to_vec(),
    ];
    for e in engines {
        rows.push(match (&e.error, e.rms, e.reproduces) {
            (None, Some(rms), Some(ok)) => vec![
                e.engine.to_string(),
                e.law.clone(),
                num(rms),
                if ok {
                    "can reproduce".to_string()
                } else {
                    "cannot reproduce".to_string()
                },
            ],
            (error, _, _) => vec![
                e.engine.to_string(),
                "-".into(),
                "-".into(),
                format!("not evaluated: {}", error.as_deref().unwrap_or("no result")),
            ],
        });
    }
    format!(
        "Engines, constants calibrated at the scene's v0, against the data (reproduce: RMS ≤ {REPRODUCES_WITHIN} × noise):\n{}",
        columns(&rows, "  ")
    )
}
