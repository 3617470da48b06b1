//! A resolved scene: two bodies with their materials and the impact conditions, SI units.
#![warn(missing_docs)]

use serde::ser::{Serialize, SerializeMap, Serializer};

use super::body::{Body, Shape};
use super::error::{ModelError, require, require_positive};
use super::fit::FitError;
use super::force::ImpactParams;
use super::pair::ContactPair;
use super::quasistatic::{ContactGeometry, PairEstimate, Quasistatic};
use super::scene_fit::FittedLaw;

/// Conditions of the impact (the `[impact]` table of a scene file).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImpactConditions {
    /// Pre-impact relative velocity v₀, m/s.
    pub v0: f64,
    /// Coefficient of restitution e in (0, 1], used by the dissipative models.
    pub restitution: f64,
    /// Plastic indentation x_pl ≥ 0, m, used by the proposed viscous model (eq 18).
    pub plastic_indentation: f64,
}

impl ImpactConditions {
    /// Checks v₀ > 0, 0 < e ≤ 1, x_pl ≥ 0 (0: no permanent deformation); field names are `impact.…`.
    /// The one check of these inputs: [`ImpactParams::validate`] calls it too.
    pub fn validate(&self) -> Result<(), ModelError> {
        require_positive("impact.v0", self.v0)?;
        require("impact.restitution", self.restitution, "in (0, 1]", |e| {
            e > 0.0 && e <= 1.0
        })?;
        require(
            "impact.plastic_indentation",
            self.plastic_indentation,
            "a finite number ≥ 0",
            |x| x >= 0.0,
        )?;
        Ok(())
    }
}

/// Impact values a scene carries that its user did not give: a preset's stand-ins (the table
/// presets borrow Fig. 5's e and x_pl), the `assumed` list of a scene file's `[impact]`. They are
/// shown as assumed, and the recommendation never rests on them without saying so; giving the
/// value (`--set`, an edit) clears the mark.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Assumed {
    /// e was not given.
    pub restitution: bool,
    /// x_pl was not given.
    pub plastic_indentation: bool,
}

impl Assumed {
    /// The `[impact]` keys of the `assumed` list, in schema order.
    pub const KEYS: [&'static str; 2] = ["restitution", "plastic_indentation"];

    /// Whether nothing is assumed.
    pub fn is_empty(&self) -> bool {
        !self.restitution && !self.plastic_indentation
    }

    /// The assumed keys of [`Assumed::KEYS`].
    pub fn keys(&self) -> Vec<&'static str> {
        Self::KEYS
            .into_iter()
            .zip([self.restitution, self.plastic_indentation])
            .filter_map(|(key, assumed)| assumed.then_some(key))
            .collect()
    }

    /// Marks `key` (an `[impact]` key) assumed or given; other keys are never assumed.
    pub fn set(&mut self, key: &str, assumed: bool) {
        match key {
            "restitution" => self.restitution = assumed,
            "plastic_indentation" => self.plastic_indentation = assumed,
            _ => {}
        }
    }
}

/// A scene with materials resolved and every value in SI units.
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    /// The scene's title.
    pub name: String,
    /// The first body (the impactor in the paper's scenes).
    pub body1: Body,
    /// The second body.
    pub body2: Body,
    /// v₀, e and x_pl.
    pub impact: ImpactConditions,
    /// Which of e and x_pl the user did not give.
    pub assumed: Assumed,
    /// The law fitted to measured restitution (the `[fit]` table), if the scene carries one: it
    /// sets `impact.restitution` at every v₀ ([`Scene::apply_fit`]) and is solved with its constant.
    pub fit: Option<FittedLaw>,
}

impl Scene {
    /// Checks both bodies, their combination and the impact conditions; errors name the dotted field.
    pub fn validate(&self) -> Result<(), ModelError> {
        self.pair()?;
        self.impact.validate()
    }

    /// The validated contact pair of the two bodies.
    pub fn pair(&self) -> Result<ContactPair, ModelError> {
        ContactPair::new(self.body1.clone(), self.body2.clone())
    }

    /// The quasistatic estimate (eqs 1–14) at the scene's v₀. Inputs that are each valid but
    /// together overflow double precision (v₀ = 1e200 m/s) are an error, never an infinite result.
    pub fn quasistatic(&self) -> Result<Quasistatic, ModelError> {
        SceneBodies::of(self).quasistatic(&self.impact)
    }

