//! DOPRI5: the Dormand–Prince 5(4) pair with FSAL, Hairer's PI step control and the 4th-order
//! continuous extension — Dormand & Prince 1980 (J. Comput. Appl. Math. 6, 19–26), implemented
//! after Hairer's DOPRI5 code (Hairer–Nørsett–Wanner I, §II.5–II.6).

use super::driver::{Scheme, Step};
use super::step_control::{
    PiController, Rejection, check_budget, error_norm, initial_step, is_finite, rhs,
    underflow_error, underflows,
};
use super::{OdeError, OdeSystem, Options, Segment, State, Stats};

// Nodes and coupling coefficients (Hairer–Nørsett–Wanner I, Table II.5.2).
const C2: f64 = 0.2;
const C3: f64 = 0.3;
const C4: f64 = 0.8;
const C5: f64 = 8.0 / 9.0;
const A21: f64 = 0.2;
const A31: f64 = 3.0 / 40.0;
const A32: f64 = 9.0 / 40.0;
const A41: f64 = 44.0 / 45.0;
const A42: f64 = -56.0 / 15.0;
const A43: f64 = 32.0 / 9.0;
const A51: f64 = 19372.0 / 6561.0;
const A52: f64 = -25360.0 / 2187.0;
const A53: f64 = 64448.0 / 6561.0;
const A54: f64 = -212.0 / 729.0;
const A61: f64 = 9017.0 / 3168.0;
const A62: f64 = -355.0 / 33.0;
const A63: f64 = 46732.0 / 5247.0;
const A64: f64 = 49.0 / 176.0;
const A65: f64 = -5103.0 / 18656.0;
// The 5th-order weights are the last row (FSAL: stage 7 is f at the new point).
const A71: f64 = 35.0 / 384.0;
const A73: f64 = 500.0 / 1113.0;
const A74: f64 = 125.0 / 192.0;
const A75: f64 = -2187.0 / 6784.0;
const A76: f64 = 11.0 / 84.0;
// Error weights b − b̂ (5th minus embedded 4th order).
const E1: f64 = 71.0 / 57600.0;
const E3: f64 = -71.0 / 16695.0;
const E4: f64 = 71.0 / 1920.0;
const E5: f64 = -17253.0 / 339200.0;
const E6: f64 = 22.0 / 525.0;
const E7: f64 = -1.0 / 40.0;
// Dense output (Hairer's DOPRI5, after Shampine 1986).
const D1: f64 = -12715105075.0 / 11282082432.0;
const D3: f64 = 87487479700.0 / 32700410799.0;
const D4: f64 = -10690763975.0 / 1880347072.0;
const D5: f64 = 701980252875.0 / 199316789632.0;
const D6: f64 = -1453857185.0 / 822651844.0;
const D7: f64 = 69997945.0 / 29380423.0;

/// The classical order that Hairer's starting-step heuristic uses for this pair.
const ORDER: u32 = 5;

/// DOPRI5 stepper state (Dormand–Prince 1980, after Hairer's DOPRI5).
pub(super) struct Dopri5 {
    /// f(t, y) at the current point (first stage of the next step, FSAL).
    f: State,
    /// Proposed size of the next attempt.
    h: f64,
    ctrl: PiController,
    /// The previous attempt was rejected (then the step may not grow).
    reject: bool,
    last_rejection: Option<Rejection>,
    rtol: f64,
    atol: f64,
    h_max: f64,
    t_max: f64,
    opts: Options,
}

impl Dopri5 {
    pub(super) fn new(
        sys: &mut dyn OdeSystem,
        stats: &mut Stats,
        t0: f64,
        y0: &State,
        opts: &Options,
    ) -> Result<Self, OdeError> {
        let f = rhs(sys, stats, t0, y0);
        if !is_finite(&f) {
            return Err(OdeError::NonFinite { t: t0 });
        }
        let h_max = opts.h_max.min(opts.t_max - t0);
        let h = match opts.h_initial {
            Some(h) => h.min(h_max),
            None => initial_step(sys, stats, t0, y0, &f, ORDER, opts, h_max),
        };
        Ok(Dopri5 {
            f,
            h,
            ctrl: PiController::dopri5(),
            reject: false,
            last_rejection: None,
            rtol: opts.rtol,
            atol: opts.atol,
            h_max,
            t_max: opts.t_max,
            opts: *opts,
        })
    }

    fn reject(&mut self, stats: &mut Stats, h_next: f64, why: Rejection) {
        stats.rejected_steps += 1;
        self.h = h_next;
        self.reject = true;
        self.last_rejection = Some(why);
    }
}

