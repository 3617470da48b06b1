//! End to end: the real binary in a detached tmux session of fixed size with a UTF-8 locale. Edits
//! v₀ with a paste, reads the pane with `capture-pane`, checks that the charts and the results
//! changed, opens the stability view (tab 3) and halves its step, comes back, quits with `q` and
//! checks that the terminal is restored (the shell's screen is back and the line discipline cooks
//! input again). Waits on the screen's content, never on fixed sleeps.
//!
//! Also pastes with bracketed paste (`paste-buffer -p`) outside a field and into one, and answers
//! the question `q` asks when there are unsaved changes.
//!
//! Needs tmux (CI installs it; locally `apt-get install -y tmux`). It is never skipped: without
//! tmux it fails with one line saying so, before anything is created (no temp folder to leave).

use std::path::PathBuf;
use std::process::{Command, Output};
use std::thread;
use std::time::{Duration, Instant};

use hertz_tui::format::units::sig;
use hertz_tui::model::ForceModel;
use hertz_tui::model::impact::{SolveOptions, solve_impact};
use hertz_tui::model::presets::{DEFAULT_SCENE, Registry};

use super::scratch::{self, Folder};

const WIDTH: u16 = 100;
const HEIGHT: u16 = 30;
/// Overall limit of every wait; the polls themselves are 50 ms apart.
const TIMEOUT: Duration = Duration::from_secs(60);
const POLL: Duration = Duration::from_millis(50);

/// A tmux server of its own, killed on drop. Its socket (`-S`) and the config folder are in a
/// temporary folder that goes after it: tmux leaves its socket file behind when killed.
struct Tmux {
    socket: PathBuf,
    config_home: PathBuf,
    _folder: Folder,
}

impl Tmux {
    fn start() -> Tmux {
        Tmux::start_as("")
    }

    /// A server and config folder of their own for each `tag`: tests run side by side.
    fn start_as(tag: &str) -> Tmux {
        if Command::new("tmux").arg("-V").output().is_err() {
            panic!("tmux is needed for the end-to-end tests: install it (apt-get install -y tmux)");
        }
        let folder = scratch::folder(format!("e2e-{tag}").trim_end_matches('-'));
        let config_home = folder.join("config");
        std::fs::create_dir_all(&config_home).unwrap();
        let tmux = Tmux {
            socket: folder.join("tmux.sock"),
            config_home,
            _folder: folder,
        };
        let size = (WIDTH.to_string(), HEIGHT.to_string());
        let out = tmux.run(&[
            "-f",
            "/dev/null",
            "new-session",
            "-d",
            "-s",
            "e2e",
            "-x",
            &size.0,
            "-y",
            &size.1,
            "sh",
        ]);
        assert!(
            out.status.success(),
            "tmux new-session failed: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        tmux
    }

    fn run(&self, args: &[&str]) -> Output {
        Command::new("tmux")
            .arg("-S")
            .arg(&self.socket)
            .args(args)
            .env("LANG", "C.UTF-8")
            .env("LC_ALL", "C.UTF-8")
            .env("XDG_CONFIG_HOME", &self.config_home)
            .env_remove("NO_COLOR")
            .output()
            .unwrap_or_else(|e| {
                panic!("cannot run tmux ({e}): install it, e.g. apt-get install -y tmux")
            })
    }

    /// Types `keys` (tmux key names, or literal text with `-l`).
    fn keys(&self, keys: &[&str]) {
        let mut args = vec!["send-keys", "-t", "e2e"];
        args.extend_from_slice(keys);
        assert!(self.run(&args).status.success(), "send-keys {keys:?}");
    }

    /// Pastes `text` as the terminal would: wrapped in bracketed-paste marks when the app asked
    /// for them.
    fn paste(&self, text: &str) {
        assert!(self.run(&["set-buffer", "--", text]).status.success());
        assert!(
            self.run(&["paste-buffer", "-p", "-t", "e2e"])
                .status
                .success()
        );
    }

    fn literal(&self, text: &str) {
        assert!(
            self.run(&["send-keys", "-t", "e2e", "-l", text])
                .status
                .success()
        );
    }

    fn screen(&self) -> String {
        let out = self.run(&["capture-pane", "-p", "-t", "e2e"]);
        String::from_utf8_lossy(&out.stdout).into_owned()
    }

    /// Polls the pane until `ready` holds; panics with the last screen after the timeout.
    fn wait_for(&self, what: &str, ready: impl Fn(&str) -> bool) -> String {
        let start = Instant::now();
        loop {
            let screen = self.screen();
            if ready(&screen) {
                return screen;
            }
            if start.elapsed() > TIMEOUT {
                panic!("timed out waiting for {what}; the screen was:\n{screen}");
            }
            thread::sleep(POLL);
        }
    }
}

impl Drop for Tmux {
    /// Never panics (a panic while a failed test unwinds would abort the whole binary). The
    /// folder with the socket and the config is removed next, when the fields drop.
    fn drop(&mut self) {
        let _ = Command::new("tmux")
            .arg("-S")
            .arg(&self.socket)
            .arg("kill-server")
            .output();
    }
}

fn is_braille(c: char) -> bool {
    ('\u{2801}'..='\u{28FF}').contains(&c)
}

/// The braille cells of the screen with their positions: the curves of the charts.
fn curves(screen: &str) -> Vec<(usize, usize, char)> {
    screen
        .lines()
        .enumerate()
        .flat_map(|(row, line)| {
            line.chars()
                .enumerate()
                .filter(|(_, c)| is_braille(*c))
                .map(move |(col, c)| (row, col, c))
        })
        .collect()
}

/// The results row of a model, as drawn in the compact table.
fn results_row<'a>(screen: &'a str, name: &str) -> &'a str {
    screen
        .lines()
        .find(|l| l.contains(&format!("  {name}  ")) || l.contains(&format!(" {name}  ")))
        .unwrap_or("")
}

