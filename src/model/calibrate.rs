//! Calibration: the damping parameter of a law that makes its realised restitution e_out equal the
//! requested e at the scene's v₀ (docs/physics.md §6.4).
//!
//! The Hunt–Crossley family in closed form: its e_out depends on χ = α·v₀ alone, through
//! ln((1 + χ)/(1 − χ·e_out)) = χ·(1 + e_out), whatever n, k, m and v₀. Thornton's law by inverting
//! his closed-form e(V) (spheres) or its line-contact counterpart (a quadrature). Every other law with a damping parameter by a bracketed root of
//! e_out(d) − e over solves at tight tolerance.
#![warn(missing_docs)]

use thiserror::Error;

use super::error::ModelError;
use super::exact::special::{unloading_root, y_minus_log1p};
use super::force::table::Family;
use super::force::thornton::Thornton;
use super::force::{AnyLaw, Damping, DampingParam, ForceModel, ImpactParams};
use super::impact::{ImpactError, MethodChoice, SolveOptions, solve_law};
use super::numeric::roots::brent;

/// Thornton's law, calibrated through his closed-form e(V).
const THORNTON: ForceModel = ForceModel::with_id("thornton");

/// The tolerance of the solves inside a bracketed calibration: two digits below the 1e-10 the
/// calibration aims at.
const SOLVE_RTOL: f64 = 1e-12;

/// Doublings of the damping tried while looking for one that rebounds below the target.
const MAX_DOUBLINGS: usize = 80;

/// Why a law could not be calibrated.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum CalibrationError {
    /// The law has no damping parameter (elastic Hertz, the exact line-contact law).
    #[error("{0} has no damping parameter to calibrate")]
    NoDamping(ForceModel),
    /// No value of the damping parameter realises the requested e.
    #[error(
        "{model} cannot reach e = {target}: its realised e stays at {lowest:.6} or above ({symbol} up to {damping:.4e})"
    )]
    Unreachable {
        /// The law.
        model: ForceModel,
        /// The requested restitution.
        target: f64,
        /// The lowest restitution the law realised.
        lowest: f64,
        /// The damping parameter's symbol (α, b, P, …).
        symbol: &'static str,
        /// The largest damping tried, in the parameter's SI unit.
        damping: f64,
    },
    /// An impact solve inside the calibration failed.
    #[error("{model}: calibration solve failed at {symbol} = {damping:.4e}: {source}")]
    Solve {
        /// The law.
        model: ForceModel,
        /// The damping parameter's symbol.
        symbol: &'static str,
        /// The damping the solve was at, in the parameter's SI unit.
        damping: f64,
        /// Why the solve failed.
        #[source]
        source: ImpactError,
    },
}

/// A calibrated law and what it realises.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Calibrated {
    /// The law with its calibrated damping, ready for [`solve_law`].
    pub law: AnyLaw,
    /// The calibrated damping parameter: its symbol, value and unit.
    pub damping: Damping,
    /// The realised restitution of the calibrated law (at the calibration's tolerance).
    pub e_out: f64,
}

/// The law to solve for `model`: the scene's (damping from e by the law's own rule), or with
/// `calibrated` its damping calibrated to the scene's e. A law that cannot be calibrated falls back
/// to the scene's, with the reason; a law without damping is the scene's, uncalibrated.
pub fn scene_or_calibrated(
    model: ForceModel,
    params: &ImpactParams,
    calibrated: bool,
) -> Result<(AnyLaw, Result<bool, CalibrationError>), ImpactError> {
    let scene_law = model.law(params)?;
    if !calibrated || model.spec().damping.is_none() {
        return Ok((scene_law, Ok(false)));
    }
    Ok(match calibrate(model, params) {
        Ok(c) => (c.law, Ok(true)),
        Err(e) => (scene_law, Err(e)),
    })
}

/// The realised e of a Hunt–Crossley-family law with χ = α·v₀: e_out = s/χ with s the unloading
/// root of G(−s) = G(χ), G(y) = y − ln(1 + y) (docs/physics.md §3, §6.4).
pub fn hunt_crossley_restitution(chi: f64) -> f64 {
    if chi <= 0.0 {
        return 1.0;
    }
    unloading_root(y_minus_log1p(chi)).0 / chi
}

