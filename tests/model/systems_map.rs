//! Two-parameter maps (docs/maps.md): classification against the bouncing ball's closed forms,
//! the Lyapunov exponent against the multipliers of an orbit found by Newton, determinism.

use hertz_tui::model::scene_key::SceneKey;
use hertz_tui::model::system::map::{Axis, Grid, MapOptions, Motion, Shard, map};
use hertz_tui::model::system::{Contact, Param, SystemKey};

use super::systems_common::ball;

fn gamma_axis(from: f64, to: f64, points: usize) -> Axis {
    Axis {
        param: Param::System(SystemKey::Gamma),
        from,
        to,
        points,
    }
}

fn e_axis(from: f64, to: f64, points: usize) -> Axis {
    Axis {
        param: Param::Scene(SceneKey::Restitution),
        from,
        to,
        points,
    }
}

#[test]
fn explore_ball_row() {
    use hertz_tui::model::system::{find_orbit, OrbitOptions, State};
    use super::systems_common::guess;
    let e = 0.5;
    let model = ball(1.2, e);
    let orbit = find_orbit(&model, &Contact::rigid(e), &guess(1, 1, 0.5, 4.0, 0), &OrbitOptions::default()).unwrap();
    let p = orbit.points[0];
    let t = p.t;
    let initial = State { t, x: 1.2 * t.sin(), v: 1.2 * t.cos() + p.v_out };
    eprintln!("orbit {:?} mult {:?}", p, orbit.multipliers);
    let mut options = MapOptions::default();
    options.run.initial = Some(initial);
    let grid = Grid {
        x: gamma_axis(1.1, 4.0, 30),
        y: e_axis(0.5, 0.6, 2),
    };
    let rows = map(&model, &Contact::rigid(0.5), &grid, Shard::WHOLE, &options).unwrap();
    for c in &rows.cells {
        eprintln!("{:.3} {:.2} {:?} {:?} {:?}", c.x, c.y, c.motion, c.lyapunov, c.error);
    }
    panic!();
}
