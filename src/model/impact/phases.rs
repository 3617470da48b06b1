//! The two phases of an impact, joined at the maximum-compression event ẋ = 0.
//!
//! Always two phases, for every law: dry friction's sign(ẋ) is then fixed within each phase and no
//! step ever straddles the switch (a step across it collapses an adaptive step-size controller).

use crate::model::force::{ContactEnd, ForceLaw, Phase};
use crate::model::ode::{
    self, DenseOutput, Direction, Event, Integration, Method, OdeError, State, Stats, Stop,
};

use super::ImpactError;
use super::scale::Scales;
use super::system::ImpactSystem;

/// Contact lasting this many elastic contact times means it will not end: [`ImpactError::NoSeparation`].
pub const TIME_LIMIT_CONTACTS: f64 = 100.0;

/// How the unloading phase ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum End {
    /// x returned to 0.
    Approach,
    /// The law's force reached 0 at x > 0: the proposed model's own end, or the compressive-only
    /// cutoff of the others.
    Tension,
}

/// Step control of one run, in scaled units.
#[derive(Debug, Clone, Copy)]
pub(crate) struct RunOptions {
    pub method: Method,
    pub rtol: f64,
    pub atol: f64,
    /// Fixed step in units of x_e/v₀ (fixed-step methods only).
    pub dt: Option<f64>,
    pub max_steps: usize,
    /// Where the phases end when that is known already (an exact solution's curves): then they
    /// run to these times instead of watching for the events.
    pub known: Option<KnownEnds>,
}

/// The ends of an impact known before it is integrated: scaled times of maximum compression and
/// of the end of contact, and how contact ends.
#[derive(Debug, Clone, Copy)]
pub(crate) struct KnownEnds {
    pub t_turn: f64,
    pub t_end: f64,
    pub end: End,
    /// Loading still finds maximum compression as its event (and unloading runs to `t_end`):
    /// the sampled curves meet the turn, where dry friction's force jumps and peaks, where the
    /// integration reaches it.
    pub find_turn: bool,
}

/// Both phases of one integrated impact.
#[derive(Debug, Clone)]
pub(crate) struct Run {
    pub loading: DenseOutput,
    pub unloading: DenseOutput,
    /// Scaled time and (X, V) at maximum compression (ẋ set to exactly 0). The loading dense
    /// output holds the solver's (X, W) ([`Scales::xv`] converts), the unloading one the state in
    /// [`Run::unloading_scales`].
    pub t_switch: f64,
    pub y_switch: State,
    /// Scaled time and (X, V) at the end of contact.
    pub t_end: f64,
    pub y_end: State,
    /// The scales of the unloading dense output: the loading's (X, W) where contact ends at x = 0
    /// with the force allowed to pull, else (X, V) ([`Scales::without_shift`]).
    pub unloading_scales: Scales,
    pub end: End,
    pub stats: Stats,
    pub force_evals: usize,
    /// The tolerance it was integrated to: the energy check's quadrature sizes its pieces by it.
    pub rtol: f64,
}

impl Run {
    /// The approach at maximum compression, m: where the unloading of a rate-independent
    /// hysteresis is anchored ([`ForceLaw::unloading_at_turn`]).
    pub fn x_turn(&self, sc: &Scales) -> f64 {
        run_x_turn(&self.y_switch, sc)
    }
}

fn run_x_turn(y_switch: &State, sc: &Scales) -> f64 {
    y_switch[0] * sc.x
}

/// Turns an integrator error in scaled time into one in seconds; an abort by the energy guard
/// becomes [`ImpactError::EnergyGrowth`].
fn impact_error(method: Method, err: OdeError, t_ref: f64, growth: Option<f64>) -> ImpactError {
    let source = match err {
        OdeError::Aborted { t, .. } if growth.is_some() => {
            return ImpactError::EnergyGrowth {
                method,
                t: t * t_ref,
                growth: 100.0 * growth.unwrap_or(0.0),
            };
        }
        OdeError::StepSizeUnderflow { t, h } => OdeError::StepSizeUnderflow {
            t: t * t_ref,
            h: h * t_ref,
        },
        OdeError::StepBudgetExhausted { t, steps } => OdeError::StepBudgetExhausted {
            t: t * t_ref,
            steps,
        },
        OdeError::NonFinite { t } => OdeError::NonFinite { t: t * t_ref },
        OdeError::NewtonFailed { t } => OdeError::NewtonFailed { t: t * t_ref },
        OdeError::Aborted { t, reason } => OdeError::Aborted {
            t: t * t_ref,
            reason,
        },
        other @ OdeError::InvalidOptions(_) => other,
    };
    ImpactError::Integration { method, source }
}

