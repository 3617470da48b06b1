//! The brute-force bifurcation engine: order, attractor, budgets, cancellation.

use std::f64::consts::PI;
use std::ops::ControlFlow;

use hertz_tui::model::system::{
    Contact, DiagramOptions, EndReason, Param, RunOptions, State, SystemError, SystemKey,
    bifurcation,
};

use crate::systems_common::ball;

fn options(transient: usize, recorded: usize) -> DiagramOptions {
    DiagramOptions {
        run: RunOptions {
            transient_impacts: transient,
            recorded_impacts: recorded,
            ..RunOptions::default()
        },
        ..DiagramOptions::default()
    }
}

#[test]
fn columns_arrive_in_order_and_show_the_period_doubling() {
    let e = 0.5;
    let sn = PI * (1.0 - e) / (1.0 + e);
    let pd = sn.hypot(2.0 * (1.0 + e * e) / (1.0 + e).powi(2));
    // Start every chunk just after the period-1 orbit's impact at Γ = 1.1 (a chattering,
    // sticking attractor coexists with it there: started at rest the ball would find that one).
    let start_gamma = 1.1;
    let phase = (sn / start_gamma).acos();
    let mut run = options(300, 64);
    run.run.initial = Some(State {
        t: phase,
        x: start_gamma * phase.sin(),
        v: PI,
    });
    let values: Vec<f64> = (0..80).map(|i| 1.1 + 0.9 * f64::from(i) / 79.0).collect();
    let mut seen = Vec::new();
    let param = Param::System(SystemKey::Amplitude);
    let model = ball(start_gamma, e);
    let d = bifurcation(&model, &Contact::rigid(e), param, &values, &run, |c| {
        seen.push(c.index);
        ControlFlow::Continue(())
    })
    .unwrap();
    assert_eq!(seen, (0..values.len()).collect::<Vec<_>>());
    assert_eq!(d.key, "system.amplitude");
    let mut counted = (0, 0);
    for c in &d.columns {
        if c.value < pd * 0.97 {
            assert_eq!(c.period, Some((1, 1)), "Γ = {}: period 1", c.value);
            // The period-1 orbit's impact speed π + Γ_SN (units g/ω).
            assert!(
                (c.velocities[0] - (PI + sn)).abs() < 1e-9,
                "Γ = {}: {}",
                c.value,
                c.velocities[0]
            );
            counted.0 += 1;
        }
        if c.value > pd * 1.02 && c.value < pd * 1.06 {
            assert_eq!(
                c.period,
                Some((2, 2)),
                "Γ = {}: period 2 past Γ_PD = {pd}",
                c.value
            );
            counted.1 += 1;
        }
    }
    assert!(counted.0 > 30 && counted.1 >= 4, "{counted:?}");
    // Below Γ = 1 the ball rides the table.
    let d = bifurcation(
        &model,
        &Contact::rigid(e),
        param,
        &[0.5, 0.9, 0.99],
        &options(10, 10),
        |_| ControlFlow::Continue(()),
    )
    .unwrap();
    for c in &d.columns {
        assert_eq!(c.end, EndReason::StuckForever, "Γ = {} < 1", c.value);
        assert!(c.velocities.is_empty());
    }
}

#[test]
fn budgets_and_cancellation() {
    let values = [1.5, 2.0, 2.5, 3.0];
    let model = ball(1.0, 0.5);
    let contact = Contact::rigid(0.5);
    let param = Param::System(SystemKey::Gamma);
    let mut small = options(100, 100);
    small.max_total_impacts = 799;
    let err = bifurcation(&model, &contact, param, &values, &small, |_| {
        ControlFlow::Continue(())
    })
    .unwrap_err();
    assert!(
        matches!(err, SystemError::DiagramBudget { needed: 800, .. }),
        "{err}"
    );
    let mut tight = options(100, 100);
    tight.run.max_impacts = 50;
    let err = bifurcation(&model, &contact, param, &values, &tight, |_| {
        ControlFlow::Continue(())
    })
    .unwrap_err()
    .to_string();
    assert!(
        err.contains("the diagram at system.gamma = 1.5") && err.contains("max_impacts = 50"),
        "{err}"
    );
    let mut count = 0;
    let err = bifurcation(&model, &contact, param, &values, &options(10, 10), |_| {
        count += 1;
        if count == 2 {
            ControlFlow::Break(())
        } else {
            ControlFlow::Continue(())
        }
    })
    .unwrap_err();
    assert_eq!(err, SystemError::Cancelled);
    assert_eq!(count, 2);
    let err = bifurcation(
        &model,
        &contact,
        "system.gap".parse().unwrap(),
        &values,
        &options(10, 10),
        |_| ControlFlow::Continue(()),
    )
    .unwrap_err()
    .to_string();
    assert!(err.contains("system.gap"), "{err}");
    assert!("system.nothing".parse::<Param>().is_err());
    let err = bifurcation(
        &model,
        &contact,
        Param::System(SystemKey::Frequency),
        &[1.0, -1.0],
        &options(10, 10),
        |_| ControlFlow::Continue(()),
    )
    .unwrap_err()
    .to_string();
    assert!(err.contains("system.frequency must be"), "{err}");
}

