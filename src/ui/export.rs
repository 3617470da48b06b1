//! Export of a model's trajectory as CSV (SI units, full precision).

use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};

use crate::model::ForceModel;
use crate::model::impact::Sample;

/// Samples written per export (the true extrema are inserted by the trajectory).
pub const EXPORT_SAMPLES: usize = 1000;

/// The CSV text of `samples`: a header, then one row per sample in SI units.
pub fn csv(samples: &[Sample]) -> String {
    let mut out = String::from("t_s,x_m,v_m_per_s,force_N\n");
    for s in samples {
        // Writing to a String cannot fail.
        let _ = writeln!(out, "{:e},{:e},{:e},{:e}", s.t, s.x, s.v, s.f);
    }
    out
}

/// The default file name for a model's export: `<scene>-<model>.csv`.
pub fn default_path(scene_name: &str, model: ForceModel) -> PathBuf {
    let stem: String = scene_name
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '-' {
                c
            } else {
                '-'
            }
        })
        .collect();
    let stem = stem.trim_matches('-');
    let stem = if stem.is_empty() { "scene" } else { stem };
    PathBuf::from(format!("{stem}-{}.csv", model.name()))
}

/// Writes `samples` to `path`; the message names the file.
pub fn write(path: &Path, samples: &[Sample]) -> Result<(), String> {
    fs::write(path, csv(samples)).map_err(|e| format!("cannot write {}: {e}", path.display()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_round_trip_in_si() {
        let samples = [
            Sample {
                t: 0.0,
                x: 0.0,
                v: 0.3,
                f: 0.0,
            },
            Sample {
                t: 4.5e-5,
                x: 9.112e-6,
                v: 0.0,
                f: 403.25,
            },
        ];
        let text = csv(&samples);
        let mut lines = text.lines();
        assert_eq!(lines.next(), Some("t_s,x_m,v_m_per_s,force_N"));
        let row: Vec<f64> = lines
            .nth(1)
            .unwrap()
            .split(',')
            .map(|v| v.parse().unwrap())
            .collect();
        assert_eq!(row, [4.5e-5, 9.112e-6, 0.0, 403.25]);
    }

    #[test]
    fn default_names_are_file_friendly() {
        assert_eq!(
            default_path("fig5-steel-sphere-r10-plate", ForceModel::Proposed),
            PathBuf::from("fig5-steel-sphere-r10-plate-proposed.csv")
        );
        assert_eq!(
            default_path("Fig. 5", ForceModel::HuntCrossley),
            PathBuf::from("Fig--5-hunt-crossley.csv")
        );
        assert_eq!(
            default_path("", ForceModel::Quasistatic),
            PathBuf::from("scene-quasistatic.csv")
        );
    }

    #[test]
    fn write_reports_the_path_on_failure() {
        let err = write(Path::new("/nonexistent-dir/x.csv"), &[]).unwrap_err();
        assert!(
            err.starts_with("cannot write /nonexistent-dir/x.csv"),
            "{err}"
        );
    }
}
