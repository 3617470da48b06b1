//! Hard cases built on purpose: chatter (its accumulation time 2w/(a(1−e)) under a constant
//! relative acceleration, docs/physics.md §8.4), sticking until the contact force turns tensile,
//! grazing, and the guarantees: no fall-through, no energy gained at an impact.

use std::f64::consts::TAU;

use hertz_tui::model::system::{
    Contact, EndReason, ImpactKind, RunOptions, State, SystemKind, SystemModel, SystemSpec,
    simulate,
};

use crate::systems_common::{ball, oscillator};

fn fixed_table(e: f64) -> SystemModel {
    let spec = SystemSpec {
        kind: SystemKind::BouncingBall {
            amplitude: 0.0,
            frequency: 1.0,
            gravity: 9.81,
        },
    };
    SystemModel::new(spec, 0.1, e).unwrap()
}

#[test]
fn chatter_accumulates_at_2w_over_a_1_minus_e() {
    for e in [0.3, 0.5, 0.9] {
        let w = 1.0;
        let options = RunOptions {
            transient_impacts: 0,
            recorded_impacts: 100_000,
            initial: Some(State {
                t: 0.0,
                x: 0.0,
                v: w,
            }),
            ..RunOptions::default()
        };
        let h = simulate(&fixed_table(e), &Contact::rigid(e), &options).unwrap();
        let end = h.impacts.last().unwrap();
        assert_eq!(end.kind, ImpactKind::ChatterEnd);
        let expected = 2.0 * w / (9.81 * (1.0 - e));
        assert!(
            (end.t - expected).abs() < 1e-8 * expected,
            "e={e}: {} vs {expected}",
            end.t
        );
        // Every simulated impact where the geometric series puts it.
        let mut t = 0.0;
        let mut v = w;
        for i in h.impacts.iter().filter(|i| i.kind == ImpactKind::Impact) {
            t += 2.0 * v / 9.81;
            assert!((i.t - t).abs() < 1e-12, "e={e}: impact at {} vs {t}", i.t);
            assert!((i.v_in - v).abs() < 1e-12);
            v *= e;
        }
        // A table at rest never lets go: stuck for ever.
        assert_eq!(h.end, EndReason::StuckForever);
        assert_eq!(h.sticks.last().unwrap().end, None);
    }
}

#[test]
fn a_stuck_ball_leaves_where_the_contact_force_turns_tensile() {
    // Γ = 1.2, e = 0.2: chatter, sticking, release at Γ·sin φ = 1 with the table decelerating
    // downward faster than g (the table's acceleration −Γ·sin φ crosses −1 going down).
    let gamma = 1.2;
    let options = RunOptions {
        transient_impacts: 50,
        recorded_impacts: 200,
        ..RunOptions::default()
    };
    let h = simulate(&ball(gamma, 0.2), &Contact::rigid(0.2), &options).unwrap();
    let released: Vec<f64> = h.sticks.iter().filter_map(|s| s.end).collect();
    assert!(
        !released.is_empty(),
        "the ball sticks and leaves: {:?}",
        h.sticks
    );
    for t in released {
        let phase = t.rem_euclid(TAU);
        assert!(
            (gamma * phase.sin() - 1.0).abs() < 1e-10,
            "release at φ = {phase}"
        );
        assert!(phase.cos() > 0.0, "the pressing force decreases through 0");
    }
    assert!(h.impacts.iter().any(|i| i.kind == ImpactKind::ChatterEnd));
}

#[test]
fn below_gamma_one_the_ball_rides_the_table() {
    let h = simulate(
        &ball(0.99, 0.5),
        &Contact::rigid(0.5),
        &RunOptions::default(),
    )
    .unwrap();
    assert_eq!(h.end, EndReason::StuckForever);
    assert!(h.impacts.is_empty());
}

