//! One contact of a compliant stop, from first touch to separation: the approach δ into the stop
//! integrated through the law with the project's integrators (src/model/ode), its turn and its end
//! located as events at the method's full order, its peak force, contact time and energy balance.
//!
//! The contact is integrated in the stop's frame, scaled like the single-impact solver
//! (docs/physics.md §3): X = δ/x_e, V = δ̇/v_s, τ = (t − t₀)·v_s/x_e, with x_e the elastic x_max
//! (eq 5) at v_s, the larger of the impact velocity and the velocity whose x_max is the static
//! deflection under the system's accelerations. Tolerances then mean the same for every stop, and
//! a micrometre indentation is not lost against the metres of the body's absolute position.

use crate::model::force::{ContactEnd, ForceLaw, Phase};
use crate::model::numeric::roots::brent_max;
use crate::model::ode::{
    self, DenseOutput, Direction, Event, Method, OdeError, OdeSystem, Segment, State, Stop,
};
use crate::model::power_law::PowerLaw;

use super::plant::{Plant, StopMotion};

/// Integrator settings of the contacts of one run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactSettings {
    /// An adaptive method of src/model/ode (DOP853 by default).
    pub method: Method,
    /// Relative tolerance in the scaled variables (absolute tolerance the same).
    pub rtol: f64,
    /// Accepted plus rejected steps allowed for one contact.
    pub max_steps: usize,
    /// Keep the dense output of the contact (for drawing); off in bifurcation runs.
    pub keep_dense: bool,
}

/// Gauss–Legendre nodes on [0, 1] and weights (5 points, exact for degree 9) for the energy
/// integrals over each step's interpolant: the integrands carry √δ-type terms near first contact
/// that fewer points resolve to only ~1e-6 of the impact energy.
const GAUSS: [(f64, f64); 5] = [
    (0.046_910_077_030_668, 0.118_463_442_528_094_54),
    (0.230_765_344_947_158_45, 0.239_314_335_249_683_23),
    (0.5, 0.284_444_444_444_444_44),
    (0.769_234_655_052_841_6, 0.239_314_335_249_683_23),
    (0.953_089_922_969_332, 0.118_463_442_528_094_54),
];

/// The energy balance of one impact in the stop's frame, J.
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize)]
pub struct EnergyAudit {
    /// ½·m·v_in².
    pub incoming: f64,
    /// ½·m·v_out² at the law's end of contact.
    pub outgoing: f64,
    /// Work of the forces other than the contact's in the stop's frame (gravity, spring, the
    /// stop's own acceleration) over the contact: ∫ m·side·(s̈ − a)·δ̇ dt.
    pub external_work: f64,
    /// What the contact kept: ∫ (F − k·xⁿ)·δ̇ dt plus the energy the law still stores at the end
    /// (a residual indentation), by Gauss–Legendre quadrature on the integrator's interpolant.
    pub absorbed: f64,
}

impl EnergyAudit {
    /// The energy the body lost to the stop: ½m(v_in² − v_out²) + external work.
    pub fn lost(&self) -> f64 {
        self.incoming - self.outgoing + self.external_work
    }

    /// |lost − absorbed| over ½·m·v_in²: how well the integration closes the balance.
    /// Relative to the largest of the energies involved (a contact begun at rest has no incoming
    /// energy).
    pub fn closure(&self) -> f64 {
        let scale = self
            .incoming
            .max(self.outgoing)
            .max(self.external_work.abs())
            .max(self.absorbed.abs())
            .max(f64::MIN_POSITIVE);
        (self.lost() - self.absorbed).abs() / scale
    }
}

/// Where the body is when the contact's excursion is over.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Exit {
    /// Back on the stop's surface (δ = 0) at time t, moving away with body state (x, v).
    Free { t: f64, x: f64, v: f64 },
    /// Still in contact when the time limit came.
    Held { t: f64, x: f64, v: f64 },
}

