//! Quantities at the edges (the explorer, the command line, figures): parsing what the user types (`200G`, `2e11`, `10 mm`, `0.3 m/s`)
//! into SI values, and formatting SI values in engineering units (µm, µs, N, GPa …) by
//! [`crate::format`], the formatter the command line uses too.

use crate::format::{self, Zeros};
use crate::model::scene_key::{BodyField, BodyIndex, SceneKey};
use crate::model::system::SystemKey;

pub use crate::format::{
    ENGINEERING, FEMTO, GIGA, KILO, MEGA, MICRO, MILLI, NANO, NONE, PICO, Prefix, TERA,
};

/// Prefix letters accepted on input, with the ASCII `u` and the Greek `μ` for micro.
const INPUT_PREFIXES: [(&str, f64); 11] = [
    ("f", 1e-15),
    ("p", 1e-12),
    ("n", 1e-9),
    ("µ", 1e-6),
    ("μ", 1e-6),
    ("u", 1e-6),
    ("m", 1e-3),
    ("k", 1e3),
    ("M", 1e6),
    ("G", 1e9),
    ("T", 1e12),
];

/// A unit of measure: its symbol, other spellings accepted on input, and its size in SI base units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Unit {
    pub symbol: &'static str,
    pub aliases: &'static [&'static str],
    /// SI value of one unit (1e-3 for the gram, whose SI base is the kilogram).
    pub si_per_unit: f64,
    /// Whether engineering prefixes are shown on output (not for kg/m³).
    pub prefixable: bool,
    /// Other units of the same quantity accepted on input, with the SI value of one of them
    /// (`km/h`, `g/cm³`).
    pub others: &'static [(&'static str, f64)],
}

pub const DIMENSIONLESS: Unit = Unit {
    symbol: "",
    aliases: &[],
    si_per_unit: 1.0,
    prefixable: false,
    others: &[],
};
pub const METRE: Unit = Unit {
    symbol: "m",
    aliases: &[],
    si_per_unit: 1.0,
    prefixable: true,
    others: &[],
};
pub const SECOND: Unit = Unit {
    symbol: "s",
    aliases: &[],
    si_per_unit: 1.0,
    prefixable: true,
    others: &[],
};
pub const GRAM: Unit = Unit {
    symbol: "g",
    aliases: &[],
    si_per_unit: 1e-3,
    prefixable: true,
    others: &[],
};
pub const NEWTON: Unit = Unit {
    symbol: "N",
    aliases: &[],
    si_per_unit: 1.0,
    prefixable: true,
    others: &[],
};
pub const PASCAL: Unit = Unit {
    symbol: "Pa",
    aliases: &[],
    si_per_unit: 1.0,
    prefixable: true,
    others: &[("N/mm²", 1e6), ("N/mm2", 1e6)],
};
pub const JOULE: Unit = Unit {
    symbol: "J",
    aliases: &[],
    si_per_unit: 1.0,
    prefixable: true,
    others: &[],
};
/// Velocities read best in m/s at impact speeds, so they are shown without a prefix.
pub const METRE_PER_SECOND: Unit = Unit {
    symbol: "m/s",
    aliases: &[],
    si_per_unit: 1.0,
    prefixable: false,
    others: &[("km/h", 1.0 / 3.6)],
};
pub const KG_PER_CUBIC_METRE: Unit = Unit {
    symbol: "kg/m³",
    aliases: &["kg/m3", "kg/m^3"],
    si_per_unit: 1.0,
    prefixable: false,
    others: &[("g/cm³", 1e3), ("g/cm3", 1e3), ("g/cc", 1e3)],
};

pub const HERTZ: Unit = Unit {
    symbol: "Hz",
    aliases: &[],
    si_per_unit: 1.0,
    prefixable: true,
    others: &[],
};
pub const NEWTON_PER_METRE: Unit = Unit {
    symbol: "N/m",
    aliases: &[],
    si_per_unit: 1.0,
    prefixable: false,
    others: &[("N/mm", 1e3)],
};
pub const NEWTON_SECOND_PER_METRE: Unit = Unit {
    symbol: "N·s/m",
    aliases: &["N*s/m", "Ns/m", "N s/m"],
    si_per_unit: 1.0,
    prefixable: false,
    others: &[],
};
pub const METRE_PER_SECOND_SQUARED: Unit = Unit {
    symbol: "m/s²",
    aliases: &["m/s2", "m/s^2"],
    si_per_unit: 1.0,
    prefixable: false,
    others: &[],
};

