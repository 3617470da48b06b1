//! The figure back-end of [`Chart`]: SVG (vector, for reports) or PNG through plotters. The same
//! description the terminal draws, on a white page: the ticks where the chart puts them, each
//! series a line in its hue and its law's pattern (solid, dashed, dotted) with its glyph at its
//! peak and end, rules dashed, a legend.
//!
//! PNG text is drawn by ab_glyph from an embedded DejaVu Sans subset (`assets/fonts`), so no
//! system font or fontconfig is needed; SVG text names the `sans-serif` family for the viewer.

use std::path::Path;
use std::sync::Once;

use plotters::coord::Shift;
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use plotters::style::{FontStyle, register_font};

use super::{Chart, Dash, Hue, Ink};

/// DejaVu Sans cut to Latin, Greek, sub- and superscripts and the symbols the charts use.
const FONT: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans-subset.ttf");
const FAMILY: &str = "sans-serif";

/// A figure's file format, by its extension.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    Svg,
    Png,
}

/// Why a figure was not written.
#[derive(Debug, thiserror::Error)]
pub enum FigureError {
    #[error("{0}: a figure is .svg or .png (the extension picks the format)")]
    Format(String),
    #[error("--size must be WIDTHxHEIGHT in pixels, each 200…8000, got {0:?}")]
    Size(String),
    #[error("cannot draw the figure {path}: {reason}")]
    Draw { path: String, reason: String },
}

impl Format {
    pub fn of(path: &Path) -> Result<Format, FigureError> {
        match path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase)
        {
            Some(e) if e == "svg" => Ok(Format::Svg),
            Some(e) if e == "png" => Ok(Format::Png),
            _ => Err(FigureError::Format(path.display().to_string())),
        }
    }
}

/// Parses `WIDTHxHEIGHT` (pixels).
pub fn parse_size(text: &str) -> Result<(u32, u32), FigureError> {
    let bad = || FigureError::Size(text.to_string());
    let (w, h) = text.split_once(['x', 'X', '×']).ok_or_else(bad)?;
    let w: u32 = w.trim().parse().map_err(|_| bad())?;
    let h: u32 = h.trim().parse().map_err(|_| bad())?;
    let ok = |v: u32| (200..=8000).contains(&v);
    if ok(w) && ok(h) {
        Ok((w, h))
    } else {
        Err(bad())
    }
}

/// The print colour of a hue on white.
fn rgb(hue: Hue) -> RGBColor {
    match hue {
        Hue::Foreground => RGBColor(0, 0, 0),
        Hue::Red => RGBColor(214, 39, 40),
        Hue::Green => RGBColor(44, 160, 44),
        Hue::Yellow => RGBColor(188, 150, 0),
        Hue::Blue => RGBColor(31, 90, 200),
        Hue::Magenta => RGBColor(180, 40, 170),
        Hue::Cyan => RGBColor(0, 160, 190),
    }
}

fn color(ink: Ink) -> RGBColor {
    rgb(ink.hue())
}

const GRID: RGBColor = RGBColor(225, 225, 225);
const MUTED: RGBColor = RGBColor(90, 90, 90);

fn font_ready() {
    static REGISTER: Once = Once::new();
    REGISTER.call_once(|| {
        // The font is compiled in and known good; a failure would only lose PNG text.
        let _ = register_font(FAMILY, FontStyle::Normal, FONT);
    });
}

/// Writes `charts` to `path` (side by side for two, stacked for more) at `size` pixels, making
/// its folder if missing.
pub fn write(charts: &[Chart], path: &Path, size: (u32, u32)) -> Result<(), FigureError> {
    let format = Format::of(path)?;
    let fail = |reason: String| FigureError::Draw {
        path: path.display().to_string(),
        reason,
    };
    // A figure path names where the user wants it, as `-o docs/figures/fig5.png` in the README.
    if let Some(folder) = path.parent().filter(|p| !p.as_os_str().is_empty()) {
        std::fs::create_dir_all(folder).map_err(|e| fail(e.to_string()))?;
    }
    font_ready();
    match format {
        Format::Svg => {
            let svg = svg(charts, size).map_err(fail)?;
            std::fs::write(path, svg).map_err(|e| fail(e.to_string()))
        }
        Format::Png => {
            let root = BitMapBackend::new(path, size).into_drawing_area();
            draw_all(&root, charts).map_err(fail)?;
            root.present().map_err(|e| fail(e.to_string()))
        }
    }
}