/// The χ whose Hunt–Crossley-family law realises `e` ∈ (0, 1]: the root of
/// ln((1 + χ)/(1 − χ·e)) = χ·(1 + e) (docs/physics.md §6.4); 0 at e = 1.
pub fn hunt_crossley_chi(e: f64) -> Option<f64> {
    if !(e > 0.0 && e <= 1.0) {
        return None;
    }
    if e == 1.0 {
        return Some(0.0);
    }
    // e_out falls from 1 (χ → 0) to 0 (χ → ∞); χ ≈ 3(1−e)/2 near e = 1 and ≈ 1/e near e = 0, so
    // [(1−e)/10, 2/e + 10] brackets it.
    brent(
        |chi| hunt_crossley_restitution(chi) - e,
        0.1 * (1.0 - e),
        2.0 / e + 10.0,
    )
}

/// The law `model` with its damping calibrated so that e_out equals `params.restitution`.
///
/// Hunt–Crossley on the paper's Fig. 5 scene, whose own rule χ = 3(1 − e)/2 gives 0.712 for the
/// requested e = 0.6; calibrated, its χ solves ln((1 + χ)/(1 − χ·e)) = χ·(1 + e)
/// (docs/physics.md §6.4) and the impact rebounds at 0.6:
///
/// ```
/// use hertz_tui::model::ForceModel;
/// use hertz_tui::model::calibrate::calibrate;
/// use hertz_tui::model::impact::{SolveOptions, solve_impact, solve_law};
/// use hertz_tui::model::presets::{DEFAULT_SCENE, Registry};
///
/// let scene = Registry::builtin()?.scene(DEFAULT_SCENE)?;
/// let params = scene.impact_params(&scene.quasistatic()?);
/// let options = SolveOptions::default();
/// assert_eq!(params.restitution, 0.6);
///
/// let own_rule = solve_impact(ForceModel::HuntCrossley, &params, &options)?.summary.e_out;
/// assert!((own_rule - 0.712).abs() < 1e-3);
///
/// let calibrated = calibrate(ForceModel::HuntCrossley, &params)?;
/// assert_eq!(calibrated.damping.param.symbol, "χ");
/// let (e, chi) = (0.6, calibrated.damping.value);
/// assert!((((1.0 + chi) / (1.0 - chi * e)).ln() - chi * (1.0 + e)).abs() < 1e-9);
/// let e_out = solve_law(&calibrated.law, &options)?.summary.e_out;
/// assert!((e_out - 0.6).abs() < 1e-6);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn calibrate(model: ForceModel, params: &ImpactParams) -> Result<Calibrated, CalibrationError> {
    calibrate_with(model, params, |d| model.law_with_damping(params, d))
}

/// [`calibrate`] with the law of `model`'s row built by `law_with` from the damping value, for a
/// law whose other constants are not the row builder's own (an engine's printed stiffness or
/// Adams' printed depth d, src/model/engine): the damping found is the one that realises e with
/// those constants.
pub fn calibrate_with(
    model: ForceModel,
    params: &ImpactParams,
    law_with: impl Fn(f64) -> Result<AnyLaw, ModelError>,
) -> Result<Calibrated, CalibrationError> {
    let target = params.restitution;
    let Some(param) = model.spec().damping else {
        return Err(CalibrationError::NoDamping(model));
    };
    let build = |d: f64| {
        law_with(d).map_err(|e| CalibrationError::Solve {
            model,
            symbol: param.symbol,
            damping: d,
            source: ImpactError::InvalidInput(e),
        })
    };
    if model.spec().family == Family::HuntCrossley {
        let chi = hunt_crossley_chi(target).ok_or(CalibrationError::Unreachable {
            model,
            target,
            lowest: 0.0,
            symbol: param.symbol,
            damping: f64::INFINITY,
        })?;
        let law = build(chi)?;
        return Ok(Calibrated {
            law,
            damping: Damping { param, value: chi },
            e_out: hunt_crossley_restitution(chi),
        });
    }
    if model == THORNTON {
        // Thornton's e(V) is closed-form on spheres, a quadrature and a root on line contacts.
        let v_yield = Thornton::v_yield_for_restitution(params, target).ok_or_else(|| {
            CalibrationError::Unreachable {
                model,
                target,
                lowest: Thornton::lowest_restitution(params),
                symbol: param.symbol,
                damping: 0.0,
            }
        })?;
        let law = build(v_yield)?;
        return Ok(Calibrated {
            law,
            damping: Damping {
                param,
                value: v_yield,
            },
            e_out: Thornton::restitution_of(params, v_yield),
        });
    }
    let opts = SolveOptions {
        method: MethodChoice::Auto,
        rtol: SOLVE_RTOL,
        ..SolveOptions::default()
    };
    let e_out = |d: f64| -> Result<f64, CalibrationError> {
        let law = build(d)?;
        match solve_law(&law, &opts) {
            Ok(s) => Ok(s.summary.e_out),
            // A law allowed to pull, damped beyond critical, creeps back without ever reaching
            // x = 0: the bodies do not separate, a rebound of 0.
            Err(ImpactError::NoSeparation { .. }) => Ok(0.0),
            Err(source) => Err(CalibrationError::Solve {
                model,
                symbol: param.symbol,
                damping: d,
                source,
            }),
        }
    };
    if model == THORNTON {
        // e_out rises with v_y, to 1 at v_y = v₀.
        return bracketed(
            model,
            param,
            target,
            1e-9 * params.v0,
            params.v0,
            &e_out,
            &build,
        );
    }
    if target == 1.0 {
        let law = build(0.0)?;
        return Ok(Calibrated {
            law,
            damping: Damping { param, value: 0.0 },
            e_out: e_out(0.0)?,
        });
    }
    // Zero damping rebounds elastically (e_out = 1 > target); double the scene's default until the
    // rebound falls below the target.
    let start = model
        .law(params)
        .ok()
        .and_then(|l| l.damping())
        .map(|d| d.value)
        .filter(|&d| d > 0.0)
        .unwrap_or(1.0);
    let (mut lo, mut hi) = (0.0, start);
    let mut lowest = 1.0;
    let mut reached = false;
    for _ in 0..MAX_DOUBLINGS {
        let e = e_out(hi)?;
        if e < target {
            reached = true;
            break;
        }
        lowest = e.min(lowest);
        lo = hi;
        hi *= 2.0;
    }
    if !reached {
        return Err(CalibrationError::Unreachable {
            model,
            target,
            lowest,
            symbol: param.symbol,
            damping: lo,
        });
    }
    bracketed(model, param, target, lo, hi, &e_out, &build).map_err(|e| match e {
        CalibrationError::Unreachable { damping, .. } => CalibrationError::Unreachable {
            model,
            target,
            lowest,
            symbol: param.symbol,
            damping,
        },
        other => other,
    })
}

