//! MuJoCo: a Python script (pip `mujoco`) building the MJCF, stepping it with MuJoCo's default
//! `Euler` integrator at the printed step, and reading the contact force of every step.
//!
//! MuJoCo's law from the printed solref (timeconst, dampratio) with a constant impedance (the
//! translation's notes): ẍ = −(K·x + B·ẋ), K = 1/(timeconst·dampratio)², B = 2/timeconst, on the
//! reduced mass, clamped at f ≥ 0 (doc/computation.rst, "Soft constraints"). MuJoCo raises a
//! timeconst below 2·timestep to 2·timestep, so the step is kept at or below timeconst/2.

use super::super::error::EngineError;
use super::super::{EngineScene, Fragment, Translation};
use super::{
    Bodies, Claim, PY_RESULT, Run, Scheme, Script, gap, max_steps, num, parameter, stepped,
};

/// The MuJoCo release the script was run in.
pub const CHECKED_IN: &str = "MuJoCo 4.0.0 (pip install mujoco==4.0.0)";

/// A constant impedance: d_min = d_max = 0.95 (as the translation assumes).
const SOLIMP: &str = "0.95 0.95 0.001 0.5 2";

/// Builds MuJoCo's run.
pub fn run(scene: &EngineScene, t: &Translation, tolerance: f64) -> Result<Run, EngineError> {
    let timeconst = parameter(t, "timeconst")?;
    let dampratio = parameter(t, "dampratio")?;
    let (k, b) = (1.0 / (timeconst * dampratio).powi(2), 2.0 / timeconst);
    let mass = scene.mass;
    let force = move |x: f64, v: f64| mass * (k * x + b * v).max(0.0);
    let choice = stepped(
        scene,
        t,
        Scheme::SemiImplicitEuler,
        tolerance,
        timeconst / 2.0,
        &force,
    )?;
    let claim = Claim::Stepped(choice);
    let bodies = match Bodies::of(scene) {
        Ok(b) => b,
        Err(reason) => return Ok(super::without_script(CHECKED_IN, claim, reason)),
    };
    let solref = format!("{} {}", num(timeconst), num(dampratio));
    let mjcf = mjcf(&bodies, choice.step, gap(scene, choice.step), &solref);
    let (v_rel, contact_line) = match bodies {
        Bodies::OnPlate { .. } => (
            "data.qvel[2]",
            "data.qvel[2] = -V0  # half a step above the plate, moving into it",
        ),
        Bodies::Spheres { .. } => (
            "data.qvel[2] - data.qvel[8]",
            "data.qvel[2] = -V0  # sphere 1 half a step above sphere 2 (at rest), moving into it",
        ),
    };
    let text = format!(
        r#"# hertz-tui translate --engine mujoco: {name}
# Runs as printed in {CHECKED_IN}: python3 impact.py
# One frictionless sphere contact, no gravity, MuJoCo's default Euler integrator at the step
# hertz-tui chose: its model of this stepping gives e = {e}, F_max = {f} N, contact time {tc} s.
import mujoco
import numpy as np

V0 = {v0}  # m/s, impact velocity
MJCF = """
{mjcf}
"""

model = mujoco.MjModel.from_xml_string(MJCF)
data = mujoco.MjData(model)
{contact_line}
wrench = np.zeros(6)
f_max, steps_in_contact, touched = 0.0, 0, False
for _ in range({max_steps}):
    mujoco.mj_step(model, data)
    f = 0.0
    for i in range(data.ncon):
        mujoco.mj_contactForce(model, data, i, wrench)
        f += wrench[0]  # normal force of the step just taken
    if f != 0.0:
        steps_in_contact += 1
        touched = True
    f_max = max(f_max, f)
    v_rel = {v_rel}  # separation speed
    if touched and data.ncon == 0 and v_rel > 0:
        break
e_out = v_rel / V0
contact_time = steps_in_contact * model.opt.timestep
{PY_RESULT}
"#,
        name = scene.scene.name,
        e = num(choice.at_step.e_out),
        f = num(choice.at_step.f_max),
        tc = num(choice.at_step.t_contact),
        v0 = num(scene.v0),
        max_steps = max_steps(scene, choice.step),
    );
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
            "Checked in MuJoCo 4.0.0, with solref (timeconst, dampratio) and solimp as doc/modeling.rst describes them; MuJoCo raises a timeconst below 2·timestep to 2·timestep (refsafe), which is why the step stays at or below timeconst/2.".into(),
            "The step is MuJoCo's, not a stability bound: at timeconst/10 a lightly damped contact gains energy (e = 7.5 asked 0.9 on the Fig. 5 scene).".into(),
        ],
        vec![Fragment {
            title: "MJCF (solref = timeconst dampratio, the printed step)",
            language: "xml",
            text: mjcf,
        }],
    ))
}

/// The MJCF with body 1 declared first (its free joint's qvel is 0..6) and `gap` above touch.
fn mjcf(bodies: &Bodies, step: f64, gap: f64, solref: &str) -> String {
    let sphere = |r: f64, m: f64| {
        format!(
            "<geom type=\"sphere\" size=\"{}\" mass=\"{}\"/>",
            num(r),
            num(m)
        )
    };
    let (other, moving) = match *bodies {
        Bodies::OnPlate { radius, mass } => (
            "<geom name=\"plate\" type=\"plane\" size=\"1 1 0.1\"/>".to_string(),
            format!(
                "<body name=\"body1\" pos=\"0 0 {}\"><freejoint/>{}</body>",
                num(radius + gap),
                sphere(radius, mass)
            ),
        ),
        Bodies::Spheres { moving, other } => (
            format!(
                "<body name=\"body2\" pos=\"0 0 -{}\"><freejoint/>{}</body>",
                num(other.0),
                sphere(other.0, other.1)
            ),
            format!(
                "<body name=\"body1\" pos=\"0 0 {}\"><freejoint/>{}</body>",
                num(moving.0 + gap),
                sphere(moving.0, moving.1)
            ),
        ),
    };
    format!(
        "<mujoco>\n  <option timestep=\"{}\" gravity=\"0 0 0\" integrator=\"Euler\"/>\n  <default><geom condim=\"1\" solref=\"{solref}\" solimp=\"{SOLIMP}\"/></default>\n  <worldbody>\n    {moving}\n    {other}\n  </worldbody>\n</mujoco>",
        num(step)
    )
}
