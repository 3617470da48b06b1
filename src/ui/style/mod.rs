//! The one place the explorer's looks are chosen: the colours and text roles (light and dark
//! terminals, `NO_COLOR`, muted text by DIM) and the chart marker of `--marker`.

mod marker;
mod theme;

pub use marker::MarkerStyle;
pub use theme::*;
