//! The real `hertz-tui` binary: list, solve (table, json, csv), --set, and user errors.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use serde_json::Value;

use crate::scratch::{self, Folder};

/// A fresh folder under the system temp dir, removed when dropped (also when the test fails).
struct TempDir(Folder);

impl TempDir {
    fn new(label: &str) -> TempDir {
        TempDir(scratch::folder(&format!("cli-{label}")))
    }

    fn write(&self, relative: &str, text: &str) -> PathBuf {
        let path = self.0.join(relative);
        fs::create_dir_all(path.parent().unwrap()).unwrap();
        fs::write(&path, text).unwrap();
        path
    }

    fn path(&self) -> &Path {
        &self.0
    }
}

/// Runs the binary with `args`; user presets come from `config` (an empty folder if `None`), so
/// the developer's own presets never leak into the tests.
fn run_with_config(config: Option<&Path>, args: &[&str]) -> Output {
    let empty = TempDir::new("empty-config");
    let config = config.unwrap_or(empty.path());
    Command::new(env!("CARGO_BIN_EXE_hertz-tui"))
        .args(args)
        .env("XDG_CONFIG_HOME", config)
        .env_remove("RUST_BACKTRACE")
        .output()
        .expect("the binary runs")
}

fn run(args: &[&str]) -> Output {
    run_with_config(None, args)
}

fn stdout(output: &Output) -> String {
    String::from_utf8(output.stdout.clone()).expect("utf-8 output")
}

fn stderr(output: &Output) -> String {
    String::from_utf8(output.stderr.clone()).expect("utf-8 output")
}

/// A successful run's stdout.
pub(crate) fn ok(args: &[&str]) -> String {
    let output = run(args);
    assert!(
        output.status.success(),
        "{args:?} failed: {}",
        stderr(&output)
    );
    stdout(&output)
}

pub(crate) fn json(args: &[&str]) -> Value {
    let mut all = args.to_vec();
    all.extend(["--format", "json"]);
    serde_json::from_str(&ok(&all)).expect("solve prints JSON")
}

/// A user error: exit status 2, nothing on stdout, one `error: …` message and no panic on stderr.
fn user_error(args: &[&str]) -> String {
    user_error_with_config(None, args)
}

fn user_error_with_config(config: Option<&Path>, args: &[&str]) -> String {
    let output = run_with_config(config, args);
    let err = stderr(&output);
    assert_eq!(output.status.code(), Some(2), "{args:?}: {err}");
    assert!(output.stdout.is_empty(), "{args:?} printed to stdout");
    assert!(err.starts_with("error: "), "{err}");
    for noise in ["panicked", "BACKTRACE", "Location:"] {
        assert!(!err.contains(noise), "{err}");
    }
    err
}

fn number(v: &Value, path: &str) -> f64 {
    let mut cur = v;
    for key in path.split('.') {
        cur = &cur[key];
    }
    cur.as_f64()
        .unwrap_or_else(|| panic!("{path} is not a number: {cur}"))
}

fn close(a: f64, b: f64, rel: f64) -> bool {
    (a / b - 1.0).abs() <= rel
}

#[test]
fn list_shows_every_preset_with_origin_and_description() {
    let out = ok(&["list"]);
    for scene in [
        "steel-sphere-r5-plate",
        "steel-sphere-r10-plate",
        "aluminium-sphere-r10-plate",
        "steel-cylinders-r20-l100",
        "steel-cylinder-r20-l100-plate",
        "fig4-steel-sphere-r10-plate",
        "fig5-steel-sphere-r10-plate",
    ] {
        let line = out
            .lines()
            .find(|l| l.split_whitespace().nth(1) == Some(scene))
            .unwrap_or_else(|| panic!("{scene} not listed:\n{out}"));
        assert!(line.starts_with("scene "), "{line}");
        assert!(line.contains("built-in"), "{line}");
    }
    let steel = out
        .lines()
        .find(|l| l.starts_with("material") && l.contains(" steel "))
        .unwrap();
    assert!(
        steel.contains("built-in") && steel.contains("7800"),
        "{steel}"
    );
    let default = out.lines().find(|l| l.contains("[default]")).unwrap();
    assert!(default.contains("fig5-steel-sphere-r10-plate"), "{default}");
}