/// One integrated piece of a contact, kept for drawing: its dense output in scaled variables.
#[derive(Debug, Clone)]
pub struct ContactPiece {
    pub dense: DenseOutput,
    pub scale: Scale,
    /// Whether the law's force acts (false in a residual excursion after the law let go).
    pub force_on: bool,
}

/// The scaled variables of a contact (see the module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Scale {
    /// t₀, s.
    pub t0: f64,
    /// x_e/v_s, s.
    pub t: f64,
    /// x_e, m.
    pub x: f64,
    /// v_s, m/s.
    pub v: f64,
    pub stop: usize,
}

impl Scale {
    /// Absolute time at scaled time τ.
    pub fn time(&self, tau: f64) -> f64 {
        self.t0 + tau * self.t
    }

    /// The body's (x, v) at scaled time τ and scaled state y.
    pub fn body<P: Plant>(&self, plant: &P, tau: f64, y: &State) -> (f64, f64) {
        plant
            .stop(self.stop, self.time(tau))
            .body(y[0] * self.x, y[1] * self.v)
    }
}

/// One contact's result.
#[derive(Debug, Clone)]
pub struct ContactResult {
    pub stop: usize,
    pub t_start: f64,
    pub v_in: f64,
    /// Time the law's contact ended (x = 0, F = 0 or the compressive-only cutoff), s.
    pub t_end: f64,
    /// Separating velocity −δ̇ there, m/s.
    pub v_out: f64,
    /// δ there, m (0 unless the law let go at F = 0).
    pub residual: f64,
    /// The residual is a permanent (plastic) dent ([`ForceLaw::residual_is_permanent`]), which
    /// the stop does not carry into its next contact (docs/compliant.md §1).
    pub permanent: bool,
    pub peak_force: f64,
    pub t_peak: f64,
    pub max_approach: f64,
    pub energy: EnergyAudit,
    /// ∫ side·(s̈ − a) dt over the contact, m/s: the impulse per unit mass with which the
    /// system's forces pressed the body into the stop while the law's force acted. Against the
    /// speed the contact reversed, v_in + v_out, it tells an impact from a resting phase
    /// ([`ContactResult::is_rest`]).
    pub pressing_impulse: f64,
    pub exit: Exit,
    /// The law's force evaluations, the floor of a contact's cost.
    pub force_evals: usize,
    pub steps: usize,
    pub pieces: Vec<ContactPiece>,
}

impl ContactResult {
    pub fn contact_time(&self) -> f64 {
        self.t_end - self.t_start
    }

    /// Whether the body came to rest on the stop rather than bounced: the contact never ended,
    /// or the system's forces pressed it in with more impulse than the contact spent reversing
    /// its motion (v_in + v_out), so that most of the contact force's impulse, v_in + v_out + J,
    /// held the body against them (docs/compliant.md §3). A free impact of any law of the table
    /// is the other way round by orders of magnitude when its contact is short against the
    /// system's motion.
    pub fn is_rest(&self) -> bool {
        matches!(self.exit, Exit::Held { .. }) || self.pressing_impulse > self.v_in + self.v_out
    }
}

/// Why a contact could not be integrated.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ContactError {
    #[error("contact at t = {t:.6e} s with the stop {stop}: {source}")]
    Integration {
        t: f64,
        stop: usize,
        #[source]
        source: OdeError,
    },
}

/// The contact's right-hand side in scaled variables: δ̈ = side·(s̈ − a_free(t, x, v)) − F/m.
struct ContactOde<'a, P, L> {
    plant: &'a P,
    law: L,
    phase: Phase,
    scale: Scale,
    inv_mass: f64,
    force_on: bool,
    evals: usize,
}

