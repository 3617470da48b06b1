//! What the compliant solver needs of a system: the body's acceleration out of contact and the
//! motion of each stop. The system module's models implement it; the solver is generic over it
//! (monomorphised, no boxing in the hot loop).

/// A stop at time t: where it is, how it moves, and which side of it the body lives on.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StopMotion {
    /// +1: the body stays above the stop (gap = x − s); −1: below it (gap = s − x).
    pub side: f64,
    /// Position s, m.
    pub s: f64,
    /// Velocity ṡ, m/s.
    pub sd: f64,
    /// Acceleration s̈, m/s².
    pub sdd: f64,
}

impl StopMotion {
    /// The gap side·(x − s), m: positive out of contact.
    #[inline]
    pub fn gap(&self, x: f64) -> f64 {
        self.side * (x - self.s)
    }

    /// The approach δ = −gap and its rate δ̇ of a body at (x, v): the law's x and ẋ.
    #[inline]
    pub fn approach(&self, x: f64, v: f64) -> (f64, f64) {
        (self.side * (self.s - x), self.side * (self.sd - v))
    }

    /// The body's (x, v) at approach δ and rate δ̇ (the inverse of [`StopMotion::approach`]).
    #[inline]
    pub fn body(&self, d: f64, dd: f64) -> (f64, f64) {
        (self.s - self.side * d, self.sd - self.side * dd)
    }
}

/// A one-degree-of-freedom body between moving or fixed stops, SI units.
pub trait Plant: Sync {
    /// The body's mass m, kg.
    fn mass(&self) -> f64;

    /// The body's acceleration out of contact at (t, x, v), m/s².
    fn free_accel(&self, t: f64, x: f64, v: f64) -> f64;

    /// How many stops there are.
    fn stop_count(&self) -> usize;

    /// Stop `i` at time t.
    fn stop(&self, i: usize, t: f64) -> StopMotion;

    /// The forcing period T, s: the scale of flight steps and of the verdict's t_c/T.
    fn period(&self) -> f64;

    /// A typical size of the accelerations acting out of contact (g, A·ω², F/m), m/s²: what
    /// sets the static deflection a slow contact settles to.
    fn accel_scale(&self) -> f64;
}
