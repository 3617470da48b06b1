//! The one place the explorer's looks are chosen: the themes (dark, light, `NO_COLOR`) with their
//! colours and text roles, the contrast they are held to, and the chart marker of `--marker`.

pub mod contrast;
mod marker;
mod theme;

pub use marker::MarkerStyle;
pub use theme::*;
