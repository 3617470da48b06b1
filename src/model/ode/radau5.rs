//! Radau IIA of order 5 (3 stages, implicit, L-stable) after Hairer's RADAU5 code
//! (Hairer–Wanner II, §IV.8): simplified Newton iterations in Hairer's transformed variables (one
//! real 2×2 and one complex 2×2 system, both LU-factorized with nalgebra), his embedded error
//! estimate, predictive (Gustafsson) step control, Jacobian reuse, and the collocation
//! polynomial as dense output.

use nalgebra::{Complex, Matrix2, U2, Vector2, linalg::LU};

use super::driver::{Scheme, Step};
use super::step_control::{
    Rejection, check_budget, initial_step, is_finite, rhs, underflow_error, underflows,
};
use super::{OdeError, OdeSystem, Options, Segment, State, Stats};

/// √6 to full precision (not const-evaluable from `sqrt`).
#[allow(clippy::excessive_precision)]
const SQ6: f64 =
    2.449_489_742_783_178_098_197_284_074_705_891_391_965_947_480_656_670_128_432_692_567;
const C1: f64 = (4.0 - SQ6) / 10.0;
const C2: f64 = (4.0 + SQ6) / 10.0;
const C1M1: f64 = C1 - 1.0;
const C2M1: f64 = C2 - 1.0;
const C1MC2: f64 = C1 - C2;
/// (c₁ − 1, c₂ − 1): the dense output evaluates the collocation polynomial with them.
pub(super) const C1M1_C2M1: (f64, f64) = (C1M1, C2M1);
// Error-estimate weights of RADAU5.
const DD1: f64 = -(13.0 + 7.0 * SQ6) / 3.0;
const DD2: f64 = (-13.0 + 7.0 * SQ6) / 3.0;
const DD3: f64 = -1.0 / 3.0;
// T and T⁻¹ bring A⁻¹ to block-diagonal form diag(γ, [[α, −β], [β, α]]) (RADAU5's values).
#[allow(clippy::excessive_precision)]
const T: [[f64; 3]; 3] = [
    [
        9.1232394870892942792e-02,
        -0.14125529502095420843,
        -3.0029194105147424492e-02,
    ],
    [
        0.24171793270710701896,
        0.20412935229379993199,
        0.38294211275726193779,
    ],
    [0.96604818261509293619, 1.0, 0.0],
];
#[allow(clippy::excessive_precision)]
const TI: [[f64; 3]; 3] = [
    [
        4.3255798900631553510,
        0.33919925181580986954,
        0.54177053993587487119,
    ],
    [
        -4.1787185915519047273,
        -0.32768282076106238708,
        0.47662355450055045196,
    ],
    [
        -0.50287263494578687595,
        2.5719269498556054292,
        -0.59603920482822492497,
    ],
];
/// Hairer's unit roundoff (RADAU5's default WORK(1)).
const UROUND: f64 = 1e-16;
/// Maximal Newton iterations per step (NIT).
const NIT: u32 = 7;
/// Safety factor of the step control.
const SAFE: f64 = 0.9;
/// Reuse the Jacobian while the Newton contraction rate stays below this (THET).
const THET: f64 = 0.001;
/// Keep h (and the factorizations) if h_new/h lies in [QUOT1, QUOT2].
const QUOT1: f64 = 1.0;
const QUOT2: f64 = 1.2;
/// Step ratio bounds: 1/FACL ≤ h_new/h ≤ 1/FACR, i.e. 0.2 … 8.
const FACL: f64 = 5.0;
const FACR: f64 = 1.0 / 8.0;
/// Consecutive step halvings after Newton failures before giving up.
const MAX_NEWTON_FAILURES: u32 = 20;
/// Singular iteration matrices tolerated in a row (RADAU5 stops at 5).
const MAX_SINGULAR: u32 = 5;

/// The real eigenvalue γ of A⁻¹ and the complex pair α ± iβ.
struct Eigen {
    gamma: f64,
    alpha: f64,
    beta: f64,
}

fn eigen() -> Eigen {
    let c81 = 81f64.powf(1.0 / 3.0);
    let c9 = 9f64.powf(1.0 / 3.0);
    let u1 = (6.0 + c81 - c9) / 30.0;
    let alph = (12.0 - c81 + c9) / 60.0;
    let beta = (c81 + c9) * 3f64.sqrt() / 60.0;
    let cno = alph * alph + beta * beta;
    Eigen {
        gamma: 1.0 / u1,
        alpha: alph / cno,
        beta: beta / cno,
    }
}

