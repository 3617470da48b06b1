//! Text shared by the command line and the explorer: numbers in engineering notation
//! ([`engineering`], [`significant`], [`scientific`], [`round_trip`]), the trajectory CSV
//! ([`csv`]) and the sweep CSV ([`sweep_csv`]), an engine translation ([`translation`]) and the model's recommendation
//! ([`recommendation`]). Neither `cli` nor `ui` keeps its own copy.

pub mod csv;
pub mod fit_csv;
mod number;
pub mod recommendation;
mod shortest_exp;
pub mod sweep_csv;
pub mod trace_csv;
pub mod translation;
pub mod units;
pub mod verdict;

pub use number::{
    ENGINEERING, FEMTO, GIGA, KILO, MEGA, MICRO, MILLI, NANO, NONE, NOT_A_NUMBER, PICO, Prefix,
    TERA, Zeros, engineering, round_trip, scientific, significant, with_unit,
};
pub use shortest_exp::push_shortest_exp;
