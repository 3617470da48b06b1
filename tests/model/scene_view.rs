//! Scenes carry their view: `models = [...]` (checked, the first focused) and `[solver]` in a scene
//! file, read strictly (refusals located at file:line), defaulted, and written back on save.

use std::path::PathBuf;

use hertz_tui::model::ForceModel;
use hertz_tui::model::force::UnknownModel;
use hertz_tui::model::impact::{MethodChoice, SolveOptions};
use hertz_tui::model::ode::Method;
use hertz_tui::model::presets::{Registry, SaveTarget};
use hertz_tui::model::scene_file::{
    Document, PAPER_MODELS, Problem, SceneView, ValueIssue, decode_view, parse_scene,
};

use crate::scratch;

/// A valid scene file without a view; tests add lines after line 1 (so `models` is on line 2).
const SCENE: &str = r#"name = "view test"
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

fn with_models(models_line: &str, solver: &str) -> String {
    let (first, rest) = SCENE.split_once('\n').unwrap();
    format!("{first}\n{models_line}\n{rest}{solver}")
}

fn view_of(text: &str) -> Result<SceneView, String> {
    let registry = Registry::builtin().unwrap();
    // The strict scene reader refuses a bad view as well as the view reader does.
    let scene = parse_scene("test.toml", text, registry.material_catalog());
    let view = Document::parse("test.toml", text)
        .and_then(|doc| decode_view(&doc))
        .map_err(|e| e.to_string());
    match (scene, &view) {
        (Ok(_), Ok(_)) => {}
        (Err(scene), Err(view)) => assert_eq!(&scene.to_string(), view),
        (scene, view) => panic!("scene {scene:?} and view {view:?} disagree"),
    }
    view
}

#[test]
fn figure_presets_open_as_the_paper_draws_them() {
    let registry = Registry::builtin().unwrap();
    let fig4 = registry.scene_view("fig4-steel-sphere-r10-plate").unwrap();
    assert_eq!(
        fig4.models,
        [ForceModel::DryFriction, ForceModel::Quasistatic],
        "Fig. 4: dry friction focused, the elastic part drawn with it"
    );
    assert_eq!(fig4.focused(), ForceModel::DryFriction);
    let fig5 = registry.scene_view("fig5-steel-sphere-r10-plate").unwrap();
    assert_eq!(
        fig5.models,
        [
            ForceModel::Proposed,
            ForceModel::HuntCrossley,
            ForceModel::LankaraniNikravesh
        ]
    );
    assert_eq!(fig5.options.method, MethodChoice::Auto);
    // A scene without the keys: the paper's five, default solver settings.
    let table = registry.scene_view("steel-sphere-r5-plate").unwrap();
    assert_eq!(table.models, PAPER_MODELS);
    assert_eq!(table.options, SolveOptions::default());
}

#[test]
fn every_model_id_reads_through_from_str() {
    for model in ForceModel::ALL {
        let text = with_models(&format!("models = [\"{}\"]", model.name()), "");
        assert_eq!(view_of(&text).unwrap().models, [model]);
    }
}

#[test]
fn solver_settings_read_as_on_the_command_line() {
    let text = with_models(
        "",
        "[solver]\nmethod = \"rk4\"\nrtol = 1e-6\natol = 1e-9\ndt = 2e-7\n",
    );
    let view = view_of(&text).unwrap();
    assert_eq!(view.options.method, MethodChoice::Integrator(Method::Rk4));
    assert_eq!(
        (view.options.rtol, view.options.atol, view.options.dt),
        (1e-6, Some(1e-9), Some(2e-7))
    );
    assert_eq!(view.options.max_steps, SolveOptions::default().max_steps);
}

#[test]
fn bad_views_are_refused_at_their_line() {
    let cases = [
        (
            with_models("models = [\"elastic\"]", ""),
            "test.toml:2:1: `models`: unknown model 'elastic' (expected one of: ",
        ),
        (
            with_models("models = [\"proposed\", \"proposed\"]", ""),
            "test.toml:2:1: `models`: \"proposed\" is listed twice",
        ),
        (
            with_models("models = []", ""),
            "test.toml:2:1: `models`: lists no model",
        ),
        (
            with_models("models = \"proposed\"", ""),
            "test.toml:2:1: `models` must be an array of model names, found string \"proposed\"",
        ),
        (
            with_models("", "[solver]\nrtol = 2\n"),
            "test.toml:15:1: `solver.rtol`: must be > 0 and < 1, got 2",
        ),
        (
            with_models("", "[solver]\nmethod = \"magic\"\n"),
            "test.toml:15:1: `solver.method`: unknown method",
        ),
        (
            with_models("", "[solver]\ndt = -1e-6\n"),
            "test.toml:15:1: `solver.dt`: must be > 0 and finite (s), got -0.000001",
        ),
        (
            with_models("", "[solver]\nstep = 1e-6\n"),
            "test.toml:15:1: unknown key `solver.step` (allowed here: method, rtol, atol, dt)",
        ),
    ];
    for (text, want) in cases {
        let got = view_of(&text).unwrap_err();
        assert!(got.starts_with(want), "got {got}\nwant {want}…");
    }
}

#[test]
fn bad_view_values_carry_what_was_given() {
    let issue = |text: &str| {
        let err = Document::parse("test.toml", text)
            .and_then(|doc| decode_view(&doc))
            .unwrap_err();
        match err.problem {
            Problem::BadValue { key, issue } => (key, issue),
            other => panic!("{other:?}"),
        }
    };
    assert_eq!(
        issue(&with_models("", "[solver]\nrtol = 2\n")),
        (
            "solver.rtol".to_string(),
            ValueIssue::OutOfRange {
                requirement: "> 0 and < 1",
                value: 2.0
            }
        )
    );
    assert_eq!(
        issue(&with_models("models = [\"proposed\", \"proposed\"]", "")),
        (
            "models".to_string(),
            ValueIssue::ListedTwice("proposed".into())
        )
    );
    assert_eq!(
        issue(&with_models("models = [\"elastic\"]", "")),
        (
            "models".to_string(),
            ValueIssue::UnknownModel(UnknownModel("elastic".into()))
        )
    );
}

#[test]
fn saving_writes_the_view_back() {
    let dir = scratch::folder("view");
    let registry = Registry::load_from(Some(&dir)).unwrap();
    let scene = registry.scene("fig4-steel-sphere-r10-plate").unwrap();
    let view = SceneView {
        models: vec![ForceModel::HuntCrossley, ForceModel::DryFriction],
        options: SolveOptions {
            method: MethodChoice::Integrator(Method::Verlet),
            rtol: 1e-5,
            atol: Some(1e-11),
            dt: Some(1.25e-7),
            ..SolveOptions::default()
        },
    };
    let file: PathBuf = dir.join("saved.toml");
    registry
        .save_scene_with_view(&scene, Some("kept"), &view, None, SaveTarget::Path(&file))
        .unwrap();
    let path = file.to_str().unwrap();
    let (scene_back, view_back) = (registry.scene(path), registry.scene_view(path));
    let description = registry.scene_description(path);
    assert_eq!(scene_back.unwrap(), scene);
    assert_eq!(view_back.unwrap(), view);
    assert_eq!(description.unwrap().as_deref(), Some("kept"));
}
