//! Scene files (TOML): parsing with errors that name file, line and key; writing back.
