//! Measured restitution: impact velocity and coefficient of restitution, with an optional
//! standard deviation per point, checked before any fit (docs/fitting.md).
#![warn(missing_docs)]

use serde::Serialize;
use thiserror::Error;

/// One measurement: e at impact velocity v. Repeats (several samples at one v) are allowed.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RestitutionSample {
    /// Impact velocity, m/s (> 0).
    pub v: f64,
    /// Coefficient of restitution, in (0, 1].
    pub e: f64,
    /// Standard deviation of e, > 0, when known.
    pub sd: Option<f64>,
    /// The line of the file it came from (1-based), 0 when not from a file.
    pub line: usize,
}

/// A checked set of restitution measurements (see [`RestitutionData::new`]).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RestitutionData {
    /// The samples, in the order given (not sorted: e(v) data need not be monotone).
    pub points: Vec<RestitutionSample>,
    /// Where they came from (a file name), for messages.
    pub source: Option<String>,
}

/// Why restitution data was refused; every variant names the line (0 when not from a file).
#[derive(Debug, Clone, PartialEq, Error)]
pub enum FitDataError {
    /// No samples at all.
    #[error("no data points")]
    Empty,
    /// A value is NaN or infinite.
    #[error("line {line}: {field} = {value} is not a finite number")]
    NotFinite {
        /// The line.
        line: usize,
        /// `v`, `e` or `sd`.
        field: &'static str,
        /// The value.
        value: f64,
    },
    /// v ≤ 0.
    #[error("line {line}: impact velocity v = {v} m/s must be > 0")]
    Velocity {
        /// The line.
        line: usize,
        /// The velocity, m/s.
        v: f64,
    },
    /// e outside (0, 1].
    #[error("line {line}: restitution e = {e} must be in (0, 1]")]
    Restitution {
        /// The line.
        line: usize,
        /// The restitution.
        e: f64,
    },
    /// sd ≤ 0.
    #[error("line {line}: standard deviation sd = {sd} must be > 0")]
    Sd {
        /// The line.
        line: usize,
        /// The standard deviation.
        sd: f64,
    },
    /// Some samples give sd and others do not: weights would mix two kinds of residual.
    #[error(
        "line {line}: no sd, while line {with_sd} gives one (give sd on every line or on none)"
    )]
    MixedSd {
        /// The first line without sd.
        line: usize,
        /// The first line with sd.
        with_sd: usize,
    },
    /// Fewer points than a law has parameters, plus one for the noise when no sd is given.
    #[error(
        "{points} data point(s) cannot fit {law}: it needs {needed} (its parameters, and one more for the noise unless sd is given)"
    )]
    TooFewPoints {
        /// Samples.
        points: usize,
        /// Samples needed.
        needed: usize,
        /// The law.
        law: String,
    },
}

impl FitDataError {
    /// The line the error is about, 0 when it concerns the whole set.
    pub fn line(&self) -> usize {
        match self {
            FitDataError::Empty | FitDataError::TooFewPoints { .. } => 0,
            FitDataError::NotFinite { line, .. }
            | FitDataError::Velocity { line, .. }
            | FitDataError::Restitution { line, .. }
            | FitDataError::Sd { line, .. }
            | FitDataError::MixedSd { line, .. } => *line,
        }
    }
}

impl RestitutionSample {
    /// Checks one sample: finite, v > 0, e in (0, 1], sd > 0 if given.
    pub fn validate(&self) -> Result<(), FitDataError> {
        let line = self.line;
        for (field, value) in [("v", self.v), ("e", self.e)]
            .into_iter()
            .chain(self.sd.map(|sd| ("sd", sd)))
        {
            if !value.is_finite() {
                return Err(FitDataError::NotFinite { line, field, value });
            }
        }
        if self.v <= 0.0 {
            return Err(FitDataError::Velocity { line, v: self.v });
        }
        if !(self.e > 0.0 && self.e <= 1.0) {
            return Err(FitDataError::Restitution { line, e: self.e });
        }
        if let Some(sd) = self.sd.filter(|&sd| sd <= 0.0) {
            return Err(FitDataError::Sd { line, sd });
        }
        Ok(())
    }
}