#[test]
fn list_shows_user_presets_and_warns_about_broken_ones() {
    let config = TempDir::new("list");
    let presets = "hertz-tui/presets";
    config.write(
        &format!("{presets}/scenes/my-drop.toml"),
        "name = \"mine\"\ndescription = \"my own drop test\"\n[body1]\nshape = \"sphere\"\nradius = 0.002\nmaterial = \"steel\"\n[body2]\nshape = \"plane\"\nmaterial = \"aluminium-alloy\"\n[impact]\nv0 = 0.1\nrestitution = 0.8\nplastic_indentation = 0\n",
    );
    config.write(&format!("{presets}/scenes/broken.toml"), "name = \n");
    let output = run_with_config(Some(config.path()), &["list"]);
    assert!(output.status.success());
    let out = stdout(&output);
    let mine = out.lines().find(|l| l.contains("my-drop")).unwrap();
    assert!(
        mine.contains("user") && mine.contains("my own drop test"),
        "{mine}"
    );
    assert!(!out.contains("broken"), "{out}");
    let err = stderr(&output);
    assert!(
        err.starts_with("warning: ") && err.contains("broken.toml:1:8: TOML syntax error"),
        "{err}"
    );
    // The user scene solves by name.
    let output = run_with_config(
        Some(config.path()),
        &[
            "solve",
            "--scene",
            "my-drop",
            "--model",
            "quasistatic",
            "--format",
            "json",
        ],
    );
    let v: Value = serde_json::from_slice(&output.stdout).unwrap();
    assert_eq!(v["scene"]["name"], "mine");
}

/// Table 1, middle column, through the binary's JSON.
#[test]
fn solve_json_reproduces_table_1() {
    let v = json(&["solve", "--scene", "steel-sphere-r10-plate"]);
    assert_eq!(v["scene"]["name"], "Steel sphere R = 10 mm on steel plate");
    assert_eq!(v["scene"]["body1"]["material"]["youngs_modulus"], 2e11);
    assert_eq!(v["scene"]["impact"]["v0"], 1.0);
    let q = &v["quasistatic"];
    // Printed in Table 1 (column 2); half a unit of the last printed digit, relative.
    for (key, printed, rel) in [
        ("eta", 9.1e-12, 1e-12),
        ("k", 1.465e10, 0.5e-3 / 1.465),
        ("x_max", 2.388e-5, 0.5e-3 / 2.388),
        ("f_max", 1710.0, 0.5 / 1710.0),
        ("t_contact", 7.029e-5, 0.5e-3 / 7.029),
        ("p_max", 3419e6, 0.5 / 3419.0),
        ("v_yield", 0.032, 0.5 / 32.0),
        ("v_plastic", 0.326, 0.5 / 326.0),
        ("reduced_mass", 0.033, 0.5 / 33.0),
    ] {
        let value = number(q, key);
        assert!(
            close(value, printed, rel),
            "{key} = {value}, Table 1: {printed}"
        );
    }
    assert_eq!(q["n"], 1.5);
    // The paper truncates a = 4.88696e-4 m to 4.886e-4 (tests/tables.rs).
    assert!(close(number(q, "contact_radius"), 4.887e-4, 1e-4));
    assert!(q.get("half_width").is_none() && q.get("fit").is_none());
    for key in [
        "v_wave_limit",
        "v_yield_mean_pressure",
        "v_plastic_mean_pressure",
    ] {
        assert!(number(q, key) > 0.0, "{key}");
    }

    let impacts = v["impacts"].as_array().unwrap();
    let models: Vec<&str> = impacts
        .iter()
        .map(|r| r["model"].as_str().unwrap())
        .collect();
    let every_law: Vec<&str> = hertz_tui::model::ForceModel::ALL
        .iter()
        .map(|m| m.name())
        .collect();
    assert_eq!(models, every_law, "every law of the table, in table order");
    for row in impacts {
        assert!(row["error"].is_null(), "{row}");
        for key in [
            "x_max",
            "f_max",
            "t_contact",
            "v_out",
            "e_out",
            "x_residual",
            "energy_dissipated",
            "energy_residual",
            "steps",
            "rejected_steps",
            "force_evals",
        ] {
            assert!(row[key].is_number(), "{key} in {row}");
        }
        assert!(row["method"].is_string());
    }
    // The elastic impact agrees with the closed form (eqs 5–7) and gives back all the energy.
    let elastic = &impacts[0];
    for (key, exact) in [
        ("x_max", number(q, "x_max")),
        ("f_max", number(q, "f_max")),
        ("t_contact", number(q, "t_contact")),
    ] {
        assert!(close(number(elastic, key), exact, 1e-6), "{key}: {elastic}");
    }
    assert!(close(number(elastic, "e_out"), 1.0, 1e-6));
}

