//! Built-in presets (embedded), user presets ($XDG_CONFIG_HOME/hertz-tui/presets/) and files by path.
//!
//! A preset's name is its file stem in kebab-case. User presets override built-ins of the same name;
//! a user preset that does not parse is skipped with a warning instead of failing everything.
#![warn(missing_docs)]

mod builtin;
mod error;
mod registry;
mod save;
mod user_dir;

pub use error::PresetError;
pub use registry::{Origin, PresetInfo, Registry};
pub use save::{SaveTarget, is_kebab_case, kebab_case, save_scene};
pub use user_dir::{user_dir, user_dir_from};

/// The scene the explorer opens with: the paper's Fig. 5 (v₀ = 0.3 m/s, e = 0.6, x_pl = 2.3 µm).
pub const DEFAULT_SCENE: &str = "fig5-steel-sphere-r10-plate";
