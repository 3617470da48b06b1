//! Continuous output of an integration: one polynomial segment per accepted step.
//!
//! Every variant stores the exact end states of its step so that evaluation at a step point returns
//! the integrator's own value bit for bit (the polynomial forms alone would be off by an ulp).

use super::State;

/// The interpolant of one step over [t0, t0 + h].
///
/// Variants are stored inline (no boxing) so that pushing a segment never allocates beyond the
/// vector's growth; the largest variant (DOP853) is 18 floats.
#[derive(Debug, Clone, PartialEq)]
pub enum Segment {
    /// Cubic Hermite interpolant from the end states and their derivatives (fixed-step methods).
    Hermite {
        t0: f64,
        h: f64,
        y0: State,
        y1: State,
        f0: State,
        f1: State,
    },
    /// DOPRI5's 4th-order continuous extension (Hairer–Nørsett–Wanner I, §II.6; Hairer's CONTD5):
    /// y(s) = y0 + s·(Δ + (1−s)·(r3 + s·(r4 + (1−s)·r5))), Δ = y1 − y0, s = (t − t0)/h.
    Dopri5 {
        t0: f64,
        h: f64,
        y0: State,
        y1: State,
        r3: State,
        r4: State,
        r5: State,
    },
    /// DOP853's 7th-order continuous extension (Hairer's CONTD8): nested in s and 1−s like
    /// [`Segment::Dopri5`] with six coefficient vectors r3…r8.
    Dop853 {
        t0: f64,
        h: f64,
        y0: State,
        y1: State,
        r: [State; 6],
    },
    /// Radau IIA collocation polynomial of the step (Hairer's CONTR5), written from the step end:
    /// y(s) = y1 + s·(c1 + (s − c₂ + 1)·(c2 + (s − c₁ + 1)·c3)), s = (t − t0 − h)/h ∈ [−1, 0].
    Radau5 {
        t0: f64,
        h: f64,
        y0: State,
        y1: State,
        c: [State; 3],
    },
}

impl Segment {
    pub fn t_start(&self) -> f64 {
        match self {
            Segment::Hermite { t0, .. }
            | Segment::Dopri5 { t0, .. }
            | Segment::Dop853 { t0, .. }
            | Segment::Radau5 { t0, .. } => *t0,
        }
    }

    pub fn t_end(&self) -> f64 {
        match self {
            Segment::Hermite { t0, h, .. }
            | Segment::Dopri5 { t0, h, .. }
            | Segment::Dop853 { t0, h, .. }
            | Segment::Radau5 { t0, h, .. } => t0 + h,
        }
    }

    /// The state at the start of the step.
    pub fn y_start(&self) -> State {
        match self {
            Segment::Hermite { y0, .. }
            | Segment::Dopri5 { y0, .. }
            | Segment::Dop853 { y0, .. }
            | Segment::Radau5 { y0, .. } => *y0,
        }
    }

    /// The state at the end of the step (the integrator's accepted value).
    pub fn y_end(&self) -> State {
        match self {
            Segment::Hermite { y1, .. }
            | Segment::Dopri5 { y1, .. }
            | Segment::Dop853 { y1, .. }
            | Segment::Radau5 { y1, .. } => *y1,
        }
    }

    /// The same interpolant moved by `dy`: every form here is an end state plus terms that vanish
    /// with the state's differences, so adding `dy` to the stored end states shifts it exactly.
    pub fn shift(&mut self, dy: State) {
        match self {
            Segment::Hermite { y0, y1, .. }
            | Segment::Dopri5 { y0, y1, .. }
            | Segment::Dop853 { y0, y1, .. }
            | Segment::Radau5 { y0, y1, .. } => {
                *y0 += dy;
                *y1 += dy;
            }
        }
    }