/// The SVG text of `charts` at `size` pixels.
pub fn svg(charts: &[Chart], size: (u32, u32)) -> Result<String, String> {
    font_ready();
    let mut out = String::new();
    {
        let root = SVGBackend::with_string(&mut out, size).into_drawing_area();
        draw_all(&root, charts)?;
        root.present().map_err(|e| e.to_string())?;
    }
    Ok(out)
}

fn draw_all<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    charts: &[Chart],
) -> Result<(), String> {
    root.fill(&WHITE).map_err(|e| e.to_string())?;
    let grid = match charts.len() {
        0 | 1 => (1, 1),
        2 => (1, 2),
        n => (n, 1),
    };
    for (area, chart) in root.split_evenly(grid).iter().zip(charts) {
        draw(area, chart).map_err(|e| e.to_string())?;
    }
    Ok(())
}

/// Margins around the plot, px: left (y labels), right, top (title, y title), bottom (x labels,
/// x title).
const LEFT: i32 = 78;
const RIGHT: i32 = 24;
const TOP: i32 = 52;
const BOTTOM: i32 = 58;

/// The plot rectangle's pixel mapping.
struct Plot {
    x0: i32,
    x1: i32,
    y0: i32,
    y1: i32,
}

impl Plot {
    fn at(&self, chart: &Chart, (x, y): (f64, f64)) -> Option<(i32, i32)> {
        let fx = chart.x.fraction(x);
        let fy = chart.y.fraction(y);
        (fx.is_finite() && fy.is_finite()).then(|| {
            (
                self.x0 + (fx * f64::from(self.x1 - self.x0)).round() as i32,
                self.y1 - (fy * f64::from(self.y1 - self.y0)).round() as i32,
            )
        })
    }
}

type Drawn<DB> = Result<(), DrawingAreaErrorKind<<DB as DrawingBackend>::ErrorType>>;

fn text_style(size: u32, ink: RGBColor, h: HPos, v: VPos) -> TextStyle<'static> {
    (FAMILY, size).into_font().color(&ink).pos(Pos::new(h, v))
}