/// The unit a `[system]` key is typed and shown in; the forcing amplitude is a length for a
/// forcing by base motion (`base`), else a force.
pub fn system_key_unit(key: SystemKey, base_motion: bool) -> Unit {
    match key {
        SystemKey::Amplitude | SystemKey::Gap | SystemKey::SecondGap => METRE,
        SystemKey::Gamma | SystemKey::DampingRatio => DIMENSIONLESS,
        SystemKey::Frequency => HERTZ,
        SystemKey::Gravity => METRE_PER_SECOND_SQUARED,
        SystemKey::Stiffness => NEWTON_PER_METRE,
        SystemKey::Damping => NEWTON_SECOND_PER_METRE,
        SystemKey::ForcingAmplitude if base_motion => METRE,
        SystemKey::ForcingAmplitude => NEWTON,
    }
}

/// Parses `text` as a quantity of `unit` and returns its SI value.
///
/// A bare number is in SI base units (`2e11` Pa, `0.01` m, `0.033` kg). A number may carry a unit
/// (`10 mm`, `0.3 m/s`, `200 GPa`, `33 g`) or just a prefix on the SI base unit (`200G`, `10m` is
/// ten metres on a length but `300m` is 0.3 on a velocity). Dimensionless values accept `%`.
pub fn parse(text: &str, unit: Unit) -> Result<f64, String> {
    let text = text.trim();
    if text.is_empty() {
        return Err("empty: type a number".into());
    }
    let (number, rest) = split_number(text).ok_or_else(|| format!("'{text}' is not a number"))?;
    let factor = suffix_factor(rest.trim(), unit)?;
    let value = number * factor;
    if value.is_finite() {
        Ok(value)
    } else {
        Err(format!("'{text}' is out of range"))
    }
}

/// The longest leading part of `text` that is a finite decimal number, and the rest.
fn split_number(text: &str) -> Option<(f64, &str)> {
    let numeric_prefix_len = text
        .char_indices()
        .take_while(|(_, c)| c.is_ascii_digit() || matches!(c, '+' | '-' | '.' | 'e' | 'E'))
        .map(|(i, c)| i + c.len_utf8())
        .last()?;
    (1..=numeric_prefix_len)
        .rev()
        .filter(|&end| text.is_char_boundary(end))
        .find_map(|end| {
            let number: f64 = text[..end].parse().ok()?;
            number.is_finite().then_some((number, &text[end..]))
        })
}

/// The factor a unit suffix applies to the number, relative to SI base units.
fn suffix_factor(suffix: &str, unit: Unit) -> Result<f64, String> {
    if suffix.is_empty() {
        return Ok(1.0);
    }
    let symbols = std::iter::once(unit.symbol)
        .chain(unit.aliases.iter().copied())
        .filter(|s| !s.is_empty());
    for symbol in symbols {
        if suffix == symbol {
            return Ok(unit.si_per_unit);
        }
        // Centi only on a unit (`cm`, `cm/s`): a bare `c` would be a surprise.
        if let Some(head) = suffix.strip_suffix(symbol)
            && let Some(factor) = input_prefix(head).or((head == "c").then_some(1e-2))
        {
            return Ok(factor * unit.si_per_unit);
        }
    }
    if let Some(&(_, si)) = unit.others.iter().find(|(other, _)| *other == suffix) {
        return Ok(si);
    }
    if let Some(factor) = input_prefix(suffix) {
        return Ok(factor);
    }
    if unit.symbol.is_empty() && suffix == "%" {
        return Ok(0.01);
    }
    let expected = if unit.symbol.is_empty() {
        "no unit".to_string()
    } else {
        let others: Vec<&str> = unit.others.iter().map(|(o, _)| *o).collect();
        let others = match others.first() {
            Some(_) => format!(", {}", others.join(", ")),
            None => String::new(),
        };
        format!("{}{others} or a bare number in SI", unit.symbol)
    };
    Err(format!(
        "unknown unit '{suffix}' (expected {expected}, with an optional prefix f p n µ m c k M G T)"
    ))
}

fn input_prefix(head: &str) -> Option<f64> {
    INPUT_PREFIXES
        .iter()
        .find(|(symbol, _)| *symbol == head)
        .map(|&(_, factor)| factor)
}

/// `value` rounded to `sig` significant digits, without trailing zeros; scientific notation
/// outside 1e-4 ≤ |value| < 1e7. Non-finite values print as `—` or `∞` (never NaN on screen).
pub fn sig(value: f64, sig: usize) -> String {
    format::significant(value, sig, Zeros::Trim)
}

