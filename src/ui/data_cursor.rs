//! The data cursor of the explorer's charts: a place along the x axis (`<` `>` move it, Esc hides
//! it) and each curve's value there, read from the solver's dense output — at a time directly,
//! at an approach x by locating every time the curve passes x (loading and unloading).

use crate::chart::kind::ChartKind;
use crate::model::impact::{ImpactSolution, Sample};

/// Steps of the cursor along the axis: per mille of its length.
pub const FULL: u16 = 1000;
/// One press of `,` or `.`.
pub const STEP: u16 = 10;
/// One press of `<` or `>`: ten steps.
pub const FAST_STEP: u16 = 10 * STEP;

/// The cursor moved by one step, or ten when `fast` (or placed mid-axis when hidden), within
/// the axis.
pub fn moved(at: Option<u16>, forward: bool, fast: bool) -> u16 {
    let step = if fast { FAST_STEP } else { STEP };
    match at {
        None => FULL / 2,
        Some(p) if forward => (p + step).min(FULL),
        Some(p) => p.saturating_sub(step),
    }
}

/// Bisections of a crossing: the bracket shrinks to 2⁻⁶⁰ of a sample interval, below f64.
const BISECTIONS: usize = 60;

/// The states of `solution` where the x quantity of `kind` equals `x` (SI): one at a time t on
/// F(t); on F(x) and v(x) every time the approach passes x, located on the dense output by
/// bisection between the samples that bracket it.
pub fn read(kind: ChartKind, solution: &ImpactSolution, samples: &[Sample], x: f64) -> Vec<Sample> {
    let trajectory = &solution.trajectory;
    if kind == ChartKind::ForceTime {
        return if (0.0..=trajectory.t_end()).contains(&x) {
            vec![trajectory.at(x)]
        } else {
            Vec::new()
        };
    }
    let mut found: Vec<Sample> = Vec::new();
    for w in samples.windows(2) {
        let (a, b) = (w[0], w[1]);
        // Bracketed: the two samples on either side of x (NaN brackets nothing).
        let bracketed = (a.x - x) * (b.x - x) <= 0.0;
        if !bracketed || a.x == b.x {
            continue;
        }
        let (mut lo, mut hi) = (a.t, b.t);
        let rising = b.x > a.x;
        for _ in 0..BISECTIONS {
            let mid = 0.5 * (lo + hi);
            if (trajectory.at(mid).x < x) == rising {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        let at = trajectory.at(0.5 * (lo + hi));
        // A crossing exactly on a sample is found from both sides: keep it once.
        if found
            .last()
            .is_none_or(|f| (f.t - at.t).abs() > 1e-9 * trajectory.t_end())
        {
            found.push(at);
        }
    }
    found
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::ForceModel;
    use crate::model::impact::{SolveOptions, solve_impact};
    use crate::ui::testing::fig5_params;

    /// Every reading is the model's own state there: on the dense output at x to 1e-12 of x_max,
    /// F the law's force; one reading on loading and one on unloading below x_max.
    #[test]
    fn readings_are_the_solution_where_the_curve_passes() {
        let params = fig5_params(0.3);
        let solution =
            solve_impact(ForceModel::HuntCrossley, &params, &SolveOptions::default()).unwrap();
        let samples = solution.trajectory.samples(300);
        let s = &solution.summary;
        let x = 0.5 * s.x_max;
        let readings = read(ChartKind::ForceDisplacement, &solution, &samples, x);
        assert_eq!(readings.len(), 2, "{readings:?}");
        for r in &readings {
            assert!((r.x - x).abs() <= 1e-12 * s.x_max, "{r:?}");
            let exact = solution.trajectory.at(r.t);
            assert_eq!(exact.f, r.f);
        }
        // Loading (v > 0) pushes harder than unloading: Hunt–Crossley's damping.
        assert!(readings[0].v > 0.0 && readings[1].v < 0.0);
        assert!(readings[0].f > readings[1].f);
        // Beyond x_max, nothing; on F(t), the state at that time.
        assert!(
            read(
                ChartKind::ForceDisplacement,
                &solution,
                &samples,
                1.1 * s.x_max
            )
            .is_empty()
        );
        let t = 0.3 * s.t_contact;
        let at_t = read(ChartKind::ForceTime, &solution, &samples, t);
        assert_eq!(at_t, vec![solution.trajectory.at(t)]);
    }

    #[test]
    fn the_cursor_steps_within_the_axis() {
        assert_eq!(moved(None, true, false), 500);
        assert_eq!(moved(Some(995), true, false), 1000);
        assert_eq!(moved(Some(5), false, false), 0);
        assert_eq!(moved(Some(500), false, false), 490);
        assert_eq!(moved(Some(500), true, true), 600, "ten steps at once");
        assert_eq!(moved(Some(950), true, true), 1000);
        assert_eq!(moved(Some(50), false, true), 0);
    }
}