impl RestitutionData {
    /// Checks every sample ([`RestitutionSample::validate`]), that there is at least one, and
    /// that sd is given on all of them or on none.
    pub fn new(points: Vec<RestitutionSample>) -> Result<Self, FitDataError> {
        if points.is_empty() {
            return Err(FitDataError::Empty);
        }
        for p in &points {
            p.validate()?;
        }
        if let Some(with) = points.iter().find(|p| p.sd.is_some())
            && let Some(without) = points.iter().find(|p| p.sd.is_none())
        {
            return Err(FitDataError::MixedSd {
                line: without.line,
                with_sd: with.line,
            });
        }
        Ok(RestitutionData {
            points,
            source: None,
        })
    }

    /// The same data, saying where it came from.
    pub fn with_source(mut self, source: impl Into<String>) -> Self {
        self.source = Some(source.into());
        self
    }

    /// Samples from (v, e) pairs without sd, numbered as lines 1, 2, …
    pub fn from_pairs(pairs: &[(f64, f64)]) -> Result<Self, FitDataError> {
        Self::new(
            pairs
                .iter()
                .enumerate()
                .map(|(i, &(v, e))| RestitutionSample {
                    v,
                    e,
                    sd: None,
                    line: i + 1,
                })
                .collect(),
        )
    }

    /// Number of samples.
    pub fn len(&self) -> usize {
        self.points.len()
    }

    /// Never true for checked data; for clippy's sake.
    pub fn is_empty(&self) -> bool {
        self.points.is_empty()
    }

    /// Every sample gives its sd (then fits are weighted by 1/sd²).
    pub fn weighted(&self) -> bool {
        self.points.iter().all(|p| p.sd.is_some())
    }

    /// The lowest and highest velocity, m/s.
    pub fn v_range(&self) -> (f64, f64) {
        self.points
            .iter()
            .fold((f64::INFINITY, 0.0f64), |(lo, hi), p| {
                (lo.min(p.v), hi.max(p.v))
            })
    }

    /// Samples sorted by v (a copy), for starting values and figures.
    pub fn sorted_by_v(&self) -> Vec<RestitutionSample> {
        let mut out = self.points.clone();
        out.sort_by(|a, b| a.v.total_cmp(&b.v));
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample(v: f64, e: f64, sd: Option<f64>, line: usize) -> RestitutionSample {
        RestitutionSample { v, e, sd, line }
    }

    #[test]
    fn bad_samples_name_their_line() {
        let cases = [
            (sample(0.0, 0.5, None, 3), "line 3: impact velocity v = 0"),
            (sample(1.0, 0.0, None, 4), "line 4: restitution e = 0"),
            (sample(1.0, 1.2, None, 5), "line 5: restitution e = 1.2"),
            (sample(f64::NAN, 0.5, None, 6), "line 6: v = NaN"),
            (sample(1.0, 0.5, Some(0.0), 7), "line 7: standard deviation"),
        ];
        for (s, msg) in cases {
            let good = sample(1.0, 0.5, s.sd.map(|_| 0.01), 2);
            let err = RestitutionData::new(vec![good, s]).unwrap_err();
            assert!(err.to_string().starts_with(msg), "{err}");
            assert_eq!(err.line(), s.line);
        }
        assert_eq!(RestitutionData::new(vec![]), Err(FitDataError::Empty));
        let mixed = RestitutionData::new(vec![
            sample(1.0, 0.5, Some(0.01), 2),
            sample(2.0, 0.4, None, 3),
        ]);
        assert_eq!(
            mixed,
            Err(FitDataError::MixedSd {
                line: 3,
                with_sd: 2
            })
        );
    }

    #[test]
    fn repeats_and_non_monotone_e_are_data() {
        let d = RestitutionData::from_pairs(&[(1.0, 0.5), (1.0, 0.52), (0.5, 0.7), (2.0, 0.8)])
            .unwrap();
        assert_eq!(d.len(), 4);
        assert_eq!(d.v_range(), (0.5, 2.0));
        assert!(!d.weighted());
        assert_eq!(d.points[1].line, 2);
    }
}