/// Integrates loading until ẋ = 0, then unloading until x = 0 or the law's force reaches 0
/// (whichever the law's rules watch), within [`TIME_LIMIT_CONTACTS`] elastic contact times and
/// `max_steps` accepted plus rejected steps in all. With [`RunOptions::known`] ends, each phase
/// runs to its known end instead, watching no event (an exact solution's curves: the event
/// landings, each step retaken until the event's time is found to rounding, were half their cost).
pub(crate) fn run<L: ForceLaw>(law: &L, sc: &Scales, ro: &RunOptions) -> Result<Run, ImpactError> {
    let t_limit = TIME_LIMIT_CONTACTS * sc.t_contact;
    let no_separation = ImpactError::NoSeparation {
        t_limit: t_limit * sc.t,
    };
    let mut opts = ode::Options {
        rtol: ro.rtol,
        atol: ro.atol,
        dt: ro.dt,
        h_initial: None,
        // A quarter of the elastic contact: no step can leap over most of the impact.
        h_max: 0.25 * sc.t_contact,
        t_max: t_limit,
        max_steps: ro.max_steps,
    };

    // Loading: from first contact to maximum compression, restarting at the law's breakpoint.
    let at_rest = |_: f64, y: &State| sc.velocity(y);
    let breakpoint = law
        .loading_breakpoint()
        .filter(|_| ro.method.is_adaptive())
        .map(|x| x / sc.x);
    let past_breakpoint = |_: f64, y: &State| y[0] - breakpoint.unwrap_or(f64::INFINITY);
    let loading_events = [
        Event {
            g: &at_rest,
            direction: Direction::Falling,
        },
        Event {
            g: &past_breakpoint,
            direction: Direction::Rising,
        },
    ];
    let mut sys = ImpactSystem::new(law, Phase::Loading, *sc);
    // Maximum compression is watched for unless known (then its event is skipped); the
    // breakpoint where there is one, after it.
    let known_turn = ro.known.filter(|known| !known.find_turn);
    let skip = usize::from(known_turn.is_some());
    let events = if breakpoint.is_some() {
        &loading_events[skip..]
    } else {
        &loading_events[skip..1]
    };
    if let Some(known) = known_turn {
        opts.t_max = known.t_turn;
    }
    let mut loading =
        ode::integrate_gliding(ro.method, &mut sys, 0.0, sc.xw(0.0, 1.0), events, &opts)
            .map_err(|e| impact_error(ro.method, e, sc.t, sys.growth))?;
    // (A breakpoint met at the known turn leaves no tail.)
    if breakpoint.is_some()
        && loading.stop == (Stop::Event { index: 1 - skip })
        && loading.t < opts.t_max
    {
        let spent = loading.stats.steps + loading.stats.rejected_steps;
        let exhausted = |steps: usize, t: f64| ImpactError::Integration {
            method: ro.method,
            source: OdeError::StepBudgetExhausted {
                t: t * sc.t,
                steps: spent + steps,
            },
        };
        if spent >= ro.max_steps {
            return Err(exhausted(0, loading.t));
        }
        let rest = ode::Options {
            max_steps: ro.max_steps - spent,
            ..opts
        };
        let tail = ode::integrate_gliding(
            ro.method,
            &mut sys,
            loading.t,
            loading.y,
            &loading_events[skip..1],
            &rest,
        )
        .map_err(|e| match e {
            // The budget is the whole solve's: count the steps before the breakpoint too.
            OdeError::StepBudgetExhausted { t, steps } => exhausted(steps, t),
            e => impact_error(ro.method, e, sc.t, sys.growth),
        })?;
        loading.dense.append(&tail.dense);
        loading.stats += tail.stats;
        loading.t = tail.t;
        loading.y = tail.y;
        loading.stop = tail.stop;
    }
    if loading.stop == Stop::TimeLimit && known_turn.is_none() {
        return Err(no_separation);
    }
    let mut force_evals = sys.force_evals;
    let mut stats = loading.stats;
    let Integration {
        dense: loading_dense,
        t: t_switch,
        y,
        ..
    } = loading;
    // The event lies on the far side of ẋ = 0 by a rounding error; start unloading exactly at rest.
    let y_switch = State::new(y[0], 0.0);
    // Unloading: events in a fixed order, x = 0 first.
    let spent = stats.steps + stats.rejected_steps;
    opts.max_steps = ro.max_steps.saturating_sub(spent);
    if opts.max_steps == 0 {
        return Err(ImpactError::Integration {
            method: ro.method,
            source: OdeError::StepBudgetExhausted {
                t: t_switch * sc.t,
                steps: spent,
            },
        });
    }
    // Adaptive methods resume with the last full step of loading instead of guessing anew: the
    // longer of the last two, as the last is usually the landing on maximum compression, cut short.
    opts.h_initial = loading_dense
        .segments()
        .iter()
        .rev()
        .take(2)
        .map(|seg| seg.t_end() - seg.t_start())
        .reduce(f64::max)
        .filter(|h| *h > 0.0 && ro.method.is_adaptive());
    // Unloading from the turning point reached, as a rate-independent hysteresis defines it.
    let law = &law.unloading_at_turn(run_x_turn(&y_switch, sc));
    // A rate-independent hysteresis (one branch up, another down) unloads over a span
    // x_max − x_res that may be 10⁻⁴ of x_max (Thornton far above v_y). Integrated in
    // X − X_turn, with atol = rtol in scaled units, its error weight is ~atol instead of
    // rtol·X_max: the rebound keeps the tolerance asked where X_max ≫ 1.
    let offset = if law.rate_independent() && law.switches_at_max_compression() {
        y_switch[0]
    } else {
        0.0
    };
    let approach = |_: f64, y: &State| y[0] + offset;
    let tension = |_: f64, y: &State| law.tension((y[0] + offset) * sc.x, y[1] * sc.v);
    let watch_tension = law.may_turn_tensile() || law.contact_end() == ContactEnd::ForceZero;
    let all_events = [
        Event {
            g: &approach,
            direction: Direction::Falling,
        },
        Event {
            g: &tension,
            direction: Direction::Falling,
        },
    ];
    let unloading_events = match ro.known {
        Some(known) => {
            opts.t_max = known.t_end;
            &all_events[..0]
        }
        None if watch_tension => &all_events[..],
        None => &all_events[..1],
    };
    // Unloading integrates V itself where contact may end at F = 0 with x > 0: near that end of a
    // heavily damped unloading V ≪ γ·Xᵖ, where recovering V from W would cost digits. Where it
    // ends at x = 0 (tension allowed) it keeps W: the damping's xᵖ⁻¹ singularity is at that end
    // too (the last steps' rejections), and there W = V.
    let usc = if offset == 0.0 && !watch_tension {
        *sc
    } else {
        sc.without_shift()
    };
    let mut sys = ImpactSystem::new(law, Phase::Unloading, usc);
    sys.x_offset = offset;
    let shift = State::new(offset, 0.0);
    let mut unloading = ode::integrate_gliding(
        ro.method,
        &mut sys,
        t_switch,
        usc.xw(y_switch[0], 0.0) - shift,
        unloading_events,
        &opts,
    )
    .map_err(|e| impact_error(ro.method, e, sc.t, sys.growth))?;
    unloading.dense.shift(shift);
    unloading.y = usc.xv(&(unloading.y + shift));
    force_evals += sys.force_evals;
    stats += unloading.stats;
    let end = match unloading.stop {
        Stop::TimeLimit if let Some(known) = ro.known => known.end,
        Stop::TimeLimit => return Err(no_separation),
        Stop::Event { index: 0 } => End::Approach,
        Stop::Event { .. } => End::Tension,
    };
    Ok(Run {
        loading: loading_dense,
        unloading: unloading.dense,
        t_switch,
        y_switch,
        t_end: unloading.t,
        y_end: unloading.y,
        unloading_scales: usc,
        end,
        stats,
        force_evals,
        rtol: ro.rtol,
    })
}
