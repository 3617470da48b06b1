//! Presets, scene files and `--set` overrides through the public API.

use std::collections::BTreeMap;
use std::fs;
use std::path::{Path, PathBuf};

use hertz_tui::model::overrides::Override;
use hertz_tui::model::presets::{DEFAULT_SCENE, Origin, PresetError, Registry, SaveTarget};
use hertz_tui::model::scene_file::{self, parse_scene};
use hertz_tui::model::{Material, Shape};

use crate::scratch::{self, Folder};

/// A fresh folder under the system temp dir, removed when dropped (also when the test fails).
struct TempDir(Folder);

impl TempDir {
    fn new(label: &str) -> TempDir {
        TempDir(scratch::folder(&format!("presets-{label}")))
    }

    fn write(&self, relative: &str, text: &str) -> PathBuf {
        let path = self.0.join(relative);
        fs::create_dir_all(path.parent().unwrap()).unwrap();
        fs::write(&path, text).unwrap();
        path
    }

    fn path(&self) -> &Path {
        &self.0
    }
}

fn builtin() -> Registry {
    Registry::builtin().expect("built-in presets load")
}

fn catalog() -> BTreeMap<String, Material> {
    builtin().material_catalog().clone()
}

/// Parses `text` as the scene file `test.toml` and returns the error message.
fn scene_error(text: &str) -> String {
    parse_scene("test.toml", text, &catalog())
        .expect_err("the scene must be refused")
        .to_string()
}

/// A valid scene file; tests spoil one line of it. Line numbers are stated where they matter.
const VALID: &str = r#"name = "Steel sphere R = 10 mm on steel plate"
description = "a test scene"
[body1]
shape = "sphere"
radius = 0.01
material = "steel"
[body2]
shape = "plane"
material = "steel"
[impact]
v0 = 0.3
restitution = 0.6
plastic_indentation = 2.3e-6
"#;

const BUILTIN_SCENES: [&str; 10] = [
    "aluminium-sphere-r10-plate",
    "bouncing-ball",
    "fig4-steel-sphere-r10-plate",
    "fig5-steel-sphere-r10-plate",
    "impact-oscillator",
    "impact-oscillator-clearance",
    "steel-cylinder-r20-l100-plate",
    "steel-cylinders-r20-l100",
    "steel-sphere-r10-plate",
    "steel-sphere-r5-plate",
];

#[test]
fn every_builtin_scene_loads_and_validates() {
    let registry = builtin();
    assert!(registry.warnings().is_empty());
    let names: Vec<&str> = registry.scenes().iter().map(|s| s.name.as_str()).collect();
    assert_eq!(names, BUILTIN_SCENES);
    for info in registry.scenes() {
        assert_eq!(info.origin, Origin::BuiltIn);
        assert!(
            !info.description.is_empty(),
            "{} has no description",
            info.name
        );
        let scene = registry.scene(&info.name).unwrap();
        assert_eq!(scene.validate(), Ok(()), "{}", info.name);
        scene.pair().unwrap();
    }
    assert!(names.contains(&DEFAULT_SCENE));
}

#[test]
fn builtin_materials_have_the_papers_values() {
    let registry = builtin();
    let names: Vec<&str> = registry
        .materials()
        .iter()
        .map(|m| m.name.as_str())
        .collect();
    assert_eq!(names, ["aluminium-alloy", "steel"]);
    let steel = registry.material("steel").unwrap();
    assert_eq!(
        (
            steel.youngs_modulus,
            steel.poisson_ratio,
            steel.yield_stress,
            steel.density
        ),
        (2e11, 0.3, 780e6, 7800.0)
    );
    let al = registry.material("aluminium-alloy").unwrap();
    assert_eq!(
        (
            al.youngs_modulus,
            al.poisson_ratio,
            al.yield_stress,
            al.density
        ),
        (7e10, 0.33, 340e6, 2700.0)
    );
    let err = registry.material("titanium").unwrap_err();
    assert_eq!(
        err,
        PresetError::UnknownMaterial {
            name: "titanium".into(),
            known: vec!["aluminium-alloy".into(), "steel".into()],
        }
    );
    assert_eq!(
        err.to_string(),
        "unknown material \"titanium\" (materials: aluminium-alloy, steel)"
    );
}