/// The damping in [lo, hi] (e_out − target changing sign there) at which e_out = target.
fn bracketed(
    model: ForceModel,
    param: DampingParam,
    target: f64,
    lo: f64,
    hi: f64,
    e_out: &dyn Fn(f64) -> Result<f64, CalibrationError>,
    build: &dyn Fn(f64) -> Result<AnyLaw, CalibrationError>,
) -> Result<Calibrated, CalibrationError> {
    let mut failure = None;
    let root = brent(
        |d| match e_out(d) {
            Ok(e) => e - target,
            Err(err) => {
                failure.get_or_insert(err);
                f64::NAN
            }
        },
        lo,
        hi,
    );
    if let Some(err) = failure {
        return Err(err);
    }
    let d = root.ok_or(CalibrationError::Unreachable {
        model,
        target,
        lowest: f64::NAN,
        symbol: param.symbol,
        damping: hi,
    })?;
    let law = build(d)?;
    Ok(Calibrated {
        law,
        damping: Damping { param, value: d },
        e_out: e_out(d)?,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_restitution_relation_holds_and_inverts() {
        // ln((1 + χ)/(1 − χ·e)) = χ(1 + e) at the realised e, and χ(e) inverts e(χ) to 1e-12.
        // 1 − χ·e is w of the unloading root, kept apart because it is tiny at large χ.
        for chi in [1e-6, 1e-3, 0.1, 0.97487, 3.0, 40.0] {
            let e = hunt_crossley_restitution(chi);
            let (_, w) = unloading_root(y_minus_log1p(chi));
            let lhs = ((1.0 + chi) / w).ln();
            assert!((lhs / (chi * (1.0 + e)) - 1.0).abs() < 1e-9, "{chi}: {e}");
            let back = hunt_crossley_chi(e).unwrap();
            assert!((back / chi - 1.0).abs() < 1e-9, "{chi}: {back}");
        }
        // The published value e = 0.6 → χ = 0.97487 (Carvalho & Martins 2019).
        assert!((hunt_crossley_chi(0.6).unwrap() - 0.97487).abs() < 5e-6);
        assert_eq!(hunt_crossley_chi(1.0), Some(0.0));
        assert_eq!(hunt_crossley_chi(0.0), None);
        assert_eq!(hunt_crossley_chi(f64::NAN), None);
    }

    #[test]
    fn the_asymptotes_of_chi() {
        // χ → 3(1−e)/2 as e → 1 and χ·e → 1 as e → 0.
        let near_one = hunt_crossley_chi(1.0 - 1e-6).unwrap();
        assert!((near_one / 1.5e-6 - 1.0).abs() < 1e-5, "{near_one}");
        let near_zero = hunt_crossley_chi(1e-4).unwrap();
        assert!((near_zero * 1e-4 - 1.0).abs() < 1e-2, "{near_zero}");
    }
}
