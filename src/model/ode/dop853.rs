//! DOP853: the Prince–Dormand 8(5,3) pair with FSAL, the combined 5th/3rd-order error estimator
//! and the 7th-order dense output of Hairer's DOP853 code (Prince & Dormand 1981; Hairer–Nørsett–
//! Wanner I, §II.10). Coefficients live in `dop853_coefficients.rs`.

use super::dop853_coefficients::*;
use super::driver::{Scheme, Step};
use super::step_control::{
    PiController, Rejection, check_budget, initial_step, is_finite, rhs, underflow_error,
    underflows,
};
use super::{OdeError, OdeSystem, Options, Segment, State, Stats};

const ORDER: u32 = 8;

/// DOP853 stepper state (Prince–Dormand 1981, after Hairer's DOP853).
pub(super) struct Dop853 {
    /// f(t, y) at the current point (FSAL).
    f: State,
    h: f64,
    ctrl: PiController,
    reject: bool,
    last_rejection: Option<Rejection>,
    h_max: f64,
    opts: Options,
}

/// Hairer's DOP853 error norm: the 5th-order estimate err₅ scaled by err₅/√(err₅² + 0.01·err₃²),
/// which behaves like an 8th-order quantity when the 3rd-order estimate err₃ is not tiny.
fn error_norm_853(e5: &State, e3: &State, y0: &State, y1: &State, h: f64, o: &Options) -> f64 {
    let mut err5 = 0.0;
    let mut err3 = 0.0;
    for i in 0..2 {
        let sk = o.atol + o.rtol * y0[i].abs().max(y1[i].abs());
        err5 += (e5[i] / sk).powi(2);
        err3 += (e3[i] / sk).powi(2);
    }
    let mut deno = err5 + 0.01 * err3;
    if deno <= 0.0 {
        deno = 1.0;
    }
    h.abs() * err5 * (1.0 / (2.0 * deno)).sqrt()
}

