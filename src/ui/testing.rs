//! Fixtures shared by the unit tests of the UI.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Color, Modifier, Style};

use crate::model::scene::Scene;

/// The paper's Fig. 5 scene: a steel sphere R = 10 mm on a steel plate, v₀ = 0.3 m/s, e = 0.6,
/// x_pl = 2.3 µm.
pub fn fig5_scene() -> Scene {
    Scene {
        name: "fig5".into(),
        ..crate::model::scene::tests::fig5_scene()
    }
}

pub(crate) use crate::model::scene::tests::fig5_params;

/// A buffer whose every cell already holds a symbol, most of them styled, so that what is drawn
/// into it shows which cells it sets and restyles.
pub fn busy_buffer(area: Rect) -> Buffer {
    let mut buf = Buffer::empty(area);
    for (i, cell) in buf.content.iter_mut().enumerate() {
        cell.set_char(char::from(b'a' + (i % 26) as u8));
        match i % 4 {
            0 => cell.set_style(Style::new().fg(Color::Yellow).bg(Color::Blue)),
            1 => cell.set_style(Style::new().add_modifier(Modifier::BOLD | Modifier::ITALIC)),
            2 => cell.set_style(Style::new().fg(Color::Indexed(99))),
            _ => cell,
        };
    }
    buf
}
