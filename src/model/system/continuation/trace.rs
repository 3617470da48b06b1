//! Following a branch: predictor, corrector, step control, test functions watched between points
//! and their roots located by the Illinois (regula falsi) iteration on the arclength
//! (docs/continuation.md §2–3).

use nalgebra::DVector;

use super::branch::{BranchEnd, BranchPoint, ContinuationOptions, SpecialKind, SpecialPoint};
use super::engine::{Equations, correct, jacobian, tangent};
use super::error::ContinuationError;
use super::problem::{Approach, Monitors, OrbitProblem};

/// A branch that cannot go on with an impact speed below this fraction of its scale is said to
/// end near grazing.
const NEAR_GRAZING: f64 = 0.05;

/// Corrector iterations at most.
const CORRECTOR_ITERATIONS: usize = 12;

/// A compliant orbit's approach at one point of a branch is the same approach at the next when
/// it is to the same stop and within this many radians of forcing phase.
const SAME_APPROACH: f64 = 1.0;

/// The orbit problem with its parameters appended to the unknowns, z = (y, μ₁[, μ₂]) with
/// λᵢ = μᵢ·scaleᵢ; with a `test`, its value is one more equation (a curve of special points).
pub(crate) struct Augmented<'a> {
    pub problem: &'a dyn OrbitProblem,
    pub scales: Vec<f64>,
    pub test: Option<(SpecialKind, usize)>,
}

impl Augmented<'_> {
    pub fn split(&self, z: &DVector<f64>) -> (Vec<f64>, Vec<f64>) {
        let n = self.problem.unknowns();
        let y = z.rows(0, n).iter().copied().collect();
        let lambda = self
            .scales
            .iter()
            .enumerate()
            .map(|(i, s)| z[n + i] * s)
            .collect();
        (y, lambda)
    }

    pub fn monitors(&self, z: &DVector<f64>) -> Result<Monitors, ContinuationError> {
        let (y, lambda) = self.split(z);
        self.problem.monitors(&y, &lambda)
    }
}

/// The value of `kind`'s test function at a point (`speed_index`: the impact whose speed counts
/// for [`SpecialKind::GrazingImpact`], None for the smallest). None where it has no value.
pub(crate) fn test_value(
    kind: SpecialKind,
    m: &Monitors,
    scales: (f64, f64),
    speed_index: Option<usize>,
) -> Option<f64> {
    if kind.is_grazing() && m.approaches.is_some() {
        // A compliant orbit's grazing is watched through its approaches (`crossings`).
        return None;
    }
    let (trace, det) = m.trace_det();
    let value = match kind {
        SpecialKind::Fold => 1.0 - trace + det,
        SpecialKind::PeriodDoubling => 1.0 + trace + det,
        SpecialKind::GrazingImpact => {
            let speed = match speed_index {
                Some(k) => *m.speeds.get(k)?,
                None => m.min_speed().1,
            };
            speed / scales.0
        }
        SpecialKind::GrazingFlight => m.min_gap? / scales.1,
    };
    value.is_finite().then_some(value)
}

/// The equation a curve of `kind` adds: its test function, or for a compliant orbit's grazing
/// the clearance (over the length scale) of the approach nearest the stop's surface, the one that
/// grazes on the curve.
pub(crate) fn curve_test(
    kind: SpecialKind,
    m: &Monitors,
    scales: (f64, f64),
    index: usize,
) -> Option<f64> {
    match &m.approaches {
        Some(approaches) if kind.is_grazing() => nearest_surface(approaches, scales),
        _ => test_value(kind, m, scales, Some(index)),
    }
}

/// The clearance, over the length scale, of the approach nearest a stop's surface.
fn nearest_surface(approaches: &[Approach], scales: (f64, f64)) -> Option<f64> {
    approaches
        .iter()
        .map(|a| a.clearance)
        .min_by(|a, b| a.abs().total_cmp(&b.abs()))
        .map(|c| c / scales.1)
}

