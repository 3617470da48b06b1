//! The `[system]` table: presets, round trips, and errors that name the key.

use hertz_tui::model::overrides::Override;
use hertz_tui::model::presets::Registry;
use hertz_tui::model::scene_file::{self, Document, decode_system, parse_scene};
use hertz_tui::model::system::{
    Contact, Damping, Forcing, RunOptions, SystemKind, SystemModel, SystemSpec, simulate,
};

const PRESETS: [&str; 3] = [
    "bouncing-ball",
    "impact-oscillator",
    "impact-oscillator-clearance",
];

fn system_of(text: &str) -> Result<Option<SystemSpec>, String> {
    let doc = Document::parse("s.toml", text).map_err(|e| e.to_string())?;
    let registry = Registry::builtin().unwrap();
    scene_file::decode_scene(&doc, registry.material_catalog()).map_err(|e| e.to_string())?;
    decode_system(&doc).map_err(|e| e.to_string())
}

const BODIES: &str = r#"name = "t"
[body1]
shape = "sphere"
radius = 0.01
material = "steel"
[body2]
shape = "plane"
material = "steel"
[impact]
v0 = 0.1
restitution = 0.5
plastic_indentation = 0.0
"#;

#[test]
fn presets_load_simulate_and_round_trip() {
    let registry = Registry::builtin().unwrap();
    for name in PRESETS {
        let scene = registry.scene(name).unwrap();
        let spec = registry
            .scene_system(name, &[])
            .unwrap()
            .expect("a system preset");
        let model = SystemModel::from_scene(&scene, &spec).unwrap();
        let options = RunOptions {
            transient_impacts: 50,
            recorded_impacts: 20,
            ..RunOptions::default()
        };
        let h = simulate(&model, &Contact::rigid(model.restitution), &options).unwrap();
        assert_eq!(h.impacts.len(), 20, "{name} impacts");
        // Each rigid impact carries the Hertz estimate of its peak force at its own speed
        // (eqs 5–6): the scene's quasistatic estimate at v₀ = v_in.
        for i in h.impacts.iter().filter(|i| i.v_in > 0.0) {
            let mut at = scene.clone();
            at.impact.v0 = i.v_in;
            let f_max = at.quasistatic().unwrap().f_max;
            assert_eq!(i.peak_force_estimate, Some(f_max), "{name}");
        }
        // Written back and read again: the same scene and the same system.
        let text = scene_file::to_toml_with_system(&scene, None, None, Some(&spec));
        let doc = Document::parse("again", &text).unwrap();
        assert_eq!(decode_system(&doc).unwrap(), Some(spec), "{name}:\n{text}");
        assert_eq!(
            parse_scene("again", &text, registry.material_catalog()).unwrap(),
            scene
        );
    }
}

#[test]
fn groups_are_the_dimensionless_numbers() {
    let registry = Registry::builtin().unwrap();
    let scene = registry.scene("bouncing-ball").unwrap();
    let spec = registry
        .scene_system("bouncing-ball", &[])
        .unwrap()
        .unwrap();
    let g = spec.groups(scene.body1.mass());
    let omega = 2.0 * std::f64::consts::PI * 20.0;
    assert!((g.gamma.unwrap() - 0.001 * omega * omega / 9.80665).abs() < 1e-12);
    let spec = registry
        .scene_system("impact-oscillator", &[])
        .unwrap()
        .unwrap();
    let m = registry.scene("impact-oscillator").unwrap().body1.mass();
    let g = spec.groups(m);
    let omega0 = (129.0 / m).sqrt();
    assert!((g.frequency_ratio.unwrap() - 2.0 * std::f64::consts::PI * 9.0 / omega0).abs() < 1e-12);
    assert_eq!(g.damping_ratio, Some(0.05));
    assert!((g.gap_ratio.unwrap() - 0.0005 / (0.05 / 129.0)).abs() < 1e-12);
}

#[test]
fn every_spelling_round_trips() {
    let specs = [
        SystemKind::ImpactOscillator {
            stiffness: 1e3,
            damping: Damping::Coefficient(0.1),
            forcing: Forcing::Base { amplitude: 1e-4 },
            frequency: 3.3,
            gap: 1e-3,
            second_gap: Some(2e-3),
        },
        SystemKind::BouncingBall {
            amplitude: 1.234_567_890_123e-4,
            frequency: 1.0 / 7.0,
            gravity: 1.62,
        },
    ];
    for kind in specs {
        let spec = SystemSpec { kind };
        let text = format!("{BODIES}\n{}", scene_file::system_table(&spec));
        assert_eq!(system_of(&text).unwrap(), Some(spec), "{text}");
    }
}