#[test]
fn builtin_scenes_have_the_papers_conditions() {
    let registry = builtin();
    let fig5 = registry.scene(DEFAULT_SCENE).unwrap();
    assert_eq!(
        (
            fig5.impact.v0,
            fig5.impact.restitution,
            fig5.impact.plastic_indentation
        ),
        (0.3, 0.6, 2.3e-6)
    );
    assert_eq!(fig5.body1.shape, Shape::Sphere { radius: 0.01 });
    assert_eq!(fig5.body2.shape, Shape::Plane);
    let fig4 = registry.scene("fig4-steel-sphere-r10-plate").unwrap();
    assert_eq!(
        (
            fig4.impact.v0,
            fig4.impact.restitution,
            fig4.impact.plastic_indentation
        ),
        (0.03, 0.9, 0.0)
    );
    // Table scenes: v0 = 1 m/s, e and x_pl as in Fig. 5; sphere masses from density.
    // (The system presets set their own: docs/systems.md.)
    let systems = [
        "bouncing-ball",
        "impact-oscillator",
        "impact-oscillator-clearance",
    ];
    for name in BUILTIN_SCENES
        .iter()
        .filter(|n| !n.starts_with("fig") && !systems.contains(n))
    {
        let scene = registry.scene(name).unwrap();
        assert_eq!(
            (
                scene.impact.v0,
                scene.impact.restitution,
                scene.impact.plastic_indentation
            ),
            (1.0, 0.6, 2.3e-6),
            "{name}"
        );
    }
    // Table 2: two 1 kg cylinders give the printed reduced mass 0.5 kg; on a plane, 1 kg.
    let two = registry.scene("steel-cylinders-r20-l100").unwrap();
    assert_eq!(two.pair().unwrap().reduced_mass(), 0.5);
    let on_plane = registry.scene("steel-cylinder-r20-l100-plate").unwrap();
    assert_eq!(on_plane.pair().unwrap().reduced_mass(), 1.0);
    assert_eq!(on_plane.pair().unwrap().contact_length(), Some(0.1));
}

#[test]
fn user_presets_override_builtins_of_the_same_name() {
    let home = TempDir::new("override");
    home.write(
        "materials/steel.toml",
        "name = \"soft steel\"\nyoungs_modulus = 1e11\npoisson_ratio = 0.3\nyield_stress = 5e8\ndensity = 7800\n",
    );
    home.write(
        "scenes/steel-sphere-r10-plate.toml",
        &VALID.replace("v0 = 0.3", "v0 = 0.5"),
    );
    home.write("scenes/my-scene.toml", VALID);
    let registry = Registry::load_from(Some(home.path())).unwrap();
    assert!(registry.warnings().is_empty(), "{:?}", registry.warnings());

    let steel = registry
        .materials()
        .into_iter()
        .find(|m| m.name == "steel")
        .unwrap();
    assert!(matches!(steel.origin, Origin::User(_)));
    assert!(steel.overrides_builtin);
    assert_eq!(registry.material("steel").unwrap().youngs_modulus, 1e11);

    let replaced = registry.scene("steel-sphere-r10-plate").unwrap();
    assert_eq!(replaced.impact.v0, 0.5);
    // Scenes naming "steel", built-in ones included, now use the user's steel.
    let fig5 = registry.scene(DEFAULT_SCENE).unwrap();
    assert_eq!(fig5.body1.material.name, "soft steel");

    let mine = registry
        .scenes()
        .into_iter()
        .find(|s| s.name == "my-scene")
        .unwrap();
    assert_eq!(mine.description, "a test scene");
    assert!(!mine.overrides_builtin);
    assert_eq!(registry.scenes().len(), BUILTIN_SCENES.len() + 1);
}

