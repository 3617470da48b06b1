//! A measured trace over one impact: time and force, or time and displacement, in SI units, with
//! the line of the file each sample came from (docs/fitting.md, Traces).

use serde::Serialize;
use thiserror::Error;

/// What a trace measures.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum TraceQuantity {
    /// The contact force F, N (a force cell under the plate, an instrumented impactor).
    Force,
    /// The approach x of the bodies' centres from first touch, m (a laser vibrometer or a
    /// high-speed camera): negative before contact, as the bodies close in.
    Displacement,
}

impl TraceQuantity {
    /// The symbol, `F` or `x`.
    pub fn symbol(self) -> &'static str {
        match self {
            TraceQuantity::Force => "F",
            TraceQuantity::Displacement => "x",
        }
    }

    /// The SI unit, `N` or `m`.
    pub fn unit(self) -> &'static str {
        match self {
            TraceQuantity::Force => "N",
            TraceQuantity::Displacement => "m",
        }
    }
}

/// One sample: time, s, and the measured value, N or m.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TraceSample {
    /// Time, s, on the recording's own clock (contact starts at the fitted t₀).
    pub t: f64,
    /// F, N, or x, m.
    pub value: f64,
    /// The line of the file (1-based; 0 for samples not read from a file).
    pub line: usize,
}

/// Why a trace is refused; each names the line it is about where there is one (the CSV reader
/// adds the file).
#[derive(Debug, Clone, PartialEq, Error)]
pub enum TraceDataError {
    /// A time or value that is NaN or infinite.
    #[error("line {line}: {column} is {value}, not a finite number")]
    NotFinite {
        /// The line.
        line: usize,
        /// `t` or the quantity's symbol.
        column: &'static str,
        /// The value read.
        value: f64,
    },
    /// Times must increase strictly from one sample to the next.
    #[error(
        "line {line}: t = {t:e} s does not increase on the previous sample's t = {previous:e} s (line {previous_line})"
    )]
    NotMonotone {
        /// The line of the offending sample.
        line: usize,
        /// Its time, s.
        t: f64,
        /// The previous sample's time, s.
        previous: f64,
        /// The previous sample's line.
        previous_line: usize,
    },
    /// No sample shows contact: the force (or approach) is never positive.
    #[error(
        "no contact in the trace: no sample has {symbol} > 0 (the largest is {largest:e} {unit})"
    )]
    NoContact {
        /// `F` or `x`.
        symbol: &'static str,
        /// `N` or `m`.
        unit: &'static str,
        /// The largest value, in that unit.
        largest: f64,
    },
    /// Fewer samples than a fit needs.
    #[error("{points} samples: fewer than the {needed} a trace needs")]
    TooFewPoints {
        /// The samples given.
        points: usize,
        /// The least number.
        needed: usize,
    },
    /// Fewer samples than a law's fit has parameters, plus one (the residual variance needs a
    /// degree of freedom).
    #[error(
        "{file}: {points} samples cannot determine the {params} parameters of {law} and leave a degree of freedom: give at least {} samples or free fewer parameters",
        params + 1
    )]
    TooFewForLaw {
        /// The file, or `the trace`.
        file: String,
        /// The samples given.
        points: usize,
        /// The law's parameters in this fit.
        params: usize,
        /// The law.
        law: &'static str,
    },
}

impl TraceDataError {
    /// The line the error is about, 0 when it concerns the whole trace.
    pub fn line(&self) -> usize {
        match self {
            TraceDataError::NotFinite { line, .. } | TraceDataError::NotMonotone { line, .. } => {
                *line
            }
            TraceDataError::NoContact { .. }
            | TraceDataError::TooFewPoints { .. }
            | TraceDataError::TooFewForLaw { .. } => 0,
        }
    }
}

/// A validated trace: at least [`TraceData::MIN_POINTS`] samples, finite, times strictly
/// increasing, and some contact (a positive value).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TraceData {
    /// What the values are.
    pub quantity: TraceQuantity,
    /// The samples, in time order.
    pub samples: Vec<TraceSample>,
    /// Where the trace came from (a file name), for messages.
    pub source: Option<String>,
}

impl TraceData {
    /// The fewest samples of any trace: a shape needs a rise and a fall. A fit needs more than
    /// it has parameters too, which [`super::fit_trace`] checks per law.
    pub const MIN_POINTS: usize = 3;