impl Scheme for Dopri5 {
    fn step(
        &mut self,
        sys: &mut dyn OdeSystem,
        t: f64,
        y: &State,
        stats: &mut Stats,
    ) -> Result<Step, OdeError> {
        loop {
            check_budget(stats, &self.opts, t)?;
            let mut h = self.h.min(self.h_max);
            // Stretch the step onto t_max rather than leave a sliver (Hairer's 1.01 rule).
            let last = t + 1.01 * h >= self.t_max;
            if last {
                h = self.t_max - t;
            }
            if underflows(h, t) {
                return Err(underflow_error(self.last_rejection, t, h));
            }
            let t_new = if last { self.t_max } else { t + h };

            let k1 = self.f;
            let k2 = rhs(sys, stats, t + C2 * h, &(y + k1 * (h * A21)));
            let k3 = rhs(sys, stats, t + C3 * h, &(y + (k1 * A31 + k2 * A32) * h));
            let k4 = rhs(
                sys,
                stats,
                t + C4 * h,
                &(y + (k1 * A41 + k2 * A42 + k3 * A43) * h),
            );
            let k5 = rhs(
                sys,
                stats,
                t + C5 * h,
                &(y + (k1 * A51 + k2 * A52 + k3 * A53 + k4 * A54) * h),
            );
            let k6 = rhs(
                sys,
                stats,
                t_new,
                &(y + (k1 * A61 + k2 * A62 + k3 * A63 + k4 * A64 + k5 * A65) * h),
            );
            let y_new = y + (k1 * A71 + k3 * A73 + k4 * A74 + k5 * A75 + k6 * A76) * h;
            let k7 = rhs(sys, stats, t_new, &y_new);
            if !(is_finite(&y_new) && is_finite(&k7)) {
                // A stage left the domain of f (or overflowed): retry much shorter.
                self.reject(stats, 0.2 * h, Rejection::NonFinite);
                continue;
            }
            let e = (k1 * E1 + k3 * E3 + k4 * E4 + k5 * E5 + k6 * E6 + k7 * E7) * h;
            let err = error_norm(&e, y, &y_new, self.atol, self.rtol);
            if !err.is_finite() {
                self.reject(stats, 0.2 * h, Rejection::NonFinite);
                continue;
            }
            if err > 1.0 {
                let h_next = self.ctrl.rejected(err, h);
                self.reject(stats, h_next, Rejection::Error);
                continue;
            }

            stats.steps += 1;
            self.h = self.ctrl.accepted(err, h, self.h_max, self.reject);
            self.reject = false;
            self.last_rejection = None;
            self.f = k7;
            let ydiff = y_new - y;
            let r3 = k1 * h - ydiff;
            let r4 = ydiff - k7 * h - r3;
            let r5 = (k1 * D1 + k3 * D3 + k4 * D4 + k5 * D5 + k6 * D6 + k7 * D7) * h;
            return Ok(Step {
                t: t_new,
                y: y_new,
                segment: Segment::Dopri5 {
                    t0: t,
                    h,
                    y0: *y,
                    y1: y_new,
                    r3,
                    r4,
                    r5,
                },
            });
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    // Order conditions up to order 5 for the 5th-order weights (the last row of A), and the
    // row-sum condition c_i = Σ_j a_ij: a wrong digit in a coefficient fails one of these.
    #[test]
    fn tableau_satisfies_its_order_conditions() {
        let c = [0.0, C2, C3, C4, C5, 1.0, 1.0];
        let a: [[f64; 7]; 7] = [
            [0.0; 7],
            [A21, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
            [A31, A32, 0.0, 0.0, 0.0, 0.0, 0.0],
            [A41, A42, A43, 0.0, 0.0, 0.0, 0.0],
            [A51, A52, A53, A54, 0.0, 0.0, 0.0],
            [A61, A62, A63, A64, A65, 0.0, 0.0],
            [A71, 0.0, A73, A74, A75, A76, 0.0],
        ];
        let b = a[6];
        for i in 1..7 {
            let row: f64 = a[i].iter().sum();
            assert!((row - c[i]).abs() < 1e-14, "row {i}");
        }
        let sum = |f: &dyn Fn(usize) -> f64| (0..7).map(f).sum::<f64>();
        assert!((sum(&|i| b[i]) - 1.0).abs() < 1e-15);
        assert!((sum(&|i| b[i] * c[i]) - 0.5).abs() < 1e-15);
        assert!((sum(&|i| b[i] * c[i].powi(2)) - 1.0 / 3.0).abs() < 1e-15);
        assert!((sum(&|i| b[i] * c[i].powi(3)) - 0.25).abs() < 1e-15);
        assert!((sum(&|i| b[i] * c[i].powi(4)) - 0.2).abs() < 1e-15);
        // Σ b_i a_ij c_j = 1/6
        let bac: f64 = (0..7)
            .map(|i| b[i] * (0..7).map(|j| a[i][j] * c[j]).sum::<f64>())
            .sum();
        assert!((bac - 1.0 / 6.0).abs() < 1e-14);
        // The error weights sum to zero (both formulas are consistent) and the embedded
        // 4th-order weights b̂ = b − e integrate t³ exactly too.
        let e = [E1, 0.0, E3, E4, E5, E6, E7];
        assert!(e.iter().sum::<f64>().abs() < 1e-16);
        let bh = |i: usize| b[i] - e[i];
        assert!((sum(&|i| bh(i) * c[i].powi(3)) - 0.25).abs() < 1e-15);
        // The dense-output weights d_i also sum to zero: r5 vanishes for f constant.
        assert!((D1 + D3 + D4 + D5 + D6 + D7).abs() < 1e-14);
    }
}
