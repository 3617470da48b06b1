//! Small helpers shared by the pane renderers.

use ratatui::layout::{Constraint, Flex, Layout, Rect};
use ratatui::style::Style;
use ratatui::text::Span;
use ratatui::widgets::{Block, Borders};

use crate::model::ForceModel;
use crate::ui::style::{Role, Theme};

use super::status::shortened;

/// A pane's frame, ratatui's `Block`: full borders on roomy screens, a titled top rule on compact
/// ones, in the theme's border and title styles.
pub fn pane<'a>(title: impl Into<ratatui::text::Line<'a>>, theme: Theme, roomy: bool) -> Block<'a> {
    let borders = if roomy { Borders::ALL } else { Borders::TOP };
    Block::new()
        .borders(borders)
        .border_style(theme.style(Role::Muted))
        .title(title)
        .title_style(theme.style(Role::Title))
}

/// [`pane`] for `area`, its title cut to fit with `…` where it is too long (ratatui would cut it
/// mid-word); on compact screens a rule cell is left before the next pane's title.
pub fn titled<'a>(title: &str, area: Rect, theme: Theme, roomy: bool) -> Block<'a> {
    let room = area.width.saturating_sub(if roomy { 2 } else { 1 });
    pane(shortened(title, usize::from(room)), theme, roomy)
}

/// How a pane names models: the paper's label, the kebab id, or the abbreviation, longest first.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum NameForm {
    Label,
    Id,
    Short,
}

impl NameForm {
    /// `model`'s name in this form.
    pub fn of(self, model: ForceModel) -> &'static str {
        match self {
            NameForm::Label => model.label(),
            NameForm::Id => model.name(),
            NameForm::Short => model.short(),
        }
    }

    /// The longest form in which every one of `models` fits `width` columns, so that a list
    /// names all its rows alike; the abbreviation when no longer form fits them all.
    pub fn fitting(models: &[ForceModel], width: usize) -> NameForm {
        [NameForm::Label, NameForm::Id]
            .into_iter()
            .find(|form| models.iter().all(|&m| form.of(m).chars().count() <= width))
            .unwrap_or(NameForm::Short)
    }
}

/// A model's name in `width` columns at most: the paper's label, the kebab name, or an abbreviation.
pub fn model_name(model: ForceModel, width: usize) -> &'static str {
    NameForm::fitting(&[model], width).of(model)
}

/// Word-wraps `text` to lines of at most `width` characters (long words are cut).
pub fn wrap(text: &str, width: usize) -> Vec<String> {
    let width = width.max(1);
    let mut lines = Vec::new();
    let mut line = String::new();
    // Characters in `line`.
    let mut used = 0;
    for mut word in text.split_whitespace() {
        let mut length = word.chars().count();
        while length > width {
            if !line.is_empty() {
                lines.push(std::mem::take(&mut line));
                used = 0;
            }
            let cut = word
                .char_indices()
                .nth(width)
                .map_or(word.len(), |(i, _)| i);
            lines.push(word[..cut].to_string());
            word = &word[cut..];
            length -= width;
        }
        if used + usize::from(!line.is_empty()) + length > width && !line.is_empty() {
            lines.push(std::mem::take(&mut line));
            used = 0;
        }
        if !line.is_empty() {
            line.push(' ');
            used += 1;
        }
        line.push_str(word);
        used += length;
    }
    if !line.is_empty() {
        lines.push(line);
    }
    lines
}

/// Spans laid out in lines of at most `width` columns, breaking only between items; items are
/// separated by `gap` on a line. Lines past `max_lines` are dropped.
pub fn flow<'a>(
    items: Vec<Vec<Span<'a>>>,
    width: usize,
    max_lines: usize,
    gap: Span<'a>,
) -> Vec<ratatui::text::Line<'a>> {
    let mut lines: Vec<Vec<Span<'a>>> = Vec::new();
    let mut used = 0;
    let gap_width = gap.width();
    for item in items {
        let item_width: usize = item.iter().map(Span::width).sum();
        let fits = used > 0 && used + gap_width + item_width <= width;
        match lines.last_mut() {
            Some(line) if fits => {
                line.push(gap.clone());
                line.extend(item);
                used += gap_width + item_width;
            }
            _ => {
                lines.push(item);
                used = item_width;
            }
        }
    }
    lines.truncate(max_lines);
    lines.into_iter().map(ratatui::text::Line::from).collect()
}