#[test]
fn broken_user_presets_are_warnings_not_failures() {
    let home = TempDir::new("broken");
    let broken = home.write(
        "scenes/steel-sphere-r10-plate.toml",
        &VALID.replace("radius = 0.01", "radius = \"big\""),
    );
    home.write("scenes/Not Kebab.toml", VALID);
    home.write(
        "materials/bad.toml",
        "name = \"bad\"\nyoungs_modulus = 1e11\n",
    );
    let registry = Registry::load_from(Some(home.path())).unwrap();
    let warnings: Vec<String> = registry.warnings().iter().map(|w| w.to_string()).collect();
    assert_eq!(warnings.len(), 3, "{warnings:?}");
    assert!(
        warnings
            .iter()
            .any(|w| w.contains("materials/bad.toml") && w.contains("missing key `poisson_ratio`"))
    );
    assert!(
        warnings
            .iter()
            .any(|w| w.contains("not kebab-case") && w.contains("not-kebab.toml"))
    );
    let expected = format!(
        "{}:5:1: `body1.radius` must be a number, found string \"big\"",
        broken.display()
    );
    assert!(warnings.contains(&expected), "{warnings:?}");
    // The built-in of that name stays available.
    let scene = registry.scene("steel-sphere-r10-plate").unwrap();
    assert_eq!(scene.impact.v0, 1.0);
}

#[test]
fn scenes_load_from_a_path_and_unknown_names_list_the_known_ones() {
    let dir = TempDir::new("path");
    let path = dir.write(
        "elsewhere.toml",
        &VALID.replace(
            "material = \"steel\"\n[body2]",
            "material = \"aluminium-alloy\"\n[body2]",
        ),
    );
    let registry = builtin();
    let scene = registry.scene(path.to_str().unwrap()).unwrap();
    assert_eq!(scene.body1.material.name, "aluminium-alloy");
    assert_eq!(scene.body2.material.name, "steel");

    let err = registry.scene("steel-sphere").unwrap_err().to_string();
    assert!(
        err.starts_with("unknown scene \"steel-sphere\" (scenes: aluminium-sphere-r10-plate, "),
        "{err}"
    );
    let missing = dir.path().join("missing.toml");
    let err = registry.scene(missing.to_str().unwrap()).unwrap_err();
    assert!(matches!(err, PresetError::Read { .. }), "{err}");
}

#[test]
fn malformed_toml_names_file_and_line() {
    let err = scene_error(&VALID.replace("v0 = 0.3", "v0 = "));
    assert!(
        err.starts_with("test.toml:11:6: TOML syntax error: "),
        "{err}"
    );
    let err =
        scene_error(&VALID.replace("restitution = 0.6", "restitution = 0.6\nrestitution = 0.7"));
    assert!(
        err.starts_with("test.toml:13:1: TOML syntax error: duplicate key"),
        "{err}"
    );
}

#[test]
fn unknown_key_names_file_line_and_key() {
    let err = scene_error(&VALID.replace("radius = 0.01", "radius = 0.01\ncolour = \"red\""));
    assert_eq!(
        err,
        "test.toml:6:1: unknown key `body1.colour` (allowed here: shape, radius, length, mass, material)"
    );
    let err = scene_error(&VALID.replace("v0 = 0.3", "v0 = 0.3\nvelocity = 1"));
    assert!(
        err.starts_with("test.toml:12:1: unknown key `impact.velocity`"),
        "{err}"
    );
    let err = scene_error(&format!("{VALID}[body3]\nshape = \"plane\"\n"));
    assert!(
        err.starts_with("test.toml:14:2: unknown key `body3`"),
        "{err}"
    );
}

#[test]
fn missing_key_names_file_line_and_key() {
    // The radius of a sphere is missing: the message points at the shape that needs it (line 4).
    let err = scene_error(&VALID.replace("radius = 0.01\n", ""));
    assert_eq!(
        err,
        "test.toml:4:1: missing key `body1.radius` (a sphere needs it)"
    );
    let err = scene_error(&VALID.replace("plastic_indentation = 2.3e-6\n", ""));
    assert!(
        err.starts_with("test.toml:10:2: missing key `impact.plastic_indentation`"),
        "{err}"
    );
    let err = scene_error(&VALID.replace("name = \"Steel sphere R = 10 mm on steel plate\"\n", ""));
    assert_eq!(err, "test.toml:1:1: missing key `name`");
    let err = scene_error(&VALID.replace(
        "shape = \"plane\"\nmaterial = \"steel\"\n",
        "shape = \"plane\"\n",
    ));
    assert!(
        err.starts_with("test.toml:7:2: missing key `body2.material`"),
        "{err}"
    );
}