impl<P: Plant, L: ForceLaw> ContactOde<'_, P, L> {
    /// δ̈ at scaled (τ, y), m/s², and the stop's motion there.
    #[inline]
    fn relative_accel(&mut self, tau: f64, y: &State) -> (f64, StopMotion, f64, f64) {
        let sc = &self.scale;
        let t = sc.time(tau);
        let (d, dd) = (y[0] * sc.x, y[1] * sc.v);
        let stop = self.plant.stop(sc.stop, t);
        let (x, v) = stop.body(d, dd);
        let a = self.plant.free_accel(t, x, v);
        let f = if self.force_on {
            self.evals += 1;
            self.law.phase_force(d, dd, self.phase)
        } else {
            0.0
        };
        (stop.side * (stop.sdd - a) - f * self.inv_mass, stop, a, f)
    }
}

impl<P: Plant, L: ForceLaw> OdeSystem for ContactOde<'_, P, L> {
    #[inline]
    fn rhs(&mut self, tau: f64, y: &State) -> State {
        let (ddd, ..) = self.relative_accel(tau, y);
        State::new(y[1], ddd * self.scale.t / self.scale.v)
    }
}

/// What ended one integrated piece.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum PieceEnd {
    /// δ fell to 0.
    Approach,
    /// The law's force fell to 0 at δ > 0 (its own end, or the compressive-only cutoff).
    Tension,
    /// δ̇ changed sign (a phase switch of a law that has phases).
    Turn,
    /// The law's force turned compressive again while the body was still inside (residual).
    Recontact,
    TimeLimit,
}

