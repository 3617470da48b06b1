//! Writing a scene back as TOML in the scene-file schema.

use toml::Value;

use crate::model::body::Shape;
use crate::model::scene::Scene;

use crate::model::system::SystemSpec;

use super::fit::fit_table;
use super::system::system_table;
use super::view::SceneView;

/// A float as TOML text that reads back to exactly the same f64, in plain or exponent notation
/// (Rust prints the shortest round-tripping digits in both).
pub fn toml_float(x: f64) -> String {
    if x.is_nan() {
        return "nan".into();
    }
    if x.is_infinite() {
        return if x > 0.0 { "inf".into() } else { "-inf".into() };
    }
    let mut plain = format!("{x}");
    if !plain.contains(['.', 'e']) {
        plain.push_str(".0");
    }
    let exponent = format!("{x:e}");
    // Plain notation unless it is clearly longer (7800.0 rather than 7.8e3, 2e11 rather than 200000000000.0).
    if exponent.len() + 2 < plain.len() {
        exponent
    } else {
        plain
    }
}

/// Writes a scene in the scene-file schema with materials inline; [`parse_scene`](super::parse_scene) reads it back
/// to an equal [`Scene`].
pub fn to_toml(scene: &Scene, description: Option<&str>) -> String {
    to_toml_with_view(scene, description, None)
}

/// [`to_toml`] with the view's `models` and `[solver]` written too.
pub fn to_toml_with_view(
    scene: &Scene,
    description: Option<&str>,
    view: Option<&SceneView>,
) -> String {
    to_toml_with_system(scene, description, view, None)
}

/// [`to_toml_with_view`] with the `[system]` table written too (a system scene round-trips).
pub fn to_toml_with_system(
    scene: &Scene,
    description: Option<&str>,
    view: Option<&SceneView>,
    system: Option<&SystemSpec>,
) -> String {
    let mut out = String::new();
    let quote = |s: &str| Value::String(s.to_string()).to_string();
    out.push_str(&format!("name = {}\n", quote(&scene.name)));
    if let Some(description) = description {
        out.push_str(&format!("description = {}\n", quote(description)));
    }
    if let Some(view) = view {
        out.push_str(&view.models_line());
    }
    for (key, body) in [("body1", &scene.body1), ("body2", &scene.body2)] {
        out.push_str(&format!("\n[{key}]\nshape = \"{}\"\n", body.shape.name()));
        match body.shape {
            Shape::Sphere { radius } => {
                out.push_str(&format!("radius = {}  # m\n", toml_float(radius)))
            }
            Shape::Cylinder { radius, length } => {
                out.push_str(&format!("radius = {}  # m\n", toml_float(radius)));
                out.push_str(&format!("length = {}  # m\n", toml_float(length)));
            }
            Shape::Plane => {}
        }
        if let Some(mass) = body.mass {
            out.push_str(&format!("mass = {}  # kg\n", toml_float(mass)));
        }
        let m = &body.material;
        out.push_str(&format!("\n[{key}.material]\nname = {}\n", quote(&m.name)));
        out.push_str(&format!(
            "youngs_modulus = {}  # Pa\n",
            toml_float(m.youngs_modulus)
        ));
        out.push_str(&format!(
            "poisson_ratio = {}\n",
            toml_float(m.poisson_ratio)
        ));
        out.push_str(&format!(
            "yield_stress = {}  # Pa\n",
            toml_float(m.yield_stress)
        ));
        out.push_str(&format!("density = {}  # kg/m³\n", toml_float(m.density)));
    }
    let i = &scene.impact;
    out.push_str("\n[impact]\n");
    out.push_str(&format!(
        "v0 = {}  # m/s, pre-impact relative velocity\n",
        toml_float(i.v0)
    ));
    let e_comment = if scene.fit.is_some() {
        "e of the [fit] law at v0, recomputed from [fit] when read"
    } else {
        "e, used by the dissipative models"
    };
    out.push_str(&format!(
        "restitution = {}  # {e_comment}\n",
        toml_float(i.restitution)
    ));
    out.push_str(&format!(
        "plastic_indentation = {}  # x_pl in m, used by the proposed viscous model\n",
        toml_float(i.plastic_indentation)
    ));
    if !scene.assumed.is_empty() {
        let keys: Vec<String> = scene.assumed.keys().iter().map(|k| quote(k)).collect();
        out.push_str(&format!(
            "assumed = [{}]  # not given by the scene's user: stand-ins\n",
            keys.join(", ")
        ));
    }
    if let Some(fit) = &scene.fit {
        out.push('\n');
        out.push_str(&fit_table(fit));
    }
    if let Some(view) = view {
        out.push('\n');
        out.push_str(&view.solver_table());
    }
    if let Some(system) = system {
        out.push('\n');
        out.push_str(&system_table(system));
    }
    out
}
