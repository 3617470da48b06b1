//! Where ticks land on a grid of cells (terminal columns or rows), so that each label is centred
//! on the cell its value falls in, by the same rounding the curves are drawn with.

use super::Axis;

/// A tick placed on a cell: `cell` counts from the start of the axis (left, or bottom).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Placed {
    pub cell: u16,
    pub label: String,
}

/// The dot (of `cells × dots_per_cell`) where display value `value` is drawn: the first dot at the
/// axis start, the last at its end. `None` off the axis.
pub fn dot(axis: &Axis, value: f64, cells: u16, dots_per_cell: u16) -> Option<u32> {
    let f = axis.fraction(value);
    let dots = u32::from(cells) * u32::from(dots_per_cell);
    if !(-1e-9..=1.0 + 1e-9).contains(&f) || dots == 0 {
        return None;
    }
    Some((f.clamp(0.0, 1.0) * f64::from(dots - 1)).round() as u32)
}

/// The cell of display value `value` along an axis of `cells` cells of `dots_per_cell` dots.
pub fn cell(axis: &Axis, value: f64, cells: u16, dots_per_cell: u16) -> Option<u16> {
    dot(axis, value, cells, dots_per_cell).map(|d| (d / u32::from(dots_per_cell.max(1))) as u16)
}

/// The axis's ticks on `cells` cells, each label `width(label)` cells wide centred on its tick
/// (`width = |_| 1` for rows): every other tick is left unlabelled, then every third…, until no two
/// labels touch (a blank cell between neighbours) — the labels left are still exactly placed.
pub fn place_ticks(
    axis: &Axis,
    cells: u16,
    dots_per_cell: u16,
    width: impl Fn(&str) -> u16,
) -> Vec<Placed> {
    let all: Vec<Placed> = axis
        .ticks
        .iter()
        .filter_map(|t| {
            Some(Placed {
                cell: cell(axis, t.at, cells, dots_per_cell)?,
                label: t.label.clone(),
            })
        })
        .collect();
    let span = |p: &Placed| {
        let w = i32::from(width(&p.label));
        let start = i32::from(p.cell) - (w - 1) / 2;
        (start, start + w)
    };
    for every in 1..=all.len().max(1) {
        let kept: Vec<Placed> = all.iter().step_by(every).cloned().collect();
        let apart = kept.windows(2).all(|w| span(&w[0]).1 < span(&w[1]).0);
        if apart {
            return kept;
        }
    }
    all.into_iter().take(1).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::chart::Tick;

    fn axis(range: [f64; 2], ticks: &[(f64, &str)]) -> Axis {
        Axis {
            title: String::new(),
            range,
            log: false,
            ticks: ticks
                .iter()
                .map(|&(at, label)| Tick {
                    at,
                    label: label.into(),
                })
                .collect(),
        }
    }

    #[test]
    fn ticks_sit_on_the_cell_of_their_value() {
        // 0…10 over 41 columns of 2 dots: 82 dots, value v at dot round(v/10·81).
        let a = axis(
            [0.0, 10.0],
            &[(0.0, "0"), (2.0, "2"), (8.0, "8"), (10.0, "10")],
        );
        let placed = place_ticks(&a, 41, 2, |l| l.chars().count() as u16);
        let cells: Vec<u16> = placed.iter().map(|p| p.cell).collect();
        assert_eq!(cells, [0, 8, 32, 40]);
        assert_eq!(cell(&a, 7.575, 41, 2), Some(30));
        assert_eq!(cell(&a, 10.5, 41, 2), None);
    }

    #[test]
    fn crowded_labels_are_thinned_never_moved() {
        let a = axis(
            [0.0, 4.0],
            &[
                (0.0, "0.0"),
                (1.0, "1.0"),
                (2.0, "2.0"),
                (3.0, "3.0"),
                (4.0, "4.0"),
            ],
        );
        // 13 columns: ticks 3 apart, labels 3 wide: touching, so every other one.
        let placed = place_ticks(&a, 13, 1, |l| l.chars().count() as u16);
        let labels: Vec<&str> = placed.iter().map(|p| p.label.as_str()).collect();
        assert_eq!(labels, ["0.0", "2.0", "4.0"]);
        assert_eq!(placed[1].cell, 6);
        // Rows: a blank row between labels.
        let rows = place_ticks(&a, 9, 4, |_| 1);
        assert_eq!(rows.len(), 5);
    }
}
