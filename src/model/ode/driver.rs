//! The integration loop shared by every method: validate the options, take accepted steps from a
//! [`Scheme`], store their interpolants, look for events, call the system's check, stop.

use super::dop853::Dop853;
use super::dopri5::Dopri5;
use super::events::EventTracker;
use super::fixed_step::{FixedKind, FixedStep};
use super::radau5::Radau5;
use super::step_control::{error_norm, is_finite, rhs};
use super::{
    DenseOutput, Event, Integration, Method, OdeError, OdeSystem, Options, Segment, State, Stats,
    Stop,
};

/// One accepted step: its end and its interpolant over [t, t_new].
pub(super) struct Step {
    pub t: f64,
    pub y: State,
    pub segment: Segment,
}

/// A one-step method. `step` advances from (t, y) by one *accepted* step, retrying rejected
/// attempts internally; every attempt counts towards the step budget. Implementors keep their own
/// memory (FSAL derivative, step-size proposal, Jacobian) between calls.
pub(super) trait Scheme {
    fn step(
        &mut self,
        sys: &mut dyn OdeSystem,
        t: f64,
        y: &State,
        stats: &mut Stats,
    ) -> Result<Step, OdeError>;
}

/// Segments reserved up front: enough for a typical impact, so the inner loop does not regrow.
const RESERVED_SEGMENTS: usize = 64;

pub(super) fn integrate(
    method: Method,
    sys: &mut dyn OdeSystem,
    t0: f64,
    y0: State,
    events: &[Event],
    opts: &Options,
    glide: bool,
) -> Result<Integration, OdeError> {
    validate(method, t0, opts)?;
    if !is_finite(&y0) {
        return Err(OdeError::NonFinite { t: t0 });
    }
    let mut stats = Stats::default();
    match method {
        Method::Euler | Method::SymplecticEuler | Method::Verlet | Method::Rk4 => {
            let kind = match method {
                Method::Euler => FixedKind::Euler,
                Method::SymplecticEuler => FixedKind::SymplecticEuler,
                Method::Verlet => FixedKind::Verlet,
                _ => FixedKind::Rk4,
            };
            // `validate` guarantees dt is present and positive.
            let dt = opts.dt.unwrap_or(f64::NAN);
            let scheme = FixedStep::new(kind, sys, &mut stats, t0, &y0, dt, opts)?;
            run(method, scheme, sys, stats, t0, y0, events, opts, glide)
        }
        Method::Dopri5 => {
            let scheme = Dopri5::new(sys, &mut stats, t0, &y0, opts)?;
            run(method, scheme, sys, stats, t0, y0, events, opts, glide)
        }
        Method::Dop853 => {
            let scheme = Dop853::new(sys, &mut stats, t0, &y0, opts)?;
            run(method, scheme, sys, stats, t0, y0, events, opts, glide)
        }
        Method::Radau5 => {
            let scheme = Radau5::new(sys, &mut stats, t0, &y0, opts)?;
            run(method, scheme, sys, stats, t0, y0, events, opts, glide)
        }
    }
}

fn invalid(msg: String) -> Result<(), OdeError> {
    Err(OdeError::InvalidOptions(msg))
}

