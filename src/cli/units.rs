//! The command line's conventions over [`crate::format`], the one number formatter: 4 significant
//! digits with trailing zeros in results (`1.710 kN`), without them in inputs (`10 mm`).

use crate::format::{self, Zeros};

pub use crate::format::NOT_A_NUMBER;

/// Significant digits of a result.
const DIGITS: usize = 4;

/// `value` in engineering notation with 4 significant digits and an SI prefix on `unit`:
/// 2.388e-5 m → "23.88 µm", 1710 N → "1.710 kN"; scientific beyond f … T (1.000e-300 m).
pub fn engineering(value: f64, unit: &str) -> String {
    format::engineering(value, unit, DIGITS, Zeros::Keep)
}

/// [`engineering`] without trailing zeros, for inputs as the user wrote them: "10 mm", "2.3 µm".
pub fn compact(value: f64, unit: &str) -> String {
    format::engineering(value, unit, DIGITS, Zeros::Trim)
}

/// `value` with at most `digits` significant digits and no trailing zeros: 0.3, 0.6, 1.09.
pub fn compact_number(value: f64, digits: usize) -> String {
    format::significant(value, digits, Zeros::Trim)
}

/// An input that must read back as itself, e.g. ν = 0.4999999999 (valid) is not 0.5 (refused).
pub fn exact_number(value: f64) -> String {
    format::round_trip(value)
}

/// `value` in scientific notation with 4 significant digits: 1.465e10.
pub fn scientific(value: f64, unit: &str) -> String {
    let text = format::scientific(value, DIGITS, Zeros::Keep);
    if unit.is_empty() || !value.is_finite() {
        text
    } else {
        format!("{text} {unit}")
    }
}

/// `value` with `digits` significant digits: 0.6123, 32.67; scientific outside [1e-4, 1e7).
pub fn significant(value: f64, digits: usize) -> String {
    format::significant(value, digits, Zeros::Keep)
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
    fn values_beyond_the_prefixes_are_scientific() {
        assert_eq!(engineering(1e-300, "g"), "1.000e-300 g");
        assert_eq!(engineering(1e300, "m"), "1.000e300 m");
        assert_eq!(compact(1e300, "m"), "1e300 m");
        assert_eq!(compact_number(1e-9, 4), "1e-9");
        assert_eq!(significant(1.121e-14, 4), "1.121e-14");
        assert_eq!(engineering(f64::INFINITY, "m/s"), "∞");
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
        assert_eq!(exact_number(0.3), "0.3");
        assert_eq!(exact_number(0.4999999999), "0.4999999999");
    }

    #[test]
    fn scientific_and_significant() {
        assert_eq!(scientific(1.465e10, "N/m^1.5"), "1.465e10 N/m^1.5");
        assert_eq!(scientific(9.1e-12, ""), "9.100e-12");
        assert_eq!(scientific(0.0, ""), "0");
        assert_eq!(scientific(f64::NAN, "m²/N"), NOT_A_NUMBER);
        assert_eq!(significant(0.61234, 4), "0.6123");
        assert_eq!(significant(1.5, 4), "1.500");
        assert_eq!(significant(99.999, 4), "100.0");
        assert_eq!(significant(f64::INFINITY, 4), "∞");
    }
}
