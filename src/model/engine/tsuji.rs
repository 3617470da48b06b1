//! Hertz with Tsuji's viscous damping, the law Chrono (SMC Hertz), LIGGGHTS (hertz), LAMMPS
//! (granular hertz/material) and Yade (Hertz–Mindlin) integrate: F = k·x^{3/2} + γ·x^{1/4}·ẋ,
//! k = (4/3)·E*·√R, γ = 2√(5/6)·|β(e)|·√(2E*√R·m) (Tsuji et al., Powder Technol. 71, 1992;
//! docs/physics.md §7). Its realised e depends on β alone (not on k, m or v₀) and on the end rule.
//! As hertz-tui laws: the `hertz-viscous` (F ≥ 0) and `hertz-viscous-tension` rows, damping γ.

use std::f64::consts::PI;

use crate::model::error::ModelError;
use crate::model::force::{AnyLaw, ForceModel};

use super::error::EngineError;
use super::solve::{calibrated_damping, realise, solve};
use super::{Engine, EngineScene, Fragment, Parameter, Translation, shown};

/// The row of an engine that clamps the force at F ≥ 0.
pub const CLAMPED: ForceModel = ForceModel::with_id("hertz-viscous");

/// The row of an engine that lets the force pull until x = 0.
pub const TENSION: ForceModel = ForceModel::with_id("hertz-viscous-tension");

/// β = ln e/√(ln² e + π²) (≤ 0): the restitution map of Tsuji et al. (Powder Technol. 1992) that
/// Chrono, LIGGGHTS, LAMMPS and Yade share (docs/physics.md §7).
pub fn beta(e: f64) -> f64 {
    let l = e.ln();
    l / (l * l + PI * PI).sqrt()
}

/// The e of β ∈ (−1, 0]: ln e = π·β/√(1 − β²), the β-map inverted; `None` for |β| ≥ 1.
pub fn restitution_of_beta(beta: f64) -> Option<f64> {
    (beta.abs() < 1.0).then(|| (PI * beta / (1.0 - beta * beta).sqrt()).exp())
}

/// 2√(5/6)·√(S₁·m), S₁ = 2E*√R: γ per |β|, N·s/m^{5/4}.
fn gamma_per_beta(scene: &EngineScene) -> f64 {
    2.0 * (5.0_f64 / 6.0).sqrt() * (2.0 * scene.e_star * scene.r_star.sqrt() * scene.mass).sqrt()
}

/// γ = 2√(5/6)·|β(e)|·√(S₁·m), S₁ = 2E*√R: the damping per x^{1/4} these engines derive from the
/// restitution `e` they are given, N·s/m^{5/4}.
pub fn gamma(scene: &EngineScene, e: f64) -> f64 {
    beta(e).abs() * gamma_per_beta(scene)
}

/// The law `model` (a row of this family) with damping γ for an impact at `v0`.
pub fn law_with(
    scene: &EngineScene,
    model: ForceModel,
    gamma: f64,
    v0: f64,
) -> Result<AnyLaw, ModelError> {
    model.law_with_damping(&scene.params(scene.elastic, v0), gamma)
}

/// The smallest input restitution tried under the clamp, which always ends contact early:
/// Chrono floors its input at machine ε (ln ε).
const SMALLEST_CLAMPED_INPUT: f64 = 1e-15;

/// The smallest input tried with tension allowed: there the realised e is the input, and the
/// return to x = 0 slows without bound as e → 0 (the damper dominates k·x^{3/2} near x = 0).
const SMALLEST_TENSILE_INPUT: f64 = 1e-6;

/// The damping γ of `model` whose realised e at v₀ is the scene's, by hertz-tui's calibration,
/// within the γ the engine's inputs reach (`gamma_max`).
pub fn calibrated_gamma(
    engine: &'static str,
    scene: &EngineScene,
    model: ForceModel,
    gamma_min: f64,
    gamma_max: f64,
) -> Result<f64, EngineError> {
    scene.require_point_contact(engine)?;
    calibrated_damping(
        engine,
        model,
        scene,
        scene.elastic,
        gamma_min..=gamma_max,
        |g| law_with(scene, model, g, scene.v0),
    )
}

