//! hertz-tui: a terminal explorer of impact contact forces.
//!
//! `model` holds the physics, the numerics and the study runner, and stands alone (it imports no
//! other module of the crate and no UI or command-line crate); `chart` builds charts from its
//! results as plain data, for the terminal and for figure files; `format` writes numbers, units
//! and trajectories for both edges; `cli` exposes them headless and `ui` is the explorer. Neither
//! `cli` nor `chart` imports `ui`.
//!
//! The model layer on its own, reproducing the paper's Fig. 5 scene (a steel sphere R = 10 mm
//! dropped at 0.3 m/s on a steel plate):
//!
//! ```
//! use hertz_tui::model::ForceModel;
//! use hertz_tui::model::impact::{SolveOptions, solve_impact};
//! use hertz_tui::model::presets::{DEFAULT_SCENE, Registry};
//!
//! let scene = Registry::builtin()?.scene(DEFAULT_SCENE)?;
//! let hertz = scene.quasistatic()?;
//! // Eqs 5–7 with Table 1's k = 1.465e10 N/m^1.5 and m = 32.67 g (density 7800 kg/m³).
//! assert!((hertz.k / 1.465e10 - 1.0).abs() < 5e-4);
//! assert!((hertz.x_max / 9.115e-6 - 1.0).abs() < 1e-3);
//! assert!((hertz.f_max / 403.2 - 1.0).abs() < 1e-3);
//!
//! // Hunt–Crossley (eq 19) leaves faster than v₀·e = 0.18 m/s, as the paper reports (0.21 m/s).
//! let params = scene.impact_params(&hertz);
//! let hc = solve_impact(ForceModel::HuntCrossley, &params, &SolveOptions::default())?;
//! assert!((hc.summary.v_out - 0.2136).abs() < 1e-4);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod chart;
pub mod cli;
pub mod format;
pub mod model;
pub mod ui;
