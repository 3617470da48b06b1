//! Every TOML and shell block of the README and of every `docs/*.md` runs as written.
//!
//! Their fenced blocks are found by their info string and checked whatever section or file they
//! are in, so new sections and new documents are covered without touching this test:
//!
//! - ```` ```toml ```` — a scene (it has `[body1]`) is read by the strict scene reader, a material
//!   (it has `youngs_modulus`) by the material reader, the explorer's config file (it has `theme`,
//!   `scene` or `[keys]`) by the config reader; any other block must at least be TOML.
//!   ```` ```toml file=NAME ```` also writes the block to `NAME` in the folder the commands run in,
//!   so that a later `--scene NAME` finds it.
//! - ```` ```sh ```` — each command (lines joined at a trailing `\`, `#` comments dropped) must be
//!   `hertz-tui …`, optionally after `VAR=value` settings and with `> FILE` at the end; it runs
//!   against the built binary in a temporary folder with its own user-presets folder and must
//!   exit 0. Anything else (cargo, the explorer itself, pipes) fails the test unless the block is
//!   marked ```` ```sh no-run ````, which keeps it out: use it for what cannot run headless here.
//!
//! - ```` ```console ```` — a shown session: each `$ hertz-tui …` line is run as a `sh` command
//!   is, and what it prints must be the lines under it, up to the next `$` line, exactly (trailing
//!   spaces and blank lines at the end aside). Shown output is checked, never left to go stale.
//!
//! Other languages (`text` captures and error examples) are not run.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

use hertz_tui::model::presets::Registry;
use hertz_tui::model::scene_file::{Document, decode_material, parse_scene};
use hertz_tui::ui::config::Config;

use crate::scratch::{self, Folder};

/// A fenced block: its info string, the line of its document it starts on, its text.
struct Block {
    info: Vec<String>,
    line: usize,
    text: String,
}

impl Block {
    fn language(&self) -> &str {
        self.info.first().map_or("", String::as_str)
    }

    fn has(&self, word: &str) -> bool {
        self.info.iter().any(|w| w == word)
    }

    fn option(&self, key: &str) -> Option<&str> {
        self.info
            .iter()
            .find_map(|w| w.strip_prefix(key)?.strip_prefix('='))
    }
}

fn blocks(markdown: &str) -> Vec<Block> {
    let mut blocks = Vec::new();
    let mut open: Option<Block> = None;
    for (i, line) in markdown.lines().enumerate() {
        let fence = line.trim_start().strip_prefix("```");
        match (&mut open, fence) {
            (None, Some(info)) => {
                open = Some(Block {
                    info: info.split_whitespace().map(str::to_string).collect(),
                    line: i + 1,
                    text: String::new(),
                })
            }
            (Some(_), Some(_)) => blocks.extend(open.take()),
            (Some(block), None) => {
                block.text.push_str(line);
                block.text.push('\n');
            }
            (None, None) => {}
        }
    }
    assert!(open.is_none(), "a fenced block is not closed");
    blocks
}

/// Splits a command line into words: quotes group, `#` outside quotes starts a comment.
fn words(line: &str) -> Vec<String> {
    let mut words = Vec::new();
    let mut word: Option<String> = None;
    let mut quote: Option<char> = None;
    for c in line.chars() {
        match (quote, c) {
            (Some(q), c) if c == q => quote = None,
            (Some(_), c) => word.get_or_insert_default().push(c),
            (None, '\'' | '"') => {
                quote = Some(c);
                word.get_or_insert_default();
            }
            (None, '#') if word.is_none() => break,
            (None, c) if c.is_whitespace() => words.extend(word.take()),
            (None, c) => word.get_or_insert_default().push(c),
        }
    }
    assert!(quote.is_none(), "unclosed quote in: {line}");
    words.extend(word);
    words
}

/// The commands of a shell block, continuation lines joined.
fn commands(text: &str) -> Vec<String> {
    let mut commands = Vec::new();
    let mut current = String::new();
    for line in text.lines() {
        match line.trim_end().strip_suffix('\\') {
            Some(head) => {
                current.push_str(head);
                current.push(' ');
            }
            None => {
                current.push_str(line);
                if !words(&current).is_empty() {
                    commands.push(current.trim().to_string());
                }
                current.clear();
            }
        }
    }
    commands
}