    /// The interpolated state at t inside the segment; t outside is clamped to the segment, and
    /// the step ends return the stored states exactly.
    pub fn eval(&self, t: f64) -> State {
        let t_start = self.t_start();
        if t <= t_start {
            return self.y_start();
        }
        if t >= self.t_end() {
            return self.y_end();
        }
        match self {
            Segment::Hermite {
                t0,
                h,
                y0,
                y1,
                f0,
                f1,
            } => {
                let s = (t - t0) / h;
                let s2 = s * s;
                let s3 = s2 * s;
                let h00 = 2.0 * s3 - 3.0 * s2 + 1.0;
                let h10 = s3 - 2.0 * s2 + s;
                let h01 = -2.0 * s3 + 3.0 * s2;
                let h11 = s3 - s2;
                y0 * h00 + f0 * (h10 * h) + y1 * h01 + f1 * (h11 * h)
            }
            Segment::Dopri5 {
                t0,
                h,
                y0,
                y1,
                r3,
                r4,
                r5,
            } => {
                let s = (t - t0) / h;
                let s1 = 1.0 - s;
                y0 + ((y1 - y0) + (r3 + (r4 + r5 * s1) * s) * s1) * s
            }
            Segment::Dop853 { t0, h, y0, y1, r } => {
                let s = (t - t0) / h;
                let s1 = 1.0 - s;
                let inner = r[4] + r[5] * s;
                let inner = r[3] + inner * s1;
                let inner = r[2] + inner * s;
                let inner = r[1] + inner * s1;
                let inner = r[0] + inner * s;
                y0 + ((y1 - y0) + inner * s1) * s
            }
            Segment::Radau5 { t0, h, y1, c, .. } => {
                let s = (t - (t0 + h)) / h;
                let (c1m1, c2m1) = super::radau5::C1M1_C2M1;
                y1 + (c[0] + (c[1] + c[2] * (s - c1m1)) * (s - c2m1)) * s
            }
        }
    }
}

/// The end slopes of a cubic Hermite step, limited so that it stays monotone in every component
/// whose data are (Fritsch & Carlson, SIAM J. Numer. Anal. 17, 1980: α² + β² ≤ 9 with α, β the
/// end slopes over the secant). A fixed step near its stability bound spans much of the impact:
/// an unlimited cubic from x = 0 at ẋ = v₀ to a step point then overshoots every step value (4.19
/// against an x_max of 3.91 µm at the RK4 critical step on Fig. 5), a maximum the method never
/// computed. Resolved steps, whose slopes are near the secant, are left as they are; a component
/// that turns inside the step (slopes of opposite signs) too, unless `no_turn` says the data are
/// monotone by construction (a step cut at an event), where a slope against the secant is set to
/// 0 (Fritsch & Carlson's first rule).
pub(super) fn monotone_slopes(
    h: f64,
    (y0, y1): (&State, &State),
    (f0, f1): (State, State),
    no_turn: bool,
) -> (State, State) {
    let (mut f0, mut f1) = (f0, f1);
    for i in 0..f0.len() {
        let secant = (y1[i] - y0[i]) / h;
        if secant == 0.0 || !secant.is_finite() {
            continue;
        }
        if no_turn {
            f0[i] = if f0[i] / secant < 0.0 { 0.0 } else { f0[i] };
            f1[i] = if f1[i] / secant < 0.0 { 0.0 } else { f1[i] };
        }
        let (alpha, beta) = (f0[i] / secant, f1[i] / secant);
        let radius = alpha.hypot(beta);
        if alpha >= 0.0 && beta >= 0.0 && radius > 3.0 {
            let tau = 3.0 / radius;
            f0[i] *= tau;
            f1[i] *= tau;
        }
    }
    (f0, f1)
}

impl Segment {
    /// A fixed step's cubic refitted to end at an event (t, y) inside the step with the slope f
    /// there, its slopes limited as `monotone_slopes` does; `None` for the other forms, which
    /// are cut at the event as they are. Cut instead, the step's cubic keeps the slope it had at
    /// the step's far end and can peak before the event: the approach rose to 4.53 µm before a
    /// maximum compression at 4.40 µm (elastic Hertz, the RK4 critical step, Fig. 5).
    pub fn hermite_ending_at(&self, t: f64, y: State, f: State) -> Option<Segment> {
        match *self {
            Segment::Hermite { t0, y0, f0, .. } if t > t0 => {
                let h = t - t0;
                // The event ends the step's motion in this phase: no turn inside it.
                let (f0, f1) = monotone_slopes(h, (&y0, &y), (f0, f), true);
                Some(Segment::Hermite {
                    t0,
                    h,
                    y0,
                    y1: y,
                    f0,
                    f1,
                })
            }
            _ => None,
        }
    }
}