fn validate(method: Method, t0: f64, opts: &Options) -> Result<(), OdeError> {
    if !t0.is_finite() {
        return invalid(format!("t0 = {t0} is not finite"));
    }
    if opts.t_max.is_nan() || opts.t_max <= t0 {
        return invalid(format!(
            "t_max = {} must lie after t0 = {t0} (integration runs forward)",
            opts.t_max
        ));
    }
    if method.is_adaptive() {
        if !(opts.rtol.is_finite() && opts.rtol >= 0.0) {
            return invalid(format!("rtol = {} must be finite and ≥ 0", opts.rtol));
        }
        if !(opts.atol.is_finite() && opts.atol > 0.0) {
            return invalid(format!("atol = {} must be finite and > 0", opts.atol));
        }
        if method == Method::Radau5 && opts.rtol <= 10.0 * f64::EPSILON {
            return invalid(format!(
                "rtol = {} is too small for radau5 (must exceed 10·ε)",
                opts.rtol
            ));
        }
        if opts.h_max.is_nan() || opts.h_max <= 0.0 {
            return invalid(format!("h_max = {} must be > 0", opts.h_max));
        }
        if let Some(h) = opts.h_initial
            && !(h.is_finite() && h > 0.0)
        {
            return invalid(format!("h_initial = {h} must be finite and > 0"));
        }
    } else {
        match opts.dt {
            None => return invalid(format!("{method} is a fixed-step method and needs dt")),
            Some(dt) if !(dt.is_finite() && dt > 0.0) => {
                return invalid(format!("dt = {dt} must be finite and > 0"));
            }
            Some(_) => {}
        }
    }
    Ok(())
}

#[allow(clippy::too_many_arguments)]
fn run<S: Scheme>(
    method: Method,
    mut scheme: S,
    sys: &mut dyn OdeSystem,
    mut stats: Stats,
    t0: f64,
    y0: State,
    events: &[Event],
    opts: &Options,
    glide: bool,
) -> Result<Integration, OdeError> {
    let mut dense = DenseOutput::with_capacity(RESERVED_SEGMENTS);
    let mut tracker = EventTracker::new(events, t0, &y0);
    let mut t = t0;
    let mut y = y0;
    loop {
        let step = scheme.step(sys, t, &y, &mut stats)?;
        // Fixed-step methods may overshoot t_max: events beyond it do not count, and the end
        // state is interpolated there.
        let beyond = step.t >= opts.t_max;
        let (t_b, y_b) = if beyond && step.t > opts.t_max {
            (opts.t_max, step.segment.eval(opts.t_max))
        } else {
            (step.t, step.y)
        };
        let hit = tracker.check(events, &step.segment, t, t_b, &y_b);
        if let Some(hit) = hit {
            let landed = if method.is_adaptive() {
                Some(land(
                    method,
                    sys,
                    &mut stats,
                    (t, y),
                    &step.segment,
                    &events[hit.index],
                    hit.t,
                    opts,
                    glide,
                )?)
            } else {
                None
            };
            dense.push(step.segment);
            let (t_hit, y_hit) = match landed {
                Some(landing) => {
                    dense.truncate_at(t);
                    dense.append(&landing.dense);
                    (landing.t, landing.y)
                }
                None => {
                    let slope = rhs(sys, &mut stats, hit.t, &hit.y);
                    let last = dense.segments().last().cloned();
                    let refit = last.filter(|_| is_finite(&slope));
                    match refit.and_then(|s| s.hermite_ending_at(hit.t, hit.y, slope)) {
                        Some(refitted) => {
                            dense.truncate_at(t);
                            dense.push(refitted);
                        }
                        None => dense.truncate_at(hit.t),
                    }
                    (hit.t, hit.y)
                }
            };
            return finish(
                sys,
                dense,
                t_hit,
                y_hit,
                Stop::Event { index: hit.index },
                stats,
            );
        }
        dense.push(step.segment);
        if beyond {
            dense.truncate_at(t_b);
            return finish(sys, dense, t_b, y_b, Stop::TimeLimit, stats);
        }
        t = step.t;
        y = step.y;
        sys.check(t, &y)
            .map_err(|reason| OdeError::Aborted { t, reason })?;
    }
}

/// Corrections of the event time after the first landing: the interpolant's root is within the
/// local error of the true one; Newton with the interpolant's rate, then secants through the
/// landed states, reach rounding in two or three.
const LANDING_CORRECTIONS: usize = 3;

