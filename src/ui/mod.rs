//! The terminal explorer (ratatui + crossterm) over the model layer.
//!
//! [`app`] holds the state and [`update`] its transitions, `update(&mut App, Action)`; [`keymap`]
//! turns keys into actions; [`render`] draws the screen from `&App`: the tab bar, the shown view
//! and the status line. Each tab is a folder of [`views`] (its keys, panes and charts) registered
//! in [`views::VIEWS`]; the panes they share are in [`widgets`], the looks in [`style`].
//! The solves ([`worker`]) and the [`studies`] of the study views run off the UI thread, each on a
//! [`jobs`] queue of its own; `runtime` ties them to the terminal. The UI holds no physics:
//! every number comes from `crate::model`.

pub mod action;
pub mod app;
#[cfg(test)]
mod app_daily_tests;
#[cfg(test)]
mod app_tab_tests;
#[cfg(test)]
mod app_tests;
#[cfg(test)]
mod app_trap_tests;
pub mod config;
pub mod data_cursor;
mod edited;
mod escapes;
pub mod export;
pub mod field;
pub mod figure_export;
pub mod frames;
pub mod jobs;
pub mod keymap;
pub mod layout;
mod mouse;
pub mod onscreen;
pub mod picker;
pub mod rebind;
pub mod render;
mod runtime;
pub mod solutions;
pub mod studies;
pub mod style;
pub mod tab;
#[cfg(test)]
mod testing;
pub mod update;
pub mod views;
pub mod widgets;
pub mod worker;

/// The engine panel's state (`t`: a simulation engine's parameters for the scene).
pub mod engine_panel;
pub mod osc52;

pub use style::MarkerStyle;

use color_eyre::eyre::WrapErr;

use crate::model::Scene;
use crate::model::overrides::Override;
use crate::model::presets::{PresetError, Registry};
use crate::model::scene_file::SceneView;
use crate::model::system::SystemSpec;

use app::App;
use config::Config;
use style::Theme;

/// What the explorer opens: a scene, its `[system]` table and its view (checked models, solver
/// settings).
#[derive(Debug, Clone)]
pub struct Opened {
    pub scene: Scene,
    pub system: Option<SystemSpec>,
    pub view: SceneView,
}

impl Opened {
    /// The scene preset or scene file `source` with `overrides` (`--set`, `system.*` included)
    /// applied; a bad table or override is an error naming its key.
    pub fn read(
        registry: &Registry,
        source: &str,
        overrides: &[Override],
    ) -> Result<Opened, PresetError> {
        Ok(Opened {
            scene: registry.scene_with(source, overrides)?,
            system: registry.scene_system(source, overrides)?,
            view: registry.scene_view(source)?,
        })
    }
}

/// Opens the explorer on the scene read from `source` (a preset name or a path), as `view` asks
/// (checked models, solver settings), and runs it until the user quits; the terminal is restored on
/// every exit path (errors and panics included: `ratatui::try_init` installs a panic hook that
/// restores the terminal before the previously installed color-eyre hook reports).
/// `config` (the user's config file) chooses the theme where it names one, and moves keys; with
/// `data` the explorer opens on the fit view with that file loaded.
pub fn run(
    opened: Opened,
    source: &str,
    data: Option<&std::path::Path>,
    marker: MarkerStyle,
    config: Config,
) -> color_eyre::Result<()> {
    let Opened {
        scene,
        system,
        view,
    } = opened;
    let registry = Registry::load()
        .or_else(|_| Registry::builtin())
        .wrap_err("cannot load the presets")?;
    // A scene file's description is kept on save, as a preset's is.
    let description = registry.scene_description(source).ok().flatten();
    // Overrides given on the command line: the description says what they edited, `system.*`
    // included.
    let description = match registry.scene(source) {
        Ok(original) => {
            let loaded = registry.scene_system(source, &[]).ok().flatten();
            let original = (&original, loaded.as_ref());
            let edited = (&scene, system.as_ref());
            app::retitled_with_system(original, description.as_deref(), edited).1
        }
        Err(_) => description,
    };
    let theme = config.theme_or(Theme::from_env);
    rebind::install(config.keys);
    let mut app = App::open_system(scene, system, view, registry, marker, theme);
    if app.description.is_none() {
        app.description = description;
    }
    // `--data FILE`: the fit view opens on it (a refused file shows its error there).
    if let Some(path) = data {
        views::fit::open(&mut app, path);
        app.tab = tab::Tab::named("fit").unwrap_or(tab::Tab::HOME);
    }
    // ratatui sets the terminal up: raw mode, the alternate screen, a panic hook that restores
    // both.
    let mut terminal = match ratatui::try_init() {
        Ok(terminal) => terminal,
        Err(e) => {
            ratatui::restore();
            return Err(e).wrap_err("cannot set up the terminal");
        }
    };
    // A panic must not leave the terminal sending mouse reports and paste marks to the shell.
    let restore = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        runtime::release_terminal_modes();
        restore(info);
    }));
    let result = runtime::event_loop(&mut terminal, app);
    ratatui::restore();
    result
}
