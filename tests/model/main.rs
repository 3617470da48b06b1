//! Model-layer tests in one binary (one link of the library instead of one per file): the paper's
//! tables and figures, exact solutions, integrators, impacts, property tests and presets.

#[allow(dead_code)]
mod ode_common;

mod dry_friction_cutoff;
mod impact_crosscheck;
mod impact_exact;
mod impact_paper;
mod impact_props;
mod impact_stability;
mod impact_trajectory;
mod ode_convergence;
mod ode_crosscheck;
mod ode_events;
mod ode_stability;
mod presets;
mod quasistatic_props;
mod tables;
mod tolerance_promise;
