//! A scene's name and description after edits: a preset's "…on steel plate" would mislabel a
//! scene whose plate was changed to aluminium, so an edited scene is named by what its bodies are
//! and its description says what was edited, everywhere a name is shown or saved.
#![warn(missing_docs)]

use super::body::{Body, Shape};
use super::scene::Scene;
use super::scene_key::SceneKey;

/// The name a scene's bodies say: `Steel sphere R = 10 mm on aluminium-alloy plate`.
pub fn bodies_name(scene: &Scene) -> String {
    let name = format!(
        "{} on {}",
        body_words(&scene.body1),
        body_words(&scene.body2)
    );
    let mut chars = name.chars();
    match chars.next() {
        Some(first) => first.to_uppercase().chain(chars).collect(),
        None => name,
    }
}

/// `steel sphere R = 10 mm`, `steel cylinder R = 20 mm, L = 100 mm`, `steel plate`.
fn body_words(body: &Body) -> String {
    let material = &body.material.name;
    match body.shape {
        Shape::Sphere { radius } => format!("{material} sphere R = {} mm", millimetres(radius)),
        Shape::Cylinder { radius, length } => format!(
            "{material} cylinder R = {} mm, L = {} mm",
            millimetres(radius),
            millimetres(length)
        ),
        Shape::Plane => format!("{material} plate"),
    }
}

/// A length in mm to four significant digits, trailing zeros dropped; in powers of ten outside
/// 0.001 … 10⁶ mm.
fn millimetres(metres: f64) -> String {
    let mm = metres * 1e3;
    if !(1e-3..1e6).contains(&mm.abs()) {
        let text = format!("{mm:.3e}");
        let (mantissa, exponent) = text.split_once('e').unwrap_or((&text, "0"));
        let mantissa = mantissa.trim_end_matches('0').trim_end_matches('.');
        return format!("{mantissa}e{exponent}");
    }
    let decimals = (3 - mm.abs().log10().floor() as i32).clamp(0, 12) as usize;
    let text = format!("{mm:.decimals$}");
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        text
    }
}

/// What differs from `original` in `edited`, as `key = value` (SI, the scene file's keys), in
/// schema order: shapes and materials by name, then every number.
pub fn edits(original: &Scene, edited: &Scene) -> Vec<String> {
    let mut out = Vec::new();
    for (key, a, b) in [
        ("body1", &original.body1, &edited.body1),
        ("body2", &original.body2, &edited.body2),
    ] {
        if a.shape.name() != b.shape.name() {
            out.push(format!("{key}.shape = {}", b.shape.name()));
        }
        if a.material.name != b.material.name {
            out.push(format!("{key}.material = {}", b.material.name));
        }
    }
    for key in SceneKey::all() {
        let (a, b) = (key.get(original), key.get(edited));
        if a != b
            && let Some(value) = b
        {
            out.push(format!("{key} = {value}"));
        }
    }
    out
}

/// The name and description of `edited`, a scene made from `original` (described by
/// `description`): the original's while nothing but the title differs, else the name its bodies
/// say and a description naming what was edited.
pub fn retitled(
    original: &Scene,
    description: Option<&str>,
    edited: &Scene,
) -> (String, Option<String>) {
    let changed = edits(original, edited);
    if changed.is_empty() {
        return (edited.name.clone(), description.map(str::to_string));
    }
    (
        bodies_name(edited),
        Some(format!(
            "edited from \"{}\": {}",
            original.name,
            changed.join(", ")
        )),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::material::tests::steel;
    use crate::model::scene::tests::fig5_scene;

    #[test]
    fn an_edited_scene_is_named_by_its_bodies_and_says_what_was_edited() {
        let original = fig5_scene();
        assert_eq!(
            bodies_name(&original),
            "Steel sphere R = 10 mm on steel plate"
        );
        let unchanged = retitled(&original, Some("Fig. 5 as published"), &original);
        assert_eq!(
            unchanged,
            ("Fig. 5".into(), Some("Fig. 5 as published".into()))
        );

        let mut edited = original.clone();
        edited.body2.material.name = "aluminium-alloy".into();
        edited.body2.material.youngs_modulus = 7e10;
        edited.impact.v0 = 1.0;
        let (name, description) = retitled(&original, Some("Fig. 5"), &edited);
        assert_eq!(name, "Steel sphere R = 10 mm on aluminium-alloy plate");
        assert_eq!(
            description.as_deref(),
            Some(
                "edited from \"Fig. 5\": body2.material = aluminium-alloy, impact.v0 = 1, \
                 body2.material.youngs_modulus = 70000000000"
            )
        );
    }

    #[test]
    fn extreme_sizes_read_in_powers_of_ten() {
        assert_eq!(millimetres(1e100), "1e103");
        assert_eq!(millimetres(2.5e-9), "2.5e-6");
        assert_eq!(millimetres(0.0123456), "12.35");
    }

    #[test]
    fn cylinders_and_small_radii_read_in_millimetres() {
        let mut scene = fig5_scene();
        scene.body1.shape = Shape::Cylinder {
            radius: 0.02,
            length: 0.1,
        };
        scene.body2 = Body {
            shape: Shape::Sphere { radius: 0.0025 },
            material: steel(),
            mass: None,
        };
        assert_eq!(
            bodies_name(&scene),
            "Steel cylinder R = 20 mm, L = 100 mm on steel sphere R = 2.5 mm"
        );
    }
}