#[test]
fn wrong_type_names_file_line_and_key() {
    let err = scene_error(&VALID.replace("radius = 0.01", "radius = \"10 mm\""));
    assert_eq!(
        err,
        "test.toml:5:1: `body1.radius` must be a number, found string \"10 mm\""
    );
    let err = scene_error(&VALID.replace("shape = \"plane\"", "shape = 3"));
    assert_eq!(
        err,
        "test.toml:8:1: `body2.shape` must be a string, found integer 3"
    );
    let err = scene_error(&VALID.replace(
        "material = \"steel\"\n[impact]",
        "material = [1, 2]\n[impact]",
    ));
    assert_eq!(
        err,
        "test.toml:9:1: `body2.material` must be a material name or a table, found array"
    );
}

#[test]
fn shape_keys_are_checked_both_ways() {
    // A field the shape does not use is an error too.
    let err = scene_error(&VALID.replace("radius = 0.01", "radius = 0.01\nlength = 0.1"));
    assert_eq!(
        err,
        "test.toml:6:1: `body1.length` is not used by a sphere; remove it"
    );
    let err = scene_error(&VALID.replace("shape = \"plane\"", "shape = \"plane\"\nradius = 1.0"));
    assert_eq!(
        err,
        "test.toml:9:1: `body2.radius` is not used by a plane; remove it"
    );
    let err = scene_error(&VALID.replace("shape = \"sphere\"", "shape = \"cylinder\""));
    assert_eq!(
        err,
        "test.toml:4:1: missing key `body1.length` (a cylinder needs it)"
    );
    let err = scene_error(&VALID.replace("shape = \"sphere\"", "shape = \"cone\""));
    assert_eq!(
        err,
        "test.toml:4:1: `body1.shape`: unknown shape \"cone\" (expected one of: sphere, cylinder, plane)"
    );
}

#[test]
fn validation_errors_name_the_dotted_field_and_its_line() {
    let inline = VALID.replace(
        "material = \"steel\"\n[body2]",
        "material = { name = \"odd\", youngs_modulus = 2e11, poisson_ratio = 0.7, yield_stress = 7.8e8, density = 7800 }\n[body2]",
    );
    let err = scene_error(&inline);
    assert!(
        err.ends_with("body1.material.poisson_ratio must be in [0, 0.5), got 0.7"),
        "{err}"
    );
    assert!(err.starts_with("test.toml:6:"), "{err}");
    let err = scene_error(&VALID.replace("restitution = 0.6", "restitution = 0"));
    assert_eq!(
        err,
        "test.toml:12:1: impact.restitution must be in (0, 1], got 0"
    );
    let err = scene_error(&VALID.replace("radius = 0.01", "radius = -0.01"));
    assert_eq!(
        err,
        "test.toml:5:1: body1.radius must be a finite number > 0, got -0.01"
    );
    let err = scene_error(&VALID.replace(
        "material = \"steel\"\n[body2]",
        "material = \"unobtainium\"\n[body2]",
    ));
    assert!(
        err.starts_with("test.toml:6:1: `body1.material`: unknown material \"unobtainium\" (known: aluminium-alloy, steel;"),
        "{err}"
    );
    let err = scene_error(&VALID.replace(
        "shape = \"plane\"",
        "shape = \"cylinder\"\nradius = 0.01\nlength = 0.1",
    ));
    assert!(
        err.starts_with("test.toml: sphere–cylinder contact is not supported"),
        "{err}"
    );
}

#[test]
fn integers_are_accepted_as_numbers_and_x_pl_may_be_zero() {
    let scene = parse_scene(
        "test.toml",
        &VALID.replace("v0 = 0.3", "v0 = 1").replace("2.3e-6", "0"),
        &catalog(),
    )
    .unwrap();
    assert_eq!(scene.impact.v0, 1.0);
    assert_eq!(scene.impact.plastic_indentation, 0.0);
}

#[test]
fn material_files_are_strict_too() {
    let home = TempDir::new("material");
    home.write(
        "materials/brass.toml",
        "youngs_modulus = 1e11\npoisson_ratio = 0.34\nyield_stress = 2e8\ndensity = 8500\nhardness = 3\n",
    );
    let registry = Registry::load_from(Some(home.path())).unwrap();
    let warning = registry.warnings()[0].to_string();
    assert!(warning.ends_with("brass.toml:5:1: unknown key `hardness` (allowed here: name, description, youngs_modulus, poisson_ratio, yield_stress, density)"), "{warning}");
    // Without the bad key the name defaults to the file stem.
    home.write(
        "materials/brass.toml",
        "youngs_modulus = 1e11\npoisson_ratio = 0.34\nyield_stress = 2e8\ndensity = 8500\n",
    );
    let registry = Registry::load_from(Some(home.path())).unwrap();
    assert_eq!(registry.material("brass").unwrap().name, "brass");
}

