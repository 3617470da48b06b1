//! `hertz-tui system`, `orbit`, `bifurcation` and the system charts of `plot`, driven as a user
//! would: numbers checked against closed forms (Newton's restitution at every rigid impact, the
//! bouncing ball's period-1 orbit v_in = gT/(1 + e) with det J = e²; docs/physics.md), the
//! streamed diagram against the orbit it settles on, a figure read through its tick labels
//! against the table, and bad input named by its key.

use super::support::{attr, json, ok, out_file, refused, tick_labels, with};

fn close(a: f64, b: f64, tolerance: f64) -> bool {
    (a - b).abs() <= tolerance * b.abs().max(1e-300)
}

const G: f64 = 9.80665;

#[test]
fn every_rigid_impact_obeys_newton_and_the_oscillator_settles_on_period_one() {
    let oscillator = [
        "system",
        "--scene",
        "impact-oscillator",
        "--transient",
        "300",
        "--recorded",
        "30",
    ];
    let report = json(&oscillator);
    assert_eq!(report["kind"], "impact-oscillator");
    let groups = &report["groups"];
    assert!(close(
        groups["damping_ratio"].as_f64().unwrap(),
        0.05,
        1e-12
    ));
    let run = &report["runs"][0];
    assert_eq!(run["contact"], "rigid");
    assert_eq!(run["period"]["impacts"], 1);
    assert_eq!(run["period"]["forcing_periods"], 1);
    let impacts = run["impacts"].as_array().unwrap();
    assert_eq!(impacts.len(), 30);
    // m of the preset's steel sphere R = 10 mm: ρ·4/3·π·R³ with the steel preset's ρ = 7800 kg/m³.
    let mass = 7800.0 * 4.0 / 3.0 * std::f64::consts::PI * 1e-6;
    for i in impacts {
        let (v_in, v_out) = (i["v_in"].as_f64().unwrap(), i["v_out"].as_f64().unwrap());
        assert!(close(v_out, 0.8 * v_in, 1e-12), "e = 0.8: {i}");
        assert!(
            close(i["x"].as_f64().unwrap(), 5e-4, 1e-12),
            "on the stop: {i}"
        );
        let lost = 0.5 * mass * (v_in * v_in - v_out * v_out);
        assert!(close(i["energy_lost"].as_f64().unwrap(), lost, 1e-3), "{i}");
    }
    // The CSV has the same impacts, one row each.
    let csv = ok(&with(&oscillator, &["--format", "csv"]));
    let lines: Vec<&str> = csv.lines().collect();
    assert!(lines[0].starts_with("contact,t,phase,x,stop,v_in,v_out"));
    assert_eq!(lines.len(), 31);
    let v_in: f64 = lines[1].split(',').nth(5).unwrap().parse().unwrap();
    // serde_json's reader is not correctly rounded: the last bit may differ.
    assert!(close(v_in, impacts[0]["v_in"].as_f64().unwrap(), 1e-15));
    // The table names the period in words.
    let table = ok(&["system", "--scene", "impact-oscillator", "--recorded", "8"]);
    assert!(
        table.contains("period-1: 1 impact every 1 forcing period"),
        "{table}"
    );
    assert!(table.contains("ω/ω₀ = 0.9 · ζ = 0.05"), "{table}");
}

#[test]
fn the_bouncing_balls_period_one_orbit_is_its_closed_form() {
    // Γ = 1.3 at e = 0.5: between Γ_SN = π(1−e)/(1+e) = 1.047 and Γ_PD = 1.53.
    let f = 20.0;
    let omega = 2.0 * std::f64::consts::PI * f;
    let amplitude = 1.3 * G / (omega * omega);
    let set = format!("system.amplitude={amplitude}");
    let args = [
        "orbit",
        "--scene",
        "bouncing-ball",
        "--set",
        &set,
        "--phase",
        "0.5",
        "--speed",
        "0.3",
    ];
    let report = json(&args);
    let orbit = &report["orbits"][0];
    assert_eq!(orbit["contact"], "rigid");
    assert_eq!(orbit["stable"], true);
    let e = 0.5;
    // One flight of one period T: up and down at gT/2, so the approach speed is gT/(1 + e) and
    // the table's velocity at impact Aω·cos φ = gT(1 − e)/(2(1 + e)) (docs/physics.md).
    let period = 1.0 / f;
    let point = &orbit["points"][0];
    let v_in = point["v_in"].as_f64().unwrap();
    assert!(close(v_in, G * period / (1.0 + e), 1e-9), "{v_in}");
    let phase = point["phase"].as_f64().unwrap();
    let table_speed = amplitude * omega * phase.cos();
    assert!(
        close(
            table_speed,
            G * period * (1.0 - e) / (2.0 * (1.0 + e)),
            1e-9
        ),
        "{table_speed}"
    );
    assert!(close(orbit["jacobian_det"].as_f64().unwrap(), e * e, 1e-9));
    for m in orbit["moduli"].as_array().unwrap() {
        assert!(m.as_f64().unwrap() < 1.0);
    }
    let table = ok(&args);
    assert!(
        table.contains("period-1 orbit, 1 impact per period, stable"),
        "{table}"
    );
    assert!(table.contains("det J       0.25"), "{table}");
}

