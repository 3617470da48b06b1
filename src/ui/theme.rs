//! Colours (16-colour palette only) and line patterns; `NO_COLOR` turns colour off.

use ratatui::style::{Color, Modifier, Style};

use crate::model::ForceModel;
use crate::model::ode::Method;

/// How a model's curve is drawn, so that curves stay distinct without colour (the paper's Fig. 5
/// draws the proposed model solid, Hunt–Crossley dotted and Lankarani–Nikravesh dashed).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LinePattern {
    Solid,
    Dotted,
    Dashed,
    DashDot,
    LongDash,
    ShortDash,
    DashDotDot,
}

impl LinePattern {
    /// Models beyond the paper's five cycle through the patterns; with the colours cycling over a
    /// list of another length, every model gets its own (colour, pattern) pair.
    pub fn of(model: ForceModel) -> LinePattern {
        const PATTERNS: [LinePattern; 7] = [
            LinePattern::Solid,
            LinePattern::Dotted,
            LinePattern::Dashed,
            LinePattern::DashDot,
            LinePattern::LongDash,
            LinePattern::ShortDash,
            LinePattern::DashDotDot,
        ];
        PATTERNS[style_index(model) % PATTERNS.len()]
    }

    /// The pattern of an integration method (work-precision and stability views): seven
    /// patterns for seven methods, so that every line stays distinct without colour.
    pub fn of_method(method: Method) -> LinePattern {
        match method {
            Method::Dopri5 => LinePattern::Solid,
            Method::Dop853 => LinePattern::Dashed,
            Method::Radau5 => LinePattern::Dotted,
            Method::Euler => LinePattern::DashDot,
            Method::SymplecticEuler => LinePattern::LongDash,
            Method::Verlet => LinePattern::ShortDash,
            Method::Rk4 => LinePattern::DashDotDot,
        }
    }

    /// A four-cell sample of the pattern for legends.
    pub fn sample(self) -> &'static str {
        match self {
            LinePattern::Solid => "────",
            LinePattern::Dotted => "····",
            LinePattern::Dashed => "╴╴╴╴",
            LinePattern::DashDot => "─·─·",
            LinePattern::LongDash => "── ─",
            LinePattern::ShortDash => "╌╌╌╌",
            LinePattern::DashDotDot => "─··─",
        }
    }

    /// Lengths of the pattern's pieces in plot dots: (drawn, gap) pairs; a drawn length of 0 is a dot.
    pub fn pieces(self) -> &'static [(f64, f64)] {
        match self {
            LinePattern::Solid => &[],
            LinePattern::Dotted => &[(0.0, 3.0)],
            LinePattern::Dashed => &[(5.0, 4.0)],
            LinePattern::DashDot => &[(7.0, 3.0), (0.0, 3.0)],
            LinePattern::LongDash => &[(14.0, 5.0)],
            LinePattern::ShortDash => &[(2.0, 2.0)],
            LinePattern::DashDotDot => &[(7.0, 3.0), (0.0, 3.0), (0.0, 3.0)],
        }
    }
}

/// The paper's Fig. 5 styles first (proposed solid yellow, Hunt–Crossley dotted, Lankarani–Nikravesh
/// dashed, then elastic Hertz and dry friction), then the other laws in table order.
fn style_index(model: ForceModel) -> usize {
    const PAPER: [ForceModel; 5] = [
        ForceModel::Proposed,
        ForceModel::HuntCrossley,
        ForceModel::LankaraniNikravesh,
        ForceModel::Quasistatic,
        ForceModel::DryFriction,
    ];
    PAPER.iter().position(|&m| m == model).unwrap_or_else(|| {
        PAPER.len()
            + ForceModel::ALL
                .iter()
                .filter(|m| !PAPER.contains(m))
                .position(|&m| m == model)
                .unwrap_or_default()
    })
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
    /// Colour unless `NO_COLOR` is set to a non-empty value (https://no-color.org).
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
            Role::Label => base.fg(Color::Gray),
            Role::Muted => base.fg(Color::DarkGray),
            Role::Cursor => base.add_modifier(Modifier::REVERSED),
            Role::Error => base.fg(Color::LightRed).add_modifier(Modifier::BOLD),
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
        const COLORS: [Color; 8] = [
            Color::Yellow,
            Color::LightCyan,
            Color::LightMagenta,
            Color::LightBlue,
            Color::LightGreen,
            Color::LightRed,
            Color::Cyan,
            Color::Magenta,
        ];
        COLORS[style_index(model) % COLORS.len()]
    }

    pub fn model_style(self, model: ForceModel) -> Style {
        Style::default().fg(self.model_color(model))
    }

    /// The colour of an integration method's line.
    pub fn method_color(self, method: Method) -> Color {
        if !self.color {
            return Color::Reset;
        }
        match method {
            Method::Dopri5 => Color::Yellow,
            Method::Dop853 => Color::LightCyan,
            Method::Radau5 => Color::LightMagenta,
            Method::Euler => Color::LightRed,
            Method::SymplecticEuler => Color::LightGreen,
            Method::Verlet => Color::LightBlue,
            Method::Rk4 => Color::Magenta,
        }
    }

    pub fn method_style(self, method: Method) -> Style {
        Style::default().fg(self.method_color(method))
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

    #[test]
    fn models_differ_in_colour_or_pattern_and_the_paper_five_in_both() {
        let theme = Theme { color: true };
        let style = |m: ForceModel| (theme.model_color(m), LinePattern::of(m).sample());
        for (i, a) in ForceModel::ALL.iter().enumerate() {
            for b in &ForceModel::ALL[i + 1..] {
                assert_ne!(style(*a), style(*b), "{a} {b}");
            }
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
                assert_ne!(theme.model_color(*a), theme.model_color(*b));
                assert_ne!(LinePattern::of(*a), LinePattern::of(*b));
            }
        }
        assert_eq!(theme.model_color(ForceModel::Proposed), Color::Yellow);
        assert_eq!(
            LinePattern::of(ForceModel::HuntCrossley),
            LinePattern::Dotted
        );
    }

    #[test]
    fn methods_differ_in_colour_and_pattern() {
        let theme = Theme { color: true };
        for (i, a) in Method::ALL.iter().enumerate() {
            for b in &Method::ALL[i + 1..] {
                assert_ne!(theme.method_color(*a), theme.method_color(*b));
                assert_ne!(LinePattern::of_method(*a), LinePattern::of_method(*b));
                let (sa, sb) = (LinePattern::of_method(*a), LinePattern::of_method(*b));
                assert_ne!(sa.sample(), sb.sample());
                assert_ne!(sa.pieces(), sb.pieces());
            }
        }
    }
}