#[test]
fn overrides_apply_by_dotted_path() {
    let registry = builtin();
    let set =
        |pairs: &[&str]| -> Vec<Override> { pairs.iter().map(|s| s.parse().unwrap()).collect() };
    let scene = registry
        .scene_with(
            "steel-sphere-r10-plate",
            &set(&[
                "impact.v0=0.5",
                "body1.radius=0.02",
                "body1.material.youngs_modulus=7e10",
            ]),
        )
        .unwrap();
    assert_eq!(scene.impact.v0, 0.5);
    assert_eq!(scene.body1.shape, Shape::Sphere { radius: 0.02 });
    // The named material was inlined first: only E changed, the rest is steel's.
    let steel = registry.material("steel").unwrap();
    assert_eq!(
        scene.body1.material,
        Material {
            youngs_modulus: 7e10,
            ..steel.clone()
        }
    );
    assert_eq!(scene.body2.material, steel);

    let scene = registry
        .scene_with(
            DEFAULT_SCENE,
            &set(&["body2.material=aluminium-alloy", "body1.mass=0.1"]),
        )
        .unwrap();
    assert_eq!(
        scene.body2.material,
        registry.material("aluminium-alloy").unwrap()
    );
    assert_eq!(scene.body1.mass, Some(0.1));

    // Shapes can be swapped: the radius a plane does not use is dropped.
    let scene = registry
        .scene_with(
            DEFAULT_SCENE,
            &set(&[
                "body1.shape=plane",
                "body2.shape=sphere",
                "body2.radius=0.005",
            ]),
        )
        .unwrap();
    assert_eq!(scene.body1.shape, Shape::Plane);
    assert_eq!(scene.body2.shape, Shape::Sphere { radius: 0.005 });
}

#[test]
fn override_errors_name_the_key() {
    let err = "body1.colour=red"
        .parse::<Override>()
        .unwrap_err()
        .to_string();
    assert!(
        err.starts_with("--set body1.colour: unknown scene key (known keys: name, "),
        "{err}"
    );
    let err = "impact.v0".parse::<Override>().unwrap_err().to_string();
    assert_eq!(
        err,
        "--set \"impact.v0\": expected KEY=VALUE, e.g. impact.v0=0.5"
    );

    let registry = builtin();
    let apply = |s: &str| {
        registry
            .scene_with(DEFAULT_SCENE, &[s.parse().unwrap()])
            .unwrap_err()
            .to_string()
    };
    assert_eq!(
        apply("impact.v0=fast"),
        "--set impact.v0: \"fast\" is not a number (e.g. 0.5, 2e11, 2.3e-6, 10 mm)"
    );
    assert_eq!(
        apply("impact.v0=-1"),
        "presets/scenes/fig5-steel-sphere-r10-plate.toml (built-in) (--set impact.v0): impact.v0 must be a finite number > 0, got -1"
    );
    assert_eq!(
        apply("body1.length=0.1"),
        "presets/scenes/fig5-steel-sphere-r10-plate.toml (built-in) (--set body1.length): `body1.length` is not used by a sphere; remove it"
    );
    assert!(
        apply("body1.material.density=abc")
            .starts_with("--set body1.material.density: \"abc\" is not a number")
    );
}

#[test]
fn scenes_round_trip_through_toml() {
    let registry = builtin();
    for info in registry.scenes() {
        let scene = registry.scene(&info.name).unwrap();
        let text = scene_file::to_toml(&scene, Some(&info.description));
        let again = parse_scene("written.toml", &text, &BTreeMap::new())
            .unwrap_or_else(|e| panic!("{e}\n{text}"));
        assert_eq!(again, scene, "{text}");
    }
    // Awkward values survive exactly: shortest round-trip digits.
    let mut scene = registry.scene("steel-cylinders-r20-l100").unwrap();
    scene.name = "quote \" and\nnewline".into();
    scene.impact.v0 = 0.1 + 0.2;
    scene.body1.material.youngs_modulus = 1.234_567_890_123_456_7e-300;
    scene.body2.mass = Some(1e300);
    let text = scene_file::to_toml(&scene, None);
    assert_eq!(
        parse_scene("written.toml", &text, &BTreeMap::new()).unwrap(),
        scene,
        "{text}"
    );
}