#[test]
fn the_streamed_diagram_settles_on_the_orbit_newton_finds() {
    let diagram = [
        "bifurcation",
        "--scene",
        "impact-oscillator",
        "--param",
        "system.frequency",
        "--from",
        "8.5",
        "--to",
        "9",
        "--points",
        "3",
        "--transient",
        "300",
        "--recorded",
        "10",
    ];
    let csv = ok(&diagram);
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(
        lines[0],
        "contact,system.frequency,v_in,phase,stop,period_impacts,period_cycles,end"
    );
    assert_eq!(lines.len(), 1 + 3 * 10, "{csv}");
    let rows: Vec<Vec<&str>> = lines[1..].iter().map(|l| l.split(',').collect()).collect();
    let values: Vec<f64> = rows.iter().map(|r| r[1].parse().unwrap()).collect();
    assert_eq!(values[0], 8.5);
    assert_eq!(values[29], 9.0, "the last value exactly");
    assert!(
        values.windows(2).all(|w| w[0] <= w[1]),
        "in the order of the values"
    );
    let orbit = json(&["orbit", "--scene", "impact-oscillator"]);
    let v_orbit = orbit["orbits"][0]["points"][0]["v_in"].as_f64().unwrap();
    for row in &rows[20..] {
        assert_eq!(row[5..7], ["1", "1"], "period-1 at 9 Hz");
        let v: f64 = row[2].parse().unwrap();
        assert!(close(v, v_orbit, 1e-6), "{v} against {v_orbit}");
    }
    // JSON and the table carry the same diagram.
    let doc = json(&diagram);
    assert_eq!(doc["param"], "system.frequency");
    assert_eq!(doc["unit"], "Hz");
    let last = &doc["diagrams"][0]["columns"][2];
    assert_eq!(last["value"], 9.0);
    assert!(close(
        last["velocities"][0].as_f64().unwrap(),
        v_orbit,
        1e-6
    ));
}

#[test]
fn bad_input_is_named_by_its_key_and_prints_nothing_else() {
    let e = refused(&["system", "--scene", "fig5-steel-sphere-r10-plate"]);
    assert!(
        e.contains("no [system] table") && e.contains("bouncing-ball"),
        "{e}"
    );
    let e = refused(&[
        "system",
        "--scene",
        "impact-oscillator",
        "--set",
        "system.gap=-0.001",
    ]);
    assert!(e.contains("system.gap must be > 0"), "{e}");
    let e = refused(&[
        "system",
        "--scene",
        "bouncing-ball",
        "--set",
        "system.frequency=0",
    ]);
    assert!(e.contains("system.frequency"), "{e}");
    let e = refused(&[
        "bifurcation",
        "--scene",
        "bouncing-ball",
        "--param",
        "system.gap",
        "--from",
        "1e-4",
        "--to",
        "2e-4",
        "--points",
        "3",
    ]);
    assert!(
        e.contains("`system.gap` is not a parameter of this system"),
        "{e}"
    );
    let e = refused(&[
        "bifurcation",
        "--scene",
        "bouncing-ball",
        "--param",
        "system.gamma",
        "--from",
        "0.9",
        "--to",
        "3.5",
        "--points",
        "1000",
        "--budget",
        "100000",
    ]);
    assert!(e.contains("more than the budget of 100000"), "{e}");
    let e = refused(&[
        "bifurcation",
        "--scene",
        "bouncing-ball",
        "--param",
        "system.height",
        "--from",
        "1",
        "--to",
        "2",
        "--points",
        "3",
    ]);
    assert!(e.contains("unknown parameter `system.height`"), "{e}");
    let e = refused(&[
        "bifurcation",
        "--scene",
        "bouncing-ball",
        "--param",
        "system.gamma",
        "--from",
        "inf",
        "--to",
        "2",
        "--points",
        "3",
    ]);
    assert!(e.contains("--from must be a finite number"), "{e}");
    let e = refused(&["system", "--scene", "bouncing-ball", "--max-impacts", "50"]);
    assert!(e.contains("max_impacts = 50"), "{e}");
}

