//! Continuous output of an integration: one polynomial segment per accepted step.

use super::State;

/// The interpolant of one step over [t0, t0 + h].
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
}

impl Segment {
    pub fn t_start(&self) -> f64 {
        match self {
            Segment::Hermite { t0, .. } => *t0,
        }
    }

    pub fn t_end(&self) -> f64 {
        match self {
            Segment::Hermite { t0, h, .. } => t0 + h,
        }
    }

    /// The interpolated state at t inside the segment.
    pub fn eval(&self, t: f64) -> State {
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
        }
    }
}

/// The piecewise-polynomial solution of a whole integration.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct DenseOutput {
    segments: Vec<Segment>,
}

impl DenseOutput {
    pub fn new() -> Self {
        Self::default()
    }

    pub fn push(&mut self, segment: Segment) {
        self.segments.push(segment);
    }

    pub fn segments(&self) -> &[Segment] {
        &self.segments
    }

    /// Keeps the solution up to t (the located event) and drops what lies beyond.
    pub fn truncate_at(&mut self, t: f64) {
        self.segments.retain(|s| s.t_start() < t);
    }

    pub fn t_start(&self) -> f64 {
        self.segments.first().map_or(0.0, Segment::t_start)
    }

    pub fn t_end(&self) -> f64 {
        self.segments.last().map_or(0.0, Segment::t_end)
    }

    /// The state at t, clamped to the covered interval; segments are found by binary search.
    pub fn eval(&self, t: f64) -> State {
        let Some(last) = self.segments.last() else {
            return State::zeros();
        };
        let i = self.segments.partition_point(|s| s.t_end() < t);
        self.segments.get(i).unwrap_or(last).eval(t)
    }
}
