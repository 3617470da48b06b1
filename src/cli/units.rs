//! Human-readable numbers: engineering notation with SI prefixes (µm, kN, µs, mm/s).

/// Shown instead of a number that is not finite: a NaN is never printed as a result.
pub const NOT_A_NUMBER: &str = "—";

const PREFIXES: [(i32, &str); 10] = [
    (-15, "f"),
    (-12, "p"),
    (-9, "n"),
    (-6, "µ"),
    (-3, "m"),
    (0, ""),
    (3, "k"),
    (6, "M"),
    (9, "G"),
    (12, "T"),
];

/// `value` in engineering notation with 4 significant digits and an SI prefix on `unit`:
/// 2.388e-5 m → "23.88 µm", 1710 N → "1.710 kN".
pub fn engineering(value: f64, unit: &str) -> String {
    if !value.is_finite() {
        return NOT_A_NUMBER.into();
    }
    if value == 0.0 {
        return format!("0 {unit}");
    }
    let mut exponent = (value.abs().log10() / 3.0).floor() as i32 * 3;
    exponent = exponent.clamp(-15, 12);
    let mut mantissa = value / 10f64.powi(exponent);
    // Rounding to 4 digits can carry into the next prefix (999.96 → 1000 → 1.000 k).
    if round_significant(mantissa.abs(), 4) >= 1000.0 && exponent < 12 {
        exponent += 3;
        mantissa = value / 10f64.powi(exponent);
    }
    let prefix = PREFIXES
        .iter()
        .find(|(e, _)| *e == exponent)
        .map_or("", |(_, p)| *p);
    format!("{} {prefix}{unit}", significant(mantissa, 4))
}

/// [`engineering`] without trailing zeros, for inputs as the user wrote them: "10 mm", "2.3 µm".
pub fn compact(value: f64, unit: &str) -> String {
    let text = engineering(value, unit);
    match text.split_once(' ') {
        Some((number, rest)) if number.contains('.') => {
            format!(
                "{} {rest}",
                number.trim_end_matches('0').trim_end_matches('.')
            )
        }
        _ => text,
    }
}

/// `value` with at most `digits` significant digits and no trailing zeros: 0.3, 0.6, 1.09.
pub fn compact_number(value: f64, digits: i32) -> String {
    let text = significant(value, digits);
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        text
    }
}

/// `value` in scientific notation with 4 significant digits: 1.465e10.
pub fn scientific(value: f64, unit: &str) -> String {
    if !value.is_finite() {
        return NOT_A_NUMBER.into();
    }
    let text = if value == 0.0 {
        "0".to_string()
    } else {
        format!("{value:.3e}")
    };
    if unit.is_empty() {
        text
    } else {
        format!("{text} {unit}")
    }
}

/// `value` with `digits` significant digits in plain notation: 0.6123, 32.67.
pub fn significant(value: f64, digits: i32) -> String {
    if !value.is_finite() {
        return NOT_A_NUMBER.into();
    }
    if value == 0.0 {
        return "0".into();
    }
    let magnitude = round_significant(value.abs(), digits).log10().floor() as i32;
    let decimals = (digits - 1 - magnitude).max(0) as usize;
    format!("{value:.decimals$}")
}

fn round_significant(x: f64, digits: i32) -> f64 {
    let scale = 10f64.powi(digits - 1 - x.log10().floor() as i32);
    (x * scale).round() / scale
}

/// A count, or the placeholder.
pub fn count(value: Option<usize>) -> String {
    value.map_or(NOT_A_NUMBER.into(), |n| n.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn engineering_prefixes() {
        assert_eq!(engineering(2.388e-5, "m"), "23.88 µm");
        assert_eq!(engineering(1710.0, "N"), "1.710 kN");
        assert_eq!(engineering(7.029e-5, "s"), "70.29 µs");
        assert_eq!(engineering(0.032, "m/s"), "32.00 mm/s");
        assert_eq!(engineering(3.419e9, "Pa"), "3.419 GPa");
        assert_eq!(engineering(1.0, "m/s"), "1.000 m/s");
        assert_eq!(engineering(-0.21, "m/s"), "-210.0 mm/s");
        assert_eq!(engineering(999.96, "N"), "1.000 kN");
        assert_eq!(engineering(0.0, "J"), "0 J");
        assert_eq!(engineering(f64::NAN, "J"), NOT_A_NUMBER);
    }

    #[test]
    fn compact_drops_trailing_zeros() {
        assert_eq!(compact(0.01, "m"), "10 mm");
        assert_eq!(compact(2.3e-6, "m"), "2.3 µm");
        assert_eq!(compact(2e11, "Pa"), "200 GPa");
        assert_eq!(compact(0.0, "m"), "0 m");
        assert_eq!(compact_number(0.3, 4), "0.3");
        assert_eq!(compact_number(1.5, 4), "1.5");
        assert_eq!(compact_number(7800.0, 4), "7800");
        assert_eq!(compact_number(1.0, 4), "1");
    }

    #[test]
    fn scientific_and_significant() {
        assert_eq!(scientific(1.465e10, "N/m^1.5"), "1.465e10 N/m^1.5");
        assert_eq!(scientific(9.1e-12, ""), "9.100e-12");
        assert_eq!(scientific(0.0, ""), "0");
        assert_eq!(significant(0.61234, 4), "0.6123");
        assert_eq!(significant(1.5, 4), "1.500");
        assert_eq!(significant(99.999, 4), "100.0");
        assert_eq!(significant(f64::INFINITY, 4), NOT_A_NUMBER);
    }
}