    /// Checks the samples (see the type) and keeps them.
    pub fn new(
        quantity: TraceQuantity,
        samples: Vec<TraceSample>,
        source: Option<String>,
    ) -> Result<Self, TraceDataError> {
        let data = TraceData {
            quantity,
            samples,
            source,
        };
        data.validate()?;
        Ok(data)
    }

    /// The checks of [`TraceData::new`], again (the fields are public: a fit re-checks them).
    pub fn validate(&self) -> Result<(), TraceDataError> {
        let (quantity, samples) = (self.quantity, &self.samples);
        for s in samples {
            if !s.t.is_finite() {
                return Err(TraceDataError::NotFinite {
                    line: s.line,
                    column: "t",
                    value: s.t,
                });
            }
            if !s.value.is_finite() {
                return Err(TraceDataError::NotFinite {
                    line: s.line,
                    column: quantity.symbol(),
                    value: s.value,
                });
            }
        }
        if let Some(w) = samples.windows(2).find(|w| w[1].t <= w[0].t) {
            return Err(TraceDataError::NotMonotone {
                line: w[1].line,
                t: w[1].t,
                previous: w[0].t,
                previous_line: w[0].line,
            });
        }
        if samples.len() < Self::MIN_POINTS {
            return Err(TraceDataError::TooFewPoints {
                points: samples.len(),
                needed: Self::MIN_POINTS,
            });
        }
        let largest = samples
            .iter()
            .map(|s| s.value)
            .fold(f64::NEG_INFINITY, f64::max);
        if largest <= 0.0 {
            return Err(TraceDataError::NoContact {
                symbol: quantity.symbol(),
                unit: quantity.unit(),
                largest,
            });
        }
        Ok(())
    }

    /// A trace from (t, value) pairs, numbered as lines 1, 2, … (synthetic data, tests).
    pub fn from_pairs(
        quantity: TraceQuantity,
        pairs: impl IntoIterator<Item = (f64, f64)>,
    ) -> Result<Self, TraceDataError> {
        let samples = pairs
            .into_iter()
            .enumerate()
            .map(|(i, (t, value))| TraceSample {
                t,
                value,
                line: i + 1,
            })
            .collect();
        Self::new(quantity, samples, None)
    }

    /// The sample times, s.
    pub fn times(&self) -> Vec<f64> {
        self.samples.iter().map(|s| s.t).collect()
    }

    /// The measured values, N or m.
    pub fn values(&self) -> Vec<f64> {
        self.samples.iter().map(|s| s.value).collect()
    }

    /// The sample with the largest value (the peak of the trace).
    pub fn peak(&self) -> TraceSample {
        // `new` refused an empty trace.
        self.samples
            .iter()
            .copied()
            .max_by(|a, b| a.value.total_cmp(&b.value))
            .unwrap_or(TraceSample {
                t: 0.0,
                value: 0.0,
                line: 0,
            })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bad_traces_name_their_line() {
        let q = TraceQuantity::Force;
        let nan = TraceData::from_pairs(q, [(0.0, 0.0), (1.0, f64::NAN), (2.0, 1.0)]);
        assert!(matches!(
            nan,
            Err(TraceDataError::NotFinite {
                line: 2,
                column: "F",
                ..
            })
        ));
        let back = TraceData::from_pairs(q, [(0.0, 0.0), (1.0, 1.0), (1.0, 2.0)]).unwrap_err();
        assert_eq!(
            back.to_string(),
            "line 3: t = 1e0 s does not increase on the previous sample's t = 1e0 s (line 2)"
        );
        let flat = TraceData::from_pairs(q, [(0.0, 0.0), (1.0, -1.0), (2.0, 0.0)]).unwrap_err();
        assert!(
            flat.to_string()
                .starts_with("no contact in the trace: no sample has F > 0")
        );
        let short = TraceData::from_pairs(q, [(0.0, 0.0), (1.0, 1.0)]).unwrap_err();
        assert!(matches!(
            short,
            TraceDataError::TooFewPoints { points: 2, .. }
        ));
        let ok = TraceData::from_pairs(q, [(0.0, 0.0), (1.0, 3.0), (2.0, 1.0)]).unwrap();
        assert_eq!(ok.peak().line, 2);
    }
}
