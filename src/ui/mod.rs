//! The terminal explorer (ratatui + crossterm) over the model layer.
