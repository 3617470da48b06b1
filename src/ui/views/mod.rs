//! The views of the explorer, one folder each, and the one registry the rest iterates: the tab
//! bar, the digit keys, the body drawn, the keys a view takes, its status hints, the studies it
//! needs, its lines in the help and the figure `f` writes all come from [`VIEWS`]. A new view is a
//! folder implementing [`View`] plus one line in the `registry!` below.
//!
//! Each folder also defines the view's own state, `State` (its settings, cursor, chart shown…),
//! and the same registry line gives it a field of [`ViewStates`], which the app holds: a view with
//! state and a study is one folder plus one line. A view reads the app (`&App`) to draw and acts on
//! it (`&mut App`) for its own keys; the app never imports a view's drawing or keys.

use ratatui::Frame;
use ratatui::layout::Position;

use crate::chart::Chart;
use crate::model::study::runner::{StudyKind, StudySpec};

use super::action::Action;
use super::app::{App, EditTarget, Valid};
use super::field::Nudge;
use super::layout::ScreenLayout;
use super::tab::Tab;

/// Tick labels on a figure's axes, x and y, and the columns its curves are sampled for.
pub const FIGURE_TICKS: (usize, usize) = (9, 8);
pub const FIGURE_COLUMNS: u16 = 600;

/// Key hints of the status line in normal mode: (key, action).
pub type Hints = &'static [(&'static str, &'static str)];

/// One tab of the explorer.
pub trait View: Sync {
    /// The name in file names (`<scene>-<id>.svg`) and for [`Tab::named`].
    fn id(&self) -> &'static str;
    /// The name on the tab bar.
    fn title(&self) -> &'static str;
    /// The name in the help's list of views (short names keep it on one line at 80 columns).
    fn short_title(&self) -> &'static str {
        self.title()
    }
    /// The view's own keys in one line of the help, if it has keys of its own beyond the
    /// explorer's.
    fn help(&self) -> Option<&'static str> {
        None
    }
    /// Draws the view in the body of `screen`.
    fn render(&self, frame: &mut Frame, screen: &ScreenLayout, app: &App);
    /// The view's own key hints, after the shared ones (help, quit, views).
    fn hints(&self) -> Hints;
    /// Handles `action` in normal mode if it is one of the view's own keys; returns it otherwise,
    /// for the keys every view shares (quit, help, presets, models…).
    fn handle(&self, _app: &mut App, action: Action) -> Option<Action> {
        Some(action)
    }
    /// Commits the text of a line editor the view opened; the reason if it is refused.
    fn commit(&self, _app: &mut App, _target: EditTarget, _text: &str) -> Result<(), String> {
        Ok(())
    }
    /// A left click in the body.
    fn click(&self, _app: &mut App, _at: Position) {}
    /// The wheel in the body.
    fn wheel(&self, _app: &mut App, _at: Position, _direction: Nudge) {}
    /// The studies the view draws (the explorer draws solves only).
    fn studies(&self) -> &'static [StudyKind] {
        &[]
    }
    /// The studies the view needs for `valid` and the app's settings.
    fn study_specs(&self, _app: &App, _valid: &Valid) -> Vec<StudySpec> {
        Vec::new()
    }
    /// The charts `f` writes to a figure (none while a study is missing).
    fn charts(&self, app: &App) -> Vec<Chart>;
}

/// Declares each view's folder as a module, lists it in [`VIEWS`] and gives its `State` a field
/// of [`ViewStates`], from one line per view.
macro_rules! registry {
    ($($folder:ident::$view:ident),+ $(,)?) => {
        $(pub mod $folder;)+

        /// Every view, in tab order: the first is where the explorer opens, the n-th of the first
        /// nine opens with digit n; `v` and `V` step through all of them.
        pub static VIEWS: &[&dyn View] = &[$(&$folder::$view),+];

        /// The state of every view, one field per view folder, named after it; each starts as its
        /// `State::default()`.
        #[derive(Debug, Default)]
        pub struct ViewStates {
            $(pub $folder: $folder::State,)+
        }
    };
}

registry! {
    explorer::Explorer,
    work_precision::WorkPrecision,
    stability::Stability,
    sweep::Sweep,
    restitution::Restitution,
    system::System,
    fit::Fit,
    map::Map,
}

