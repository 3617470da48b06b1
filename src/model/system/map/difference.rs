//! The rigid/compliant difference as a map of its own: where the two stops give the same motion,
//! and where they do not, the known cause (docs/maps.md §2).
#![warn(missing_docs)]

use serde::Serialize;

use crate::model::system::compliant::verdict::SHORT_CONTACT;

use super::motion::Motion;
use super::run::Cell;

/// Realised restitutions closer than this are the same e: the system's forces during the fastest
/// contact move it by about (1 + Γ)·g·t_c/v_in, 1 % on the bouncing-ball preset.
pub const RESTITUTION_AGREES: f64 = 0.02;

/// Why the two stops' motions differ at a cell, where a cause is known.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(rename_all = "kebab-case", tag = "cause")]
pub enum Cause {
    /// The compliant law realises another e than the rigid stop's: the two are different
    /// systems before any compliance (the Hunt–Crossley row's χ = 3(1 − e)/2 realises 0.66 for
    /// an asked 0.5).
    Restitution {
        /// The rigid stop's e.
        rigid: f64,
        /// v_out/v_in of the compliant stop's fastest impact.
        compliant: f64,
    },
    /// The compliant stop's contacts last more than [`SHORT_CONTACT`] of a forcing period: it
    /// cannot resolve the bounces a rigid stop makes in that time.
    LongContacts {
        /// The longest impact's contact over the forcing period.
        ratio: f64,
    },
    /// Both chatter, repeating over different forcing periods (or one not within the record):
    /// a chatter's long orbits are many and close, and a contact of finite duration moves the
    /// motion from one to another (at Γ = 2, e = 0.5 the compliant stop reaches the rigid 16:8
    /// at 10⁴ times the steel's stiffness, docs/maps.md §2).
    ChatterOrbit {
        /// The rigid stop's m, if it repeats.
        rigid: Option<u32>,
        /// The compliant stop's m, if it repeats.
        compliant: Option<u32>,
    },
    /// One stop's run reached its time limit still in its transient (its motion is
    /// [`Motion::Unsettled`]) where the other's settled: the two are not compared (`unknown`).
    Unsettled {
        /// Which stop's run: the rigid one's (else the compliant one's).
        rigid: bool,
    },
}

impl Cause {
    /// The cause in words with its numbers, for the map file.
    pub fn words(self) -> String {
        match self {
            Cause::Restitution { rigid, compliant } => {
                format!("the law realises e = {compliant:.3}, the rigid stop {rigid:.3}")
            }
            Cause::LongContacts { ratio } => {
                format!("contacts last {:.2} % of a forcing period", 100.0 * ratio)
            }
            Cause::ChatterOrbit { rigid, compliant } => {
                let m = |m: Option<u32>| m.map_or("does not repeat".into(), |m| format!("{m}"));
                format!(
                    "both chatter, on other orbits: m = {} rigid, {} compliant",
                    m(rigid),
                    m(compliant)
                )
            }
            Cause::Unsettled { rigid } => format!(
                "the {} stop's transient never ended",
                if rigid { "rigid" } else { "compliant" }
            ),
        }
    }

    /// Why two stops' motions are `unknown` where one of them is known: the other never settled
    /// (none where a run failed: the failed cell keeps its error).
    pub fn unknown(rigid: Motion, compliant: Motion) -> Option<Cause> {
        match (rigid, compliant) {
            (Motion::Failed, _) | (_, Motion::Failed) => None,
            (Motion::Unsettled, _) => Some(Cause::Unsettled { rigid: true }),
            (_, Motion::Unsettled) => Some(Cause::Unsettled { rigid: false }),
            _ => None,
        }
    }

