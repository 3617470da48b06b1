//! Colours (16-colour palette only) and the one place text styles are chosen; `NO_COLOR` turns
//! colour off. Text is the terminal's own foreground, muted by DIM, never a fixed grey: both stay
//! legible on dark and light backgrounds. Curves take the six ANSI hues (not their bright
//! variants, which fade on white) and the foreground.

use ratatui::style::{Color, Modifier, Style};

use crate::chart::{Hue, Ink};
use crate::model::ForceModel;
use crate::model::ode::Method;

/// A four-cell legend sample of a curve: its line with its glyph, the glyph the chart puts at the
/// curve's peak and end (and along it without colour).
pub fn sample(glyph: char) -> String {
    format!("─{glyph}──")
}

/// The ANSI colour of a hue.
fn color_of(hue: Hue) -> Color {
    match hue {
        Hue::Foreground => Color::Reset,
        Hue::Red => Color::Red,
        Hue::Green => Color::Green,
        Hue::Yellow => Color::Yellow,
        Hue::Blue => Color::Blue,
        Hue::Magenta => Color::Magenta,
        Hue::Cyan => Color::Cyan,
    }
}

/// What a piece of text is, for styling.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Role {
    Normal,
    Title,
    Label,
    Muted,
    /// The row under the cursor.
    Cursor,
    Error,
    Good,
    Warning,
    /// Key names in hints.
    Key,
}

/// The palette: 16 ANSI colours, or none at all under `NO_COLOR`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Theme {
    pub color: bool,
}

impl Theme {
    /// Colour unless `NO_COLOR` is set to a non-empty value (<https://no-color.org>).
    pub fn from_env() -> Theme {
        Theme::from_no_color(std::env::var_os("NO_COLOR"))
    }

    pub fn from_no_color(value: Option<std::ffi::OsString>) -> Theme {
        Theme {
            color: value.is_none_or(|v| v.is_empty()),
        }
    }

    pub fn style(self, role: Role) -> Style {
        let base = Style::default();
        if !self.color {
            return match role {
                Role::Title | Role::Key => base.add_modifier(Modifier::BOLD),
                Role::Cursor => base.add_modifier(Modifier::REVERSED),
                Role::Error => base.add_modifier(Modifier::BOLD | Modifier::UNDERLINED),
                Role::Muted => base.add_modifier(Modifier::DIM),
                Role::Normal | Role::Label | Role::Good | Role::Warning => base,
            };
        }
        match role {
            Role::Normal => base,
            Role::Title => base.fg(Color::Cyan).add_modifier(Modifier::BOLD),
            Role::Label => base,
            Role::Muted => base.add_modifier(Modifier::DIM),
            Role::Cursor => base.add_modifier(Modifier::REVERSED),
            Role::Error => base.fg(Color::Red).add_modifier(Modifier::BOLD),
            Role::Good => base.fg(Color::Green),
            Role::Warning => base.fg(Color::Yellow),
            Role::Key => base.fg(Color::Cyan).add_modifier(Modifier::BOLD),
        }
    }

    /// The colour of a model's curve and legend entry.
    pub fn model_color(self, model: ForceModel) -> Color {
        if !self.color {
            return Color::Reset;
        }
        color_of(Ink::Model(model).hue())
    }

    pub fn model_style(self, model: ForceModel) -> Style {
        Style::default().fg(self.model_color(model))
    }

    /// The colour of an integration method's line.
    pub fn method_color(self, method: Method) -> Color {
        if !self.color {
            return Color::Reset;
        }
        color_of(Ink::Method(method).hue())
    }

    pub fn method_style(self, method: Method) -> Style {
        Style::default().fg(self.method_color(method))
    }

    /// The style of a chart's ink.
    pub fn ink(self, ink: Ink) -> Style {
        match ink {
            Ink::Foreground => Style::default(),
            Ink::Model(m) => self.model_style(m),
            Ink::Method(m) => self.method_style(m),
            Ink::Warning => self.style(Role::Warning),
            Ink::Error => self.style(Role::Error).remove_modifier(Modifier::BOLD),
            Ink::Plain(hue) if self.color => Style::default().fg(color_of(hue)),
            Ink::Plain(_) => Style::default(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn no_color_is_honoured_only_when_non_empty() {
        assert!(Theme::from_no_color(None).color);
        assert!(Theme::from_no_color(Some("".into())).color);
        let plain = Theme::from_no_color(Some("1".into()));
        assert!(!plain.color);
        for role in [Role::Error, Role::Title, Role::Good, Role::Muted] {
            let s = plain.style(role);
            assert_eq!((s.fg, s.bg), (None, None), "{role:?}");
        }
        assert_eq!(plain.model_color(ForceModel::Proposed), Color::Reset);
    }

    /// Fixed greys and bright variants vanish on one background or the other.
    const FADING: [Color; 10] = [
        Color::Gray,
        Color::DarkGray,
        Color::White,
        Color::Black,
        Color::LightYellow,
        Color::LightCyan,
        Color::LightMagenta,
        Color::LightBlue,
        Color::LightGreen,
        Color::LightRed,
    ];

    #[test]
    fn models_differ_in_colour_and_no_colour_fades_on_light_or_dark() {
        let theme = Theme { color: true };
        // Each law's hue is on its row of the law table; the paper's five never share a colour,
        // and past them the glyph tells curves apart (model::force::table::LawStyle).
        for model in ForceModel::ALL {
            assert!(!FADING.contains(&theme.model_color(model)), "{model}");
        }
        let paper = [
            ForceModel::Quasistatic,
            ForceModel::DryFriction,
            ForceModel::Proposed,
            ForceModel::HuntCrossley,
            ForceModel::LankaraniNikravesh,
        ];
        for (i, a) in paper.iter().enumerate() {
            for b in &paper[i + 1..] {
                assert_ne!(theme.model_color(*a), theme.model_color(*b), "{a} {b}");
            }
        }
        for role in [Role::Normal, Role::Label, Role::Muted, Role::Error] {
            let fg = theme.style(role).fg;
            assert!(fg.is_none_or(|c| !FADING.contains(&c)), "{role:?}: {fg:?}");
        }
        assert!(
            theme
                .style(Role::Muted)
                .add_modifier
                .contains(Modifier::DIM)
        );
    }

    #[test]
    fn methods_differ_in_colour() {
        let theme = Theme { color: true };
        for (i, a) in Method::ALL.iter().enumerate() {
            assert!(!FADING.contains(&theme.method_color(*a)));
            for b in &Method::ALL[i + 1..] {
                assert_ne!(theme.method_color(*a), theme.method_color(*b));
            }
        }
    }
}
