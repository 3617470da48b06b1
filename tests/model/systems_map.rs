//! Two-parameter maps (docs/maps.md): the classification against the bouncing ball's closed forms
//! (its period-1 region Γ_SN < Γ < Γ_PD, docs/physics.md §8), the largest Lyapunov exponent of a
//! period-1 orbit against ln|μ| of the multipliers Newton finds (rigid and compliant), a chaotic Γ
//! whose exponent is checked by an independent estimate (nearby runs of `simulate`), and the map
//! fixed by the grid alone (shards and threads change nothing).

use std::f64::consts::{PI, TAU};

use hertz_tui::model::ForceModel;
use hertz_tui::model::presets::Registry;
use hertz_tui::model::scene_key::SceneKey;
use hertz_tui::model::system::map::{self, Axis, Grid, MapOptions, Motion, Shard};
use hertz_tui::model::system::{
    CompliantDamping, Contact, OrbitOptions, Param, RunOptions, State, SystemKey, SystemKind,
    SystemModel, SystemSpec, find_orbit, simulate,
};

use super::systems_common::{ball, guess, oscillator};

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

/// Γ_SN = π(1−e)/(1+e) and Γ_PD = √(Γ_SN² + (2(1+e²)/(1+e)²)²) at n = 1 (docs/physics.md §8).
fn thresholds(e: f64) -> (f64, f64) {
    let sn = PI * (1.0 - e) / (1.0 + e);
    let b = 2.0 * (1.0 + e * e) / (1.0 + e).powi(2);
    (sn, (sn * sn + b * b).sqrt())
}

/// The state just after the first impact of the rigid period-1 orbit of `model` (g = ω = 1).
fn on_period_one(model: &SystemModel, e: f64) -> State {
    let gamma = match model.spec.kind {
        SystemKind::BouncingBall { amplitude, .. } => amplitude,
        _ => unreachable!(),
    };
    let orbit = find_orbit(
        model,
        &Contact::rigid(e),
        &guess(1, 1, 0.5, TAU / (1.0 + e), 0),
        &OrbitOptions::default(),
    )
    .unwrap();
    let t = orbit.points[0].t;
    State {
        t,
        x: gamma * t.sin(),
        v: gamma * t.cos() + orbit.points[0].v_out,
    }
}

#[test]
fn the_period_one_region_lies_between_gamma_sn_and_gamma_pd() {
    // Rows e = 0.5 and 0.6, Γ from 1.1 (inside both regions) to 1.7 (past both Γ_PD), each row
    // started on the period-1 orbit at Γ = 1.1 and followed along Γ.
    let model = ball(1.1, 0.5);
    let mut options = MapOptions::default();
    options.run.initial = Some(on_period_one(&model, 0.5));
    let grid = Grid {
        x: gamma_axis(1.1, 1.7, 25),
        y: e_axis(0.5, 0.6, 2),
    };
    let cells = map::map(&model, &Contact::rigid(0.5), &grid, Shard::WHOLE, &options)
        .unwrap()
        .cells;
    let (mut inside, mut beyond) = (0, 0);
    for c in &cells {
        let (sn, pd) = thresholds(c.y);
        // Within 0.03 of a threshold a multiplier is near the unit circle: the transient is slow.
        if c.x > sn + 0.03 && c.x < pd - 0.03 {
            inside += 1;
            assert_eq!(
                c.motion,
                Motion::Periodic {
                    impacts: 1,
                    cycles: 1
                },
                "{c:?}"
            );
        } else if c.x > pd + 0.03 {
            beyond += 1;
            assert!(
                !matches!(c.motion, Motion::Periodic { impacts: 1, .. }),
                "period 1 past Γ_PD = {pd}: {c:?}"
            );
        }
    }
    assert!(inside >= 20 && beyond >= 10, "{inside} {beyond}");
}

#[test]
fn known_motions_sticking_chatter_no_impact() {
    let options = MapOptions::default();
    let rigid = |m: &SystemModel| {
        map::cell(m, &Contact::rigid(m.restitution), &options.run, &options)
            .unwrap()
            .0
    };
    // Γ < 1: the table never pulls away from the ball (docs/systems.md §4).
    assert_eq!(rigid(&ball(0.9, 0.5)), Motion::Sticking);
    // e = 0.3, Γ = 2 from rest: chatter sequences ending in sticking phases that release.
    assert!(matches!(rigid(&ball(2.0, 0.3)), Motion::Chattering { .. }));
    // An oscillator whose free amplitude |P| = f/|k − ω²| = 0.05/0.75 never reaches a gap of 0.1.
    let far = oscillator(1.0, 0.1, 0.05, 0.5, 0.1, None, 0.8);
    assert_eq!(rigid(&far), Motion::NoImpact);
    // The same with a gap of 0.05: it impacts, one impact a forcing period.
    let near = oscillator(1.0, 0.1, 0.05, 0.5, 0.05, None, 0.8);
    assert_eq!(
        rigid(&near),
        Motion::Periodic {
            impacts: 1,
            cycles: 1
        }
    );
}

