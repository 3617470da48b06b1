//! The results table's damping column against `solve --format json` for the same scene: each
//! checked law's parameter (its symbol) and the value used, to the digits shown, with the damping
//! from e by each law's rule and calibrated (`C`, `--calibrate`).

use std::process::Command;

use hertz_tui::model::presets::DEFAULT_SCENE;
use hertz_tui::ui::action::Action;
use hertz_tui::ui::update::update;
use serde_json::Value;

use super::render::{app, half_last_digit, render, settle, text};

/// Each law's damping as `solve` reports it: (model id, (symbol, value) or none).
fn solve_json(models: &[String], calibrate: bool) -> Vec<(String, Option<(String, f64)>)> {
    let mut command = Command::new(env!("CARGO_BIN_EXE_hertz-tui"));
    command.args(["solve", "--scene", DEFAULT_SCENE, "--format", "json"]);
    for model in models {
        command.args(["--model", model]);
    }
    if calibrate {
        command.arg("--calibrate");
    }
    let output = command.output().unwrap();
    assert!(output.status.success(), "{output:?}");
    let json: Value = serde_json::from_slice(&output.stdout).unwrap();
    json["impacts"]
        .as_array()
        .unwrap()
        .iter()
        .map(|impact| {
            let damping = &impact["damping"];
            let used = damping["symbol"]
                .as_str()
                .map(|symbol| (symbol.to_string(), damping["value"].as_f64().unwrap()));
            (impact["model"].as_str().unwrap().to_string(), used)
        })
        .collect()
}

#[test]
fn the_damping_column_shows_what_solve_reports() {
    for calibrate in [false, true] {
        let mut app = app();
        if calibrate {
            update(&mut app, Action::ToggleCalibration);
            settle(&mut app);
        }
        let models: Vec<String> = app
            .checked_models()
            .iter()
            .map(|m| m.name().to_string())
            .collect();
        let expected = solve_json(&models, calibrate);
        let ids: Vec<&String> = expected.iter().map(|(id, _)| id).collect();
        assert_eq!(
            ids,
            models.iter().collect::<Vec<_>>(),
            "rows in table order"
        );
        let title = if calibrate { "calibrated" } else { "damping" };
        for (width, height) in [(80, 24), (120, 40), (160, 48)] {
            let screen = text(render(&app, width, height).backend().buffer());
            let rows: Vec<Vec<char>> = screen.lines().map(|l| l.chars().collect()).collect();
            let find = |row: &[char], word: &str| {
                let word: Vec<char> = word.chars().collect();
                row.windows(word.len()).position(|w| w == word.as_slice())
            };
            let header = rows
                .iter()
                .position(|r| find(r, "x_max").is_some() && find(r, "model").is_some())
                .unwrap_or_else(|| panic!("no results header at {width}×{height}\n{screen}"));
            // Column names are looked for right of the table's "model" (the models pane beside
            // it has a "viscous damping" heading).
            let table = find(&rows[header], "model").unwrap_or(0);
            let find = |row: &[char], word: &str| find(&row[table..], word).map(|at| at + table);
            let from = find(&rows[header], title)
                .unwrap_or_else(|| panic!("no {title} column at {width}×{height}\n{screen}"));
            let to = find(&rows[header], "e_out").unwrap_or(rows[header].len());
            for (i, (model, used)) in expected.iter().enumerate() {
                let row = &rows[header + 1 + i];
                let cell: String = row[from..to].iter().collect();
                let cell = cell.trim();
                let at = format!("{model} at {width}×{height}, calibrated {calibrate}");
                let Some((symbol, value)) = used else {
                    assert_eq!(cell, "-", "{at}");
                    continue;
                };
                let mut words = cell.split_whitespace();
                assert_eq!(words.next(), Some(symbol.as_str()), "{at}: '{cell}'");
                let number = words.next().unwrap_or_default();
                let shown: f64 = number
                    .parse()
                    .unwrap_or_else(|_| panic!("{at}: '{cell}' holds no whole number"));
                assert!(
                    (shown - value).abs() <= half_last_digit(number) * (1.0 + 1e-9),
                    "{at}: '{cell}' shown for {value:e}"
                );
            }
        }
    }
}