/// x_max of the proposed model at `v0`, as the results table prints it (µm, 4 digits).
fn expected_x_max(v0: f64) -> String {
    let registry = Registry::builtin().unwrap();
    let mut scene = registry.scene(DEFAULT_SCENE).unwrap();
    scene.impact.v0 = v0;
    let q = scene.quasistatic().unwrap();
    let solution = solve_impact(
        ForceModel::Proposed,
        &scene.impact_params(&q),
        &SolveOptions::default(),
    )
    .unwrap();
    sig(solution.summary.x_max * 1e6, 4)
}

#[test]
fn edit_v0_in_the_real_binary_and_quit_cleanly() {
    let tmux = Tmux::start();
    tmux.literal("echo before-$((40+2))");
    tmux.keys(&["Enter"]);
    tmux.wait_for("the shell to echo", |s| s.contains("before-42"));

    let binary = env!("CARGO_BIN_EXE_hertz-tui");
    tmux.literal(&format!("{binary}; echo exited-$?"));
    tmux.keys(&["Enter"]);
    let x_before = expected_x_max(0.3);
    let before = tmux.wait_for("the explorer with its results", |s| {
        s.contains("F(x) force–approach")
            && results_row(s, "proposed").contains(&x_before)
            && !s.contains("computing…")
            && s.contains("v₀     0.3 m/s")
    });
    assert!(
        !before.contains("before-42"),
        "the explorer uses the alternate screen"
    );
    assert!(!curves(&before).is_empty(), "braille curves are drawn");

    // A paste on a model never runs its characters as keys ("2" would open tab 2, " " uncheck).
    tmux.keys(&["End"]);
    tmux.paste("2 0");
    tmux.wait_for("the paste to be refused", |s| s.contains("paste ignored"));
    assert!(
        tmux.screen().contains("F(x) force–approach"),
        "still on tab 1"
    );
    // The cursor back on v₀ (Home, then PgDn twice to the impact section): a paste opens its
    // editor with the text, Enter commits.
    tmux.keys(&["Home"]);
    tmux.keys(&["PageDown"]);
    tmux.keys(&["PageDown"]);
    tmux.paste("50 mm/s");
    tmux.keys(&["Enter"]);
    let x_after = expected_x_max(0.05);
    assert_ne!(x_before, x_after);
    let after = tmux.wait_for("the results of v₀ = 0.05 m/s", |s| {
        s.contains("v₀     0.05 m/s")
            && results_row(s, "proposed").contains(&x_after)
            && !s.contains("computing…")
            && s.contains('*')
            && (s.contains("elastic") || s.contains("yield begins"))
    });
    assert_ne!(
        results_row(&before, "proposed"),
        results_row(&after, "proposed"),
        "the results changed"
    );
    assert_ne!(curves(&before), curves(&after), "the charts changed");

    // Tab 3: every fixed-step method at the RK4 critical step, judged, its bounds measured, all
    // off the UI thread.
    tmux.keys(&["3"]);
    let stability = tmux.wait_for("the stability view with verdicts and bounds", |s| {
        s.contains("Methods at this step")
            && s.contains("symplectic-euler")
            && s.contains("h·ω_max = 2.83")
            && (s.contains("stable") || s.contains("diverged at t =") || s.contains("drift"))
            && !s.contains("computing…")
            && !s.contains("measuring…")
            && s.contains("auto: the rk4 critical step")
    });
    assert!(
        !stability.contains("Hertz estimate"),
        "the explorer's results are gone: {stability}"
    );
    // ← halves the step: the methods run again at h·ω_max = √2.
    tmux.keys(&["Left"]);
    tmux.wait_for("the methods at half the step", |s| {
        s.contains("h·ω_max = 1.41") && !s.contains("computing…")
    });
    tmux.keys(&["1"]);
    tmux.wait_for("the explorer again", |s| {
        s.contains("F(x) force–approach") && results_row(s, "proposed").contains(&x_after)
    });

    // Unsaved changes: q asks; q again is "another key" and stays, the edit kept; y quits.
    tmux.keys(&["q"]);
    tmux.wait_for("the question", |s| {
        s.contains("Unsaved changes: y quit without saving · s save and quit · other keys stay")
    });
    tmux.keys(&["q"]);
    tmux.wait_for("the explorer still, edited", |s| {
        !s.contains("Unsaved changes") && s.contains("v₀     0.05 m/s")
    });
    tmux.keys(&["q"]);
    tmux.wait_for("the question again", |s| s.contains("Unsaved changes"));
    tmux.keys(&["y"]);
    let restored = tmux.wait_for("the shell after the explorer", |s| s.contains("exited-0"));
    assert!(
        restored.contains("before-42"),
        "the primary screen is back:\n{restored}"
    );
    assert!(!restored.contains("F(x) force–approach"), "{restored}");
    assert!(curves(&restored).is_empty(), "{restored}");
    // Raw mode is off: Enter ends a line again, so the shell runs the command.
    tmux.literal("echo after-$((1+1))");
    tmux.keys(&["Enter"]);
    tmux.wait_for("the shell to run a command", |s| s.contains("after-2"));
}

