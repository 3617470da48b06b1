//! What an edit does besides changing a value: nudges stop at the model's domain bounds, a field
//! goes back to the scene as loaded or saved, and a material whose numbers were edited is named so.

use crate::model::Material;
use crate::model::scene_key::{BodyField, BodyIndex, SceneKey};

use super::app::App;
use super::field::{Field, Nudge, body, body_mut};

/// Added to a preset material's name once its numbers differ from the preset's.
pub const EDITED: &str = " (edited)";

/// Nudges `field`; a step that would turn a valid scene invalid (ν 0.49 → 0.5, e 1 → 1.01) is
/// refused with the model's reason, so the value stops at the bound.
pub fn nudge_within_domain(app: &mut App, field: Field, direction: Nudge) {
    let mut next = app.draft.clone();
    if field == Field::Dt && next.options.dt.is_none() {
        // ←/→ from `auto` halve/double the solver's own step.
        next.options.dt = app.auto_dt();
    }
    if !field.nudge(direction, &mut next) {
        return;
    }
    if let (Ok(()), Err(reason)) = (app.draft.scene.validate(), next.scene.validate()) {
        app.say(
            format!(
                "{} stays at {}: {reason}",
                field.label(),
                field.display(&app.draft)
            ),
            true,
        );
        return;
    }
    app.draft = next;
    app.recompute();
}

/// Sets `field` back to its value in the scene (and solver settings) as last loaded or saved.
pub fn reset_field(app: &mut App, field: Field) {
    let saved = app.saved.clone();
    let options = app.saved_view.options;
    let draft = &mut app.draft;
    match field {
        Field::Shape(index) => body_mut(&mut draft.scene, index).shape = body(&saved, index).shape,
        Field::Method => draft.options.method = options.method,
        Field::Rtol => draft.options.rtol = options.rtol,
        Field::Dt => draft.options.dt = options.dt,
        Field::Number(SceneKey::Body(index, BodyField::Mass)) => {
            body_mut(&mut draft.scene, index).mass = body(&saved, index).mass;
        }
        Field::Number(key) => match key.get(&saved) {
            Some(value) => {
                // The key exists in both scenes (same shape), so setting it cannot fail.
                let _ = key.set(&mut draft.scene, value);
                // Back to the loaded value, back to its standing: a stand-in stays assumed.
                if let Some(name) = key.path().strip_prefix("impact.") {
                    draft
                        .scene
                        .assumed
                        .set(name, saved.assumed.keys().contains(&name));
                }
            }
            None => {
                app.say(
                    format!("{} is not in the scene as loaded", field.label()),
                    true,
                );
                return;
            }
        },
    }
    let shown = field.display(&app.draft);
    app.recompute();
    app.say(format!("{} reset to {shown}", field.label()), false);
}

/// Names a body's material "<preset> (edited)" while its numbers differ from the material of the
/// scene as loaded or saved, and gives the preset's name back when they match again; a material
/// from elsewhere (the picker) keeps its own name.
pub fn name_edited_materials(app: &mut App) {
    for index in [BodyIndex::One, BodyIndex::Two] {
        let original = &body(&app.saved, index).material;
        let material = &mut body_mut(&mut app.draft.scene, index).material;
        let base = material.name.strip_suffix(EDITED).unwrap_or(&material.name);
        if base != original.name {
            continue;
        }
        material.name = if same_numbers(material, original) {
            original.name.clone()
        } else {
            format!("{}{EDITED}", original.name)
        };
    }
}

fn same_numbers(a: &Material, b: &Material) -> bool {
    (a.youngs_modulus, a.poisson_ratio, a.yield_stress, a.density)
        == (b.youngs_modulus, b.poisson_ratio, b.yield_stress, b.density)
}
