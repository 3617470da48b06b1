//! What a continuation returns: a branch (or a two-parameter curve) of periodic orbits with their
//! stability, and the special points on it, located to the settings' tolerance.
#![warn(missing_docs)]

use nalgebra::Complex;
use serde::Serialize;

use crate::model::system::ImpactPoint;

/// Continuation settings (scaled arclength: phases in rad, speeds over the start orbit's largest
/// impact speed, parameters over their range).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContinuationOptions {
    /// Points on a branch at most (beyond, it ends with [`BranchEnd::MaxPoints`]).
    pub max_points: usize,
    /// First arclength step.
    pub initial_step: f64,
    /// Largest arclength step.
    pub max_step: f64,
    /// Below this step the branch ends ([`BranchEnd::StepTooSmall`]).
    pub min_step: f64,
    /// A special point is located when its arclength bracket is below this.
    pub locate_tolerance: f64,
    /// Whether the branch ends at a grazing point (past it the orbit would cross the stop).
    pub stop_at_grazing: bool,
}

impl Default for ContinuationOptions {
    fn default() -> ContinuationOptions {
        ContinuationOptions {
            max_points: 400,
            initial_step: 0.01,
            max_step: 0.05,
            min_step: 1e-9,
            locate_tolerance: 1e-13,
            stop_at_grazing: true,
        }
    }
}

/// What happens at a special point.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum SpecialKind {
    /// A multiplier +1, det(J − I) = 0: a fold (saddle-node), the branch turns back.
    Fold,
    /// A multiplier −1, det(J + I) = 0: a period doubling.
    PeriodDoubling,
    /// An impact's approach speed reaches zero: the orbit grazes the stop at an impact (for a
    /// compliant stop: a contact's largest penetration falls to zero, the contact vanishes).
    GrazingImpact,
    /// A flight's gap minimum reaches zero: a new, low-speed impact appears (for a compliant
    /// stop: a new contact in a flight).
    GrazingFlight,
}

impl SpecialKind {
    /// Every kind.
    pub const ALL: [SpecialKind; 4] = [
        SpecialKind::Fold,
        SpecialKind::PeriodDoubling,
        SpecialKind::GrazingImpact,
        SpecialKind::GrazingFlight,
    ];

    /// Short label: `fold`, `period-doubling`, `grazing-impact`, `grazing-flight`.
    pub fn label(self) -> &'static str {
        match self {
            SpecialKind::Fold => "fold",
            SpecialKind::PeriodDoubling => "period-doubling",
            SpecialKind::GrazingImpact => "grazing-impact",
            SpecialKind::GrazingFlight => "grazing-flight",
        }
    }

    /// Whether the orbit stops being an orbit of the same impacts past it.
    pub fn is_grazing(self) -> bool {
        matches!(
            self,
            SpecialKind::GrazingImpact | SpecialKind::GrazingFlight
        )
    }
}

/// One orbit on a branch or a curve.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BranchPoint {
    /// The continued keys' values (one on a branch, two on a curve), SI.
    pub values: Vec<f64>,
    /// The orbit's impacts.
    pub points: Vec<ImpactPoint>,
    /// Floquet multipliers: the eigenvalues of the n-fold impact map's Jacobian.
    #[serde(serialize_with = "crate::model::system::orbit::serialize_complex")]
    pub multipliers: Vec<Complex<f64>>,
    /// det J (r^{2n}·e^{−2ζω₀·mT} for a rigid stop: docs/physics.md §8.5).
    pub jacobian_det: f64,
    /// Every multiplier inside the unit circle (and the orbit physical).
    pub stable: bool,
    /// The smallest approach speed of its impacts, m/s (infinite for an orbit without one: a
    /// compliant branch past a grazing).
    pub min_speed: f64,
    /// The smallest interior minimum of a gap over its flights, m (None: none, or not watched).
    pub min_gap: Option<f64>,
    /// Scaled arclength from the branch's start.
    pub arclength: f64,
    /// The scaled unknowns and parameters (for branch switching and curves).
    #[serde(skip)]
    pub(crate) z: Vec<f64>,
}

/// A located special point.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SpecialPoint {
    /// What happens there.
    pub kind: SpecialKind,
    /// The orbit there.
    pub point: BranchPoint,
    /// The test function's value there (0 to the location's accuracy).
    pub test: f64,
    /// The index of the branch point it follows.
    pub after: usize,
}

/// Why a branch ended.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(rename_all = "kebab-case", tag = "reason", content = "detail")]
pub enum BranchEnd {
    /// It left the parameter range (its last point is on the range's end).
    Range,
    /// It reached a grazing point (its last point).
    Grazing,
    /// It has the maximum number of points.
    MaxPoints,
    /// The step fell below the minimum; the reason of the last failure.
    StepTooSmall(String),
}

impl BranchEnd {
    /// In words.
    pub fn describe(&self) -> String {
        match self {
            BranchEnd::Range => "left the parameter range".into(),
            BranchEnd::Grazing => "reached a grazing point".into(),
            BranchEnd::MaxPoints => "reached the maximum number of points".into(),
            BranchEnd::StepTooSmall(why) => {
                format!("stopped: the step fell below its minimum ({why})")
            }
        }
    }
}

/// A branch of periodic orbits in one key (or a curve of special points in two).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Branch {
    /// The continued keys (`system.gamma`; a curve: the first key, then the second).
    pub keys: Vec<String>,
    /// `rigid` or `compliant`.
    pub contact: String,
    /// m: forcing periods per orbit.
    pub cycles: u32,
    /// The stop of each impact (n impacts per orbit).
    pub stops: Vec<usize>,
    /// For a curve: the kind of special point it follows.
    pub follows: Option<SpecialKind>,
    /// The orbits, in the order of the arclength.
    pub points: Vec<BranchPoint>,
    /// The special points, in the same order.
    pub specials: Vec<SpecialPoint>,
    /// Why it ended.
    pub end: BranchEnd,
    /// The speed scale of the unknowns, m/s.
    #[serde(skip)]
    pub(crate) speed: f64,
    /// The parameters' scales.
    #[serde(skip)]
    pub(crate) scales: Vec<f64>,
    /// A compliant branch's stroboscopic section, its forcing phase in rad.
    #[serde(skip)]
    pub(crate) section: f64,
}

impl Branch {
    /// The special points of one kind.
    pub fn special(&self, kind: SpecialKind) -> impl Iterator<Item = &SpecialPoint> {
        self.specials.iter().filter(move |s| s.kind == kind)
    }
}