/// Integrates one contact of `plant` with stop `stop`, starting at t₀ with incoming velocity
/// v_in ≥ 0 (δ = 0, δ̇ = v_in), with `law` (built for this impact), until the body is back on
/// the stop's surface or `t_limit`.
#[allow(clippy::too_many_arguments)]
pub fn integrate_contact<P: Plant, L: ForceLaw>(
    plant: &P,
    law: &L,
    elastic: PowerLaw,
    stop: usize,
    t0: f64,
    v_in: f64,
    t_limit: f64,
    settings: &ContactSettings,
) -> Result<ContactResult, ContactError> {
    let mass = plant.mass();
    // The velocity whose elastic x_max is the static deflection under the plant's accelerations:
    // slow contacts (chatter, resting) are scaled by it, not by a vanishing v_in.
    let x_static = (mass * plant.accel_scale() / elastic.k).powf(1.0 / elastic.n);
    let v_static = (2.0 * elastic.energy(x_static) / mass).sqrt();
    let v_s = v_in.max(v_static).max(f64::MIN_POSITIVE.sqrt());
    let x_e = elastic.max_approach(mass, v_s);
    let scale = Scale {
        t0,
        t: x_e / v_s,
        x: x_e,
        v: v_s,
        stop,
    };
    let t_contact = elastic.contact_time(mass, v_s) / scale.t;
    let phased = law.switches_at_max_compression() || law.rate_independent();
    let watch_tension = law.may_turn_tensile() || law.contact_end() == ContactEnd::ForceZero;

    let mut ode_sys = ContactOde {
        plant,
        law: *law,
        phase: Phase::Loading,
        scale,
        inv_mass: 1.0 / mass,
        force_on: true,
        evals: 0,
    };
    let tau_limit = (t_limit - t0) / scale.t;
    // A touch with no approach speed while the stop pulls away (or the body is pulled off it) is
    // no contact: it ends where it began.
    if v_in == 0.0 {
        let (ddd, stop_now, ..) = ode_sys.relative_accel(0.0, &State::zeros());
        if ddd <= 0.0 {
            let (x, v) = stop_now.body(0.0, 0.0);
            let mut totals = Totals::new(mass, scale, v_in);
            totals.law_end = Some((0.0, State::zeros()));
            return Ok(totals.finish(Exit::Free { t: t0, x, v }));
        }
    }
    let mut tau = 0.0;
    let mut y = State::new(0.0, v_in / v_s);
    let mut totals = Totals::new(mass, scale, v_in);
    let mut h_initial = None;
    let mut pending_work = 0.0;
    let fail = |tau: f64, source| ContactError::Integration {
        t: scale.time(tau),
        stop,
        source,
    };
    loop {
        if tau >= tau_limit {
            let (x, v) = scale.body(plant, tau, &y);
            let t = scale.time(tau);
            return Ok(totals.finish(Exit::Held { t, x, v }));
        }
        let phase = ode_sys.phase;
        let law_now = ode_sys.law;
        let approach = |_: f64, y: &State| y[0];
        let tension = |_: f64, y: &State| law_now.tension(y[0] * scale.x, y[1] * scale.v);
        let turn = |_: f64, y: &State| y[1];
        let (piece_end, integration) = if ode_sys.force_on {
            let mut events = vec![Event {
                g: &approach,
                direction: Direction::Falling,
            }];
            let mut kinds = vec![PieceEnd::Approach];
            if watch_tension {
                events.push(Event {
                    g: &tension,
                    direction: Direction::Falling,
                });
                kinds.push(PieceEnd::Tension);
            }
            if phased {
                events.push(Event {
                    g: &turn,
                    direction: match phase {
                        Phase::Loading => Direction::Falling,
                        Phase::Unloading => Direction::Rising,
                    },
                });
                kinds.push(PieceEnd::Turn);
            }
            let opts = options(settings, tau, tau_limit, t_contact, h_initial);
            let run = ode::integrate(settings.method, &mut ode_sys, tau, y, &events, &opts)
                .map_err(|e| fail(tau, e))?;
            let end = match run.stop {
                Stop::TimeLimit => PieceEnd::TimeLimit,
                Stop::Event { index } => kinds[index],
            };
            (end, run)
        } else {
            // A residual excursion: the law let go with the body still inside. It leaves at
            // δ = 0 or the law's force turns compressive again.
            let events = [
                Event {
                    g: &approach,
                    direction: Direction::Falling,
                },
                Event {
                    g: &tension,
                    direction: Direction::Rising,
                },
            ];
            let opts = options(settings, tau, tau_limit, t_contact, h_initial);
            let run = ode::integrate(settings.method, &mut ode_sys, tau, y, &events, &opts)
                .map_err(|e| fail(tau, e))?;
            let end = match run.stop {
                Stop::TimeLimit => PieceEnd::TimeLimit,
                Stop::Event { index: 0 } => PieceEnd::Approach,
                Stop::Event { .. } => PieceEnd::Recontact,
            };
            (end, run)
        };
        totals.steps += integration.stats.steps + integration.stats.rejected_steps;
        totals.force_evals = ode_sys.evals;
        if totals.steps > settings.max_steps {
            return Err(fail(
                integration.t,
                OdeError::StepBudgetExhausted {
                    t: scale.time(integration.t),
                    steps: totals.steps,
                },
            ));
        }
        let segments = integration.dense.segments();
        h_initial = segments
            .iter()
            .rev()
            .take(2)
            .map(|s| s.t_end() - s.t_start())
            .reduce(f64::max);
        if ode_sys.force_on {
            let (piece_peak, piece_max) = extremes(&ode_sys, segments, integration.t, scale);
            if piece_peak.0 > totals.peak.0 {
                totals.peak = piece_peak;
            }
            totals.max_approach = totals.max_approach.max(piece_max);
            let (work, dissipated, impulse) =
                energy_integrals(&mut ode_sys, segments, integration.t);
            totals.energy.external_work += work;
            totals.energy.absorbed += dissipated;
            totals.pressing_impulse += impulse;
        } else {
            // Free motion inside: only the external forces work, and that counts towards this
            // impact only if the law takes up the contact again.
            let (work, ..) = energy_integrals(&mut ode_sys, segments, integration.t);
            pending_work += work;
        }
        let (tau_end, y_end) = (integration.t, integration.y);
        if settings.keep_dense {
            let mut dense = integration.dense;
            dense.truncate_at(tau_end);
            totals.pieces.push(ContactPiece {
                dense,
                scale,
                force_on: ode_sys.force_on,
            });
        }
        tau = tau_end;
        y = y_end;
        match piece_end {
            PieceEnd::Approach => {
                if ode_sys.force_on {
                    totals.law_end = Some((tau, State::new(0.0, y[1])));
                }
                // Exactly on the surface, so that the flight starts from a gap of exactly 0.
                let t = scale.time(tau);
                let stop_now = plant.stop(stop, t);
                let (x, v) = stop_now.body(0.0, y[1] * scale.v);
                return Ok(totals.finish(Exit::Free { t, x, v }));
            }
            PieceEnd::Tension => {
                totals.law_end = Some((tau, y));
                totals.permanent = law_now.residual_is_permanent();
                let d = y[0] * scale.x;
                totals.energy.absorbed += law_now.stored_energy(d, phase);
                ode_sys.force_on = false;
            }
            PieceEnd::Recontact => {
                // The excursion is part of the same impact: its energy bookkeeping restarts from
                // the state the law takes up again.
                let d = y[0] * scale.x;
                totals.energy.absorbed -= law_now.stored_energy(d, phase);
                totals.energy.external_work += std::mem::take(&mut pending_work);
                ode_sys.force_on = true;
                ode_sys.phase = Phase::of_velocity(y[1]);
                totals.law_end = None;
                totals.permanent = false;
            }
            PieceEnd::Turn => {
                y[1] = 0.0;
                if phase == Phase::Loading {
                    ode_sys.law = law_now.unloading_at_turn(y[0] * scale.x);
                    ode_sys.phase = Phase::Unloading;
                } else {
                    ode_sys.phase = Phase::Loading;
                }
            }
            PieceEnd::TimeLimit => {
                let (x, v) = scale.body(plant, tau, &y);
                let t = scale.time(tau);
                return Ok(totals.finish(Exit::Held { t, x, v }));
            }
        }
    }
}

