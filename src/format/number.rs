//! Numbers as text: engineering notation with SI prefixes (µm, kN, µs), significant digits and
//! scientific notation. Values beyond the prefixes (f … T) fall back to scientific notation; a NaN
//! prints as [`NOT_A_NUMBER`] and an infinity as `∞`, never as a number.

/// Shown instead of a NaN: a NaN is never printed as a result.
pub const NOT_A_NUMBER: &str = "—";

/// A decimal SI prefix.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Prefix {
    pub symbol: &'static str,
    pub factor: f64,
}

pub const FEMTO: Prefix = Prefix {
    symbol: "f",
    factor: 1e-15,
};
pub const PICO: Prefix = Prefix {
    symbol: "p",
    factor: 1e-12,
};
pub const NANO: Prefix = Prefix {
    symbol: "n",
    factor: 1e-9,
};
pub const MICRO: Prefix = Prefix {
    symbol: "µ",
    factor: 1e-6,
};
pub const MILLI: Prefix = Prefix {
    symbol: "m",
    factor: 1e-3,
};
pub const NONE: Prefix = Prefix {
    symbol: "",
    factor: 1.0,
};
pub const KILO: Prefix = Prefix {
    symbol: "k",
    factor: 1e3,
};
pub const MEGA: Prefix = Prefix {
    symbol: "M",
    factor: 1e6,
};
pub const GIGA: Prefix = Prefix {
    symbol: "G",
    factor: 1e9,
};
pub const TERA: Prefix = Prefix {
    symbol: "T",
    factor: 1e12,
};

/// The engineering prefixes (powers of 1000), smallest first.
pub const ENGINEERING: [Prefix; 10] = [
    FEMTO, PICO, NANO, MICRO, MILLI, NONE, KILO, MEGA, GIGA, TERA,
];

/// The decimal exponent of [`FEMTO`], the first of [`ENGINEERING`].
const SMALLEST_EXPONENT: i32 = -15;

/// Plain notation for magnitudes in [1e-4, 1e7) after rounding, scientific outside.
const PLAIN: std::ops::Range<f64> = 1e-4..1e7;

/// Whether trailing zeros stay (`1.500 kN`, the fixed precision of a table column) or go
/// (`1.5 kN`, a value as the user would type it).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Zeros {
    Keep,
    Trim,
}

/// The most significant digits a number is written with: 17 tell every double apart.
const MAX_DIGITS: usize = 17;

/// `value` (finite, non-zero) rounded to `digits` significant digits, as `{:.*e}` rounds it (the
/// double's exact value, ties to even): its sign, its digits (trailing zeros kept) and the decimal
/// exponent of the first digit, which a carry moves (999.96 → 1.000e3).
struct Digits {
    negative: bool,
    digits: String,
    exponent: i32,
}

impl Digits {
    fn new(value: f64, digits: usize) -> Self {
        let digits = digits.clamp(1, MAX_DIGITS);
        let text = format!("{:.*e}", digits - 1, value.abs());
        let (mantissa, exponent) = text.split_once('e').unwrap_or((&text, "0"));
        Digits {
            negative: value < 0.0,
            digits: mantissa.replace('.', ""),
            exponent: exponent.parse().unwrap_or(0),
        }
    }

