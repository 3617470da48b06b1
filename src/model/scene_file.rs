//! Scene files (TOML): parsing with errors that name file, line and key; writing back.
//!
//! A file is parsed into a [`Document`] (the TOML table plus the line of every key), which
//! `--set` overrides may edit before it is decoded into a [`Scene`](crate::model::Scene). Decoding is strict: unknown
//! keys, missing keys, wrong types and keys the body's shape does not use are all errors. A scene
//! file may also say how to view it ([`SceneView`]: the checked models and the solver settings)
//! and put its bodies in a machine (`[system]`: [`decode_system`], [`system_table`]).

mod decode;
mod document;
mod fit;
mod schema;
mod system;
mod view;
mod write;

pub use decode::{decode_material, decode_scene, decode_view, parse_scene};
pub use document::{Document, Location, Problem, SceneFileError, ValueIssue};
pub use fit::fit_table;
pub(crate) use schema::{KeyKind, SHAPES, key_kind, shape_keys};
pub use system::{FORCINGS, SYSTEM_KINDS, decode_system, system_table};
pub use view::{PAPER_MODELS, SceneView};
pub use write::{to_toml, to_toml_with_system, to_toml_with_view, toml_float};
