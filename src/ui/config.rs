//! The explorer's config file, `$XDG_CONFIG_HOME/hertz-tui/config.toml` (`~/.config/…` where
//! that is unset): the theme, the scene opened without `--scene`, and moved keys. Every key is
//! optional and no file is no error; a bad file is an error naming the file and line
//! (docs/explorer.md, "Config file").

use std::path::{Path, PathBuf};

use serde::Deserialize;
use toml::Spanned;
use toml::de::{DeTable, DeValue};

use super::rebind::Rebind;
use super::style::Theme;

/// What the config file says.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Config {
    /// `None`: chosen from the terminal (`NO_COLOR`, `COLORFGBG`).
    pub theme: Option<Theme>,
    /// The scene the explorer opens without `--scene`: a preset name or a path.
    pub scene: Option<String>,
    pub keys: Rebind,
}

/// A config file that cannot be read or used, with where.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum ConfigError {
    #[error("{path}: {message}")]
    Read { path: String, message: String },
    #[error("{path}:{line}: {message}")]
    Invalid {
        path: String,
        line: usize,
        message: String,
    },
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Raw {
    theme: Option<Spanned<String>>,
    scene: Option<String>,
    #[serde(default)]
    keys: toml::Table,
}

/// Where the config file is: `$XDG_CONFIG_HOME/hertz-tui/config.toml`, else
/// `$HOME/.config/hertz-tui/config.toml`; `None` without either variable.
pub fn path(xdg_config_home: Option<&Path>, home: Option<&Path>) -> Option<PathBuf> {
    let dir = match xdg_config_home.filter(|p| p.is_absolute()) {
        Some(dir) => dir.to_path_buf(),
        None => home?.join(".config"),
    };
    Some(dir.join("hertz-tui").join("config.toml"))
}

impl Config {
    /// The config file of this user, if there is one.
    pub fn load() -> Result<Config, ConfigError> {
        let xdg = std::env::var_os("XDG_CONFIG_HOME").map(PathBuf::from);
        let home = std::env::var_os("HOME").map(PathBuf::from);
        match path(xdg.as_deref(), home.as_deref()) {
            Some(path) => Config::read(&path),
            None => Ok(Config::default()),
        }
    }

    /// The file at `path`; no file is the default config.
    pub fn read(path: &Path) -> Result<Config, ConfigError> {
        match std::fs::read_to_string(path) {
            Ok(text) => Config::parse(&path.display().to_string(), &text),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(Config::default()),
            Err(e) => Err(ConfigError::Read {
                path: path.display().to_string(),
                message: e.to_string(),
            }),
        }
    }

    /// `text`, read from `origin` (named in errors).
    pub fn parse(origin: &str, text: &str) -> Result<Config, ConfigError> {
        let invalid = |offset: usize, message: String| ConfigError::Invalid {
            path: origin.to_string(),
            line: text[..offset.min(text.len())].matches('\n').count() + 1,
            message,
        };
        let raw: Raw = toml::from_str(text).map_err(|e| {
            let at = e.span().map_or(0, |s| s.start);
            invalid(at, e.message().trim().to_string())
        })?;
        let theme = match raw.theme {
            None => None,
            Some(name) if name.get_ref() == "auto" => None,
            Some(name) => Some(Theme::named(name.get_ref()).ok_or_else(|| {
                invalid(
                    name.span().start,
                    format!(
                        "theme `{}` is not one of auto, dark, light, plain",
                        name.get_ref()
                    ),
                )
            })?),
        };
        let mut keys = Rebind::default();
        if !raw.keys.is_empty() {
            // The table lost its spans; find each entry's line by parsing it spanned.
            let spanned = DeTable::parse(text)
                .map_err(|e| invalid(e.span().map_or(0, |s| s.start), e.message().to_string()))?;
            let table = spanned
                .get_ref()
                .iter()
                .find_map(|(k, v)| match v.get_ref() {
                    DeValue::Table(t) if k.get_ref() == "keys" => Some(t),
                    _ => None,
                });
            let Some(table) = table else {
                return Err(invalid(0, "`keys` must be a table: [keys]".into()));
            };
            // The table iterates in key order: bind in the file's, so a clash names its later line.
            let mut entries: Vec<_> = table.iter().collect();
            entries.sort_by_key(|(action, _)| action.span().start);
            for (action, key) in entries {
                let at = action.span().start;
                let name = action.get_ref();
                let DeValue::String(key) = key.get_ref() else {
                    let message = format!("keys.{name}: give the key as a string, e.g. \"x\"");
                    return Err(invalid(at, message));
                };
                keys.bind(name, key)
                    .map_err(|e| invalid(at, format!("keys.{name}: {e}")))?;
            }
        }
        Ok(Config {
            theme,
            scene: raw.scene,
            keys,
        })
    }