/// Ends an adaptive integration on an event with the method's full order: the interpolant of a
/// step is an order lower than the step itself (DOPRI5's is 4th order) and, in the step that
/// straddles the event, was built from stages beyond it. So the step from `start` is retaken to
/// end exactly at the located time `t_hit`, and that time is corrected by Newton's method on the
/// event function along the new end state (its rate first taken from the straddling `segment`,
/// then by secant through the landed states).
///
/// With `glides` (`ode::integrate_gliding`), a correction is a short move along the solution from
/// the landed state ([`glide`]) when it
/// is short enough for a second-order step to keep the tolerance — after the first landing it
/// nearly always is, the interpolant's root being off by about the local error — and a retaken
/// step otherwise. A glide costs one force evaluation (the first two) where a retaken DOP853 step
/// costs sixteen.
#[allow(clippy::too_many_arguments)]
fn land(
    method: Method,
    sys: &mut dyn OdeSystem,
    stats: &mut Stats,
    (t_start, y_start): (f64, State),
    segment: &Segment,
    event: &Event,
    t_hit: f64,
    opts: &Options,
    glides: bool,
) -> Result<Integration, OdeError> {
    let g = |t: f64, y: &State| (event.g)(t, y);
    // dg/dt along the solution, by a central difference on the straddling step's interpolant.
    let h_step = segment.t_end() - t_start;
    let delta = 1e-5 * h_step;
    let mut rate = (g(t_hit + delta, &segment.eval(t_hit + delta))
        - g(t_hit - delta, &segment.eval(t_hit - delta)))
        / (2.0 * delta);
    let mut target = t_hit;
    let mut corrections = 0;
    // The previous landing (time, g), for a secant rate from the landed states themselves.
    let mut previous: Option<(f64, f64)> = None;
    // The first step of the previous landing where it took more than one: the span was rejected
    // there (a step ending on the event can be harder than the one straddling it, e.g. a force
    // ∝ x^¼ ending at x = 0), and the corrections move the target by far less than a step.
    let mut first_step: Option<f64> = None;
    let (mut landing, mut f) = loop {
        let spent = stats.steps + stats.rejected_steps;
        let span = target - t_start;
        let sub_opts = Options {
            h_initial: Some(first_step.map_or(span, |h| h.min(span))),
            h_max: span,
            t_max: target,
            max_steps: opts.max_steps.saturating_sub(spent).max(1),
            ..*opts
        };
        let landing = integrate(method, sys, t_start, y_start, &[], &sub_opts, false)?;
        *stats += landing.stats;
        let segments = landing.dense.segments();
        first_step = (segments.len() > 1).then(|| segments[0].t_end() - segments[0].t_start());
        let g_landed = g(landing.t, &landing.y);
        if let Some((t_prev, g_prev)) = previous {
            let secant = (g_landed - g_prev) / (landing.t - t_prev);
            if secant.is_finite() && secant != 0.0 {
                rate = secant;
            }
        }
        previous = Some((landing.t, g_landed));
        let dt = -g_landed / rate;
        corrections += 1;
        let next = target + dt;
        if settled(dt, target, h_step)
            || corrections > LANDING_CORRECTIONS
            || next <= t_start
            || next > t_start + 2.0 * h_step
        {
            return Ok(landing);
        }
        if !glides {
            target = next;
            continue;
        }
        let f = rhs(sys, stats, landing.t, &landing.y);
        let mut landing = landing;
        if is_finite(&f)
            && let Some(f_new) = glide(sys, stats, &mut landing, f, dt, opts)
        {
            break (landing, f_new);
        }
        target = next;
    };
    // The remaining corrections glide on from there, each with the secant through the last two
    // states.
    let g_start = g(t_start, &y_start);
    let (mut t_prev, mut g_prev) = previous.unwrap_or((t_start, g(t_start, &y_start)));
    while corrections <= LANDING_CORRECTIONS {
        let g_now = g(landing.t, &landing.y);
        let secant = (g_now - g_prev) / (landing.t - t_prev);
        // Both g's are near rounding by now: a secant of the other sign is their noise.
        if secant.is_finite() && secant * rate > 0.0 {
            rate = secant;
        }
        (t_prev, g_prev) = (landing.t, g_now);
        let dt = -g_now / rate;
        if !is_finite(&f) {
            break;
        }
        if settled(dt, landing.t, h_step) {
            cross(&mut landing, &g, g_start, f, dt);
            break;
        }
        let Some(f_new) = glide(sys, stats, &mut landing, f, dt, opts) else {
            break;
        };
        f = f_new;
        corrections += 1;
    }
    Ok(landing)
}

