//! `{:e}` text of a double, the shortest that reads back as the same number, appended to a byte
//! buffer: the digits come from Żmij (V. Zverovich's algorithm, ported by the `zmij` crate),
//! shortest round-trip digits like the standard library's Grisu/Dragon, re-laid out here as
//! `d.ddde±x` from the places Żmij's two layouts fix (its exponent in the last five bytes, its
//! point): about 400 instructions a number (callgrind), a third of them Żmij's, where scanning its
//! text with `str` searches took 610; a sweep's CSV writes millions of numbers. Żmij and `{:e}`
//! differ only where two shortest texts are equally near the double (Żmij takes the even last
//! digit): both read back as it.

/// Longest text: sign, 17 significant digits, the point, `e`, the exponent's sign and 3 digits.
const LONGEST: usize = 24;

/// Appends `value` as Rust's `{:e}` would write it (`3.669e2`, `-1e-7`, `0e0`; `NaN`, `inf`).
pub fn push_shortest_exp(out: &mut Vec<u8>, value: f64) {
    if !value.is_finite() {
        let text: &[u8] = if value.is_nan() {
            b"NaN"
        } else if value > 0.0 {
            b"inf"
        } else {
            b"-inf"
        };
        out.extend_from_slice(text);
        return;
    }
    let mut zmij = zmij::Buffer::new();
    let text = zmij.format_finite(value).as_bytes();
    out.reserve(LONGEST);
    let body = match text.split_first() {
        Some((b'-', rest)) => {
            out.push(b'-');
            rest
        }
        _ => text,
    };
    let (lead, rest, power) = layout(body);
    let Some((&first, lead)) = lead.split_first() else {
        out.extend_from_slice(b"0e0");
        return;
    };
    out.push(first);
    if !lead.is_empty() || !rest.is_empty() {
        out.push(b'.');
        out.extend_from_slice(lead);
        out.extend_from_slice(rest);
    }
    out.push(b'e');
    if power < 0 {
        out.push(b'-');
    }
    let e = power.unsigned_abs();
    let digit = |d: u32| b'0' + (d % 10) as u8;
    if e >= 100 {
        out.push(digit(e / 100));
    }
    if e >= 10 {
        out.push(digit(e / 10));
    }
    out.push(digit(e));
}

/// Żmij's text of a finite value, without its sign, as the digits before and after the point of
/// a number whose first digit has the decimal exponent `power`, trailing zeros trimmed (`lead`
/// may be left empty only for a zero).
fn layout(body: &[u8]) -> (&[u8], &[u8], i32) {
    // Żmij writes `1e-7` or `1.2345e+30` (scientific: the exponent is among the last five bytes,
    // `e-324`), or `123.45`, `0.00123`, `1230.0` (fixed: always with a point).
    let tail = body.len().saturating_sub(5);
    let (lead, rest, power) = match body[tail..].iter().rposition(|&b| b == b'e') {
        Some(e) => {
            let (mantissa, exponent) = body.split_at(tail + e);
            let (lead, rest) = mantissa.split_at(1);
            (
                lead,
                rest.get(1..).unwrap_or_default(),
                parse_exponent(&exponent[1..]),
            )
        }
        None => {
            let point = body.iter().position(|&b| b == b'.').unwrap_or(body.len());
            let (int, frac) = (&body[..point], body.get(point + 1..).unwrap_or_default());
            if int == b"0" {
                // 0.00123: the first non-zero fraction digit leads.
                let zeros = frac.iter().take_while(|&&d| d == b'0').count();
                (&frac[zeros..], &[][..], -(zeros as i32) - 1)
            } else {
                (int, frac, point as i32 - 1)
            }
        }
    };
    let rest = trim_end_zeros(rest);
    let lead = if rest.is_empty() {
        trim_end_zeros(lead)
    } else {
        lead
    };
    (lead, rest, power)
}

/// `digits` without its trailing zeros.
fn trim_end_zeros(digits: &[u8]) -> &[u8] {
    let kept = digits.iter().rposition(|&d| d != b'0').map_or(0, |i| i + 1);
    &digits[..kept]
}

/// The decimal exponent after Żmij's `e` (signed).
fn parse_exponent(text: &[u8]) -> i32 {
    let (sign, digits) = match text.split_first() {
        Some((b'-', rest)) => (-1, rest),
        Some((b'+', rest)) => (1, rest),
        _ => (1, text),
    };
    sign * digits
        .iter()
        .fold(0i32, |acc, &d| acc * 10 + i32::from(d.wrapping_sub(b'0')))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn shortest(v: f64) -> String {
        let mut bytes = Vec::new();
        push_shortest_exp(&mut bytes, v);
        String::from_utf8(bytes).expect("the text is ASCII")
    }

    /// Both shortest and exact: as many digits as the standard formatter's text, read back as
    /// the same double (a tie between two shortest texts may be broken the other way).
    fn assert_shortest_round_trip(v: f64, context: &str) {
        let (ours, std) = (shortest(v), format!("{v:e}"));
        let mantissa = |s: &str| {
            s.split('e')
                .next()
                .unwrap_or("")
                .replace(['-', '.'], "")
                .len()
        };
        assert_eq!(mantissa(&ours), mantissa(&std), "{ours} vs {std} {context}");
        assert_eq!(
            ours.parse::<f64>().unwrap().to_bits(),
            v.to_bits(),
            "{ours} {context}"
        );
    }

    #[test]
    fn same_text_as_the_standard_formatter() {
        let special = [
            0.0,
            -0.0,
            1.0,
            -1.0,
            0.3,
            1e-7,
            366.898_766_799_700_87,
            8.035_169_159_662_6e-6,
            123_456.0,
            1e15,
            1e16,
            1e17,
            1.5e300,
            f64::MAX,
            f64::MIN_POSITIVE,
            5e-324,
            -2.5e-310,
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ];
        for v in special {
            assert_eq!(shortest(v), format!("{v:e}"), "{v:?}");
        }
        // Random bit patterns (xorshift): every exponent and mantissa, both signs; the same text
        // but for ties, such as 1658206780088562.25 (…562.2e15 here, …562.3e15 from `{:e}`).
        let mut state = 0x9E37_79B9_7F4A_7C15_u64;
        let mut same = 0;
        for _ in 0..200_000 {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            let v = f64::from_bits(state);
            if v.is_finite() {
                assert_shortest_round_trip(v, &format!("({state:#x})"));
                same += usize::from(shortest(v) == format!("{v:e}"));
            }
        }
        assert!(same > 199_000, "{same}");
        assert_eq!(
            shortest(f64::from_bits(0x4317_9085_685d_83c9)),
            "1.6582067800885622e15"
        );
    }

    #[test]
    fn reads_back_exactly() {
        for v in [0.1 + 0.2, 1.0 / 3.0, 2f64.sqrt() * 1e-200] {
            assert_eq!(shortest(v).parse::<f64>().unwrap(), v);
        }
    }
}