/// Radau IIA(5) stepper state (Hairer–Wanner II §IV.8, after Hairer's RADAU5).
pub(super) struct Radau5 {
    /// f(t, y) at the current point (RADAU5's Y0).
    f0: State,
    h: f64,
    /// The last accepted step, for extrapolating Newton starting values.
    h_old: f64,
    jac: Matrix2<f64>,
    /// The Jacobian was evaluated at the current step start (RADAU5's CALJAC).
    jac_fresh: bool,
    need_jac: bool,
    /// Factorizations of E₁ = γ/h·I − J and E₂ = (α + iβ)/h·I − J for the step `lu_h`.
    e1: Option<LU<f64, U2, U2>>,
    e2: Option<LU<Complex<f64>, U2, U2>>,
    lu_h: f64,
    /// Collocation coefficients of the last accepted step (CONT(N+1..4N)).
    cont: [State; 3],
    first: bool,
    reject: bool,
    faccon: f64,
    theta: f64,
    h_acc: f64,
    err_acc: f64,
    n_accepted: usize,
    newton_failures: u32,
    singular: u32,
    last_rejection: Option<Rejection>,
    /// RADAU5 works with rtol' = 0.1·rtol^(2/3) and atol' = rtol'·atol/rtol.
    rtol: f64,
    atol: f64,
    fnewt: f64,
    h_max: f64,
    eig: Eigen,
    opts: Options,
}

/// Why a Newton attempt ended without a converged solution.
enum NewtonOutcome {
    Converged {
        z: [State; 3],
        newt: u32,
    },
    /// Slow convergence predicted: retry with h scaled by this factor.
    Shrink(f64),
    /// Divergence, too many iterations, non-finite values (RADAU5's label 78).
    Failed,
}

impl Radau5 {
    pub(super) fn new(
        sys: &mut dyn OdeSystem,
        stats: &mut Stats,
        t0: f64,
        y0: &State,
        opts: &Options,
    ) -> Result<Self, OdeError> {
        let f0 = rhs(sys, stats, t0, y0);
        if !is_finite(&f0) {
            return Err(OdeError::NonFinite { t: t0 });
        }
        let rtol = 0.1 * opts.rtol.powf(2.0 / 3.0);
        let atol = rtol * opts.atol / opts.rtol;
        let fnewt = (10.0 * UROUND / rtol).max(0.03f64.min(rtol.sqrt()));
        let h_max = opts.h_max.min(opts.t_max - t0);
        let h = match opts.h_initial {
            Some(h) => h.min(h_max),
            None => {
                // RADAU5 itself starts from 1e-6; Hairer's HINIT, with the transformed
                // tolerances and the error estimate's order 4, adapts to the problem's scale.
                let scaled = Options {
                    rtol,
                    atol,
                    ..*opts
                };
                initial_step(sys, stats, t0, y0, &f0, 4, &scaled, h_max)
            }
        };
        Ok(Radau5 {
            f0,
            h,
            h_old: h,
            jac: Matrix2::zeros(),
            jac_fresh: false,
            need_jac: true,
            e1: None,
            e2: None,
            lu_h: f64::NAN,
            cont: [State::zeros(); 3],
            first: true,
            reject: false,
            faccon: 1.0,
            theta: THET,
            h_acc: h,
            err_acc: 1e-2,
            n_accepted: 0,
            newton_failures: 0,
            singular: 0,
            last_rejection: None,
            rtol,
            atol,
            fnewt,
            h_max,
            eig: eigen(),
            opts: *opts,
        })
    }

    /// Factorizes E₁ and E₂ for step h; false if either is singular.
    fn factorize(&mut self, h: f64) -> bool {
        let e1 = Matrix2::identity() * (self.eig.gamma / h) - self.jac;
        let shift = Complex::new(self.eig.alpha / h, self.eig.beta / h);
        let e2 = Matrix2::from_fn(|i, j| {
            let d = if i == j {
                shift
            } else {
                Complex::new(0.0, 0.0)
            };
            d - Complex::new(self.jac[(i, j)], 0.0)
        });
        let (lu1, lu2) = (e1.lu(), e2.lu());
        let ok = lu1.is_invertible() && lu2.is_invertible();
        self.e1 = Some(lu1);
        self.e2 = Some(lu2);
        self.lu_h = if ok { h } else { f64::NAN };
        ok
    }

