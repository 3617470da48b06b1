//! Every character of text the explorer draws reads at 4.5:1 or more (WCAG 2 AA) on its theme's
//! background: each view, the help and an invalid field, at 80×24 and 160×48, on the dark and
//! light themes and without colour (on both backgrounds). Colours are taken at xterm's values
//! (`hertz_tui::ui::style::contrast`); chart dots, box drawing and block elements are lines, not
//! text, and are left out.

use hertz_tui::ui::MarkerStyle;
use hertz_tui::ui::action::Action;
use hertz_tui::ui::app::App;
use hertz_tui::ui::style::Theme;
use hertz_tui::ui::style::contrast::{Surface, of_text};
use hertz_tui::ui::tab::Tab;
use hertz_tui::ui::update::update;
use ratatui::buffer::Buffer;

use super::render::{app_with, invalid_app, render, settle};

/// Braille, box drawing, block elements and the chart's bullet: lines and marks, not text.
fn is_text(symbol: &str) -> bool {
    symbol.chars().any(|c| {
        !c.is_whitespace()
            && !('\u{2500}'..='\u{259f}').contains(&c)
            && !('\u{2800}'..='\u{28ff}').contains(&c)
            && c != '●'
    })
}

fn surfaces(theme: Theme) -> &'static [Surface] {
    match theme {
        Theme::Dark => &[Surface::DARK],
        Theme::Light => &[Surface::LIGHT],
        Theme::Plain => &[Surface::DARK, Surface::LIGHT],
    }
}

/// The text cells of `buffer` under 4.5:1, one line each (the first few).
fn low_contrast(buffer: &Buffer, theme: Theme, what: &str) -> Vec<String> {
    let mut low = Vec::new();
    for &surface in surfaces(theme) {
        for position in buffer.area.positions() {
            let cell = &buffer[position];
            if !is_text(cell.symbol()) {
                continue;
            }
            let c = of_text(cell.fg, cell.bg, cell.modifier, surface);
            if c < 4.5 {
                low.push(format!(
                    "{theme:?} {what} ({}, {}) {:?} {:?} {:?}: {c:.2}:1",
                    position.x,
                    position.y,
                    cell.symbol(),
                    cell.fg,
                    cell.modifier
                ));
            }
        }
    }
    low
}

#[test]
fn every_text_cell_of_every_view_reads_at_4_5_to_1() {
    let mut low = Vec::new();
    for theme in Theme::ALL {
        let mut app: App = app_with(MarkerStyle::Braille, theme);
        for (w, h) in [(80, 24), (160, 48)] {
            update(&mut app, Action::Resize(w, h));
            for tab in Tab::all() {
                update(&mut app, Action::Tab(tab));
                settle(&mut app);
                let terminal = render(&app, w, h);
                let what = format!("{} {w}x{h}", tab.name());
                low.extend(low_contrast(terminal.backend().buffer(), theme, &what));
            }
            update(&mut app, Action::Tab(Tab::HOME));
            update(&mut app, Action::Help);
            let terminal = render(&app, w, h);
            low.extend(low_contrast(terminal.backend().buffer(), theme, "help"));
            update(&mut app, Action::Cancel);
        }
        let mut invalid = invalid_app();
        invalid.theme = theme;
        let terminal = render(&invalid, 160, 48);
        low.extend(low_contrast(terminal.backend().buffer(), theme, "invalid"));
    }
    let shown: Vec<&String> = low.iter().take(20).collect();
    assert!(
        low.is_empty(),
        "{} cells under 4.5:1:\n{shown:#?}",
        low.len()
    );
}
