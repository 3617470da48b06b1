//! The README's picture of the explorer is what the real explorer draws: the ```` ```text
//! screen=WxH ```` block is the default scene rendered at that size (fixed stand-ins for wall
//! times, as in the layout snapshots). When the drawing changes on purpose, run this test with
//! `HERTZ_UPDATE_README=1` to write the new picture into the README.

use std::fs;

use super::render::{app, render, text};

/// The picture block: its first and last line indices (the fences) and its size.
fn screen_block(lines: &[&str]) -> Option<(usize, usize, u16, u16)> {
    let start = lines
        .iter()
        .position(|l| l.starts_with("```text screen="))?;
    let size = lines[start].strip_prefix("```text screen=")?.trim();
    let (w, h) = size.split_once('x')?;
    let end = start
        + 1
        + lines[start + 1..]
            .iter()
            .position(|l| l.starts_with("```"))?;
    Some((start, end, w.parse().ok()?, h.parse().ok()?))
}

#[test]
fn the_readme_shows_what_the_explorer_draws() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/README.md");
    let readme = fs::read_to_string(path).unwrap();
    let lines: Vec<&str> = readme.lines().collect();
    let (start, end, width, height) =
        screen_block(&lines).expect("the README has a ```text screen=WxH block");
    let drawn = text(render(&app(), width, height).backend().buffer());
    let drawn: Vec<&str> = drawn.lines().map(str::trim_end).collect();
    let shown: Vec<&str> = lines[start + 1..end].iter().map(|l| l.trim_end()).collect();
    if shown == drawn {
        return;
    }
    if std::env::var_os("HERTZ_UPDATE_README").is_some() {
        let mut out: Vec<&str> = lines[..=start].to_vec();
        out.extend(&drawn);
        out.extend(&lines[end..]);
        fs::write(path, out.join("\n") + "\n").unwrap();
        return;
    }
    let row = shown
        .iter()
        .zip(&drawn)
        .position(|(a, b)| a != b)
        .unwrap_or(shown.len().min(drawn.len()));
    panic!(
        "README.md's picture differs from the explorer at row {row} ({} rows shown, {} drawn): \
         rerun with HERTZ_UPDATE_README=1 if the change is meant",
        shown.len(),
        drawn.len()
    );
}
