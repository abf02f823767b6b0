//! Numbers as text, fast: the writers (Modelica, DXF, OBJ, URDF, MJCF, the contact data) print
//! millions of numbers for a large assembly, and the standard library's shortest formatting
//! (Grisu with a Dragon fallback behind `core::fmt`) was a tenth of a conversion's instructions.
//!
//! The shortest round-trip digits come from `ryu`; they are the same digits the standard library
//! finds (both give the shortest decimal that reads back to the same value, the one nearest to
//! it where several are equally short), and this module lays them out exactly as `{:?}` and `{}`
//! do, so every file keeps its bytes (`tests` compares them on millions of values).

use std::fmt;

/// `x` printed as `format!("{x}")` prints it: positional, no exponent, no `.0` (`1`, `0.00001`).
#[derive(Clone, Copy, Debug)]
pub struct Disp(pub f64);

impl fmt::Display for Disp {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut out = Text::new();
        lay_out(&mut out, self.0, false, Layout::Display);
        f.write_str(out.as_str())
    }
}

/// `x` as `format!("{x:?}")` prints it (`1.0`, `0.0001`, `1e-5`, `1.5e16`), `-0` as `0.0`: the
/// number format of the writers.
pub fn dbg(x: f64) -> String {
    let mut s = String::with_capacity(24);
    push_dbg(&mut s, if x == 0.0 { 0.0 } else { x });
    s
}

/// Appends `x` as `format!("{x:?}")` prints it to `s`, without going through `core::fmt`.
pub fn push_dbg(s: &mut String, x: f64) {
    let mut out = Text::new();
    lay_out(&mut out, x, false, Layout::Debug);
    s.push_str(out.as_str());
}

/// Appends `x` as `format!("{x}")` prints it (as [`Disp`]) to `s`, without going through
/// `core::fmt`.
pub fn push_disp(s: &mut String, x: f64) {
    let mut out = Text::new();
    lay_out(&mut out, x, false, Layout::Display);
    s.push_str(out.as_str());
}

/// Appends the integer `n` in decimal to `s`, as `format!("{n}")` prints it.
pub fn push_uint(s: &mut String, mut n: u64) {
    let mut digits = [0u8; 20];
    let mut at = digits.len();
    loop {
        at -= 1;
        digits[at] = b'0' + (n % 10) as u8;
        n /= 10;
        if n == 0 {
            break;
        }
    }
    s.push_str(std::str::from_utf8(&digits[at..]).unwrap_or_default());
}

/// Appends the `f32` `x` as `format!("{x}")` prints it to `out`.
pub fn push_disp32(out: &mut Vec<u8>, x: f32) {
    let mut text = Text::new();
    lay_out(&mut text, f64::from(x), true, Layout::Display);
    out.extend_from_slice(text.as_bytes());
}

/// The number of significant digits of `x`'s shortest round-trip decimal (0 for zero and
/// non-finite values).
pub fn significant_digits(x: f64) -> usize {
    if x == 0.0 || !x.is_finite() {
        return 0;
    }
    digits_in(&dbg(x))
}

/// The number of significant digits of a number as [`dbg`] wrote it (its mantissa's digits
/// without leading and trailing zeros): a writer that needs both the text and its length
/// formats once.
pub fn digits_in(text: &str) -> usize {
    let mantissa = text.split(['e', 'E']).next().unwrap_or(text);
    let digits: Vec<u8> = mantissa.bytes().filter(u8::is_ascii_digit).collect();
    let first = digits.iter().position(|&d| d != b'0');
    let last = digits.iter().rposition(|&d| d != b'0');
    first.zip(last).map_or(0, |(a, b)| b + 1 - a)
}