/// Step control of a piece: a quarter of the elastic contact time at most, so that no step leaps
/// over most of a contact.
fn options(
    settings: &ContactSettings,
    tau: f64,
    tau_limit: f64,
    t_contact: f64,
    h_initial: Option<f64>,
) -> ode::Options {
    ode::Options {
        rtol: settings.rtol,
        atol: settings.rtol,
        dt: None,
        h_initial,
        h_max: 0.25 * t_contact,
        t_max: tau_limit.max(tau * (1.0 + f64::EPSILON) + f64::MIN_POSITIVE),
        max_steps: settings.max_steps,
    }
}

/// A contact's running totals, from its first touch to whichever exit ends it.
struct Totals {
    mass: f64,
    scale: Scale,
    v_in: f64,
    /// Where the law let go (scaled time and state), if it did.
    law_end: Option<(f64, State)>,
    /// Peak force, N, and its time, s.
    peak: (f64, f64),
    max_approach: f64,
    energy: EnergyAudit,
    pressing_impulse: f64,
    /// The law let go at F = 0 with a permanent residual.
    permanent: bool,
    force_evals: usize,
    steps: usize,
    pieces: Vec<ContactPiece>,
}

impl Totals {
    fn new(mass: f64, scale: Scale, v_in: f64) -> Totals {
        Totals {
            mass,
            scale,
            v_in,
            law_end: None,
            peak: (0.0, scale.t0),
            max_approach: 0.0,
            energy: EnergyAudit {
                incoming: 0.5 * mass * v_in * v_in,
                ..EnergyAudit::default()
            },
            pressing_impulse: 0.0,
            permanent: false,
            force_evals: 0,
            steps: 0,
            pieces: Vec::new(),
        }
    }

    /// The contact's result once `exit` ends it.
    fn finish(self, exit: Exit) -> ContactResult {
        let scale = self.scale;
        let (t_end, v_out, residual) = match (self.law_end, exit) {
            (Some((tau, y)), _) => (scale.time(tau), -y[1] * scale.v, y[0] * scale.x),
            (None, Exit::Held { t, .. } | Exit::Free { t, .. }) => (t, 0.0, 0.0),
        };
        let mut energy = self.energy;
        energy.outgoing = 0.5 * self.mass * v_out * v_out;
        ContactResult {
            stop: scale.stop,
            t_start: scale.t0,
            v_in: self.v_in,
            t_end,
            v_out,
            residual,
            permanent: self.permanent && residual > 0.0,
            peak_force: self.peak.0,
            t_peak: self.peak.1,
            max_approach: self.max_approach,
            energy,
            pressing_impulse: self.pressing_impulse,
            exit,
            force_evals: self.force_evals,
            steps: self.steps,
            pieces: self.pieces,
        }
    }
}