    /// The known cause of a difference between `rigid` and `compliant`: the restitution first
    /// (it changes the system), then the contacts' length, then two chatters' orbits.
    pub fn of(rigid: &Cell, compliant: &Cell) -> Option<Cause> {
        let (r, c) = (rigid.contacts, compliant.contacts);
        if let (Some(rigid), Some(compliant)) = (r.restitution, c.restitution)
            && (rigid - compliant).abs() > RESTITUTION_AGREES
        {
            return Some(Cause::Restitution { rigid, compliant });
        }
        if let Some(ratio) = c.contact_ratio.filter(|&ratio| ratio > SHORT_CONTACT) {
            return Some(Cause::LongContacts { ratio });
        }
        match (rigid.motion, compliant.motion) {
            (Motion::Chattering { period: p }, Motion::Chattering { period: q }) => {
                Some(Cause::ChatterOrbit {
                    rigid: p.map(|(_, m)| m),
                    compliant: q.map(|(_, m)| m),
                })
            }
            _ => None,
        }
    }
}

/// Whether two stops agree at a cell.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Agreement {
    /// The same kind of motion, with the same n:m where it has one.
    Same,
    /// Different kinds, or different periods.
    Differs,
    /// One of the two runs failed, or one never settled where the other did
    /// ([`Motion::Unsettled`]): its motion, so the comparison, is not known.
    Unknown,
}

impl Agreement {
    /// The name in every output.
    pub fn name(self) -> &'static str {
        match self {
            Agreement::Same => "same",
            Agreement::Differs => "differs",
            Agreement::Unknown => "unknown",
        }
    }

    /// Whether two motions agree. Two chatters agree when they repeat over the same forcing
    /// periods m (or neither repeats): their n is not compared, since an impact whose flight is
    /// near [`CHATTER_FLIGHT`](super::motion::CHATTER_FLIGHT) falls on either side of it for two
    /// stops whose sequences differ by the contact time (docs/maps.md §2). Two unsettled runs
    /// agree (both still impact at the time limit); one unsettled beside a settled one is
    /// unknown: given longer, it might settle to the same motion.
    pub fn of(a: Motion, b: Motion) -> Agreement {
        let cycles = |p: Option<(u32, u32)>| p.map(|(_, m)| m);
        match (a, b) {
            _ if a == Motion::Failed || b == Motion::Failed => Agreement::Unknown,
            _ if a == b => Agreement::Same,
            _ if a == Motion::Unsettled || b == Motion::Unsettled => Agreement::Unknown,
            (Motion::Chattering { period: p }, Motion::Chattering { period: q })
                if cycles(p) == cycles(q) =>
            {
                Agreement::Same
            }
            _ => Agreement::Differs,
        }
    }
}

/// One cell of the difference map.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DifferenceCell {
    /// Column index.
    pub ix: usize,
    /// Row index.
    pub iy: usize,
    /// x value, SI.
    pub x: f64,
    /// y value, SI.
    pub y: f64,
    /// Agreement of the two motions.
    pub agreement: Agreement,
    /// λ_compliant − λ_rigid, per impact, where both have one.
    pub lyapunov_change: Option<f64>,
    /// Why the motions differ, where they do and the cause is known; where they are unknown,
    /// the stop whose transient never ended.
    pub cause: Option<Cause>,
}

/// The difference of two maps over the same cells (`rigid` and `compliant` in the same order).
pub fn difference(rigid: &[Cell], compliant: &[Cell]) -> Vec<DifferenceCell> {
    rigid
        .iter()
        .zip(compliant)
        .map(|(r, c)| {
            let agreement = Agreement::of(r.motion, c.motion);
            DifferenceCell {
                ix: r.ix,
                iy: r.iy,
                x: r.x,
                y: r.y,
                agreement,
                lyapunov_change: r.lyapunov.zip(c.lyapunov).map(|(a, b)| b - a),
                cause: match agreement {
                    Agreement::Differs => Cause::of(r, c),
                    Agreement::Unknown => Cause::unknown(r.motion, c.motion),
                    Agreement::Same => None,
                },
            }
        })
        .collect()
}