#[test]
fn solve_json_for_cylinders_has_half_width_and_fit() {
    let v = json(&[
        "solve",
        "--scene",
        "steel-cylinders-r20-l100",
        "--model",
        "quasistatic",
    ]);
    let q = &v["quasistatic"];
    assert!(q.get("contact_radius").is_none());
    assert!(close(number(q, "half_width"), 2.154e-4, 0.02));
    assert!(close(number(q, "fit.n"), 1.090, 0.02));
    assert_eq!(q["fit"]["a"], q["k"]);
    assert!(number(q, "fit.max_rel_error") < 0.01);
    assert!(q["fit"]["c"].is_number());
    assert_eq!(v["impacts"].as_array().unwrap().len(), 1);
}

#[test]
fn set_overrides_scene_keys() {
    let base = json(&[
        "solve",
        "--scene",
        "steel-sphere-r10-plate",
        "--model",
        "quasistatic",
    ]);
    let faster = json(&[
        "solve",
        "--scene",
        "steel-sphere-r10-plate",
        "--model",
        "quasistatic",
        "--set",
        "impact.v0=2",
    ]);
    assert_eq!(faster["scene"]["impact"]["v0"], 2.0);
    let ratio = number(&faster["quasistatic"], "x_max") / number(&base["quasistatic"], "x_max");
    assert!(close(ratio, 2f64.powf(0.8), 1e-12), "{ratio}");

    let v = json(&[
        "solve",
        "--scene",
        "steel-sphere-r10-plate",
        "--model",
        "quasistatic",
        "--set",
        "body1.material.youngs_modulus=7e10",
        "--set",
        "body2.material=aluminium-alloy",
        "--set",
        "body1.radius=0.02",
    ]);
    let body1 = &v["scene"]["body1"];
    assert_eq!(body1["radius"], 0.02);
    assert_eq!(body1["material"]["youngs_modulus"], 7e10);
    assert_eq!(
        body1["material"]["poisson_ratio"], 0.3,
        "the rest of steel stays"
    );
    assert_eq!(v["scene"]["body2"]["material"]["name"], "aluminium-alloy");
    let eta = (1.0 - 0.09) / 7e10 + (1.0 - 0.33 * 0.33) / 7e10;
    assert!(close(number(&v["quasistatic"], "eta"), eta, 1e-12));
}

#[test]
fn solve_table_has_units() {
    let out = ok(&["solve", "--scene", "steel-sphere-r10-plate"]);
    for expected in [
        "23.88 µm",
        "1.710 kN",
        "70.29 µs",
        "3.419 GPa",
        "31.55 mm/s",
        "hunt-crossley",
    ] {
        assert!(out.contains(expected), "{expected} missing:\n{out}");
    }
    assert!(!out.contains("NaN") && !out.contains("inf"), "{out}");
}

