//! `--set KEY=VALUE` overrides of scene keys by dotted path.
