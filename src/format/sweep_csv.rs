//! A sweep as CSV, for `sweep --format csv` and the explorer's sweep view (`e`) alike: the swept
//! value, the quasistatic columns and five columns per model, in SI units at full precision
//! (Rust's shortest round-trip `{:e}`), and the failures of a row, if any, in `error`.

use crate::format::{csv, push_shortest_exp};
use crate::model::ForceModel;
use crate::model::study::sweep::SweepRow;

/// The whole CSV of `rows`, swept over the key at `param` (its dotted path), for `models`.
pub fn sweep_csv(param: &str, models: &[ForceModel], rows: &[SweepRow]) -> String {
    let mut out = csv_header(param, models).into_bytes();
    let mut quasistatic = QuasistaticColumns::default();
    for row in rows {
        csv_row(&mut out, row, models, &mut quasistatic);
    }
    // Every piece written is ASCII or the UTF-8 of a message.
    String::from_utf8_lossy(&out).into_owned()
}

/// The messages of a row's failures, `model: message` joined by `; `.
pub fn failures(row: &SweepRow) -> String {
    let mut messages: Vec<String> = row.error.iter().cloned().collect();
    messages.extend(
        row.impacts
            .iter()
            .filter_map(|i| i.error.as_ref().map(|e| format!("{}: {e}", i.model))),
    );
    messages.join("; ")
}

/// The header row: the swept key's path, the quasistatic columns, five columns per model
/// (`<model>.x_max` …), and `error`.
pub fn csv_header(param: &str, models: &[ForceModel]) -> String {
    let mut header = vec![
        param.to_string(),
        "p_max".into(),
        "contact_radius".into(),
        "half_width".into(),
        "v_yield".into(),
        "v_plastic".into(),
    ];
    for model in models {
        for field in ["x_max", "f_max", "t_contact", "v_out", "e_out"] {
            header.push(format!("{model}.{field}"));
        }
    }
    header.push("error".into());
    header.join(",") + "\n"
}

/// `value,` in Rust's `{:e}` (shortest round-trip), or just `,` for a missing number.
fn push_number(out: &mut Vec<u8>, value: Option<f64>) {
    if let Some(v) = value {
        push_shortest_exp(out, v);
    }
    out.push(b',');
}

/// The text of the last number written in a column: copied, not formatted again, while the column
/// repeats (a sweep of v₀ on a sphere keeps v_yield and v_plastic, of e or x_pl every quasistatic
/// column).
#[derive(Default)]
struct Repeated {
    bits: Option<u64>,
    text: Vec<u8>,
}

impl Repeated {
    /// [`push_number`], from the last text when `value` is the last number.
    fn push(&mut self, out: &mut Vec<u8>, value: Option<f64>) {
        if let Some(v) = value {
            if self.bits != Some(v.to_bits()) {
                self.text.clear();
                push_shortest_exp(&mut self.text, v);
                self.bits = Some(v.to_bits());
            }
            out.extend_from_slice(&self.text);
        }
        out.push(b',');
    }
}

/// The quasistatic columns, p_max … v_plastic, each remembering its last number.
#[derive(Default)]
pub struct QuasistaticColumns([Repeated; 5]);

/// One CSV row of `row` appended to `out`.
pub fn csv_row(
    out: &mut Vec<u8>,
    row: &SweepRow,
    models: &[ForceModel],
    quasistatic: &mut QuasistaticColumns,
) {
    let q = row.quasistatic;
    push_number(out, Some(row.value));
    let [p_max, contact_radius, half_width, v_yield, v_plastic] = &mut quasistatic.0;
    p_max.push(out, q.map(|q| q.p_max));
    contact_radius.push(out, q.and_then(|q| q.contact_radius));
    half_width.push(out, q.and_then(|q| q.half_width));
    v_yield.push(out, q.map(|q| q.v_yield));
    v_plastic.push(out, q.map(|q| q.v_plastic));
    for model in models {
        let point = row.impacts.iter().find(|i| i.model == *model);
        push_number(out, point.and_then(|p| p.x_max));
        push_number(out, point.and_then(|p| p.f_max));
        push_number(out, point.and_then(|p| p.t_contact));
        push_number(out, point.and_then(|p| p.v_out));
        push_number(out, point.and_then(|p| p.e_out));
    }
    let failed = row.error.is_some() || row.impacts.iter().any(|i| i.error.is_some());
    if failed {
        out.extend_from_slice(csv::field(&failures(row)).as_bytes());
    }
    out.push(b'\n');
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::study::sweep::QuasistaticPoint;

    fn row(value: f64, quasistatic: Option<QuasistaticPoint>) -> SweepRow {
        SweepRow {
            value,
            quasistatic,
            impacts: Vec::new(),
            error: quasistatic.is_none().then(|| "invalid".into()),
        }
    }

    #[test]
    fn repeated_columns_are_written_as_if_formatted_afresh() {
        let q = |p_max: f64, v_yield: f64| QuasistaticPoint {
            p_max,
            contact_radius: Some(7.7e-5),
            half_width: None,
            v_yield,
            v_plastic: 0.326,
        };
        // v_yield repeats, changes, disappears with an invalid point, and comes back.
        let rows = [
            row(0.01, Some(q(5.4e8, 0.0316))),
            row(0.02, Some(q(6.1e8, 0.0316))),
            row(0.03, Some(q(6.6e8, 0.0451))),
            row(0.04, None),
            row(0.05, Some(q(7.3e8, 0.0451))),
        ];
        let mut out = Vec::new();
        let mut columns = QuasistaticColumns::default();
        for row in &rows {
            csv_row(&mut out, row, &[], &mut columns);
        }
        assert_eq!(
            String::from_utf8(out).unwrap(),
            "1e-2,5.4e8,7.7e-5,,3.16e-2,3.26e-1,\n\
             2e-2,6.1e8,7.7e-5,,3.16e-2,3.26e-1,\n\
             3e-2,6.6e8,7.7e-5,,4.51e-2,3.26e-1,\n\
             4e-2,,,,,,invalid\n\
             5e-2,7.3e8,7.7e-5,,4.51e-2,3.26e-1,\n"
        );
    }
}
