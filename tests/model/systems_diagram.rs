//! The brute-force bifurcation engine: order, attractor, budgets, cancellation.

use std::f64::consts::PI;
use std::ops::ControlFlow;

use hertz_tui::model::system::{
    Contact, DiagramOptions, EndReason, Param, RunOptions, SystemError, SystemKey, bifurcation,
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
    let values: Vec<f64> = (0..80).map(|i| 0.9 + 2.6 * f64::from(i) / 79.0).collect();
    let mut seen = Vec::new();
    let param = Param::System(SystemKey::Amplitude);
    let d = bifurcation(
        &ball(1.0, e),
        &Contact::rigid(e),
        param,
        &values,
        &options(300, 64),
        |c| {
            seen.push(c.index);
            ControlFlow::Continue(())
        },
    )
    .unwrap();
    assert_eq!(seen, (0..values.len()).collect::<Vec<_>>());
    assert_eq!(d.key, "system.amplitude");
    let sn = PI * (1.0 - e) / (1.0 + e);
    let pd = sn.hypot(2.0 * (1.0 + e * e) / (1.0 + e).powi(2));
    for c in &d.columns {
        if c.value < 1.0 {
            assert_eq!(
                c.end,
                EndReason::StuckForever,
                "Γ = {} < 1 rides the table",
                c.value
            );
            assert!(c.velocities.is_empty());
        }
        if c.value > sn * 1.05 && c.value < pd * 0.97 {
            assert_eq!(c.period, Some((1, 1)), "Γ = {}: period 1", c.value);
            // The period-1 orbit's impact speed nπ + Γ_SN (units g/ω).
            assert!(
                (c.velocities[0] - (PI + sn)).abs() < 1e-6,
                "Γ = {}: {}",
                c.value,
                c.velocities[0]
            );
        }
        if c.value > pd * 1.03 && c.value < pd * 1.12 {
            assert_eq!(
                c.period,
                Some((2, 2)),
                "Γ = {}: period 2 past Γ_PD = {pd}",
                c.value
            );
        }
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