fn draw<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, chart: &Chart) -> Drawn<DB> {
    let (w, h) = area.dim_in_pixel();
    let (w, h) = (w as i32, h as i32);
    // The legend stands right of the plot, where it covers no data.
    let p = Plot {
        x0: LEFT,
        x1: w - RIGHT - legend_width(chart),
        y0: TOP,
        y1: h - BOTTOM,
    };
    if p.x1 <= p.x0 + 20 || p.y1 <= p.y0 + 20 {
        return Ok(());
    }
    let body = text_style(14, BLACK, HPos::Center, VPos::Top);
    area.draw(&Text::new(
        chart.title.clone(),
        (w / 2, 8),
        text_style(16, BLACK, HPos::Center, VPos::Top),
    ))?;
    // Grid and ticks at the chart's own tick values.
    for t in &chart.x.ticks {
        let Some((x, _)) = p.at(chart, (t.at, chart.y.range[0])) else {
            continue;
        };
        area.draw(&PathElement::new(vec![(x, p.y0), (x, p.y1)], GRID))?;
        area.draw(&PathElement::new(vec![(x, p.y1), (x, p.y1 + 5)], BLACK))?;
        area.draw(&Text::new(t.label.clone(), (x, p.y1 + 8), body.clone()))?;
    }
    for t in &chart.y.ticks {
        let Some((_, y)) = p.at(chart, (chart.x.range[0], t.at)) else {
            continue;
        };
        area.draw(&PathElement::new(vec![(p.x0, y), (p.x1, y)], GRID))?;
        area.draw(&PathElement::new(vec![(p.x0 - 5, y), (p.x0, y)], BLACK))?;
        area.draw(&Text::new(
            t.label.clone(),
            (p.x0 - 8, y),
            text_style(14, BLACK, HPos::Right, VPos::Center),
        ))?;
    }
    area.draw(&Rectangle::new([(p.x0, p.y0), (p.x1, p.y1)], BLACK))?;
    area.draw(&Text::new(
        chart.x.title.clone(),
        ((p.x0 + p.x1) / 2, p.y1 + 30),
        body.clone(),
    ))?;
    area.draw(&Text::new(
        chart.y.title.clone(),
        (8, p.y0 - 20),
        text_style(14, BLACK, HPos::Left, VPos::Top),
    ))?;
    for rule in &chart.rules {
        let [a, b] = rule.ends(chart);
        let (Some(a), Some(b)) = (p.at(chart, a), p.at(chart, b)) else {
            continue;
        };
        let style = color(rule.ink).stroke_width(2);
        area.draw(&DashedPathElement::new(vec![a, b], 8, 5, style))?;
        let (at, pos) = if rule.horizontal {
            ((b.0 - 5, b.1 - 4), (HPos::Right, VPos::Bottom))
        } else {
            ((b.0 + 5, b.1 + 4), (HPos::Left, VPos::Top))
        };
        area.draw(&Text::new(
            rule.label.clone(),
            at,
            text_style(14, color(rule.ink), pos.0, pos.1),
        ))?;
    }
    for s in &chart.series {
        let style = color(s.ink).stroke_width(if s.focused { 3 } else { 2 });
        for run in &s.runs {
            let points = thinned(run.iter().filter_map(|&q| p.at(chart, q)));
            if let [dot] = points[..] {
                // A scatter's point (an impact, a diagram's point) alone: a line would not show.
                area.draw(&Circle::new(dot, 2, color(s.ink).filled()))?;
            } else {
                stroke(area, points, s.ink.dash(), style)?;
            }
        }
        let glyph = text_style(16, color(s.ink), HPos::Center, VPos::Center);
        let marked: Vec<(f64, f64)> = if s.steps {
            s.runs.iter().flatten().copied().collect()
        } else {
            s.peak.iter().copied().chain(s.end()).collect()
        };
        for q in marked {
            if let Some(at) = p.at(chart, q) {
                area.draw(&Text::new(s.glyph.to_string(), at, glyph.clone()))?;
            }
        }
    }
    let mut labels = Vec::new();
    for mark in &chart.marks {
        let Some((x, y)) = p.at(chart, mark.at) else {
            continue;
        };
        area.draw(&Rectangle::new(
            [(x - 5, y - 5), (x + 5, y + 5)],
            color(mark.ink).filled(),
        ))?;
        if let Some(label) = &mark.label {
            area.draw(&Text::new(
                label.clone(),
                // Stacked towards the plot's middle, away from the axes' labels.
                free_line(&mut labels, (x + 9, y), label, y > (p.y0 + p.y1) / 2),
                text_style(13, color(mark.ink), HPos::Left, VPos::Center),
            ))?;
        }
    }
    legend(area, chart, &p)?;
    for (i, note) in chart.notes.iter().enumerate() {
        area.draw(&Text::new(
            note.clone(),
            (p.x0 + 8, p.y0 + 8 + 18 * i as i32),
            text_style(13, rgb(Hue::Red), HPos::Left, VPos::Top),
        ))?;
    }
    Ok(())
}

/// A line through `points` in the pattern `dash`, as the terminal draws it: dashes of 10 px 6 px
/// apart, dots of 2 px 4 px apart.
/// Where a mark's label at `at` (left, vertical centre) is read, stacked a line above (`up`) or
/// below the labels already `placed` that it would overprint (a rigid and a compliant point a hair
/// apart, e.g. their grazing); records its box. About 7 px a character and 16 px a line at size 13.
fn free_line(
    placed: &mut Vec<[i32; 4]>,
    (x, mut y): (i32, i32),
    label: &str,
    up: bool,
) -> (i32, i32) {
    const LINE: i32 = 16;
    let right = x + 7 * label.chars().count() as i32;
    let overlaps = |y: i32, b: &[i32; 4]| {
        x < b[2] && b[0] < right && y - LINE / 2 < b[3] && b[1] < y + LINE / 2
    };
    while placed.iter().any(|b| overlaps(y, b)) {
        y += if up { -LINE } else { LINE };
    }
    placed.push([x, y - LINE / 2, right, y + LINE / 2]);
    (x, y)
}

fn stroke<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    points: Vec<(i32, i32)>,
    dash: Dash,
    style: ShapeStyle,
) -> Drawn<DB> {
    match dash {
        Dash::Solid => area.draw(&PathElement::new(points, style)),
        Dash::Dashed => area.draw(&DashedPathElement::new(points, 10, 6, style)),
        Dash::Dotted => area.draw(&DashedPathElement::new(points, 2, 4, style)),
    }
}

/// Pixels closer than this to the last point kept are dropped from a path: wide strokes drawn
/// through many sub-pixel segments come out ragged at every joint.
const MIN_STEP_PX: i32 = 3;

