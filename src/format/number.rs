//! Numbers as text: engineering notation with SI prefixes (µm, kN, µs), significant digits and
//! scientific notation. Values beyond the prefixes (f … T) fall back to scientific notation; a NaN
//! prints as [`NOT_A_NUMBER`] and an infinity as `∞`, never as a number.

use super::shortest_exp::{shortest_digits, trim_end_zeros};

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
    let digits = digits.max(1);
    // The exponent of the rounded value, so that a carry (999.96 → 1.000e3) moves the prefix.
    let rounded = Rounded::new(value, digits);
    let exponent = rounded.exponent;
    let engineering = exponent.div_euclid(3) * 3;
    let index = (engineering - SMALLEST_EXPONENT) / 3;
    let prefix = match usize::try_from(index).ok().and_then(|i| ENGINEERING.get(i)) {
        Some(prefix) => prefix,
        None => return with_unit(rounded.scientific(zeros), "", unit),
    };
    let mut number = rounded.positional(exponent - engineering);
    trim_in_place(&mut number, zeros);
    with_unit(number, prefix.symbol, unit)
}

/// `value` with `digits` significant digits: plain for 1e-4 ≤ |value| < 1e7 (0.6123, 32.67,
/// 100.0), scientific outside (1.121e-14).
pub fn significant(value: f64, digits: usize, zeros: Zeros) -> String {
    if !value.is_finite() {
        return non_finite(value);
    }
    if value == 0.0 {
        return "0".into();
    }
    Rounded::new(value, digits.max(1)).significant(value, zeros)
}