#[test]
fn a_failing_model_is_a_row_not_a_failed_command() {
    // Explicit Euler with a step near the contact time: every model blows up.
    let v = json(&[
        "solve",
        "--scene",
        "fig5-steel-sphere-r10-plate",
        "--method",
        "euler",
        "--dt",
        "2e-5",
    ]);
    let impacts = v["impacts"].as_array().unwrap();
    assert_eq!(impacts.len(), hertz_tui::model::ForceModel::ALL.len());
    for row in impacts {
        assert!(row["error"].is_string(), "{row}");
        assert_eq!(row["method"], "euler");
        assert!(row["x_max"].is_null());
    }
    let out = ok(&[
        "solve",
        "--scene",
        "fig5-steel-sphere-r10-plate",
        "--method",
        "euler",
        "--dt",
        "2e-5",
        "--model",
        "quasistatic",
    ]);
    assert!(
        out.contains("failed (see below)") && out.contains("quasistatic: euler"),
        "{out}"
    );
}

#[test]
fn csv_prints_a_monotone_trajectory() {
    let out = ok(&[
        "solve",
        "--scene",
        "fig5-steel-sphere-r10-plate",
        "--format",
        "csv",
        "--model",
        "hunt-crossley",
        "--points",
        "50",
    ]);
    let mut lines = out.lines();
    assert_eq!(lines.next(), Some("t,x,v,F"));
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|x| x.parse().expect("a number")).collect())
        .collect();
    assert!(rows.len() >= 50, "{} rows", rows.len());
    assert!(
        rows.iter()
            .all(|r| r.len() == 4 && r.iter().all(|x| x.is_finite()))
    );
    assert!(
        rows.windows(2).all(|w| w[1][0] >= w[0][0]),
        "t is not monotone"
    );
    assert_eq!(rows[0][0], 0.0);
    assert!(close(rows[0][2], 0.3, 1e-12), "starts at v0");
    // Hunt–Crossley: x_max 8.0 µm in Fig. 5 (exact 8.00e-6 m here).
    let x_max = rows.iter().map(|r| r[1]).fold(0.0, f64::max);
    assert!(close(x_max, 8.0e-6, 0.01), "{x_max}");
}

#[test]
fn user_errors_exit_2_with_a_message() {
    let err = user_error(&["solve", "--scene", "no-such-scene"]);
    assert!(
        err.contains("unknown scene \"no-such-scene\" (scenes: aluminium-sphere-r10-plate"),
        "{err}"
    );
    let err = user_error(&[
        "solve",
        "--scene",
        "fig5-steel-sphere-r10-plate",
        "--set",
        "impact.speed=1",
    ]);
    assert!(
        err.contains("--set impact.speed: unknown scene key"),
        "{err}"
    );
    let err = user_error(&[
        "solve",
        "--scene",
        "fig5-steel-sphere-r10-plate",
        "--set",
        "impact.v0=fast",
    ]);
    assert!(
        err.contains("--set impact.v0: \"fast\" is not a number"),
        "{err}"
    );
    let err = user_error(&[
        "solve",
        "--scene",
        "fig5-steel-sphere-r10-plate",
        "--set",
        "body1.material.poisson_ratio=0.7",
    ]);
    assert!(
        err.ends_with("body1.material.poisson_ratio must be in [0, 0.5), got 0.7\n"),
        "{err}"
    );
    let err = user_error(&[
        "solve",
        "--scene",
        "fig5-steel-sphere-r10-plate",
        "--model",
        "hertz",
    ]);
    assert!(err.contains("unknown model 'hertz'"), "{err}");
    let err = user_error(&[
        "solve",
        "--scene",
        "fig5-steel-sphere-r10-plate",
        "--method",
        "leapfrog",
    ]);
    assert!(err.contains("unknown method 'leapfrog'"), "{err}");
    let err = user_error(&[
        "solve",
        "--scene",
        "fig5-steel-sphere-r10-plate",
        "--rtol",
        "-1",
    ]);
    assert!(err.contains("-1 must be a finite number > 0"), "{err}");
    let err = user_error(&[
        "solve",
        "--scene",
        "fig5-steel-sphere-r10-plate",
        "--format",
        "csv",
    ]);
    assert!(err.contains("give exactly one --model"), "{err}");
    let err = user_error(&[
        "solve",
        "--scene",
        "fig5-steel-sphere-r10-plate",
        "--set",
        "body1.shape=cylinder",
    ]);
    assert!(
        err.ends_with("(--set body1.shape): missing key `body1.length` (a cylinder needs it)\n"),
        "{err}"
    );
    // The explorer refuses a bad scene before it touches the terminal.
    let err = user_error(&["--scene", "no-such-scene"]);
    assert!(err.contains("unknown scene"), "{err}");
}

