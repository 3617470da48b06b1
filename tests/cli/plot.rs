//! `hertz-tui plot`: the figure files, read back. The SVG has the chart's titles, tick labels at
//! pixels linear in their values, one path per curve, the peak where the solver puts it, and the
//! paper's Fig. 2 levels; bad arguments are user errors.

use serde_json::Value;

use super::support::{out_file, run, texts, tick_labels};

fn plot(args: &[&str], file: &str) -> String {
    let path = out_file("plot", file);
    let mut all = vec!["plot"];
    all.extend(args);
    all.extend(["-o", path.to_str().unwrap()]);
    let output = run(&all);
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    std::fs::read_to_string(&path).unwrap()
}

/// Where labels that are numbers put `v`: interpolated between the two around it, by `coord`
/// (x or y pixel) of the labels in `labels`.
fn pixel(labels: &[(f64, f64)], v: f64) -> f64 {
    let w = labels
        .windows(2)
        .find(|w| w[0].0.min(w[1].0) <= v && v <= w[0].0.max(w[1].0))
        .unwrap_or_else(|| panic!("{v} not within {labels:?}"));
    w[0].1 + (v - w[0].0) / (w[1].0 - w[0].0) * (w[1].1 - w[0].1)
}

#[test]
fn fig5_svg_puts_the_proposed_peak_where_its_labels_say() {
    let svg = plot(
        &[
            "--scene",
            "fig5-steel-sphere-r10-plate",
            "--chart",
            "fx",
            "--model",
            "proposed",
            "--model",
            "hunt-crossley",
            "--model",
            "lankarani-nikravesh",
        ],
        "fig5.svg",
    );
    for title in [
        "F(x) force–approach",
        "x [µm]",
        "F [N]",
        "proposed viscous (eq 18)",
    ] {
        assert!(svg.contains(title), "{title}");
    }
    // Each model's colour (red, cyan, magenta) and its law's pattern: proposed solid, one
    // polyline, the focused one wider; Hunt–Crossley dotted and Lankarani–Nikravesh dashed, many
    // short strokes (the dots far more than the dashes) for the curve and its legend sample.
    let strokes = |colour: &str, width: &str| {
        svg.split('<')
            .filter(|e| e.starts_with("polyline") || e.starts_with("line"))
            .filter(|e| e.contains(colour) && e.contains(&format!("stroke-width=\"{width}\"")))
            .count()
    };
    assert_eq!(strokes("#D62728", "3"), 1, "proposed");
    let (dotted, dashed) = (strokes("#00A0BE", "2"), strokes("#B428AA", "2"));
    assert!(dashed > 10, "lankarani-nikravesh: {dashed} dashes");
    assert!(
        dotted > 2 * dashed,
        "hunt-crossley: {dotted} dots, {dashed} dashes"
    );
    let all = texts(&svg);
    // Tick labels: x labels share one row, y labels one column; each evenly spaced in value is
    // evenly spaced in pixels.
    let (xs, ys) = tick_labels(&svg);
    assert!(xs.len() >= 4 && ys.len() >= 4, "{xs:?} {ys:?}");
    for w in xs.windows(3) {
        let (a, b) = (w[1].1 - w[0].1, w[2].1 - w[1].1);
        let scaled = b * (w[1].0 - w[0].0) / (w[2].0 - w[1].0);
        assert!((a - scaled).abs() <= 1.0, "whole pixels: {xs:?}");
    }
    // F_max of the proposed model as `solve` reports it: the peak glyph lies at its pixel row.
    let solved = run(&[
        "solve",
        "--scene",
        "fig5-steel-sphere-r10-plate",
        "--model",
        "proposed",
        "--format",
        "json",
    ]);
    let json: Value = serde_json::from_slice(&solved.stdout).unwrap();
    let f_max = json["impacts"][0]["f_max"].as_f64().unwrap();
    let row = pixel(&ys, f_max);
    let star = all
        .iter()
        .filter(|(t, _, _)| t == "*")
        .map(|(_, _, y)| (y - row).abs())
        .fold(f64::INFINITY, f64::min);
    assert!(star <= 1.5, "* is {star} px off the row of F_max = {f_max}");
}

#[test]
fn fig2_has_both_materials_and_their_yield_levels() {
    let svg = plot(
        &[
            "--scene",
            "steel-sphere-r10-plate",
            "--scene",
            "aluminium-sphere-r10-plate",
            "--chart",
            "sweep",
            "--quantity",
            "p0",
            "--from",
            "0.01",
            "--to",
            "1",
            "--log",
        ],
        "fig2.svg",
    );
    for label in [
        "1.1·σ_y steel",
        "2.8·σ_y steel",
        "1.1·σ_y aluminium-alloy",
        "2.8·σ_y aluminium-alloy",
        "p₀ [GPa]",
        "v₀ [m/s]",
        "0.01",
        "0.1",
    ] {
        assert!(svg.contains(label), "{label}");
    }
}

#[test]
fn bad_files_and_sizes_are_user_errors() {
    for args in [
        vec![
            "plot",
            "--scene",
            "fig5-steel-sphere-r10-plate",
            "--chart",
            "fx",
            "-o",
            "f.pdf",
        ],
        vec![
            "plot",
            "--scene",
            "fig5-steel-sphere-r10-plate",
            "--chart",
            "fx",
            "-o",
            "f.svg",
            "--size",
            "10x10",
        ],
        vec![
            "plot",
            "--scene",
            "fig5-steel-sphere-r10-plate",
            "--scene",
            "fig4-steel-sphere-r10-plate",
            "--chart",
            "fx",
            "-o",
            "f.svg",
        ],
    ] {
        let output = run(&args);
        assert_eq!(output.status.code(), Some(2), "{args:?}");
        assert!(String::from_utf8_lossy(&output.stderr).starts_with("error: "));
    }
}

/// A figure of an edited scene is titled by its bodies, not by the preset's "…on steel plate".
#[test]
fn an_edited_scene_s_figure_is_titled_by_its_bodies() {
    let svg = plot(
        &[
            "--scene",
            "fig5-steel-sphere-r10-plate",
            "--set",
            "body2.material=aluminium-alloy",
            "--chart",
            "fx",
            "--model",
            "proposed",
        ],
        "edited.svg",
    );
    assert!(
        svg.contains("Steel sphere R = 10 mm on aluminium-alloy plate"),
        "{svg}"
    );
    assert!(!svg.contains("steel plate"));
}
