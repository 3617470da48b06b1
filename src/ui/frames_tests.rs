use super::*;
use crate::model::presets::Registry;
use crate::ui::action::Action;
use crate::ui::app_tests::{key, settle, type_text};
use crate::ui::style::{MarkerStyle, Theme};
use crate::ui::testing::fig5_scene;
use crate::ui::update::update;
use ratatui::backend::CrosstermBackend;
use ratatui::crossterm::event::KeyCode;

/// Counts the writes it is given.
#[derive(Default)]
struct Writes {
    count: usize,
    bytes: Vec<u8>,
}

impl Write for Writes {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.count += 1;
        self.bytes.extend_from_slice(buf);
        Ok(buf.len())
    }

    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

fn app_of(width: u16, height: u16) -> App {
    let mut app = App::new(
        fig5_scene(),
        Registry::builtin().unwrap(),
        MarkerStyle::Braille,
        Theme::Plain,
    );
    update(&mut app, Action::Resize(width, height));
    app
}

#[test]
fn a_frame_is_one_synchronized_update_in_one_write() {
    let mut app = app_of(100, 30);
    let mut terminal = Frames::new(100, 30).unwrap();
    let mut out = Writes::default();
    draw_synchronized(&mut terminal, &mut out, &app).unwrap();
    assert_eq!(out.count, 1, "the whole frame in one write");
    let text = String::from_utf8_lossy(&out.bytes).into_owned();
    assert!(
        text.starts_with("\x1b[?2026h"),
        "begins the update (mode 2026)"
    );
    assert!(text.ends_with("\x1b[?2026l"), "ends it");
    assert!(
        text.contains("explorer"),
        "the frame was drawn between them"
    );

    // Nothing changed: the next frame writes nothing but the update's marks and the cursor's
    // hiding, still at once.
    let mut again = Writes::default();
    draw_synchronized(&mut terminal, &mut again, &app).unwrap();
    assert_eq!(again.count, 1);
    assert!(
        again.bytes.len() < 64,
        "{:?}",
        String::from_utf8_lossy(&again.bytes)
    );

    // A resize (the app's screen, from the terminal's resize event) redraws the whole screen
    // at the new size inside the update.
    update(&mut app, Action::Resize(120, 40));
    let mut resized = Writes::default();
    draw_synchronized(&mut terminal, &mut resized, &app).unwrap();
    assert_eq!(resized.count, 1);
    assert_eq!(terminal.area(), Rect::new(0, 0, 120, 40));
    let text = String::from_utf8_lossy(&resized.bytes).into_owned();
    assert!(text.starts_with("\x1b[?2026h"));
    assert!(text.contains("explorer"), "redrawn");
}

/// A frame as stock ratatui draws it: its terminal's own diff, through crossterm's backend.
struct Stock {
    terminal: Terminal<CrosstermBackend<FrameWriter>>,
    held: FrameWriter,
}

impl Stock {
    fn new(width: u16, height: u16) -> Stock {
        let held = FrameWriter::default();
        let terminal = Terminal::with_options(
            CrosstermBackend::new(held.clone()),
            TerminalOptions {
                viewport: Viewport::Fixed(Rect::new(0, 0, width, height)),
            },
        )
        .unwrap();
        Stock { terminal, held }
    }

    fn draw(&mut self, app: &App) -> Vec<u8> {
        queue!(self.held, BeginSynchronizedUpdate).unwrap();
        let screen = Rect::new(0, 0, app.screen.0, app.screen.1);
        if self.terminal.get_frame().area() != screen {
            self.terminal.resize(screen).unwrap();
        }
        self.terminal
            .draw(|frame| render::draw(frame, app))
            .unwrap();
        queue!(self.held, EndSynchronizedUpdate).unwrap();
        let mut out = Vec::new();
        self.held.send(&mut out).unwrap();
        out
    }
}

/// The bytes of every frame are stock ratatui's, byte for byte, through a session's keys: a
/// nudge of v₀ (every number and curve moves), an edit with the cursor shown, a wide character
/// typed into it (ratatui's own diff takes those frames), another view, a resize.
#[test]
fn every_frame_writes_the_bytes_stock_ratatui_writes() {
    let mut app = app_of(120, 36);
    settle(&mut app);
    let (mut frames, mut stock) = (Frames::new(120, 36).unwrap(), Stock::new(120, 36));
    let mut drawn = Vec::new();
    let mut check = |app: &App, what: &str| {
        let mut out = Writes::default();
        draw_synchronized(&mut frames, &mut out, app).unwrap();
        let (ours, stock) = (String::from_utf8_lossy(&out.bytes), stock.draw(app));
        let stock = String::from_utf8_lossy(&stock);
        // From a little before the first difference, if any.
        let same = ours.chars().zip(stock.chars()).take_while(|(a, b)| a == b);
        let from = same.count().saturating_sub(20);
        let near = |s: &str| s.chars().skip(from).take(200).collect::<String>();
        assert_eq!(near(&ours), near(&stock), "{what}");
        drawn.push(out.bytes);
    };
    check(&app, "the first frame");
    for (i, code) in [KeyCode::Home, KeyCode::PageDown, KeyCode::PageDown]
        .into_iter()
        .enumerate()
    {
        key(&mut app, code);
        settle(&mut app);
        check(&app, &format!("moving to v₀, key {i}"));
    }
    for code in [KeyCode::Char('l'), KeyCode::Char('l'), KeyCode::Char('h')] {
        key(&mut app, code);
        settle(&mut app);
        check(&app, &format!("nudged with {code}"));
    }
    key(&mut app, KeyCode::Enter);
    check(&app, "editing, the cursor shown");
    type_text(&mut app, "界界");
    check(&app, "wide characters typed");
    key(&mut app, KeyCode::Esc);
    check(&app, "the edit abandoned");
    key(&mut app, KeyCode::Char('v'));
    settle(&mut app);
    check(&app, "the next view");
    update(&mut app, Action::Resize(90, 30));
    check(&app, "resized");
    key(&mut app, KeyCode::Char('V'));
    settle(&mut app);
    check(&app, "back to the explorer, at the new size");

    let text: Vec<String> = drawn
        .iter()
        .map(|b| String::from_utf8_lossy(b).into_owned())
        .collect();
    assert!(
        text.iter().any(|t| t.contains("\x1b[?25h")),
        "some frame shows the cursor"
    );
    assert!(
        text.iter().any(|t| t.contains('界')),
        "some frame has a wide character"
    );
    assert!(
        text.iter().all(|t| t.len() > 40),
        "every frame changed cells"
    );
}
