//! The largest Lyapunov exponent of the impact map, per impact (docs/maps.md §2).
//!
//! - Rigid stop: the exact Jacobian of each map step (docs/systems.md §5) applied to a tangent
//!   vector renormalised every step — the one-column form of the QR method of Benettin et al.
//!   (1980): λ = (1/L)·Σ ln‖J_k·w_{k−1}‖, ‖w‖ = 1.
//! - Compliant stop: two trajectories (Benettin's method): a companion started d₀ away, both
//!   mapped one step, the distance's growth logged and the companion brought back to d₀ along the
//!   difference. Both are integrated at [`COMPANION_RTOL`] so that the difference, d₀ = 1e-6 of the
//!   scales, is resolved to ~1e-4.
//!
//! Distances are measured in (t/T, v/V): T the forcing period, V the largest recorded speed; the
//! exponent does not depend on that choice as L grows, only its convergence does.

use crate::model::ForceModel;
use crate::model::system::compliant::orbit::{MapPoint, map_step as compliant_step};
use crate::model::system::compliant::{CompliantOptions, CompliantStop};
use crate::model::system::rigid::dynamics::Dynamics;
use crate::model::system::rigid::orbit::map_step as rigid_step;
use crate::model::system::{
    CompliantDamping, ImpactKind, ImpactRecord, State, SystemError, SystemModel,
};

/// The companion's distance, relative to the scales.
const D0: f64 = 1e-6;

/// The integration tolerance of both trajectories of the compliant method.
pub const COMPANION_RTOL: f64 = 1e-10;

/// Forcing periods searched for the next impact of one map step.
const HORIZON_PERIODS: f64 = 64.0;

/// Why no exponent: the map stops being a map of isolated impacts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum NoExponent {
    /// The orbit chatters or sticks, or a contact holds the body.
    Chatters,
    /// No further impact within the horizon.
    NoImpact,
    /// The companion hit the other stop (the orbit grazes a stop).
    Grazes,
}

/// Why a map step refused: the steps say so only in words (`OrbitDegenerate`), so the two "no
/// impact" messages of the rigid and compliant steps are told from chatter and held contacts by
/// their text; anything else (a budget, a failed contact) is the cell's error.
fn degenerate(e: SystemError) -> Result<NoExponent, SystemError> {
    match e {
        SystemError::OrbitDegenerate(why)
            if why.contains("no impact") || why.contains("no further") =>
        {
            Ok(NoExponent::NoImpact)
        }
        SystemError::OrbitDegenerate(_) => Ok(NoExponent::Chatters),
        other => Err(other),
    }
}

/// The exponent of the rigid map over `steps` impacts from just after `last` (an isolated impact).
pub fn rigid(
    model: &SystemModel,
    restitution: f64,
    last: &ImpactRecord,
    speed: f64,
    steps: usize,
) -> Result<Result<f64, NoExponent>, SystemError> {
    let d = Dynamics::new(model, restitution);
    let (s, sv, _) = d.stop_motion(last.stop, last.t);
    let mut state = State {
        t: last.t,
        x: s,
        v: sv + d.stops[last.stop].sigma * last.v_out,
    };
    let mut stop = last.stop;
    let (tt, vv) = (d.period, speed.max(f64::MIN_POSITIVE));
    let mut w = [std::f64::consts::FRAC_1_SQRT_2; 2];
    let mut sum = 0.0;
    for _ in 0..steps {
        let step = match rigid_step(&d, stop, state, HORIZON_PERIODS * d.period) {
            Ok(step) => step,
            Err(e) => return degenerate(e).map(Err),
        };
        let j = step.jacobian;
        // J in the scaled variables (t/T, v/V).
        let js = [[j[0][0], j[0][1] * vv / tt], [j[1][0] * tt / vv, j[1][1]]];
        let u = [
            js[0][0] * w[0] + js[0][1] * w[1],
            js[1][0] * w[0] + js[1][1] * w[1],
        ];
        let norm = u[0].hypot(u[1]);
        if !(norm > 0.0 && norm.is_finite()) {
            return Ok(Err(NoExponent::Chatters));
        }
        sum += norm.ln();
        w = [u[0] / norm, u[1] / norm];
        stop = step.point.stop;
        state = step.after;
    }
    Ok(Ok(sum / steps.max(1) as f64))
}

/// The exponent of the compliant map over `steps` impacts from the first contact of `last`.
pub fn compliant(
    model: &SystemModel,
    law: ForceModel,
    damping: CompliantDamping,
    last: &ImpactRecord,
    speed: f64,
    steps: usize,
) -> Result<Result<f64, NoExponent>, SystemError> {
    let options = CompliantOptions {
        rtol: COMPANION_RTOL,
        ..CompliantOptions::default()
    };
    let stop = CompliantStop::new(model, law, damping, options)?;
    let tt = model.spec.period();
    let vv = speed.max(f64::MIN_POSITIVE);
    let mut p = MapPoint {
        t: last.t,
        v_in: last.v_in,
        stop: last.stop,
    };
    let offset = D0 * std::f64::consts::FRAC_1_SQRT_2;
    let mut q = MapPoint {
        t: p.t + offset * tt,
        v_in: p.v_in + offset * vv,
        ..p
    };
    let mut sum = 0.0;
    for _ in 0..steps {
        let (a, b) = match (compliant_step(&stop, p), compliant_step(&stop, q)) {
            (Ok(a), Ok(b)) => (a.next, b.next),
            (Err(e), _) | (_, Err(e)) => return degenerate(e).map(Err),
        };
        if a.stop != b.stop {
            return Ok(Err(NoExponent::Grazes));
        }
        let (dt, dv) = ((b.t - a.t) / tt, (b.v_in - a.v_in) / vv);
        let dist = dt.hypot(dv).max(f64::MIN_POSITIVE);
        sum += (dist / D0).ln();
        p = a;
        q = MapPoint {
            t: a.t + (b.t - a.t) * D0 / dist,
            v_in: a.v_in + (b.v_in - a.v_in) * D0 / dist,
            ..a
        };
    }
    Ok(Ok(sum / steps.max(1) as f64))
}

/// The last recorded isolated impact the map can start from (one that leaves the stop).
pub fn start_of(impacts: &[ImpactRecord]) -> Option<&ImpactRecord> {
    impacts
        .iter()
        .rev()
        .find(|i| i.kind == ImpactKind::Impact && i.v_out > 0.0)
}
