//! Continuation with a compliant stop (Hertz–Hunt–Crossley, χ calibrated to e): the bouncing
//! ball's fold and period doubling converge to the rigid closed forms (docs/physics.md §8.1) as
//! contact time over forcing period falls, and the period doubling agrees with Brent's method on
//! the compliant map's 1 + tr J + det J (an independent search of the same threshold).

use std::f64::consts::PI;

use hertz_tui::model::ForceModel;
use hertz_tui::model::presets::Registry;
use hertz_tui::model::system::compliant::orbit::{MapPoint, period_doubling};
use hertz_tui::model::system::compliant::{CompliantOptions, CompliantStop};
use hertz_tui::model::system::continuation::{
    ContinuationOptions, SpecialKind, continue_orbit, switch_at_period_doubling,
};
use hertz_tui::model::system::{
    CompliantDamping, Contact, GuessStart, ImpactKind, OrbitGuess, Param, RunOptions, SystemKey,
    SystemKind, SystemModel, SystemSpec, map::period_one, simulate,
};

const E: f64 = 0.5;
const G: f64 = 9.81;

fn gamma_sn(e: f64) -> f64 {
    PI * (1.0 - e) / (1.0 + e)
}

fn gamma_pd(e: f64) -> f64 {
    gamma_sn(e).hypot(2.0 * (1.0 + e * e) / (1.0 + e).powi(2))
}

/// The steel sphere R = 10 mm on a steel plate on a table at `frequency` with Γ.
fn ball(frequency: f64, gamma: f64) -> SystemModel {
    let mut scene = Registry::builtin()
        .unwrap()
        .scene("steel-sphere-r10-plate")
        .unwrap();
    scene.impact.restitution = E;
    let omega = 2.0 * PI * frequency;
    let spec = SystemSpec {
        kind: SystemKind::BouncingBall {
            amplitude: gamma * G / (omega * omega),
            frequency,
            gravity: G,
        },
    };
    SystemModel::from_scene(&scene, &spec).unwrap()
}

const DAMPING: CompliantDamping = CompliantDamping::CalibratedTo(E);

fn contact() -> Contact {
    Contact::Compliant {
        model: ForceModel::HuntCrossley,
        damping: DAMPING,
    }
}

/// The forcing frequency at which the elastic contact at the rigid orbit's impact speed
/// gT/(1+e) lasts `ratio` of the period (eq 7: t_c ∝ v^(−1/5)).
fn frequency_for_ratio(ratio: f64) -> f64 {
    let model = ball(20.0, 1.0);
    let s = CompliantStop::new(
        &model,
        ForceModel::Quasistatic,
        CompliantDamping::PerImpact,
        CompliantOptions::default(),
    )
    .unwrap();
    let c1 = s.elastic.contact_time(model.mass, 1.0);
    (ratio / c1 * (G / (1.0 + E)).powf(0.2)).powf(5.0 / 6.0)
}

/// The rigid period-1 orbit's first impact at Γ (stable side): the guess for both stops.
fn rigid_guess(frequency: f64, gamma: f64) -> OrbitGuess {
    let period = 1.0 / frequency;
    let phase = (gamma_sn(E) / gamma).acos();
    OrbitGuess {
        forcing_cycles: 1,
        impacts: 1,
        start: Some(GuessStart {
            phase,
            v_in: G * period / (1.0 + E),
            stop: 0,
        }),
        attractor: RunOptions::default(),
    }
}

