//! `hertz-tui continue` driven as a user would: the bouncing ball's period doubling against its
//! closed form Γ_PD (docs/physics.md §8.1), the doubled branch, the oscillator's grazing against
//! F_g = F₀·(gap/δ_st)·√((1 − r²)² + (2ζr)²) (§8.3, in the groups the report prints), the CSV's
//! rows against the JSON's points, the figure's labels, and bad input named.

use std::f64::consts::PI;

use serde_json::Value;

use crate::support::{ok, out_file, refused, with};

/// The ball's branch in `param` from `from` to `to`.
fn ball<'a>(param: &'a str, from: &'a str, to: &'a str) -> Vec<&'a str> {
    vec![
        "continue",
        "--scene",
        "bouncing-ball",
        "--param",
        param,
        "--from",
        from,
        "--to",
        to,
    ]
}

/// The ball's branch from Γ = 1.3 (the orbit found from the run's settled period-1 cycle).
fn gamma_branch() -> Vec<&'static str> {
    ball("system.gamma", "1.3", "1.7")
}

#[test]
fn the_balls_period_doubling_and_doubled_branch() {
    let mut args = gamma_branch();
    args.extend(["--doubled", "--format", "json"]);
    let report: Value = serde_json::from_str(&ok(&args)).unwrap();
    let e: f64 = 0.5;
    let sn = PI * (1.0 - e) / (1.0 + e);
    let pd = sn.hypot(2.0 * (1.0 + e * e) / (1.0 + e).powi(2));
    let result = &report["results"][0];
    let specials = result["branch"]["specials"].as_array().unwrap();
    assert_eq!(specials.len(), 1, "{specials:?}");
    assert_eq!(specials[0]["kind"], "period-doubling");
    let at = specials[0]["point"]["values"][0].as_f64().unwrap();
    assert!((at - pd).abs() < 1e-8, "{at} vs {pd}");
    let doubled = &result["doubled"];
    assert_eq!(doubled["cycles"], 2);
    assert_eq!(doubled["stops"].as_array().unwrap().len(), 2);
    // The CSV: a row per impact of every orbit, and the special point's own row.
    let mut args = gamma_branch();
    args.extend(["--format", "csv"]);
    let csv = ok(&args);
    let mut lines = csv.lines();
    assert!(
        lines
            .next()
            .unwrap()
            .starts_with("contact,branch,system.gamma,impact,")
    );
    let rows: Vec<&str> = lines.collect();
    let points = result["branch"]["points"].as_array().unwrap().len();
    assert_eq!(rows.len(), points + 1, "one row per point plus the special");
    let special: Vec<&str> = rows
        .iter()
        .filter(|r| r.ends_with(",period-doubling"))
        .copied()
        .collect();
    assert_eq!(special.len(), 1);
    let value: f64 = special[0].split(',').nth(2).unwrap().parse().unwrap();
    assert!((value - pd).abs() < 1e-8);
}

#[test]
fn the_oscillators_grazing_is_its_closed_form() {
    let report: Value = serde_json::from_str(&ok(&[
        "continue",
        "--scene",
        "impact-oscillator",
        "--param",
        "system.forcing_amplitude",
        "--from",
        "0.05",
        "--to",
        "0.001",
        "--transient",
        "100",
        "--recorded",
        "20",
        "--format",
        "json",
    ]))
    .unwrap();
    let g = &report["groups"];
    let r = g["frequency_ratio"].as_f64().unwrap();
    let zeta = g["damping_ratio"].as_f64().unwrap();
    let gap = g["gap_ratio"].as_f64().unwrap();
    // The scene's F₀ = 0.05 N: the static deflection the gap ratio is measured in.
    let expected = 0.05 * gap * ((1.0 - r * r).powi(2) + (2.0 * zeta * r).powi(2)).sqrt();
    let branch = &report["results"][0]["branch"];
    assert_eq!(branch["end"]["reason"], "grazing");
    let grazing = branch["specials"]
        .as_array()
        .unwrap()
        .iter()
        .find(|s| s["kind"] == "grazing-impact")
        .unwrap();
    let at = grazing["point"]["values"][0].as_f64().unwrap();
    assert!(
        (at - expected).abs() < 1e-8 * expected,
        "{at} vs {expected}"
    );
}