    fn solve_e1(&self, b: &State) -> Option<State> {
        self.e1.as_ref()?.solve(b)
    }

    fn solve_e2(&self, re: &State, im: &State) -> Option<(State, State)> {
        let b = Vector2::new(Complex::new(re[0], im[0]), Complex::new(re[1], im[1]));
        let x = self.e2.as_ref()?.solve(&b)?;
        Some((State::new(x[0].re, x[1].re), State::new(x[0].im, x[1].im)))
    }

    /// The simplified Newton iteration for the stage increments Z (RADAU5, label 40).
    fn newton(
        &mut self,
        sys: &mut dyn OdeSystem,
        stats: &mut Stats,
        t: f64,
        y: &State,
        h: f64,
        scal: &State,
    ) -> NewtonOutcome {
        let fac1 = self.eig.gamma / h;
        let alphn = self.eig.alpha / h;
        let betan = self.eig.beta / h;
        // Starting values: zero on the first step, else the last collocation polynomial
        // extrapolated to the new stage times.
        let mut z = [State::zeros(); 3];
        if !self.first {
            let c3q = h / self.h_old;
            let cq = [C1 * c3q, C2 * c3q, c3q];
            let [ak1, ak2, ak3] = self.cont;
            for i in 0..3 {
                z[i] = (ak1 + (ak2 + ak3 * (cq[i] - C1M1)) * (cq[i] - C2M1)) * cq[i];
            }
        }
        let mut w = transform(&TI, &z);
        self.faccon = self.faccon.max(UROUND).powf(0.8);
        self.theta = THET;
        let mut dynold = 0.0;
        let mut thqold = 0.0;
        let mut newt = 0;
        loop {
            if newt >= NIT {
                return NewtonOutcome::Failed;
            }
            let fz = [
                rhs(sys, stats, t + C1 * h, &(y + z[0])),
                rhs(sys, stats, t + C2 * h, &(y + z[1])),
                rhs(sys, stats, t + h, &(y + z[2])),
            ];
            if !fz.iter().all(is_finite) {
                return NewtonOutcome::Failed;
            }
            let g = transform(&TI, &fz);
            // Right-hand sides of the transformed linear systems (RADAU5's SLVRAD).
            let r1 = g[0] - w[0] * fac1;
            let r2 = g[1] - w[1] * alphn + w[2] * betan;
            let r3 = g[2] - w[2] * alphn - w[1] * betan;
            let Some(d1) = self.solve_e1(&r1) else {
                return NewtonOutcome::Failed;
            };
            let Some((d2, d3)) = self.solve_e2(&r2, &r3) else {
                return NewtonOutcome::Failed;
            };
            newt += 1;
            let mut dyno = 0.0;
            for i in 0..2 {
                dyno += (d1[i] / scal[i]).powi(2)
                    + (d2[i] / scal[i]).powi(2)
                    + (d3[i] / scal[i]).powi(2);
            }
            let dyno = (dyno / 6.0).sqrt();
            if !dyno.is_finite() {
                return NewtonOutcome::Failed;
            }
            if newt > 1 && newt < NIT {
                let thq = dyno / dynold;
                self.theta = if newt == 2 {
                    thq
                } else {
                    (thq * thqold).sqrt()
                };
                thqold = thq;
                if self.theta < 0.99 {
                    self.faccon = self.theta / (1.0 - self.theta);
                    let dyth =
                        self.faccon * dyno * self.theta.powi((NIT - 1 - newt) as i32) / self.fnewt;
                    if dyth >= 1.0 {
                        // Convergence too slow to finish within NIT iterations: shrink now.
                        let qnewt = dyth.clamp(1e-4, 20.0);
                        let hhfac = 0.8 * qnewt.powf(-1.0 / (4.0 + f64::from(NIT - 1 - newt)));
                        return NewtonOutcome::Shrink(hhfac);
                    }
                } else {
                    return NewtonOutcome::Failed;
                }
            }
            dynold = dyno.max(UROUND);
            w[0] += d1;
            w[1] += d2;
            w[2] += d3;
            z = transform(&T, &w);
            if self.faccon * dyno <= self.fnewt {
                return NewtonOutcome::Converged { z, newt };
            }
        }
    }

