//! Colours and the one place text styles are chosen, per theme: dark and light terminals each
//! get a palette whose every colour reads at 4.5:1 or more on that background (WCAG 2's AA for
//! text, computed in [`super::contrast`]), and `NO_COLOR` turns colour off. Text is the
//! terminal's own foreground or a colour of the palette, never DIM (faint text drops below 4.5:1
//! on either background). A law's hue is a name (its row of the law table); each theme maps it to
//! a colour that reads on its background: the 16 ANSI colours where one does, else the xterm
//! 256-colour cube, whose values terminals do not remap.

use ratatui::style::{Color, Modifier, Style};

use crate::chart::{Dash, Hue, Ink};
use crate::model::ForceModel;
use crate::model::ode::Method;

/// A four-cell legend sample of a curve: its line in its pattern with its glyph, the glyph the
/// chart puts at the curve's peak and end (and along it without colour).
pub fn sample(glyph: char, dash: Dash) -> String {
    let line = match dash {
        Dash::Solid => '─',
        Dash::Dotted => '┈',
        Dash::Dashed => '╌',
    };
    format!("{line}{glyph}{line}{line}")
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

impl Role {
    pub const ALL: [Role; 9] = [
        Role::Normal,
        Role::Title,
        Role::Label,
        Role::Muted,
        Role::Cursor,
        Role::Error,
        Role::Good,
        Role::Warning,
        Role::Key,
    ];
}

/// The explorer's looks: a palette for a dark or a light background, or no colour at all.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Theme {
    /// Light text on a dark background.
    #[default]
    Dark,
    /// Dark text on a light background.
    Light,
    /// No colour (`NO_COLOR`): bold, underline and reverse video only.
    Plain,
}

impl Theme {
    pub const ALL: [Theme; 3] = [Theme::Dark, Theme::Light, Theme::Plain];

    /// Its name in the config file and the docs.
    pub fn name(self) -> &'static str {
        match self {
            Theme::Dark => "dark",
            Theme::Light => "light",
            Theme::Plain => "plain",
        }
    }

    /// The theme of that name.
    pub fn named(name: &str) -> Option<Theme> {
        Theme::ALL.into_iter().find(|t| t.name() == name)
    }

    /// Whether it has colours.
    pub fn color(self) -> bool {
        self != Theme::Plain
    }

    /// The theme the terminal asks for: none under `NO_COLOR` set to a non-empty value
    /// (<https://no-color.org>); else light or dark as `COLORFGBG` says of the background (set by
    /// rxvt, Konsole and others); else dark, the common case.
    pub fn from_env() -> Theme {
        Theme::detect(
            std::env::var_os("NO_COLOR"),
            std::env::var("COLORFGBG").ok().as_deref(),
        )
    }

    /// [`Theme::from_env`] on the values of `NO_COLOR` and `COLORFGBG`.
    pub fn detect(no_color: Option<std::ffi::OsString>, colorfgbg: Option<&str>) -> Theme {
        if no_color.is_some_and(|v| !v.is_empty()) {
            return Theme::Plain;
        }
        colorfgbg.and_then(background_of).unwrap_or(Theme::Dark)
    }

    /// The colour of a hue on this theme's background.
    pub fn hue(self, hue: Hue) -> Color {
        match (self, hue) {
            (Theme::Plain, _) | (_, Hue::Foreground) => Color::Reset,
            (Theme::Dark, Hue::Red) => Color::LightRed,
            (Theme::Dark, Hue::Green) => Color::Green,
            (Theme::Dark, Hue::Yellow) => Color::Yellow,
            // ANSI blue and bright blue are 2.2 and 4.4:1 on black: #5f87ff is 6.4:1.
            (Theme::Dark, Hue::Blue) => Color::Indexed(69),
            (Theme::Dark, Hue::Magenta) => Color::LightMagenta,
            (Theme::Dark, Hue::Cyan) => Color::Cyan,
            (Theme::Light, Hue::Red) => Color::Red,
            // ANSI green, yellow and cyan are 1.7 to 2.1:1 on white.
            (Theme::Light, Hue::Green) => Color::Indexed(28),
            (Theme::Light, Hue::Yellow) => Color::Indexed(130),
            (Theme::Light, Hue::Blue) => Color::Blue,
            (Theme::Light, Hue::Magenta) => Color::Indexed(127),
            (Theme::Light, Hue::Cyan) => Color::Indexed(23),
        }
    }

    pub fn style(self, role: Role) -> Style {
        let base = Style::default();
        let bold = Modifier::BOLD;
        match (self, role) {
            (_, Role::Normal | Role::Label) => base,
            (_, Role::Cursor) => base.add_modifier(Modifier::REVERSED),
            (Theme::Plain, Role::Title | Role::Key) => base.add_modifier(bold),
            (Theme::Plain, Role::Error) => base.add_modifier(bold | Modifier::UNDERLINED),
            (Theme::Plain, Role::Muted | Role::Good | Role::Warning) => base,
            (Theme::Dark, Role::Title | Role::Key) => base.fg(Color::Cyan).add_modifier(bold),
            (Theme::Light, Role::Title | Role::Key) => base.fg(Color::Blue).add_modifier(bold),
            // Grey, not DIM: #7f7f7f is 5.3:1 on black; on white ANSI's greys are under 4.5:1,
            // #6c6c6c is 5.3:1.
            (Theme::Dark, Role::Muted) => base.fg(Color::DarkGray),
            (Theme::Light, Role::Muted) => base.fg(Color::Indexed(242)),
            (_, Role::Error) => base.fg(self.hue(Hue::Red)).add_modifier(bold),
            (_, Role::Good) => base.fg(self.hue(Hue::Green)),
            (_, Role::Warning) => base.fg(self.hue(Hue::Yellow)),
        }
    }

    /// The colour of a model's curve and legend entry.
    pub fn model_color(self, model: ForceModel) -> Color {
        self.hue(Ink::Model(model).hue())
    }

    pub fn model_style(self, model: ForceModel) -> Style {
        Style::default().fg(self.model_color(model))
    }

    /// The colour of an integration method's line.
    pub fn method_color(self, method: Method) -> Color {
        self.hue(Ink::Method(method).hue())
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
            Ink::Plain(hue) => Style::default().fg(self.hue(hue)),
        }
    }
}

