//! Two-parameter maps (issue 24; docs/maps.md, docs/performance.md "Maps"): the `bouncing-ball`
//! preset over Γ from 0.9 to 3.5 and e from 0.3 to 0.9 at `hertz-tui map`'s defaults (300
//! transient and 64 recorded impacts a cell, the Lyapunov exponent over 200 map steps), on
//! rayon's pool (both cores):
//! - rigid stop, 200 × 200 cells;
//! - compliant stop (Hunt–Crossley, its damping from each impact's speed, eq 19), 50 × 50 cells.
//!
//! Run with `cargo bench --bench maps` (`-- --rigid N --compliant N` for N × N maps instead).
//! Prints wall and CPU time, cells a second, and the share of each kind of motion.

use std::time::Instant;

use hertz_tui::model::ForceModel;
use hertz_tui::model::presets::Registry;
use hertz_tui::model::scene_key::SceneKey;
use hertz_tui::model::system::map::{Axis, Grid, MapOptions, Shard, map};
use hertz_tui::model::system::{CompliantDamping, Contact, Param, SystemKey, SystemModel};

mod machine;
use machine::{cpu_seconds, load_average};

fn model() -> SystemModel {
    let registry = Registry::load().expect("built-in presets load");
    let scene = registry.scene("bouncing-ball").expect("preset resolves");
    let spec = registry
        .scene_system("bouncing-ball", &[])
        .expect("preset system")
        .expect("a [system] table");
    SystemModel::from_scene(&scene, &spec).expect("bench model")
}

fn run(name: &str, model: &SystemModel, contact: &Contact, n: usize) {
    let grid = Grid {
        x: Axis {
            param: Param::System(SystemKey::Gamma),
            from: 0.9,
            to: 3.5,
            points: n,
        },
        y: Axis {
            param: Param::Scene(SceneKey::Restitution),
            from: 0.3,
            to: 0.9,
            points: n,
        },
    };
    let options = MapOptions::default();
    let (start, cpu) = (Instant::now(), cpu_seconds());
    let cells = map(model, contact, &grid, Shard::WHOLE, &options)
        .expect("map runs")
        .cells;
    let (wall, cpu) = (start.elapsed().as_secs_f64(), cpu_seconds() - cpu);
    let mut kinds: Vec<(&str, usize)> = Vec::new();
    for c in &cells {
        match kinds.iter_mut().find(|k| k.0 == c.motion.name()) {
            Some(k) => k.1 += 1,
            None => kinds.push((c.motion.name(), 1)),
        }
    }
    kinds.sort_by_key(|k| std::cmp::Reverse(k.1));
    let shares: Vec<String> = kinds
        .iter()
        .map(|(k, c)| format!("{k} {:.1} %", 100.0 * *c as f64 / cells.len() as f64))
        .collect();
    println!(
        "{name}: {n} × {n} cells in {wall:.2} s wall, {cpu:.2} s CPU ({:.0} cells/s, {:.2} ms CPU a cell); {}",
        cells.len() as f64 / wall,
        1e3 * cpu / cells.len() as f64,
        shares.join(", ")
    );
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let size = |flag: &str, default: usize| {
        args.iter()
            .position(|a| a == flag)
            .and_then(|i| args.get(i + 1))
            .and_then(|v| v.parse().ok())
            .unwrap_or(default)
    };
    let (rigid_n, compliant_n) = (size("--rigid", 200), size("--compliant", 50));
    println!(
        "maps bench: {} rayon threads, load average before: {}",
        rayon::current_num_threads(),
        load_average()
    );
    let model = model();
    run("rigid", &model, &Contact::rigid(model.restitution), rigid_n);
    let hc = Contact::Compliant {
        model: ForceModel::HuntCrossley,
        damping: CompliantDamping::PerImpact,
    };
    run("compliant (hunt-crossley)", &model, &hc, compliant_n);
    println!("load average after: {}", load_average());
}