/// `value` in at most `width` columns, never cut: `digits` significant digits or fewer, plain
/// (`0.3`, `150.7`) while that fits, else compact scientific (`1.51e6`, `2.7e10`, `9.1e-15`); the
/// most significant digits win, plain on a tie. When not even one digit fits, `…` (`—`/`∞` for a
/// NaN or an infinity, `…` too if those do not fit).
pub fn fit(value: f64, digits: usize, width: usize) -> String {
    let fits = |s: &String| s.chars().count() <= width;
    if value != 0.0 && value.is_finite() {
        for d in (1..=digits.max(1)).rev() {
            let plain = format::significant(value, d, Zeros::Trim);
            if fits(&plain) {
                return plain;
            }
            let scientific = format::scientific(value, d, Zeros::Trim);
            if fits(&scientific) {
                return scientific;
            }
        }
    } else {
        // `0` for either zero (a rounding would keep −0's sign), `—` or `∞` for the others.
        let text = sig(value, digits);
        if fits(&text) {
            return text;
        }
    }
    if width == 0 {
        String::new()
    } else {
        "…".into()
    }
}

/// `value_si` shown in `unit` with a fixed `prefix`, e.g. `10 mm`.
pub fn with_prefix(value_si: f64, unit: Unit, prefix: Prefix, digits: usize) -> String {
    let number = sig(value_si / (prefix.factor * unit.si_per_unit), digits);
    format::with_unit(number, prefix.symbol, unit.symbol)
}

/// The engineering prefix that brings `magnitude_si` (in SI base units) into [1, 1000) of `unit`.
pub fn engineering_prefix(magnitude_si: f64, unit: Unit) -> Prefix {
    if !unit.prefixable || !magnitude_si.is_finite() || magnitude_si == 0.0 {
        return NONE;
    }
    let in_unit = magnitude_si.abs() / unit.si_per_unit;
    ENGINEERING
        .iter()
        .rev()
        .find(|p| in_unit >= p.factor * (1.0 - 1e-12))
        .copied()
        .unwrap_or(FEMTO)
}

/// `value_si` in `unit` with the engineering prefix that suits it, e.g. `32.67 g`, `4.345 GPa`;
/// scientific beyond f … T (`1e-300 m`), and no prefix on units that take none (m/s, kg/m³).
pub fn engineering(value_si: f64, unit: Unit, digits: usize) -> String {
    let value = value_si / unit.si_per_unit;
    if !value.is_finite() {
        sig(value, digits)
    } else if unit.prefixable {
        format::engineering(value, unit.symbol, digits, Zeros::Trim)
    } else {
        format::with_unit(sig(value, digits), "", unit.symbol)
    }
}

/// The symbol of a scene key as the form and the axes write it: `v₀`, `R`, `σ_y`.
pub fn key_label(key: SceneKey) -> &'static str {
    match key {
        SceneKey::V0 => "v₀",
        SceneKey::Restitution => "e",
        SceneKey::PlasticIndentation => "x_pl",
        SceneKey::Body(_, field) => match field {
            BodyField::Radius => "R",
            BodyField::Length => "L",
            BodyField::Mass => "mass",
            BodyField::YoungsModulus => "E",
            BodyField::PoissonRatio => "ν",
            BodyField::YieldStress => "σ_y",
            BodyField::Density => "ρ",
        },
    }
}

/// The short name of a key on an axis: `v₀`, `R₁`, `E₂`.
pub fn key_symbol(key: SceneKey) -> String {
    let label = key_label(key);
    match key {
        SceneKey::Body(BodyIndex::One, _) => format!("{label}₁"),
        SceneKey::Body(BodyIndex::Two, _) => format!("{label}₂"),
        _ => label.to_string(),
    }
}