#[test]
fn compliant_fold_and_period_doubling_converge_to_the_rigid_ones() {
    let gamma = Param::System(SystemKey::Gamma);
    let (sn, pd) = (gamma_sn(E), gamma_pd(E));
    let start = 0.5 * (sn + pd);
    let options = ContinuationOptions::default();
    let mut deviations = Vec::new();
    for ratio in [0.03, 0.003] {
        let f = frequency_for_ratio(ratio);
        let model = ball(f, start);
        let up = continue_orbit(
            &model,
            &contact(),
            gamma,
            (start, 1.05 * pd),
            &rigid_guess(f, start),
            &options,
        )
        .unwrap();
        let at_pd = up
            .special(SpecialKind::PeriodDoubling)
            .next()
            .unwrap_or_else(|| panic!("{:?} {:?}", up.specials, up.end))
            .point
            .values[0];
        let down = continue_orbit(
            &model,
            &contact(),
            gamma,
            (start, 0.8 * sn),
            &rigid_guess(f, start),
            &options,
        )
        .unwrap();
        let at_fold = down
            .special(SpecialKind::Fold)
            .next()
            .unwrap_or_else(|| panic!("{:?} {:?}", down.specials, down.end))
            .point
            .values[0];
        // Brent on the compliant map's 1 + tr J + det J, independent of the continuation.
        let p0 = rigid_guess(f, 0.99 * pd).start.unwrap();
        let brent = period_doubling(
            |g| {
                CompliantStop::new(
                    &ball(f, g),
                    ForceModel::HuntCrossley,
                    DAMPING,
                    CompliantOptions {
                        rtol: 1e-12,
                        ..CompliantOptions::default()
                    },
                )
            },
            MapPoint {
                t: p0.phase / (2.0 * PI * f),
                v_in: p0.v_in,
                stop: 0,
            },
            (1, 1),
            (0.97 * pd, 1.03 * pd),
        )
        .unwrap()
        .unwrap();
        assert!(
            (at_pd - brent).abs() < 1e-6 * pd,
            "{at_pd} vs Brent {brent}"
        );
        deviations.push((ratio, at_fold / sn - 1.0, at_pd / pd - 1.0));
    }
    eprintln!("Hunt–Crossley, (t_c/T, ΔΓ_SN/Γ_SN, ΔΓ_PD/Γ_PD): {deviations:?}");
    let (coarse, fine) = (deviations[0], deviations[1]);
    assert!(
        fine.1.abs() < coarse.1.abs() && fine.2.abs() < coarse.2.abs(),
        "{deviations:?}"
    );
    assert!(
        fine.1.abs() < 0.003 && fine.2.abs() < 0.003,
        "{deviations:?}"
    );
}

/// At t_c/T = 0.003 the compliant branch's period doubling switches onto a period-2 branch: born
/// there, two distinct impacts a period past it, and each such orbit is the attractor a plain
/// simulation of the compliant stop started near the period-1 orbit settles on (its impact
/// speeds agree to 1e-6, an
/// integration independent of the continuation), near the rigid closed form's Γ_PD.
#[test]
fn switching_at_the_compliant_period_doubling_follows_the_doubled_orbit() {
    let gamma = Param::System(SystemKey::Gamma);
    let (sn, pd) = (gamma_sn(E), gamma_pd(E));
    let start = 0.5 * (sn + pd);
    let range = (start, 1.05 * pd);
    let f = frequency_for_ratio(0.003);
    let model = ball(f, start);
    let options = ContinuationOptions::default();
    let up = continue_orbit(
        &model,
        &contact(),
        gamma,
        range,
        &rigid_guess(f, start),
        &options,
    )
    .unwrap();
    let special = up.special(SpecialKind::PeriodDoubling).next().unwrap();
    let at_pd = special.point.values[0];
    assert!((at_pd / pd - 1.0).abs() < 0.003, "{at_pd} vs rigid {pd}");
    let doubled =
        switch_at_period_doubling(&model, &contact(), gamma, range, &up, special, &options)
            .unwrap();
    assert_eq!(doubled.cycles, 2);
    assert!(
        (doubled.points[0].values[0] - at_pd).abs() < 1e-8 * pd,
        "born at {} vs {at_pd}",
        doubled.points[0].values[0]
    );
    let past: Vec<_> = doubled
        .points
        .iter()
        .filter(|p| p.values[0] > at_pd * 1.005 && p.stable)
        .take(2)
        .collect();
    assert!(
        !past.is_empty(),
        "no stable point past Γ_PD: {:?}",
        doubled.end
    );
    for point in past {
        let g = point.values[0];
        let mut speeds: Vec<f64> = point.points.iter().map(|i| i.v_in).collect();
        speeds.sort_by(f64::total_cmp);
        assert_eq!(speeds.len(), 2, "{speeds:?}");
        assert!(
            speeds[1] - speeds[0] > 1e-3 * speeds[1],
            "{speeds:?}: period 1"
        );
        // Started on the rigid period-1 orbit, unstable past Γ_PD, it leaves along the doubling
        // (from rest the ball chatters, another attractor here).
        let model = ball(f, g);
        let run = simulate(
            &model,
            &contact(),
            &RunOptions {
                transient_impacts: 600,
                recorded_impacts: 20,
                initial: Some(period_one(&model, E, &RunOptions::default()).unwrap()),
                ..RunOptions::default()
            },
        )
        .unwrap();
        let recorded: Vec<f64> = (run.impacts.iter())
            .filter(|i| i.kind == ImpactKind::Impact)
            .map(|i| i.v_in)
            .collect();
        assert!(recorded.len() >= 10, "{recorded:?}");
        for v in recorded {
            let nearest = speeds
                .iter()
                .map(|s| (v - s).abs())
                .fold(f64::INFINITY, f64::min);
            assert!(nearest < 1e-6 * speeds[1], "Γ = {g}: {v} not in {speeds:?}");
        }
    }
}