    fn sign(&self) -> &'static str {
        if self.negative { "-" } else { "" }
    }

    /// Scientific notation: `1.465e10`, or `1.5e-12` with the mantissa's trailing zeros trimmed.
    fn scientific(&self, zeros: Zeros) -> String {
        let (first, rest) = self.digits.split_at(1);
        let rest = match zeros {
            Zeros::Trim => rest.trim_end_matches('0'),
            Zeros::Keep => rest,
        };
        let point = if rest.is_empty() { "" } else { "." };
        format!("{}{first}{point}{rest}e{}", self.sign(), self.exponent)
    }

    /// Plain notation of the digits, for an exponent below the digits' count: `12.35`, `0.01235`.
    fn plain(&self, zeros: Zeros) -> String {
        match usize::try_from(self.exponent) {
            Ok(shift) => self.shifted(shift, zeros),
            Err(_) => {
                let leading = "0".repeat(self.exponent.unsigned_abs() as usize - 1);
                let number = format!("{}0.{leading}{}", self.sign(), self.digits);
                trim(&number, zeros).to_string()
            }
        }
    }

    /// The digits with the point after the digit at 10^`shift` (an engineering prefix's shift,
    /// 0 to 2, or a plain number's exponent), zeros filling in where the digits end before it: for `2.388`, `23.88` at 1; for
    /// `3`, `300` at 2.
    fn shifted(&self, shift: usize, zeros: Zeros) -> String {
        let whole = shift + 1;
        let digits = format!("{:0<whole$}", self.digits);
        let (int, frac) = digits.split_at(whole);
        let number = if frac.is_empty() {
            format!("{}{int}", self.sign())
        } else {
            format!("{}{int}.{frac}", self.sign())
        };
        trim(&number, zeros).to_string()
    }
}

/// `value` in engineering notation: `digits` significant digits and the SI prefix on `unit` that
/// brings the number into [1, 1000) once rounded (2.388e-5 m → `23.88 µm`, 999.96 N →
/// `1.000 kN`). Beyond f … T it is scientific in the bare unit (`1.000e-300 m`). A number without
/// a unit takes no prefix (a lone `m` would read as metres): it is [`significant`].
pub fn engineering(value: f64, unit: &str, digits: usize, zeros: Zeros) -> String {
    if unit.is_empty() {
        return significant(value, digits, zeros);
    }
    if !value.is_finite() {
        return non_finite(value);
    }
    if value == 0.0 {
        return with_unit("0".to_string(), "", unit);
    }
    // The exponent of the rounded value, so that a carry (999.96 → 1.000e3) moves the prefix.
    let rounded = Digits::new(value, digits);
    let engineering = rounded.exponent.div_euclid(3) * 3;
    let index = (engineering - SMALLEST_EXPONENT) / 3;
    match usize::try_from(index).ok().and_then(|i| ENGINEERING.get(i)) {
        Some(prefix) => {
            let shift = (rounded.exponent - engineering) as usize;
            with_unit(rounded.shifted(shift, zeros), prefix.symbol, unit)
        }
        None => with_unit(rounded.scientific(zeros), "", unit),
    }
}

/// `value` with `digits` significant digits: plain for 1e-4 ≤ |value| < 1e7 once rounded
/// (0.6123, 32.67, 100.0), scientific outside (1.121e-14).
pub fn significant(value: f64, digits: usize, zeros: Zeros) -> String {
    if !value.is_finite() {
        return non_finite(value);
    }
    if value == 0.0 {
        return "0".into();
    }
    let digits = digits.clamp(1, MAX_DIGITS);
    let rounded = Digits::new(value, digits);
    if !(-4..=6).contains(&rounded.exponent) {
        return rounded.scientific(zeros);
    }
    if rounded.exponent >= digits as i32 - 1 {
        // A whole number: written whole (1234567 at four digits), as `{:.0}` rounds it.
        return trim(&format!("{value:.0}"), zeros).to_string();
    }
    // The same digits as `{:.decimals$}` with the decimals that keep `digits` significant digits
    // (a carry makes them all zeros either way), without formatting the value a second time.
    rounded.plain(zeros)
}

/// `value` in scientific notation with `digits` significant digits: 1.465e10, 9.100e-12.
pub fn scientific(value: f64, digits: usize, zeros: Zeros) -> String {
    if !value.is_finite() {
        return non_finite(value);
    }
    if value == 0.0 {
        return "0".into();
    }
    Digits::new(value, digits).scientific(zeros)
}

