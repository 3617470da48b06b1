//! Drake with the SAP solver: the Drake script with `relaxation_time` on both geometries, the
//! discrete plant only (SAP is a discrete solver), at the printed step.
//!
//! SAP's law from the printed input: K = k/2, τ the sum of the two relaxation times,
//! F = (K·x + τ·K·ẋ)₊, stepped as implicit Euler (SAP's convex approximation for one frictionless
//! contact; checked against Drake 1.51 to 1e-13).

use super::super::error::EngineError;
use super::super::{EngineScene, Translation};
use super::drake::{CHECKED_IN, script};
use super::{Bodies, Claim, Run, Scheme, Script, num, parameter, stepped};

/// Builds Drake SAP's run.
pub fn run(scene: &EngineScene, t: &Translation, tolerance: f64) -> Result<Run, EngineError> {
    let k = parameter(t, "point_contact_stiffness")?;
    let tau = parameter(t, "relaxation_time")?;
    let (big_k, tau_total) = (0.5 * k, 2.0 * tau);
    let force = move |x: f64, v: f64| big_k * (x + tau_total * v);
    let choice = stepped(
        scene,
        t,
        Scheme::ImplicitEuler,
        tolerance,
        f64::INFINITY,
        &force,
    )?;
    let claim = Claim::Stepped(choice);
    let bodies = match Bodies::of(scene) {
        Ok(b) => b,
        Err(reason) => return Ok(super::without_script(CHECKED_IN, claim, reason)),
    };
    let props = format!(
        "<drake:point_contact_stiffness>{}</drake:point_contact_stiffness><drake:relaxation_time>{}</drake:relaxation_time>",
        num(k),
        num(tau)
    );
    let header = format!(
        "#   python3 impact.py   discrete plant, SAP at TIME_STEP: hertz-tui's model of its stepping\n#                       gives e = {}, F_max = {} N, contact time {} s",
        num(choice.at_step.e_out),
        num(choice.at_step.f_max),
        num(choice.at_step.t_contact),
    );
    let text = script(scene, &bodies, &props, choice.step, "sap", &header, true);
    Ok(Run::run_in(
        CHECKED_IN,
        claim,
        Script {
            file: "impact.py",
            language: "python",
            command: "python3 impact.py",
            text,
        },
        vec![
            "Checked in Drake 1.51.1 only. On a step comparable to the contact time SAP's near-rigid regime (near_rigid_threshold) changes the law; the printed step is far below it.".into(),
            "TAMSI, Similar and Lagged ignore relaxation_time and use hunt_crossley_dissipation: use `translate --engine drake` for them.".into(),
        ],
        Vec::new(),
    ))
}
