//! Bad restitution data gets a clear error naming the file and line (issue 23, item 5): the CSV
//! reader's refusals, and data too small for a law.

use hertz_tui::format::fit_csv::parse_restitution_csv;
use hertz_tui::model::fit::{
    Candidate, FitError, FitOptions, RestitutionData, fit_restitution_params,
};

use super::fit_common::params;

#[test]
fn bad_files_are_refused_with_file_and_line() {
    let cases = [
        ("v (m/s), sd\n0.1, 0.01\n", "data.csv:1: missing column e"),
        (
            "v, e\n0.1, 0.9\n0, 0.8\n",
            "data.csv:3: impact velocity v = 0 m/s must be > 0",
        ),
        (
            "v, e\n0.1, 1.01\n",
            "data.csv:2: restitution e = 1.01 must be in (0, 1]",
        ),
        (
            "v, e\n0.1, nan\n",
            "data.csv:2: e = NaN is not a finite number",
        ),
        ("v, e\n0.1\n", "data.csv:2: 1 field(s), the header has 2"),
    ];
    for (text, message) in cases {
        let err = parse_restitution_csv(text, "data.csv")
            .unwrap_err()
            .to_string();
        assert!(err.starts_with(message), "{text:?}: {err}");
    }
    // Non-monotone e(v) is data, not an error.
    let ok = parse_restitution_csv("v, e\n0.1, 0.8\n0.2, 0.9\n0.3, 0.7\n", "data.csv").unwrap();
    assert_eq!(ok.len(), 3);
}

#[test]
fn too_few_points_fail_the_law_and_say_how_many_it_needs() {
    let p = params();
    let hc = Candidate::from_id("hunt-crossley").unwrap();
    // One point without sd: a's value but no noise estimate.
    let one = RestitutionData::from_pairs(&[(0.3, 0.8)]).unwrap();
    let err = fit_restitution_params(&p, &one, &[hc], &FitOptions::default()).unwrap_err();
    let FitError::NothingFitted(failed) = &err else {
        panic!("{err}");
    };
    assert!(
        failed[0]
            .1
            .contains("1 data point(s) cannot fit hunt-crossley: it needs 2"),
        "{err}"
    );
    // With sd given one point determines one parameter.
    let mut weighted = one.clone();
    weighted.points[0].sd = Some(0.01);
    let report = fit_restitution_params(&p, &weighted, &[hc], &FitOptions::default()).unwrap();
    assert!((report.fits[0].predict_params(&p, 0.3).unwrap() - 0.8).abs() < 1e-9);
    // An elastic law is refused with its reason.
    let elastic = Candidate::from_id("quasistatic").unwrap();
    let two = RestitutionData::from_pairs(&[(0.3, 0.8), (0.6, 0.7)]).unwrap();
    let report = fit_restitution_params(&p, &two, &[hc, elastic], &FitOptions::default()).unwrap();
    assert!(
        report.failed[0].1.contains("no dissipation"),
        "{:?}",
        report.failed
    );
}
