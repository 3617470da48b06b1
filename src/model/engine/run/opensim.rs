//! OpenSim (Simbody's HuntCrossleyForce): a Python script (pip `opensim`) building the sphere on
//! a ContactHalfSpace turned so that its normal is +y (OpenSim's half-space faces −x in its own
//! frame), with the printed stiffness and dissipation on both surfaces, integrated by OpenSim's
//! error-controlled Runge–Kutta–Merson: the continuous law, claimed to 1e-3 in e.

use super::super::error::EngineError;
use super::super::{EngineScene, Translation};
use super::{Bodies, CONTINUOUS_TOLERANCE, Claim, PY_RESULT, Run, Script, num, parameter};

/// The OpenSim release the script was run in.
pub const CHECKED_IN: &str = "OpenSim 4.6 (pip install opensim==4.6)";

/// Builds OpenSim's run.
pub fn run(scene: &EngineScene, t: &Translation, _tolerance: f64) -> Result<Run, EngineError> {
    let stiffness = parameter(t, "stiffness")?;
    let dissipation = parameter(t, "dissipation")?;
    let claim = Claim::Continuous {
        integrator: "OpenSim's Manager, Runge–Kutta–Merson at accuracy 1e-10",
        tolerance: CONTINUOUS_TOLERANCE,
    };
    let bodies = match Bodies::of(scene) {
        Ok(b) => b,
        Err(reason) => return Ok(super::without_script(CHECKED_IN, claim, reason)),
    };
    let body = |name: &str, r: f64, m: f64| {
        let i = num(0.4 * m * r * r);
        format!(
            "{name} = osim.Body(\"{name}\", {}, osim.Vec3(0), osim.Inertia({i}, {i}, {i}))\nmodel.addBody({name})\nmodel.addJoint(osim.FreeJoint(\"{name}_free\", model.getGround(), {name}))\nmodel.addContactGeometry(osim.ContactSphere({}, osim.Vec3(0), {name}, \"{name}_contact\"))",
            num(m),
            num(r)
        )
    };
    let (build, start, x_v) = match bodies {
        Bodies::OnPlate { radius, mass } => (
            format!(
                "{}\n# The half-space's normal is −x in its frame: turned by −π/2 about z it faces +y.\nmodel.addContactGeometry(\n    osim.ContactHalfSpace(osim.Vec3(0), osim.Vec3(0, 0, -math.pi / 2), model.getGround(), \"body2_contact\")\n)",
                body("body1", radius, mass)
            ),
            format!(
                "y1 = model.getCoordinateSet().get(\"body1_free_coord_4\")  # translation along y\ny1.setValue(state, {})  # touching\ny1.setSpeedValue(state, -V0)",
                num(radius)
            ),
            format!(
                "    return {} - y1.getValue(state), y1.getSpeedValue(state)",
                num(radius)
            ),
        ),
        Bodies::Spheres { moving, other } => (
            format!(
                "{}\n{}",
                body("body1", moving.0, moving.1),
                body("body2", other.0, other.1)
            ),
            format!(
                "y1 = model.getCoordinateSet().get(\"body1_free_coord_4\")  # translation along y\ny2 = model.getCoordinateSet().get(\"body2_free_coord_4\")\ny1.setValue(state, {})  # touching\ny2.setValue(state, -{})\ny1.setSpeedValue(state, -V0)",
                num(moving.0),
                num(other.0)
            ),
            format!(
                "    gap = y1.getValue(state) - y2.getValue(state)\n    return {} - gap, y1.getSpeedValue(state) - y2.getSpeedValue(state)",
                num(moving.0 + other.0)
            ),
        ),
    };
    let text = format!(
        r#"# hertz-tui translate --engine simbody: {name}
# Runs as printed in {CHECKED_IN}: python3 impact.py
# HuntCrossleyForce, no friction, no gravity, integrated with error control: the law itself,
# e = {e}, F_max = {f} N, contact time {tc} s (e to 1e-3 or better).
import math

import opensim as osim

osim.Logger.setLevelString("warn")  # the Manager reports every integrate() otherwise
V0 = {v0}  # m/s, impact velocity
model = osim.Model()
model.setGravity(osim.Vec3(0, 0, 0))
{build}
contact = osim.HuntCrossleyForce()
contact.setName("impact")
contact.addGeometry("body1_contact")
contact.addGeometry("body2_contact")
contact.setStiffness({stiffness})  # Pa, per surface
contact.setDissipation({dissipation})  # s/m, per surface
contact.setStaticFriction(0)
contact.setDynamicFriction(0)
contact.setViscousFriction(0)
model.addForce(contact)
state = model.initSystem()
{start}


def approach():
    """Approach x (m) and its rate (m/s, < 0 closing)."""
{x_v}


manager = osim.Manager(model)
manager.setIntegratorAccuracy(1e-10)
state.setTime(0)
manager.initialize(state)
dt, x_prev, touched, f_max, contact_time = {sample}, 0.0, False, 0.0, 0.0
for n in range(200000):
    state = manager.integrate((n + 1) * dt)
    model.realizeDynamics(state)
    record = contact.getRecordValues(state)
    f_max = max(f_max, math.sqrt(sum(record.get(i) ** 2 for i in range(3))))
    x, rate = approach()
    touched = touched or x > 0
    if touched and x <= 0:
        contact_time = n * dt + dt * x_prev / (x_prev - x)  # where x returned to 0
        break
    x_prev = x
e_out = rate / V0
{PY_RESULT}
"#,
        name = scene.scene.name,
        e = num(t.realised.e_out),
        f = num(t.realised.f_max),
        tc = num(t.realised.t_contact),
        v0 = num(scene.v0),
        stiffness = num(stiffness),
        dissipation = num(dissipation),
        sample = num(scene.t_contact / 1000.0),
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
            "OpenSim 4.x and Simbody 3.x share this HuntCrossleyForce (f = k·x^(3/2)·(1 + 1.5·c·ẋ)); OpenSim 4.6 is the release run.".into(),
            "With a fixed-step integrator (e.g. Manager.setIntegratorMethod with a fixed step) the claim is not modelled: keep the error-controlled default.".into(),
        ],
        Vec::new(),
    ))
}
