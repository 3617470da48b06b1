//! The printed scripts in the real engines: runs `tests/engines/check.py` against the built
//! binary (docs/engines.md). It runs each installed engine's script on six scenes and compares the
//! engine's rebound e, F_max and contact time with what `translate` claims; an engine that is not
//! installed is skipped, and said so on the terminal (not captured), unless
//! `HERTZ_TUI_ENGINES=required` (as `.ci/run` sets), where a missing engine fails.

use std::io::Write;
use std::path::Path;
use std::process::Command;

/// Writes past the test harness's capture, so that a skip is seen in `cargo test`'s output.
fn say(text: &str) {
    let mut err = std::io::stderr();
    let _ = err.write_all(text.as_bytes());
    let _ = err.flush();
}

#[test]
fn printed_scripts_realise_their_claims_in_the_engines() {
    let required = std::env::var("HERTZ_TUI_ENGINES").is_ok_and(|v| v == "required");
    let check = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/engines/check.py");
    let output = Command::new("python3")
        .arg(&check)
        .arg("--binary")
        .arg(env!("CARGO_BIN_EXE_hertz-tui"))
        .output();
    let output = match output {
        Ok(output) => output,
        Err(e) if !required => {
            say(&format!(
                "\nengines: SKIPPED, python3 cannot be run ({e}); no engine was checked\n"
            ));
            return;
        }
        Err(e) => panic!("python3 cannot be run ({e}) and HERTZ_TUI_ENGINES=required"),
    };
    let text = String::from_utf8_lossy(&output.stdout);
    let summary = text.lines().last().unwrap_or("no summary line");
    // The table is the evidence: shown whether the test passes or not.
    say(&format!("\nengines (tests/engines/check.py):\n{text}"));
    if text.lines().any(|l| l.starts_with("skipped")) {
        say("engines: the engines marked skipped were NOT checked (.ci/run installs them)\n");
    }
    assert!(
        output.status.success(),
        "engine checks failed ({summary}):\n{text}\n{}",
        String::from_utf8_lossy(&output.stderr)
    );
}
