//! LIGGGHTS-PUBLIC: an input file (`liggghts -in impact.in`, Debian `liggghts`) with
//! `hard_particles yes` (SI inputs with E > 1e9 Pa stop without it) and the plate as a
//! `fix wall/gran … primitive` carrying its own `limitForce on` (the pair style's does not reach a
//! wall: without it the wall pulls and realises 0.561 for 0.6 on the Fig. 5 scene).
//!
//! LIGGGHTS's law from the printed input (doc/gran_model_hertz.txt): F = k·x^{3/2} + γ·x^{1/4}·ẋ,
//! γ = 2√(5/6)·|β(e)|·√(2Y*√R*·m*), clamped at F ≥ 0 (limitForce), stepped by velocity Verlet.

use super::super::error::EngineError;
use super::super::tsuji::beta;
use super::super::{EngineScene, Fragment, Translation};
use super::{
    Bodies, Claim, Run, Scheme, Script, gap, max_steps, measure_loop, num, parameter, stepped,
    verlet_header,
};

/// The LIGGGHTS release the input was run in.
pub const CHECKED_IN: &str = "LIGGGHTS-PUBLIC 3.8.0 (Debian 12: apt-get install liggghts)";

/// The command that runs the input.
const COMMAND: &str = "liggghts -in impact.in";

/// Builds LIGGGHTS's run.
pub fn run(scene: &EngineScene, t: &Translation, tolerance: f64) -> Result<Run, EngineError> {
    let e_in = parameter(t, "coefficientRestitution")?;
    let gamma = 2.0
        * (5.0_f64 / 6.0).sqrt()
        * beta(e_in).abs()
        * (2.0 * scene.e_star * scene.r_star.sqrt() * scene.mass).sqrt();
    let k = scene.elastic.k;
    let force = move |x: f64, v: f64| (k * x.powf(1.5) + gamma * x.powf(0.25) * v).max(0.0);
    let choice = stepped(
        scene,
        t,
        Scheme::VelocityVerlet,
        tolerance,
        f64::INFINITY,
        &force,
    )?;
    let claim = Claim::Stepped(choice);
    let bodies = match Bodies::of(scene) {
        Ok(b) => b,
        Err(reason) => return Ok(super::without_script(CHECKED_IN, claim, reason)),
    };
    let [b1, b2] = scene.bodies();
    let (m1, m2) = (&b1.material, &b2.material);
    let lift = gap(scene, choice.step);
    let e = num(e_in);
    let materials = format!(
        "fix m1 all property/global youngsModulus peratomtype {} {}\nfix m2 all property/global poissonsRatio peratomtype {} {}\nfix m3 all property/global coefficientRestitution peratomtypepair 2 {e} {e} {e} {e}\nfix m4 all property/global coefficientFriction peratomtypepair 2 0 0 0 0\npair_style gran model hertz tangential history limitForce on\npair_coeff * *",
        num(m1.youngs_modulus),
        num(m2.youngs_modulus),
        num(m1.poisson_ratio),
        num(m2.poisson_ratio),
    );
    let (atoms, wall, v_rel, extent) = match bodies {
        Bodies::OnPlate { radius, .. } => (
            format!(
                "create_atoms 1 single 0 0 {}  # half a step above the plate\nset atom 1 diameter {} density {}",
                num(radius + lift),
                num(2.0 * radius),
                num(m1.density)
            ),
            "# The plate: a primitive wall of type 2's material, with its own limitForce\nfix plate all wall/gran model hertz tangential history primitive type 2 zplane 0.0 limitForce on".to_string(),
            "vz[1]",
            radius,
        ),
        Bodies::Spheres { moving, other } => (
            format!(
                "create_atoms 1 single 0 0 {}  # half a step above atom 2\ncreate_atoms 2 single 0 0 -{}\nset atom 1 diameter {} density {}\nset atom 2 diameter {} density {}",
                num(moving.0 + lift),
                num(other.0),
                num(2.0 * moving.0),
                num(m1.density),
                num(2.0 * other.0),
                num(m2.density)
            ),
            String::new(),
            "vz[1]-vz[2]",
            moving.0 + other.0,
        ),
    };
    let half = num(4.0 * extent);
    let text = format!(
        r#"{header}
atom_style granular
atom_modify map array
boundary m m m
newton off
communicate single vel yes
units si
hard_particles yes  # SI moduli above 1e9 Pa are refused without it
region reg block -{half} {half} -{half} {half} -{half} {half} units box
create_box 2 reg
neighbor {skin} bin
neigh_modify delay 0
{materials}
timestep {step}
{wall}
{atoms}
group ball id 1
velocity ball set 0 0 -{v0}
fix integr all nve/sphere
thermo 0
{measure}"#,
        header = verlet_header(t, scene, CHECKED_IN, COMMAND, &choice),
        skin = num(0.1 * bodies.radius()),
        step = num(choice.step),
        v0 = num(scene.v0),
        measure = measure_loop(v_rel, max_steps(scene, choice.step), num(scene.v0)),
    );
    Ok(Run::run_in(
        CHECKED_IN,
        claim,
        Script {
            file: "impact.in",
            language: "text",
            command: COMMAND,
            text,
        },
        vec![
            "LIGGGHTS-PUBLIC 3.x: `hard_particles yes` is required for SI moduli above 1e9 Pa; a wall reads limitForce from its own fix wall/gran line, not from the pair style.".into(),
        ],
        vec![Fragment {
            title: "LIGGGHTS input lines (materials, pair style, wall)",
            language: "text",
            text: format!(
                "hard_particles yes\n{materials}\n{}",
                if wall.is_empty() {
                    "# (no wall: two atoms)".to_string()
                } else {
                    wall
                }
            ),
        }],
    ))
}
