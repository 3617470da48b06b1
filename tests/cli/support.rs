//! What the CLI tests share: the binary run with no user config, its output checked and parsed,
//! and the SVG figures it writes read back.

use std::process::{Command, Output};

use serde_json::Value;

use crate::scratch::{self, ScratchPath, folder};

/// Runs the binary with `args`, with a config folder of its own (none of the user's settings)
/// and no backtraces in its messages.
pub fn run(args: &[&str]) -> Output {
    let config = folder("cli-config");
    Command::new(env!("CARGO_BIN_EXE_hertz-tui"))
        .args(args)
        .env("XDG_CONFIG_HOME", &*config)
        .env_remove("RUST_BACKTRACE")
        .output()
        .expect("the binary runs")
}

/// The stdout of a run that must succeed.
pub fn ok(args: &[&str]) -> String {
    let output = run(args);
    assert!(
        output.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    String::from_utf8(output.stdout).unwrap()
}

/// `args` with `--format json` added, run and parsed.
pub fn json(args: &[&str]) -> Value {
    let mut all = args.to_vec();
    if !args.contains(&"--format") {
        all.extend(["--format", "json"]);
    }
    serde_json::from_str(&ok(&all)).unwrap()
}

/// `base` followed by `more`.
pub fn with<'a>(base: &[&'a str], more: &[&'a str]) -> Vec<&'a str> {
    base.iter().chain(more).copied().collect()
}

/// The user error of `args`: exit status 2, nothing on stdout, the message on stderr (no panic).
pub fn refused(args: &[&str]) -> String {
    let output = run(args);
    let err = String::from_utf8_lossy(&output.stderr).to_string();
    assert_eq!(output.status.code(), Some(2), "{args:?}: {err}");
    assert!(output.stdout.is_empty(), "{args:?}: {:?}", output.stdout);
    assert!(!err.contains("panicked"), "{err}");
    err
}

/// A file `name` in a temporary folder of its own, removed when the result is dropped.
pub fn out_file(group: &str, name: &str) -> ScratchPath {
    scratch::path(group, name)
}

/// (text, x, y) of every `<text>` element of an SVG.
pub fn texts(svg: &str) -> Vec<(String, f64, f64)> {
    svg.split("<text")
        .skip(1)
        .map(|t| {
            let content = t.split_once('>').unwrap().1;
            let content = content.split("</text>").next().unwrap().trim().to_string();
            (content, attr(t, "x"), attr(t, "y"))
        })
        .collect()
}

/// The number of attribute `name` of an SVG element's text.
pub fn attr(element: &str, name: &str) -> f64 {
    let start = element.find(&format!(" {name}=\"")).unwrap() + name.len() + 3;
    let rest = &element[start..];
    rest[..rest.find('"').unwrap()].parse().unwrap()
}

/// Tick labels as (value, pixel).
pub type Labels = Vec<(f64, f64)>;

/// The tick labels of a chart as (value, pixel): the numbers on its bottom row (x, by their x
/// pixel) and in its leftmost column (y, by their y pixel).
pub fn tick_labels(svg: &str) -> (Labels, Labels) {
    let numbers: Vec<(f64, f64, f64)> = texts(svg)
        .iter()
        .filter_map(|(t, x, y)| t.parse::<f64>().ok().map(|v| (v, *x, *y)))
        .collect();
    let bottom = numbers.iter().map(|n| n.2).fold(f64::MIN, f64::max);
    let xs = numbers
        .iter()
        .filter(|n| n.2 == bottom)
        .map(|n| (n.0, n.1))
        .collect();
    let left = numbers.iter().map(|n| n.1).fold(f64::MAX, f64::min);
    let ys = numbers
        .iter()
        .filter(|n| n.1 == left)
        .map(|n| (n.0, n.2))
        .collect();
    (xs, ys)
}