#[test]
fn set_takes_units_and_a_unit_of_another_quantity_is_named_by_its_key() {
    // The same runs, byte for byte, whether the keys are given in SI or in units.
    let base = [
        "system",
        "--scene",
        "impact-oscillator",
        "--recorded",
        "3",
        "--format",
        "json",
    ];
    let si = ok(&with(
        &base,
        &[
            "--set",
            "system.gap=0.0005",
            "--set",
            "system.stiffness=10000",
            "--set",
            "system.frequency=20",
            "--set",
            "system.forcing_amplitude=0.5",
        ],
    ));
    let units = ok(&with(
        &base,
        &[
            "--set",
            "system.gap=0.5 mm",
            "--set",
            "system.stiffness=1e4 N/m",
            "--set",
            "system.frequency=20Hz",
            "--set",
            "system.forcing_amplitude=500 mN",
        ],
    ));
    assert_eq!(si, units);
    let report: serde_json::Value = serde_json::from_str(&units).unwrap();
    assert_eq!(report["frequency"], 20.0);
    let ball = json(&[
        "system",
        "--scene",
        "bouncing-ball",
        "--recorded",
        "1",
        "--set",
        "system.amplitude=1.2mm",
        "--set",
        "system.frequency=0.025 kHz",
    ]);
    let omega = 2.0 * std::f64::consts::PI * 25.0;
    let gamma = ball["groups"]["gamma"].as_f64().unwrap();
    assert!(close(gamma, 0.0012 * omega * omega / G, 1e-12), "{gamma}");

    for (set, key, expected) in [
        ("system.frequency=20 kg", "system.frequency", "expected Hz"),
        ("system.gap=0.5 N", "system.gap", "expected m"),
        ("system.stiffness=3 N", "system.stiffness", "expected N/m"),
        (
            "system.forcing_amplitude=2 mm",
            "system.forcing_amplitude",
            "system.forcing = \"base\"",
        ),
    ] {
        let e = refused(&["system", "--scene", "impact-oscillator", "--set", set]);
        assert!(
            e.starts_with(&format!("error: --set {key}: ")) && e.contains(expected),
            "{set}: {e}"
        );
    }
}

/// The value at pixel `p` read through the tick labels (value, pixel) around it.
fn read(labels: &[(f64, f64)], p: f64) -> f64 {
    let w = labels
        .windows(2)
        .find(|w| w[0].1.min(w[1].1) <= p && p <= w[0].1.max(w[1].1))
        .unwrap_or_else(|| panic!("{p} not within {labels:?}"));
    w[0].0 + (p - w[0].1) / (w[1].1 - w[0].1) * (w[1].0 - w[0].0)
}

#[test]
fn the_impact_map_figure_reads_the_tables_impacts_through_its_ticks() {
    let path = out_file("systems", "map.svg");
    let common = [
        "--scene",
        "impact-oscillator",
        "--transient",
        "300",
        "--recorded",
        "10",
    ];
    let mut args = vec![
        "plot",
        "--chart",
        "impact-map",
        "-o",
        path.to_str().unwrap(),
    ];
    args.extend(common);
    ok(&args);
    let svg = std::fs::read_to_string(&path).unwrap();
    assert!(
        svg.contains("impact map") && svg.contains("v_in [m/s]"),
        "{svg}"
    );
    let report = json(&with(&["system"], &common));
    let impact = &report["runs"][0]["impacts"][0];
    let (phase, v_in) = (
        impact["phase"].as_f64().unwrap(),
        impact["v_in"].as_f64().unwrap(),
    );
    let (xs, ys) = tick_labels(&svg);
    // The period-1 orbit's ten impacts are one dot.
    let dots: Vec<(f64, f64)> = svg
        .split("<circle")
        .skip(1)
        .map(|c| (attr(c, "cx"), attr(c, "cy")))
        .collect();
    assert!(!dots.is_empty(), "{svg}");
    for &(cx, cy) in &dots {
        // A pixel is worth a tick interval over its pixels: read within a pixel and a half.
        let px_x = (xs[1].0 - xs[0].0) / (xs[1].1 - xs[0].1).abs();
        let px_y = (ys[1].0 - ys[0].0).abs() / (ys[1].1 - ys[0].1).abs();
        assert!((read(&xs, cx) - phase).abs() <= 1.5 * px_x, "φ {cx} {xs:?}");
        assert!(
            (read(&ys, cy) - v_in).abs() <= 1.5 * px_y,
            "v_in {cy} {ys:?}"
        );
    }
}

