//! The figure of docs/systems.md's compliant-stop section: the bouncing ball's period-doubling
//! threshold Γ_PD with a compliant stop, against the rigid closed form, as contact time over forcing
//! period falls — Hunt–Crossley with the exact χ (its realised e is the asked e = 0.5) and clamped
//! Kelvin–Voigt asked for e = 0.5 (it realises more), the latter against the rigid threshold at
//! both e. The same computation as `tests/model/system_compliant.rs`, on more ratios.
//!
//! `cargo bench --bench convergence -- docs/figures/compliant-convergence.svg` writes the figure
//! and prints its numbers as a table (about a minute).

use std::f64::consts::PI;

use hertz_tui::chart::ticks::{log_axis, nice_axis};
use hertz_tui::chart::{Chart, Hue, Ink, Rule, Series, figure};
use hertz_tui::format::units::DIMENSIONLESS;
use hertz_tui::model::ForceModel;
use hertz_tui::model::force::ForceLaw;
use hertz_tui::model::presets::Registry;
use hertz_tui::model::system::compliant::orbit::{MapPoint, period_doubling};
use hertz_tui::model::system::compliant::{CompliantOptions, CompliantStop, ORBIT_RTOL};
use hertz_tui::model::system::{CompliantDamping, SystemKind, SystemModel, SystemSpec};

const E: f64 = 0.5;
const G: f64 = 9.81;
const RATIOS: [f64; 9] = [0.1, 0.05, 0.03, 0.02, 0.01, 0.005, 0.003, 0.002, 0.001];

/// Γ_PD of the rigid ball (exact impact map; docs/physics.md).
fn rigid_threshold(e: f64) -> f64 {
    let sn = PI * (1.0 - e) / (1.0 + e);
    let b = 2.0 * (1.0 + e * e) / (1.0 + e).powi(2);
    (sn * sn + b * b).sqrt()
}

fn ball(frequency: f64, gamma: f64) -> SystemModel {
    let mut scene = Registry::load()
        .expect("presets")
        .scene("steel-sphere-r10-plate")
        .expect("preset");
    scene.impact.restitution = E;
    let omega = 2.0 * PI * frequency;
    let spec = SystemSpec {
        kind: SystemKind::BouncingBall {
            amplitude: gamma * G / (omega * omega),
            frequency,
            gravity: G,
        },
    };
    SystemModel::from_scene(&scene, &spec).expect("model")
}

fn stop(model: &SystemModel, law: ForceModel) -> CompliantStop {
    let damping = if law == ForceModel::HuntCrossley {
        CompliantDamping::CalibratedTo(E)
    } else {
        CompliantDamping::PerImpact
    };
    let options = CompliantOptions {
        rtol: ORBIT_RTOL,
        ..CompliantOptions::default()
    };
    CompliantStop::new(model, law, damping, options).expect("stop")
}

fn rigid_orbit(frequency: f64, gamma: f64, e: f64) -> MapPoint {
    let omega = 2.0 * PI * frequency;
    let amplitude = gamma * G / (omega * omega);
    let u = G / (2.0 * frequency);
    let phase = (u * (1.0 - e) / ((1.0 + e) * amplitude * omega)).acos();
    MapPoint {
        t: phase / omega,
        v_in: G / (frequency * (1.0 + e)),
        stop: 0,
    }
}

fn threshold(frequency: f64, law: ForceModel, e_rigid: f64) -> Option<f64> {
    let rigid = rigid_threshold(e_rigid);
    period_doubling(
        |gamma| Ok(stop(&ball(frequency, gamma), law)),
        rigid_orbit(frequency, 0.99 * rigid, e_rigid),
        (1, 1),
        (0.9 * rigid, 1.03 * rigid),
    )
    .ok()
    .flatten()
}