/// The shortest text that reads back as exactly `value`: for an input that must not look like
/// another one (ν = 0.4999999999 is valid, 0.5 is not). Plain in [1e-4, 1e7), scientific outside.
pub fn round_trip(value: f64) -> String {
    if !value.is_finite() {
        return non_finite(value);
    }
    if value == 0.0 {
        "0".into()
    } else if PLAIN.contains(&value.abs()) {
        format!("{value}")
    } else {
        format!("{value:e}")
    }
}

/// `—` for a NaN, `∞` or `−∞` for an infinity.
fn non_finite(value: f64) -> String {
    if value.is_nan() {
        NOT_A_NUMBER.into()
    } else if value > 0.0 {
        "∞".into()
    } else {
        "−∞".into()
    }
}

fn trim(number: &str, zeros: Zeros) -> &str {
    if zeros == Zeros::Trim && number.contains('.') {
        number.trim_end_matches('0').trim_end_matches('.')
    } else {
        number
    }
}

/// `number prefix+unit` (`23.88 µm`), or the number alone when both are empty.
pub fn with_unit(number: String, prefix: &str, unit: &str) -> String {
    if prefix.is_empty() && unit.is_empty() {
        number
    } else {
        format!("{number} {prefix}{unit}")
    }
}

#[cfg(test)]
mod tests {
    use super::Zeros::{Keep, Trim};
    use super::*;

    /// Plain notation from the rounded digits is what formatting the value again with the
    /// decimals that keep its significant digits gives, carries (9.9996 → 10.00) included.
    #[test]
    fn plain_digits_are_the_formatted_decimals() {
        let mut checked = 0;
        for mantissa in [
            1.0, 1.2345, 2.5, 3.25159, 9.9996, 9.99996, 5.55555, 7.0, 1.0005,
        ] {
            for exponent in -5..=7 {
                for sign in [1.0, -1.0] {
                    let value = sign * mantissa * 10f64.powi(exponent);
                    for digits in 1..=6 {
                        let rounded = Digits::new(value, digits);
                        if !(-4..digits as i32 - 1).contains(&rounded.exponent) {
                            continue;
                        }
                        let decimals = (digits as i32 - 1 - rounded.exponent) as usize;
                        for zeros in [Zeros::Keep, Zeros::Trim] {
                            let formatted = format!("{value:.decimals$}");
                            assert_eq!(
                                significant(value, digits, zeros),
                                trim(&formatted, zeros),
                                "{value} at {digits} digits"
                            );
                            checked += 1;
                        }
                    }
                }
            }
        }
        assert!(checked > 500, "{checked}");
    }

    #[test]
    fn engineering_prefixes() {
        assert_eq!(engineering(2.388e-5, "m", 4, Keep), "23.88 µm");
        assert_eq!(engineering(1710.0, "N", 4, Keep), "1.710 kN");
        assert_eq!(engineering(0.032, "m/s", 4, Keep), "32.00 mm/s");
        assert_eq!(engineering(3.419e9, "Pa", 4, Keep), "3.419 GPa");
        assert_eq!(engineering(1.0, "m/s", 4, Keep), "1.000 m/s");
        assert_eq!(engineering(2e11, "Pa", 4, Trim), "200 GPa");
        assert_eq!(engineering(1.5e-15, "m", 4, Trim), "1.5 fm");
        assert_eq!(engineering(999.9e12, "N", 4, Keep), "999.9 TN");
        assert_eq!(engineering(0.6, "", 4, Trim), "0.6");
        assert_eq!(engineering(2e-9, "", 4, Trim), "2e-9");
    }

