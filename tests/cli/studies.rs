//! The real binary's `bench` (work-precision, --stability) and `sweep` subcommands.

use std::process::Output;

use serde_json::Value;

use crate::support::run;

/// The stdout of a successful run (else the test fails with its stderr).
fn stdout_text(output: &Output) -> String {
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    String::from_utf8(output.stdout.clone()).expect("stdout is UTF-8")
}

fn stdout_json(output: &Output) -> Value {
    serde_json::from_str(&stdout_text(output)).expect("stdout is JSON")
}

const FIG5: &str = "fig5-steel-sphere-r10-plate";

#[test]
fn bench_rows_cover_every_method_with_the_documented_fields() {
    let rows = stdout_json(&run(&[
        "bench",
        "--scene",
        FIG5,
        "--model",
        "hunt-crossley",
        "--format",
        "json",
    ]));
    let rows = rows.as_array().expect("an array of rows");
    for method in [
        "euler",
        "symplectic-euler",
        "verlet",
        "rk4",
        "dopri5",
        "dop853",
        "radau5",
    ] {
        assert!(
            rows.iter().any(|r| r["method"] == method),
            "no row for {method}"
        );
    }
    for row in rows {
        assert!(
            row.get("rtol").is_some() != row.get("dt").is_some(),
            "{row}"
        );
        for key in [
            "error_x_max",
            "error_f_max",
            "error_t_contact",
            "error_v_out",
            "force_evals",
            "seconds_per_solve",
        ] {
            assert!(row.get(key).is_some(), "{key} missing in {row}");
        }
    }
    // Hunt–Crossley has an exact solution: DOPRI5 at rtol 1e-8 lands within 1e-6 of it on every number.
    let dopri5 = rows
        .iter()
        .find(|r| r["method"] == "dopri5" && r["rtol"].as_f64() == Some(1e-8))
        .expect("a dopri5 row at rtol 1e-8");
    for key in [
        "error_x_max",
        "error_f_max",
        "error_t_contact",
        "error_v_out",
    ] {
        let e = dopri5[key].as_f64().expect("a number");
        assert!(e < 1e-6, "{key} = {e}");
    }
    // Fixed-step rungs halve: consecutive dt of one method differ by exactly 2.
    let rk4: Vec<f64> = rows
        .iter()
        .filter(|r| r["method"] == "rk4")
        .filter_map(|r| r["dt"].as_f64())
        .collect();
    assert!(rk4.len() >= 2);
    for pair in rk4.windows(2) {
        assert!((pair[0] / pair[1] - 2.0).abs() < 1e-12);
    }
}

#[test]
fn bench_stability_puts_measurement_next_to_the_h_omega_bound() {
    let rows = stdout_json(&run(&[
        "bench",
        "--scene",
        FIG5,
        "--model",
        "quasistatic",
        "--stability",
        "--format",
        "json",
    ]));
    let rows = rows.as_array().expect("an array of rows");
    assert_eq!(rows.len(), 4);
    // ω_max of the Fig. 5 scene: √(1.5·k·x_max^{1/2}/m) = 4.507e4 rad/s.
    let omega = rows[0]["omega_max"].as_f64().unwrap();
    assert!((omega / 4.507e4 - 1.0).abs() < 1e-3, "{omega}");
    // The measured step keeps x_max, F_max, t_c and v_out within 1 %: well inside the linear
    // stability bound, where the theory's critical step itself is far off (or fails) — so the
    // figure ranks the methods by order: Euler, symplectic Euler, Verlet, RK4.
    let mut last = 0.0;
    for row in rows {
        assert_eq!(row["tolerance"].as_f64(), Some(0.01));
        let measured = row["measured_h_omega"].as_f64().expect("a measured step");
        assert!(
            measured > last,
            "{}: {measured} after {last}",
            row["method"]
        );
        last = measured;
        match row["bound_h_omega"].as_f64() {
            Some(bound) => {
                assert!(measured < 0.6 * bound, "{}: {measured}", row["method"]);
                // null: the solve failed at the critical step.
                let at_theory = row["error_at_theoretical_dt"]
                    .as_f64()
                    .unwrap_or(f64::INFINITY);
                assert!(at_theory > 0.01, "{}: {at_theory}", row["method"]);
            }
            None => assert!(row["error_at_theoretical_dt"].is_null()),
        }
    }
}