fn main() {
    let path = std::env::args()
        .skip(1)
        .find(|a| !a.starts_with("--"))
        .unwrap_or_else(|| "docs/figures/compliant-convergence.svg".into());
    let kv = ForceModel::with_id("kelvin-voigt");
    let probe = ball(20.0, 1.0);
    let hc_c1 = stop(&probe, ForceModel::HuntCrossley)
        .elastic
        .contact_time(probe.mass, 1.0);
    let kv_stop = stop(&probe, kv);
    let kv_law = kv_stop.source.at(1.0).expect("law");
    let exact = kv_law.exact(1e-12).expect("exact Kelvin–Voigt");
    let realised = exact.v_out / kv_stop.source.base().v0;
    let (rigid, rigid_realised) = (rigid_threshold(E), rigid_threshold(realised));
    println!(
        "rigid Γ_PD at e = {E}: {rigid:.6}; at the realised e = {realised:.4}: {rigid_realised:.6}"
    );
    println!(
        "| t_c/T | H–C exact χ: ΔΓ_PD vs rigid (e = 0.5) | K–V clamped: vs rigid at e = 0.5 | K–V: vs rigid at realised e |"
    );
    println!("|---|---|---|---|");
    let mut hc = Vec::new();
    let mut kv_asked = Vec::new();
    let mut kv_real = Vec::new();
    for ratio in RATIOS {
        // H–C: f with t_c(gT/(1+e))/T = ratio (eq 7, t_c ∝ v^(−1/5)); K–V: t_c is its own.
        let f_hc = (ratio / hc_c1 * (G / (1.0 + E)).powf(0.2)).powf(5.0 / 6.0);
        let f_kv = ratio / exact.t_contact;
        let h = threshold(f_hc, ForceModel::HuntCrossley, E).map(|g| 100.0 * (g / rigid - 1.0));
        let k = threshold(f_kv, kv, realised);
        let ka = k.map(|g| 100.0 * (g / rigid - 1.0));
        let kr = k.map(|g| 100.0 * (g / rigid_realised - 1.0));
        let cell = |v: Option<f64>| v.map_or("—".into(), |v| format!("{v:+.3} %"));
        println!("| {ratio} | {} | {} | {} |", cell(h), cell(ka), cell(kr));
        let x = ratio.log10();
        if let Some(v) = h {
            hc.push((x, v));
        }
        if let Some(v) = ka {
            kv_asked.push((x, v));
        }
        if let Some(v) = kr {
            kv_real.push((x, v));
        }
    }
    let lows: Vec<f64> = kv_asked
        .iter()
        .chain(&hc)
        .chain(&kv_real)
        .map(|p| p.1)
        .collect();
    let lo = lows.iter().copied().fold(0.0, f64::min);
    let hi = lows.iter().copied().fold(0.0, f64::max);
    let x = log_axis(RATIOS[RATIOS.len() - 1], RATIOS[0], DIMENSIONLESS, 3);
    let y = nice_axis(lo - 0.5, hi + 0.5, DIMENSIONLESS, 6);
    let series = |name: &str, ink, glyph, runs: Vec<(f64, f64)>| Series {
        name: name.into(),
        ink,
        glyph,
        runs: vec![runs],
        focused: false,
        peak: None,
        steps: true,
    };
    let chart = Chart {
        title: "Bouncing ball, e = 0.5: compliant period-doubling threshold against the rigid closed form".into(),
        x: x.chart_axis("contact time / forcing period".into()),
        y: y.chart_axis("threshold Γ, compliant/rigid − 1, %".into()),
        series: vec![
            series(
                "Hunt–Crossley, exact χ, vs rigid e = 0.5",
                Ink::Plain(Hue::Red),
                'x',
                hc,
            ),
            series(
                "Kelvin–Voigt F ≥ 0 asked e = 0.5, vs rigid e = 0.5",
                Ink::Plain(Hue::Cyan),
                '$',
                kv_asked,
            ),
            series(
                &format!("Kelvin–Voigt F ≥ 0, vs rigid at its realised e = {realised:.3}"),
                Ink::Plain(Hue::Magenta),
                '#',
                kv_real,
            ),
        ],
        marks: Vec::new(),
        rules: vec![
            Rule {
                at: 0.0,
                horizontal: true,
                ink: Ink::Foreground,
                label: "rigid".into(),
            },
            Rule {
                at: 100.0 * (rigid_realised / rigid - 1.0),
                horizontal: true,
                ink: Ink::Plain(Hue::Magenta),
                label: format!("rigid e = {realised:.3}"),
            },
        ],
        notes: Vec::new(),
        readout: None,
    };
    figure::write(&[chart], std::path::Path::new(&path), (900, 560)).expect("figure written");
    println!("figure: {path}");
}
