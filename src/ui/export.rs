//! Export of a model's trajectory as CSV: [`crate::format::csv`], the rows `solve --format csv`
//! prints (header `t,x,v,F`, SI units, full precision, no non-finite sample); and of view 4's
//! sweep, as `sweep --format csv` prints it ([`crate::format::sweep_csv`]).

use std::fs;
use std::path::{Path, PathBuf};

use crate::format::csv::trajectory_csv;
use crate::format::sweep_csv::sweep_csv;
use crate::model::ForceModel;
use crate::model::impact::ImpactSolution;
use crate::model::scene_key::SceneKey;
use crate::model::study::runner::SweepData;

/// Samples written per export (the true extrema are inserted by the trajectory).
pub const EXPORT_SAMPLES: usize = 1000;

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

/// The default file name for the sweep of view 4: `<scene>-sweep-<key>.csv`
/// (`fig5-…-sweep-impact-v0.csv`).
pub fn default_sweep_path(scene_name: &str, key: SceneKey) -> PathBuf {
    let stem = default_path(scene_name, ForceModel::Proposed);
    let stem = stem.to_string_lossy();
    let scene = stem.trim_end_matches(&format!("-{}.csv", ForceModel::Proposed.name()));
    PathBuf::from(format!(
        "{scene}-sweep-{}.csv",
        key.path().replace('.', "-")
    ))
}

/// Writes the sweep to `path` as `sweep --format csv` prints it; the number of rows.
pub fn write_sweep(path: &Path, data: &SweepData) -> Result<usize, String> {
    let text = sweep_csv(&data.spec.key.path(), &data.spec.models, &data.rows);
    fs::write(path, &text).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    Ok(data.rows.len())
}

/// Writes the trajectory of `solution` to `path` and returns the number of rows; the message
/// names the file, or the sample that is not finite.
pub fn write(path: &Path, solution: &ImpactSolution) -> Result<usize, String> {
    let text = trajectory_csv(solution, EXPORT_SAMPLES)?;
    fs::write(path, &text).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    Ok(text.lines().count().saturating_sub(1))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::impact::{SolveOptions, solve_impact};
    use crate::ui::testing::fig5_params;

    fn solution() -> ImpactSolution {
        let params = fig5_params(0.3);
        solve_impact(ForceModel::HuntCrossley, &params, &SolveOptions::default()).unwrap()
    }

    #[test]
    fn writes_the_rows_solve_prints() {
        let solution = solution();
        let path = crate::ui::testing::temp_path("export.csv");
        let rows = write(&path, &solution).unwrap();
        let text = fs::read_to_string(&path).unwrap();
        assert_eq!(text, trajectory_csv(&solution, EXPORT_SAMPLES).unwrap());
        assert!(text.starts_with("t,x,v,F\n"));
        assert_eq!(rows, text.lines().count() - 1);
        assert!(rows >= EXPORT_SAMPLES);
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
        let err = write(Path::new("/nonexistent-dir/x.csv"), &solution()).unwrap_err();
        assert!(
            err.starts_with("cannot write /nonexistent-dir/x.csv"),
            "{err}"
        );
    }
}