/// The shortest round-trip digits of a finite, nonzero `x` (of an `f32` where `single`), as the
/// standard library chooses them: where two candidates of that length are equally near, `ryu`
/// takes the even one and the standard library the larger, so an exact tie is moved up.
fn shortest(x: f64, single: bool) -> Digits {
    let abs = x.abs();
    if abs >= 1e38 {
        // Too large for the tie check in 128 bits; rare enough for the standard library.
        return if single { Digits::of(&format!("{:e}", x as f32)) } else { Digits::of(&format!("{x:e}")) };
    }
    let mut ryu = ryu::Buffer::new();
    let mut d = if single { Digits::of(ryu.format_finite(x as f32)) } else { Digits::of(ryu.format_finite(x)) };
    if let Some(p) = exact_digits(abs) {
        if p % 10 == 5 {
            let lo = p / 10;
            let n_p = decimal_len(p);
            if d.len + 1 == n_p && d.value() == lo {
                let hi = lo + 1;
                let grow = decimal_len(hi) as i32 - decimal_len(lo) as i32;
                let point = d.point + grow;
                d = Digits::of_integer(hi);
                d.point = point;
            }
        }
    }
    d
}

/// The significant digits of `x`'s exact binary value as an integer without trailing zeros,
/// where there are at most 18 of them (the only case a tie between two shortest candidates of
/// up to 17 digits can arise in).
fn exact_digits(abs: f64) -> Option<u128> {
    let bits = abs.to_bits();
    let exp = ((bits >> 52) & 0x7ff) as i32;
    let frac = bits & ((1u64 << 52) - 1);
    let (mut m, mut e) = if exp == 0 { (frac, -1074) } else { (frac | (1u64 << 52), exp - 1075) };
    if m == 0 {
        return None;
    }
    let tz = m.trailing_zeros();
    m >>= tz;
    e += tz as i32;
    // Most values have many fractional bits (e < -25): their exact decimal has more than 18
    // significant digits, so no tie. Where the product fits 64 bits, it is done in 64 bits.
    let bits = 64 - m.leading_zeros() as i32;
    if e < -25 {
        return None;
    }
    if e >= 0 && bits + e <= 63 {
        let mut p = m << e;
        while p % 10 == 0 {
            p /= 10;
        }
        return (p < 1_000_000_000_000_000_000).then_some(u128::from(p));
    }
    let mut p = if e >= 0 {
        if bits + e > 127 {
            return None;
        }
        (m as u128) << e
    } else {
        (m as u128) * 5u128.pow((-e) as u32)
    };
    while p % 10 == 0 {
        p /= 10;
    }
    (p < 1_000_000_000_000_000_000).then_some(p)
}

fn decimal_len(mut v: u128) -> usize {
    let mut n = 1;
    while v >= 10 {
        v /= 10;
        n += 1;
    }
    n
}

#[derive(Clone, Copy, PartialEq)]
enum Layout {
    /// `{:?}`: positional with at least one fractional digit for 1e-4 <= |x| < 1e16, else
    /// exponential (`1e-5`, `1.25e16`).
    Debug,
    /// `{}`: always positional, no fractional digits where there are none.
    Display,
}

/// A number's text (ASCII only: digits, '.', '-', 'e' and the letters of "inf"/"NaN"), on the
/// stack up to 32 bytes (every `{:?}` form is shorter), on the heap beyond (a positional
/// `{}` of a very large or small value).
struct Text {
    buf: [u8; 32],
    len: usize,
    long: Vec<u8>,
}

impl Text {
    fn new() -> Self {
        Text { buf: [0; 32], len: 0, long: Vec::new() }
    }
    fn push(&mut self, b: u8) {
        if self.len < self.buf.len() {
            self.buf[self.len] = b;
            self.len += 1;
        } else {
            if self.long.is_empty() {
                self.long.extend_from_slice(&self.buf);
            }
            self.long.push(b);
        }
    }
    fn push_str(&mut self, s: &[u8]) {
        if self.long.is_empty() && self.len + s.len() <= self.buf.len() {
            self.buf[self.len..self.len + s.len()].copy_from_slice(s);
            self.len += s.len();
            return;
        }
        for &b in s {
            self.push(b);
        }
    }
    fn zeros(&mut self, n: usize) {
        for _ in 0..n {
            self.push(b'0');
        }
    }
    fn as_bytes(&self) -> &[u8] {
        if self.long.is_empty() {
            &self.buf[..self.len]
        } else {
            &self.long
        }
    }
    fn as_str(&self) -> &str {
        std::str::from_utf8(self.as_bytes()).unwrap_or("")
    }
}