    /// Sets `impact.restitution` to the e the fitted law realises at the scene's v₀ (nothing
    /// without a `[fit]`), so that every other law is set or calibrated to the measured e; e is
    /// then given, not assumed. Called wherever v₀ may have changed (decoding, the explorer's edits).
    pub fn apply_fit(&mut self) -> Result<(), FitError> {
        let Some(fit) = &self.fit else {
            return Ok(());
        };
        let quasistatic = self.quasistatic()?;
        let e = fit.restitution_at(&self.impact_params(&quasistatic))?;
        self.impact.restitution = e;
        self.assumed.restitution = false;
        Ok(())
    }

    /// Inputs of the impact solver: the quasistatic law F = k·xⁿ, the reduced mass, the impact
    /// conditions and the bodies' contact (for the laws that need it).
    pub fn impact_params(&self, quasistatic: &Quasistatic) -> ImpactParams {
        self.impact.params(quasistatic)
    }
}

impl ImpactConditions {
    /// The impact solver's inputs under these conditions: [`Scene::impact_params`].
    pub fn params(&self, quasistatic: &Quasistatic) -> ImpactParams {
        ImpactParams {
            mass: quasistatic.reduced_mass,
            law: quasistatic.law(),
            v0: self.v0,
            restitution: self.restitution,
            plastic_indentation: self.plastic_indentation,
            contact: quasistatic.contact,
        }
    }
}

/// A scene's bodies evaluated once, for many impact conditions: a sweep of v₀, e or x_pl gets at
/// every point the numbers [`Scene::quasistatic`] would, without re-validating and re-evaluating
/// what only the bodies fix.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneBodies {
    /// The pair's part of the estimate, or why the bodies make no valid pair.
    estimate: Result<PairEstimate, ModelError>,
}

impl SceneBodies {
    /// Evaluates what `scene`'s bodies fix.
    pub fn of(scene: &Scene) -> Self {
        SceneBodies {
            estimate: scene.pair().map(PairEstimate::new),
        }
    }

    /// [`Scene::quasistatic`] of these bodies under `impact`.
    pub fn quasistatic(&self, impact: &ImpactConditions) -> Result<Quasistatic, ModelError> {
        impact.validate()?;
        let estimate = self.estimate.as_ref().map_err(Clone::clone)?;
        let q = estimate.at(impact.v0)?;
        require_finite_results(&q)?;
        Ok(q)
    }
}

/// Refuses an estimate with a non-finite or non-positive number, naming the first one.
fn require_finite_results(q: &Quasistatic) -> Result<(), ModelError> {
    let o = &q.onset;
    // The contact's size too: a radius of 1e-107 m underflows the contact radius to 0.
    let (size_name, size) = match q.geometry {
        ContactGeometry::Point { contact_radius } => ("contact_radius", contact_radius),
        ContactGeometry::Line { half_width, .. } => ("half_width", half_width),
    };
    let values = [
        ("eta", q.eta),
        ("k", q.k),
        ("reduced_mass", q.reduced_mass),
        ("x_max", q.x_max),
        ("f_max", q.f_max),
        ("t_contact", q.t_contact),
        ("p_max", q.p_max),
        ("v_yield", o.v_yield),
        ("v_plastic", o.v_plastic),
        ("v_yield_mean_pressure", o.v_yield_mean_pressure),
        ("v_plastic_mean_pressure", o.v_plastic_mean_pressure),
        ("v_wave_limit", o.v_wave_limit),
        (size_name, size),
    ];
    match values.iter().find(|(_, v)| !(v.is_finite() && *v > 0.0)) {
        None => Ok(()),
        Some(&(quantity, value)) => Err(ModelError::EstimateOutOfRange { quantity, value }),
    }
}

/// Serializes in the scene-file schema (materials inline, SI units): what `solve --format json` prints.
impl Serialize for Scene {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut map = serializer.serialize_map(None)?;
        map.serialize_entry("name", &self.name)?;
        map.serialize_entry("body1", &BodyRecord(&self.body1))?;
        map.serialize_entry("body2", &BodyRecord(&self.body2))?;
        map.serialize_entry("impact", &ImpactRecord(&self.impact, &self.assumed))?;
        if let Some(fit) = &self.fit {
            map.serialize_entry("fit", &FitRecord(fit))?;
        }
        map.end()
    }
}

/// A body as the scene file writes it: only the keys its shape uses, the mass only when given.
struct BodyRecord<'a>(&'a Body);

impl Serialize for BodyRecord<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let body = self.0;
        let mut map = serializer.serialize_map(None)?;
        map.serialize_entry("shape", body.shape.name())?;
        match body.shape {
            Shape::Sphere { radius } => map.serialize_entry("radius", &radius)?,
            Shape::Cylinder { radius, length } => {
                map.serialize_entry("radius", &radius)?;
                map.serialize_entry("length", &length)?;
            }
            Shape::Plane => {}
        }
        if let Some(mass) = body.mass {
            map.serialize_entry("mass", &mass)?;
        }
        map.serialize_entry("material", &body.material)?;
        map.end()
    }
}