/// Runs one documented command in `dir` and returns what it printed; the error says why it does
/// not run as written.
fn run(command: &str, dir: &Path) -> Result<String, String> {
    let mut words = words(command);
    let mut stdout_file = None;
    if let Some(i) = words.iter().position(|w| w == ">") {
        let target = words.get(i + 1).ok_or("`>` without a file")?.clone();
        if words.len() != i + 2 {
            return Err("only `> FILE` at the end is supported".into());
        }
        stdout_file = Some(dir.join(target));
        words.truncate(i);
    }
    if words
        .iter()
        .any(|w| w.contains('|') || w == "&&" || w == ";")
    {
        return Err("pipes and command lists are not run: mark the block `sh no-run`".into());
    }
    let settings = words.iter().take_while(|w| w.contains('=')).count();
    let (env, rest) = words.split_at(settings);
    match rest.first().map(String::as_str) {
        Some("hertz-tui") => {}
        Some(other) => {
            return Err(format!(
                "`{other}` is not hertz-tui: mark the block `sh no-run` if it must stay"
            ));
        }
        None => return Err("no command".into()),
    }
    let args = &rest[1..];
    let headless = [
        "list",
        "solve",
        "bench",
        "sweep",
        "plot",
        "translate",
        "restitution",
        "system",
        "orbit",
        "bifurcation",
        "fit",
        "continue",
        "map",
        "merge",
        "help",
    ];
    if !args
        .first()
        .is_some_and(|a| headless.contains(&a.as_str()) || a.starts_with("--h"))
    {
        return Err(
            "opens the explorer, which needs a terminal: mark the block `sh no-run`".into(),
        );
    }
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_hertz-tui"));
    cmd.args(args)
        .current_dir(dir)
        .env("XDG_CONFIG_HOME", dir.join("config"))
        .env_remove("NO_COLOR");
    for setting in env {
        let (key, value) = setting.split_once('=').unwrap_or((setting, ""));
        cmd.env(key, value);
    }
    let out = cmd.output().map_err(|e| format!("cannot run: {e}"))?;
    if !out.status.success() {
        return Err(format!(
            "exit {:?}: {}",
            out.status.code(),
            String::from_utf8_lossy(&out.stderr).trim()
        ));
    }
    if let Some(file) = stdout_file {
        fs::write(&file, &out.stdout)
            .map_err(|e| format!("cannot write {}: {e}", file.display()))?;
        return Ok(String::new());
    }
    String::from_utf8(out.stdout).map_err(|e| format!("output is not UTF-8: {e}"))
}

/// A `console` block's sessions: each `$ ` command with the output shown under it.
fn sessions(text: &str) -> Vec<(String, String)> {
    let mut sessions: Vec<(String, String)> = Vec::new();
    for line in text.lines() {
        match (line.strip_prefix("$ "), sessions.last_mut()) {
            (Some(command), _) => sessions.push((command.trim().to_string(), String::new())),
            (None, Some((_, shown))) => {
                shown.push_str(line);
                shown.push('\n');
            }
            (None, None) => {}
        }
    }
    sessions
}

/// Output compared line by line without trailing spaces or trailing blank lines.
fn normalised(output: &str) -> String {
    let lines: Vec<&str> = output.lines().map(str::trim_end).collect();
    let end = lines
        .iter()
        .rposition(|l| !l.is_empty())
        .map_or(0, |i| i + 1);
    lines[..end].join("\n")
}

/// The first line where `shown` and `printed` differ, both quoted, or `None` when they agree.
fn first_difference(shown: &str, printed: &str) -> Option<String> {
    let (shown, printed) = (normalised(shown), normalised(printed));
    if shown == printed {
        return None;
    }
    let mut p = printed.lines().enumerate().peekable();
    let mut eliding = false;
    for (i, line) in shown.lines().enumerate() {
        if line == ELIDED {
            eliding = true;
            continue;
        }
        loop {
            match p.next() {
                Some((_, printed)) if printed == line => break,
                Some(_) if eliding => {}
                other => {
                    return Some(format!(
                        "shown line {} is {line:?} but the command prints {:?}",
                        i + 1,
                        other.map_or("(nothing)", |(_, l)| l)
                    ));
                }
            }
        }
        eliding = false;
    }
    match (eliding, p.next()) {
        (false, Some((_, extra))) => Some(format!(
            "the command prints {extra:?} after the shown lines"
        )),
        _ => None,
    }
}