/// `points` without those within [`MIN_STEP_PX`] of the previous one kept (the last always kept).
fn thinned(points: impl Iterator<Item = (i32, i32)>) -> Vec<(i32, i32)> {
    let mut out: Vec<(i32, i32)> = Vec::new();
    let mut last_dropped = None;
    for q in points {
        match out.last() {
            Some(&(x, y)) if (q.0 - x).abs().max((q.1 - y).abs()) < MIN_STEP_PX => {
                last_dropped = Some(q);
            }
            _ => {
                out.push(q);
                last_dropped = None;
            }
        }
    }
    out.extend(last_dropped);
    out
}

/// Space between the plot and its legend, px.
const LEGEND_GAP: i32 = 12;

/// Width the legend takes right of the plot (gap included), px; none without series.
fn legend_width(chart: &Chart) -> i32 {
    let longest = chart.series.iter().map(|s| s.name.chars().count()).max();
    longest.map_or(0, |n| LEGEND_GAP + 44 + 7 * n as i32)
}

/// The series' names with line samples and glyphs, in a box right of the plot's top.
fn legend<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, chart: &Chart, p: &Plot) -> Drawn<DB> {
    if chart.series.is_empty() {
        return Ok(());
    }
    let row = 18;
    let width = legend_width(chart) - LEGEND_GAP;
    let height = row * chart.series.len() as i32 + 8;
    let (x, y) = (p.x1 + LEGEND_GAP, p.y0);
    area.draw(&Rectangle::new(
        [(x, y), (x + width, y + height)],
        WHITE.mix(0.85).filled(),
    ))?;
    area.draw(&Rectangle::new([(x, y), (x + width, y + height)], MUTED))?;
    for (i, s) in chart.series.iter().enumerate() {
        let cy = y + 4 + row * i as i32 + row / 2;
        let ink = color(s.ink);
        stroke(
            area,
            vec![(x + 6, cy), (x + 34, cy)],
            s.ink.dash(),
            ink.stroke_width(2),
        )?;
        area.draw(&Text::new(
            s.glyph.to_string(),
            (x + 20, cy),
            text_style(14, ink, HPos::Center, VPos::Center),
        ))?;
        area.draw(&Text::new(
            s.name.clone(),
            (x + 40, cy),
            text_style(13, BLACK, HPos::Left, VPos::Center),
        ))?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::chart::{Axis, Mark, Rule, Series, Tick};

    fn chart() -> Chart {
        let axis = |title: &str, hi: f64| Axis {
            title: title.into(),
            range: [0.0, hi],
            log: false,
            ticks: (0..=4)
                .map(|i| Tick {
                    at: hi * f64::from(i) / 4.0,
                    label: format!("{}", hi * f64::from(i) / 4.0),
                })
                .collect(),
        };
        Chart {
            rules: vec![Rule {
                at: 4.0,
                horizontal: false,
                ink: Ink::Warning,
                label: "v_y".into(),
            }],
            ..Chart::new(
                "F(x)".into(),
                axis("x [µm]", 8.0),
                axis("F [N]", 400.0),
                vec![
                    Series {
                        name: "proposed".into(),
                        ink: Ink::Model(crate::model::ForceModel::Proposed),
                        glyph: '*',
                        runs: vec![vec![(0.0, 0.0), (7.0, 320.0), (2.0, 0.0)]],
                        focused: true,
                        peak: Some((7.0, 320.0)),
                        steps: false,
                    },
                    Series {
                        name: "hunt-crossley".into(),
                        ink: Ink::Model(crate::model::ForceModel::HuntCrossley),
                        glyph: 'x',
                        runs: vec![vec![(0.0, 0.0), (8.0, 360.0), (0.0, 0.0)]],
                        focused: false,
                        peak: Some((8.0, 360.0)),
                        steps: false,
                    },
                ],
            )
        }
    }

    /// Two marks a hair apart (a rigid and a compliant grazing point): both labels readable, the
    /// second a line from the first towards the plot's middle; a third elsewhere stays at its
    /// point.
    #[test]
    fn labels_that_would_overprint_are_stacked() {
        let mut c = chart();
        let mark = |at, label: &str| Mark {
            at,
            ink: Ink::Warning,
            glyph: 'G',
            label: Some(label.into()),
        };
        c.marks = vec![
            mark((2.0, 100.0), "grazing 0.0135653"),
            mark((2.0001, 100.0), "grazing 0.0135652"),
            mark((6.0, 300.0), "PD 0.0368"),
        ];
        let svg = svg(&[c], (640, 480)).unwrap();
        let y_of = |label: &str| {
            svg.split("<text")
                .find(|t| t.contains(&format!(">{label}<")) || t.contains(&format!(">\n{label}")))
                .and_then(|t| attr(t, "y"))
                .unwrap_or_else(|| panic!("{label} in {svg}"))
        };
        let (a, b) = (y_of("grazing 0.0135653"), y_of("grazing 0.0135652"));
        // In the plot's lower half: the second above the first, towards the middle.
        assert!(a - b >= 15.0, "{a} {b}");
        let mut placed = Vec::new();
        assert_eq!(free_line(&mut placed, (10, 50), "PD", false), (10, 50));
        assert_eq!(free_line(&mut placed, (12, 52), "PD", false), (12, 68));
        assert_eq!(free_line(&mut placed, (12, 52), "PD", true), (12, 20));
        assert_eq!(free_line(&mut placed, (200, 50), "PD", false), (200, 50));
    }

    /// Numbers of the attribute `name` in an SVG element's text.
    fn attr(element: &str, name: &str) -> Option<f64> {
        let start = element.find(&format!(" {name}=\""))? + name.len() + 3;
        let rest = &element[start..];
        rest[..rest.find('"')?].parse().ok()
    }

    /// The SVG has the axes' labels at their pixels (linear in value between the plot's edges),
    /// the titles, one path per series run and a dashed rule.
    #[test]
    fn the_svg_has_ticks_at_their_values_and_one_path_per_series() {
        let svg = svg(&[chart()], (640, 480)).unwrap();
        let texts: Vec<&str> = svg.split("<text").skip(1).collect();
        let label_x = |label: &str| {
            texts
                .iter()
                .find(|t| {
                    let content = t.split_once('>').map_or("", |(_, c)| c);
                    content.split("</text>").next().map(str::trim) == Some(label)
                })
                .and_then(|t| attr(t, "x"))
                .unwrap_or_else(|| panic!("{label} in {svg}"))
        };
        // x ticks 0, 2, …, 8 over the plot from LEFT to the legend.
        let span = f64::from(640 - RIGHT - legend_width(&chart()) - LEFT);
        for (i, label) in ["0", "2", "4", "6", "8"].iter().enumerate() {
            let expected = f64::from(LEFT) + span * i as f64 / 4.0;
            assert!((label_x(label) - expected).abs() <= 1.0, "{label}");
        }
        for title in [
            "x [µm]",
            "F [N]",
            "F(x)",
            "proposed",
            "hunt-crossley",
            "v_y",
        ] {
            assert!(svg.contains(title), "{title}");
        }
        // Curves: one polyline per series, in its hue, the focused one wider.
        let red = "#D62728";
        let polylines: Vec<&str> = svg.split("<polyline").skip(1).collect();
        let curves = polylines
            .iter()
            .filter(|p| p.contains(red) && p.contains("stroke-width=\"3\""))
            .count();
        assert_eq!(curves, 1, "{svg}");
        assert!(svg.contains("#00A0BE"), "hunt-crossley in cyan");
        // Hunt–Crossley's line is dotted, as in the terminal: many short strokes, not one path.
        let dots = svg
            .split("<line")
            .skip(1)
            .filter(|l| l.contains("#00A0BE"))
            .count()
            + polylines.iter().filter(|p| p.contains("#00A0BE")).count();
        assert!(dots > 20, "{dots} strokes: {svg}");
    }

    #[test]
    fn paths_drop_points_closer_than_a_few_pixels_but_keep_their_ends() {
        let points = [(0, 0), (1, 0), (2, 1), (5, 1), (6, 1), (7, 2)];
        assert_eq!(thinned(points.into_iter()), [(0, 0), (5, 1), (7, 2)]);
        assert_eq!(thinned([(0, 0)].into_iter()), [(0, 0)]);
    }

    #[test]
    fn formats_and_sizes_are_checked() {
        assert_eq!(Format::of(Path::new("a/b.SVG")).unwrap(), Format::Svg);
        assert_eq!(Format::of(Path::new("fig.png")).unwrap(), Format::Png);
        assert!(Format::of(Path::new("fig.pdf")).is_err());
        assert_eq!(parse_size("1200x800").unwrap(), (1200, 800));
        assert!(parse_size("12x800").is_err());
        assert!(parse_size("wide").is_err());
    }

    #[test]
    fn a_png_is_written_with_text() {
        let dir = tempfile::Builder::new()
            .prefix("hertz-tui-figure-")
            .tempdir()
            .unwrap();
        let path = dir.path().join("f.png");
        write(&[chart(), chart()], &path, (800, 400)).unwrap();
        let bytes = std::fs::read(&path).unwrap();
        assert_eq!(&bytes[1..4], b"PNG");
    }
}
