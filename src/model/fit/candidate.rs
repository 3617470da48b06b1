//! What may be fitted to e(v) data: Newton's constant e, or a law whose e depends on v through a
//! material constant (docs/physics.md §9.1), and why the other laws are left out.
#![warn(missing_docs)]

use serde::Serialize;

use crate::model::force::ForceModel;
use crate::model::force::table::Family;

use super::lsq::ParamSpec;

/// A model of e(v) that can be fitted.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Candidate {
    /// Newton's coefficient of restitution: e(v) = e, the same at every velocity.
    ConstantE,
    /// A contact law of the table with its damping held as a material constant (for the
    /// Hunt–Crossley family a = χ/v₀, so that χ = a·v).
    Law(ForceModel),
}

/// The id of [`Candidate::ConstantE`] on the command line and in reports.
pub const CONSTANT_E_ID: &str = "constant-e";

/// Newton's e.
const E: ParamSpec = ParamSpec::bounded("e", "e", "1", 0.0, 1.0);

/// The Hunt–Crossley family's material constant: χ = a·v₀ (eq 19, a = (3/2)·α of Hunt & Crossley).
const HC_A: ParamSpec = ParamSpec::positive("a", "a", "s/m");

impl Candidate {
    /// The id: `constant-e` or the law's table id.
    pub fn id(self) -> &'static str {
        match self {
            Candidate::ConstantE => CONSTANT_E_ID,
            Candidate::Law(m) => m.name(),
        }
    }

    /// The name shown in tables.
    pub fn label(self) -> &'static str {
        match self {
            Candidate::ConstantE => "constant e (Newton)",
            Candidate::Law(m) => m.label(),
        }
    }

    /// The law, `None` for constant e.
    pub fn model(self) -> Option<ForceModel> {
        match self {
            Candidate::ConstantE => None,
            Candidate::Law(m) => Some(m),
        }
    }

    /// The candidate with id `id` (`constant-e` or a law id).
    pub fn from_id(id: &str) -> Option<Candidate> {
        if id == CONSTANT_E_ID {
            return Some(Candidate::ConstantE);
        }
        id.parse::<ForceModel>().ok().map(Candidate::Law)
    }

    /// The fitted parameters, `Err` with the reason for a law that cannot be fitted.
    pub fn params(self) -> Result<Vec<ParamSpec>, &'static str> {
        let model = match self {
            Candidate::ConstantE => return Ok(vec![E]),
            Candidate::Law(m) => m,
        };
        let Some(d) = model.spec().damping else {
            return Err(NO_DISSIPATION);
        };
        if model.spec().family == Family::HuntCrossley {
            return Ok(vec![HC_A]);
        }
        Ok(vec![ParamSpec::positive(d.symbol, d.key, d.unit)])
    }
}

impl std::fmt::Display for Candidate {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.id())
    }
}

impl Serialize for Candidate {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.serialize_str(self.id())
    }
}

/// Why an elastic law is not fitted.
const NO_DISSIPATION: &str = "no dissipation: e = 1 at every velocity, no parameter to fit";

/// A law left out of the default candidates, and why.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct Unfittable {
    /// The law.
    pub model: ForceModel,
    /// Why, in a phrase.
    pub reason: &'static str,
    /// The candidate it is identical to on any e(v) data, when that is the reason (it may still
    /// be fitted when asked for by name, and then ties with this one).
    pub same_as: Option<Candidate>,
}

/// Every Hunt–Crossley row but `hunt-crossley` itself.
const SAME_AS_HC: &str = "with a constant a the force is k·xⁿ·(1 + a·ẋ) whatever the row's χ(e): the same e(v) as hunt-crossley";

/// The proposed model against Kuwabara–Kono.
const SAME_AS_KK: &str = "with a constant b it is kuwabara-kono with A = b/k (eq 18 is §6.5's law): the same e(v); a constant x_pl is no material constant (b = k·x_pl/(v₀·e) ties it to v₀)";

/// The default candidates: constant e and every law with a material constant, one per distinct
/// e(v) (the Hunt–Crossley rows are one law under a constant a; the proposed model is
/// Kuwabara–Kono's), in table order.
pub fn candidates() -> Vec<Candidate> {
    std::iter::once(Candidate::ConstantE)
        .chain(
            ForceModel::ALL
                .into_iter()
                .filter(|&m| excluded(m).is_none())
                .map(Candidate::Law),
        )
        .collect()
}

/// The laws [`candidates`] leaves out, with the reason.
pub fn unfittable() -> Vec<Unfittable> {
    ForceModel::ALL.into_iter().filter_map(excluded).collect()
}

/// Why `model` is not a default candidate, `None` when it is.
fn excluded(model: ForceModel) -> Option<Unfittable> {
    let spec = model.spec();
    if spec.damping.is_none() {
        return Some(Unfittable {
            model,
            reason: NO_DISSIPATION,
            same_as: None,
        });
    }
    if spec.family == Family::HuntCrossley && model != ForceModel::HuntCrossley {
        return Some(Unfittable {
            model,
            reason: SAME_AS_HC,
            same_as: Some(Candidate::Law(ForceModel::HuntCrossley)),
        });
    }
    if model == ForceModel::Proposed {
        return Some(Unfittable {
            model,
            reason: SAME_AS_KK,
            same_as: Some(Candidate::Law(ForceModel::with_id("kuwabara-kono"))),
        });
    }
    None
}

/// The candidates whose e(v) is the same function as `candidate`'s on any data (a reparametrised
/// copy): the Hunt–Crossley rows among themselves, the proposed model and Kuwabara–Kono (F ≥ 0),
/// and the laws whose e does not depend on v (constant e and Hertz–viscous, §6.2) within the
/// range of e they reach.
pub fn identical(candidate: Candidate) -> Vec<Candidate> {
    let class = |c: Candidate| -> Option<u8> {
        match c {
            Candidate::ConstantE => Some(0),
            Candidate::Law(m) if m.spec().family == Family::HuntCrossley => Some(1),
            Candidate::Law(m) if m == ForceModel::Proposed => Some(2),
            Candidate::Law(m) if m.name() == "kuwabara-kono" => Some(2),
            Candidate::Law(m) if m.name().starts_with("hertz-viscous") => Some(0),
            Candidate::Law(_) => None,
        }
    };
    let Some(own) = class(candidate) else {
        return Vec::new();
    };
    std::iter::once(Candidate::ConstantE)
        .chain(ForceModel::ALL.into_iter().map(Candidate::Law))
        .filter(|&c| c != candidate && class(c) == Some(own))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_law_is_a_candidate_or_says_why_not() {
        let fit = candidates();
        let out = unfittable();
        assert_eq!(fit.len() - 1 + out.len(), ForceModel::ALL.len());
        for u in &out {
            assert!(!fit.contains(&Candidate::Law(u.model)), "{}", u.model);
        }
        let ids: Vec<_> = fit.iter().map(|c| c.id()).collect();
        assert_eq!(ids[0], "constant-e");
        for id in [
            "hunt-crossley",
            "thornton",
            "kuwabara-kono",
            "dry-friction",
            "adams-impact",
        ] {
            assert!(ids.contains(&id), "{id}");
        }
        assert!(!ids.contains(&"quasistatic") && !ids.contains(&"lee-wang"));
        assert_eq!(
            Candidate::from_id("lee-wang").map(Candidate::id),
            Some("lee-wang")
        );
        assert_eq!(Candidate::from_id("constant-e"), Some(Candidate::ConstantE));
        assert!(Candidate::Law(ForceModel::Quasistatic).params().is_err());
    }
}
