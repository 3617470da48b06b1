//! Model-layer tests in one binary (one link of the library instead of one per file): the paper's
//! tables and figures, exact solutions, integrators, impacts, property tests and presets.

#[allow(dead_code)]
mod ode_common;

mod bodies_props;
mod calibration;
mod continuation_ball;
mod continuation_compliant;
mod continuation_grazing;
mod continuation_oscillator;
mod dry_friction_cutoff;
mod engine_runs;
mod engines;
mod engines_vs_laws;
#[allow(dead_code)]
mod fit_common;
mod fit_coverage;
mod fit_errors;
mod fit_forward;
mod fit_recovery;
mod fit_selection;
mod fit_trace;
mod impact_crosscheck;
mod impact_exact;
mod impact_paper;
mod impact_props;
mod impact_stability;
mod impact_trajectory;
mod integrated_landing;
mod laws_common;
mod laws_kuwabara_kono;
mod laws_line_exact;
mod laws_thornton;
mod laws_thornton_line;
mod laws_viscous;
mod ode_convergence;
mod ode_crosscheck;
mod ode_events;
mod ode_stability;
mod presets;
mod quasistatic_props;
mod scene_view;
#[allow(dead_code)]
#[path = "../scratch/mod.rs"]
mod scratch;
mod system_compliant;
mod systems_ball;
#[allow(dead_code)]
mod systems_common;
mod systems_diagram;
mod systems_hard;
mod systems_map;
mod systems_map_chatter;
mod systems_map_unsettled;
mod systems_oscillator;
mod systems_scene;
mod systems_seed;
mod tables;
mod tolerance_promise;
