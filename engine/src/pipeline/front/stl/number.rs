//! Decimal number parsing for ASCII STL.
//!
//! [`parse_f64`] is a fast path that is exact by construction (Clinger's fast path): when the
//! significand has at most 19 digits, fits in 53 bits and the decimal exponent is within ±22, both
//! the significand and the power of ten are exact `f64`s, so one IEEE multiplication or division
//! rounds the exact value once — the same correctly rounded result `str::parse::<f64>` gives.
//! Everything else (long significands, large exponents, `inf`, `nan`, malformed text) returns
//! `None` and the caller falls back to the standard library parser on the whole token.

/// Exact powers of ten representable in `f64`.
const POW10: [f64; 23] =
    [1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22];

/// Parses `[+-]digits[.digits][(e|E)[+-]digits]` starting at `start` (at least one significand
/// digit). Returns the value and the index just past the number, or `None` when the text is not in
/// that form or the value is outside the exact fast path. The caller checks what follows the
/// number.
#[inline]
pub(crate) fn parse_f64(b: &[u8], start: usize) -> Option<(f64, usize)> {
    let mut i = start;
    let neg = match b.get(i) {
        Some(b'-') => {
            i += 1;
            true
        }
        Some(b'+') => {
            i += 1;
            false
        }
        _ => false,
    };
    let mut mant: u64 = 0;
    let mut digits: u32 = 0;
    while let Some(&c) = b.get(i) {
        let d = c.wrapping_sub(b'0');
        if d > 9 {
            break;
        }
        mant = mant.wrapping_mul(10).wrapping_add(u64::from(d));
        digits += 1;
        i += 1;
    }
    let mut exp: i32 = 0;
    if b.get(i) == Some(&b'.') {
        i += 1;
        while let Some(&c) = b.get(i) {
            let d = c.wrapping_sub(b'0');
            if d > 9 {
                break;
            }
            mant = mant.wrapping_mul(10).wrapping_add(u64::from(d));
            digits += 1;
            exp -= 1;
            i += 1;
        }
    }
    if digits == 0 || digits > 19 {
        return None;
    }
    if let Some(b'e' | b'E') = b.get(i) {
        i += 1;
        let eneg = match b.get(i) {
            Some(b'-') => {
                i += 1;
                true
            }
            Some(b'+') => {
                i += 1;
                false
            }
            _ => false,
        };
        let estart = i;
        let mut e: i32 = 0;
        while let Some(&c) = b.get(i) {
            let d = c.wrapping_sub(b'0');
            if d > 9 {
                break;
            }
            if e < 100_000 {
                e = e * 10 + i32::from(d);
            }
            i += 1;
        }
        if i == estart {
            return None;
        }
        exp += if eneg { -e } else { e };
    }
    if mant > (1u64 << 53) {
        return None;
    }
    let v = if mant == 0 {
        0.0
    } else if (0..=22).contains(&exp) {
        mant as f64 * POW10[exp as usize]
    } else if (-22..0).contains(&exp) {
        mant as f64 / POW10[(-exp) as usize]
    } else {
        return None;
    };
    Some((if neg { -v } else { v }, i))
}

#[cfg(test)]
mod tests {
    use super::parse_f64;

    /// The fast path, when it takes `s`, gives exactly the std result. Returns whether it took it.
    fn check(s: &str) -> bool {
        let want: f64 = s.parse().expect("std parses the test input");
        match parse_f64(s.as_bytes(), 0) {
            Some((got, end)) if end == s.len() => {
                assert_eq!(got.to_bits(), want.to_bits(), "{s}: {got} vs {want}");
                true
            }
            _ => false,
        }
    }

    #[test]
    fn agrees_with_std() {
        for s in [
            "0",
            "-0",
            "-0.0",
            "+1",
            "1.",
            ".5",
            "-.5",
            "1.5e-005",
            "1.5E+005",
            "6.000000e+00",
            "-1.206066e+01",
            "5.228807e-002",
            "0.000000e+000",
            "9007199254740992",
            "0.1",
            "0.2",
            "0.3",
            "3.14159265358979",
            "1e22",
            "1e-22",
            "4.9e-5",
            "17.5",
            "-2.736396e+00",
        ] {
            assert!(check(s), "{s} takes the fast path");
        }
    }

    #[test]
    fn declines_outside_fast_path() {
        for s in [
            "",
            "-",
            ".",
            "e5",
            "1e",
            "1e+",
            "nan",
            "inf",
            "1e23",
            "1e-23",
            "12345678901234567890",
            "9007199254740993",
            "123456789012345678",
            "4.318765e-17",
        ] {
            assert!(parse_f64(s.as_bytes(), 0).map(|(_, e)| e == s.len()) != Some(true), "{s}");
        }
    }

    #[test]
    fn stops_at_first_non_number_byte() {
        assert_eq!(parse_f64(b"1.5x", 0), Some((1.5, 3)));
        assert_eq!(parse_f64(b"  -2 ", 2), Some((-2.0, 4)));
    }

    #[test]
    fn pseudo_random_decimals_agree_with_std() {
        // xorshift; decimals shaped like STL writers' `%e` and `%f` output.
        let mut x: u64 = 0x9E37_79B9_7F4A_7C15;
        let mut next = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x
        };
        let mut fast = 0;
        for _ in 0..200_000 {
            let r = next();
            let mant = r % 10_000_000;
            let e = (next() % 41) as i32 - 20;
            let s = match r % 3 {
                0 => format!("{}.{:06}e{:+03}", mant / 1_000_000, mant % 1_000_000, e),
                1 => format!("-{}.{:06}e{:+04}", mant / 1_000_000, mant % 1_000_000, e),
                _ => format!("{}.{}", mant / 1000, mant % 1000),
            };
            fast += usize::from(check(&s));
        }
        // Exponents below -16 (on 7-digit `%e` significands) leave the fast path; the rest take it.
        assert!(fast > 150_000, "{fast}");
    }
}