/// Every sample outside the stops and every impact dissipative, for a run with samples.
fn check_guarantees(model: &SystemModel, e: f64, options: &RunOptions, gaps: (f64, Option<f64>)) {
    let h = simulate(model, &Contact::rigid(e), options).unwrap();
    assert!(h.samples.len() > 1000, "{} samples", h.samples.len());
    let scale = gaps.0;
    for s in &h.samples {
        match model.spec.kind {
            SystemKind::BouncingBall { .. } => {
                // Beyond the resolution of t (ε·t, here ω = 1 rad/s): in sin(ωt), and in the
                // impact's time times the closing speed.
                let speed = (s.v - scale * s.t.cos()).abs();
                let resolution = 4.0 * f64::EPSILON * (1.0 + s.t.abs()) * (scale + speed);
                assert!(
                    s.x - s.stop >= -resolution,
                    "fell through the table at t = {}: {}",
                    s.t,
                    s.x - s.stop
                )
            }
            SystemKind::ImpactOscillator { .. } => {
                assert!(
                    s.x <= gaps.0 * (1.0 + 1e-12),
                    "through the stop at t = {}: {}",
                    s.t,
                    s.x
                );
                if let Some(second) = gaps.1 {
                    assert!(
                        s.x >= -second * (1.0 + 1e-12),
                        "through the second stop at t = {}",
                        s.t
                    );
                }
            }
        }
    }
    for i in &h.impacts {
        assert!(
            i.v_out <= e * i.v_in * (1.0 + 1e-15) + 1e-300,
            "energy gained: {i:?}"
        );
        assert!(i.energy_lost >= 0.0);
    }
}

#[test]
fn never_falls_through_never_gains_energy() {
    let dense = RunOptions {
        transient_impacts: 20,
        recorded_impacts: 400,
        samples_per_period: 200,
        ..RunOptions::default()
    };
    // Chaotic ball, chattering ball, a ball with e = 1.
    for (gamma, e) in [(3.3, 0.5), (1.1, 0.1), (2.0, 1.0)] {
        check_guarantees(&ball(gamma, e), e, &dense, (gamma, None));
    }
    // A two-sided clearance, lightly damped, near resonance; a stop barely reached (grazing).
    check_guarantees(
        &oscillator(1.0, 0.02, 0.3, 1.05, 1.0, Some(0.8), 0.7),
        0.7,
        &dense,
        (1.0, Some(0.8)),
    );
    let a_g = ((1.0f64 - 1.3 * 1.3).powi(2) + (0.1 * 1.3f64).powi(2)).sqrt();
    check_guarantees(
        &oscillator(1.0, 0.1, a_g * (1.0 + 1e-6), 1.3, 1.0, None, 0.9),
        0.9,
        &dense,
        (1.0, None),
    );
}

#[test]
fn an_impact_budget_refuses_instead_of_hanging() {
    let options = RunOptions {
        transient_impacts: 0,
        recorded_impacts: 100_000,
        max_impacts: 10,
        ..RunOptions::default()
    };
    let err = simulate(&ball(3.0, 0.5), &Contact::rigid(0.5), &options).unwrap_err();
    assert!(err.to_string().contains("max_impacts = 10"), "{err}");
}

#[test]
fn starting_inside_a_stop_is_refused() {
    let options = RunOptions {
        initial: Some(State {
            t: 0.0,
            x: 1.5,
            v: 0.0,
        }),
        ..RunOptions::default()
    };
    let model = oscillator(1.0, 0.1, 1.0, 1.0, 1.0, None, 0.5);
    assert!(simulate(&model, &Contact::rigid(0.5), &options).is_err());
}

#[test]
fn a_long_flight_without_impacts_ends_at_the_time_limit() {
    // Below grazing for 20 000 periods: searched a stretch at a time, no impact, no error.
    let a_g = ((1.0f64 - 1.3 * 1.3).powi(2) + (0.1 * 1.3f64).powi(2)).sqrt();
    let model = oscillator(1.0, 0.1, 0.5 * a_g, 1.3, 1.0, None, 0.9);
    let options = RunOptions {
        max_periods: 20_000.0,
        ..RunOptions::default()
    };
    let h = simulate(&model, &Contact::rigid(0.9), &options).unwrap();
    assert_eq!(h.end, EndReason::TimeLimit);
    assert!(h.impacts.is_empty());
    assert!((h.end_state.t - 20_000.0 * TAU / 1.3).abs() < 1e-6);
}
