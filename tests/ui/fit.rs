//! The fit view rendered into ratatui's TestBackend.

use hertz_tui::ui::action::Action;
use hertz_tui::ui::app::App;
use hertz_tui::ui::tab::Tab;
use hertz_tui::ui::update::update;

use super::render::{app, render, settle, text};

fn screen(app: &App, width: u16, height: u16) -> String {
    text(render(app, width, height).backend().buffer())
}

fn on_fit(path: Option<&str>, (w, h): (u16, u16)) -> App {
    let mut app = app();
    update(&mut app, Action::Resize(w, h));
    if let Some(path) = path {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
        let _ = root;
        hertz_tui::ui::views::fit::open(&mut app, std::path::Path::new(path));
    }
    update(&mut app, Action::Tab(Tab::named("fit").unwrap()));
    settle(&mut app);
    app
}

#[test]
fn show() {
    for size in [(80, 24), (160, 48)] {
        let app = on_fit(Some("presets/data/steel-hunt-crossley.csv"), size);
        println!("{}", screen(&app, size.0, size.1));
    }
    let app = on_fit(None, (80, 24));
    println!("{}", screen(&app, 80, 24));
}
