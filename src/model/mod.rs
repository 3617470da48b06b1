//! The model layer: contact mechanics and impact dynamics in SI units. Knows nothing of the UI,
//! the command line or charts (`tests/architecture.rs` fails the build if it imports them), and
//! words no text for them: errors carry their numbers and fields, results are data.
//!
//! Used as a library, its entry points are:
//! - a scene: [`presets::Registry::scene`] (or [`scene_file::parse_scene`]), its quasistatic
//!   estimate [`Scene::quasistatic`] (eqs 1–14) and the solver's inputs [`Scene::impact_params`];
//! - solving an impact: [`impact::solve_impact`];
//! - calibrating a law to a requested restitution: [`calibrate::calibrate`];
//! - the restitution each law realises: [`restitution::table`];
//! - contact parameters for a simulation engine: [`engine::translate`].
//!
//! Each has an example that runs as a test.

pub mod body;
pub mod calibrate;
pub mod cylinder;
pub mod engine;
pub mod error;
pub mod exact;
pub mod fit;
pub mod force;
pub mod impact;
pub mod material;
pub mod numeric;
pub mod ode;
pub mod overrides;
pub mod pair;
pub mod power_law;
pub mod presets;
pub mod pressure;
pub mod quasistatic;
pub mod recommend;
pub mod restitution;
pub mod scene;
pub mod scene_file;
pub mod scene_fit;
pub mod scene_key;
pub mod scene_title;
pub mod sphere;
pub mod study;
pub mod system;
pub mod warnings;

pub use body::{Body, Shape};
pub use error::ModelError;
pub use force::{ForceModel, ImpactParams};
pub use material::Material;
pub use pair::{ContactPair, PairKind};
pub use power_law::PowerLaw;
pub use quasistatic::Quasistatic;
pub use scene::{ImpactConditions, Scene};