/// A rectangle of at most `width`×`height` centred in `area`.
pub fn centered(area: Rect, width: u16, height: u16) -> Rect {
    let [row] = Layout::vertical([Constraint::Length(height.min(area.height))])
        .flex(Flex::Center)
        .areas(area);
    let [cell] = Layout::horizontal([Constraint::Length(width.min(area.width))])
        .flex(Flex::Center)
        .areas(row);
    cell
}

/// A styled span.
pub fn span<'a>(text: impl Into<std::borrow::Cow<'a, str>>, style: Style) -> Span<'a> {
    Span::styled(text, style)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wrap_breaks_between_words_and_cuts_long_ones() {
        assert_eq!(
            wrap("body1.radius must be a finite number > 0, got -0.001", 20),
            ["body1.radius must be", "a finite number > 0,", "got -0.001"]
        );
        assert_eq!(wrap("abcdefghij", 4), ["abcd", "efgh", "ij"]);
        assert!(wrap("", 10).is_empty());
    }

    /// The wrapping as it was, a `Vec<char>` a word: the oracle of the test below.
    fn wrap_by_chars(text: &str, width: usize) -> Vec<String> {
        let width = width.max(1);
        let mut lines = Vec::new();
        let mut line = String::new();
        for word in text.split_whitespace() {
            let mut word: Vec<char> = word.chars().collect();
            while word.len() > width {
                if !line.is_empty() {
                    lines.push(std::mem::take(&mut line));
                }
                lines.push(word.drain(..width).collect());
            }
            let word: String = word.into_iter().collect();
            let needed =
                line.chars().count() + usize::from(!line.is_empty()) + word.chars().count();
            if needed > width && !line.is_empty() {
                lines.push(std::mem::take(&mut line));
            }
            if !line.is_empty() {
                line.push(' ');
            }
            line.push_str(&word);
        }
        if !line.is_empty() {
            lines.push(line);
        }
        lines
    }

    proptest::proptest! {
        /// Words of ASCII and wider characters, of every length up to several widths, runs of
        /// spaces and newlines, widths from none up: the lines the char-vector wrapping gave.
        #[test]
        fn wrap_gives_what_wrapping_by_chars_gave(
            text in "[a-cµ–⚠ \n]{0,60}",
            width in 0usize..12,
        ) {
            proptest::prop_assert_eq!(wrap(&text, width), wrap_by_chars(&text, width));
        }
    }

    #[test]
    fn flow_keeps_items_whole() {
        let item = |s: &'static str| vec![Span::raw(s)];
        let lines = flow(
            vec![item("aaaa"), item("bbbb"), item("cccccc"), item("d")],
            10,
            2,
            Span::raw(" "),
        );
        let text: Vec<String> = lines.iter().map(|l| l.to_string()).collect();
        assert_eq!(text, ["aaaa bbbb", "cccccc d"]);
    }

    #[test]
    fn names_fit_their_width() {
        for model in ForceModel::ALL {
            for width in [5, 9, 19, 30] {
                assert!(model_name(model, width).chars().count() <= width.max(8));
            }
        }
        assert_eq!(
            model_name(ForceModel::HuntCrossley, 30),
            "Hunt–Crossley (eq 19)"
        );
        assert_eq!(model_name(ForceModel::HuntCrossley, 13), "hunt-crossley");
        assert_eq!(model_name(ForceModel::HuntCrossley, 8), "H–C");
    }

    #[test]
    fn a_list_takes_the_longest_form_that_fits_all_its_names() {
        let all = &ForceModel::ALL;
        let longest = |form: NameForm| all.iter().map(|&m| form.of(m).chars().count()).max();
        let (label, id) = (
            longest(NameForm::Label).unwrap(),
            longest(NameForm::Id).unwrap(),
        );
        assert_eq!(NameForm::fitting(all, label), NameForm::Label);
        assert_eq!(NameForm::fitting(all, label - 1), NameForm::Id);
        assert_eq!(NameForm::fitting(all, id), NameForm::Id);
        assert_eq!(NameForm::fitting(all, id - 1), NameForm::Short);
        // One long label is enough to rename the whole list.
        let pair = [ForceModel::Quasistatic, ForceModel::LankaraniNikravesh];
        assert_eq!(NameForm::fitting(&pair, 21), NameForm::Id);
        assert_eq!(
            model_name(ForceModel::Quasistatic, 21),
            "Hertz, elastic (eq 1)"
        );
    }
}