/// Shortest digits without leading or trailing zeros, `x = 0.d1 d2 ... dn * 10^point`.
struct Digits {
    d: [u8; 17],
    len: usize,
    point: i32,
}

impl Digits {
    fn of_integer(mut v: u128) -> Digits {
        let n = decimal_len(v);
        let mut d = [0u8; 17];
        for k in (0..n.min(17)).rev() {
            d[k] = b'0' + (v % 10) as u8;
            v /= 10;
        }
        let mut len = n.min(17);
        while len > 0 && d[len - 1] == b'0' {
            len -= 1;
        }
        Digits { d, len, point: n as i32 }
    }

    /// The digits as an integer.
    fn value(&self) -> u128 {
        self.d[..self.len].iter().fold(0u128, |v, &b| v * 10 + u128::from(b - b'0'))
    }

    /// Reads `ryu`'s text (`-1.2345e-7`, `123.45`, `0.00012`, `1e16`, `1.0`), without its sign.
    fn of(text: &str) -> Digits {
        let text = text.strip_prefix('-').unwrap_or(text);
        let (mantissa, exp) = match text.split_once('e') {
            Some((m, e)) => (m, e.parse::<i32>().unwrap_or(0)),
            None => (text, 0),
        };
        let mut d = [0u8; 17];
        let mut len = 0;
        // Digits seen before the point, and leading zeros skipped after it.
        let mut before = 0i32;
        let mut seen_point = false;
        let mut leading = 0i32;
        for b in mantissa.bytes() {
            match b {
                b'.' => seen_point = true,
                b'0'..=b'9' => {
                    if len == 0 && b == b'0' {
                        if seen_point {
                            leading += 1;
                        }
                        continue;
                    }
                    if !seen_point {
                        before += 1;
                    }
                    if len < d.len() {
                        d[len] = b;
                        len += 1;
                    }
                }
                _ => {}
            }
        }
        // Integer digits that are zeros after the significant ones (e.g. "1200.0") count in
        // `before` already; fractional leading zeros shift the point left.
        let point = if before > 0 { before + exp } else { -leading + exp };
        while len > 0 && d[len - 1] == b'0' {
            len -= 1;
        }
        Digits { d, len, point }
    }
}

