//! Built-in presets (embedded), user presets ($XDG_CONFIG_HOME/hertz-tui/presets/) and files by path.
