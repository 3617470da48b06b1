//! The command line driven as a user would: the real binary, its output parsed.

mod commands;
mod continuation;
mod fit;
mod fit_data;
mod laws;
mod maps;
mod plot;
mod readme;
mod recommendation;
#[path = "../scratch/mod.rs"]
mod scratch;
mod studies;
mod support;
mod systems;