/// A shown line standing for any number of printed lines (a long output cut in the docs).
const ELIDED: &str = "…";

/// A TOML block of the document `name` read as what it is; `Err` says why it is refused.
fn check_toml(name: &str, block: &Block, registry: &Registry) -> Result<(), String> {
    let origin = format!("{name}:{}", block.line);
    let doc = Document::parse(&origin, &block.text).map_err(|e| e.to_string())?;
    let table = doc.table();
    if table.contains_key("body1") {
        parse_scene(&origin, &block.text, registry.material_catalog())
            .map(drop)
            .map_err(|e| e.to_string())
    } else if ["theme", "keys", "scene"]
        .iter()
        .any(|k| table.contains_key(*k))
    {
        // The explorer's config file.
        Config::parse(&origin, &block.text)
            .map(drop)
            .map_err(|e| e.to_string())
    } else if table.contains_key("youngs_modulus") {
        decode_material(&doc, "readme")
            .map(drop)
            .map_err(|e| e.to_string())
    } else {
        Ok(())
    }
}

/// What checking one document found.
#[derive(Default)]
struct Checked {
    failures: Vec<String>,
    commands_run: usize,
}

/// Checks every TOML and shell block of the document `name` (its text `markdown`), running the
/// commands in `dir`.
fn check_document(name: &str, markdown: &str, dir: &Path, registry: &Registry) -> Checked {
    let mut checked = Checked::default();
    for block in blocks(markdown) {
        match block.language() {
            "toml" => {
                if let Err(e) = check_toml(name, &block, registry) {
                    checked
                        .failures
                        .push(format!("{name}:{}: toml: {e}", block.line));
                }
                if let Some(file) = block.option("file") {
                    fs::write(dir.join(file), &block.text).unwrap();
                }
            }
            "sh" if !block.has("no-run") => {
                for command in commands(&block.text) {
                    checked.commands_run += 1;
                    if let Err(e) = run(&command, dir) {
                        checked
                            .failures
                            .push(format!("{name}:{}: `{command}`: {e}", block.line));
                    }
                }
            }
            "console" => {
                for (command, shown) in sessions(&block.text) {
                    checked.commands_run += 1;
                    let problem = match run(&command, dir) {
                        Ok(printed) => first_difference(&shown, &printed),
                        Err(e) => Some(e),
                    };
                    if let Some(problem) = problem {
                        checked
                            .failures
                            .push(format!("{name}:{}: `{command}`: {problem}", block.line));
                    }
                }
            }
            _ => {}
        }
    }
    checked
}

/// A temporary folder for a document's commands, with its own empty user-presets folder and the
/// shipped example data at `presets/data/` as in a checkout, so that `--data presets/data/…` runs
/// as written. Removed when dropped.
fn command_dir(label: &str) -> Folder {
    let dir = scratch::folder(label);
    fs::create_dir_all(dir.join("config")).unwrap();
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("presets/data");
    let copy = dir.join("presets/data");
    fs::create_dir_all(&copy).unwrap();
    for entry in fs::read_dir(&data).unwrap() {
        let path = entry.unwrap().path();
        fs::copy(&path, copy.join(path.file_name().unwrap())).unwrap();
    }
    dir
}

#[test]
fn every_toml_and_command_block_of_the_readme_runs_as_written() {
    let readme = fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/README.md")).unwrap();
    let dir = command_dir("readme");
    let registry = Registry::builtin().unwrap();
    let checked = check_document("README.md", &readme, &dir, &registry);
    assert!(
        checked.failures.is_empty(),
        "{}",
        checked.failures.join("\n")
    );
    assert!(
        checked.commands_run >= 5,
        "the README's five questions were found"
    );
}

