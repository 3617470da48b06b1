//! The `[system]` table: presets, round trips, and errors that name the key.

use hertz_tui::model::overrides::Override;
use hertz_tui::model::presets::{Registry, SaveTarget};
use hertz_tui::model::scene_file::{self, Document, decode_system, parse_scene};
use hertz_tui::model::system::{
    Contact, Damping, Forcing, RunOptions, SystemKind, SystemModel, SystemSpec, simulate,
};

use crate::scratch;
use crate::systems_common::bouncing_ball_preset;

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
    let (scene, spec) = bouncing_ball_preset();
    let g = spec.groups(scene.body1.mass());
    let omega = 2.0 * std::f64::consts::PI * 20.0;
    assert!((g.gamma.unwrap() - 0.001 * omega * omega / 9.80665).abs() < 1e-12);
    let registry = Registry::builtin().unwrap();
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
fn set_overrides_take_each_keys_unit_and_a_wrong_unit_names_the_key() {
    let registry = Registry::builtin().unwrap();
    let system = |preset: &str, sets: &[&str]| {
        let overrides: Vec<Override> = sets.iter().map(|s| s.parse().unwrap()).collect();
        registry
            .scene_system(preset, &overrides)
            .map(|s| s.unwrap())
            .map_err(|e| e.to_string())
    };
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-15 * b.abs();
    // Units and prefixes give the SI value a bare number gives.
    let ball = system(
        "bouncing-ball",
        &[
            "system.frequency=25Hz",
            "system.amplitude=0.8 mm",
            "system.gravity=9.81 m/s^2",
        ],
    )
    .unwrap();
    let SystemKind::BouncingBall {
        amplitude,
        frequency,
        gravity,
    } = ball.kind
    else {
        panic!("{ball:?}");
    };
    assert!(close(amplitude, 0.0008) && frequency == 25.0 && gravity == 9.81);
    let oscillator = system(
        "impact-oscillator",
        &[
            "system.gap=0.5 mm",
            "system.stiffness=1e4 N/m",
            "system.forcing_amplitude=50 mN",
            "system.frequency=0.012 kHz",
        ],
    )
    .unwrap();
    let SystemKind::ImpactOscillator {
        gap,
        stiffness,
        forcing,
        frequency,
        ..
    } = oscillator.kind
    else {
        panic!("{oscillator:?}");
    };
    assert!(close(gap, 0.0005) && stiffness == 1e4 && close(frequency, 12.0));
    assert!(matches!(forcing, Forcing::Force { amplitude } if close(amplitude, 0.05)));
    // The forcing amplitude is a length for a base motion, whichever of the two is set first.
    for sets in [
        ["system.forcing=base", "system.forcing_amplitude=0.2 mm"],
        ["system.forcing_amplitude=0.2 mm", "system.forcing=base"],
    ] {
        let spec = system("impact-oscillator", &sets).unwrap();
        assert!(
            matches!(spec.kind, SystemKind::ImpactOscillator { forcing: Forcing::Base { amplitude }, .. } if close(amplitude, 0.0002)),
            "{sets:?}: {spec:?}"
        );
    }
    // A unit that is not the key's: refused, naming the key and the units it takes.
    for (preset, set, key, expected) in [
        (
            "bouncing-ball",
            "system.frequency=20 kg",
            "system.frequency",
            "Hz",
        ),
        (
            "bouncing-ball",
            "system.amplitude=1 N",
            "system.amplitude",
            "expected m",
        ),
        (
            "impact-oscillator",
            "system.stiffness=1 N",
            "system.stiffness",
            "N/m",
        ),
        (
            "impact-oscillator",
            "system.forcing_amplitude=1 mm",
            "system.forcing_amplitude",
            "base",
        ),
        (
            "impact-oscillator",
            "system.damping_ratio=0.1 s",
            "system.damping_ratio",
            "no unit",
        ),
    ] {
        let e = system(preset, &[set]).unwrap_err();
        assert!(
            e.starts_with(&format!("--set {key}: ")) && e.contains(expected),
            "{set}: {e}"
        );
    }
    let e = system("bouncing-ball", &["system.frequency=fast"]).unwrap_err();
    assert!(
        e.starts_with("--set system.frequency: \"fast\" is not a number"),
        "{e}"
    );
}

#[test]
fn a_system_scene_saved_with_its_table_reads_back_the_same() {
    let registry = Registry::builtin().unwrap();
    let dir = scratch::folder("system-save");
    for name in PRESETS {
        let scene = registry.scene(name).unwrap();
        let view = registry.scene_view(name).unwrap();
        let overrides: Vec<Override> = ["system.gap=0.7 mm", "system.frequency=9.3 Hz"]
            .iter()
            .map(|s| s.parse().unwrap())
            .collect();
        let system = registry.scene_system(name, &[]).unwrap().unwrap();
        let edited = if name == "bouncing-ball" {
            &overrides[1..]
        } else {
            &overrides[..]
        };
        let (scene, system) = registry
            .apply_overrides_with_system(&scene, Some(&system), edited)
            .unwrap();
        let system = system.unwrap();
        assert_ne!(
            Some(system),
            registry.scene_system(name, &[]).unwrap(),
            "{name}"
        );
        let file = dir.join(format!("{name}.toml"));
        registry
            .save_scene_with_view(&scene, None, &view, Some(&system), SaveTarget::Path(&file))
            .unwrap();
        let path = file.to_str().unwrap();
        assert_eq!(
            registry.scene_system(path, &[]).unwrap(),
            Some(system),
            "{name}"
        );
        assert_eq!(registry.scene(path).unwrap(), scene, "{name}");
    }
    // A table that would not read back is refused, and nothing is written.
    let scene = registry.scene("bouncing-ball").unwrap();
    let view = registry.scene_view("bouncing-ball").unwrap();
    let mut bad = registry
        .scene_system("bouncing-ball", &[])
        .unwrap()
        .unwrap();
    if let SystemKind::BouncingBall { frequency, .. } = &mut bad.kind {
        *frequency = -1.0;
    }
    let file = dir.join("bad.toml");
    let e = registry
        .save_scene_with_view(&scene, None, &view, Some(&bad), SaveTarget::Path(&file))
        .unwrap_err()
        .to_string();
    assert!(e.contains("system.frequency"), "{e}");
    assert!(!file.exists());
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