/// `value` in scientific notation with `digits` significant digits: 1.465e10, 9.100e-12.
pub fn scientific(value: f64, digits: usize, zeros: Zeros) -> String {
    if !value.is_finite() {
        return non_finite(value);
    }
    if value == 0.0 {
        return "0".into();
    }
    Rounded::new(value, digits.max(1)).scientific(zeros)
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

/// `value` with `decimals` digits after the point, exactly as `format!("{value:.decimals$}")`
/// writes it (the double's exact value rounded, ties to even): from its shortest digits rounded
/// where that is its rounding (as [`Rounded::new`] argues, up to 15 digits kept), else by the
/// standard formatter (zeros, subnormals, values rounding to nothing, ties, more digits).
pub fn fixed(value: f64, decimals: usize) -> String {
    if value.is_finite() && value.abs() >= f64::MIN_POSITIVE {
        let shortest = Shortest::of(value);
        // The significant digits the decimals keep.
        let kept = i64::from(shortest.exponent) + 1 + decimals as i64;
        if let Ok(kept @ 1..=SHORTEST_EXACT_UP_TO) = usize::try_from(kept)
            && let Some(rounded) = shortest.rounded(kept)
        {
            return rounded.with_decimals(decimals);
        }
    }
    format!("{value:.decimals$}")
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

/// The most significant digits [`Rounded`] keeps: 17 tell every double apart.
const MAX_DIGITS: usize = 17;

/// Up to this many digits the shortest round-trip digits, rounded, are the exact rounding of the
/// double (away from the cases [`Rounded::new`] hands to the exact formatter): a normal double
/// is within 2⁻⁵³ of them, relatively, and a rounding boundary of 15 digits is at least 5·10⁻¹⁶
/// away from a number of 15 digits or fewer.
const SHORTEST_EXACT_UP_TO: usize = 15;

/// A finite non-zero value rounded to a number of significant digits, exactly (as the standard
/// formatter's `{:.*e}` rounds the double's exact value, ties to even), kept as digits on the
/// stack, from which the scientific, plain and engineering forms are written. The digits are
/// Żmij's shortest round-trip digits rounded where that is provably the exact rounding (see
/// [`Rounded::new`]), else the standard formatter's: about a fifth of the instructions.
#[derive(Debug, Clone)]
pub struct Rounded {
    /// The significant digits, ASCII, trailing zeros kept: `len` of them.
    digits: [u8; MAX_DIGITS],
    len: usize,
    negative: bool,
    /// The decimal exponent of the first digit.
    pub exponent: i32,
}

/// Żmij's shortest round-trip digits of a normal non-zero double, from which [`Rounded`]s are
/// made.
struct Shortest {
    digits: [u8; MAX_DIGITS],
    len: usize,
    negative: bool,
    /// The decimal exponent of the first digit.
    exponent: i32,
}

impl Shortest {
    fn of(value: f64) -> Self {
        let mut digits = [b'0'; MAX_DIGITS];
        let (negative, len, exponent) = shortest_digits(value, &mut digits);
        Self {
            digits,
            len,
            negative,
            exponent,
        }
    }

    /// These digits rounded half up to `wanted` (1 to [`SHORTEST_EXACT_UP_TO`]) significant
    /// digits, which is the double's own rounding (see [`Rounded::new`]); `None` where it may not
    /// be: the digit after the cut is the last and a 5.
    fn rounded(&self, wanted: usize) -> Option<Rounded> {
        let mut rounded = Rounded {
            digits: [b'0'; MAX_DIGITS],
            len: wanted,
            negative: self.negative,
            exponent: self.exponent,
        };
        if self.len <= wanted {
            rounded.digits[..self.len].copy_from_slice(&self.digits[..self.len]);
            return Some(rounded);
        }
        let next = self.digits[wanted];
        if self.len == wanted + 1 && next == b'5' {
            return None;
        }
        rounded.digits[..wanted].copy_from_slice(&self.digits[..wanted]);
        if next >= b'5' {
            rounded.round_up();
        }
        Some(rounded)
    }
}

impl Rounded {
    /// `value` (finite, non-zero) rounded to `digits` significant digits (at least one, at most
    /// `MAX_DIGITS`).
    ///
    /// From Żmij's shortest digits S of the double v, rounded half up, when that is v's own
    /// rounding: S and v lie in v's rounding interval, so a rounding boundary (a number of
    /// `digits` + 1 digits ending in 5) between them would be in it too. With more than
    /// `digits` + 1 digits in S there is none (S is the shortest in the interval); with exactly
    /// that many, none either unless S ends in that 5 (S is the nearest of its length), so that
    /// case goes to the exact formatter; with `digits` or fewer, a boundary is farther from S
    /// than v can be, for normal doubles up to `SHORTEST_EXACT_UP_TO` digits. Subnormals
    /// (whose interval is wide) and more digits go to the exact formatter.
    pub fn new(value: f64, digits: usize) -> Self {
        let wanted = digits.clamp(1, MAX_DIGITS);
        if wanted > SHORTEST_EXACT_UP_TO || value.abs() < f64::MIN_POSITIVE {
            return Self::exact(value, wanted);
        }
        let shortest = Shortest::of(value);
        shortest
            .rounded(wanted)
            .unwrap_or_else(|| Self::exact(value, wanted))
    }

    /// The standard formatter's exact rounding, written on the stack.
    fn exact(value: f64, digits: usize) -> Self {
        use std::fmt::Write;
        let mut text = StackText::default();
        // Sign, 17 digits, the point, `e`, a sign and three digits fit the buffer.
        let _ = write!(text, "{:.*e}", digits - 1, value);
        let text = text.as_bytes();
        let e = text.iter().position(|&b| b == b'e').unwrap_or(text.len());
        let exponent = std::str::from_utf8(text.get(e + 1..).unwrap_or_default())
            .ok()
            .and_then(|x| x.parse().ok())
            .unwrap_or(0);
        let mut rounded = Self {
            digits: [b'0'; MAX_DIGITS],
            len: 0,
            negative: text.first() == Some(&b'-'),
            exponent,
        };
        for &d in text[..e].iter().filter(|d| d.is_ascii_digit()) {
            if rounded.len < MAX_DIGITS {
                rounded.digits[rounded.len] = d;
                rounded.len += 1;
            }
        }
        rounded
    }

    /// Adds one in the last kept digit: 9.999 → 10.00, written 1.000 one decade up.
    fn round_up(&mut self) {
        for d in self.digits[..self.len].iter_mut().rev() {
            if *d == b'9' {
                *d = b'0';
            } else {
                *d += 1;
                return;
            }
        }
        self.digits[0] = b'1';
        self.exponent += 1;
    }

    /// The significant digits, ASCII.
    fn digits(&self) -> &[u8] {
        &self.digits[..self.len]
    }

    /// The digits written with exactly `decimals` digits after the point (none and no point for
    /// none), zeros filling in where the digits end or start after it.
    fn with_decimals(&self, decimals: usize) -> String {
        let digits = self.digits();
        // The digit at place 10^p, counting from the first at 10^exponent.
        let digit = |p: i32| {
            usize::try_from(self.exponent - p)
                .ok()
                .and_then(|i| digits.get(i))
                .map_or('0', |&d| char::from(d))
        };
        let mut out = String::with_capacity(self.exponent.max(0) as usize + decimals + 3);
        if self.negative {
            out.push('-');
        }
        for p in (0..=self.exponent.max(0)).rev() {
            out.push(digit(p));
        }
        if decimals > 0 {
            out.push('.');
            for p in 1..=decimals as i32 {
                out.push(digit(-p));
            }
        }
        out
    }

    /// Scientific notation: `1.465e10`, or `1.5e-12` with the mantissa's trailing zeros trimmed.
    pub fn scientific(&self, zeros: Zeros) -> String {
        let digits = self.digits();
        let rest = match zeros {
            Zeros::Trim => trim_end_zeros(&digits[1..]),
            Zeros::Keep => &digits[1..],
        };
        let mut out = String::with_capacity(rest.len() + 9);
        if self.negative {
            out.push('-');
        }
        out.push(char::from(digits[0]));
        if !rest.is_empty() {
            out.push('.');
            push_ascii(&mut out, rest);
        }
        out.push('e');
        push_integer(&mut out, i64::from(self.exponent));
        out
    }

    /// [`significant`]'s text of `value`, which this is the rounding of: plain for a rounded
    /// magnitude in [1e-4, 1e7), scientific outside.
    pub fn significant(&self, value: f64, zeros: Zeros) -> String {
        if !(-4..=6).contains(&self.exponent) {
            return self.scientific(zeros);
        }
        if self.exponent >= self.len as i32 {
            // More integer digits than significant ones: all of them, as `{:.0}` prints them
            // (the exact value rounded to an integer, ties to even; below 1e7 here).
            let mut out = String::with_capacity(9);
            push_integer(&mut out, value.round_ties_even() as i64);
            return out;
        }
        let mut number = self.positional(self.exponent);
        trim_in_place(&mut number, zeros);
        number
    }

    /// The digits written with `exponent` as the first digit's decimal exponent, as many
    /// decimals as the digits reach (none past the point when they end before it, zeros filling
    /// up to it): for `2.388`, `23.88` at 1, `0.02388` at -2; for `3`, `300` at 2.
    fn positional(&self, exponent: i32) -> String {
        let digits = self.digits();
        let mut out = String::with_capacity(digits.len() + 8);
        if self.negative {
            out.push('-');
        }
        if exponent < 0 {
            out.push_str("0.");
            for _ in 0..(-exponent - 1) {
                out.push('0');
            }
            push_ascii(&mut out, digits);
            return out;
        }
        let whole = exponent as usize + 1;
        if whole >= digits.len() {
            push_ascii(&mut out, digits);
            for _ in digits.len()..whole {
                out.push('0');
            }
        } else {
            push_ascii(&mut out, &digits[..whole]);
            out.push('.');
            push_ascii(&mut out, &digits[whole..]);
        }
        out
    }
}

/// A short text written on the stack (a [`Rounded::exact`] formatting); what does not fit is
/// dropped, which the longest `{:.16e}` of a double never needs.
#[derive(Default)]
struct StackText {
    bytes: [u8; 32],
    len: usize,
}

impl StackText {
    fn as_bytes(&self) -> &[u8] {
        &self.bytes[..self.len]
    }
}

impl std::fmt::Write for StackText {
    fn write_str(&mut self, s: &str) -> std::fmt::Result {
        let end = self.len + s.len();
        let room = self.bytes.get_mut(self.len..end).ok_or(std::fmt::Error)?;
        room.copy_from_slice(s.as_bytes());
        self.len = end;
        Ok(())
    }
}

/// Appends ASCII digits.
fn push_ascii(out: &mut String, digits: &[u8]) {
    out.extend(digits.iter().map(|&d| char::from(d)));
}

/// Appends `n` in decimal, as `{}` writes it.
fn push_integer(out: &mut String, n: i64) {
    if n < 0 {
        out.push('-');
    }
    let mut magnitude = n.unsigned_abs();
    let mut buf = [0u8; 20];
    let mut start = buf.len();
    loop {
        start -= 1;
        buf[start] = b'0' + (magnitude % 10) as u8;
        magnitude /= 10;
        if magnitude == 0 {
            break;
        }
    }
    push_ascii(out, &buf[start..]);
}

fn trim(number: &str, zeros: Zeros) -> &str {
    if zeros == Zeros::Trim && number.contains('.') {
        number.trim_end_matches('0').trim_end_matches('.')
    } else {
        number
    }
}

/// `number` without the trailing zeros [`trim`] drops.
fn trim_in_place(number: &mut String, zeros: Zeros) {
    let kept = trim(number, zeros).len();
    number.truncate(kept);
}

/// `number prefix+unit` (`23.88 µm`), or the number alone when both are empty.
pub fn with_unit(mut number: String, prefix: &str, unit: &str) -> String {
    if !(prefix.is_empty() && unit.is_empty()) {
        number.reserve(1 + prefix.len() + unit.len());
        number.push(' ');
        number.push_str(prefix);
        number.push_str(unit);
    }
    number
}

#[cfg(test)]
mod tests {
    use super::Zeros::{Keep, Trim};
    use super::*;

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

    /// The formatting as it was before [`Rounded`]: the value formatted in scientific notation,
    /// parsed back, and formatted again plain. Slower, and the oracle of the property test below.
    mod reference {
        use super::super::{ENGINEERING, PLAIN, SMALLEST_EXPONENT, Zeros, trim, with_unit};

        pub fn engineering(value: f64, unit: &str, digits: usize, zeros: Zeros) -> String {
            let (mantissa, exponent) = rounded(value, digits);
            let engineering = exponent.div_euclid(3) * 3;
            let index = (engineering - SMALLEST_EXPONENT) / 3;
            let prefix = match usize::try_from(index).ok().and_then(|i| ENGINEERING.get(i)) {
                Some(prefix) => prefix,
                None => return with_unit(scientific(value, digits, zeros), "", unit),
            };
            let shift = exponent - engineering;
            let decimals = (digits as i32 - 1 - shift).max(0) as usize;
            let number = format!("{:.decimals$}", mantissa * 10f64.powi(shift));
            with_unit(trim(&number, zeros).to_string(), prefix.symbol, unit)
        }

        pub fn significant(value: f64, digits: usize, zeros: Zeros) -> String {
            let (mantissa, exponent) = rounded(value, digits);
            if !PLAIN.contains(&(mantissa.abs() * 10f64.powi(exponent))) {
                return scientific(value, digits, zeros);
            }
            let decimals = (digits as i32 - 1 - exponent).max(0) as usize;
            trim(&format!("{value:.decimals$}"), zeros).to_string()
        }

        pub fn scientific(value: f64, digits: usize, zeros: Zeros) -> String {
            let text = format!("{:.*e}", digits - 1, value);
            match (zeros, text.split_once('e')) {
                (Zeros::Trim, Some((mantissa, exponent))) => {
                    format!("{}e{exponent}", trim(mantissa, Zeros::Trim))
                }
                _ => text,
            }
        }

        fn rounded(value: f64, digits: usize) -> (f64, i32) {
            let text = format!("{:.*e}", digits - 1, value);
            let (mantissa, exponent) = text.split_once('e').unwrap_or((&text, "0"));
            (mantissa.parse().unwrap(), exponent.parse().unwrap())
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig { cases: 4000, ..Default::default() })]

        /// Doubles from their bits, tick values as a chart computes them ((first + i)·step, with
        /// their floating-point error), decimal midpoints, values near a carry and subnormals, at
        /// 0 to 20 decimals: what `format!("{v:.decimals$}")` writes.
        #[test]
        fn fixed_writes_what_the_formatter_writes(
            bits in proptest::prelude::any::<u64>(),
            kind in 0u8..5,
            decimals in 0usize..21,
        ) {
            let scale = 10f64.powi((bits % 30) as i32 - 15);
            let value = match kind {
                1 => {
                    let step = [1.0, 2.0, 2.5, 5.0][(bits >> 8) as usize % 4] * scale;
                    (((bits >> 16) % 200) as f64 - 100.0) * step
                }
                2 => (((bits >> 8) % 100_000) as f64 + 0.5) * scale,
                3 => (1.0 - 1e-6 * ((bits >> 8) % 100) as f64) * scale,
                4 => f64::from_bits(bits % (1 << 52)),
                _ => f64::from_bits(bits),
            };
            proptest::prop_assume!(value.is_finite());
            proptest::prop_assert_eq!(fixed(value, decimals), format!("{value:.decimals$}"));
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig { cases: 4000, ..Default::default() })]

        /// Every finite non-zero double (drawn from its bits, so every exponent is as likely, and
        /// near prefix changes, decimal midpoints, binary fractions and subnormals), at 1 to 17
        /// digits, both zero policies: the same text as the exact formatter, formatting twice,
        /// gave.
        #[test]
        fn formatting_once_gives_what_formatting_twice_gave(
            bits in proptest::prelude::any::<u64>(),
            kind in 0u8..5,
            digits in 1usize..18,
            trim_zeros in proptest::prelude::any::<bool>(),
        ) {
            let mut value = f64::from_bits(bits);
            let scale = 10f64.powi((bits % 40) as i32 - 20);
            match kind {
                // Where the prefixes and the plain range change, and where rounding carries.
                1 => value = (1.0 - 1e-6 * ((bits >> 8) % 100) as f64) * scale,
                // Decimal midpoints (k + 0.5)·10^j: the shortest digits end in 5.
                2 => value = (((bits >> 8) % 100_000) as f64 + 0.5) * scale,
                // Binary fractions, exactly representable midpoints (0.125, 2.5, 1.0625 …).
                3 => value = ((bits >> 8) % 100_000) as f64 / f64::from(1u32 << ((bits >> 40) % 12)),
                // Subnormals, whose shortest digits are few and far from the exact value.
                4 => value = f64::from_bits(bits % (1 << 52)),
                _ => {}
            }
            proptest::prop_assume!(value.is_finite() && value != 0.0);
            let zeros = if trim_zeros { Trim } else { Keep };
            proptest::prop_assert_eq!(significant(value, digits, zeros), reference::significant(value, digits, zeros));
            proptest::prop_assert_eq!(scientific(value, digits, zeros), reference::scientific(value, digits, zeros));
            // The old engineering form multiplied the rounded mantissa by 10^shift in floating
            // point, which shows from the 16th digit (99.99630000000002 mm where the double is
            // 99.99630000000001… mm): compared up to 15 digits.
            if digits <= 15 {
                proptest::prop_assert_eq!(engineering(value, "m", digits, zeros), reference::engineering(value, "m", digits, zeros));
            }
        }
    }
}