/// The piecewise-polynomial solution of a whole integration.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct DenseOutput {
    segments: Vec<Segment>,
    /// End of the covered interval: the last segment's end, or the located event / `t_max` after
    /// [`DenseOutput::truncate_at`] (the last segment may extend beyond it), or a little beyond
    /// the last segment after [`DenseOutput::end_with`].
    end: f64,
    /// The state at `end` when it is not the last segment's value there: an event's landed state
    /// after its last glide (`ode::integrate`).
    end_state: Option<State>,
}

impl DenseOutput {
    pub fn new() -> Self {
        Self::default()
    }

    /// An empty output with room for `n` segments (integrators reserve to avoid regrowth).
    pub fn with_capacity(n: usize) -> Self {
        DenseOutput {
            segments: Vec::with_capacity(n),
            end: 0.0,
            end_state: None,
        }
    }

    pub fn push(&mut self, segment: Segment) {
        self.end = segment.t_end();
        self.end_state = None;
        self.segments.push(segment);
    }

    /// Appends `other`'s segments, and its end: a continuation of this output from where it ends.
    pub fn append(&mut self, other: &DenseOutput) {
        for segment in other.segments() {
            self.push(segment.clone());
        }
        if !other.is_empty() {
            self.end = other.end;
            self.end_state = other.end_state;
        }
    }

    /// Ends the solution at (t, y), t within rounding of the last segment's covered interval or
    /// a few local errors beyond it: an event's state, moved onto the event by a glide from the
    /// landed step's end. Evaluation at or after t returns y exactly; before t, the segments.
    pub fn end_with(&mut self, t: f64, y: State) {
        self.segments.retain(|s| s.t_start() < t);
        if !self.segments.is_empty() {
            self.end = t;
            self.end_state = Some(y);
        }
    }

    pub fn segments(&self) -> &[Segment] {
        &self.segments
    }

    pub fn len(&self) -> usize {
        self.segments.len()
    }

    pub fn is_empty(&self) -> bool {
        self.segments.is_empty()
    }

    /// The whole solution moved by `dy` (an integration done in shifted coordinates).
    pub fn shift(&mut self, dy: State) {
        for segment in &mut self.segments {
            segment.shift(dy);
        }
        if let Some(y) = &mut self.end_state {
            *y += dy;
        }
    }

    /// Keeps the solution up to t (the located event) and drops what lies beyond; the covered
    /// interval then ends exactly at t.
    pub fn truncate_at(&mut self, t: f64) {
        self.segments.retain(|s| s.t_start() < t);
        self.end_state = None;
        self.end = match self.segments.last() {
            Some(last) => t.min(last.t_end()),
            None => 0.0,
        };
    }

    pub fn t_start(&self) -> f64 {
        self.segments.first().map_or(0.0, Segment::t_start)
    }

    pub fn t_end(&self) -> f64 {
        if self.segments.is_empty() {
            0.0
        } else {
            self.end
        }
    }

    /// The state at t, clamped to the covered interval; segments are found by binary search, and
    /// step points return the integrator's accepted states exactly.
    pub fn eval(&self, t: f64) -> State {
        self.eval_from(t, &mut None)
    }

