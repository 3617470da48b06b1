//! Periodic orbits with no first impact given (docs/systems.md §5): Newton's starts come from the
//! run past the transient, skipping chatter and resting, the cycle it settles on first, then a
//! grid; where the run from rest chatters the orbit is still found, and where there is no orbit
//! the error says why. Checked against the bouncing ball's closed forms (docs/physics.md §8.1).

use std::f64::consts::TAU;

use hertz_tui::model::presets::Registry;
use hertz_tui::model::system::{
    Contact, ImpactKind, OrbitGuess, OrbitOptions, RunOptions, SystemError, SystemKind,
    SystemModel, find_orbit, simulate,
};

use super::systems_common::ball;

const E: f64 = 0.5;

fn no_start(cycles: u32, impacts: u32) -> OrbitGuess {
    OrbitGuess {
        forcing_cycles: cycles,
        impacts,
        start: None,
        attractor: RunOptions::default(),
    }
}

fn orbit(
    model: &SystemModel,
    guess: &OrbitGuess,
) -> Result<hertz_tui::model::system::Orbit, SystemError> {
    find_orbit(model, &Contact::rigid(E), guess, &OrbitOptions::default())
}

#[test]
fn the_balls_period_one_orbit_is_found_where_the_run_from_rest_chatters() {
    // g = 1, ω = 1: T = 2π, the orbit's approach speed gT/(1 + e), det J = e².
    let v_orbit = TAU / (1.0 + E);
    let model = ball(1.3, E);
    let run = simulate(&model, &Contact::rigid(E), &RunOptions::default()).unwrap();
    assert!(
        run.impacts.iter().any(|i| i.kind == ImpactKind::ChatterEnd),
        "the run from rest chatters at Γ = 1.3: {:?}",
        run.period(TAU)
    );
    for guess in [no_start(1, 1), no_start(0, 0)] {
        let o = orbit(&model, &guess).unwrap();
        assert_eq!((o.period_forcing_cycles, o.impacts_per_period), (1, 1));
        assert!(o.stable, "{o:?}");
        assert!((o.points[0].v_in / v_orbit - 1.0).abs() < 1e-9, "{o:?}");
        assert!((o.jacobian_det - E * E).abs() < 1e-9, "{o:?}");
    }
    // Past Γ_PD = 1.527 the period-1 orbit is unstable: found all the same.
    let o = orbit(&ball(1.6, E), &no_start(1, 1)).unwrap();
    assert!(
        !o.stable && (o.points[0].v_in / v_orbit - 1.0).abs() < 1e-9,
        "{o:?}"
    );
}

#[test]
fn below_the_saddle_node_the_error_says_there_is_no_orbit_and_why() {
    // Γ_SN = π(1 − e)/(1 + e) = 1.0472: at Γ = 0.97 the ball never leaves the table.
    let e = orbit(&ball(0.97, E), &no_start(1, 1)).unwrap_err();
    let text = e.to_string();
    assert!(matches!(e, SystemError::OrbitNotFound { .. }), "{text}");
    assert!(
        text.contains("the run from rest comes to rest on the stop for good")
            && text.contains("exists only from Γ = π(1−e)/(1+e) = 1.0472, and Γ = 0.9700 here"),
        "{text}"
    );
    // Between Γ = 1 and Γ_SN the ball hops and chatters, and still has no period-1 orbit.
    let text = orbit(&ball(1.03, E), &no_start(1, 1))
        .unwrap_err()
        .to_string();
    assert!(
        text.contains("exists only from Γ = π(1−e)/(1+e) = 1.0472"),
        "{text}"
    );
}

/// The `impact-oscillator` preset with its stop at `gap`.
fn oscillator(gap: f64) -> SystemModel {
    let registry = Registry::builtin().unwrap();
    let scene = registry.scene("impact-oscillator").unwrap();
    let mut spec = registry
        .scene_system("impact-oscillator", &[])
        .unwrap()
        .unwrap();
    if let SystemKind::ImpactOscillator { gap: g, .. } = &mut spec.kind {
        *g = gap;
    }
    SystemModel::from_scene(&scene, &spec).unwrap()
}

#[test]
fn a_small_gap_settles_on_two_impacts_a_period_and_the_search_finds_that_cycle() {
    // Gap 0.13 of the static deflection: two impacts every forcing period, no one-impact orbit.
    let model = oscillator(5e-5);
    let e = model.restitution;
    let contact = Contact::rigid(e);
    let run = simulate(&model, &contact, &RunOptions::default()).unwrap();
    let period = model.spec.period();
    assert_eq!(run.period(period), Some((2, 1)));
    let o = find_orbit(&model, &contact, &no_start(0, 0), &OrbitOptions::default()).unwrap();
    assert_eq!((o.period_forcing_cycles, o.impacts_per_period), (1, 2));
    assert!(o.stable, "{o:?}");
    // The orbit is the cycle the run settled on: the same two impacts.
    let last = &run.impacts[run.impacts.len() - 2..];
    for p in &o.points {
        assert!(
            last.iter()
                .any(|i| (i.v_in / p.v_in - 1.0).abs() < 1e-8 && (i.phase - p.phase).abs() < 1e-8),
            "{p:?} not in {last:?}"
        );
    }
    // r^{2n}e^{−2ζω₀mT}-type contraction: det J = e⁴·e^{−2ζω₀T} for two impacts in one period.
    let osc = model.spec.oscillator(model.mass).unwrap();
    let det = e.powi(4) * (-2.0 * osc.zeta * osc.omega0 * period).exp();
    assert!(
        (o.jacobian_det / det - 1.0).abs() < 1e-8,
        "{} {det}",
        o.jacobian_det
    );
    let text = find_orbit(&model, &contact, &no_start(1, 1), &OrbitOptions::default())
        .unwrap_err()
        .to_string();
    assert!(
        text.contains(
            "the run settles on an orbit of 2 impacts in 1 forcing period: ask for that one"
        ),
        "{text}"
    );
}