/// The approach of `m` to `stop` nearest in phase to `phase` on the orbit's circle of `span`
/// radians, if one is within [`SAME_APPROACH`].
fn matched(m: &Monitors, stop: usize, phase: f64, span: f64) -> Option<Approach> {
    let distance = |a: &Approach| {
        let d = (a.phase - phase).rem_euclid(span);
        d.min(span - d)
    };
    m.approaches
        .as_ref()?
        .iter()
        .filter(|a| a.stop == stop && distance(a) < SAME_APPROACH)
        .min_by(|a, b| distance(a).total_cmp(&distance(b)))
        .copied()
}

/// A compliant orbit's grazings between two points: each approach whose clearance changes sign,
/// with the kind that says which way ([`SpecialKind::GrazingImpact`]: a contact vanishes;
/// [`SpecialKind::GrazingFlight`]: a flight's gap minimum becomes a new contact).
fn crossings(before: &Monitors, after: &Monitors, span: f64) -> Vec<(SpecialKind, Approach)> {
    let Some(approaches) = &before.approaches else {
        return Vec::new();
    };
    let mut out: Vec<(SpecialKind, Approach)> = Vec::new();
    for a in approaches {
        let Some(b) = matched(after, a.stop, a.phase, span) else {
            continue;
        };
        if (a.clearance < 0.0) == (b.clearance < 0.0) || out.iter().any(|(_, o)| *o == *a) {
            continue;
        }
        let kind = if a.clearance < 0.0 {
            SpecialKind::GrazingImpact
        } else {
            SpecialKind::GrazingFlight
        };
        out.push((kind, *a));
    }
    out
}

impl Equations for Augmented<'_> {
    fn equations(&self) -> usize {
        self.problem.unknowns() + usize::from(self.test.is_some())
    }

    fn residual(&self, z: &DVector<f64>) -> Result<DVector<f64>, ContinuationError> {
        let (y, lambda) = self.split(z);
        let mut r = self.problem.residual(&y, &lambda)?;
        if let Some((kind, index)) = self.test {
            let scales = self.problem.scales();
            let approaches = if kind.is_grazing() {
                self.problem.approaches(&y, &lambda)?
            } else {
                None
            };
            let value = match approaches {
                Some(approaches) => nearest_surface(&approaches, scales),
                None => curve_test(kind, &self.problem.monitors(&y, &lambda)?, scales, index),
            }
            .ok_or(ContinuationError::NoSuchPoint(format!(
                "the {} test function has no value here",
                kind.label()
            )))?;
            r.push(value);
        }
        Ok(DVector::from_vec(r))
    }

    fn fd_step(&self) -> f64 {
        self.problem.fd_step()
    }

    fn tolerance(&self) -> f64 {
        self.problem.tolerance()
    }
}

/// A point of the trace with what is watched there.
#[derive(Clone)]
struct Node {
    z: DVector<f64>,
    t: DVector<f64>,
    monitors: Monitors,
    arclength: f64,
}

/// What to follow and watch.
pub(crate) struct Trace<'a> {
    pub eq: &'a Augmented<'a>,
    pub options: ContinuationOptions,
    /// The kinds whose test functions are watched.
    pub watch: Vec<SpecialKind>,
    /// Bounds of the last scaled parameter.
    pub bounds: (f64, f64),
    /// Ends the trace as grazing where the smallest impact speed falls below this (scaled): a
    /// fold or period-doubling curve runs into a grazing point without crossing it (J ~ 1/v).
    pub min_speed: Option<f64>,
    /// Polled before every step: true ends the trace with [`ContinuationError::Stopped`] (the
    /// explorer's job superseded by an edit).
    pub stop: &'a (dyn Fn() -> bool + Sync),
}

/// The `stop` of a trace nobody stops.
pub(crate) fn never() -> bool {
    false
}

/// The outcome of a trace.
pub(crate) struct Traced {
    pub points: Vec<BranchPoint>,
    pub specials: Vec<SpecialPoint>,
    pub end: BranchEnd,
}

