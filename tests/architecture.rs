//! The layering the design promises, checked on the source text: a folder's Rust files must not
//! name the modules and crates its rule forbids. The model layer (`src/model`) stands alone: no
//! UI, CLI or chart module of this crate, and none of the terminal, argument-parsing or figure
//! crates. Every path is checked, in `use` trees (grouped ones expanded) and in code, with `self::`
//! and `super::` resolved against the file's module, so `super::super::ui` from `src/model/x.rs`
//! is caught as `crate::ui`. Comments and string literals are not code and are skipped.
//!
//! A new rule is one more row of [`RULES`].

use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};

/// A folder and the paths its files must not name: `crate::…` (resolved through `self` and
/// `super`), `hertz_tui::…` (from outside the library) or an external crate.
struct Rule {
    folder: &'static str,
    forbidden: &'static [&'static str],
    /// Files of the folder the rule does not cover, each for a reason said where it is listed.
    except: &'static [&'static str],
}

const RULES: &[Rule] = &[
    Rule {
        folder: "src/model",
        forbidden: &[
            "crate::ui",
            "crate::cli",
            "crate::chart",
            "hertz_tui::ui",
            "hertz_tui::cli",
            "hertz_tui::chart",
            "ratatui",
            "crossterm",
            "tui_input",
            "clap",
            "plotters",
            "color_eyre",
        ],
        except: &[],
    },
    Rule {
        folder: "src/cli",
        forbidden: &["crate::ui", "hertz_tui::ui"],
        except: &[],
    },
    Rule {
        folder: "src/chart",
        forbidden: &["crate::ui", "hertz_tui::ui"],
        except: &[],
    },
    Rule {
        folder: "benches",
        forbidden: &["crate::ui", "hertz_tui::ui"],
        // The one benchmark whose subject is the explorer's drawing itself, in process.
        except: &["benches/frame.rs"],
    },
];

#[test]
fn every_folder_keeps_to_its_rule() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut report = String::new();
    for rule in RULES {
        for except in rule.except {
            assert!(
                root.join(except).is_file(),
                "{except} is excepted from {} but is no file",
                rule.folder
            );
        }
        let files = rust_files(&root.join(rule.folder));
        assert!(!files.is_empty(), "{} holds no .rs file", rule.folder);
        for file in files {
            let relative = file.strip_prefix(root).unwrap();
            if rule.except.iter().any(|e| relative == Path::new(e)) {
                continue;
            }
            let text = fs::read_to_string(&file).unwrap();
            let module = module_of(relative);
            for hit in violations(&text, &module, rule.forbidden) {
                let _ = writeln!(
                    report,
                    "{}:{}: `{}` names {} (forbidden in {})",
                    relative.display(),
                    hit.line,
                    hit.path,
                    hit.forbidden,
                    rule.folder
                );
            }
        }
    }
    assert!(report.is_empty(), "layering broken:\n{report}");
}

/// Every `.rs` file under `dir`, sorted.
fn rust_files(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(dir) = stack.pop() {
        for entry in fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                stack.push(path);
            } else if path.extension().is_some_and(|e| e == "rs") {
                out.push(path);
            }
        }
    }
    out.sort();
    out
}

/// The module a file is, below its crate root: `src/model/force/mod.rs` → `model::force`. Outside
/// `src`, each top-level file and each folder's `main.rs` is a crate root of its own (benches, tests).
fn module_of(relative: &Path) -> Vec<String> {
    let parts: Vec<String> = relative
        .iter()
        .map(|p| p.to_string_lossy().into_owned())
        .collect();
    let rest = match parts.as_slice() {
        [src, rest @ ..] if src == "src" => rest,
        [_folder, _crate_root] => return Vec::new(),
        [_folder, _crate_dir, rest @ ..] => rest,
        _ => return Vec::new(),
    };
    let mut module: Vec<String> = rest
        .iter()
        .map(|p| p.trim_end_matches(".rs").to_string())
        .collect();
    if matches!(
        module.last().map(String::as_str),
        Some("mod" | "lib" | "main")
    ) {
        module.pop();
    }
    module
}

#[derive(Debug, Clone, PartialEq)]
enum Token {
    Ident(String),
    /// `::`
    PathSep,
    Punct(char),
}

