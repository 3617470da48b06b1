//! The trajectory of one impact as CSV, for `solve --format csv` and the explorer's export alike:
//! the header `t,x,v,F`, then one row per sample in SI units (s, m, m/s, N) at full precision.

use std::fmt::{Display, Write as _};

use crate::model::impact::{ImpactSolution, Sample};

/// A CSV field as text: quoted (quotes doubled) when it holds a comma, a quote or a newline.
pub fn field(text: &str) -> String {
    if text.contains([',', '"', '\n']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_string()
    }
}

/// The header row: time (s), displacement (m), velocity (m/s), force (N).
pub const HEADER: &str = "t,x,v,F";

/// `points` samples of the trajectory (plus its exact extrema) under [`HEADER`]; refuses a
/// non-finite sample rather than write NaN into someone's plot.
pub fn trajectory_csv(solution: &ImpactSolution, points: usize) -> Result<String, String> {
    samples_csv(solution.summary.model, &solution.trajectory.samples(points))
}

/// [`trajectory_csv`] of given samples of `model`'s trajectory (named in the error).
pub fn samples_csv(model: impl Display, samples: &[Sample]) -> Result<String, String> {
    let mut out = format!("{HEADER}\n");
    for s in samples {
        if ![s.t, s.x, s.v, s.f].iter().all(|x| x.is_finite()) {
            return Err(format!(
                "the {model} trajectory has a non-finite sample at t = {:e} s",
                s.t
            ));
        }
        // Writing to a String cannot fail.
        let _ = writeln!(out, "{:e},{:e},{:e},{:e}", s.t, s.x, s.v, s.f);
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fields_with_commas_quotes_or_newlines_are_quoted() {
        assert_eq!(field("plain text"), "plain text");
        assert_eq!(field("a, b"), "\"a, b\"");
        assert_eq!(field("say \"hi\""), "\"say \"\"hi\"\"\"");
        assert_eq!(field("two\nlines"), "\"two\nlines\"");
    }
    use crate::model::ForceModel;

    fn sample(t: f64, x: f64, v: f64, f: f64) -> Sample {
        Sample { t, x, v, f }
    }

    #[test]
    fn rows_round_trip_in_si() {
        let samples = [
            sample(0.0, 0.0, 0.3, 0.0),
            sample(4.5e-5, 9.112e-6, 0.0, 403.25),
        ];
        let text = samples_csv(ForceModel::Proposed, &samples).unwrap();
        let mut lines = text.lines();
        assert_eq!(lines.next(), Some("t,x,v,F"));
        let rows: Vec<Vec<f64>> = lines
            .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
            .collect();
        assert_eq!(
            rows,
            [[0.0, 0.0, 0.3, 0.0], [4.5e-5, 9.112e-6, 0.0, 403.25]]
        );
        assert_eq!(samples_csv(ForceModel::Proposed, &[]).unwrap(), "t,x,v,F\n");
    }

    #[test]
    fn non_finite_samples_are_refused_with_model_and_time() {
        for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            let samples = [sample(0.0, 0.0, 0.3, 0.0), sample(2e-5, 1e-6, 0.1, bad)];
            let err = samples_csv(ForceModel::HuntCrossley, &samples).unwrap_err();
            assert_eq!(
                err,
                format!(
                    "the {} trajectory has a non-finite sample at t = 2e-5 s",
                    ForceModel::HuntCrossley
                )
            );
        }
    }
}