#[test]
fn the_exponent_of_a_period_one_orbit_is_ln_of_its_largest_multiplier() {
    // Complex multipliers (|μ| = e, from det J = e²) at Γ = 1.2, real ones near Γ_PD at 1.5.
    for (gamma, e) in [(1.2, 0.5), (1.5, 0.5), (1.25, 0.6)] {
        let model = ball(gamma, e);
        let orbit = find_orbit(
            &model,
            &Contact::rigid(e),
            &guess(1, 1, 0.5, TAU / (1.0 + e), 0),
            &OrbitOptions::default(),
        )
        .unwrap();
        let largest = orbit
            .multipliers
            .iter()
            .map(|z| z.norm())
            .fold(0.0, f64::max);
        let options = MapOptions {
            lyapunov_impacts: 4000,
            ..MapOptions::default()
        };
        let run = RunOptions {
            initial: Some(on_period_one(&model, e)),
            ..options.run
        };
        let (motion, lyapunov, _, _) =
            map::cell(&model, &Contact::rigid(e), &run, &options).unwrap();
        assert_eq!(
            motion,
            Motion::Periodic {
                impacts: 1,
                cycles: 1
            }
        );
        let lyapunov = lyapunov.unwrap();
        // The renormalised tangent's error is O(ln κ / L), κ the condition of J's eigenvectors.
        assert!(
            (lyapunov - largest.ln()).abs() < 2e-3,
            "Γ = {gamma}, e = {e}: λ = {lyapunov}, ln|μ| = {}",
            largest.ln()
        );
    }
}

/// Independent of the Jacobian: pairs of runs of `simulate` started 1e-11 apart along the
/// attractor, the mean slope of ln(distance) over impacts 4..12 (the distance in (t/T, v/V) of
/// their k-th impacts).
fn exponent_from_nearby_runs(model: &SystemModel, e: f64, start: State, pairs: usize) -> f64 {
    let contact = Contact::rigid(e);
    let mut state = start;
    let mut slopes = 0.0;
    let (first, last) = (4usize, 12usize);
    for _ in 0..pairs {
        let run = |s: State| {
            simulate(
                model,
                &contact,
                &RunOptions {
                    transient_impacts: 0,
                    recorded_impacts: last,
                    initial: Some(s),
                    ..RunOptions::default()
                },
            )
            .unwrap()
        };
        let a = run(state);
        let b = run(State {
            v: state.v + 1e-11,
            ..state
        });
        let v = a.impacts.iter().map(|i| i.v_in).fold(0.0, f64::max);
        let d = |k: usize| {
            let (p, q) = (&a.impacts[k - 1], &b.impacts[k - 1]);
            ((q.t - p.t) / TAU).hypot((q.v_in - p.v_in) / v).ln()
        };
        slopes += (d(last) - d(first)) / (last - first) as f64;
        state = a.end_state;
    }
    slopes / pairs as f64
}

#[test]
fn chaos_at_e_0_8_gamma_2_8_has_a_positive_exponent() {
    // From rest: the ball's attractor at Γ = 2.8, e = 0.8 is chaotic (λ ≈ 1.4 per impact).
    let e = 0.8;
    let model = ball(2.8, e);
    let options = MapOptions {
        lyapunov_impacts: 2000,
        ..MapOptions::default()
    };
    let run = RunOptions {
        transient_impacts: 500,
        ..options.run
    };
    let (motion, lyapunov, _, end) = map::cell(&model, &Contact::rigid(e), &run, &options).unwrap();
    assert_eq!(motion, Motion::Chaotic);
    let lyapunov = lyapunov.unwrap();
    let independent = exponent_from_nearby_runs(&model, e, end, 200);
    assert!(lyapunov > 1.0, "{lyapunov}");
    assert!(
        // 200 pairs: the estimate's spread is ~1 % (measured 1.352 against 1.341).
        (lyapunov / independent - 1.0).abs() < 0.04,
        "tangent λ = {lyapunov}, nearby runs {independent}"
    );
}

/// The steel sphere R = 10 mm of the presets on a table at 30 Hz, Γ = 1.3, e = 0.5.
fn steel_ball(gamma: f64) -> SystemModel {
    let mut scene = Registry::builtin()
        .unwrap()
        .scene("steel-sphere-r10-plate")
        .unwrap();
    scene.impact.restitution = 0.5;
    let (f, g) = (30.0, 9.81);
    let omega = TAU * f;
    let spec = SystemSpec {
        kind: SystemKind::BouncingBall {
            amplitude: gamma * g / (omega * omega),
            frequency: f,
            gravity: g,
        },
    };
    SystemModel::from_scene(&scene, &spec).unwrap()
}