fn lay_out(out: &mut Text, x: f64, single: bool, layout: Layout) {
    if x.is_nan() {
        out.push_str(b"NaN");
        return;
    }
    if x.is_sign_negative() {
        out.push(b'-');
    }
    if x.is_infinite() {
        out.push_str(b"inf");
        return;
    }
    if x == 0.0 {
        out.push_str(if layout == Layout::Debug { b"0.0" } else { b"0" });
        return;
    }
    let abs = x.abs();
    // Nearly always `ryu`'s own text is already the standard library's: it differs only where
    // two shortest candidates tie, for `{:?}` between 1e-5 and 1e-4 (positional there, `1e-5`
    // in the standard library), and for `{}` in `ryu`'s exponential forms and its `.0`.
    if abs < 1e38 && exact_digits(abs).is_none_or(|p| p % 10 != 5) {
        let mut ryu = ryu::Buffer::new();
        let t = if single { ryu.format_finite(x as f32) } else { ryu.format_finite(x) };
        let t = t.strip_prefix('-').unwrap_or(t).as_bytes();
        match layout {
            Layout::Debug if !(1e-5..1e-4).contains(&abs) => {
                out.push_str(t);
                return;
            }
            Layout::Display if !t.contains(&b'e') => {
                out.push_str(t.strip_suffix(b".0").unwrap_or(t));
                return;
            }
            _ => {}
        }
    }
    let digits = shortest(x, single);
    let d = &digits.d[..digits.len];
    let p = digits.point;
    if layout == Layout::Debug && !(1e-4..1e16).contains(&abs) {
        out.push(d[0]);
        if d.len() > 1 {
            out.push(b'.');
            out.push_str(&d[1..]);
        }
        out.push(b'e');
        let e = p - 1;
        if e < 0 {
            out.push(b'-');
        }
        let mut itoa = [0u8; 4];
        let mut n = 0;
        let mut v = e.unsigned_abs();
        loop {
            itoa[n] = b'0' + (v % 10) as u8;
            n += 1;
            v /= 10;
            if v == 0 {
                break;
            }
        }
        for k in (0..n).rev() {
            out.push(itoa[k]);
        }
        return;
    }
    let min_frac = if layout == Layout::Debug { 1 } else { 0 };
    if p <= 0 {
        out.push_str(b"0.");
        out.zeros(p.unsigned_abs() as usize);
        out.push_str(d);
    } else if (p as usize) >= d.len() {
        out.push_str(d);
        out.zeros(p as usize - d.len());
        if min_frac > 0 {
            out.push_str(b".0");
        }
    } else {
        out.push_str(&d[..p as usize]);
        out.push(b'.');
        out.push_str(&d[p as usize..]);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A deterministic stream of values: random bit patterns (every exponent) and random
    /// values of the magnitudes CAD data has, both signs.
    fn values(n: usize) -> Vec<f64> {
        let mut state = 0x9E37_79B9_7F4A_7C15u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        let mut v = Vec::with_capacity(n + 64);
        for k in 0..n {
            let bits = next();
            v.push(match k % 4 {
                0 => f64::from_bits(bits),
                1 => (bits >> 11) as f64 / (1u64 << 53) as f64 * 10f64.powi((k % 40) as i32 - 20),
                2 => ((bits % 2_000_001) as f64 - 1e6) / 10f64.powi((k % 12) as i32),
                _ => f64::from(f32::from_bits(bits as u32)),
            });
        }
        for e in -330..=310 {
            for m in [1.0, 1.5, 9.999_999_999_999_999, 2.5] {
                v.push(m * 10f64.powi(e));
            }
        }
        v.extend([
            0.0,
            -0.0,
            1e-4,
            9.999_999_999_999_999e-5,
            1e16,
            9.999_999_999_999_998e15,
            0.1 + 0.2,
            f64::MIN_POSITIVE,
            5e-324,
            f64::MAX,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
        ]);
        v
    }

    #[test]
    fn the_same_text_as_the_standard_library() {
        for x in values(400_000) {
            assert_eq!(Disp(x).to_string(), format!("{x}"), "{:e} ({:#x})", x, x.to_bits());
            let mut s = String::from("a");
            push_disp(&mut s, x);
            assert_eq!(s, format!("a{x}"), "{:e} ({:#x})", x, x.to_bits());
            let mut s = String::from("a");
            push_dbg(&mut s, x);
            assert_eq!(s, format!("a{x:?}"), "{:e} ({:#x})", x, x.to_bits());
            if x != 0.0 {
                assert_eq!(dbg(x), format!("{x:?}"));
            }
            let y = x as f32;
            let mut b = Vec::new();
            push_disp32(&mut b, y);
            assert_eq!(String::from_utf8_lossy(&b), format!("{y}"), "{y:e} ({:#x})", y.to_bits());
        }
    }

    #[test]
    fn integers_as_the_standard_library_prints_them() {
        for n in
            [0u64, 1, 9, 10, 99, 100, 12_345, 999_999, 1 << 32, u64::MAX - 1, u64::MAX].into_iter().chain((0..2_000).map(|k| k * 7_919))
        {
            let mut s = String::from("v ");
            push_uint(&mut s, n);
            assert_eq!(s, format!("v {n}"));
        }
    }

    #[test]
    fn digit_counts() {
        assert_eq!(significant_digits(0.1 + 0.2), 17);
        assert_eq!(significant_digits(1200.0), 2);
        assert_eq!(significant_digits(1e-5), 1);
        assert_eq!(significant_digits(-0.001_25), 3);
        assert_eq!(significant_digits(0.0), 0);
        for x in values(20_000) {
            if x.is_finite() && x != 0.0 {
                let s = format!("{x:e}");
                let m = s.split('e').next().unwrap_or("");
                let n = m.bytes().filter(u8::is_ascii_digit).count();
                assert_eq!(significant_digits(x), n, "{s}");
            }
        }
    }
}
