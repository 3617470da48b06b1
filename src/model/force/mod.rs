//! The contact-force laws — the paper's five (eqs 1, 15–20) and those the field uses besides
//! (docs/physics.md §6) — behind one interface, declared in one table ([`table::LAWS`]).

use std::fmt;
use std::str::FromStr;

use serde::Serialize;

use super::error::{ModelError, require_positive};
use super::power_law::PowerLaw;
use super::scene::ImpactConditions;

pub mod adams_impact;
pub mod any;
pub mod contact;
pub mod dry_friction;
pub mod elastic;
pub mod hertz_line_exact;
pub mod hertz_viscous;
pub mod hysteresis;
pub mod kelvin_voigt;
pub mod law;
pub mod proposed;
pub mod table;
pub mod thornton;

pub use any::{AnyLaw, Damping, LawVisitor};
pub use contact::{Contact, PointContact};
pub use law::{ContactEnd, ForceLaw, Phase};
pub use table::{ContactRule, DampingParam, Family, LAW_COUNT, LAWS, LawSpec};

use table::index_of;

/// Inputs every force law draws its parameters from (the scene plus the quasistatic law).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ImpactParams {
    /// Reduced mass m, kg (eq 4).
    pub mass: f64,
    /// Elastic law F = k·xⁿ (eq 1).
    pub law: PowerLaw,
    /// Pre-impact velocity v₀ > 0, m/s.
    pub v0: f64,
    /// Coefficient of restitution e in (0, 1].
    pub restitution: f64,
    /// Plastic indentation x_pl ≥ 0, m (eq 18); 0 makes the proposed model elastic.
    pub plastic_indentation: f64,
    /// The bodies, for the laws that need more than k, n and m (Thornton's yield pressure, the
    /// exact line-contact law's eq 13/14); [`Contact::Unspecified`] without a scene.
    #[serde(skip)]
    pub contact: Contact,
}

impl ImpactParams {
    /// Checks m > 0, a valid power law (k > 0, n ≥ 1), the impact conditions (v₀ > 0, 0 < e ≤ 1,
    /// x_pl ≥ 0, all finite: [`ImpactConditions::validate`]), the contact, and
    /// that the elastic scales x_max, x_max/v₀ and F_max are finite and non-zero (they scale the
    /// solver; t_c is x_max/v₀ times a constant of n).
    pub fn validate(&self) -> Result<(), ModelError> {
        require_positive("mass", self.mass)?;
        PowerLaw::new(self.law.k, self.law.n)?;
        self.conditions().validate()?;
        self.contact.validate()?;
        let x_max = self.law.max_approach(self.mass, self.v0);
        let t_ref = x_max / self.v0;
        let f_max = self.law.force(x_max);
        if [x_max, t_ref, f_max]
            .iter()
            .any(|q| !(q.is_finite() && q.is_normal()))
        {
            return Err(ModelError::ImpactScales {
                x_max,
                t_ref,
                f_max,
            });
        }
        let damping = self.law.k * self.plastic_indentation / (self.v0 * self.restitution);
        if !damping.is_finite() {
            return Err(ModelError::ProposedDamping {
                plastic_indentation: self.plastic_indentation,
                damping,
                x_max,
            });
        }
        Ok(())
    }
}

impl ImpactParams {
    /// The impact conditions among these inputs (v₀, e, x_pl), checked by
    /// [`ImpactConditions::validate`], the one check of them.
    pub fn conditions(&self) -> ImpactConditions {
        ImpactConditions {
            v0: self.v0,
            restitution: self.restitution,
            plastic_indentation: self.plastic_indentation,
        }
    }
}

/// Which force law: a row of [`LAWS`], the one table where laws are declared. The paper's five
/// keep their names as constants (`ForceModel::HuntCrossley`) and their ids on the command line.
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct ForceModel(u8);

#[allow(non_upper_case_globals)]
impl ForceModel {
    /// Elastic Hertz F = k·xⁿ (eq 1).
    pub const Quasistatic: ForceModel = ForceModel::with_id("quasistatic");
    /// F = k·xⁿ + P·x·sign(ẋ) (eqs 15–17).
    pub const DryFriction: ForceModel = ForceModel::with_id("dry-friction");
    /// The paper's viscous model F = k·xⁿ + b·xⁿ⁻¹·ẋ (eq 18).
    pub const Proposed: ForceModel = ForceModel::with_id("proposed");
    /// F = k·xⁿ·(1 + (3/2)·a·ẋ), a = (1 − e)/v₀ (eq 19).
    pub const HuntCrossley: ForceModel = ForceModel::with_id("hunt-crossley");
    /// F = k·xⁿ·(1 + 3(1 − e²)/4·ẋ/v₀) (eq 20).
    pub const LankaraniNikravesh: ForceModel = ForceModel::with_id("lankarani-nikravesh");

    /// Every law, in table order.
    pub const ALL: [ForceModel; LAW_COUNT] = {
        let mut all = [ForceModel(0); LAW_COUNT];
        let mut i = 0;
        while i < LAW_COUNT {
            all[i] = ForceModel(i as u8);
            i += 1;
        }
        all
    };

    /// The law with table id `id`; a missing id fails the build.
    pub const fn with_id(id: &str) -> ForceModel {
        ForceModel(index_of(id) as u8)
    }

    /// Its row of the table.
    pub fn spec(self) -> &'static LawSpec {
        &LAWS[self.index()]
    }

    /// Its position in [`ForceModel::ALL`]: the index of every per-law array.
    pub fn index(self) -> usize {
        usize::from(self.0)
    }

    /// The kebab-case id used on the command line, in scene files and in JSON.
    pub fn name(self) -> &'static str {
        self.spec().id
    }

    /// The name shown in every pane, with the paper's equation number where it has one.
    pub fn label(self) -> &'static str {
        self.spec().label
    }

    /// An abbreviation for narrow panes.
    pub fn short(self) -> &'static str {
        self.spec().short
    }

    /// The law of this model for `params` (validated), its damping from the scene's e.
    pub fn law(self, params: &ImpactParams) -> Result<AnyLaw, ModelError> {
        AnyLaw::new(self, params)
    }

    /// The law with its damping parameter set to `value` (see [`AnyLaw::with_damping`]).
    pub fn law_with_damping(self, params: &ImpactParams, value: f64) -> Result<AnyLaw, ModelError> {
        AnyLaw::with_damping(self, params, value)
    }
}

impl fmt::Debug for ForceModel {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "ForceModel({})", self.name())
    }
}

impl fmt::Display for ForceModel {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl Serialize for ForceModel {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.serialize_str(self.name())
    }
}

/// A model id that names no row of [`LAWS`]; the message lists the ids that do.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("unknown model '{0}' (expected one of: {ids})", ids = ForceModel::ALL.map(ForceModel::name).join(", "))]
pub struct UnknownModel(pub String);

impl FromStr for ForceModel {
    type Err = UnknownModel;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        ForceModel::ALL
            .into_iter()
            .find(|m| m.name() == s)
            .ok_or_else(|| UnknownModel(s.to_string()))
    }
}

#[cfg(test)]
mod tests;