/// Rust tokens with their line, comments and literals dropped (only paths and braces matter).
fn tokens(text: &str) -> Vec<(Token, usize)> {
    let chars: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    let (mut i, mut line) = (0, 1);
    let at = |i: usize| chars.get(i).copied().unwrap_or('\0');
    while i < chars.len() {
        let c = chars[i];
        if c == '\n' {
            line += 1;
            i += 1;
        } else if c.is_whitespace() {
            i += 1;
        } else if c == '/' && at(i + 1) == '/' {
            while i < chars.len() && chars[i] != '\n' {
                i += 1;
            }
        } else if c == '/' && at(i + 1) == '*' {
            let mut depth = 0;
            while i < chars.len() {
                if chars[i] == '/' && at(i + 1) == '*' {
                    depth += 1;
                    i += 2;
                } else if chars[i] == '*' && at(i + 1) == '/' {
                    depth -= 1;
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    line += usize::from(chars[i] == '\n');
                    i += 1;
                }
            }
        } else if let Some(hashes) = raw_string_start(&chars, i) {
            // r"…", r#"…"#, br"…": no escapes, ends at a quote followed by as many hashes.
            i = chars[i..]
                .iter()
                .position(|&c| c == '"')
                .map_or(chars.len(), |p| i + p + 1);
            while i < chars.len() {
                if chars[i] == '"' && (1..=hashes).all(|h| at(i + h) == '#') {
                    i += 1 + hashes;
                    break;
                }
                line += usize::from(chars[i] == '\n');
                i += 1;
            }
        } else if c == '"' || (c == 'b' && at(i + 1) == '"') {
            i += if c == 'b' { 2 } else { 1 };
            while i < chars.len() && chars[i] != '"' {
                line += usize::from(chars[i] == '\n');
                i += if chars[i] == '\\' { 2 } else { 1 };
            }
            i += 1;
        } else if c == '\'' || (c == 'b' && at(i + 1) == '\'') {
            // A char literal ('x', '\n', '{', b'x'), or a lifetime ('a), which is skipped.
            let start = if c == 'b' { i + 1 } else { i };
            if at(start + 1) == '\\' {
                i = start + 2;
                while i < chars.len() && chars[i] != '\'' {
                    i += 1;
                }
                i += 1;
            } else if at(start + 2) == '\'' {
                i = start + 3;
            } else {
                i = start + 1;
            }
        } else if c == ':' && at(i + 1) == ':' {
            out.push((Token::PathSep, line));
            i += 2;
        } else if c.is_alphanumeric() || c == '_' {
            let start = if c == 'r' && at(i + 1) == '#' {
                i + 2
            } else {
                i
            };
            let mut end = start;
            while end < chars.len() && (chars[end].is_alphanumeric() || chars[end] == '_') {
                end += 1;
            }
            let word: String = chars[start..end].iter().collect();
            if !word.starts_with(|c: char| c.is_ascii_digit()) {
                out.push((Token::Ident(word), line));
            }
            i = end;
        } else {
            out.push((Token::Punct(c), line));
            i += 1;
        }
    }
    out
}

/// The number of `#`s if a raw string starts at `i` (`r"`, `r#"`, `br"`, …).
fn raw_string_start(chars: &[char], i: usize) -> Option<usize> {
    let previous_is_word = i > 0 && (chars[i - 1].is_alphanumeric() || chars[i - 1] == '_');
    if previous_is_word {
        return None;
    }
    let mut j = i;
    if chars.get(j) == Some(&'b') {
        j += 1;
    }
    if chars.get(j) != Some(&'r') {
        return None;
    }
    j += 1;
    let hashes = chars[j..].iter().take_while(|&&c| c == '#').count();
    (chars.get(j + hashes) == Some(&'"')).then_some(hashes)
}

/// One forbidden path found.
#[derive(Debug, PartialEq)]
struct Hit {
    line: usize,
    /// The path as resolved, e.g. `crate::ui::App`.
    path: String,
    forbidden: &'static str,
}

/// A path as written: its segments, each with its line.
type Segments = Vec<(String, usize)>;

