//! The `[system]` table: decoding into a [`SystemSpec`] and writing it back.

use toml::Table;

use crate::model::system::{Damping, Forcing, STANDARD_GRAVITY, SystemKind, SystemSpec};

use super::decode::Decoder;
use super::document::{Document, Problem, SceneFileError, ValueIssue, join};
use super::write::toml_float;

/// The systems `system.kind` may name.
pub const SYSTEM_KINDS: &[&str] = &["bouncing-ball", "impact-oscillator"];
/// Keys of `[system]` for a bouncing ball (`gravity` optional, standard gravity by default).
pub(super) const BALL_KEYS: &[&str] = &["kind", "amplitude", "frequency", "gravity"];
/// Keys of `[system]` for an impact oscillator (one of `damping_ratio`/`damping`; `second_gap`
/// optional).
pub(super) const OSCILLATOR_KEYS: &[&str] = &[
    "kind",
    "stiffness",
    "damping_ratio",
    "damping",
    "forcing",
    "forcing_amplitude",
    "frequency",
    "gap",
    "second_gap",
];
/// Every key of `[system]` (for `--set`).
pub(crate) const SYSTEM_KEYS: &[&str] = &[
    "kind",
    "amplitude",
    "frequency",
    "gravity",
    "stiffness",
    "damping_ratio",
    "damping",
    "forcing",
    "forcing_amplitude",
    "gap",
    "second_gap",
];
/// The values of `system.forcing`.
pub const FORCINGS: &[&str] = &["force", "base"];

impl Decoder<'_> {
    /// The optional `[system]` table, validated (errors name `system.<key>`).
    pub(super) fn system(&self, root: &Table) -> Result<Option<SystemSpec>, SceneFileError> {
        let table = match root.get("system") {
            None => return Ok(None),
            Some(toml::Value::Table(t)) => t,
            Some(other) => return Err(self.wrong_type("system", "a table", other)),
        };
        let p = "system";
        let kind = self.optional_string(table, p, "kind")?.ok_or_else(|| {
            self.missing_key("system.kind", " (bouncing-ball or impact-oscillator)")
        })?;
        let number = |key: &str, why: &'static str| -> Result<f64, SceneFileError> {
            self.optional_number(table, p, key)?
                .ok_or_else(|| self.missing_key(&join(p, key), why))
        };
        let kind = match kind {
            "bouncing-ball" => {
                self.check_keys(p, table, BALL_KEYS)?;
                SystemKind::BouncingBall {
                    amplitude: number("amplitude", " (table amplitude A, m)")?,
                    frequency: number("frequency", " (forcing frequency, Hz)")?,
                    gravity: self
                        .optional_number(table, p, "gravity")?
                        .unwrap_or(STANDARD_GRAVITY),
                }
            }
            "impact-oscillator" => {
                self.check_keys(p, table, OSCILLATOR_KEYS)?;
                let ratio = self.optional_number(table, p, "damping_ratio")?;
                let coefficient = self.optional_number(table, p, "damping")?;
                let damping = match (ratio, coefficient) {
                    (Some(z), None) => Damping::Ratio(z),
                    (None, Some(c)) => Damping::Coefficient(c),
                    (None, None) => {
                        return Err(self.missing_key(
                            "system.damping_ratio",
                            " (or system.damping in N·s/m; 0 for none)",
                        ));
                    }
                    (Some(_), Some(_)) => {
                        return Err(self.bad_value(
                            "system.damping",
                            ValueIssue::Conflict("give damping_ratio or damping, not both"),
                        ));
                    }
                };
                let forcing_amplitude = number(
                    "forcing_amplitude",
                    " (force amplitude F₀ in N, or base amplitude B in m)",
                )?;
                let forcing = match self.optional_string(table, p, "forcing")? {
                    Some("force") => Forcing::Force {
                        amplitude: forcing_amplitude,
                    },
                    Some("base") => Forcing::Base {
                        amplitude: forcing_amplitude,
                    },
                    Some(other) => {
                        return Err(self.bad_value(
                            "system.forcing",
                            ValueIssue::UnknownName {
                                name: other.to_string(),
                                known: FORCINGS,
                            },
                        ));
                    }
                    None => return Err(self.missing_key("system.forcing", " (force or base)")),
                };
                SystemKind::ImpactOscillator {
                    stiffness: number("stiffness", " (spring stiffness k, N/m)")?,
                    damping,
                    forcing,
                    frequency: number("frequency", " (forcing frequency, Hz)")?,
                    gap: number("gap", " (distance from rest to the stop, m)")?,
                    second_gap: self.optional_number(table, p, "second_gap")?,
                }
            }
            other => {
                return Err(self.bad_value(
                    "system.kind",
                    ValueIssue::UnknownName {
                        name: other.to_string(),
                        known: SYSTEM_KINDS,
                    },
                ));
            }
        };
        let spec = SystemSpec { kind };
        spec.validate().map_err(|e| self.doc.invalid(e))?;
        Ok(Some(spec))
    }

    pub(super) fn missing_key(&self, path: &str, why: &'static str) -> SceneFileError {
        self.doc.error(
            path,
            Problem::MissingKey {
                key: path.to_string(),
                why,
            },
        )
    }

    pub(super) fn bad_value(&self, path: &str, issue: ValueIssue) -> SceneFileError {
        self.doc.error(
            path,
            Problem::BadValue {
                key: path.to_string(),
                issue,
            },
        )
    }
}

/// Decodes the optional `[system]` table of a scene file.
pub fn decode_system(doc: &Document) -> Result<Option<SystemSpec>, SceneFileError> {
    let materials = std::collections::BTreeMap::new();
    Decoder {
        doc,
        materials: &materials,
    }
    .system(doc.table())
}

/// The `[system]` table as scene-file text (reads back to an equal [`SystemSpec`]).
pub fn system_table(spec: &SystemSpec) -> String {
    let mut out = format!("[system]\nkind = \"{}\"\n", spec.kind_name());
    match spec.kind {
        SystemKind::BouncingBall {
            amplitude,
            frequency,
            gravity,
        } => {
            push(
                &mut out,
                "amplitude",
                amplitude,
                "m, table motion A·sin(ωt)",
            );
            push(&mut out, "frequency", frequency, "Hz");
            push(&mut out, "gravity", gravity, "m/s²");
        }
        SystemKind::ImpactOscillator {
            stiffness,
            damping,
            forcing,
            frequency,
            gap,
            second_gap,
        } => {
            push(&mut out, "stiffness", stiffness, "N/m");
            match damping {
                Damping::Ratio(z) => push(&mut out, "damping_ratio", z, "ζ = c/(2√(km))"),
                Damping::Coefficient(c) => push(&mut out, "damping", c, "N·s/m"),
            }
            let (name, amplitude, unit) = match forcing {
                Forcing::Force { amplitude } => ("force", amplitude, "N, force F₀·cos(ωt)"),
                Forcing::Base { amplitude } => ("base", amplitude, "m, frame motion B·cos(ωt)"),
            };
            out.push_str(&format!("forcing = \"{name}\"\n"));
            push(&mut out, "forcing_amplitude", amplitude, unit);
            push(&mut out, "frequency", frequency, "Hz");
            push(&mut out, "gap", gap, "m, stop at x = gap");
            if let Some(second) = second_gap {
                push(&mut out, "second_gap", second, "m, stop at x = −second_gap");
            }
        }
    }
    out
}

/// `key = value  # unit` on its own line.
fn push(out: &mut String, key: &str, value: f64, unit: &str) {
    out.push_str(&format!("{key} = {}  # {unit}\n", toml_float(value)));
}