    #[test]
    fn engineering_edges() {
        // Beyond f … T: scientific in the bare unit, never a 300-digit decimal.
        assert_eq!(engineering(1e-300, "m", 4, Keep), "1.000e-300 m");
        assert_eq!(engineering(1e300, "m", 4, Keep), "1.000e300 m");
        assert_eq!(engineering(-1e300, "m", 4, Trim), "-1e300 m");
        assert_eq!(engineering(9.99e-16, "s", 4, Keep), "9.990e-16 s");
        assert_eq!(
            engineering(f64::MIN_POSITIVE / 8.0, "m", 4, Keep),
            "2.781e-309 m"
        );
        assert_eq!(engineering(f64::MAX, "N", 4, Trim), "1.798e308 N");
        // Rounding that carries into the next prefix, or past the last one.
        assert_eq!(engineering(999.96, "N", 4, Keep), "1.000 kN");
        assert_eq!(engineering(-999.96, "N", 4, Keep), "-1.000 kN");
        assert_eq!(engineering(999.96e-18, "m", 4, Keep), "1.000 fm");
        assert_eq!(engineering(999.96e12, "N", 4, Keep), "1.000e15 N");
        assert_eq!(engineering(0.99996e-3, "s", 4, Trim), "1 ms");
        // Zero, negative, non-finite.
        assert_eq!(engineering(0.0, "J", 4, Keep), "0 J");
        assert_eq!(engineering(-0.0, "J", 4, Keep), "0 J");
        assert_eq!(engineering(-0.21, "m/s", 4, Keep), "-210.0 mm/s");
        assert_eq!(engineering(f64::NAN, "J", 4, Keep), NOT_A_NUMBER);
        assert_eq!(engineering(f64::INFINITY, "J", 4, Keep), "∞");
        assert_eq!(engineering(f64::NEG_INFINITY, "J", 4, Keep), "−∞");
    }

    #[test]
    fn significant_digits() {
        assert_eq!(significant(0.61234, 4, Keep), "0.6123");
        assert_eq!(significant(1.5, 4, Keep), "1.500");
        assert_eq!(significant(1.5, 4, Trim), "1.5");
        assert_eq!(significant(99.999, 4, Keep), "100.0");
        assert_eq!(significant(9.99996, 4, Trim), "10");
        assert_eq!(significant(7800.0, 6, Trim), "7800");
        assert_eq!(significant(-0.21347, 3, Trim), "-0.213");
        assert_eq!(significant(1.465e10, 4, Trim), "1.465e10");
        assert_eq!(significant(1.121e-14, 4, Keep), "1.121e-14");
        assert_eq!(significant(1e-9, 4, Trim), "1e-9");
        assert_eq!(significant(1e-300, 4, Keep), "1.000e-300");
        assert_eq!(significant(1e300, 4, Trim), "1e300");
        assert_eq!(significant(0.0, 4, Keep), "0");
        assert_eq!(significant(f64::NAN, 4, Keep), NOT_A_NUMBER);
        assert_eq!(significant(f64::INFINITY, 4, Keep), "∞");
    }

    #[test]
    fn scientific_notation() {
        assert_eq!(scientific(1.465e10, 4, Keep), "1.465e10");
        assert_eq!(scientific(9.1e-12, 4, Keep), "9.100e-12");
        assert_eq!(scientific(9.1e-12, 4, Trim), "9.1e-12");
        assert_eq!(scientific(-2.5e-300, 2, Keep), "-2.5e-300");
        assert_eq!(scientific(0.0, 4, Keep), "0");
        assert_eq!(scientific(f64::NAN, 4, Keep), NOT_A_NUMBER);
    }

    #[test]
    fn round_trip_tells_close_values_apart() {
        assert_eq!(round_trip(0.3), "0.3");
        assert_eq!(round_trip(0.4999999999), "0.4999999999");
        assert_eq!(round_trip(0.49999999999999994), "0.49999999999999994");
        assert_eq!(round_trip(1e-9), "1e-9");
        assert_eq!(round_trip(1e300), "1e300");
        assert_eq!(round_trip(0.0), "0");
        assert_eq!(round_trip(f64::NAN), NOT_A_NUMBER);
        for value in [0.4999999999, 1e-9, 1e300, 7800.0, -1.25e-5] {
            assert_eq!(round_trip(value).parse::<f64>().unwrap(), value);
        }
    }
}
