//! The map drawn as text: one glyph per cell (rows of y from the top down, x to the right), the
//! axes' ends, and a legend of the motions with their share of the cells.

use std::fmt::Write as _;

use crate::chart::map::look;

use super::file::{Layer, MapFile};

/// Columns and rows of text at most: a larger map is drawn by the nearest cell.
const MAX: (usize, usize) = (100, 50);

/// Every layer of `file`, one after the other.
pub fn draw(file: &MapFile) -> String {
    let mut out = String::new();
    for layer in &file.layers {
        draw_layer(&mut out, file, layer);
    }
    out
}

fn draw_layer(out: &mut String, file: &MapFile, layer: &Layer) {
    let (hx, hy) = (&file.header.x, &file.header.y);
    let (nx, ny) = (hx.points, hy.points);
    let (cols, rows) = (nx.min(MAX.0), ny.min(MAX.1));
    let _ = writeln!(
        out,
        "{} map of {}: {} across, {} up ({nx} × {ny} cells)",
        layer.contact, file.header.scene, hx.key, hy.key
    );
    let pick = |i: usize, of: usize, n: usize| {
        if of <= 1 {
            0
        } else {
            (i * (n - 1) + (of - 1) / 2) / (of - 1)
        }
    };
    let label = format!("{}", hy.to);
    let width = label.len().max(format!("{}", hy.from).len());
    let mut cells = vec![None; nx * ny];
    for c in &layer.cells {
        if let Some(slot) = cells.get_mut(c.iy * nx + c.ix).filter(|_| c.ix < nx) {
            *slot = Some(c);
        }
    }
    for r in 0..rows {
        let iy = pick(rows - 1 - r, rows, ny);
        let side = if r == 0 {
            format!("{}", hy.to)
        } else if r + 1 == rows {
            format!("{}", hy.from)
        } else {
            String::new()
        };
        let line: String = (0..cols)
            .map(|c| {
                cells[iy * nx + pick(c, cols, nx)]
                    .map_or(' ', |cell| look(&cell.motion, cell.impacts).glyph)
            })
            .collect();
        let _ = writeln!(out, "{side:>width$} |{line}");
    }
    let left = format!("{}", hx.from);
    let right = format!("{}", hx.to);
    let _ = writeln!(out, "{:>width$} +{}", "", "-".repeat(cols));
    let gap = (cols + 1).saturating_sub(left.len() + right.len()).max(1);
    let _ = writeln!(out, "{:>width$}  {left}{}{right}", "", " ".repeat(gap));
    // The legend: each look with its count, in order of first appearance.
    let mut legend: Vec<(char, String, usize)> = Vec::new();
    for cell in &layer.cells {
        let l = look(&cell.motion, cell.impacts);
        match legend.iter_mut().find(|e| e.1 == l.name) {
            Some(e) => e.2 += 1,
            None => legend.push((l.glyph, l.name, 1)),
        }
    }
    let total = layer.cells.len().max(1);
    for (glyph, name, count) in legend {
        let _ = writeln!(
            out,
            "  {glyph}  {name}: {count} cell{} ({:.1} %)",
            if count == 1 { "" } else { "s" },
            100.0 * count as f64 / total as f64
        );
    }
    out.push('\n');
}