/// Moves a settled glide onto the far side of the event (or onto g = 0) where rounding left it on
/// the near side, by Euler moves of a few ulps of t: an integration restarted from there must not
/// see the same event again right after its start.
fn cross(
    landing: &mut Integration,
    g: &dyn Fn(f64, &State) -> f64,
    g_start: f64,
    f: State,
    dt: f64,
) {
    let ulps = 4.0 * f64::EPSILON * landing.t.abs().max(f64::MIN_POSITIVE);
    let mut step = dt.abs().max(ulps).copysign(dt);
    for _ in 0..4 {
        let g_now = g(landing.t, &landing.y);
        if g_now == 0.0 || g_now.signum() != g_start.signum() || step == 0.0 {
            return;
        }
        let (t1, y1) = (landing.t + step, landing.y + f * step);
        landing.dense.end_with(t1, y1);
        landing.t = t1;
        landing.y = y1;
        step *= 2.0;
    }
}

/// A Newton correction `dt` below rounding of the time.
fn settled(dt: f64, t: f64, h_step: f64) -> bool {
    !(dt.is_finite()) || dt.abs() <= 4.0 * f64::EPSILON * t.abs().max(h_step)
}

/// The largest error an Euler step over a glide's move may have, in units of the local tolerance
/// (estimated as ½·dt·(f(y + f·dt) − f), Hairer–Nørsett–Wanner I, §II.4): Heun's step over the same
/// move is a further factor of about dt·y‴/y″ below it.
const GLIDE_ERROR: f64 = 1e-2;

/// Moves the landed state by `dt` along the solution with Heun's second-order step from its slope
/// `f` (Hairer–Nørsett–Wanner I, §II.1), ends the dense output there ([`DenseOutput::end_with`]),
/// and returns the slope there; `None` (nothing moved) where the move is too long for the tolerance
/// (its Euler error above [`GLIDE_ERROR`]) or leaves the domain of f.
fn glide(
    sys: &mut dyn OdeSystem,
    stats: &mut Stats,
    landing: &mut Integration,
    f: State,
    dt: f64,
    opts: &Options,
) -> Option<State> {
    let (t0, y0) = (landing.t, landing.y);
    let t1 = t0 + dt;
    let f_euler = rhs(sys, stats, t1, &(y0 + f * dt));
    let euler_error = (f_euler - f) * (0.5 * dt);
    let y1 = y0 + (f + f_euler) * (0.5 * dt);
    if !is_finite(&y1)
        || !is_finite(&f_euler)
        || error_norm(&euler_error, &y0, &y1, opts.atol, opts.rtol) > GLIDE_ERROR
    {
        return None;
    }
    landing.dense.end_with(t1, y1);
    landing.t = t1;
    landing.y = y1;
    Some(f_euler)
}

/// The last accepted state also passes the system's check before it is returned.
fn finish(
    sys: &mut dyn OdeSystem,
    dense: DenseOutput,
    t: f64,
    y: State,
    stop: Stop,
    stats: Stats,
) -> Result<Integration, OdeError> {
    if !is_finite(&y) {
        return Err(OdeError::NonFinite { t });
    }
    sys.check(t, &y)
        .map_err(|reason| OdeError::Aborted { t, reason })?;
    Ok(Integration {
        dense,
        t,
        y,
        stop,
        stats,
    })
}