#[test]
fn the_compliant_oscillators_grazing_is_in_the_csv_as_the_rigid_ones() {
    // The Hunt–Crossley stop's contact vanishes where the free response touches the stop: the
    // same F_g as the rigid stop's (docs/continuation.md §6), in a `grazing-impact` row.
    let csv = ok(&[
        "continue",
        "--scene",
        "impact-oscillator",
        "--param",
        "system.forcing_amplitude",
        "--from",
        "0.05",
        "--to",
        "0.001",
        "--transient",
        "100",
        "--recorded",
        "20",
        "--contact",
        "compliant",
        "--format",
        "csv",
    ]);
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let column = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let (key, special) = (column("system.forcing_amplitude"), column("special"));
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    let grazing: Vec<&Vec<&str>> = rows
        .iter()
        .filter(|r| r[special] == "grazing-impact")
        .collect();
    assert_eq!(grazing.len(), 1, "{csv}");
    assert!(grazing[0][0].contains("hunt-crossley"), "{:?}", grazing[0]);
    let at: f64 = grazing[0][key].parse().unwrap();
    // F_g = F₀·(gap/δ_st)·√((1 − r²)² + (2ζr)²) with the preset's groups (r = 0.9, ζ = 0.05,
    // gap/δ_st = 1.29…): the rigid branch's 13.565299 mN.
    assert!((at / 0.013565299 - 1.0).abs() < 1e-7, "{at}");
}

#[test]
fn the_figure_marks_the_special_points() {
    let path = out_file("continuation", "branch.svg");
    let mut args = gamma_branch();
    args.extend([
        "--diagram",
        "20",
        "--transient",
        "200",
        "--recorded",
        "20",
        "-o",
    ]);
    args.push(path.to_str().unwrap());
    let table = ok(&args);
    assert!(table.contains("period-doubling  1.5268237"), "{table}");
    let svg = std::fs::read_to_string(&path).unwrap();
    for text in [
        "periodic orbits over Γ",
        "PD 1.5268",
        "rigid period-1 stable",
        "rigid period-1 unstable",
        "rigid diagram",
    ] {
        assert!(svg.contains(text), "{text} missing");
    }
}

#[test]
fn bad_input_is_named() {
    let e = refused(&ball("system.gamma", "1", "1"));
    assert!(e.contains("--from and --to must differ"), "{e}");
    let e = refused(&ball("system.gap", "1", "2"));
    assert!(e.contains("system.gap"), "{e}");
    let e = refused(&with(
        &ball("system.gamma", "1.3", "2"),
        &["--second", "system.frequency"],
    ));
    assert!(e.contains("--from2"), "{e}");
    // A start below the fold, where no period-1 orbit exists: said in words, naming the stop.
    let e = refused(&ball("system.gamma", "0.5", "2"));
    assert!(
        e.contains("rigid stop") && e.contains("exists only from Γ"),
        "{e}"
    );
}

#[test]
fn a_negative_start_speed_is_refused_as_orbit_refuses_it() {
    let start = ["--phase", "0", "--speed", "-1"];
    let mut args = gamma_branch();
    args.extend(start);
    let e = refused(&args);
    assert!(
        e.contains("--speed") && e.contains("-1 must be a finite number > 0"),
        "{e}"
    );
    let mut args = vec!["orbit", "--scene", "bouncing-ball"];
    args.extend(start);
    let first_line = |s: &str| s.lines().next().unwrap_or_default().to_string();
    assert_eq!(first_line(&refused(&args)), first_line(&e));
}