#[test]
fn scene_file_errors_name_file_line_and_key() {
    let dir = TempDir::new("errors");
    let path = dir.write(
        "bad.toml",
        "name = \"bad\"\n[body1]\nshape = \"sphere\"\nradius = \"large\"\nmaterial = \"steel\"\n[body2]\nshape = \"plane\"\nmaterial = \"steel\"\n[impact]\nv0 = 1\nrestitution = 0.5\nplastic_indentation = 0\n",
    );
    let file = path.to_str().unwrap();
    let err = user_error(&["solve", "--scene", file]);
    assert_eq!(
        err,
        format!("error: {file}:4:1: `body1.radius` must be a number, found string \"large\"\n")
    );
    let err = user_error(&[
        "solve",
        "--scene",
        &format!("{}/missing.toml", dir.path().display()),
    ]);
    assert!(
        err.starts_with("error: cannot read ") && err.contains("missing.toml"),
        "{err}"
    );
}

#[test]
fn help_and_version_work() {
    let out = ok(&["--help"]);
    assert!(
        out.contains("solve") && out.contains("list") && out.contains("--marker"),
        "{out}"
    );
    let out = ok(&["solve", "--help"]);
    for flag in [
        "--scene", "--set", "--format", "--model", "--method", "--rtol", "--atol", "--dt",
        "--points",
    ] {
        assert!(out.contains(flag), "{flag} missing:\n{out}");
    }
}

#[test]
fn translate_json_for_every_engine_realises_the_scene_restitution() {
    for engine in [
        "drake",
        "drake-sap",
        "simbody",
        "chrono",
        "liggghts",
        "lammps",
        "lammps-tsuji",
        "yade",
        "adams",
        "mujoco",
    ] {
        let v = json(&[
            "translate",
            "--scene",
            "fig5-steel-sphere-r10-plate",
            "--set",
            "impact.restitution=0.4",
            "--engine",
            engine,
        ]);
        assert_eq!(v["engine"], engine);
        assert_eq!(number(&v, "e_requested"), 0.4);
        let tolerance = if engine == "chrono" { 1e-6 } else { 1e-8 };
        assert!(
            (number(&v, "realised.e_out") - 0.4).abs() < tolerance,
            "{engine}: {v}"
        );
        for key in ["f_max", "t_contact", "x_max", "dt_stable"] {
            assert!(number(&v["realised"], key) > 0.0, "{engine}: {key}");
        }
        assert_eq!(v["e_of_v"].as_array().map(Vec::len), Some(7), "{engine}");
        let fragment = v["fragments"][0]["text"].as_str().unwrap_or_default();
        for p in v["parameters"].as_array().into_iter().flatten() {
            assert!(
                p["value"].as_f64().is_some_and(f64::is_finite),
                "{engine}: {p}"
            );
        }
        assert!(!fragment.is_empty(), "{engine}");
    }
}

