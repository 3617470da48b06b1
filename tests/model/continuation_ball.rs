//! Continuation of the bouncing ball's period-n orbits against the closed forms of the exact
//! impact map (docs/physics.md §8.1): the fold at Γ_SN = nπ(1−e)/(1+e) and the period doubling at
//! Γ_PD = √(Γ_SN² + (2(1+e²)/(1+e)²)²), found by continuation to 1e-8, det J = e² all along.

use std::f64::consts::PI;

use hertz_tui::model::system::continuation::{
    Branch, BranchEnd, ContinuationOptions, SpecialKind, continue_orbit,
};
use hertz_tui::model::system::{Contact, Param, SystemKey};

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
        assert!((fold - sn).abs() < 1e-8, "n = {n}: fold at {fold} vs Γ_SN = {sn}");
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
            assert!((p.jacobian_det - E * E).abs() < 1e-9, "det {}", p.jacobian_det);
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
