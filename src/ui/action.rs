//! Everything that can happen to the app: the vocabulary of [`update`](super::update::update).

use tui_input::InputRequest;

use crate::model::scene_key::BodyIndex;
use crate::model::study::runner::StudyOutcome;

use super::field::Nudge;
use super::jobs::Report;
use super::solutions::Outcome;
use super::tab::Tab;

/// One step of the state machine, from a key, the terminal or the solver.
#[derive(Debug, Clone)]
pub enum Action {
    /// `q`: quit, asking first when there are unsaved changes.
    Quit,
    /// `Ctrl-C`: like `Quit`, but a second one quits without asking.
    Interrupt,
    /// `y` to the question on screen.
    Yes,
    /// Text pasted from the terminal (bracketed paste).
    Paste(String),
    /// `u`: back to the draft before the last change.
    Undo,
    /// `r`: the field under the cursor back to the value of the scene as loaded or saved.
    ResetField,
    /// `Home` `End` `PgUp` `PgDn`: first or last row, previous or next section.
    Jump(Jump),
    /// `m`: mouse capture on or off.
    ToggleMouse,
    /// A left click at (column, row).
    Click(u16, u16),
    /// The wheel at (column, row): up or down.
    Wheel(u16, u16, Nudge),
    /// Cursor (or picker selection) up / down.
    Up,
    Down,
    /// Steps the value under the cursor (←/→, −/+).
    Nudge(Nudge),
    /// Enter: edit the field, toggle the model, commit the edit or prompt, apply the preset.
    Enter,
    /// Esc: cancel the edit, close the overlay, clear the message.
    Cancel,
    /// A line-editing request for the open editor or prompt.
    Input(InputRequest),
    /// Space: check or uncheck the model under the cursor (else the focused one).
    ToggleModel,
    /// Moves the focus to the next / previous model without moving the cursor.
    FocusModel(Nudge),
    /// Shows the next chart where not all fit.
    CycleChart,
    /// Switches between each law's own damping rule and damping calibrated to realise e.
    ToggleCalibration,
    /// Shows a view: the explorer or a study.
    Tab(Tab),
    /// Shows the next (`Up`) or previous (`Down`) view, wrapping around.
    CycleView(Nudge),
    Help,
    /// Opens the engine panel: the scene's contact parameters for a simulation engine.
    Engines,
    /// `y` in the engine panel: copies its script to the terminal's clipboard (OSC 52).
    Copy,
    Presets,
    Save,
    Export,
    /// Writes the charts of the view on screen to an SVG figure.
    Figure,
    /// `o`: opens a file into the view (the fit view's data).
    Open,
    /// Moves the explorer's data cursor along the charts' x axes: forward (right) or back, one
    /// step (`,` `.`) or ten (`<` `>`).
    MoveCursor {
        forward: bool,
        fast: bool,
    },
    /// `P`: the data cursor to the focused model's peak on the first chart.
    CursorToPeak,
    /// `b`: in the system view, the continued branch over the bifurcation diagram on or off.
    Branch,
    /// Applies the material selected in the picker to a body.
    ApplyMaterialTo(BodyIndex),
    /// The terminal has this many columns and rows: redraw (and size sweeps to it).
    Resize(u16, u16),
    /// The solver finished a job (or failed).
    Solved(Report<Outcome>),
    /// The studies' job queue finished a study (or it panicked).
    Studied(Report<StudyOutcome>),
}

/// Where `Home` `End` `PgUp` `PgDn` go.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Jump {
    First,
    Last,
    PreviousSection,
    NextSection,
}