    /// RADAU5's error estimate (ESTRAD): (γ/h·I − J)⁻¹ applied to f₀ + Σ eᵢ zᵢ / h, with one
    /// extra smoothing solve on the first or a rejected step if the estimate exceeds 1.
    #[allow(clippy::too_many_arguments)]
    fn estimate(
        &self,
        sys: &mut dyn OdeSystem,
        stats: &mut Stats,
        t: f64,
        y: &State,
        y_new: &State,
        z: &[State; 3],
        h: f64,
    ) -> f64 {
        let f2 = (z[0] * DD1 + z[1] * DD2 + z[2] * DD3) / h;
        let norm = |e: &State| {
            let mut s = 0.0;
            for i in 0..2 {
                let sc = self.atol + self.rtol * y[i].abs().max(y_new[i].abs());
                s += (e[i] / sc).powi(2);
            }
            (s / 2.0).sqrt().max(1e-10)
        };
        let Some(e) = self.solve_e1(&(f2 + self.f0)) else {
            return f64::INFINITY;
        };
        let err = norm(&e);
        if err < 1.0 || !(self.first || self.reject) {
            return err;
        }
        let f1 = rhs(sys, stats, t, &(y + e));
        match self.solve_e1(&(f1 + f2)) {
            Some(e) => norm(&e),
            None => f64::INFINITY,
        }
    }

    /// An attempt failed without an error estimate (RADAU5's label 78): halve h.
    fn unexpected_rejection(&mut self, stats: &mut Stats, h: f64) {
        stats.rejected_steps += 1;
        self.newton_failures += 1;
        self.h = 0.5 * h;
        self.reject = true;
        self.need_jac = !self.jac_fresh;
        self.last_rejection = Some(Rejection::Newton);
    }
}

/// (M ⊗ I)·v for a 3×3 stage matrix M and three 2-vectors.
fn transform(m: &[[f64; 3]; 3], v: &[State; 3]) -> [State; 3] {
    let row = |r: &[f64; 3]| v[0] * r[0] + v[1] * r[1] + v[2] * r[2];
    [row(&m[0]), row(&m[1]), row(&m[2])]
}

impl Scheme for Radau5 {
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
            if self.newton_failures > MAX_NEWTON_FAILURES {
                return Err(OdeError::NewtonFailed { t });
            }
            let mut h = self.h.min(self.h_max);
            let last = t + 1.01 * h >= t_max;
            if last {
                h = t_max - t;
            }
            if underflows(h, t) {
                return Err(underflow_error(self.last_rejection, t, h));
            }
            let t_new = if last { t_max } else { t + h };
            if self.need_jac {
                self.jac = sys.jacobian(t, y);
                stats.jacobian_evals += 1;
                self.jac_fresh = true;
                self.need_jac = false;
                self.lu_h = f64::NAN;
            }
            if self.lu_h != h && !self.factorize(h) {
                self.singular += 1;
                if self.singular >= MAX_SINGULAR {
                    return Err(OdeError::NewtonFailed { t });
                }
                self.unexpected_rejection(stats, h);
                continue;
            }
            let scal = State::new(
                self.atol + self.rtol * y[0].abs(),
                self.atol + self.rtol * y[1].abs(),
            );
            let (z, newt) = match self.newton(sys, stats, t, y, h, &scal) {
                NewtonOutcome::Converged { z, newt } => (z, newt),
                NewtonOutcome::Shrink(fac) => {
                    stats.rejected_steps += 1;
                    self.h = fac * h;
                    self.reject = true;
                    self.need_jac = !self.jac_fresh;
                    self.last_rejection = Some(Rejection::Newton);
                    continue;
                }
                NewtonOutcome::Failed => {
                    self.unexpected_rejection(stats, h);
                    continue;
                }
            };
            let y_new = y + z[2];
            let err = self.estimate(sys, stats, t, y, &y_new, &z, h);
            if !(err.is_finite() && is_finite(&y_new)) {
                self.unexpected_rejection(stats, h);
                continue;
            }
            self.newton_failures = 0;
            self.singular = 0;
            // New step size: fewer Newton iterations allow a bolder step.
            let fac = SAFE.min(SAFE * f64::from(1 + 2 * NIT) / f64::from(newt + 2 * NIT));
            let mut quot = FACR.max(FACL.min(err.powf(0.25) / fac));
            let mut h_new = h / quot;
            if err >= 1.0 {
                stats.rejected_steps += 1;
                self.reject = true;
                self.last_rejection = Some(Rejection::Error);
                self.h = if self.first { 0.1 * h } else { h_new };
                self.need_jac = !self.jac_fresh;
                continue;
            }