/// The theme `COLORFGBG` ("foreground;background", or "fg;default;bg") asks for: its background
/// is an ANSI colour number, 7 (white) and 9–15 (the bright ones, but 8, grey) light, 0–6 and 8
/// dark.
fn background_of(colorfgbg: &str) -> Option<Theme> {
    let bg: u8 = colorfgbg.rsplit(';').next()?.trim().parse().ok()?;
    match bg {
        0..=6 | 8 => Some(Theme::Dark),
        7 | 9..=15 => Some(Theme::Light),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::ui::style::contrast::{Surface, of_text};

    #[test]
    fn no_color_is_honoured_only_when_non_empty_and_colorfgbg_names_the_background() {
        assert_eq!(Theme::detect(None, None), Theme::Dark);
        assert_eq!(Theme::detect(Some("".into()), None), Theme::Dark);
        let plain = Theme::detect(Some("1".into()), Some("0;15"));
        assert_eq!(plain, Theme::Plain);
        for role in Role::ALL {
            let s = plain.style(role);
            assert_eq!((s.fg, s.bg), (None, None), "{role:?}");
        }
        assert_eq!(plain.model_color(ForceModel::Proposed), Color::Reset);
        assert_eq!(Theme::detect(None, Some("0;15")), Theme::Light);
        assert_eq!(Theme::detect(None, Some("0;default;7")), Theme::Light);
        assert_eq!(Theme::detect(None, Some("15;0")), Theme::Dark);
        assert_eq!(Theme::detect(None, Some("15;8")), Theme::Dark);
        assert_eq!(Theme::detect(None, Some("garbage")), Theme::Dark);
    }

    /// The backgrounds a theme is read on: its own, and either for the theme without colour.
    fn surfaces(theme: Theme) -> &'static [Surface] {
        match theme {
            Theme::Dark => &[Surface::DARK],
            Theme::Light => &[Surface::LIGHT],
            Theme::Plain => &[Surface::DARK, Surface::LIGHT],
        }
    }

    /// Every text style of every theme — each role, each hue, every law's and method's ink, the
    /// chart's warning and error inks, bold or not — reads at 4.5:1 or more on the theme's own
    /// background (ANSI colours at xterm's values, see `contrast`). Before themes, muted text and
    /// pane borders (so titles and legends) were DIM, 4.4:1 on black and 4.0:1 on white where
    /// faint is a blend half-way to the background, less where terminals dim further; ANSI red
    /// and blue on black were 3.6 and 2.2:1, green, yellow and cyan on white 2.2, 1.7 and 2.0:1.
    #[test]
    fn every_style_reads_at_4_5_to_1_on_its_background() {
        for theme in Theme::ALL {
            let mut styles: Vec<(String, Style)> = Role::ALL
                .iter()
                .map(|&r| (format!("{r:?}"), theme.style(r)))
                .collect();
            for m in ForceModel::ALL {
                styles.push((m.name().to_string(), theme.ink(Ink::Model(m))));
            }
            for m in Method::ALL {
                styles.push((format!("{m}"), theme.ink(Ink::Method(m))));
            }
            for ink in [Ink::Warning, Ink::Error, Ink::Foreground] {
                styles.push((format!("{ink:?}"), theme.ink(ink)));
            }
            for &surface in surfaces(theme) {
                for (name, style) in &styles {
                    for bold in [Modifier::empty(), Modifier::BOLD] {
                        let fg = style.fg.unwrap_or(Color::Reset);
                        let bg = style.bg.unwrap_or(Color::Reset);
                        let modifier = style.add_modifier | bold;
                        let c = of_text(fg, bg, modifier, surface);
                        assert!(c >= 4.5, "{theme:?} {name}: {c:.2}:1 on {surface:?}");
                    }
                }
            }
        }
    }

    #[test]
    fn the_papers_five_and_the_methods_differ_in_colour_on_each_theme() {
        let paper = [
            ForceModel::Quasistatic,
            ForceModel::DryFriction,
            ForceModel::Proposed,
            ForceModel::HuntCrossley,
            ForceModel::LankaraniNikravesh,
        ];
        for theme in [Theme::Dark, Theme::Light] {
            for (i, a) in paper.iter().enumerate() {
                for b in &paper[i + 1..] {
                    assert_ne!(theme.model_color(*a), theme.model_color(*b), "{a} {b}");
                }
            }
            for (i, a) in Method::ALL.iter().enumerate() {
                for b in &Method::ALL[i + 1..] {
                    assert_ne!(theme.method_color(*a), theme.method_color(*b));
                }
            }
        }
    }
}
