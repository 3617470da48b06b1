//! The explorer: rendered into ratatui's TestBackend, and the real binary driven in tmux.

mod axes;
mod contrast;
mod cut_words;
mod e2e_tmux;
mod fit;
mod map;
mod models_pane;
mod readme_screen;
mod render;
mod results_damping;
#[path = "../scratch/mod.rs"]
mod scratch;
mod system;
mod system_branch;
mod system_scene;
