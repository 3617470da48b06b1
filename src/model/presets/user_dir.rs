//! Where user presets live: `$XDG_CONFIG_HOME/hertz-tui/presets`, else `~/.config/hertz-tui/presets`.

use std::ffi::OsString;
use std::path::PathBuf;

/// The user preset folder from the environment (holding `materials/` and `scenes/`), if any.
pub fn user_dir() -> Option<PathBuf> {
    user_dir_from(
        std::env::var_os("XDG_CONFIG_HOME"),
        std::env::var_os("HOME"),
    )
}

/// The user preset folder given the values of `XDG_CONFIG_HOME` and `HOME`. The XDG base-directory
/// specification says to ignore an empty or relative `XDG_CONFIG_HOME`.
pub fn user_dir_from(xdg_config_home: Option<OsString>, home: Option<OsString>) -> Option<PathBuf> {
    let config = xdg_config_home
        .map(PathBuf::from)
        .filter(|p| p.is_absolute())
        .or_else(|| {
            home.filter(|h| !h.is_empty())
                .map(|h| PathBuf::from(h).join(".config"))
        })?;
    Some(config.join("hertz-tui").join("presets"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn xdg_wins_over_home() {
        assert_eq!(
            user_dir_from(Some("/x".into()), Some("/home/u".into())),
            Some(PathBuf::from("/x/hertz-tui/presets"))
        );
    }

    #[test]
    fn empty_or_relative_xdg_falls_back_to_home() {
        let expected = Some(PathBuf::from("/home/u/.config/hertz-tui/presets"));
        assert_eq!(
            user_dir_from(Some("".into()), Some("/home/u".into())),
            expected
        );
        assert_eq!(
            user_dir_from(Some("rel".into()), Some("/home/u".into())),
            expected
        );
        assert_eq!(user_dir_from(None, Some("/home/u".into())), expected);
        assert_eq!(user_dir_from(None, None), None);
    }
}