/// The paths of `text` (a file of module `module`) that name a `forbidden` path.
fn violations(text: &str, module: &[String], forbidden: &[&'static str]) -> Vec<Hit> {
    let tokens = tokens(text);
    let mut hits = Vec::new();
    // Inline `mod name { … }` blocks the scan is inside, with the brace depth each opened at.
    let mut inline: Vec<(String, usize)> = Vec::new();
    let mut depth = 0;
    let mut i = 0;
    while i < tokens.len() {
        let mut paths = Vec::new();
        match &tokens[i].0 {
            Token::Ident(word) if word == "use" => {
                i = use_tree(&tokens, i + 1, Vec::new(), &mut paths);
            }
            Token::Ident(word) if word == "extern" => {
                match (tokens.get(i + 1), tokens.get(i + 2)) {
                    (Some((Token::Ident(k), _)), Some((Token::Ident(name), line)))
                        if k == "crate" =>
                    {
                        paths.push(vec![(name.clone(), *line)]);
                        i += 3;
                    }
                    _ => i += 1,
                }
            }
            Token::Ident(word) if word == "mod" => match (tokens.get(i + 1), tokens.get(i + 2)) {
                (Some((Token::Ident(name), _)), Some((Token::Punct('{'), _))) => {
                    inline.push((name.clone(), depth));
                    depth += 1;
                    i += 3;
                }
                _ => i += 1,
            },
            Token::Punct('{') => {
                depth += 1;
                i += 1;
            }
            Token::Punct('}') => {
                depth = depth.saturating_sub(1);
                if inline.last().is_some_and(|&(_, d)| d == depth) {
                    inline.pop();
                }
                i += 1;
            }
            Token::Punct('$') => {
                // `$crate::…` in a macro is this crate's own path; skip its segments.
                i += 2;
                while tokens.get(i).is_some_and(|(t, _)| *t == Token::PathSep)
                    && matches!(tokens.get(i + 1), Some((Token::Ident(_), _)))
                {
                    i += 2;
                }
            }
            Token::Ident(_) | Token::PathSep => {
                let (path, next) = code_path(&tokens, i);
                // A lone word is a name, not a path (a local called `clap` is no import).
                if path.len() > 1 || tokens[i].0 == Token::PathSep {
                    paths.push(path);
                }
                i = next;
            }
            Token::Punct(_) => i += 1,
        }
        if paths.is_empty() {
            continue;
        }
        let here: Vec<String> = module
            .iter()
            .cloned()
            .chain(inline.iter().map(|(name, _)| name.clone()))
            .collect();
        for path in paths {
            let resolved = resolve(&path, &here);
            for &f in forbidden {
                let want: Vec<&str> = f.split("::").collect();
                let named = resolved.len() >= want.len()
                    && resolved.iter().zip(&want).all(|((s, _), w)| s == w);
                if named {
                    hits.push(Hit {
                        line: resolved[want.len() - 1].1,
                        path: resolved
                            .iter()
                            .map(|(s, _)| s.as_str())
                            .collect::<Vec<_>>()
                            .join("::"),
                        forbidden: f,
                    });
                }
            }
        }
    }
    hits
}

/// The path starting at `i` in code (`a::b::c`, `::a::b`) and the index after it.
fn code_path(tokens: &[(Token, usize)], mut i: usize) -> (Segments, usize) {
    let mut path = Vec::new();
    if tokens[i].0 == Token::PathSep {
        i += 1;
    }
    while let Some((Token::Ident(word), line)) = tokens.get(i) {
        path.push((word.clone(), *line));
        i += 1;
        let continues = tokens.get(i).is_some_and(|(t, _)| *t == Token::PathSep)
            && matches!(tokens.get(i + 1), Some((Token::Ident(_), _)));
        if !continues {
            break;
        }
        i += 1;
    }
    (path, i)
}

/// Expands the use tree starting at `i` below `prefix` into `out`; returns the index after it.
fn use_tree(
    tokens: &[(Token, usize)],
    mut i: usize,
    mut prefix: Segments,
    out: &mut Vec<Segments>,
) -> usize {
    if tokens.get(i).is_some_and(|(t, _)| *t == Token::PathSep) {
        i += 1;
    }
    loop {
        match tokens.get(i) {
            Some((Token::Ident(word), line)) if word != "as" => {
                prefix.push((word.clone(), *line));
                i += 1;
                if tokens.get(i).is_some_and(|(t, _)| *t == Token::PathSep) {
                    i += 1;
                    continue;
                }
                out.push(prefix);
                // Skip `as name`.
                if matches!(tokens.get(i), Some((Token::Ident(w), _)) if w == "as") {
                    i += 2;
                }
                return i;
            }
            Some((Token::Punct('{'), _)) => {
                i += 1;
                loop {
                    match tokens.get(i) {
                        Some((Token::Punct('}'), _)) => return i + 1,
                        Some((Token::Punct(','), _)) => i += 1,
                        None => return i,
                        _ => i = use_tree(tokens, i, prefix.clone(), out),
                    }
                }
            }
            Some((Token::Punct('*'), _)) => {
                out.push(prefix);
                return i + 1;
            }
            _ => {
                if !prefix.is_empty() {
                    out.push(prefix);
                }
                return i;
            }
        }
    }
}

/// `path` with a leading `self`/`super` chain resolved against `module` to `crate::…`; any other
/// path is kept as written (`crate::…`, an external crate, or a name in scope).
fn resolve(path: &Segments, module: &[String]) -> Segments {
    let Some((first, line)) = path.first() else {
        return Vec::new();
    };
    let line = *line;
    let supers = path.iter().take_while(|(s, _)| s == "super").count();
    let base: &[String] = if supers > 0 {
        &module[..module.len().saturating_sub(supers)]
    } else if first == "self" {
        module
    } else {
        return path.clone();
    };
    let skip = supers.max(usize::from(first == "self"));
    std::iter::once(("crate".to_string(), line))
        .chain(base.iter().map(|m| (m.clone(), line)))
        .chain(path[skip..].iter().cloned())
        .collect()
}

#[cfg(test)]
mod checker {
    //! The checker itself: each test feeds it a source text that breaks (or keeps) a rule.
    use super::*;

    const MODEL: &[&str] = RULES[0].forbidden;

    fn lines(text: &str, file: &str) -> Vec<(usize, String)> {
        violations(text, &module_of(Path::new(file)), MODEL)
            .into_iter()
            .map(|h| (h.line, h.path))
            .collect()
    }

    #[test]
    fn a_use_of_the_ui_is_caught_with_its_line() {
        let text = "use super::power_law::PowerLaw;\nuse crate::ui::App;\n";
        assert_eq!(
            lines(text, "src/model/scene.rs"),
            [(2, "crate::ui::App".to_string())]
        );
    }

    #[test]
    fn grouped_uses_are_expanded() {
        let text = "use crate::{\n    model::Scene,\n    cli::{args::Cli, run},\n};\n";
        assert_eq!(
            lines(text, "src/model/scene.rs"),
            [
                (3, "crate::cli::args::Cli".to_string()),
                (3, "crate::cli::run".to_string())
            ]
        );
    }

    #[test]
    fn super_chains_that_leave_the_model_are_resolved() {
        // From model::cylinder::fit, super::super is model and super::super::super the crate.
        let text = "use super::super::pair::ContactPair;\nuse super::super::super::chart::Kind;\n";
        assert_eq!(
            lines(text, "src/model/cylinder/fit.rs"),
            [(2, "crate::chart::Kind".to_string())]
        );
        // Inside an inline `mod tests` one more super is needed to get as far: three reach only
        // crate::model, four the crate; after the block, three reach the crate again.
        let text = "mod tests {\n    fn f() { super::super::super::ui::draw(); }\n    fn g() { super::super::super::super::ui::draw(); }\n}\nfn h() { super::super::super::ui::draw(); }\n";
        assert_eq!(
            lines(text, "src/model/cylinder/fit.rs"),
            [
                (3, "crate::ui::draw".to_string()),
                (5, "crate::ui::draw".to_string())
            ]
        );
    }

    #[test]
    fn external_crates_are_caught_in_code_and_attributes() {
        let text = "#[derive(clap::Parser)]\nstruct A;\nfn f() { let _ = ::ratatui::text::Line::default(); }\nextern crate plotters;\n";
        assert_eq!(
            lines(text, "src/model/a.rs"),
            [
                (1, "clap::Parser".to_string()),
                (3, "ratatui::text::Line::default".to_string()),
                (4, "plotters".to_string())
            ]
        );
    }

    #[test]
    fn comments_strings_and_lone_names_are_not_imports() {
        let text = r##"
            //! Drawn by crate::ui::plot.
            /* use crate::ui::App; /* nested */ use clap::Parser; */
            const A: &str = "use crate::ui::App;";
            const B: &str = r#"crate::cli::run "quoted" "#;
            const C: char = '"';
            fn f<'a>(clap: &'a str) -> &'a str { let ui = clap; ui }
            use crate::format::round_trip;
        "##;
        assert_eq!(lines(text, "src/model/engine/mod.rs"), []);
    }

    #[test]
    fn module_paths_follow_the_file_layout() {
        assert_eq!(
            module_of(Path::new("src/model/force/mod.rs")),
            ["model", "force"]
        );
        assert_eq!(
            module_of(Path::new("src/model/scene.rs")),
            ["model", "scene"]
        );
        assert!(module_of(Path::new("src/lib.rs")).is_empty());
        assert!(module_of(Path::new("benches/impact.rs")).is_empty());
        assert!(module_of(Path::new("tests/model/main.rs")).is_empty());
        assert_eq!(module_of(Path::new("tests/model/presets.rs")), ["presets"]);
    }
}