#[test]
fn a_diagram_over_the_restitution_moves_the_rigid_stop_e() {
    // Γ = 1.3: the period-1 orbit's impact speed π + Γ_SN(e) depends on the varied e.
    let gamma = 1.3;
    let sn = |e: f64| PI * (1.0 - e) / (1.0 + e);
    let phase = (sn(0.5) / gamma).acos();
    let mut run = options(400, 8);
    run.run.initial = Some(State {
        t: phase,
        x: gamma * phase.sin(),
        v: PI,
    });
    let values = [0.45, 0.5, 0.55];
    let param: Param = "impact.restitution".parse().unwrap();
    let d = bifurcation(
        &ball(gamma, 0.5),
        &Contact::rigid(0.5),
        param,
        &values,
        &run,
        |_| ControlFlow::Continue(()),
    )
    .unwrap();
    for c in &d.columns {
        assert_eq!(c.period, Some((1, 1)), "e = {}", c.value);
        let expected = PI + sn(c.value);
        assert!(
            (c.velocities[0] - expected).abs() < 1e-9,
            "e = {}: {} vs {expected}",
            c.value,
            c.velocities[0]
        );
    }
}

/// The same attractor: the same period and, over one period, the same impact speeds (sorted, to
/// within 1e-9 of the largest), or the same end without impacts.
fn same_attractor(
    a: &hertz_tui::model::system::Column,
    b: &hertz_tui::model::system::Column,
) -> bool {
    let cycle = |c: &hertz_tui::model::system::Column| {
        let n = c.period.map_or(c.velocities.len(), |(n, _)| n as usize);
        let mut v: Vec<f64> = c.velocities[c.velocities.len() - n..].to_vec();
        v.sort_by(f64::total_cmp);
        v
    };
    if a.period != b.period || a.end != b.end || a.period.is_none() {
        return a.period == b.period && a.end == b.end && a.velocities.len() == b.velocities.len();
    }
    let (va, vb) = (cycle(a), cycle(b));
    let scale = va.iter().chain(&vb).fold(0.0_f64, |m, v| m.max(v.abs()));
    va.len() == vb.len()
        && va
            .iter()
            .zip(&vb)
            .all(|(x, y)| (x - y).abs() <= 1e-9 * scale)
}

#[test]
fn a_parallel_diagram_follows_the_attractor_across_chunks_as_a_sequential_one_does() {
    // Γ from 1.45 down to 1.07. Every run that starts cold starts just after the impact of the
    // one-impact-in-two-periods orbit of Γ = 2.3 (carried to its Γ at the same phase and relative
    // speed): at Γ = 1.45 that lands on the period-1 orbit, which a sequential follow keeps down to
    // its saddle-node Γ_SN = 1.047; below Γ ≈ 1.21 the same cold start lands on the chattering,
    // sticking attractor that coexists with it. Chunks of 5 or 7 values on the pool must give the
    // sequence's columns.
    let e = 0.5;
    let sn2 = 2.0 * PI * (1.0 - e) / (1.0 + e);
    let start_gamma = 2.3;
    let phase = (sn2 / start_gamma).acos();
    let mut run = options(200, 16);
    run.run.initial = Some(State {
        t: phase,
        x: start_gamma * phase.sin(),
        v: start_gamma * phase.cos() + e * 4.0 * PI / (1.0 + e),
    });
    let values: Vec<f64> = (0..39).map(|i| 1.45 - 0.38 * f64::from(i) / 38.0).collect();
    let model = ball(start_gamma, e);
    let param = Param::System(SystemKey::Gamma);
    let diagram = |chunk: usize| {
        let options = DiagramOptions { chunk, ..run };
        let mut order = Vec::new();
        let d = bifurcation(&model, &Contact::rigid(e), param, &values, &options, |c| {
            order.push(c.index);
            ControlFlow::Continue(())
        })
        .unwrap();
        assert_eq!(
            order,
            (0..values.len()).collect::<Vec<_>>(),
            "streamed in order"
        );
        d
    };
    let sequential = diagram(values.len());
    assert!(
        sequential.columns.iter().all(|c| c.period == Some((1, 1))),
        "{:?}",
        sequential
            .columns
            .iter()
            .map(|c| c.period)
            .collect::<Vec<_>>()
    );
    for chunk in [5, 7] {
        let parallel = diagram(chunk);
        for (a, b) in sequential.columns.iter().zip(&parallel.columns) {
            assert!(
                same_attractor(a, b),
                "chunks of {chunk}, Γ = {}: {:?} against {:?}",
                a.value,
                (a.period, &a.velocities[..2.min(a.velocities.len())]),
                (b.period, &b.velocities[..2.min(b.velocities.len())])
            );
        }
    }
}
