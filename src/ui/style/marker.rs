//! The chart marker (the command line's `--marker`), for fonts that lack braille.

use ratatui::symbols::Marker;

/// How chart points are drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum MarkerStyle {
    /// Braille patterns: 2×4 dots per cell, the finest resolution.
    #[default]
    Braille,
    /// One dot per cell.
    Dot,
    /// One full block per cell.
    Block,
}

impl MarkerStyle {
    /// The ratatui marker drawn for this style.
    pub fn marker(self) -> Marker {
        match self {
            MarkerStyle::Braille => Marker::Braille,
            MarkerStyle::Dot => Marker::Dot,
            MarkerStyle::Block => Marker::Block,
        }
    }

    /// Horizontal resolution of one terminal cell with this marker, in plot columns.
    pub fn dots_per_cell(self) -> u16 {
        match self {
            MarkerStyle::Braille => 2,
            MarkerStyle::Dot | MarkerStyle::Block => 1,
        }
    }

    /// Vertical resolution of one terminal cell with this marker, in plot rows.
    pub fn dots_per_row(self) -> u16 {
        match self {
            MarkerStyle::Braille => 4,
            MarkerStyle::Dot | MarkerStyle::Block => 1,
        }
    }
}