#[test]
fn toml_floats_are_short_and_exact() {
    assert_eq!(scene_file::toml_float(2e11), "2e11");
    assert_eq!(scene_file::toml_float(0.01), "0.01");
    assert_eq!(scene_file::toml_float(2.3e-6), "2.3e-6");
    assert_eq!(scene_file::toml_float(7800.0), "7800.0");
    assert_eq!(scene_file::toml_float(1.0), "1.0");
    assert_eq!(scene_file::toml_float(0.0), "0.0");
}

#[test]
fn saved_scenes_load_back() {
    let home = TempDir::new("save");
    let registry = Registry::load_from(Some(home.path())).unwrap();
    let scene = registry
        .scene_with(DEFAULT_SCENE, &["impact.v0=0.25".parse().unwrap()])
        .unwrap();
    let path = registry
        .save_scene(
            &scene,
            Some("my variant"),
            SaveTarget::UserPreset { name: "my-variant" },
        )
        .unwrap();
    assert_eq!(path, home.path().join("scenes/my-variant.toml"));
    let reloaded = Registry::load_from(Some(home.path())).unwrap();
    let info = reloaded
        .scenes()
        .into_iter()
        .find(|s| s.name == "my-variant")
        .unwrap()
        .clone();
    assert_eq!(info.description, "my variant");
    assert_eq!(info.origin, Origin::User(path.clone()));
    assert_eq!(reloaded.scene("my-variant").unwrap(), scene);

    let file = home.path().join("anywhere.toml");
    registry
        .save_scene(&scene, None, SaveTarget::Path(&file))
        .unwrap();
    assert_eq!(registry.scene(file.to_str().unwrap()).unwrap(), scene);

    let err = registry
        .save_scene(&scene, None, SaveTarget::UserPreset { name: "My Variant" })
        .unwrap_err();
    assert!(matches!(err, PresetError::InvalidName(_)), "{err}");
    let mut invalid = scene.clone();
    invalid.impact.restitution = 2.0;
    let err = registry
        .save_scene(&invalid, None, SaveTarget::Path(&file))
        .unwrap_err();
    assert_eq!(
        err.to_string(),
        "refusing to save an invalid scene: impact.restitution must be in (0, 1], got 2"
    );
    let err = Registry::builtin()
        .unwrap()
        .save_scene(&scene, None, SaveTarget::UserPreset { name: "x" })
        .unwrap_err();
    assert_eq!(err, PresetError::NoUserDir);
}

#[test]
fn overrides_apply_to_a_scene_in_memory() {
    let registry = builtin();
    let scene = registry.scene(DEFAULT_SCENE).unwrap();
    let changed = registry
        .apply_overrides(&scene, &["body2.material.density=8000".parse().unwrap()])
        .unwrap();
    assert_eq!(changed.body2.material.density, 8000.0);
    assert_eq!(changed.body1, scene.body1);
}

mod round_trip {
    use super::*;
    use hertz_tui::model::{Body, ImpactConditions, Scene};
    use proptest::prelude::*;

    fn positive() -> impl Strategy<Value = f64> {
        (-300.0f64..300.0).prop_map(|e| 10f64.powf(e))
    }

    fn material() -> impl Strategy<Value = Material> {
        ("[ -~]{0,20}", positive(), 0.0..0.5, positive(), positive()).prop_map(
            |(name, e, nu, sy, rho)| Material {
                name,
                youngs_modulus: e,
                poisson_ratio: nu,
                yield_stress: sy,
                density: rho,
            },
        )
    }

    fn body() -> impl Strategy<Value = Body> {
        (
            prop_oneof![
                positive().prop_map(|radius| Shape::Sphere { radius }),
                (positive(), positive())
                    .prop_map(|(radius, length)| Shape::Cylinder { radius, length }),
                Just(Shape::Plane),
            ],
            material(),
            prop::option::of(positive()),
        )
            .prop_map(|(shape, material, mass)| Body {
                shape,
                material,
                mass,
            })
    }