/// A bouncing ball as a user writes it (docs/systems.md §1), A = 1 mm at 20 Hz.
const BALL_FILE: &str = r#"name = "My ball"
[body1]
shape = "sphere"
radius = 0.01
material = "steel"
[body2]
shape = "plane"
material = "steel"
[impact]
v0 = 0.25
restitution = 0.5
plastic_indentation = 0.0
[system]
kind = "bouncing-ball"
amplitude = 0.001
frequency = 20.0
"#;

#[test]
fn a_system_scene_file_with_set_opens_in_the_system_view_and_saves_its_edit() {
    let tmux = Tmux::start_as("system-");
    let dir = tmux.config_home.join("scenes-here");
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("my-ball.toml");
    std::fs::write(&file, BALL_FILE).unwrap();
    let saved = dir.join("my-ball-saved.toml");

    let binary = env!("CARGO_BIN_EXE_hertz-tui");
    tmux.literal(&format!(
        "{binary} --scene {} --set 'system.amplitude=0.8 mm'; echo exited-$?",
        file.display()
    ));
    tmux.keys(&["Enter"]);
    tmux.wait_for("the explorer", |s| s.contains("F(x) force–approach"));
    tmux.keys(&["6"]);
    // The file's table with the override, in its unit: Γ = Aω²/g = 0.8 mm·(40π/s)²/g.
    tmux.wait_for("the system view on the file's table", |s| {
        s.contains("800 µm") && s.contains("Γ = Aω²/g = 1.288")
    });
    // → on the amplitude (the first row): 5 % more, then saved to a path.
    tmux.keys(&["Right"]);
    tmux.wait_for("the amplitude stepped", |s| s.contains("840 µm"));
    tmux.keys(&["s"]);
    tmux.wait_for("the save prompt", |s| s.contains("Save"));
    tmux.keys(&["C-u"]);
    tmux.literal(&saved.display().to_string());
    tmux.keys(&["Enter"]);
    tmux.wait_for("the save", |s| s.contains("saved "));
    // Saved: q quits without asking.
    tmux.keys(&["q"]);
    tmux.wait_for("the shell after the explorer", |s| s.contains("exited-0"));
    let text = std::fs::read_to_string(&saved).unwrap();
    assert!(
        text.contains("[system]") && text.contains("amplitude = 0.00084"),
        "{text}"
    );
}

