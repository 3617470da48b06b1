//! The models pane names every row in one form: the longest of label, id and abbreviation that
//! fits all of them, at the sizes the explorer is used at.

use hertz_tui::model::ForceModel;
use hertz_tui::ui::action::Action;
use hertz_tui::ui::update::update;
use ratatui::buffer::Buffer;

use super::render::{app, render};

/// The model a pane row names and the forms its name is in (0 label, 1 id, 2 abbreviation: some
/// names are two forms at once, such as `proposed`).
fn forms_of(name: &str) -> Option<(ForceModel, Vec<usize>)> {
    ForceModel::ALL.into_iter().find_map(|m| {
        let forms: Vec<usize> = [m.label(), m.name(), m.short()]
            .iter()
            .enumerate()
            .filter(|(_, n)| **n == name)
            .map(|(form, _)| form)
            .collect();
        (!forms.is_empty()).then_some((m, forms))
    })
}

/// The names in the checklist rows (`▸[x] ─●── name …✓`) of the screen, in order.
fn pane_names(rows: &[String]) -> Vec<String> {
    rows.iter()
        .filter_map(|row| {
            let at = row.find("[x]").or_else(|| row.find("[ ]"))?;
            // The check box, a blank, the 4-cell sample, a blank, then the name padded to its
            // column, then the busy and fit marks.
            let rest: String = row[at..].chars().skip(3 + 1 + 4 + 1).collect();
            let name = rest.split("  ").next()?.trim_end_matches(['✓', '…']).trim();
            Some(name.to_string())
        })
        .collect()
}

#[test]
fn every_row_of_the_models_pane_is_named_in_one_form() {
    // (size, the form expected: 0 label, 1 id, 2 abbreviation).
    for ((width, height), expected) in [((80, 24), 2), ((120, 40), 0), ((160, 48), 0)] {
        let mut app = app();
        update(&mut app, Action::Resize(width, height));
        // Walk the cursor down the whole list so that every row is drawn once.
        let mut seen: Vec<(ForceModel, Vec<usize>)> = Vec::new();
        for _ in 0..120 {
            let terminal = render(&app, width, height);
            let buffer = terminal.backend().buffer();
            let rows = rows_of(buffer, width);
            for name in pane_names(&rows) {
                let found = forms_of(&name)
                    .unwrap_or_else(|| panic!("{width}×{height}: {name:?} is no model's name"));
                if !seen.iter().any(|(m, _)| *m == found.0) {
                    seen.push(found);
                }
            }
            update(&mut app, Action::Down);
        }
        assert_eq!(
            seen.len(),
            ForceModel::ALL.len(),
            "{width}×{height}: every model was shown"
        );
        for (model, forms) in &seen {
            assert!(
                forms.contains(&expected),
                "{width}×{height}: {model:?} named in form {forms:?}, the pane in {expected}"
            );
        }
    }
}

/// With calibration on, the pane's title at 80 columns still leaves a rule cell before the
/// results pane's title, and says that the laws are calibrated.
#[test]
fn the_calibrated_title_does_not_run_into_the_results_title() {
    let mut app = app();
    update(&mut app, Action::ToggleCalibration);
    for width in [80, 120, 160] {
        let height = if width == 80 { 24 } else { 40 };
        let terminal = render(&app, width, height);
        let rows: Vec<String> = terminal
            .backend()
            .buffer()
            .content
            .chunks(usize::from(width))
            .map(|row| row.iter().map(|c| c.symbol()).collect())
            .collect();
        let title = rows
            .iter()
            .find(|r| r.contains("Models · ✓ fits"))
            .unwrap_or_else(|| panic!("no models title at {width}"));
        assert!(title.contains("calibrated"), "{width}: {title}");
        if width == 80 {
            assert!(title.contains("─Results"), "{width}: {title}");
        }
    }
}

