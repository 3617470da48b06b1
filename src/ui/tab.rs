//! The views of the explorer, one per digit key.

/// A view: the explorer of issue 4, or one of the studies of issue 5.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Tab {
    /// Forms, charts and results of the checked models.
    Explorer,
    /// Error against cost of every method for the focused model.
    WorkPrecision,
    /// Fixed-step methods at a chosen step over the reference.
    Stability,
    /// One output against one scene parameter for the checked models.
    Sweep,
    /// Realised against requested restitution, and e against v₀, for the checked models.
    Restitution,
}

impl Tab {
    pub const ALL: [Tab; 5] = [
        Tab::Explorer,
        Tab::WorkPrecision,
        Tab::Stability,
        Tab::Sweep,
        Tab::Restitution,
    ];

    /// The key that opens the tab.
    pub fn key(self) -> char {
        match self {
            Tab::Explorer => '1',
            Tab::WorkPrecision => '2',
            Tab::Stability => '3',
            Tab::Sweep => '4',
            Tab::Restitution => '5',
        }
    }

    /// The tab of a digit key, if any.
    pub fn of_key(key: char) -> Option<Tab> {
        Tab::ALL.into_iter().find(|t| t.key() == key)
    }

    /// The name on the tab bar.
    pub fn title(self) -> &'static str {
        match self {
            Tab::Explorer => "explorer",
            Tab::WorkPrecision => "work–precision",
            Tab::Stability => "stability",
            Tab::Sweep => "sweep",
            Tab::Restitution => "restitution",
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn digits_one_to_five_open_the_tabs_in_order() {
        let keys: String = Tab::ALL.iter().map(|t| t.key()).collect();
        assert_eq!(keys, "12345");
        for tab in Tab::ALL {
            assert_eq!(Tab::of_key(tab.key()), Some(tab));
        }
        assert_eq!(Tab::of_key('6'), None);
        assert_eq!(Tab::of_key('0'), None);
    }
}
