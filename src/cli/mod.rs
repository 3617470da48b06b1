//! Headless subcommands over the model layer.