/// The regime box's "use: … · also fit: …" names its models in one form too (it mixed
/// "Thornton 1997" with "lankarani-nikravesh").
#[test]
fn the_regime_advice_names_its_models_in_one_form() {
    for (width, height) in [(80, 24), (120, 40), (160, 48), (200, 24)] {
        let mut app = app();
        update(&mut app, Action::Resize(width, height));
        let terminal = render(&app, width, height);
        let screen: String = terminal
            .backend()
            .buffer()
            .content
            .chunks(usize::from(width))
            .map(|row| row.iter().map(|c| c.symbol()).collect::<String>() + "\n")
            .collect();
        let mut names: Vec<String> = Vec::new();
        for line in screen.lines() {
            if let Some(used) = line.split("use: ").nth(1) {
                names.push(used.split(" (").next().unwrap().trim().to_string());
            }
            if let Some(also) = line.split("also fit: ").nth(1) {
                let also = also.trim_end_matches(['│', ' ']);
                names.extend(also.split(", ").map(|n| n.trim().to_string()));
            }
        }
        // At 80×24 the box has room for "use:" only.
        let shown = if width >= 120 { 3 } else { 1 };
        assert!(
            names.len() >= shown,
            "{width}×{height}: {names:?}\n{screen}"
        );
        let forms: Vec<Vec<usize>> = names
            .iter()
            .map(|n| {
                forms_of(n)
                    .unwrap_or_else(|| panic!("{width}×{height}: {n:?} is no model's name"))
                    .1
            })
            .collect();
        assert!(
            (0..3).any(|form| forms.iter().all(|f| f.contains(&form))),
            "{width}×{height}: {names:?} in forms {forms:?}"
        );
    }
}

/// The rows the layout snapshots blank: the pane lists the law table in its order under each
/// family's heading, every row with its law's glyph in its law's colour (the row's style in the
/// table), `[x]` on the checked laws, and says how many rows there are.
#[test]
fn the_models_pane_lists_the_table_in_order_with_each_laws_style() {
    use hertz_tui::chart::{Ink, model_glyph};
    use hertz_tui::ui::style::{Theme, sample};
    let theme = Theme::Dark;
    for (width, height) in [(80, 24), (160, 48)] {
        let mut app = app();
        update(&mut app, Action::Resize(width, height));
        let checked = app.checked_models();
        let left_width = usize::from(hertz_tui::ui::layout::left_width(
            ratatui::layout::Rect::new(0, 0, width, height),
        ));
        let mut seen: Vec<ForceModel> = Vec::new();
        for _ in 0..120 {
            let terminal = render(&app, width, height);
            let buffer = terminal.backend().buffer();
            let rows = rows_of(buffer, width);
            let mut family = None;
            for (y, row) in rows.iter().enumerate() {
                let left: String = row.chars().take(left_width).collect();
                if let Some(heading) = ForceModel::ALL
                    .iter()
                    .map(|m| m.spec().family)
                    .find(|f| left.trim_matches(['│', ' ']) == f.title())
                {
                    family = Some(heading);
                    continue;
                }
                let Some(name) = pane_names(std::slice::from_ref(row)).pop() else {
                    continue;
                };
                let (model, _) = forms_of(&name).unwrap();
                // The top row shown may be a law whose heading is scrolled off.
                let family = *family.get_or_insert(model.spec().family);
                assert_eq!(family, model.spec().family, "{model}: under its family");
                let glyph = sample(model_glyph(model), Ink::Model(model).dash());
                let at = row.find(&glyph).unwrap_or_else(|| panic!("{model}: {row}"));
                let x = row[..at].chars().count() + 1;
                let cell = &buffer[(x as u16, y as u16)];
                assert_eq!(cell.fg, theme.model_color(model), "{model}: its colour");
                let check = if checked.contains(&model) {
                    "[x]"
                } else {
                    "[ ]"
                };
                assert!(row.contains(check), "{model}: {check} in {row}");
                match seen.last() {
                    Some(last) if *last == model => {}
                    Some(last) if last.index() > model.index() => {}
                    Some(last) => {
                        assert!(!seen.contains(&model), "{model} once");
                        assert_eq!(model.index(), last.index() + 1, "{model} after {last}");
                        seen.push(model);
                    }
                    None => {
                        assert_eq!(model, ForceModel::ALL[0], "the table's first row on top");
                        seen.push(model);
                    }
                }
            }
            update(&mut app, Action::Down);
        }
        assert_eq!(seen, ForceModel::ALL.to_vec(), "{width}×{height}");
        let screen = super::render::text(render(&app, width, height).backend().buffer());
        let total = format!("of {} ", hertz_tui::ui::widgets::models::row_count());
        if width >= 120 {
            assert!(
                screen.contains(&total),
                "{width}×{height}: {total}\n{screen}"
            );
        }
    }
}

/// The rows of `buffer`, `width` cells each, a string a row.
fn rows_of(buffer: &Buffer, width: u16) -> Vec<String> {
    buffer
        .content
        .chunks(usize::from(width))
        .map(|row| row.iter().map(|c| c.symbol()).collect())
        .collect()
}