            // Accepted.
            self.n_accepted += 1;
            if self.n_accepted > 1 {
                // Gustafsson's predictive controller.
                let facgus = (self.h_acc / h) * (err * err / self.err_acc).powf(0.25) / SAFE;
                quot = quot.max(facgus.clamp(FACR, FACL));
                h_new = h / quot;
            }
            self.h_acc = h;
            self.err_acc = err.max(1e-2);
            let f_new = rhs(sys, stats, t_new, &y_new);
            if !is_finite(&f_new) {
                self.unexpected_rejection(stats, h);
                self.n_accepted -= 1;
                continue;
            }
            stats.steps += 1;
            self.first = false;
            self.last_rejection = None;
            self.h_old = h;
            let [z1, z2, z3] = z;
            let c1 = (z2 - z3) / C2M1;
            let ak = (z1 - z2) / C1MC2;
            let acont3 = (ak - z1 / C1) / C2;
            let c2 = (ak - c1) / C1M1;
            let c3 = c2 - acont3;
            self.cont = [c1, c2, c3];
            self.f0 = f_new;
            h_new = h_new.min(self.h_max);
            if self.reject {
                h_new = h_new.min(h);
            }
            self.reject = false;
            self.jac_fresh = false;
            let qt = h_new / h;
            if !(self.theta <= THET && (QUOT1..=QUOT2).contains(&qt)) {
                self.h = h_new;
            } else {
                self.h = h;
            }
            self.need_jac = self.theta > THET;
            return Ok(Step {
                t: t_new,
                y: y_new,
                segment: Segment::Radau5 {
                    t0: t,
                    h,
                    y0: *y,
                    y1: y_new,
                    c: self.cont,
                },
            });
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The Radau IIA(5) coefficient matrix (Hairer–Wanner II, Table IV.5.6).
    fn a_matrix() -> [[f64; 3]; 3] {
        [
            [
                (88.0 - 7.0 * SQ6) / 360.0,
                (296.0 - 169.0 * SQ6) / 1800.0,
                (-2.0 + 3.0 * SQ6) / 225.0,
            ],
            [
                (296.0 + 169.0 * SQ6) / 1800.0,
                (88.0 + 7.0 * SQ6) / 360.0,
                (-2.0 - 3.0 * SQ6) / 225.0,
            ],
            [(16.0 - SQ6) / 36.0, (16.0 + SQ6) / 36.0, 1.0 / 9.0],
        ]
    }

    fn mul(a: &[[f64; 3]; 3], b: &[[f64; 3]; 3]) -> [[f64; 3]; 3] {
        let mut c = [[0.0; 3]; 3];
        for i in 0..3 {
            for j in 0..3 {
                c[i][j] = (0..3).map(|k| a[i][k] * b[k][j]).sum();
            }
        }
        c
    }

    #[test]
    fn transformation_block_diagonalizes_the_inverse_of_a() {
        // T⁻¹·A⁻¹·T = diag(γ, [[α, −β], [β, α]]), i.e. A·T = T·Λ⁻¹ — checked as T⁻¹·A·T = Λ⁻¹.
        let e = eigen();
        let lam = mul(&TI, &mul(&a_matrix(), &T));
        let det = e.alpha * e.alpha + e.beta * e.beta;
        let expected = [
            [1.0 / e.gamma, 0.0, 0.0],
            [0.0, e.alpha / det, e.beta / det],
            [0.0, -e.beta / det, e.alpha / det],
        ];
        for i in 0..3 {
            for j in 0..3 {
                assert!(
                    (lam[i][j] - expected[i][j]).abs() < 1e-15,
                    "({i},{j}): {}",
                    lam[i][j]
                );
            }
        }
        // And T·T⁻¹ = I.
        let id = mul(&T, &TI);
        for (i, row) in id.iter().enumerate() {
            for (j, value) in row.iter().enumerate() {
                let want = if i == j { 1.0 } else { 0.0 };
                assert!((value - want).abs() < 1e-15, "({i},{j}): {value}");
            }
        }
    }

    #[test]
    fn radau_nodes_are_the_row_sums() {
        let a = a_matrix();
        let c = [C1, C2, 1.0];
        for i in 0..3 {
            assert!((a[i].iter().sum::<f64>() - c[i]).abs() < 1e-15);
        }
    }
}
