//! The terminal explorer (ratatui + crossterm) over the model layer.

mod marker;

pub use marker::MarkerStyle;

use crate::model::Scene;

/// Opens the explorer on `scene` and runs it until the user quits; the terminal is restored on
/// every exit path (errors and panics included).
pub fn run(scene: Scene, marker: MarkerStyle) -> color_eyre::Result<()> {
    let mut terminal = ratatui::try_init()?;
    let result = (|| -> color_eyre::Result<()> {
        loop {
            terminal.draw(|frame| {
                let text = format!("{} ({marker:?}) — press q to quit", scene.name);
                frame.render_widget(ratatui::widgets::Paragraph::new(text), frame.area());
            })?;
            if let ratatui::crossterm::event::Event::Key(key) = ratatui::crossterm::event::read()?
                && key.code == ratatui::crossterm::event::KeyCode::Char('q')
            {
                return Ok(());
            }
        }
    })();
    ratatui::restore();
    result
}