#[test]
fn translate_text_ends_with_the_script_and_writes_it() {
    let dir = TempDir::new("translate-script");
    let path = dir.path().join("impact.py");
    let out = ok(&[
        "translate",
        "--scene",
        "fig5-steel-sphere-r10-plate",
        "--engine",
        "drake",
        "--script",
        path.to_str().expect("utf-8 path"),
    ]);
    for heading in [
        "engine law",
        "Warnings: what the engine's law cannot do here",
        "yield begins",
        "Parameters",
        "What the engine's law gives",
        "Time step and what the engine gives",
        "python3 impact.py discrete: step",
        "e_out against v₀",
        "Versions",
        "run in Drake 1.51.1",
        "Script (python; save as impact.py",
    ] {
        assert!(out.contains(heading), "{heading}: {out}");
    }
    let script = fs::read_to_string(&path).expect("--script wrote the file");
    assert!(script.contains("contact_model=\"point\""), "{script}");
    assert!(
        out.trim_end().ends_with(script.trim_end()),
        "the script comes last, as written: {out}"
    );
    assert!(
        script
            .trim_end()
            .ends_with("contact_time {contact_time:.12g}\")")
    );
}

#[test]
fn translate_json_carries_the_run_and_the_regime() {
    let v = json(&[
        "translate",
        "--scene",
        "fig5-steel-sphere-r10-plate",
        "--engine",
        "lammps-tsuji",
        "--tolerance",
        "0.001",
    ]);
    assert_eq!(v["warnings"][0]["kind"], "yield-begins", "{v}");
    let claim = &v["run"]["claim"];
    assert_eq!(claim["kind"], "stepped");
    assert_eq!(number(claim, "tolerance"), 0.001);
    let e = number(&claim["at_step"], "e_out");
    assert!((e / 0.6 - 1.0).abs() <= 0.001, "{claim}");
    let script = v["run"]["script"]["text"].as_str().unwrap_or_default();
    // Both releases' inputs: the one run, and the √2 one commented out.
    assert!(script.contains("variable e_in equal"), "{script}");
    assert!(script.contains("# variable e_in equal"), "{script}");
    assert!(script.contains("units si") && script.contains("comm_modify vel yes"));
    let elastic = json(&[
        "translate",
        "--scene",
        "steel-sphere-r10-plate",
        "--set",
        "impact.v0=0.01",
        "--engine",
        "mujoco",
    ]);
    assert_eq!(elastic["warnings"].as_array().map(Vec::len), Some(0));
    let err = user_error(&[
        "translate",
        "--scene",
        "fig5-steel-sphere-r10-plate",
        "--engine",
        "mujoco",
        "--tolerance",
        "2",
    ]);
    assert!(err.contains("--tolerance"), "{err}");
    let err = user_error(&[
        "translate",
        "--scene",
        "steel-cylinder-r20-l100-plate",
        "--engine",
        "mujoco",
        "--script",
        "never-written.py",
    ]);
    assert!(
        err.contains("--script") && err.contains("cylinder"),
        "{err}"
    );
}

#[test]
fn chrono_and_adams_say_they_are_not_run_in_the_engine() {
    for engine in ["chrono", "adams"] {
        let out = ok(&[
            "translate",
            "--scene",
            "fig5-steel-sphere-r10-plate",
            "--engine",
            engine,
        ]);
        assert!(out.contains("not run in the engine"), "{engine}: {out}");
        assert!(out.contains("only the continuous limit"), "{engine}: {out}");
    }
}

#[test]
fn translate_errors_name_the_engine_or_the_limit() {
    let err = user_error(&[
        "translate",
        "--scene",
        "fig5-steel-sphere-r10-plate",
        "--engine",
        "bullet",
    ]);
    assert!(
        err.contains("unknown engine 'bullet'") && err.contains("drake"),
        "{err}"
    );
    let err = user_error(&[
        "translate",
        "--scene",
        "steel-cylinders-r20-l100",
        "--engine",
        "chrono",
    ]);
    assert!(err.contains("point contact"), "{err}");
    let err = user_error(&[
        "translate",
        "--scene",
        "fig5-steel-sphere-r10-plate",
        "--set",
        "impact.restitution=0.05",
        "--engine",
        "lammps-tsuji",
    ]);
    assert!(err.contains("cannot be reached"), "{err}");
}