#[test]
fn the_system_charts_overlay_both_stops_each_in_its_own_look() {
    for chart in ["history", "phase", "impact-map"] {
        let path = out_file("systems", &format!("{chart}.svg"));
        ok(&[
            "plot",
            "--scene",
            "impact-oscillator",
            "--chart",
            chart,
            "--contact",
            "both",
            "--transient",
            "100",
            "--recorded",
            "10",
            "-o",
            path.to_str().unwrap(),
        ]);
        let svg = std::fs::read_to_string(&path).unwrap();
        // Rigid in black, Hunt–Crossley in its law's cyan, both in the legend.
        assert!(
            svg.contains(">\nrigid\n") || svg.contains(">rigid<"),
            "{chart}"
        );
        assert!(
            svg.contains("Hunt") || svg.contains("hunt-crossley"),
            "{chart}"
        );
        assert!(svg.contains("#00A0BE"), "{chart}: the law's hue");
        assert!(svg.contains("#000000"), "{chart}: the rigid stop's");
    }
    let path = out_file("systems", "bif.svg");
    ok(&[
        "plot",
        "--scene",
        "bouncing-ball",
        "--chart",
        "bifurcation",
        "--param",
        "system.gamma",
        "--from",
        "0.9",
        "--to",
        "2",
        "--points",
        "40",
        "--transient",
        "100",
        "--recorded",
        "20",
        "-o",
        path.to_str().unwrap(),
    ]);
    let svg = std::fs::read_to_string(&path).unwrap();
    assert!(svg.contains("bifurcation diagram over Γ"), "{svg}");
    assert!(
        svg.split("<circle").count() > 40,
        "a dot per recorded impact"
    );
    let e = refused(&[
        "plot",
        "--scene",
        "bouncing-ball",
        "--chart",
        "bifurcation",
        "--param",
        "system.gamma",
        "-o",
        path.to_str().unwrap(),
    ]);
    assert!(e.contains("needs --param, --from and --to"), "{e}");
}

#[test]
fn a_run_whose_transient_never_ends_says_so_not_that_the_body_does_not_bounce() {
    // The proposed law with x_pl = 0 (the preset's) is elastic: e = 1, and the ball climbs ever
    // higher on the vibrating table. Its run reaches --max-periods before its 500 transient
    // impacts, so nothing is recorded: that is the transient never ending, not a body that does
    // not bounce.
    let args = [
        "system",
        "--scene",
        "bouncing-ball",
        "--contact",
        "both",
        "--law",
        "proposed",
        "--max-periods",
        "2000",
    ];
    let table = ok(&args);
    assert!(
        table.contains("proposed: the transient never ended: the run reached --max-periods after ")
            && table.contains("of its 500 transient impacts; 0 impacts recorded"),
        "{table}"
    );
    assert!(!table.contains("does not bounce"), "{table}");
    let report = json(&with(&args, &["--format", "json"]));
    let verdict = &report["verdict"];
    let why = &verdict["nothing_recorded"];
    assert_eq!(why["kind"], "transient-unfinished", "{verdict}");
    let impacts = why["impacts"].as_u64().unwrap();
    let periods = why["periods"].as_f64().unwrap();
    assert!(impacts > 0 && impacts < 500, "{why}");
    // The run ends at the time limit: 2000 forcing periods from t = 0, to the last flight's end.
    assert!((periods - 2000.0).abs() < 1e-6, "{why}");
    // Still impacting in the run's last tenth (the map's `unsettled`, docs/maps.md §2): 2000
    // forcing periods at the preset's 20 Hz are 100 s.
    let run = &report["runs"][1];
    assert_eq!(run["contact"], "proposed", "{run}");
    assert_eq!(run["transient_unfinished"], true, "{run}");
    let last = run["last_impact"].as_f64().unwrap();
    assert!(last > 90.0 && last < 100.0, "{last}");
    assert_eq!(report["runs"][0]["transient_unfinished"], false);
    let sentence = verdict["sentence"].as_str().unwrap();
    assert!(
        sentence.starts_with(&format!(
            "no impacts to compare: the compliant run's transient never ended: it reached \
             --max-periods (2000 forcing periods) after {impacts} of its 500 transient impacts"
        )),
        "{sentence}"
    );
    // A law that settles records its impacts and compares them.
    let settles = json(&[
        "system",
        "--scene",
        "bouncing-ball",
        "--contact",
        "compliant",
        "--format",
        "json",
    ]);
    assert!(
        settles["verdict"]["nothing_recorded"].is_null(),
        "{settles}"
    );
}
