//! Hertz with Tsuji's viscous damping, the law Chrono (SMC Hertz), LIGGGHTS (hertz), LAMMPS
//! (granular hertz/material) and Yade (Hertz–Mindlin) integrate: F = k·x^{3/2} + γ·x^{1/4}·ẋ,
//! k = (4/3)·E*·√R, γ = 2√(5/6)·|β(e)|·√(2E*√R·m) (Tsuji et al., Powder Technol. 71, 1992;
//! docs/physics.md §7). Its realised e depends on β alone (not on k, m or v₀) and on the end rule.

use super::calibrate::{beta, solve_for_restitution};
use super::contact::{self, ContactLaw, EndRule, EngineDamping};
use super::error::EngineError;
use super::{Engine, EngineScene, Fragment, Parameter, Translation, realise, shown};

/// γ = 2√(5/6)·|β(e)|·√(S₁·m), S₁ = 2E*√R: the damping per x^{1/4} these engines derive from the
/// restitution `e` they are given, N·s/m^{5/4}.
pub fn gamma(scene: &EngineScene, e: f64) -> f64 {
    2.0 * (5.0_f64 / 6.0).sqrt()
        * beta(e).abs()
        * (2.0 * scene.e_star * scene.r_star.sqrt() * scene.mass).sqrt()
}

/// The law for viscous coefficient `c` (per x^{1/4}) ending by `end`.
pub fn law_with(scene: &EngineScene, c: f64, end: EndRule) -> ContactLaw {
    ContactLaw {
        elastic: scene.elastic,
        damping: EngineDamping::Viscous { c, p: 0.25 },
        end,
    }
}

/// The law an engine builds from input restitution `e_in`.
pub fn law(scene: &EngineScene, e_in: f64, end: EndRule) -> ContactLaw {
    law_with(scene, gamma(scene, e_in), end)
}

/// The smallest input restitution tried under the clamp, which always ends contact early:
/// Chrono floors its input at machine ε (ln ε).
const SMALLEST_CLAMPED_INPUT: f64 = 1e-15;

/// The smallest input tried with tension allowed: there the realised e is the input, and the
/// return to x = 0 slows without bound as e → 0 (the damper dominates k·x^{3/2} near x = 0).
const SMALLEST_TENSILE_INPUT: f64 = 1e-6;

/// The input restitution whose realised e at v₀ is the scene's, under `end`.
pub fn input_restitution(
    engine: &'static str,
    scene: &EngineScene,
    end: EndRule,
) -> Result<f64, EngineError> {
    scene.require_point_contact(engine)?;
    let lo = match end {
        EndRule::Clamp => SMALLEST_CLAMPED_INPUT,
        EndRule::Tension => SMALLEST_TENSILE_INPUT,
    };
    solve_for_restitution(engine, scene.restitution, lo, 1.0, |e_in| {
        contact::solve(&law(scene, e_in, end), scene.mass, scene.v0).map(|r| r.e_out)
    })
}

/// The realised restitution of input `e_in` under the other end rule: what a user who leaves
/// the engine's clamp setting the other way gets.
pub fn other_rule_e(scene: &EngineScene, e_in: f64, end: EndRule) -> Result<f64, EngineError> {
    let other = match end {
        EndRule::Clamp => EndRule::Tension,
        EndRule::Tension => EndRule::Clamp,
    };
    contact::solve(&law(scene, e_in, other), scene.mass, scene.v0).map(|r| r.e_out)
}

/// The id of this law in hertz-tui's law table (`--model`) under `end`.
pub fn family_id(end: EndRule) -> &'static str {
    match end {
        EndRule::Clamp => "hertz-viscous",
        EndRule::Tension => "hertz-viscous-tension",
    }
}

/// How one engine of this family takes the law.
pub struct Family {
    /// The engine.
    pub engine: &'static Engine,
    /// How its contact ends.
    pub end: EndRule,
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
    let e_in = input_restitution(engine.id, scene, family.end)?;
    let parameter = Parameter::new(
        family.parameter,
        e_in,
        "",
        format!(
            "the input restitution whose realised e at v₀ = {} m/s is the requested {} under the {} (Brent root on hertz-tui's solve)",
            shown(scene.v0),
            shown(scene.restitution),
            family.end.describe()
        ),
    );
    let stored = (family.stored)(parameter.value);
    let law = law(scene, stored, family.end);
    let (realised, e_of_v) = realise(&law, scene)?;
    notes.insert(
        0,
        format!(
            "Given the requested e itself ({}), the engine realises {} ({}); with the other end rule the input above gives {}.",
            shown(scene.restitution),
            shown(
                contact::solve(&self::law(scene, scene.restitution, family.end), scene.mass, scene.v0)?.e_out
            ),
            family.end.describe(),
            shown(other_rule_e(scene, stored, family.end)?)
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
            shown(law.elastic.k),
            shown(gamma(scene, stored))
        ),
        hertz_tui_law: format!(
            "Hertz with Tsuji's viscous damping ({}), β = {}, {}",
            family_id(family.end),
            shown(beta(stored)),
            family.end.describe()
        ),
        end_rule: family.end,
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