#[test]
fn sweep_csv_rows_follow_the_hertz_scaling_in_order() {
    let output = run(&[
        "sweep",
        "--scene",
        FIG5,
        "--param",
        "impact.v0",
        "--from",
        "0.01",
        "--to",
        "1",
        "--points",
        "21",
        "--log",
        "--model",
        "quasistatic",
        "--model",
        "hunt-crossley",
    ]);
    let text = stdout_text(&output);
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(header[0], "impact.v0");
    let column = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let (p_max, x_max) = (column("p_max"), column("quasistatic.x_max"));
    let e_out = column("hunt-crossley.e_out");
    // Each row as [v0, p_max, quasistatic x_max, hunt-crossley e_out].
    let rows: Vec<[f64; 4]> = lines
        .map(|l| {
            let cells: Vec<&str> = l.split(',').collect();
            [0, p_max, x_max, e_out].map(|c| cells[c].parse::<f64>().expect("a number"))
        })
        .collect();
    assert_eq!(rows.len(), 21);
    for pair in rows.windows(2) {
        assert!(pair[1][0] > pair[0][0], "rows out of order");
    }
    let (first, last) = (&rows[0], &rows[20]);
    // p₀ ∝ v₀^{2/5} (eq 9 with eq 6) and x_max ∝ v₀^{4/5} (eq 5) over two decades.
    assert!((last[1] / first[1] / 100f64.powf(0.4) - 1.0).abs() < 1e-9);
    assert!((last[2] / first[2] / 100f64.powf(0.8) - 1.0).abs() < 1e-9);
    // Hunt–Crossley with a = (1 − e)/v₀ re-derived at each v₀ gives the same e_out at every v₀.
    assert!((last[3] - first[3]).abs() < 1e-9);
}

#[test]
fn sweep_json_marks_invalid_points_without_failing_the_rest() {
    // e must lie in (0, 1]: the sweep from 0.5 to 1.5 has invalid points past 1.
    let report = stdout_json(&run(&[
        "sweep",
        "--scene",
        FIG5,
        "--param",
        "impact.restitution",
        "--from",
        "0.5",
        "--to",
        "1.5",
        "--points",
        "3",
        "--model",
        "proposed",
        "--format",
        "json",
    ]));
    assert_eq!(report["param"], "impact.restitution");
    let rows = report["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 3);
    assert!(rows[0]["error"].is_null() && rows[1]["error"].is_null());
    let message = rows[2]["error"]
        .as_str()
        .expect("the e = 1.5 row has an error");
    assert!(message.contains("impact.restitution"), "{message}");
}

#[test]
fn sweep_refuses_keys_that_do_not_exist_or_do_not_apply() {
    let unknown = run(&[
        "sweep",
        "--scene",
        FIG5,
        "--param",
        "impact.vo",
        "--from",
        "0.1",
        "--to",
        "1",
        "--points",
        "3",
    ]);
    assert_eq!(unknown.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&unknown.stderr).contains("impact.vo"));
    let plane = run(&[
        "sweep",
        "--scene",
        FIG5,
        "--param",
        "body2.radius",
        "--from",
        "0.1",
        "--to",
        "1",
        "--points",
        "3",
    ]);
    assert_eq!(plane.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&plane.stderr);
    assert!(
        stderr.contains("body2.radius does not apply: the body is a plane"),
        "{stderr}"
    );
    let log = run(&[
        "sweep",
        "--scene",
        FIG5,
        "--param",
        "impact.v0",
        "--from",
        "0",
        "--to",
        "1",
        "--points",
        "3",
        "--log",
    ]);
    assert_eq!(log.status.code(), Some(2));
}

#[test]
fn a_streamed_sweep_keeps_every_row_in_order_across_chunks() {
    // 40 000 points: the CSV is solved and formatted in pieces of 512 points on every core and
    // written in order; every row must come out once, in parameter order, matching its value.
    let points = 40_000;
    let output = run(&[
        "sweep",
        "--scene",
        FIG5,
        "--param",
        "impact.v0",
        "--from",
        "0.01",
        "--to",
        "1",
        "--points",
        &points.to_string(),
        "--model",
        "quasistatic",
    ]);
    let text = stdout_text(&output);
    let values: Vec<f64> = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').next().unwrap().parse().expect("a number"))
        .collect();
    assert_eq!(values.len(), points);
    let step = 0.99 / (points - 1) as f64;
    for (i, v) in values.iter().enumerate() {
        assert!((v - (0.01 + step * i as f64)).abs() < 1e-12, "row {i}: {v}");
    }
}
