//! `solve`'s restitution fields and `--calibrate`, through the real binary.

use hertz_tui::model::ForceModel;

use crate::commands::{json, ok};

const FIG5: &str = "fig5-steel-sphere-r10-plate";

#[test]
fn solve_reports_the_requested_and_realised_e_and_the_damping_used() {
    let v = json(&["solve", "--scene", FIG5]);
    let rows = v["impacts"].as_array().unwrap();
    assert_eq!(rows.len(), ForceModel::ALL.len());
    for row in rows {
        assert_eq!(row["e_requested"], 0.6, "{row}");
        assert_eq!(row["calibrated"], false);
        let model: ForceModel = row["model"].as_str().unwrap().parse().unwrap();
        match model.spec().damping {
            None => assert!(row["damping"].is_null(), "{row}"),
            Some(param) => {
                assert_eq!(row["damping"]["parameter"], param.key, "{row}");
                assert_eq!(row["damping"]["unit"], param.unit, "{row}");
                assert!(row["damping"]["value"].as_f64().unwrap() > 0.0, "{row}");
            }
        }
    }
    // Fig. 5 keeps a dent: the proposed model, with its reason.
    assert_eq!(v["recommendation"]["model"], "proposed");
    assert!(
        v["recommendation"]["why"]
            .as_str()
            .unwrap()
            .contains("dent")
    );
    // Hunt–Crossley's χ = 3(1 − e)/2 (eq 19) and its realised e of the issue: 0.712, not 0.6.
    let hc = &rows[ForceModel::HuntCrossley.index()];
    assert!((hc["damping"]["value"].as_f64().unwrap() - 0.6).abs() < 1e-15);
    assert!((hc["e_out"].as_f64().unwrap() - 0.712).abs() < 5e-4, "{hc}");
}

#[test]
fn calibrate_makes_every_law_with_damping_rebound_with_the_requested_e() {
    let v = json(&[
        "solve",
        "--scene",
        FIG5,
        "--calibrate",
        "--set",
        "impact.restitution=0.3",
        "--rtol",
        "1e-12",
        "--atol",
        "1e-14",
    ]);
    for row in v["impacts"].as_array().unwrap() {
        let e = row["e_out"].as_f64().unwrap();
        if row["damping"].is_null() {
            // Nothing to calibrate: the law is elastic, e = 1 within the promise of 100·rtol
            // (exact where the law has a closed form, integrated otherwise).
            assert_eq!(row["calibrated"], false);
            assert!((e - 1.0).abs() <= 100.0 * 1e-12, "{row}");
            continue;
        }
        assert_eq!(row["calibrated"], true, "{row}");
        assert!((e / 0.3 - 1.0).abs() < 1e-9, "{row}");
        assert!(row["calibration_error"].is_null());
    }
    // Without a dent and at e = 0.3, the law whose own rule realises e, said in one line.
    let table = ok(&[
        "solve",
        "--scene",
        FIG5,
        "--set",
        "impact.restitution=0.3",
        "--set",
        "impact.plastic_indentation=0",
        "--model",
        "gonthier",
    ]);
    assert!(
        table.contains("Recommended: gonthier — ") && table.contains("realises e = 0.304"),
        "{table}"
    );
    // The table marks calibrated values with *.
    let table = ok(&[
        "solve",
        "--scene",
        FIG5,
        "--calibrate",
        "--model",
        "hunt-crossley",
    ]);
    assert!(table.contains("χ = 0.9749*"), "{table}");
}

#[test]
fn restitution_tabulates_the_realised_e_of_every_law() {
    let v = json(&["restitution", "--scene", FIG5]);
    let rows = v.as_array().unwrap();
    assert_eq!(rows.len(), ForceModel::ALL.len());
    for row in rows {
        let model: ForceModel = row["model"].as_str().unwrap().parse().unwrap();
        let points = row["points"].as_array().unwrap();
        let requested: Vec<f64> = points
            .iter()
            .map(|p| p["e_requested"].as_f64().unwrap())
            .collect();
        assert_eq!(requested, [0.1, 0.3, 0.5, 0.7, 0.9]);
        for p in points {
            let (e, e_out) = (
                p["e_requested"].as_f64().unwrap(),
                p["e_out"].as_f64().unwrap(),
            );
            match model.name() {
                // The bilateral linear law realises e exactly (docs/physics.md §6.3).
                "kelvin-voigt-tension" => assert!((e_out - e).abs() < 1e-12, "{row}"),
                "quasistatic" => assert_eq!(e_out, 1.0),
                _ => assert!(e_out > 0.0 && e_out <= 1.0, "{row}"),
            }
        }
    }
    // Hunt–Crossley realises 0.663 for 0.5 asked: the gap the calibration closes.
    let hc = &rows[ForceModel::HuntCrossley.index()]["points"][2];
    assert!((hc["e_out"].as_f64().unwrap() - 0.663).abs() < 5e-4, "{hc}");

    let csv = ok(&[
        "restitution",
        "--scene",
        FIG5,
        "--format",
        "csv",
        "--model",
        "flores",
    ]);
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(lines[0], "model,e_requested,e_out,error");
    assert_eq!(lines.len(), 6);
    assert!(lines[1].starts_with("flores,0.1,0.069"), "{csv}");
    let table = ok(&["restitution", "--scene", FIG5, "--model", "hunt-crossley"]);
    assert!(
        table.contains("e = 0.1") && table.contains("0.6630"),
        "{table}"
    );
}

#[test]
fn every_law_solves_and_calibrates_on_both_cylinder_presets() {
    // Issue 10's "on spheres and cylinders": no law refuses a line contact any more (Thornton's
    // caps the strip's pressure, docs/physics.md §6.6), and each one with a damping parameter
    // realises the scene's e = 0.6 once calibrated, to the default tolerance.
    for scene in ["steel-cylinder-r20-l100-plate", "steel-cylinders-r20-l100"] {
        for calibrated in [false, true] {
            let mut args = vec!["solve", "--scene", scene];
            if calibrated {
                args.push("--calibrate");
            }
            let v = json(&args);
            let rows = v["impacts"].as_array().unwrap();
            assert_eq!(rows.len(), ForceModel::ALL.len());
            for row in rows {
                assert!(row["error"].is_null(), "{scene}: {row}");
                assert!(row["calibration_error"].is_null(), "{scene}: {row}");
                let model: ForceModel = row["model"].as_str().unwrap().parse().unwrap();
                let e_out = row["e_out"].as_f64().unwrap();
                if calibrated && model.spec().damping.is_some() {
                    assert!((e_out - 0.6).abs() < 1e-4, "{scene}: {row}");
                }
            }
            if calibrated {
                // Thornton's v_y lowered until the rebound is 0.6: the strip yields and keeps a dent.
                let thornton = &rows[ForceModel::with_id("thornton").index()];
                assert!(thornton["x_residual"].as_f64().unwrap() > 0.0, "{thornton}");
            }
        }
    }
}