    /// [`DenseOutput::eval`] for times visited in increasing order: `at` is the segment the
    /// previous time was found on (`None` before the first), from which the walk goes on instead
    /// of searching all segments again; it is left on this time's segment.
    pub fn eval_from(&self, t: f64, at: &mut Option<usize>) -> State {
        let Some(last) = self.segments.last() else {
            return State::zeros();
        };
        if let Some(y) = self.end_state
            && t >= self.end
        {
            return y;
        }
        // max/min rather than clamp: never panics, even for hand-pushed segments out of order.
        let t = t.max(self.t_start()).min(self.end);
        let i = match *at {
            None => self.segments.partition_point(|s| s.t_end() < t),
            Some(mut i) => {
                while self.segments.get(i).is_some_and(|s| s.t_end() < t) {
                    i += 1;
                }
                i
            }
        };
        *at = Some(i);
        self.segments.get(i).unwrap_or(last).eval(t)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn line(t0: f64, h: f64, a: f64) -> Segment {
        // y = (a·t, a): a straight line is reproduced exactly by the Hermite cubic.
        Segment::Hermite {
            t0,
            h,
            y0: State::new(a * t0, a),
            y1: State::new(a * (t0 + h), a),
            f0: State::new(a, 0.0),
            f1: State::new(a, 0.0),
        }
    }

    #[test]
    fn eval_finds_the_segment_and_clamps() {
        let mut d = DenseOutput::with_capacity(3);
        d.push(line(0.0, 1.0, 2.0));
        d.push(line(1.0, 1.0, 2.0));
        d.push(line(2.0, 0.5, 2.0));
        assert_eq!(d.t_end(), 2.5);
        for &t in &[0.0, 0.3, 1.0, 1.7, 2.0, 2.25, 2.5] {
            assert!((d.eval(t)[0] - 2.0 * t).abs() < 1e-15, "t = {t}");
        }
        // Clamped outside [t_start, t_end].
        assert_eq!(d.eval(-1.0)[0], 0.0);
        assert_eq!(d.eval(9.0)[0], 5.0);
    }

    #[test]
    fn truncation_moves_the_end_inside_the_last_segment() {
        let mut d = DenseOutput::new();
        d.push(line(0.0, 1.0, 1.0));
        d.push(line(1.0, 1.0, 1.0));
        d.push(line(2.0, 1.0, 1.0));
        d.truncate_at(1.25);
        assert_eq!(d.len(), 2);
        assert_eq!(d.t_end(), 1.25);
        assert!((d.eval(2.5)[0] - 1.25).abs() < 1e-15);
    }

    #[test]
    fn out_of_order_segments_do_not_panic() {
        // A caller may push segments by hand; evaluation must stay total.
        let mut d = DenseOutput::new();
        d.push(line(5.0, 1.0, 1.0));
        d.push(line(0.0, 1.0, 1.0));
        assert!(d.eval(3.0)[0].is_finite());
        // A NaN time must not panic either (the result is meaningless and not checked).
        let _ = d.eval(f64::NAN);
        d.truncate_at(-1.0);
        assert!(d.is_empty());
        assert_eq!(d.eval(0.5), State::zeros());
    }

    #[test]
    fn step_points_are_exact() {
        // A Hermite segment with data that is not a cubic: the end values still come back bit for bit.
        let s = Segment::Hermite {
            t0: 0.1,
            h: 0.7,
            y0: State::new(0.3, -1.1),
            y1: State::new(1.0 / 3.0, 2.0f64.sqrt()),
            f0: State::new(5.0, 7.0),
            f1: State::new(-3.0, 11.0),
        };
        assert_eq!(s.eval(0.1), State::new(0.3, -1.1));
        assert_eq!(s.eval(0.1 + 0.7), State::new(1.0 / 3.0, 2.0f64.sqrt()));
    }

    #[test]
    fn an_end_state_is_returned_exactly_at_and_after_the_end() {
        let mut d = DenseOutput::new();
        d.push(line(0.0, 1.0, 2.0));
        // A glide a little past the segment, then one back inside it.
        let past = State::new(2.0 + 1e-9, 2.0);
        d.end_with(1.0 + 5e-10, past);
        assert_eq!(d.t_end(), 1.0 + 5e-10);
        assert_eq!(d.eval(d.t_end()), past);
        assert_eq!(d.eval(7.0), past);
        // Inside, the segment as it was.
        assert!((d.eval(0.5) - State::new(1.0, 2.0)).norm() < 1e-15);
        let inside = State::new(1.5, 2.0);
        d.end_with(0.75, inside);
        assert_eq!((d.t_end(), d.eval(0.75)), (0.75, inside));
        // Shifted with the rest; appended to another output it stays its end; a push ends it.
        d.shift(State::new(1.0, 0.0));
        assert_eq!(d.eval(0.75), State::new(2.5, 2.0));
        let mut whole = DenseOutput::new();
        whole.push(line(-1.0, 1.0, 2.0));
        whole.append(&d);
        assert_eq!(
            (whole.t_end(), whole.eval(0.8)),
            (0.75, State::new(2.5, 2.0))
        );
        whole.push(line(0.75, 1.0, 2.0));
        assert_eq!(whole.eval(1.75), State::new(3.5, 2.0));
    }
}
