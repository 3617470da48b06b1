//! Widgets the views share: the chart canvas, the model checklist, line editors, the tab bar, the
//! status line and the overlays (help, engines, presets, prompts), each a pure function of `&App`.

pub(crate) mod common;
mod dots;
pub(crate) mod editable;
pub mod engine;
pub mod graph;
pub mod help;
pub mod models;
pub mod picker;
pub mod prompt;
pub mod status;
mod strokes;
pub mod tabs;
pub mod too_small;
