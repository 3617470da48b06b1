//! Which view is shown: a place in the registry of views ([`crate::ui::views::VIEWS`]), whose
//! methods (key, title, the view itself) live with the registry. The app state holds only this
//! plain value, so it never imports a view.

/// A view of the explorer, by its place in [`crate::ui::views::VIEWS`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Tab(pub(crate) usize);

impl Tab {
    /// The view the explorer opens on: the first of the registry.
    pub const HOME: Tab = Tab(0);
}