/// The input restitution whose realised e at v₀ is the scene's under `model`'s end rule: the
/// calibrated γ through the inverted β-map.
pub fn input_restitution(
    engine: &'static str,
    scene: &EngineScene,
    model: ForceModel,
) -> Result<f64, EngineError> {
    let lo = if model == CLAMPED {
        SMALLEST_CLAMPED_INPUT
    } else {
        SMALLEST_TENSILE_INPUT
    };
    let g = calibrated_gamma(engine, scene, model, 0.0, gamma(scene, lo))?;
    restitution_of_beta(-g / gamma_per_beta(scene)).ok_or(EngineError::Unreachable {
        engine,
        requested: scene.restitution,
        reason: format!("γ = {} needs |β| ≥ 1", shown(g)),
    })
}

/// The realised restitution of damping γ under the other end rule: what a user who leaves the
/// engine's clamp setting the other way gets.
pub fn other_rule_e(
    scene: &EngineScene,
    gamma: f64,
    model: ForceModel,
) -> Result<f64, EngineError> {
    let other = if model == CLAMPED { TENSION } else { CLAMPED };
    Ok(solve(&law_with(scene, other, gamma, scene.v0)?)?.e_out)
}

/// The id of this law in hertz-tui's law table (`--model`) for `model`.
pub fn family_id(model: ForceModel) -> &'static str {
    model.name()
}

/// How one engine of this family takes the law.
pub struct Family {
    /// The engine.
    pub engine: &'static Engine,
    /// Its row of the law table: [`CLAMPED`] or [`TENSION`].
    pub model: ForceModel,
    /// The engine's name for its restitution input.
    pub parameter: &'static str,
    /// The value the engine really stores for an input (Chrono keeps single precision).
    pub stored: fn(f64) -> f64,
}

/// The shared translation: calibrate the input restitution under the family's end rule, then
/// state what it realises; `fragments` prints the engine's input with it.
pub fn translate(
    family: &Family,
    scene: &EngineScene,
    fragments: impl FnOnce(&Parameter) -> Vec<Fragment>,
    mut notes: Vec<String>,
) -> Result<Translation, EngineError> {
    let engine = family.engine;
    let model = family.model;
    let rule = model.spec().contact.describe();
    let e_in = input_restitution(engine.id, scene, model)?;
    let parameter = Parameter::new(
        family.parameter,
        e_in,
        "",
        format!(
            "the input restitution whose realised e at v₀ = {} m/s is the requested {} under the {} (hertz-tui's calibration of {}, β-map inverted)",
            shown(scene.v0),
            shown(scene.restitution),
            rule,
            model.name()
        ),
    );
    let stored = (family.stored)(parameter.value);
    let g = gamma(scene, stored);
    let (realised, e_of_v) = realise(scene, |v0| Ok(law_with(scene, model, g, v0)?))?;
    let naive = solve(&law_with(
        scene,
        model,
        gamma(scene, scene.restitution),
        scene.v0,
    )?)?;
    notes.insert(
        0,
        format!(
            "Given the requested e itself ({}), the engine realises {} ({}); with the other end rule the input above gives {}.",
            shown(scene.restitution),
            shown(naive.e_out),
            rule,
            shown(other_rule_e(scene, g, model)?)
        ),
    );
    notes.push(
        "The damping grows with x^{1/4} and β alone sets e: e does not change with v₀, k or m."
            .into(),
    );
    let fragments = fragments(&parameter);
    Ok(Translation {
        engine: engine.id,
        name: engine.name,
        source: engine.source,
        law: format!(
            "F = k·x^(3/2) + γ·x^(1/4)·ẋ with k = (4/3)E*√R = {} N/m^1.5, γ = 2√(5/6)|β|√(2E*√R·m) = {} N·s/m^1.25",
            shown(scene.elastic.k),
            shown(g)
        ),
        hertz_tui_law: format!(
            "Hertz with Tsuji's viscous damping ({}), β = {}, {}",
            family_id(model),
            shown(beta(stored)),
            rule
        ),
        model,
        end_rule: model.spec().contact,
        approximation: None,
        parameters: vec![parameter],
        fragments,
        notes,
        v0: scene.v0,
        e_requested: scene.restitution,
        realised,
        e_of_v,
    })
}
