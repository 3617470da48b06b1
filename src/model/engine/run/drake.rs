//! Drake: a Python script (pip `drake`) building the two bodies in SDFormat with the printed
//! proximity properties, selecting point contact (MultibodyPlantConfig's default is hydroelastic
//! with fallback), and running either the continuous plant (time_step = 0, error-controlled
//! Runge–Kutta 3) or the discrete one at the printed step.
//!
//! Drake's law from the printed input (multibody/plant/contact_model_doxygen.h): two geometries of
//! stiffness k combine to K = k/2, and F = K·x·(1 + d·ẋ)₊. Its discrete approximations TAMSI,
//! Similar and Lagged step it as implicit Euler ([`Scheme::ImplicitEuler`]).

use super::super::error::EngineError;
use super::super::{EngineScene, Translation};
use super::{
    Bodies, CONTINUOUS_TOLERANCE, Claim, PY_RESULT, Run, Scheme, Script, max_steps, num, parameter,
    stepped,
};

/// The Drake release the script was run in.
pub const CHECKED_IN: &str = "Drake 1.51.1 (pip install drake==1.51.1)";

/// Builds Drake's (Hunt–Crossley point contact) run.
pub fn run(scene: &EngineScene, t: &Translation, tolerance: f64) -> Result<Run, EngineError> {
    let k = parameter(t, "point_contact_stiffness")?;
    let d = parameter(t, "hunt_crossley_dissipation")?;
    let force = move |x: f64, v: f64| 0.5 * k * x * (1.0 + d * v).max(0.0);
    let discrete = stepped(
        scene,
        t,
        Scheme::ImplicitEuler,
        tolerance,
        f64::INFINITY,
        &force,
    )?;
    let claim = Claim::Continuous {
        integrator: "Drake's continuous MultibodyPlant (time_step = 0), error-controlled Runge–Kutta 3 at accuracy 1e-10",
        tolerance: CONTINUOUS_TOLERANCE,
    };
    let other = vec![(
        "python3 impact.py discrete".to_string(),
        Claim::Stepped(discrete),
    )];
    let bodies = match Bodies::of(scene) {
        Ok(b) => b,
        Err(reason) => {
            let mut run = super::without_script(CHECKED_IN, claim, reason);
            run.other_claims = other;
            return Ok(run);
        }
    };
    let props = format!(
        "<drake:point_contact_stiffness>{}</drake:point_contact_stiffness><drake:hunt_crossley_dissipation>{}</drake:hunt_crossley_dissipation>",
        num(k),
        num(d)
    );
    let text = script(
        scene,
        &bodies,
        &props,
        discrete.step,
        "lagged",
        &format!(
            "#   python3 impact.py            continuous plant (time_step = 0): e = {}, F_max = {} N,\n#                                contact time {} s (the law itself, e to 1e-3 or better)\n#   python3 impact.py discrete   discrete plant, Lagged approximation at TIME_STEP: hertz-tui's\n#                                model of its stepping gives e = {}, F_max = {} N, contact time {} s",
            num(t.realised.e_out),
            num(t.realised.f_max),
            num(t.realised.t_contact),
            num(discrete.at_step.e_out),
            num(discrete.at_step.f_max),
            num(discrete.at_step.t_contact),
        ),
        false,
    );
    Ok(Run {
        checked_in: Some(CHECKED_IN),
        claim,
        other_claims: other,
        script: Some(Script {
            file: "impact.py",
            language: "python",
            command: "python3 impact.py",
            text,
        }),
        no_script: None,
        versions: vec![
            "SAP (Drake's default discrete solver for many configurations) ignores hunt_crossley_dissipation and uses relaxation_time: with these parameters it comes out perfectly inelastic; use `translate --engine drake-sap` for SAP.".into(),
            "TAMSI, Similar and Lagged step this law alike (implicit Euler, converging as O(h): −0.7 % at t_c/500 on the Fig. 5 scene); TAMSI is deprecated in Drake 1.51 (removal after 2026-09-01).".into(),
            "Drake before 1.17 had no MultibodyPlantConfig.discrete_contact_approximation; there, select the solver with plant.set_discrete_contact_solver.".into(),
        ],
        fragments: Vec::new(),
    })
}