/// The peak force (value, time) and the largest approach over a piece: the best step end, then
/// refined on the interpolant over its two neighbouring steps (Brent's fmin).
fn extremes<P: Plant, L: ForceLaw>(
    sys: &ContactOde<'_, P, L>,
    segments: &[Segment],
    tau_end: f64,
    scale: Scale,
) -> ((f64, f64), f64) {
    let force = |y: &State| {
        sys.law
            .phase_force(y[0] * scale.x, y[1] * scale.v, sys.phase)
    };
    let mut best_f = (f64::NEG_INFINITY, 0usize);
    let mut best_x = (f64::NEG_INFINITY, 0usize);
    for (i, seg) in segments.iter().enumerate() {
        let y = if seg.t_end() > tau_end {
            seg.eval(tau_end)
        } else {
            seg.y_end()
        };
        let f = force(&y);
        if f > best_f.0 {
            best_f = (f, i);
        }
        if y[0] > best_x.0 {
            best_x = (y[0], i);
        }
    }
    if segments.is_empty() {
        return ((0.0, scale.t0), 0.0);
    }
    let around = |i: usize| {
        let a = segments[i].t_start();
        let b = segments
            .get(i + 1)
            .map_or(segments[i].t_end(), Segment::t_end)
            .min(tau_end);
        (a, b)
    };
    let eval = |tau: f64| {
        let i = segments
            .partition_point(|s| s.t_end() < tau)
            .min(segments.len() - 1);
        segments[i].eval(tau)
    };
    let (a, b) = around(best_f.1);
    let (tau_f, f) = brent_max(|tau| force(&eval(tau)), a, b);
    let (a, b) = around(best_x.1);
    let (_, x) = brent_max(|tau| eval(tau)[0], a, b);
    let f_start = force(&segments[0].y_start());
    let peak = if f_start > f {
        (f_start, scale.time(segments[0].t_start()))
    } else {
        (f, scale.time(tau_f))
    };
    (peak, x.max(0.0) * scale.x)
}

/// ∫ m·side·(s̈ − a)·δ̇ dt (external work, J), ∫ (F − k·xⁿ)·δ̇ dt (the law's dissipative work, J)
/// and ∫ side·(s̈ − a) dt (the pressing impulse per unit mass, m/s) over a piece, by
/// Gauss–Legendre on each step's interpolant.
fn energy_integrals<P: Plant, L: ForceLaw>(
    sys: &mut ContactOde<'_, P, L>,
    segments: &[Segment],
    tau_end: f64,
) -> (f64, f64, f64) {
    let scale = sys.scale;
    let mass = 1.0 / sys.inv_mass;
    let (mut work, mut dissipated, mut impulse) = (0.0, 0.0, 0.0);
    for seg in segments {
        let (a, b) = (seg.t_start(), seg.t_end().min(tau_end));
        if b <= a {
            continue;
        }
        let h = (b - a) * scale.t;
        for (node, weight) in GAUSS {
            let tau = a + node * (b - a);
            let y = seg.eval(tau);
            let (d, dd) = (y[0] * scale.x, y[1] * scale.v);
            let t = scale.time(tau);
            let stop = sys.plant.stop(scale.stop, t);
            let (x, v) = stop.body(d, dd);
            let accel = sys.plant.free_accel(t, x, v);
            let pressing = stop.side * (stop.sdd - accel);
            work += weight * h * mass * pressing * dd;
            impulse += weight * h * pressing;
            if sys.force_on {
                dissipated += weight * h * sys.law.dissipative_force(d, dd, sys.phase) * dd;
            }
        }
    }
    (work, dissipated, impulse)
}