    proptest! {
        /// Any scene the writer is given reads back identically: every f64 to the last bit.
        #[test]
        fn any_scene_reads_back_identically(
            name in "\\PC{0,30}",
            body1 in body(),
            body2 in body(),
            v0 in positive(),
            e in 1e-9..=1.0f64,
            x_pl in prop_oneof![Just(0.0), positive()],
        ) {
            let scene = Scene {
                name,
                body1,
                body2,
                impact: ImpactConditions { v0, restitution: e, plastic_indentation: x_pl },
                assumed: Default::default(),
                fit: None,
            };
            let text = scene_file::to_toml(&scene, Some("round trip"));
            let doc = scene_file::Document::parse("written.toml", &text).unwrap();
            // Decoding validates: it reads back the scene if the scene is valid, else it refuses
            // it with the scene's own validation error.
            let decoded = scene_file::decode_scene(&doc, &BTreeMap::new());
            match scene.validate() {
                Ok(()) => prop_assert_eq!(decoded.unwrap(), scene),
                Err(invalid) => {
                    let message = decoded.unwrap_err().to_string();
                    prop_assert!(message.ends_with(&invalid.to_string()), "{}\n{}", message, text);
                }
            }
        }
    }
}

/// The table presets borrow Fig. 5's e and x_pl: they say so (`assumed`), a `--set` of either
/// makes it given, and a scene written back keeps what is still assumed.
#[test]
fn borrowed_values_are_assumed_until_given() {
    let registry = builtin();
    for info in registry.scenes() {
        let scene = registry.scene(&info.name).unwrap();
        let figure = info.name.starts_with("fig");
        assert_eq!(scene.assumed.restitution, !figure, "{}", info.name);
        assert_eq!(scene.assumed.plastic_indentation, !figure, "{}", info.name);
    }
    let set =
        |pairs: &[&str]| -> Vec<Override> { pairs.iter().map(|s| s.parse().unwrap()).collect() };
    let given_e = registry
        .scene_with("steel-sphere-r10-plate", &set(&["impact.restitution=0.7"]))
        .unwrap();
    assert!(!given_e.assumed.restitution);
    assert!(given_e.assumed.plastic_indentation);
    // Written back and read again: the assumed list survives, the given e is given.
    let text = scene_file::to_toml(&given_e, None);
    assert!(
        text.contains("assumed = [\"plastic_indentation\"]"),
        "{text}"
    );
    let read = parse_scene("written.toml", &text, registry.material_catalog()).unwrap();
    assert_eq!(read.assumed, given_e.assumed);
    // A key that is not e or x_pl is refused by name and line.
    let bad = text.replace("[\"plastic_indentation\"]", "[\"v0\"]");
    let err = parse_scene("bad.toml", &bad, registry.material_catalog()).unwrap_err();
    assert!(
        err.to_string().contains(
            "`impact.assumed` must be a list of \"restitution\" and \"plastic_indentation\""
        ),
        "{err}"
    );
}

/// An edited scene is not "…on steel plate": `--set` of a body renames it by its bodies, and a
/// `--set name=…` wins.
#[test]
fn an_edited_scene_is_named_by_its_bodies() {
    let registry = builtin();
    let set =
        |pairs: &[&str]| -> Vec<Override> { pairs.iter().map(|s| s.parse().unwrap()).collect() };
    let edited = registry
        .scene_with(DEFAULT_SCENE, &set(&["body2.material=aluminium-alloy"]))
        .unwrap();
    assert_eq!(
        edited.name,
        "Steel sphere R = 10 mm on aluminium-alloy plate"
    );
    let impact_only = registry
        .scene_with(DEFAULT_SCENE, &set(&["impact.v0=1"]))
        .unwrap();
    assert_eq!(impact_only.name, "Steel sphere R = 10 mm on steel plate");
    let named = registry
        .scene_with(
            DEFAULT_SCENE,
            &set(&["body2.material=aluminium-alloy", "name=my impact"]),
        )
        .unwrap();
    assert_eq!(named.name, "my impact");
    // Without overrides the preset's own name.
    assert!(
        registry
            .scene(DEFAULT_SCENE)
            .unwrap()
            .name
            .starts_with("Fig. 5")
    );
}