#[test]
fn errors_name_the_key_and_line() {
    let cases = [
        (
            "kind = \"impact-oscillator\"\nstiffness = 1.0\ndamping_ratio = 0.1\nforcing = \"force\"\nforcing_amplitude = 1.0\nfrequency = 1.0\ngap = 0.0\n",
            "system.gap must be > 0",
            21,
        ),
        (
            "kind = \"impact-oscillator\"\nstiffness = 1.0\ndamping_ratio = 0.1\nforcing = \"force\"\nforcing_amplitude = 1.0\nfrequency = 1.0\ngap = 0.1\nsecond_gap = -0.1\n",
            "system.second_gap must be > 0",
            22,
        ),
        (
            "kind = \"bouncing-ball\"\namplitude = 0.001\nfrequency = 0.0\n",
            "system.frequency must be a finite number > 0",
            17,
        ),
        (
            "kind = \"bouncing-ball\"\namplitude = 0.001\nfrequency = -5\n",
            "system.frequency must be a finite number > 0",
            17,
        ),
        (
            "kind = \"bouncing-ball\"\namplitude = 0.001\n",
            "missing key `system.frequency`",
            14,
        ),
        (
            "kind = \"bouncing-ball\"\namplitude = 0.001\nfrequency = 20.0\ngap = 1.0\n",
            "unknown key `system.gap`",
            18,
        ),
        ("kind = \"pendulum\"\n", "unknown value \"pendulum\"", 15),
        (
            "kind = \"impact-oscillator\"\nstiffness = 1.0\nforcing = \"force\"\nforcing_amplitude = 1.0\nfrequency = 1.0\ngap = 0.1\n",
            "missing key `system.damping_ratio`",
            14,
        ),
        (
            "kind = \"impact-oscillator\"\nstiffness = 1.0\ndamping_ratio = 0.1\ndamping = 1.0\nforcing = \"force\"\nforcing_amplitude = 1.0\nfrequency = 1.0\ngap = 0.1\n",
            "give damping_ratio or damping, not both",
            18,
        ),
        (
            "kind = \"impact-oscillator\"\nstiffness = 1.0\ndamping_ratio = 1.5\nforcing = \"force\"\nforcing_amplitude = 1.0\nfrequency = 1.0\ngap = 0.1\n",
            "system.damping_ratio must be in [0, 1)",
            17,
        ),
        (
            "kind = \"impact-oscillator\"\nstiffness = 1.0\ndamping_ratio = 0.1\nforcing = \"push\"\nforcing_amplitude = 1.0\nfrequency = 1.0\ngap = 0.1\n",
            "unknown value \"push\"",
            18,
        ),
    ];
    for (table, message, line) in cases {
        let text = format!("{BODIES}\n[system]\n{table}");
        let err = system_of(&text).unwrap_err();
        assert!(err.contains(message), "{err}\n--- for ---\n{text}");
        assert!(
            err.starts_with(&format!("s.toml:{line}:")),
            "{err} (expected line {line})"
        );
    }
}

#[test]
fn set_overrides_reach_the_system() {
    let registry = Registry::builtin().unwrap();
    let set = |key: &str, value: &str| Override {
        key: key.into(),
        value: value.into(),
    };
    let spec = registry
        .scene_system("impact-oscillator", &[set("system.gap", "0.002")])
        .unwrap()
        .unwrap();
    assert!(matches!(spec.kind, SystemKind::ImpactOscillator { gap, .. } if gap == 0.002));
    let err = registry
        .scene_system("impact-oscillator", &[set("system.gap", "-1")])
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("--set system.gap") && err.contains("system.gap must be > 0"),
        "{err}"
    );
    // The scene itself refuses a bad system too, wherever it is read.
    assert!(
        registry
            .scene_with("bouncing-ball", &[set("system.frequency", "0")])
            .is_err()
    );
}

#[test]
fn a_plane_cannot_be_the_moving_body() {
    let registry = Registry::builtin().unwrap();
    let mut scene = registry.scene("bouncing-ball").unwrap();
    std::mem::swap(&mut scene.body1, &mut scene.body2);
    let spec = registry
        .scene_system("bouncing-ball", &[])
        .unwrap()
        .unwrap();
    let err = SystemModel::from_scene(&scene, &spec)
        .unwrap_err()
        .to_string();
    assert!(err.contains("body1.mass"), "{err}");
}