#[test]
fn every_toml_and_command_block_of_the_docs_runs_as_written() {
    let docs = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs");
    let mut names: Vec<PathBuf> = fs::read_dir(&docs)
        .unwrap()
        .map(|entry| entry.unwrap().path())
        .filter(|path| path.extension().is_some_and(|e| e == "md"))
        .collect();
    names.sort();
    assert!(
        names.iter().any(|p| p.ends_with("performance.md")),
        "the docs were found: {names:?}"
    );
    let registry = Registry::builtin().unwrap();
    let mut failures = Vec::new();
    for path in &names {
        let name = format!("docs/{}", path.file_name().unwrap().to_string_lossy());
        let dir = command_dir("docs");
        let text = fs::read_to_string(path).unwrap();
        failures.extend(check_document(&name, &text, &dir, &registry).failures);
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn the_block_reader_and_the_runner_refuse_what_would_not_run() {
    let markdown = "text\n```sh no-run\ncargo test\n```\n```toml file=a.toml\nx = 1\n```\n";
    let found = blocks(markdown);
    assert_eq!(found.len(), 2);
    assert!(found[0].has("no-run") && found[0].language() == "sh");
    assert_eq!(
        (found[1].option("file"), found[1].line),
        (Some("a.toml"), 5)
    );
    assert_eq!(
        words(r#"hertz-tui solve --scene "my scene.toml"  # comment"#),
        ["hertz-tui", "solve", "--scene", "my scene.toml"]
    );
    assert_eq!(
        commands("hertz-tui solve \\\n  --scene x\n\n"),
        ["hertz-tui solve    --scene x"]
    );
    let dir = scratch::folder("readme-refusals");
    for (command, why) in [
        ("cargo test", "is not hertz-tui"),
        (
            "hertz-tui --scene fig5-steel-sphere-r10-plate",
            "opens the explorer",
        ),
        ("hertz-tui list | head", "pipes"),
        ("hertz-tui solve --scene nowhere", "exit Some(2)"),
    ] {
        let error = run(command, &dir).unwrap_err();
        assert!(error.contains(why), "{command}: {error}");
    }
    let registry = Registry::builtin().unwrap();
    let sphere_with_length = Block {
        info: vec!["toml".into()],
        line: 1,
        text: "name = \"x\"\n[body1]\nshape = \"sphere\"\nradius = 0.01\nlength = 0.1\nmaterial = \"steel\"\n[body2]\nshape = \"plane\"\nmaterial = \"steel\"\n[impact]\nv0 = 0.3\nrestitution = 0.6\nplastic_indentation = 0.0\n".into(),
    };
    let shown = sessions("$ hertz-tui list\na\nb  \n\n$ hertz-tui help\n");
    assert_eq!(
        shown,
        [
            ("hertz-tui list".to_string(), "a\nb  \n\n".to_string()),
            ("hertz-tui help".to_string(), String::new()),
        ]
    );
    assert_eq!(first_difference(&shown[0].1, "a\nb\n"), None);
    assert!(
        first_difference(&shown[0].1, "a\nc\n")
            .is_some_and(|d| d.contains("line 2") && d.contains("\"c\"")),
        "a changed line is found"
    );
    assert!(
        first_difference(&shown[0].1, "a\n").is_some(),
        "a missing line is found"
    );
    assert!(
        first_difference("a\nb", "a\nb\nc").is_some(),
        "an extra printed line is found"
    );
    let cut = "a\n…\nd\n…";
    assert_eq!(first_difference(cut, "a\nb\nc\nd\ne\n"), None);
    assert_eq!(first_difference(cut, "a\nd\n"), None);
    assert!(
        first_difference(cut, "a\nb\nc\n").is_some_and(|d| d.contains("\"d\"")),
        "a shown line after a cut must still be printed"
    );
    let error = check_toml("README.md", &sphere_with_length, &registry).unwrap_err();
    assert!(
        error.contains("`body1.length` is not used by a sphere"),
        "{error}"
    );
}

/// The README is the first screen and the five questions; everything else lives in `docs/`.
#[test]
fn the_readme_stays_under_25_kb() {
    let bytes = fs::metadata(concat!(env!("CARGO_MANIFEST_DIR"), "/README.md"))
        .unwrap()
        .len();
    assert!(
        bytes < 25 * 1024,
        "README.md is {bytes} bytes: move detail into docs/"
    );
}
