//! Every checked model stays visible in every chart of the explorer, at every size from 80×24 to
//! 200×50, with colour and without: counted in rendered frames, a model's own cells are those
//! that show what the chart of its curve alone shows there (its dots, in its colour) and change
//! when its curve is taken out of the chart (same axes, same marks), and each of
//! n models keeps at least [`MIN_SHARE_TIMES_N`]/n of the cells its curve covers drawn alone, and
//! at least [`MIN_CELLS`]. Before the painter shared the cells curves pass through together, the curve
//! drawn last took them all: Hunt–Crossley kept 3–21 cells beside Lankarani–Nikravesh's 83–250,
//! and in Fig. 4 elastic Hertz 5 under dry friction's 267.

use ratatui::Terminal;
use ratatui::backend::TestBackend;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;

use crate::chart::{Chart, Ink};
use crate::chart::kind::ChartKind;
use crate::model::ForceModel;
use crate::model::presets::Registry;
use crate::model::scene_file::SceneView;
use crate::ui::MarkerStyle;
use crate::ui::action::Action;
use crate::ui::app::App;
use crate::ui::app_tests::settle;
use crate::ui::style::Theme;
use crate::ui::update::update;
use crate::ui::widgets::common::pane;
use crate::ui::widgets::graph;

use super::chart::describe;
use super::layout::layout;

/// A model among n keeps at least this share of the cells its curve covers alone, over n: half
/// what it would keep if every curve lay on every other (measured: 0.39 at worst of two, 0.14 of
/// five, against 0.25 and 0.1 asked).
const MIN_SHARE_TIMES_N: f64 = 0.5;
/// Fewest cells of its own a checked model keeps in each chart (measured: 5 at worst, F(t) at
/// 80×24 among five).
const MIN_CELLS: usize = 4;

const SIZES: [(u16, u16); 4] = [(80, 24), (120, 40), (160, 48), (200, 50)];

fn app_on(preset: &str, models: &[ForceModel], theme: Theme, (w, h): (u16, u16)) -> App {
    let registry = Registry::builtin().unwrap();
    let scene = registry.scene(preset).unwrap();
    let options = registry.scene_view(preset).unwrap().options;
    let view = SceneView {
        models: models.to_vec(),
        options,
    };
    let mut app = App::open(scene, view, registry, MarkerStyle::Braille, theme);
    update(&mut app, Action::Resize(w, h));
    settle(&mut app);
    app
}

/// `chart` drawn in `area` of a `size` screen, and the plot's rectangle.
fn draw(chart: &Chart, size: (u16, u16), area: Rect, theme: Theme, roomy: bool) -> (Buffer, Rect) {
    let mut terminal = Terminal::new(TestBackend::new(size.0, size.1)).unwrap();
    terminal
        .draw(|frame| {
            graph::render(frame, area, pane("", theme, roomy), chart, MarkerStyle::Braille, theme)
        })
        .unwrap();
    let inner = pane("", theme, roomy).inner(area);
    let plot = graph::frame_of(inner, chart).plot;
    (terminal.backend().buffer().clone(), plot)
}

/// Cells of `plot` where the frame of every curve shows one curve as the frame of it alone does
/// (its dots, in its colour) and differs from the frame without it: where that curve, and no
/// other, is seen.
fn own(all: &Buffer, without: &Buffer, alone: &Buffer, plot: Rect) -> usize {
    plot.positions()
        .filter(|&p| all[p] != without[p] && all[p] == alone[p])
        .count()
}

/// Cells of `plot` with anything drawn.
fn drawn(a: &Buffer, plot: Rect) -> usize {
    plot.positions().filter(|&p| a[p].symbol() != " ").count()
}

/// For each chart the explorer shows of `app` on a `size` screen, each series: its model, its
/// own cells and the cells it covers alone.
fn own_cells(app: &App, size: (u16, u16)) -> Vec<(ChartKind, ForceModel, usize, usize)> {
    let mut out = Vec::new();
    for first in ChartKind::ALL {
        let areas = layout(Rect::new(0, 0, size.0, size.1), first, |_| 0).unwrap();
        for &(kind, area) in areas.charts.iter().filter(|(k, _)| *k == first) {
            let inner = pane("", app.theme, areas.roomy).inner(area);
            let chart = describe(
                app,
                kind,
                inner.width.saturating_sub(7),
                inner.height.saturating_sub(4),
            );
            let (all, plot) = draw(&chart, size, area, app.theme, areas.roomy);
            for (i, series) in chart.series.iter().enumerate() {
                let Ink::Model(model) = series.ink else {
                    continue;
                };
                let mut without = chart.clone();
                without.series.remove(i);
                let mut alone = chart.clone();
                alone.series = vec![series.clone()];
                alone.marks.clear();
                let (rest, _) = draw(&without, size, area, app.theme, areas.roomy);
                let (solo, _) = draw(&alone, size, area, app.theme, areas.roomy);
                out.push((kind, model, own(&all, &rest, &solo, plot), drawn(&solo, plot)));
            }
        }
    }
    out
}

fn check(preset: &str, models: &[ForceModel]) {
    let mut failures = Vec::new();
    for theme in [Theme::Dark, Theme::Plain] {
        for size in SIZES {
            let app = app_on(preset, models, theme, size);
            let cells = own_cells(&app, size);
            let charted: std::collections::HashSet<ForceModel> =
                cells.iter().map(|c| c.1).collect();
            assert_eq!(charted.len(), models.len(), "{preset} {size:?}: {cells:?}");
            for (kind, model, own, alone) in cells {
                let share = MIN_SHARE_TIMES_N / models.len() as f64;
                let least = MIN_CELLS.max((share * alone as f64).ceil() as usize);
                if own < least {
                    failures.push(format!(
                        "{theme:?} {size:?} {kind:?} {model}: {own} own cells of {alone} (< {least})"
                    ));
                }
            }
        }
    }
    assert!(failures.is_empty(), "{preset}:\n{}", failures.join("\n"));
}

#[test]
fn hunt_crossley_beside_lankarani_nikravesh_keeps_its_cells() {
    // Fig. 5's own checks, proposed focused: drawn last, it and Lankarani–Nikravesh took every
    // cell Hunt–Crossley shared with them.
    check(
        "fig5-steel-sphere-r10-plate",
        &[
            ForceModel::Proposed,
            ForceModel::HuntCrossley,
            ForceModel::LankaraniNikravesh,
        ],
    );
    check(
        "fig5-steel-sphere-r10-plate",
        &[ForceModel::HuntCrossley, ForceModel::LankaraniNikravesh],
    );
}

#[test]
fn every_model_of_fig5_and_the_default_checks_keeps_its_cells() {
    check(
        "fig5-steel-sphere-r10-plate",
        &[
            ForceModel::Proposed,
            ForceModel::Quasistatic,
            ForceModel::HuntCrossley,
            ForceModel::LankaraniNikravesh,
            ForceModel::DryFriction,
        ],
    );
}

#[test]
fn elastic_hertz_under_dry_friction_in_fig4_keeps_its_cells() {
    check(
        "fig4-steel-sphere-r10-plate",
        &[ForceModel::DryFriction, ForceModel::Quasistatic],
    );
}
