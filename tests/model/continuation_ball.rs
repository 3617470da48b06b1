//! Continuation of the bouncing ball's period-n orbits against the closed forms of the exact
//! impact map (docs/physics.md §8.1): the fold at Γ_SN = nπ(1−e)/(1+e) and the period doubling at
//! Γ_PD = √(Γ_SN² + (2(1+e²)/(1+e)²)²), found by continuation to 1e-8, det J = e² all along.

use std::f64::consts::PI;

use hertz_tui::model::system::continuation::{
    Branch, BranchEnd, ContinuationOptions, SpecialKind, continue_orbit, switch_at_period_doubling,
};
use hertz_tui::model::system::{Contact, OrbitOptions, Param, SystemKey, find_orbit};

use crate::systems_common::{ball, guess};

const E: f64 = 0.5;

fn gamma_sn(n: u32, e: f64) -> f64 {
    f64::from(n) * PI * (1.0 - e) / (1.0 + e)
}

fn gamma_pd(n: u32, e: f64) -> f64 {
    let b = 2.0 * (1.0 + e * e) / (1.0 + e).powi(2);
    gamma_sn(n, e).hypot(b)
}

/// The period-n branch of the ball (g = 1, ω = 1: Γ = A) from Γ = `from` towards `to`, started on
/// the stable orbit (sin φ > 0).
fn branch(n: u32, e: f64, from: f64, to: f64) -> Branch {
    let sn = gamma_sn(n, e);
    let phase = (sn / from).acos();
    let model = ball(from, e);
    continue_orbit(
        &model,
        &Contact::rigid(e),
        Param::System(SystemKey::Amplitude),
        (from, to),
        &guess(n, 1, phase + 1e-3, (f64::from(n) * PI + sn) * 1.001, 0),
        &ContinuationOptions::default(),
    )
    .unwrap()
}

#[test]
fn ball_fold_and_period_doubling_at_their_closed_forms() {
    for n in [1, 2] {
        let (sn, pd) = (gamma_sn(n, E), gamma_pd(n, E));
        let start = 0.5 * (sn + pd);
        let down = branch(n, E, start, 0.5 * sn);
        let folds: Vec<_> = down.special(SpecialKind::Fold).collect();
        assert_eq!(folds.len(), 1, "n = {n}: {:?}", down.specials);
        let fold = folds[0].point.values[0];
        assert!(
            (fold - sn).abs() < 1e-8,
            "n = {n}: fold at {fold} vs Γ_SN = {sn}"
        );
        // Past the fold the branch comes back up on the unstable orbits and leaves the range.
        assert_eq!(down.end, BranchEnd::Range);
        let last = down.points.last().unwrap();
        assert!(!last.stable && (last.values[0] - start).abs() < 1e-12);
        let up = branch(n, E, start, 1.2 * pd);
        let pds: Vec<_> = up.special(SpecialKind::PeriodDoubling).collect();
        assert_eq!(pds.len(), 1, "n = {n}: {:?}", up.specials);
        let at = pds[0].point.values[0];
        assert!((at - pd).abs() < 1e-8, "n = {n}: PD at {at} vs Γ_PD = {pd}");
        // Stable before, unstable after; det J = e² everywhere (docs/physics.md §8.1).
        assert!(up.points[0].stable && !up.points.last().unwrap().stable);
        for p in down.points.iter().chain(&up.points) {
            assert!(
                (p.jacobian_det - E * E).abs() < 1e-9,
                "det {}",
                p.jacobian_det
            );
        }
        eprintln!(
            "n = {n}: fold {:.3e} from Γ_SN, PD {:.3e} from Γ_PD; {} + {} points",
            fold - sn,
            at - pd,
            down.points.len(),
            up.points.len()
        );
    }
}

#[test]
fn switching_at_the_period_doubling_follows_the_doubled_orbit() {
    let (sn, pd) = (gamma_sn(1, E), gamma_pd(1, E));
    let from = 0.5 * (sn + pd);
    let up = branch(1, E, from, 1.2 * pd);
    let special = up.special(SpecialKind::PeriodDoubling).next().unwrap();
    let model = ball(from, E);
    let doubled = switch_at_period_doubling(
        &model,
        &Contact::rigid(E),
        Param::System(SystemKey::Amplitude),
        (from, 1.2 * pd),
        &up,
        special,
        &ContinuationOptions::default(),
    )
    .unwrap();
    assert_eq!((doubled.cycles, doubled.stops.len()), (2, 2));
    // It is born at Γ_PD and exists past it (supercritical), stable at first: two distinct
    // impacts per orbit, det J = e⁴.
    let first = &doubled.points[0];
    assert!((first.values[0] - pd).abs() < 1e-8);
    let next = &doubled.points[3];
    assert!(next.values[0] > pd, "{}", next.values[0]);
    assert!(next.stable, "{next:?}");
    assert!((next.jacobian_det - E.powi(4)).abs() < 1e-9);
    let (a, b) = (next.points[0].v_in, next.points[1].v_in);
    assert!(
        (a - b).abs() > 1e-3 * a,
        "{a} {b}: still the period-1 orbit"
    );
    // The same orbit by Newton on the impact map (the orbit solver, independent of continuation).
    let gamma = next.values[0];
    let orbit = find_orbit(
        &ball(gamma, E),
        &Contact::rigid(E),
        &guess(2, 2, next.points[0].phase + 1e-4, a * 1.0001, 0),
        &OrbitOptions::default(),
    )
    .unwrap();
    let speeds = |p: &[hertz_tui::model::system::ImpactPoint]| {
        let mut v: Vec<f64> = p.iter().map(|q| q.v_in).collect();
        v.sort_by(f64::total_cmp);
        v
    };
    for (x, y) in speeds(&orbit.points).iter().zip(speeds(&next.points)) {
        assert!((x - y).abs() < 1e-9, "{x} vs {y}");
    }
    eprintln!(
        "doubled branch: {} points, from Γ = {} to {}, specials {:?}",
        doubled.points.len(),
        first.values[0],
        doubled.points.last().unwrap().values[0],
        doubled
            .specials
            .iter()
            .map(|s| (s.kind, s.point.values[0]))
            .collect::<Vec<_>>()
    );
}