const _: () = assert!(!VIEWS.is_empty());

/// How many views have a digit key: 1–9.
const DIGITS: usize = 9;

impl Tab {
    /// The view this tab shows.
    pub fn view(self) -> &'static dyn View {
        VIEWS.get(self.0).copied().unwrap_or(VIEWS[0])
    }

    /// Every tab, in order.
    pub fn all() -> impl Iterator<Item = Tab> {
        (0..VIEWS.len()).map(Tab)
    }

    /// The digit key that opens the tab: the first nine have one.
    pub fn key(self) -> Option<char> {
        char::from_digit(u32::try_from(self.0 + 1).ok()?, 10).filter(|_| self.0 < DIGITS)
    }

    /// The tab of a digit key, if any.
    pub fn of_key(key: char) -> Option<Tab> {
        Tab::all().find(|t| t.key() == Some(key))
    }

    /// How the help names the tab: its digit, else its title.
    pub fn name(self) -> String {
        match self.key() {
            Some(key) => key.to_string(),
            None => self.view().short_title().to_string(),
        }
    }

    /// The next (`Up`) or previous (`Down`) tab, wrapping around.
    pub fn cycle(self, direction: Nudge) -> Tab {
        let n = VIEWS.len();
        Tab(match direction {
            Nudge::Up => (self.0 + 1) % n,
            Nudge::Down => (self.0 + n - 1) % n,
        })
    }

    /// The tab of a view's [`View::id`], if any.
    pub fn named(id: &str) -> Option<Tab> {
        Tab::all().find(|t| t.view().id() == id)
    }

    /// The name on the tab bar.
    pub fn title(self) -> &'static str {
        self.view().title()
    }
}

/// The keys of the views as the status line names them: `1-5`, or `1-9 v` when some have no digit.
pub fn keys_hint() -> String {
    match VIEWS.len() {
        n if n <= DIGITS => format!("1-{n}"),
        _ => format!("1-{DIGITS} v"),
    }
}

/// Whether a study the shown view draws is running.
pub fn is_studying(app: &App) -> bool {
    app.tab
        .view()
        .studies()
        .iter()
        .any(|&k| app.studies.is_pending(k))
}

/// Requests the studies of the shown view whose inputs changed (same inputs ask nothing).
pub fn request_studies(app: &mut App) {
    let Some(valid) = &app.valid else {
        return;
    };
    let specs = app.tab.view().study_specs(app, valid);
    for spec in specs {
        app.queue_study(spec);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// However many views there are, the n-th opens with digit n and by its id, and no other key
    /// opens one; the explorer is where the app opens.
    #[test]
    fn digits_open_the_first_nine_tabs_in_order() {
        for tab in Tab::all() {
            let digit = (tab.0 < 9).then(|| char::from_digit(tab.0 as u32 + 1, 10).unwrap());
            assert_eq!(tab.key(), digit);
            if let Some(key) = tab.key() {
                assert_eq!(Tab::of_key(key), Some(tab));
            }
            assert_eq!(Tab::named(tab.view().id()), Some(tab));
        }
        for key in ('0'..='9').filter(|k| !Tab::all().any(|t| t.key() == Some(*k))) {
            assert_eq!(Tab::of_key(key), None);
        }
        assert_eq!(Tab::HOME.view().id(), "explorer");
    }

    #[test]
    fn cycling_visits_every_tab_and_wraps() {
        let mut tab = Tab::HOME;
        let mut seen = Vec::new();
        for _ in Tab::all() {
            seen.push(tab);
            tab = tab.cycle(Nudge::Up);
        }
        assert_eq!(tab, Tab::HOME, "wraps after the last");
        assert_eq!(seen, Tab::all().collect::<Vec<_>>());
        for tab in Tab::all() {
            assert_eq!(tab.cycle(Nudge::Up).cycle(Nudge::Down), tab);
        }
        assert_eq!(Tab::HOME.cycle(Nudge::Down), Tab(VIEWS.len() - 1));
    }

    #[test]
    fn ids_and_titles_are_distinct() {
        for (i, a) in VIEWS.iter().enumerate() {
            for b in &VIEWS[i + 1..] {
                assert_ne!(a.id(), b.id());
                assert_ne!(a.title(), b.title());
            }
        }
    }
}
