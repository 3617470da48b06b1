//! Yade: a Python script (`yade -n -x impact.py`, Debian `yade`) with Hertz–Mindlin given
//! `betan`, and the plate as a fixed sphere 10⁴ times the ball's radius.
//!
//! Why `betan` and not `en`: how `en` maps to the damping changed across versions (Tsuji's β-map
//! in older sources; Thornton et al. 2013 in Debian's 2023.02a, where en = 0.6 realises 0.59997),
//! while `betan` is read the same way: cₙ = 2·betan·√(m·kₙ), kₙ = (3/2)·kₙ₀·√x the tangent
//! stiffness (pkg/dem/HertzMindlin.cpp). With kₙ₀ = (4/3)E√R this is Tsuji's γ·x^{1/4} with
//! betan = √(5/6)·|β(en)|: the translation's law, clamped at F ≥ 0 (no attractive force).
//! Why a sphere for the plate: a `utils.wall` reports no radius and HertzMindlin.cpp then uses
//! the ball's twice, R* = R/2 (F_max 15 % low); a facet gives 2R/3.

use super::super::error::EngineError;
use super::super::tsuji::beta;
use super::super::{EngineScene, Fragment, Translation};
use super::{
    Bodies, Claim, PY_RESULT, Run, Scheme, Script, gap, max_steps, num, parameter, stepped,
};

/// The Yade release the script was run in.
pub const CHECKED_IN: &str = "Yade 2023.02a (Debian 12: apt-get install yade)";

/// The plate sphere's radius over the ball's: R* = R·(1 − 1e-4), F_max and t_c within 2e-5.
const PLATE_RADIUS_FACTOR: f64 = 1e4;

/// Builds Yade's run.
pub fn run(scene: &EngineScene, t: &Translation, tolerance: f64) -> Result<Run, EngineError> {
    let en = parameter(t, "en")?;
    let betan = crate::model::engine::pasteable((5.0_f64 / 6.0).sqrt() * beta(en).abs());
    let bodies = Bodies::of(scene);
    // Yade's own R*: the plate sphere's finite radius included.
    let r_star = match bodies {
        Ok(Bodies::OnPlate { radius, .. }) => {
            let plate = PLATE_RADIUS_FACTOR * radius;
            radius * plate / (radius + plate)
        }
        _ => scene.r_star,
    };
    let kno = 4.0 / 3.0 * scene.e_star * r_star.sqrt();
    let cn = 2.0 * betan * (1.5 * scene.mass * kno).sqrt();
    let force = move |x: f64, v: f64| (kno * x.powf(1.5) + cn * x.powf(0.25) * v).max(0.0);
    let choice = stepped(
        scene,
        t,
        Scheme::VelocityVerlet,
        tolerance,
        f64::INFINITY,
        &force,
    )?;
    let claim = Claim::Stepped(choice);
    let bodies = match bodies {
        Ok(b) => b,
        Err(reason) => return Ok(super::without_script(CHECKED_IN, claim, reason)),
    };
    let [b1, b2] = scene.bodies();
    let material = |m: &crate::model::Material| {
        format!(
            "FrictMat(young={}, poisson={}, density={}, frictionAngle=0)",
            num(m.youngs_modulus),
            num(m.poisson_ratio),
            num(m.density)
        )
    };
    let (plate, v_rel) = match bodies {
        Bodies::OnPlate { radius, .. } => (
            format!(
                "# The plate: a fixed sphere 1e4 times larger (R* within 1e-4 of R); a utils.wall would\n# make Yade take R* = R/2, a facet 2R/3.\nRB = {}\nplate = O.bodies.append(sphere((0, 0, -RB), RB, material=mat2, fixed=True))",
                num(PLATE_RADIUS_FACTOR * radius)
            ),
            "O.bodies[ball].state.vel[2]",
        ),
        Bodies::Spheres { other, .. } => (
            format!(
                "other = O.bodies.append(sphere((0, 0, -{r}), {r}, material=mat2))",
                r = num(other.0)
            ),
            "O.bodies[ball].state.vel[2] - O.bodies[other].state.vel[2]",
        ),
    };
    let law = format!(
        "InteractionLoop(\n        [Ig2_Sphere_Sphere_ScGeom()],\n        [Ip2_FrictMat_FrictMat_MindlinPhys(betan={})],\n        [Law2_ScGeom_MindlinPhys_Mindlin()],\n    )",
        num(betan)
    );
    let text = format!(
        r#"# hertz-tui translate --engine yade: {name}
# Runs as printed in {CHECKED_IN}: yade -n -x impact.py
# Hertz–Mindlin with betan (the damping ratio on the tangent stiffness), no friction, no gravity,
# at the step hertz-tui chose: its model of this stepping (leapfrog, as velocity Verlet) gives
# e = {e}, F_max = {f} N, contact time {tc} s.
V0 = {v0}  # m/s, impact velocity
R = {r}  # m, the ball's radius
mat1 = O.materials.append({mat1})
mat2 = O.materials.append({mat2})
ball = O.bodies.append(sphere((0, 0, R + {lift}), R, material=mat1))  # half a step above
{plate}
O.engines = [
    ForceResetter(),
    InsertionSortCollider([Bo1_Sphere_Aabb()]),
    {law},
    NewtonIntegrator(damping=0, gravity=(0, 0, 0)),
]
O.dt = {step}
O.bodies[ball].state.vel = (0, 0, -V0)
f_max, steps_in_contact, touched = 0.0, 0, False
for _ in range({max_steps}):
    O.step()
    f = abs(O.forces.f(ball)[2])
    if f != 0.0:
        steps_in_contact += 1
        touched = True
    f_max = max(f_max, f)
    v_rel = {v_rel}
    if touched and f == 0.0 and v_rel > 0:
        break
e_out = v_rel / V0
contact_time = steps_in_contact * O.dt
{PY_RESULT}
# Yade removes its temporary folder (/tmp/yade-XXXXXX) only on this exit, which `-x` skips.
O.exitNoBacktrace()
"#,
        name = scene.scene.name,
        e = num(choice.at_step.e_out),
        f = num(choice.at_step.f_max),
        tc = num(choice.at_step.t_contact),
        v0 = num(scene.v0),
        r = num(bodies.radius()),
        mat1 = material(&b1.material),
        mat2 = material(&b2.material),
        step = num(choice.step),
        lift = num(gap(scene, choice.step)),
        max_steps = max_steps(scene, choice.step),
    );
    Ok(Run::run_in(
        CHECKED_IN,
        claim,
        Script {
            file: "impact.py",
            language: "python",
            command: "yade -n -x impact.py",
            text,
        },
        vec![format!(
            "en changed meaning: Yade 2023.02a (Debian) maps en through Thornton et al. 2013 and realises en itself (give en = {} there); older sources map en by Tsuji's β-map (give en = {} there). The script gives betan = {}, read the same way in both.",
            num(t.e_requested),
            num(en),
            num(betan)
        )],
        vec![Fragment {
            title: "Yade interaction loop (betan)",
            language: "python",
            text: law,
        }],
    ))
}
