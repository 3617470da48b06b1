//! What a user feels: the time from a key to the last byte of the frame it causes, measured on a
//! pseudo-terminal driving the real release binary, as a terminal emulator would see it.
//!
//! `cargo bench --bench pty` opens the explorer at 160×48 and at 80×24 with every law checked (a
//! scene file of its own), waits until the first frames settle, moves to v₀ and nudges it with `l`
//! and `h` in turn, one key at a time, each after the last has settled. A key's last byte is the end
//! of the last frame it causes (the `ESC[?2026l` that closes a synchronized update), where the
//! output then stays quiet for 50 ms; the latency is from just before the key is written to the
//! read of that mark. A nudge draws at once and again as the solver's reports come in, so a key
//! causes several frames; their bytes are counted together. Then 200 keys are written at once: the
//! frames drawn until the output settles and the time to settle.
//!
//! Beside the times, what a key costs the binary whatever else the machine runs: the CPU time of
//! its threads from the key to the settled output (the kernel's per-thread run time, in
//! `/proc/<pid>/task/<tid>/schedstat`: the UI thread, the one with the process's id, apart from
//! the solver and input threads), and its minor page faults (`/proc/<pid>/stat`).
//!
//! `HERTZ_TUI_BASELINE=<path of another hertz-tui build>` measures that build too, its sessions
//! open beside this build's and the keys alternating between them, so both see the same machine.
//! `HERTZ_PTY_SAMPLES` sets the keys per size and build (default 200).
//!
//! Every wait is bounded: a binary that dies or stops drawing fails the run with a message.

use std::fs::File;
use std::io::{Read, Write};
use std::os::unix::process::CommandExt;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::sync::mpsc::{self, Receiver, RecvTimeoutError};
use std::thread;
use std::time::{Duration, Instant};

use hertz_tui::model::ForceModel;
use rustix::fs::{Mode, OFlags};
use rustix::pty::{OpenptFlags, grantpt, openpt, ptsname, unlockpt};
use rustix::termios::{Winsize, tcsetwinsize};

mod machine;
use machine::load_average;

/// The terminal sizes measured, the larger first (the budget is stated for it).
const SIZES: [(u16, u16); 2] = [(160, 48), (80, 24)];
/// Output quiet this long after a frame's end means the key has been fully answered.
const QUIET: Duration = Duration::from_millis(50);
/// The start-up settles when quiet this long (the first solves of every law run meanwhile).
const STARTUP_QUIET: Duration = Duration::from_millis(500);
/// No key may take longer than this to settle, nor the start-up.
const LIMIT: Duration = Duration::from_secs(30);
/// Keys written at once in the burst case.
const BURST: usize = 200;
/// Bursts per size and build.
const BURSTS: usize = 5;
/// The end of a synchronized update: every frame ends with it.
const FRAME_END: &[u8] = b"\x1b[?2026l";