impl Dop853 {
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
        Ok(Dop853 {
            f,
            h,
            ctrl: PiController::dop853(),
            reject: false,
            last_rejection: None,
            h_max,
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

impl Scheme for Dop853 {
    fn step(
        &mut self,
        sys: &mut dyn OdeSystem,
        t: f64,
        y: &State,
        stats: &mut Stats,
    ) -> Result<Step, OdeError> {
        let t_max = self.opts.t_max;
        loop {
            check_budget(stats, &self.opts, t)?;
            let mut h = self.h.min(self.h_max);
            let last = t + 1.01 * h >= t_max;
            if last {
                h = t_max - t;
            }
            if underflows(h, t) {
                return Err(underflow_error(self.last_rejection, t, h));
            }
            let t_new = if last { t_max } else { t + h };

            let k1 = self.f;
            let k2 = rhs(sys, stats, t + C2 * h, &(y + k1 * (h * A21)));
            let k3 = rhs(sys, stats, t + C3 * h, &(y + (k1 * A31 + k2 * A32) * h));
            let k4 = rhs(sys, stats, t + C4 * h, &(y + (k1 * A41 + k3 * A43) * h));
            let k5 = rhs(
                sys,
                stats,
                t + C5 * h,
                &(y + (k1 * A51 + k3 * A53 + k4 * A54) * h),
            );
            let k6 = rhs(
                sys,
                stats,
                t + C6 * h,
                &(y + (k1 * A61 + k4 * A64 + k5 * A65) * h),
            );
            let k7 = rhs(
                sys,
                stats,
                t + C7 * h,
                &(y + (k1 * A71 + k4 * A74 + k5 * A75 + k6 * A76) * h),
            );
            let k8 = rhs(
                sys,
                stats,
                t + C8 * h,
                &(y + (k1 * A81 + k4 * A84 + k5 * A85 + k6 * A86 + k7 * A87) * h),
            );
            let k9 = rhs(
                sys,
                stats,
                t + C9 * h,
                &(y + (k1 * A91 + k4 * A94 + k5 * A95 + k6 * A96 + k7 * A97 + k8 * A98) * h),
            );
            let k10 = rhs(
                sys,
                stats,
                t + C10 * h,
                &(y + (k1 * A101
                    + k4 * A104
                    + k5 * A105
                    + k6 * A106
                    + k7 * A107
                    + k8 * A108
                    + k9 * A109)
                    * h),
            );
            let k11 = rhs(
                sys,
                stats,
                t + C11 * h,
                &(y + (k1 * A111
                    + k4 * A114
                    + k5 * A115
                    + k6 * A116
                    + k7 * A117
                    + k8 * A118
                    + k9 * A119
                    + k10 * A1110)
                    * h),
            );
            let k12 = rhs(
                sys,
                stats,
                t_new,
                &(y + (k1 * A121
                    + k4 * A124
                    + k5 * A125
                    + k6 * A126
                    + k7 * A127
                    + k8 * A128
                    + k9 * A129
                    + k10 * A1210
                    + k11 * A1211)
                    * h),
            );
            let bk =
                k1 * B1 + k6 * B6 + k7 * B7 + k8 * B8 + k9 * B9 + k10 * B10 + k11 * B11 + k12 * B12;
            let y_new = y + bk * h;
            if !is_finite(&y_new) {
                self.reject(stats, 0.2 * h, Rejection::NonFinite);
                continue;
            }
            let e3 = bk - k1 * BHH1 - k9 * BHH2 - k12 * BHH3;
            let e5 = k1 * ER1
                + k6 * ER6
                + k7 * ER7
                + k8 * ER8
                + k9 * ER9
                + k10 * ER10
                + k11 * ER11
                + k12 * ER12;
            let err = error_norm_853(&e5, &e3, y, &y_new, h, &self.opts);
            if !err.is_finite() {
                self.reject(stats, 0.2 * h, Rejection::NonFinite);
                continue;
            }
            if err > 1.0 {
                let h_next = self.ctrl.rejected(err, h);
                self.reject(stats, h_next, Rejection::Error);
                continue;
            }
            let k13 = rhs(sys, stats, t_new, &y_new);
            if !is_finite(&k13) {
                self.reject(stats, 0.2 * h, Rejection::NonFinite);
                continue;
            }

            // Dense output: three more stages, then the CONTD8 coefficients.
            let k14 = rhs(
                sys,
                stats,
                t + C14 * h,
                &(y + (k1 * A141
                    + k7 * A147
                    + k8 * A148
                    + k9 * A149
                    + k10 * A1410
                    + k11 * A1411
                    + k12 * A1412
                    + k13 * A1413)
                    * h),
            );
            let k15 = rhs(
                sys,
                stats,
                t + C15 * h,
                &(y + (k1 * A151
                    + k6 * A156
                    + k7 * A157
                    + k8 * A158
                    + k11 * A1511
                    + k12 * A1512
                    + k13 * A1513
                    + k14 * A1514)
                    * h),
            );
            let k16 = rhs(
                sys,
                stats,
                t + C16 * h,
                &(y + (k1 * A161
                    + k6 * A166
                    + k7 * A167
                    + k8 * A168
                    + k9 * A169
                    + k13 * A1613
                    + k14 * A1614
                    + k15 * A1615)
                    * h),
            );
            let stages = [k1, k6, k7, k8, k9, k10, k11, k12, k13, k14, k15, k16];
            let ydiff = y_new - y;
            let bspl = k1 * h - ydiff;
            let mut r = [
                bspl,
                ydiff - k13 * h - bspl,
                State::zeros(),
                State::zeros(),
                State::zeros(),
                State::zeros(),
            ];
            for (row, d) in D.iter().enumerate() {
                let mut acc = State::zeros();
                for (k, w) in stages.iter().zip(d) {
                    acc += k * *w;
                }
                r[row + 2] = acc * h;
            }
            // A stage of the dense output may still leave the domain of f; the step itself is
            // fine, so only the interpolant would be poisoned: retry shorter in that case too.
            if !r.iter().all(is_finite) {
                self.reject(stats, 0.2 * h, Rejection::NonFinite);
                continue;
            }

            stats.steps += 1;
            self.h = self.ctrl.accepted(err, h, self.h_max, self.reject);
            self.reject = false;
            self.last_rejection = None;
            self.f = k13;
            return Ok(Step {
                t: t_new,
                y: y_new,
                segment: Segment::Dop853 {
                    t0: t,
                    h,
                    y0: *y,
                    y1: y_new,
                    r,
                },
            });
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Rows of the 16-stage tableau as (c_i, [(j, a_ij)]) with 1-based stage numbers.
    fn rows() -> Vec<(f64, Vec<(usize, f64)>)> {
        vec![
            (C2, vec![(1, A21)]),
            (C3, vec![(1, A31), (2, A32)]),
            (C4, vec![(1, A41), (3, A43)]),
            (C5, vec![(1, A51), (3, A53), (4, A54)]),
            (C6, vec![(1, A61), (4, A64), (5, A65)]),
            (C7, vec![(1, A71), (4, A74), (5, A75), (6, A76)]),
            (C8, vec![(1, A81), (4, A84), (5, A85), (6, A86), (7, A87)]),
            (
                C9,
                vec![(1, A91), (4, A94), (5, A95), (6, A96), (7, A97), (8, A98)],
            ),
            (
                C10,
                vec![
                    (1, A101),
                    (4, A104),
                    (5, A105),
                    (6, A106),
                    (7, A107),
                    (8, A108),
                    (9, A109),
                ],
            ),
            (
                C11,
                vec![
                    (1, A111),
                    (4, A114),
                    (5, A115),
                    (6, A116),
                    (7, A117),
                    (8, A118),
                    (9, A119),
                    (10, A1110),
                ],
            ),
            (
                1.0,
                vec![
                    (1, A121),
                    (4, A124),
                    (5, A125),
                    (6, A126),
                    (7, A127),
                    (8, A128),
                    (9, A129),
                    (10, A1210),
                    (11, A1211),
                ],
            ),
            (
                C14,
                vec![
                    (1, A141),
                    (7, A147),
                    (8, A148),
                    (9, A149),
                    (10, A1410),
                    (11, A1411),
                    (12, A1412),
                    (13, A1413),
                ],
            ),
            (
                C15,
                vec![
                    (1, A151),
                    (6, A156),
                    (7, A157),
                    (8, A158),
                    (11, A1511),
                    (12, A1512),
                    (13, A1513),
                    (14, A1514),
                ],
            ),
            (
                C16,
                vec![
                    (1, A161),
                    (6, A166),
                    (7, A167),
                    (8, A168),
                    (9, A169),
                    (13, A1613),
                    (14, A1614),
                    (15, A1615),
                ],
            ),
        ]
    }

    #[test]
    fn rows_sum_to_their_nodes() {
        for (c, row) in rows() {
            let s: f64 = row.iter().map(|(_, a)| a).sum();
            assert!((s - c).abs() < 2e-14, "row with c = {c}: {s}");
        }
    }

    #[test]
    fn weights_integrate_polynomials_to_degree_seven() {
        let c = [0.0, C6, C7, C8, C9, C10, C11, 1.0];
        let b = [B1, B6, B7, B8, B9, B10, B11, B12];
        for k in 0..8 {
            let q: f64 = b.iter().zip(&c).map(|(b, c)| b * c.powi(k)).sum();
            let exact = 1.0 / f64::from(k + 1);
            assert!((q - exact).abs() < 1e-13, "degree {k}: {q} vs {exact}");
        }
        // The 3rd-order weights: 1, 1/2, 1/3 on nodes (0, c9, 1).
        let c3 = [0.0, C9, 1.0];
        let bh = [BHH1, BHH2, BHH3];
        for k in 0..3 {
            let q: f64 = bh.iter().zip(&c3).map(|(b, c)| b * c.powi(k)).sum();
            assert!((q - 1.0 / f64::from(k + 1)).abs() < 1e-14, "bhh degree {k}");
        }
        // The 5th-order error weights annihilate constants.
        let er = [ER1, ER6, ER7, ER8, ER9, ER10, ER11, ER12];
        assert!(er.iter().sum::<f64>().abs() < 1e-13);
    }

    #[test]
    fn coefficients_match_an_independent_transcription() {
        // The `differential-equations` crate carries its own copy of Hairer's table.
        let t = differential_equations::tableau::ButcherTableau::<f64, 12, 16>::dop853();
        let rel = |a: f64, b: f64| (a - b).abs() <= 1e-15 * a.abs().max(1.0);
        let ours_b = [B1, 0.0, 0.0, 0.0, 0.0, B6, B7, B8, B9, B10, B11, B12];
        for (i, b) in ours_b.iter().enumerate() {
            assert!(rel(*b, t.b[i]), "b{}", i + 1);
        }
        for (c, row) in rows() {
            let i = (1..16).find(|&i| (t.c[i] - c).abs() < 1e-15).unwrap_or(0);
            assert!(i > 0, "node {c} missing");
            // Rows 12 and 13 both have c = 1 in the reference table; row 12 is the step's.
            let i = if c == 1.0 { 11 } else { i };
            for (j, a) in row {
                assert!(rel(a, t.a[i][j - 1]), "a[{}][{}]", i + 1, j);
            }
        }
        let bi = t.bi.unwrap_or([[0.0; 16]; 16]);
        let cols = [0, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15];
        for (row, d) in D.iter().enumerate() {
            for (k, &col) in cols.iter().enumerate() {
                assert!(rel(d[k], bi[row + 4][col]), "d{}{}", row + 4, col + 1);
            }
        }
    }
}
