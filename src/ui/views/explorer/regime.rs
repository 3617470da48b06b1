//! The regime line: v₀ against the yield-onset velocities, the wave criterion, the model the scene
//! needs (the model layer's recommendation) and the others that fit, with the reason.

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span, Text};

use crate::model::pressure::Regime;
use crate::format::recommendation;
use crate::model::warnings::impact_warnings;
use crate::ui::app::App;
use crate::ui::style::Role;
use crate::format::units::sig;
use crate::ui::widgets::common::{NameForm, flow, pane, wrap};

/// A short name of a regime for the regime line.
fn regime_name(regime: Regime) -> &'static str {
    match regime {
        Regime::Elastic => "elastic",
        Regime::YieldBegins => "yield begins",
        Regime::FullyPlastic => "fully plastic",
    }
}

fn speed(v: f64) -> String {
    crate::format::with_unit(sig(v, 3), "", "m/s")
}

pub fn render(frame: &mut Frame, area: Rect, app: &App, roomy: bool) {
    let theme = app.theme;
    let (inner, block) = if roomy {
        let block = pane("Regime", theme, true);
        (block.inner(area), Some(block))
    } else {
        (area, None)
    };
    if let Some(block) = block {
        frame.render_widget(block, area);
    }
    let width = inner.width as usize;
    let max_lines = inner.height as usize;
    let mut items: Vec<Vec<Span>> = Vec::new();
    if let Some(error) = &app.scene_error {
        items.push(vec![Span::styled(
            if app.error_fields().is_empty() {
                format!("✗ {error}: showing the last valid scene")
            } else {
                // The form says what is wrong; this says that what follows is not the draft.
                "last valid scene:".to_string()
            },
            theme.style(Role::Error),
        )]);
    }
    let Some(valid) = &app.valid else {
        let lines = flow(items, width, max_lines, Span::raw("  "));
        frame.render_widget(Text::from(lines), inner);
        return;
    };
    let onset = &valid.quasistatic.onset;
    let v0 = valid.scene.impact.v0;
    let Some(advice) = app.advice() else {
        return;
    };
    let regime_role = match advice.regime {
        Regime::Elastic => Role::Good,
        Regime::YieldBegins => Role::Warning,
        Regime::FullyPlastic => Role::Error,
    };
    let relation = match advice.regime {
        Regime::Elastic => format!("v₀ {} < v_y {}", speed(v0), speed(onset.v_yield)),
        Regime::YieldBegins => format!(
            "v_y {} ≤ v₀ {} < v_p {}",
            speed(onset.v_yield),
            speed(v0),
            speed(onset.v_plastic)
        ),
        Regime::FullyPlastic => format!("v₀ {} ≥ v_p {}", speed(v0), speed(onset.v_plastic)),
    };
    items.push(vec![
        Span::styled(
            format!("● {}", regime_name(advice.regime)),
            theme.style(regime_role),
        ),
        Span::raw(": "),
        Span::styled(relation, theme.style(Role::Normal)),
        Span::styled(" (p₀ = 1.1 / 2.8 σ_y)", theme.style(Role::Muted)),
    ]);
    let wave = if advice.within_wave_limit {
        "within: no permanent indentation"
    } else {
        "exceeded: permanent indentation possible"
    };
    items.push(vec![
        Span::styled("wave limit ", theme.style(Role::Label)),
        Span::styled(
            format!("10⁻⁵√(E/ρ) = {} {wave}", speed(onset.v_wave_limit)),
            theme.style(if advice.within_wave_limit {
                Role::Normal
            } else {
                Role::Warning
            }),
        ),
    ]);
    // One name form for the advised model and the others that fit, as in the Models pane.
    let named: Vec<_> = std::iter::once(advice.model)
        .chain(advice.fits.iter().copied())
        .collect();
    let form = NameForm::fitting(&named, 19);
    items.push(vec![
        Span::styled("use: ", theme.style(Role::Label)),
        Span::styled(form.of(advice.model), theme.model_style(advice.model)),
        Span::styled(format!(" ({})", recommendation::gist(&advice.reason)), theme.style(Role::Normal)),
    ]);
    if advice.fits.len() > 1 {
        let mut also = vec![Span::styled("also fit: ", theme.style(Role::Label))];
        for (i, &model) in advice.fits[1..].iter().enumerate() {
            if i > 0 {
                also.push(Span::raw(", "));
            }
            also.push(Span::styled(form.of(model), theme.model_style(model)));
        }
        items.push(also);
    }
    let mut lines = flow(items, width, max_lines, Span::raw("  ·  "));
    let mean_pressure = format!(
        "mean-pressure convention: v_y {}, v_p {}",
        speed(onset.v_yield_mean_pressure),
        speed(onset.v_plastic_mean_pressure)
    );
    // Warnings before the reason: the scene's, then each checked model's solved impact's.
    let impact = app.checked_models().into_iter().filter_map(|model| {
        let solution = app.solutions.solution(model)?;
        Some(impact_warnings(&valid.params, &solution.summary))
    });
    let warnings: Vec<String> = valid
        .warnings
        .iter()
        .cloned()
        .chain(impact.flatten())
        .map(|w| format!("⚠ {w}"))
        .collect();
    for warning in warnings {
        let wrapped = wrap(&warning, width);
        if lines.len() + wrapped.len() > max_lines {
            break;
        }
        lines.extend(
            wrapped
                .into_iter()
                .map(|l| Line::from(Span::styled(l, theme.style(Role::Warning)))),
        );
    }
    // The reason clause by clause, the most needed first, each whole or not at all; then the
    // other convention if a line is left.
    let clauses = recommendation::why_clauses(advice, &valid.scene);
    for (i, clause) in clauses.iter().enumerate() {
        let text = if i == 0 {
            format!("why: {clause}")
        } else {
            format!("     {clause}")
        };
        let wrapped = wrap(&text, width);
        if lines.len() + wrapped.len() > max_lines {
            break;
        }
        lines.extend(
            wrapped
                .into_iter()
                .map(|l| Line::from(Span::styled(l, theme.style(Role::Muted)))),
        );
    }
    if lines.len() < max_lines {
        lines.push(Line::from(Span::styled(
            mean_pressure,
            theme.style(Role::Muted),
        )));
    }
    frame.render_widget(Text::from(lines), inner);
}