#[test]
fn solve_json_warns_where_the_theory_or_the_numbers_do_not_hold() {
    // At 50 m/s a 10 mm steel sphere's contact radius is 0.23 R: outside Hertz's a ≪ R.
    let fast = json(&[
        "solve",
        "--scene",
        "steel-sphere-r10-plate",
        "--set",
        "impact.v0=50",
        "--model",
        "hunt-crossley",
    ]);
    let kinds: Vec<&str> = fast["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|w| w["kind"].as_str().unwrap())
        .collect();
    assert_eq!(kinds, ["large-contact"]);
    assert!(fast["warnings"][0]["ratio"].as_f64().unwrap() > 0.1);
    // e = 0.05 on the Fig. 5 scene: the proposed model's bodies creep apart along F ≈ 0.
    let grazing = json(&[
        "solve",
        "--scene",
        "fig5-steel-sphere-r10-plate",
        "--set",
        "impact.restitution=0.05",
        "--model",
        "proposed",
    ]);
    assert_eq!(grazing["warnings"][0]["kind"], "ill-conditioned-end");
    assert!(grazing["warnings"][0]["condition"].as_f64().unwrap() > 10.0);
    // The Fig. 5 scene as published has nothing to warn about.
    let fig5 = json(&["solve", "--scene", "fig5-steel-sphere-r10-plate"]);
    assert_eq!(fig5["warnings"].as_array().map(Vec::len), Some(0));
}

#[test]
fn solve_json_warns_where_the_cylinder_fit_departs_from_eqs_13_14() {
    // At 10 m/s the fitted a·xⁿ gives an impact ~3 % off the exact line-contact law's; at 1 m/s
    // (Table 2) the departure is ~0.3 % and nothing is said.
    let fast = json(&[
        "solve",
        "--scene",
        "steel-cylinders-r20-l100",
        "--set",
        "impact.v0=10",
        "--model",
        "hunt-crossley",
    ]);
    assert_eq!(fast["warnings"][0]["kind"], "fit-departs");
    let departure = fast["warnings"][0]["departure"].as_f64().unwrap();
    assert!(departure > 1.0 && departure < 10.0, "{departure} %");
    let table_2 = json(&["solve", "--scene", "steel-cylinders-r20-l100"]);
    assert_eq!(table_2["warnings"].as_array().map(Vec::len), Some(0));
}

/// After `--set body2.material=…` no header says "…on steel plate": solve's, translate's and a
/// plotted figure's title name the scene by its bodies.
#[test]
fn headers_follow_an_edited_plate() {
    let set = ["--set", "body2.material=aluminium-alloy"];
    let name = "Steel sphere R = 10 mm on aluminium-alloy plate";
    let scene = ["--scene", "fig5-steel-sphere-r10-plate"];
    let solve = ok(&[&["solve"][..], &scene, &set, &["--model", "proposed"]].concat());
    assert!(solve.starts_with(&format!("Scene: {name}\n")), "{solve}");
    let translate = ok(&[&["translate"][..], &scene, &set, &["--engine", "drake"]].concat());
    assert!(
        translate.lines().next().unwrap().ends_with(name),
        "{translate}"
    );
    assert!(!translate.contains("steel plate"), "{translate}");
}

/// The explorer reads its config file before it takes the terminal: a mistake is a user error
/// naming the file and line, and the file's `scene` is the one it opens without `--scene`.
#[test]
fn the_explorer_reads_its_config_file_and_names_the_line_of_a_mistake() {
    let dir = TempDir::new("explorer-config");
    dir.write(
        "hertz-tui/config.toml",
        "theme = \"dark\"\n[keys]\nquit = \"xy\"\n",
    );
    let err = user_error_with_config(Some(dir.path()), &[]);
    let file = dir.path().join("hertz-tui").join("config.toml");
    assert!(
        err.contains(&format!("{}:3: keys.quit", file.display())),
        "{err}"
    );
    dir.write("hertz-tui/config.toml", "scene = \"no-such-scene\"\n");
    let err = user_error_with_config(Some(dir.path()), &[]);
    assert!(err.contains("no-such-scene"), "{err}");
}