#[test]
fn the_compliant_exponent_of_a_period_one_orbit_matches_its_multipliers() {
    let model = steel_ball(1.3);
    let hc = Contact::Compliant {
        model: ForceModel::HuntCrossley,
        damping: CompliantDamping::CalibratedTo(0.5),
    };
    let (f, g, e) = (30.0, 9.81, 0.5);
    let omega = TAU * f;
    let period = 1.0 / f;
    let amplitude = 1.3 * g / (omega * omega);
    // The rigid orbit's phase: the table's velocity at impact is u(1−e)/(1+e), u = gT/2.
    let phase = ((g * period / 2.0) * (1.0 - e) / ((1.0 + e) * amplitude * omega)).acos();
    let orbit = find_orbit(
        &model,
        &hc,
        &guess(1, 1, phase, g * period / (1.0 + e), 0),
        &OrbitOptions::default(),
    )
    .unwrap();
    let largest = orbit
        .multipliers
        .iter()
        .map(|z| z.norm())
        .fold(0.0, f64::max);
    let options = MapOptions {
        lyapunov_impacts: 400,
        ..MapOptions::default()
    };
    let t = phase / omega;
    let run = RunOptions {
        transient_impacts: 100,
        initial: Some(State {
            t,
            x: amplitude * (omega * t).sin(),
            v: amplitude * omega * (omega * t).cos() + e * g * period / (1.0 + e),
        }),
        ..options.run
    };
    let (motion, lyapunov, _, _) = map::cell(&model, &hc, &run, &options).unwrap();
    assert_eq!(
        motion,
        Motion::Periodic {
            impacts: 1,
            cycles: 1
        }
    );
    let lyapunov = lyapunov.unwrap();
    // Two trajectories 1e-6 apart integrated to 1e-10: the exponent to ~1e-3; the multipliers'
    // central differences to ~1e-6; the finite average over 400 steps adds O(ln κ/400).
    assert!(
        (lyapunov - largest.ln()).abs() < 1e-2,
        "λ = {lyapunov}, ln|μ| = {}",
        largest.ln()
    );
}

#[test]
fn shards_and_threads_do_not_change_the_map() {
    let model = ball(1.0, 0.5);
    let options = MapOptions {
        lyapunov_impacts: 50,
        ..MapOptions::default()
    };
    let grid = Grid {
        x: gamma_axis(0.9, 3.5, 8),
        y: e_axis(0.3, 0.9, 7),
    };
    let contact = Contact::rigid(0.5);
    let whole = map::map(&model, &contact, &grid, Shard::WHOLE, &options)
        .unwrap()
        .cells;
    let one_thread = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap()
        .install(|| map::map(&model, &contact, &grid, Shard::WHOLE, &options).unwrap());
    assert_eq!(one_thread.cells, whole);
    let mut pieces: Vec<_> = (1..=3)
        .flat_map(|i| {
            map::map(&model, &contact, &grid, Shard::new(i, 3).unwrap(), &options)
                .unwrap()
                .cells
        })
        .collect();
    pieces.sort_by_key(|c| (c.iy, c.ix));
    assert_eq!(pieces, whole);
    // A map of one kind only would not show much: this one has several.
    let kinds: std::collections::BTreeSet<&str> = whole.iter().map(|c| c.motion.name()).collect();
    assert!(kinds.len() >= 3, "{kinds:?}");
}

#[test]
fn a_compliant_map_does_not_depend_on_the_threads_either() {
    let model = steel_ball(1.3);
    let hc = Contact::Compliant {
        model: ForceModel::HuntCrossley,
        damping: CompliantDamping::PerImpact,
    };
    let options = MapOptions {
        run: RunOptions {
            transient_impacts: 40,
            recorded_impacts: 16,
            ..MapOptions::default().run
        },
        lyapunov_impacts: 20,
        ..MapOptions::default()
    };
    let grid = Grid {
        x: gamma_axis(1.2, 2.4, 3),
        y: e_axis(0.4, 0.8, 3),
    };
    let on = |threads: usize| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| map::map(&model, &hc, &grid, Shard::WHOLE, &options).unwrap())
    };
    let (one, three) = (on(1), on(3));
    assert_eq!(one, three);
    assert!(one.cells.iter().any(|c| c.lyapunov.is_some()), "{one:?}");
}

#[test]
fn bad_grids_are_refused_naming_the_key() {
    let model = ball(1.0, 0.5);
    let options = MapOptions::default();
    let grid = Grid {
        x: gamma_axis(0.9, 3.5, 4),
        y: Axis {
            param: Param::System(SystemKey::Gap),
            from: 0.1,
            to: 0.2,
            points: 3,
        },
    };
    let e = map::map(&model, &Contact::rigid(0.5), &grid, Shard::WHOLE, &options).unwrap_err();
    assert!(e.to_string().contains("system.gap"), "{e}");
    let same = Grid {
        x: gamma_axis(0.9, 3.5, 4),
        y: gamma_axis(1.0, 2.0, 3),
    };
    let e = map::map(&model, &Contact::rigid(0.5), &same, Shard::WHOLE, &options).unwrap_err();
    assert!(e.to_string().contains("two different keys"), "{e}");
}
