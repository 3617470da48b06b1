//! Pseudo-arclength continuation of the zeros of F: ℝᴺ⁺¹ → ℝᴺ (docs/continuation.md §2): the
//! tangent as the null vector of DF, a predictor along it and a Newton corrector on
//! (F(z) = 0, t·(z − z_pred) = 0), with central-difference Jacobians.
//!
//! Everything here works in scaled variables of order one (phases in radians, speeds over a speed
//! scale, parameters over their range), so one absolute tolerance fits all components.

use nalgebra::{DMatrix, DVector};

use super::error::ContinuationError;

/// A system of N equations in N + 1 scaled unknowns.
pub(crate) trait Equations {
    /// N.
    fn equations(&self) -> usize;
    /// F(z).
    fn residual(&self, z: &DVector<f64>) -> Result<DVector<f64>, ContinuationError>;
    /// Step of the central differences, in the scaled variables.
    fn fd_step(&self) -> f64;
    /// Newton's convergence: a correction below this (scaled) ends it.
    fn tolerance(&self) -> f64;
}

/// DF(z) by central differences (N × (N + 1)).
pub(crate) fn jacobian(
    eq: &dyn Equations,
    z: &DVector<f64>,
) -> Result<DMatrix<f64>, ContinuationError> {
    let n = eq.equations();
    let mut jac = DMatrix::zeros(n, z.len());
    let h = eq.fd_step();
    for j in 0..z.len() {
        let step = h * z[j].abs().max(1.0);
        let mut plus = z.clone();
        plus[j] += step;
        let mut minus = z.clone();
        minus[j] -= step;
        let column = (eq.residual(&plus)? - eq.residual(&minus)?) / (2.0 * step);
        jac.set_column(j, &column);
    }
    Ok(jac)
}

/// The unit null vector of `jac` (N × (N + 1)) on the side of `prev`: the solution of
/// [DF; prevᵀ]·t = (0, 1), normalised.
pub(crate) fn tangent(
    jac: &DMatrix<f64>,
    prev: &DVector<f64>,
) -> Result<DVector<f64>, ContinuationError> {
    let n = jac.nrows();
    let mut a = jac.clone().insert_row(n, 0.0);
    a.set_row(n, &prev.transpose());
    let mut rhs = DVector::zeros(n + 1);
    rhs[n] = 1.0;
    let t = a
        .lu()
        .solve(&rhs)
        .filter(|t| t.iter().all(|v| v.is_finite()))
        .ok_or(ContinuationError::Singular("the branch's tangent"))?;
    let t = t.normalize();
    Ok(if t.dot(prev) < 0.0 { -t } else { t })
}

/// Newton on (F(z) = 0, t·(z − pred) = 0) from `pred`: the point of the branch on the hyperplane
/// through `pred` normal to `t`, and the iterations taken.
pub(crate) fn correct(
    eq: &dyn Equations,
    pred: &DVector<f64>,
    t: &DVector<f64>,
    max_iterations: usize,
) -> Result<(DVector<f64>, usize), ContinuationError> {
    let n = eq.equations();
    let mut z = pred.clone();
    let mut last = f64::INFINITY;
    for iteration in 1..=max_iterations {
        let f = eq.residual(&z)?;
        let jac = jacobian(eq, &z)?;
        let mut a = jac.insert_row(n, 0.0);
        a.set_row(n, &t.transpose());
        let mut rhs = -f.clone().insert_row(n, 0.0);
        rhs[n] = -t.dot(&(&z - pred));
        let dz = a
            .lu()
            .solve(&rhs)
            .filter(|d| d.iter().all(|v| v.is_finite()))
            .ok_or(ContinuationError::Singular("the corrector's Jacobian"))?;
        z += &dz;
        let size = dz.amax();
        // Diverging: let the caller halve the step.
        if size > 4.0 * last && iteration > 2 {
            break;
        }
        last = size;
        if size <= eq.tolerance() {
            return Ok((z, iteration));
        }
    }
    Err(ContinuationError::Corrector {
        iterations: max_iterations,
        correction: last,
    })
}