#[test]
fn the_branch_key_moves_in_the_config_file_and_a_clash_names_the_key() {
    let tmux = Tmux::start_as("branch-key-");
    let config = tmux.config_home.join("hertz-tui").join("config.toml");
    std::fs::create_dir_all(config.parent().unwrap()).unwrap();
    let binary = env!("CARGO_BIN_EXE_hertz-tui");
    // Two actions on one key: refused before the terminal is taken, naming the key and line.
    std::fs::write(&config, "[keys]\nbranch = \"x\"\nquit = \"x\"\n").unwrap();
    let out = Command::new(binary)
        .env("XDG_CONFIG_HOME", &tmux.config_home)
        .stdin(std::process::Stdio::null())
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success(), "{stderr}");
    assert!(
        stderr.contains("config.toml:3: keys.quit: `x` is given to both branch and quit"),
        "{stderr}"
    );

    std::fs::write(&config, "[keys]\nbranch = \"x\"\n").unwrap();
    assert!(
        tmux.run(&["resize-window", "-t", "e2e", "-x", "160", "-y", "48"])
            .status
            .success()
    );
    tmux.literal(&format!("{binary} --scene bouncing-ball; echo exited-$?"));
    tmux.keys(&["Enter"]);
    tmux.wait_for("the explorer", |s| s.contains("F(x) force–approach"));
    tmux.keys(&["6"]);
    // The status line's hints name the key in force.
    tmux.wait_for("the system view's hints", |s| {
        s.lines().last().is_some_and(|l| l.contains("x branch"))
    });
    tmux.keys(&["x"]);
    tmux.wait_for("x continuing the branch", |s| {
        s.contains("continuing the orbit over the diagram's range (x hides it)")
    });
    tmux.keys(&["?"]);
    // The whole help in the predicate: a capture can catch a frame half written (CI did), so
    // a check made after the wait could read the chart beneath the popup.
    tmux.wait_for("the help naming x for the branch", |s| {
        s.contains("Help · keys") && s.contains("f m t o x") && s.contains("x branch")
    });
    tmux.keys(&["Escape"]);
    // (A key right after Esc would read as Alt with it.)
    tmux.wait_for("the help closed", |s| !s.contains("Help · keys"));
    tmux.keys(&["x"]);
    tmux.wait_for("x hiding the branch", |s| {
        s.contains("continued branch hidden (x shows it)")
    });
    tmux.keys(&["q"]);
    tmux.wait_for("the shell after the explorer", |s| s.contains("exited-0"));
}