/// The unit a key's values are typed and shown in.
pub fn key_unit(key: SceneKey) -> Unit {
    match key {
        SceneKey::V0 => METRE_PER_SECOND,
        SceneKey::Restitution => DIMENSIONLESS,
        SceneKey::PlasticIndentation => METRE,
        SceneKey::Body(_, field) => match field {
            BodyField::Radius | BodyField::Length => METRE,
            BodyField::Mass => GRAM,
            BodyField::YoungsModulus | BodyField::YieldStress => PASCAL,
            BodyField::PoissonRatio => DIMENSIONLESS,
            BodyField::Density => KG_PER_CUBIC_METRE,
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() <= 1e-12 * b.abs()
    }

    #[test]
    fn a_keys_symbol_names_its_body() {
        assert_eq!(
            key_symbol(SceneKey::Body(BodyIndex::Two, BodyField::YoungsModulus)),
            "E₂"
        );
    }

    #[test]
    fn fit_never_cuts_a_number() {
        assert_eq!(fit(7.575, 4, 6), "7.575");
        assert_eq!(fit(1_506_870.0, 4, 6), "1.51e6");
        assert_eq!(fit(2.71e10, 4, 6), "2.7e10");
        assert_eq!(fit(2.71e10, 4, 8), "2.71e10");
        assert_eq!(fit(9.131e-15, 4, 6), "9e-15");
        assert_eq!(fit(9.131e-15, 4, 8), "9.13e-15");
        assert_eq!(fit(-1e300, 4, 3), "…");
        assert_eq!(fit(f64::NAN, 4, 6), "—");
        // Either zero is `0`, never `-0`; not even that fits in no room.
        assert_eq!(fit(0.0, 4, 6), "0");
        assert_eq!(fit(-0.0, 4, 6), "0");
        assert_eq!(fit(0.0, 4, 0), "");
        for value in [1.234e-9, 9.99e5, 123_456.0, -0.000_123_4, 5e22, 0.0] {
            for width in 1..12 {
                let text = fit(value, 4, width);
                assert!(text.chars().count() <= width, "{value} in {width}: {text}");
                if text != "…" {
                    let back: f64 = text.parse().unwrap();
                    assert!((back - value).abs() <= 0.5 * value.abs(), "{value}: {text}");
                }
            }
        }
    }

    #[test]
    fn issue_examples_parse_to_si() {
        assert!(close(parse("200G", PASCAL).unwrap(), 2e11));
        assert!(close(parse("2e11", PASCAL).unwrap(), 2e11));
        assert!(close(parse("10 mm", METRE).unwrap(), 0.01));
        assert!(close(parse("0.3 m/s", METRE_PER_SECOND).unwrap(), 0.3));
    }

    #[test]
    fn units_prefixes_and_aliases() {
        assert!(close(parse("200 GPa", PASCAL).unwrap(), 2e11));
        assert!(close(parse("780MPa", PASCAL).unwrap(), 7.8e8));
        assert!(close(parse("2.3 µm", METRE).unwrap(), 2.3e-6));
        assert!(close(parse("2.3um", METRE).unwrap(), 2.3e-6));
        assert!(close(parse("2.3 μm", METRE).unwrap(), 2.3e-6));
        assert!(close(parse("300 mm/s", METRE_PER_SECOND).unwrap(), 0.3));
        assert!(close(parse("300m", METRE_PER_SECOND).unwrap(), 0.3));
        // On a length, a lone "m" is the metre, not milli.
        assert!(close(parse("10m", METRE).unwrap(), 10.0));
        assert!(close(parse("33 g", GRAM).unwrap(), 0.033));
        assert!(close(parse("1 kg", GRAM).unwrap(), 1.0));
        assert!(close(parse("0.5", GRAM).unwrap(), 0.5));
        assert!(close(
            parse("7800 kg/m3", KG_PER_CUBIC_METRE).unwrap(),
            7800.0
        ));
        assert!(close(parse("7.8k", KG_PER_CUBIC_METRE).unwrap(), 7800.0));
        assert!(close(parse("60%", DIMENSIONLESS).unwrap(), 0.6));
        assert!(close(parse("1.5 fm", METRE).unwrap(), 1.5e-15));
    }

    /// Every common way to type a length, a speed, a density or a stress, as a user would.
    #[test]
    fn common_units_of_lengths_speeds_densities_and_stresses() {
        for (text, si) in [
            ("2 cm", 0.02),
            ("2cm", 0.02),
            ("20 mm", 0.02),
            ("20000 µm", 0.02),
            ("20000um", 0.02),
            ("0.02 m", 0.02),
            ("0.02", 0.02),
        ] {
            assert!(close(parse(text, METRE).unwrap(), si), "{text}");
        }
        for (text, si) in [
            ("100 cm/s", 1.0),
            ("3.6 km/h", 1.0),
            ("1000 mm/s", 1.0),
            ("1 m/s", 1.0),
        ] {
            assert!(close(parse(text, METRE_PER_SECOND).unwrap(), si), "{text}");
        }
        for text in ["7.8 g/cm³", "7.8 g/cm3", "7.8 g/cc", "7800 kg/m³"] {
            assert!(
                close(parse(text, KG_PER_CUBIC_METRE).unwrap(), 7800.0),
                "{text}"
            );
        }
        assert!(close(parse("620 N/mm²", PASCAL).unwrap(), 6.2e8));
        // Centi only on a unit: a bare `c` is not a length.
        assert!(parse("2 c", METRE).is_err());
        let refused = parse("3 km/s/h", METRE_PER_SECOND).unwrap_err();
        assert!(refused.contains("km/h"), "the others are named: {refused}");
        assert!(close(parse(" -1.5E-3 ", DIMENSIONLESS).unwrap(), -1.5e-3));
    }

    #[test]
    fn bad_input_says_why() {
        assert_eq!(parse("", METRE).unwrap_err(), "empty: type a number");
        assert_eq!(parse("abc", METRE).unwrap_err(), "'abc' is not a number");
        assert!(
            parse("10 furlongs", METRE)
                .unwrap_err()
                .starts_with("unknown unit 'furlongs' (expected m")
        );
        assert!(parse("1 kg", PASCAL).unwrap_err().contains("unknown unit"));
        assert!(
            parse("1e308 T", PASCAL)
                .unwrap_err()
                .contains("out of range")
        );
        assert!(parse("inf", METRE).is_err());
        assert!(parse("NaN", METRE).is_err());
        assert!(parse("5 %", METRE).is_err());
    }

    #[test]
    fn significant_digits() {
        assert_eq!(sig(0.3, 6), "0.3");
        assert_eq!(sig(9.112345, 4), "9.112");
        assert_eq!(sig(403.24, 4), "403.2");
        assert_eq!(sig(9.99996, 4), "10");
        assert_eq!(sig(-0.21347, 3), "-0.213");
        assert_eq!(sig(1.465e10, 4), "1.465e10");
        assert_eq!(sig(2.5e-6, 3), "2.5e-6");
        assert_eq!(sig(0.0, 3), "0");
        assert_eq!(sig(f64::NAN, 3), "—");
        assert_eq!(sig(f64::INFINITY, 3), "∞");
    }

    #[test]
    fn engineering_units() {
        assert_eq!(engineering(9.11e-6, METRE, 4), "9.11 µm");
        assert_eq!(engineering(8.9e-5, SECOND, 3), "89 µs");
        assert_eq!(engineering(0.0326725, GRAM, 4), "32.67 g");
        assert_eq!(engineering(1.0, GRAM, 4), "1 kg");
        assert_eq!(engineering(4.3452e9, PASCAL, 4), "4.345 GPa");
        assert_eq!(engineering(999.96, NEWTON, 4), "1 kN");
        assert_eq!(engineering(0.3, METRE_PER_SECOND, 4), "0.3 m/s");
        assert_eq!(engineering(7800.0, KG_PER_CUBIC_METRE, 4), "7800 kg/m³");
        assert_eq!(engineering(0.6, DIMENSIONLESS, 4), "0.6");
        assert_eq!(engineering(2.5e-15, METRE, 4), "2.5 fm");
        assert_eq!(engineering_prefix(2.5e-15, METRE), FEMTO);
        assert_eq!(with_prefix(0.01, METRE, MILLI, 6), "10 mm");
        assert_eq!(with_prefix(2e11, PASCAL, GIGA, 6), "200 GPa");
    }

    #[test]
    fn engineering_edges() {
        assert_eq!(engineering(1e-300, METRE, 4), "1e-300 m");
        assert_eq!(engineering(1e300, PASCAL, 4), "1e300 Pa");
        assert_eq!(engineering(1e-300, GRAM, 4), "1e-297 g");
        assert_eq!(engineering(-0.0326725, GRAM, 4), "-32.67 g");
        assert_eq!(engineering(0.0, NEWTON, 4), "0 N");
        assert_eq!(engineering(999.96e3, NEWTON, 4), "1 MN");
        assert_eq!(engineering(999.96e12, NEWTON, 4), "1e15 N");
        assert_eq!(engineering(1e-300, METRE_PER_SECOND, 4), "1e-300 m/s");
        assert_eq!(engineering(f64::NAN, METRE, 4), "—");
        assert_eq!(engineering(f64::NEG_INFINITY, METRE, 4), "−∞");
        assert_eq!(sig(1e-300, 4), "1e-300");
    }

    #[test]
    fn formatted_values_parse_back() {
        for (value, unit) in [
            (2.3e-6, METRE),
            (0.0326725, GRAM),
            (7.8e8, PASCAL),
            (0.21, METRE_PER_SECOND),
            (7800.0, KG_PER_CUBIC_METRE),
            (1.5e-15, METRE),
            (1e-300, METRE),
            (1e300, PASCAL),
            (-999.96, NEWTON),
        ] {
            let text = engineering(value, unit, 6);
            assert!(close(parse(&text, unit).unwrap(), value), "{text}");
        }
    }
}