fn main() {
    // `cargo bench` passes `--bench` (and a filter, if any): nothing here to choose.
    let samples: usize = std::env::var("HERTZ_PTY_SAMPLES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(200)
        .max(1);
    let mut builds = vec![Build {
        label: "this",
        path: PathBuf::from(env!("CARGO_BIN_EXE_hertz-tui")),
    }];
    if let Some(path) = std::env::var_os("HERTZ_TUI_BASELINE") {
        builds.insert(
            0,
            Build {
                label: "baseline",
                path: PathBuf::from(path),
            },
        );
    }
    if let Err(e) = run(&builds, samples) {
        eprintln!("pty bench failed: {e}");
        std::process::exit(1);
    }
}

struct Build {
    label: &'static str,
    path: PathBuf,
}

fn run(builds: &[Build], samples: usize) -> Result<(), String> {
    // Removed when dropped, a panic's unwinding included.
    let dir = tempfile::Builder::new()
        .prefix("hertz-pty-bench-")
        .tempdir()
        .map_err(|e| format!("cannot create a temporary folder: {e}"))?;
    measure_all(builds, samples, dir.path())
}

fn measure_all(builds: &[Build], samples: usize, dir: &Path) -> Result<(), String> {
    let scene = dir.join("every-law.toml");
    std::fs::write(&scene, every_law_scene())
        .map_err(|e| format!("cannot write the scene: {e}"))?;
    let started = Instant::now();
    println!(
        "hertz-tui on a pty: key → last byte of its frames; v₀ nudged with l/h, {} laws checked, {samples} keys per size and build",
        ForceModel::ALL.len()
    );
    for build in builds {
        println!("{:<8} {}", build.label, build.path.display());
    }
    println!("load average (1, 5, 15 min) at start: {}", load_average());
    println!(
        "\nms from the key to the end of its last frame (median, p99, max) and of its first frame \
         (median, p99); frames per key (median, range); bytes per key (median: all frames, first)"
    );
    println!(
        "CPU µs per key (the UI thread: median and mean; the other threads: median); minor page faults per key (mean)"
    );
    println!(
        "{:<8} {:<8} {:>6} {:>6} {:>6}   {:>6} {:>6}   {:<9}  {:>6} {:>6}   {:>6} {:>6} {:>6} {:>6}",
        "size",
        "build",
        "last",
        "p99",
        "max",
        "first",
        "p99",
        "frames",
        "bytes",
        "first",
        "ui µs",
        "mean",
        "others",
        "faults"
    );
    let mut bursts = Vec::new();
    for (width, height) in SIZES {
        let mut sessions = builds
            .iter()
            .map(|b| Session::open(b, &scene, dir, width, height))
            .collect::<Result<Vec<_>, _>>()?;
        for session in &mut sessions {
            session.settle(Instant::now(), STARTUP_QUIET)?;
            // v₀: Home, then PgDn twice to the impact section.
            for key in ["\x1b[H", "\x1b[6~", "\x1b[6~"] {
                session.key(key.as_bytes())?;
            }
        }
        let mut keys: Vec<Vec<Answer>> = vec![Vec::new(); sessions.len()];
        for i in 0..samples {
            let key: &[u8] = if i % 2 == 0 { b"l" } else { b"h" };
            for (session, answers) in sessions.iter_mut().zip(&mut keys) {
                answers.push(session.key(key)?);
            }
        }
        for (session, answers) in sessions.iter().zip(&keys) {
            print_row(width, height, session.label, answers);
        }
        for session in &mut sessions {
            let burst: Vec<u8> = b"lh".iter().copied().cycle().take(BURST).collect();
            let answers = (0..BURSTS)
                .map(|_| session.key(&burst))
                .collect::<Result<Vec<_>, _>>()?;
            bursts.push((width, height, session.label, answers));
        }
    }
    println!(
        "\n{BURST} keys written at once ({BURSTS} bursts): frames drawn until settled, time to the last frame's end"
    );
    for (width, height, label, answers) in &bursts {
        let frames: Vec<String> = answers.iter().map(|a| a.frames.to_string()).collect();
        let mut times: Vec<f64> = answers.iter().map(|a| a.latency_ms()).collect();
        times.sort_by(f64::total_cmp);
        println!(
            "{:<8} {:<8} frames {:<16} settled in {:.2}–{:.2} ms (median {:.2})",
            format!("{width}x{height}"),
            label,
            frames.join(" "),
            times[0],
            times[times.len() - 1],
            percentile(&times, 0.5),
        );
    }
    println!("\nload average (1, 5, 15 min) at end: {}", load_average());
    println!("ran in {:.0} s", started.elapsed().as_secs_f64());
    Ok(())
}

/// The explorer's default scene (Fig. 5) with every law checked.
fn every_law_scene() -> String {
    let names: Vec<String> = ForceModel::ALL
        .iter()
        .map(|m| format!("\"{}\"", m.name()))
        .collect();
    format!(
        "name = \"Fig. 5 with every law\"\nmodels = [{}]\n\n\
         [body1]\nshape = \"sphere\"\nradius = 0.01\nmaterial = \"steel\"\n\n\
         [body2]\nshape = \"plane\"\nmaterial = \"steel\"\n\n\
         [impact]\nv0 = 0.3\nrestitution = 0.6\nplastic_indentation = 2.3e-6\n",
        names.join(", ")
    )
}

fn print_row(width: u16, height: u16, label: &str, answers: &[Answer]) {
    let sorted = |value: fn(&Answer) -> f64| {
        let mut values: Vec<f64> = answers.iter().map(value).collect();
        values.sort_by(f64::total_cmp);
        values
    };
    let last = sorted(Answer::latency_ms);
    let first = sorted(Answer::first_ms);
    let frames = sorted(|a| a.frames as f64);
    let mean =
        |value: fn(&Answer) -> f64| answers.iter().map(value).sum::<f64>() / answers.len() as f64;
    let faults = mean(|a| a.cost.faults as f64);
    println!(
        "{:<8} {:<8} {:>6.2} {:>6.2} {:>6.2}   {:>6.2} {:>6.2}   {:>2} ({}–{})  {:>6.0} {:>6.0}   {:>6.0} {:>6.0} {:>6.0} {:>6.1}",
        format!("{width}x{height}"),
        label,
        percentile(&last, 0.5),
        percentile(&last, 0.99),
        last[last.len() - 1],
        percentile(&first, 0.5),
        percentile(&first, 0.99),
        percentile(&frames, 0.5),
        frames[0],
        frames[frames.len() - 1],
        percentile(&sorted(|a| a.bytes as f64), 0.5),
        percentile(&sorted(|a| a.first_bytes as f64), 0.5),
        percentile(&sorted(|a| a.cost.ui_ns as f64 / 1e3), 0.5),
        mean(|a| a.cost.ui_ns as f64 / 1e3),
        percentile(&sorted(|a| a.cost.others_ns as f64 / 1e3), 0.5),
        faults,
    );
}

/// The value at fraction `q` of `sorted`, by nearest rank.
fn percentile(sorted: &[f64], q: f64) -> f64 {
    let rank = ((q * sorted.len() as f64).ceil() as usize).clamp(1, sorted.len());
    sorted[rank - 1]
}

/// What the terminal saw after a write.
#[derive(Clone, Default)]
struct Answer {
    /// From just before the write to the read of the last frame's end.
    latency: Duration,
    /// From just before the write to the read of the first frame's end.
    first: Duration,
    frames: usize,
    bytes: usize,
    /// The bytes up to the first frame's end.
    first_bytes: usize,
    /// What the binary spent on it.
    cost: Cost,
}

/// CPU time and page faults of a process, or their growth over a key.
#[derive(Clone, Copy, Default)]
struct Cost {
    /// Run time of the thread whose id is the process's (the event loop's), in ns.
    ui_ns: u64,
    /// Run time of its other threads (solvers, input), in ns.
    others_ns: u64,
    /// Minor page faults of the whole process.
    faults: u64,
}

impl Cost {
    /// What process `pid` has spent so far (zero where /proc cannot say: the bench still runs).
    fn of(pid: u32) -> Cost {
        let mut cost = Cost::default();
        if let Ok(tasks) = std::fs::read_dir(format!("/proc/{pid}/task")) {
            for task in tasks.flatten() {
                let Ok(stat) = std::fs::read_to_string(task.path().join("schedstat")) else {
                    continue;
                };
                let ns: u64 = stat
                    .split_whitespace()
                    .next()
                    .and_then(|n| n.parse().ok())
                    .unwrap_or(0);
                if task.file_name().to_str() == Some(&pid.to_string()) {
                    cost.ui_ns += ns;
                } else {
                    cost.others_ns += ns;
                }
            }
        }
        // Field 10 of stat is minflt; the command name (field 2) may hold spaces, so count from
        // its closing parenthesis.
        cost.faults = std::fs::read_to_string(format!("/proc/{pid}/stat"))
            .ok()
            .and_then(|s| {
                let rest = &s[s.rfind(')')? + 1..];
                rest.split_whitespace().nth(7)?.parse().ok()
            })
            .unwrap_or(0);
        cost
    }

    fn since(self, before: Cost) -> Cost {
        Cost {
            ui_ns: self.ui_ns.saturating_sub(before.ui_ns),
            others_ns: self.others_ns.saturating_sub(before.others_ns),
            faults: self.faults.saturating_sub(before.faults),
        }
    }
}

impl Answer {
    fn latency_ms(&self) -> f64 {
        self.latency.as_secs_f64() * 1e3
    }

    fn first_ms(&self) -> f64 {
        self.first.as_secs_f64() * 1e3
    }
}

/// A piece of one read of the terminal's output, cut after each frame's end: when it was read,
/// its bytes, whether a frame ends with it.
struct Chunk {
    at: Instant,
    bytes: usize,
    frame_end: bool,
}

/// A binary running on a pty of its own, its output read on a thread.
struct Session {
    label: &'static str,
    child: Child,
    master: File,
    output: Receiver<Chunk>,
}

impl Session {
    fn open(
        build: &Build,
        scene: &Path,
        dir: &Path,
        width: u16,
        height: u16,
    ) -> Result<Session, String> {
        let fail = |what: &str, e: &dyn std::fmt::Display| format!("{what}: {e}");
        let master = openpt(OpenptFlags::RDWR | OpenptFlags::NOCTTY | OpenptFlags::CLOEXEC)
            .map_err(|e| fail("openpt", &e))?;
        grantpt(&master).map_err(|e| fail("grantpt", &e))?;
        unlockpt(&master).map_err(|e| fail("unlockpt", &e))?;
        let name = ptsname(&master, Vec::new()).map_err(|e| fail("ptsname", &e))?;
        let slave = rustix::fs::open(
            name.as_c_str(),
            OFlags::RDWR | OFlags::NOCTTY | OFlags::CLOEXEC,
            Mode::empty(),
        )
        .map_err(|e| fail("open the pty", &e))?;
        let size = Winsize {
            ws_row: height,
            ws_col: width,
            ws_xpixel: 0,
            ws_ypixel: 0,
        };
        tcsetwinsize(&slave, size).map_err(|e| fail("set the pty size", &e))?;
        let slave = File::from(slave);
        let stdio = || slave.try_clone().map(Stdio::from);
        let mut command = Command::new(&build.path);
        command
            .arg("--scene")
            .arg(scene)
            .env("TERM", "xterm-256color")
            .env("LANG", "C.UTF-8")
            .env("LC_ALL", "C.UTF-8")
            .env("XDG_CONFIG_HOME", dir)
            .env_remove("NO_COLOR")
            .stdin(stdio().map_err(|e| fail("dup", &e))?)
            .stdout(stdio().map_err(|e| fail("dup", &e))?)
            .stderr(stdio().map_err(|e| fail("dup", &e))?);
        // SAFETY: between fork and exec only two system calls, no allocation or lock: a session
        // of its own, with the pty (its standard input) as its controlling terminal.
        unsafe {
            command.pre_exec(|| {
                rustix::process::setsid()?;
                rustix::process::ioctl_tiocsctty(rustix::stdio::stdin())?;
                Ok(())
            });
        }
        let child = command
            .spawn()
            .map_err(|e| format!("cannot start {}: {e}", build.path.display()))?;
        drop(slave);
        let master = File::from(master);
        let reader = master.try_clone().map_err(|e| fail("dup", &e))?;
        let (send, output) = mpsc::channel();
        thread::Builder::new()
            .name("pty-reader".into())
            .spawn(move || read_output(reader, send))
            .map_err(|e| fail("cannot start the reader", &e))?;
        Ok(Session {
            label: build.label,
            child,
            master,
            output,
        })
    }

    /// Writes `keys`, then reads until the frames they cause have settled.
    /// Also what the binary spent on them, from just before the write until it settled.
    fn key(&mut self, keys: &[u8]) -> Result<Answer, String> {
        let before = Cost::of(self.child.id());
        let start = Instant::now();
        self.master
            .write_all(keys)
            .map_err(|e| format!("{}: cannot write a key: {e}", self.label))?;
        let mut answer = self.settle(start, QUIET)?;
        answer.cost = Cost::of(self.child.id()).since(before);
        Ok(answer)
    }

    /// Reads until at least one frame has ended and nothing more came for `quiet`.
    fn settle(&mut self, start: Instant, quiet: Duration) -> Result<Answer, String> {
        let deadline = Instant::now() + LIMIT;
        let mut answer = Answer::default();
        loop {
            let wait = match answer.frames {
                0 => deadline.saturating_duration_since(Instant::now()),
                _ => quiet,
            };
            match self.output.recv_timeout(wait) {
                Ok(chunk) => {
                    answer.bytes += chunk.bytes;
                    if chunk.frame_end {
                        answer.frames += 1;
                        answer.latency = chunk.at.saturating_duration_since(start);
                        if answer.frames == 1 {
                            answer.first = answer.latency;
                            answer.first_bytes = answer.bytes;
                        }
                    }
                }
                Err(RecvTimeoutError::Timeout) if answer.frames > 0 => return Ok(answer),
                Err(RecvTimeoutError::Timeout) => {
                    return Err(format!("{}: no frame within {LIMIT:?}", self.label));
                }
                Err(RecvTimeoutError::Disconnected) => {
                    let status = match self.child.try_wait() {
                        Ok(Some(status)) => status.to_string(),
                        _ => "its output closed".into(),
                    };
                    return Err(format!("{}: the binary stopped ({status})", self.label));
                }
            }
            if Instant::now() > deadline {
                return Err(format!(
                    "{}: output never settled within {LIMIT:?}",
                    self.label
                ));
            }
        }
    }
}

impl Drop for Session {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// Reads the pty until it closes (the binary has exited), counting frame ends across reads.
fn read_output(mut master: File, chunks: mpsc::Sender<Chunk>) {
    let mut buffer = vec![0u8; 1 << 16];
    let mut matched = 0;
    loop {
        let n = match master.read(&mut buffer) {
            Ok(0) | Err(_) => return,
            Ok(n) => n,
        };
        let at = Instant::now();
        let mut piece = 0;
        for &byte in &buffer[..n] {
            piece += 1;
            matched = if byte == FRAME_END[matched] {
                matched + 1
            } else {
                usize::from(byte == FRAME_END[0])
            };
            if matched == FRAME_END.len() {
                matched = 0;
                let chunk = Chunk {
                    at,
                    bytes: std::mem::take(&mut piece),
                    frame_end: true,
                };
                if chunks.send(chunk).is_err() {
                    return;
                }
            }
        }
        let chunk = Chunk {
            at,
            bytes: piece,
            frame_end: false,
        };
        if piece > 0 && chunks.send(chunk).is_err() {
            return;
        }
    }
}
