//! Aligned text columns.

/// Renders `rows` as left-aligned columns separated by two spaces, each line prefixed by `indent`.
/// Widths count characters, so `µ` and `σ` take one column. The last cell is not padded.
pub fn columns(rows: &[Vec<String>], indent: &str) -> String {
    let width = |s: &str| s.chars().count();
    let n = rows.iter().map(Vec::len).max().unwrap_or(0);
    let widths: Vec<usize> = (0..n)
        .map(|c| {
            rows.iter()
                .filter_map(|r| r.get(c))
                .map(|s| width(s))
                .max()
                .unwrap_or(0)
        })
        .collect();
    let mut out = String::new();
    for row in rows {
        let mut line = String::from(indent);
        for (c, cell) in row.iter().enumerate() {
            line.push_str(cell);
            if c + 1 < row.len() {
                line.push_str(&" ".repeat(widths[c] - width(cell) + 2));
            }
        }
        out.push_str(line.trim_end());
        out.push('\n');
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pads_by_characters() {
        let rows = vec![
            vec![
                "x_max".to_string(),
                "23.88 µm".to_string(),
                "(eq 5)".to_string(),
            ],
            vec!["F".to_string(), "1.710 kN".to_string()],
        ];
        assert_eq!(
            columns(&rows, "  "),
            "  x_max  23.88 µm  (eq 5)\n  F      1.710 kN\n"
        );
    }
}