/// The script for `bodies` with collision properties `props` (both geometries), discrete step
/// `step` with `approximation`; `header` says what each way of running gives; `discrete_only`
/// makes the discrete plant the default.
pub fn script(
    scene: &EngineScene,
    bodies: &Bodies,
    props: &str,
    step: f64,
    approximation: &str,
    header: &str,
    discrete_only: bool,
) -> String {
    let inertial = |m: f64, r: f64| {
        let i = num(0.4 * m * r * r);
        format!(
            "<inertial><mass>{}</mass><inertia><ixx>{i}</ixx><iyy>{i}</iyy><izz>{i}</izz><ixy>0</ixy><ixz>0</ixz><iyz>0</iyz></inertia></inertial>",
            num(m)
        )
    };
    let collision = |name: &str, geometry: String| {
        format!(
            "<collision name=\"{name}\"><geometry>{geometry}</geometry><drake:proximity_properties>{props}</drake:proximity_properties></collision>"
        )
    };
    let sphere = |r: f64| format!("<sphere><radius>{}</radius></sphere>", num(r));
    let (r1, other, x_expr, v_expr, start) = match *bodies {
        Bodies::OnPlate { radius, mass } => (
            radius,
            format!(
                "  <link name=\"body1\">{}{}</link>\n  <link name=\"plate\">{}</link>\n  <joint name=\"weld\" type=\"fixed\"><parent>world</parent><child>plate</child></joint>",
                inertial(mass, radius),
                collision("body1", sphere(radius)),
                collision(
                    "plate",
                    "<plane><normal>0 0 1</normal><size>1 1</size></plane>".into()
                )
            ),
            format!("{} - z1", num(radius)),
            "v1".to_string(),
            String::new(),
        ),
        Bodies::Spheres { moving, other } => (
            moving.0,
            format!(
                "  <link name=\"body1\">{}{}</link>\n  <link name=\"body2\">{}{}</link>",
                inertial(moving.1, moving.0),
                collision("body1", sphere(moving.0)),
                inertial(other.1, other.0),
                collision("body2", sphere(other.0))
            ),
            format!("{} - (z1 - z2)", num(moving.0 + other.0)),
            "v1 - v2".to_string(),
            format!(
                "body2 = plant.GetBodyByName(\"body2\")\nplant.SetFreeBodyPose(plant_context, body2, RigidTransform([0, 0, -{}]))\n",
                num(other.0)
            ),
        ),
    };
    let state = match bodies {
        Bodies::OnPlate { .. } => {
            "    z1 = plant.EvalBodyPoseInWorld(plant_context, body1).translation()[2]\n    v1 = plant.EvalBodySpatialVelocityInWorld(plant_context, body1).translational()[2]\n    return {x}, {v}\n"
        }
        Bodies::Spheres { .. } => {
            "    z1 = plant.EvalBodyPoseInWorld(plant_context, body1).translation()[2]\n    v1 = plant.EvalBodySpatialVelocityInWorld(plant_context, body1).translational()[2]\n    z2 = plant.EvalBodyPoseInWorld(plant_context, body2).translation()[2]\n    v2 = plant.EvalBodySpatialVelocityInWorld(plant_context, body2).translational()[2]\n    return {x}, {v}\n"
        }
    }
    .replace("{x}", &x_expr)
    .replace("{v}", &v_expr);
    let discrete_test = if discrete_only {
        "True".to_string()
    } else {
        "len(sys.argv) > 1 and sys.argv[1] == \"discrete\"".to_string()
    };
    format!(
        r#"# hertz-tui translate --engine drake{sap}: {name}
# Runs as printed in {CHECKED_IN}:
{header}
import sys

from pydrake.all import (
    AddMultibodyPlant,
    DiagramBuilder,
    MultibodyPlantConfig,
    Parser,
    ResetIntegratorFromFlags,
    RigidTransform,
    Simulator,
    SpatialVelocity,
)

V0 = {v0}  # m/s, impact velocity
TIME_STEP = {step}  # s, the discrete plant's step
SDF = """<?xml version="1.0"?>
<sdf version="1.9" xmlns:drake="http://drake.mit.edu">
<model name="impact">
{other}
</model>
</sdf>"""

discrete = {discrete_test}
config = MultibodyPlantConfig(
    time_step=TIME_STEP if discrete else 0.0,
    contact_model="point",  # the default, hydroelastic_with_fallback, is another law
)
if discrete:
    config.discrete_contact_approximation = "{approximation}"
builder = DiagramBuilder()
plant, _ = AddMultibodyPlant(config, builder)
Parser(plant).AddModelsFromString(SDF, "sdf")
plant.mutable_gravity_field().set_gravity_vector([0, 0, 0])
plant.Finalize()
simulator = Simulator(builder.Build())
context = simulator.get_mutable_context()
plant_context = plant.GetMyMutableContextFromRoot(context)
body1 = plant.GetBodyByName("body1")
GAP = V0 * TIME_STEP / 2 if discrete else 0.0  # a stepped run starts half a step apart
{start}plant.SetFreeBodyPose(plant_context, body1, RigidTransform([0, 0, {r1} + GAP]))
plant.SetFreeBodySpatialVelocity(plant_context, body1, SpatialVelocity([0, 0, 0], [0, 0, -V0]))


def state():
    """Approach x (m) and separation speed (m/s)."""
{state}

def normal_force():
    results = plant.get_contact_results_output_port().Eval(plant_context)
    return sum(
        abs(results.point_pair_contact_info(i).contact_force()[2])
        for i in range(results.num_point_pair_contacts())
    )


f_max, contact_time, touched = 0.0, 0.0, False
if discrete:
    # Each step's force is the one the plant reports before taking it.
    for n in range({max_discrete}):
        f = normal_force()
        if f != 0.0:
            contact_time += TIME_STEP
            touched = True
        f_max = max(f_max, f)
        simulator.AdvanceTo((n + 1) * TIME_STEP)
        x, v_rel = state()
        if touched and x <= 0 and v_rel > 0:
            break
else:
    ResetIntegratorFromFlags(simulator, "runge_kutta3", 1e-3)
    simulator.get_mutable_integrator().set_target_accuracy(1e-10)
    dt, x_prev = {sample}, 0.0  # s, output interval: a thousandth of the contact time
    for n in range({max_samples}):
        simulator.AdvanceTo((n + 1) * dt)
        f_max = max(f_max, normal_force())
        x, v_rel = state()
        touched = touched or x > 0
        if touched and x <= 0:
            contact_time = n * dt + dt * x_prev / (x_prev - x)  # where x returned to 0
            break
        x_prev = x
e_out = v_rel / V0
{PY_RESULT}
"#,
        sap = if discrete_only { "-sap" } else { "" },
        name = scene.scene.name,
        v0 = num(scene.v0),
        step = num(step),
        r1 = num(r1),
        max_discrete = max_steps(scene, step),
        sample = num(scene.t_contact / 1000.0),
        max_samples = 200_000,
    )
}