    /// The theme to draw with: the file's, else the terminal's.
    pub fn theme_or(&self, detected: impl FnOnce() -> Theme) -> Theme {
        self.theme.unwrap_or_else(detected)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_full_file_sets_the_theme_the_scene_and_keys() {
        let text =
            "theme = \"light\"\nscene = \"fig4-steel-sphere-r10-plate\"\n\n[keys]\nquit = \"x\"\n";
        let config = Config::parse("config.toml", text).unwrap();
        assert_eq!(config.theme, Some(Theme::Light));
        assert_eq!(config.scene.as_deref(), Some("fig4-steel-sphere-r10-plate"));
        assert_eq!(config.keys.moved(), [('x', "quit")]);
        assert_eq!(Config::parse("c", "").unwrap(), Config::default());
        assert_eq!(Config::parse("c", "theme = \"auto\"").unwrap().theme, None);
        assert_eq!(config.theme_or(|| Theme::Dark), Theme::Light);
    }

    /// Each mistake is reported at its file and line.
    #[test]
    fn mistakes_name_the_file_and_line() {
        let cases = [
            ("theme = \"solarized\"", 1, "theme `solarized`"),
            ("\n\ncolour = \"dark\"", 3, "unknown field `colour`"),
            (
                "scene = \"a\"\n[keys]\nquit = \"xy\"",
                3,
                "keys.quit: `xy` is not a key",
            ),
            ("[keys]\nleave = \"x\"", 2, "unknown action `leave`"),
            ("[keys]\nquit = 1", 2, "give the key as a string"),
            (
                "[keys]\nquit = \"x\"\nsave = \"x\"",
                3,
                "given to both quit and save",
            ),
            (
                "[keys]\nbranch = \"x\"\nquit = \"x\"",
                3,
                "keys.quit: `x` is given to both branch and quit",
            ),
            (
                "[keys]\nquit = \"x\"\nbranch = \"x\"",
                3,
                "keys.branch: `x` is given to both quit and branch",
            ),
            ("theme = dark", 1, ""),
        ];
        for (text, line, says) in cases {
            let e = Config::parse("/home/u/.config/hertz-tui/config.toml", text).unwrap_err();
            let message = e.to_string();
            let at = format!("/home/u/.config/hertz-tui/config.toml:{line}: ");
            assert!(message.starts_with(&at), "{text:?}: {message}");
            assert!(message.contains(says), "{text:?}: {message}");
        }
    }

    #[test]
    fn the_file_is_found_where_xdg_says() {
        let xdg = path(Some(Path::new("/x/cfg")), Some(Path::new("/home/u")));
        assert_eq!(xdg, Some(PathBuf::from("/x/cfg/hertz-tui/config.toml")));
        let home = path(None, Some(Path::new("/home/u")));
        assert_eq!(
            home,
            Some(PathBuf::from("/home/u/.config/hertz-tui/config.toml"))
        );
        // A relative XDG_CONFIG_HOME is invalid by the XDG spec and ignored.
        let relative = path(Some(Path::new("cfg")), Some(Path::new("/home/u")));
        assert_eq!(relative, home);
        assert_eq!(path(None, None), None);
        let missing = Config::read(Path::new("/nonexistent/hertz-tui/config.toml"));
        assert_eq!(missing, Ok(Config::default()));
    }
}