/// The `[impact]` table, with the list of assumed keys when there are any.
struct ImpactRecord<'a>(&'a ImpactConditions, &'a Assumed);

impl Serialize for ImpactRecord<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let (impact, assumed) = (self.0, self.1);
        let mut map = serializer.serialize_map(None)?;
        map.serialize_entry("v0", &impact.v0)?;
        map.serialize_entry("restitution", &impact.restitution)?;
        map.serialize_entry("plastic_indentation", &impact.plastic_indentation)?;
        if !assumed.is_empty() {
            map.serialize_entry("assumed", &assumed.keys())?;
        }
        map.end()
    }
}

/// The `[fit]` table: the law, its constant by its key, and the data file when known.
struct FitRecord<'a>(&'a FittedLaw);

impl Serialize for FitRecord<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let fit = self.0;
        let mut map = serializer.serialize_map(None)?;
        map.serialize_entry("law", fit.kind.id())?;
        map.serialize_entry(fit.constant().0, &fit.value)?;
        if let Some(source) = &fit.source {
            map.serialize_entry("source", source)?;
        }
        if let Some(note) = &fit.note {
            map.serialize_entry("note", note)?;
        }
        map.end()
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::model::material::tests::steel;

    /// Impact parameters of the Fig. 5 scene (m = 32.7 g, k = 1.465e10 N/m^1.5, Table 1; e = 0.6,
    /// x_pl = 2.3 µm) at pre-impact velocity `v0`.
    pub(crate) fn fig5_params(v0: f64) -> crate::model::ImpactParams {
        crate::model::ImpactParams {
            mass: 0.0327,
            law: crate::model::PowerLaw {
                k: 1.465e10,
                n: 1.5,
            },
            v0,
            restitution: 0.6,
            plastic_indentation: 2.3e-6,
            contact: crate::model::force::Contact::Unspecified,
        }
    }

    /// The paper's Fig. 5 scene: steel sphere R = 10 mm on a steel plate, v₀ = 0.3 m/s, e = 0.6,
    /// x_pl = 2.3 µm — the fixture of every unit test that needs a scene.
    pub(crate) fn fig5_scene() -> Scene {
        Scene {
            name: "Fig. 5".into(),
            body1: Body {
                shape: Shape::Sphere { radius: 0.01 },
                material: steel(),
                mass: None,
            },
            body2: Body {
                shape: Shape::Plane,
                material: steel(),
                mass: None,
            },
            impact: ImpactConditions {
                v0: 0.3,
                restitution: 0.6,
                plastic_indentation: 2.3e-6,
            },
            assumed: Assumed::default(),
            fit: None,
        }
    }

    #[test]
    fn validate_names_the_dotted_field() {
        let mut scene = fig5_scene();
        assert_eq!(scene.validate(), Ok(()));
        scene.body2.material.poisson_ratio = 0.7;
        assert_eq!(
            scene.validate().unwrap_err().to_string(),
            "body2.material.poisson_ratio must be in [0, 0.5), got 0.7"
        );
        let mut scene = fig5_scene();
        scene.impact.restitution = 1.5;
        assert!(
            scene
                .validate()
                .unwrap_err()
                .to_string()
                .starts_with("impact.restitution must be in (0, 1]")
        );
    }

    #[test]
    fn overflowing_inputs_are_an_error_not_infinity() {
        let mut scene = fig5_scene();
        scene.impact.v0 = 1e200;
        let err = scene.quasistatic().unwrap_err();
        assert_eq!(
            err,
            ModelError::EstimateOutOfRange {
                quantity: "x_max",
                value: f64::INFINITY
            }
        );
        let err = err.to_string();
        assert!(
            err.starts_with("quasistatic estimate: x_max = inf is out of double-precision range"),
            "{err}"
        );
        scene.impact.v0 = 0.3;
        assert!(scene.quasistatic().is_ok());
    }

    #[test]
    fn json_follows_the_scene_file_schema() {
        let json = serde_json::to_value(fig5_scene()).unwrap();
        assert_eq!(json["body1"]["shape"], "sphere");
        assert_eq!(json["body1"]["radius"], 0.01);
        assert_eq!(json["body1"]["material"]["youngs_modulus"], 2e11);
        // A plane has no radius key, and an omitted mass stays omitted.
        assert!(json["body2"].get("radius").is_none());
        assert!(json["body1"].get("mass").is_none());
        assert_eq!(json["impact"]["plastic_indentation"], 2.3e-6);
    }
}
