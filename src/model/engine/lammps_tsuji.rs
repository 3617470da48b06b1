//! LAMMPS `pair_style granular`, `hertz/material` with `damping tsuji`
//! (doc/src/pair_granular.rst; src/GRANULAR/gran_sub_mod_damping.cpp, `GranSubModDampingTsuji`).
//!
//! - Law: F = (4/3)·E·√R·δ^{3/2} − η·vₙ, η = α(e)·√(m_eff·kₙ), kₙ = F_ne/δ = (4/3)·E·√(R·δ), with
//!   α(e) = 1.2728 − 4.2783e + 11.087e² − 22.348e³ + 27.467e⁴ − 18.022e⁵ + 4.8218e⁶, Tsuji's fit:
//!   Hertz with γ·δ^{1/4} damping, γ = α(e)·√(m·(4/3)E√R).
//! - Parameters, combination: as the coeff_restitution variant ([`super::lammps`]).
//! - End of contact: tension allowed unless `limit_damping` is given.

use crate::model::numeric::roots::brent;

use super::error::EngineError;
use super::solve::{realise, solve};
use super::{Engine, EngineScene, Parameter, Translation, lammps, shown, tsuji};

/// This engine's row of [`super::ENGINES`].
pub const ENGINE: Engine = Engine {
    id: "lammps-tsuji",
    name: "LAMMPS (granular, damping tsuji)",
    source: "lammps/lammps: doc/src/pair_granular.rst, src/GRANULAR/gran_sub_mod_damping.cpp",
    translate,
};

/// Tsuji's α(e) as LAMMPS evaluates it (`GranSubModDampingTsuji::init`).
pub fn alpha(e: f64) -> f64 {
    const C: [f64; 7] = [1.2728, -4.2783, 11.087, -22.348, 27.467, -18.022, 4.8218];
    C.iter().rev().fold(0.0, |acc, c| acc * e + c)
}

/// √(m·(4/3)E*√R): γ = α·this, N·s/m^{5/4}.
fn scale(scene: &EngineScene) -> f64 {
    (scene.mass * scene.elastic.k).sqrt()
}

fn translate(scene: &EngineScene) -> Result<Translation, EngineError> {
    let model = tsuji::TENSION;
    let (alpha_min, alpha_max) = (alpha(1.0), alpha(0.0));
    let gamma = tsuji::calibrated_gamma(
        ENGINE.id,
        scene,
        model,
        alpha_min * scale(scene),
        alpha_max * scale(scene),
    )?;
    let needed = gamma / scale(scene);
    let e_in = brent(|e| alpha(e) - needed, 0.0, 1.0).ok_or(EngineError::Unreachable {
        engine: ENGINE.id,
        requested: scene.restitution,
        reason: format!("no input e in [0, 1] gives α = {needed}"),
    })?;
    let parameter = Parameter::new(
        "e (hertz/material, damping tsuji)",
        e_in,
        "",
        format!(
            "the input e whose α(e) = {} realises the requested e at v₀ (hertz-tui's calibration of hertz-viscous-tension, then a Brent root on the polynomial)",
            shown(needed)
        ),
    );
    let law_of_alpha = |a: f64, v0: f64| tsuji::law_with(scene, model, a * scale(scene), v0);
    let (realised, e_of_v) = realise(scene, |v0| Ok(law_of_alpha(alpha(parameter.value), v0)?))?;
    let naive = solve(&law_of_alpha(alpha(scene.restitution), scene.v0)?)?.e_out;
    let notes = vec![
        format!(
            "Given the requested e itself ({}), α(e) = {} realises {}: Tsuji's polynomial fits e of the linear spring–dashpot's α, not this law's.",
            shown(scene.restitution),
            shown(alpha(scene.restitution)),
            shown(naive)
        ),
        "α(e) bottoms out near 0 at e = 1 and tops at 1.2728 at e = 0; a requested e outside what that range realises is refused.".into(),
        "The damping grows with x^{1/4} and α alone sets e: e does not change with v₀, k or m.".into(),
    ];
    Ok(Translation {
        engine: ENGINE.id,
        name: ENGINE.name,
        source: ENGINE.source,
        law: format!(
            "F = k·x^(3/2) + γ·x^(1/4)·ẋ with k = (4/3)E*√R = {} N/m^1.5, γ = α(e)·√(m·k) = {} N·s/m^1.25",
            shown(scene.elastic.k),
            shown(alpha(parameter.value) * scale(scene))
        ),
        hertz_tui_law: format!(
            "Hertz with Tsuji's viscous damping ({}), α = {}, {}",
            tsuji::family_id(model),
            shown(alpha(parameter.value)),
            model.spec().contact.describe()
        ),
        model,
        end_rule: model.spec().contact,
        approximation: None,
        fragments: lammps::lines(scene, &parameter.text(), "tsuji"),
        parameters: vec![parameter],
        notes,
        v0: scene.v0,
        e_requested: scene.restitution,
        realised,
        e_of_v,
    })
}