impl Trace<'_> {
    pub fn point(&self, z: &DVector<f64>, m: &Monitors, arclength: f64) -> BranchPoint {
        let (_, lambda) = self.eq.split(z);
        let multipliers = m.multipliers();
        let (_, det) = m.trace_det();
        let min_speed = m.min_speed().1;
        let physical = min_speed > 0.0 && m.min_gap.is_none_or(|g| g > 0.0);
        BranchPoint {
            values: lambda,
            points: m.points.clone(),
            multipliers: multipliers.to_vec(),
            jacobian_det: det,
            stable: physical && multipliers.iter().all(|z| z.norm() < 1.0),
            min_speed,
            min_gap: m.min_gap,
            arclength,
            z: z.iter().copied().collect(),
        }
    }

    fn tests(&self, m: &Monitors) -> Vec<Option<f64>> {
        let scales = self.eq.problem.scales();
        self.watch
            .iter()
            .map(|&k| test_value(k, m, scales, None))
            .collect()
    }

    /// The branch point at arclength s past `from` along its tangent.
    fn at(&self, from: &Node, s: f64) -> Result<(DVector<f64>, Monitors), ContinuationError> {
        let pred = &from.z + &from.t * s;
        let (z, _) = correct(self.eq, &pred, &from.t, CORRECTOR_ITERATIONS)?;
        let m = self.eq.monitors(&z)?;
        Ok((z, m))
    }

    /// The root in (0, ds) of `f` along the step from `from`, f(0) = fa and f(ds) = fb of
    /// opposite signs: Illinois iteration on s.
    fn locate(
        &self,
        from: &Node,
        (mut b, mut fb): (f64, f64),
        mut fa: f64,
        f: &dyn Fn(&DVector<f64>, &Monitors) -> Option<f64>,
    ) -> Result<(f64, DVector<f64>, Monitors, f64), ContinuationError> {
        let mut a = 0.0;
        let mut side = 0;
        let mut last = None;
        for _ in 0..200 {
            let s = if fb != fa {
                (a * fb - b * fa) / (fb - fa)
            } else {
                0.5 * (a + b)
            };
            let s = if s > a.min(b) && s < a.max(b) {
                s
            } else {
                0.5 * (a + b)
            };
            let (z, m) = self.at(from, s)?;
            let fs = f(&z, &m).ok_or(ContinuationError::NoSuchPoint(
                "a test function lost its value while being located".into(),
            ))?;
            let done = fs == 0.0 || (b - a).abs() <= self.options.locate_tolerance;
            last = Some((s, z, m, fs));
            if done {
                break;
            }
            if fs.signum() == fb.signum() {
                b = s;
                fb = fs;
                if side == -1 {
                    fa *= 0.5;
                }
                side = -1;
            } else {
                a = s;
                fa = fs;
                if side == 1 {
                    fb *= 0.5;
                }
                side = 1;
            }
        }
        last.ok_or(ContinuationError::NoSuchPoint("no iteration".into()))
    }

    /// Follows the branch from `z0` (tangent `t0`); the first step's interval is not searched
    /// for special points when `skip_first` (z0 is itself a branch point).
    pub fn run(
        &self,
        z0: DVector<f64>,
        t0: DVector<f64>,
        skip_first: bool,
    ) -> Result<Traced, ContinuationError> {
        let o = &self.options;
        let m0 = self.eq.monitors(&z0)?;
        let mut node = Node {
            z: z0,
            t: t0,
            monitors: m0,
            arclength: 0.0,
        };
        let mut points = vec![self.point(&node.z, &node.monitors, 0.0)];
        let mut specials = Vec::new();
        let mut ds = o.initial_step;
        let mut skip = skip_first;
        let last = node.z.len() - 1;
        let (lo, hi) = self.bounds;
        let end = loop {
            if (self.stop)() {
                return Err(ContinuationError::Stopped);
            }
            if points.len() >= o.max_points {
                break BranchEnd::MaxPoints;
            }
            if ds < o.min_step {
                let (_, v) = node.monitors.min_speed();
                let scale = self.eq.problem.scales().0;
                break BranchEnd::StepTooSmall(if v < NEAR_GRAZING * scale {
                    format!("near grazing: the impact speed fell to {v:.3e} m/s")
                } else {
                    "the corrector failed at every step size".into()
                });
            }
            let step = self.at(&node, ds).and_then(|(z, m)| {
                let jac = jacobian(self.eq, &z)?;
                let t = tangent(&jac, &node.t)?;
                Ok((z, m, t))
            });
            let (z, m, t) = match step {
                Ok(s) if s.2.dot(&node.t) > 0.9 => s,
                Ok(_) | Err(_) => {
                    ds *= 0.5;
                    continue;
                }
            };
            // Special points in this step, in the order of the arclength.
            let before = self.tests(&node.monitors);
            let after = self.tests(&m);
            let mut found: Vec<(f64, SpecialKind, DVector<f64>, Monitors, f64)> = Vec::new();
            let mut lost = false;
            if !skip {
                for (i, &kind) in self.watch.iter().enumerate() {
                    let (Some(fa), Some(fb)) = (before[i], after[i]) else {
                        continue;
                    };
                    if fa.signum() == fb.signum() || fa == 0.0 {
                        continue;
                    }
                    let scales = self.eq.problem.scales();
                    let f = move |_: &DVector<f64>, m: &Monitors| test_value(kind, m, scales, None);
                    match self.locate(&node, (ds, fb), fa, &f) {
                        // A test through a pole (J's 1/v near grazing) is no root.
                        Ok((s, zs, ms, fs)) if fs.abs() < 1e-6 => found.push((s, kind, zs, ms, fs)),
                        Ok(_) => {}
                        Err(_) => lost = true,
                    }
                }
                // A compliant orbit: an approach's clearance through zero, located on it.
                let (cycles, _) = self.eq.problem.signature();
                let span = std::f64::consts::TAU * f64::from(cycles);
                let length = self.eq.problem.scales().1;
                for (kind, a) in crossings(&node.monitors, &m, span) {
                    if !self.watch.contains(&kind) {
                        continue;
                    }
                    let Some(b) = matched(&m, a.stop, a.phase, span) else {
                        continue;
                    };
                    let f = move |_: &DVector<f64>, m: &Monitors| {
                        matched(m, a.stop, a.phase, span).map(|c| c.clearance / length)
                    };
                    match self.locate(&node, (ds, b.clearance / length), a.clearance / length, &f) {
                        Ok((s, zs, ms, fs)) if fs.abs() < 1e-6 => found.push((s, kind, zs, ms, fs)),
                        Ok(_) => {}
                        Err(_) => lost = true,
                    }
                }
            }
            if lost {
                // A root the corrector could not reach from this step: take a shorter one.
                ds *= 0.5;
                continue;
            }
            skip = false;
            found.sort_by(|a, b| a.0.total_cmp(&b.0));
            let mut grazed = None;
            for (s, kind, zs, ms, fs) in found {
                let point = self.point(&zs, &ms, node.arclength + s);
                specials.push(SpecialPoint {
                    kind,
                    point: point.clone(),
                    test: fs,
                    after: points.len() - 1,
                });
                if kind.is_grazing() && o.stop_at_grazing {
                    grazed = Some(point);
                    break;
                }
            }
            if let Some(point) = grazed {
                points.push(point);
                break BranchEnd::Grazing;
            }
            // The range's end: the last point exactly on it.
            if z[last] < lo || z[last] > hi {
                let bound = if z[last] < lo { lo } else { hi };
                let f = move |z: &DVector<f64>, _: &Monitors| Some(z[last] - bound);
                let (s, zb, mb, _) =
                    self.locate(&node, (ds, z[last] - bound), node.z[last] - bound, &f)?;
                points.push(self.point(&zb, &mb, node.arclength + s));
                break BranchEnd::Range;
            }
            let arclength = node.arclength + ds;
            points.push(self.point(&z, &m, arclength));
            let scale = self.eq.problem.scales().0;
            if self.min_speed.is_some_and(|v| m.min_speed().1 < v * scale) {
                break BranchEnd::Grazing;
            }
            node = Node {
                z,
                t,
                monitors: m,
                arclength,
            };
            ds = (ds * 1.5).min(o.max_step);
        };
        Ok(Traced {
            points,
            specials,
            end,
        })
    }
}
