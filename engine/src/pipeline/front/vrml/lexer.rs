//! A streaming tokenizer over a byte slice: no token vector, numbers parsed in place.
//!
//! Whitespace is every byte up to and including space, plus `,` (VRML treats commas as
//! whitespace); `#` starts a comment that runs to the end of the line. Words (node types, field
//! names, DEF names, keywords) run up to the next delimiter: whitespace, `,`, `"`, `#`, `[`, `]`,
//! `{`, `}`. Positions are 1-based lines (LF-counted) and 1-based byte columns.

use crate::pipeline::front::stl::number::parse_f64;

/// Whether `c` ends a word or a number.
#[inline]
pub(super) fn is_delim(c: u8) -> bool {
    c <= b' ' || matches!(c, b',' | b'"' | b'#' | b'[' | b']' | b'{' | b'}' | 0x7f)
}

/// A problem the lexer found, without the file name (the parser adds it).
#[derive(Clone, Debug, PartialEq)]
pub(super) enum LexError {
    /// A token that is not a number where one is required.
    BadNumber(String),
    /// A string without its closing quote.
    UnterminatedString,
    /// Something else than expected; `found` is `None` at the end of the input.
    Expected { expected: &'static str, found: Option<String> },
}

/// A cursor over `b` with line bookkeeping.
#[derive(Clone)]
pub(super) struct Lexer<'s> {
    pub b: &'s [u8],
    pub pos: usize,
    pub line: u32,
    /// Index of the first byte of the current line.
    pub line_start: usize,
}

impl<'s> Lexer<'s> {
    pub fn new(b: &'s [u8], pos: usize, line: u32, line_start: usize) -> Self {
        Lexer { b, pos, line, line_start }
    }

    /// `(line, column)` of the current position.
    pub fn loc(&self) -> (u32, u32) {
        let col = self.pos.saturating_sub(self.line_start) + 1;
        (self.line, u32::try_from(col).unwrap_or(u32::MAX))
    }

    /// Skips whitespace, commas and comments.
    #[inline]
    pub fn ws(&mut self) {
        let b = self.b;
        while let Some(&c) = b.get(self.pos) {
            if c == b'\n' {
                self.pos += 1;
                self.line += 1;
                self.line_start = self.pos;
            } else if c <= b' ' || c == b',' {
                self.pos += 1;
            } else if c == b'#' {
                while let Some(&c) = b.get(self.pos) {
                    if c == b'\n' {
                        break;
                    }
                    self.pos += 1;
                }
            } else {
                break;
            }
        }
    }

    /// The next significant byte (after whitespace), not consumed.
    #[inline]
    pub fn peek(&mut self) -> Option<u8> {
        self.ws();
        self.b.get(self.pos).copied()
    }

    /// Consumes `c` when it is the next significant byte.
    #[inline]
    pub fn eat(&mut self, c: u8) -> bool {
        if self.peek() == Some(c) {
            self.pos += 1;
            true
        } else {
            false
        }
    }

    /// The next word, consumed; `None` (nothing consumed) when the next byte is a delimiter or
    /// the input ends.
    pub fn word(&mut self) -> Option<&'s [u8]> {
        self.ws();
        let start = self.pos;
        let b = self.b;
        while let Some(&c) = b.get(self.pos) {
            if is_delim(c) {
                break;
            }
            self.pos += 1;
        }
        (self.pos > start).then(|| &b[start..self.pos])
    }

    /// The next word without consuming it.
    pub fn peek_word(&mut self) -> Option<&'s [u8]> {
        self.ws();
        let mut i = self.pos;
        while let Some(&c) = self.b.get(i) {
            if is_delim(c) {
                break;
            }
            i += 1;
        }
        (i > self.pos).then(|| &self.b[self.pos..i])
    }

    /// The word after the next one, without consuming anything (`None` when the byte after the
    /// next word is a delimiter such as `{`).
    pub fn peek_second_byte(&mut self) -> Option<u8> {
        let save = self.clone();
        let _ = self.word();
        let c = self.peek();
        *self = save;
        c
    }

    /// A short description of what comes next, for error messages.
    pub fn found(&mut self) -> Option<String> {
        self.ws();
        let c = *self.b.get(self.pos)?;
        if is_delim(c) {
            return Some((c as char).to_string());
        }
        let mut i = self.pos;
        while i < self.b.len() && !is_delim(self.b[i]) && i - self.pos < 40 {
            i += 1;
        }
        Some(String::from_utf8_lossy(&self.b[self.pos..i]).into_owned())
    }

    pub fn expected(&mut self, expected: &'static str) -> LexError {
        LexError::Expected { expected, found: self.found() }
    }

    /// End of the token at the current position: up to the next delimiter, or just past the
    /// current byte when that is a delimiter.
    fn token_end(&self) -> usize {
        match self.b.get(self.pos) {
            None => self.pos,
            Some(&c) if is_delim(c) => self.pos + 1,
            Some(_) => {
                let mut i = self.pos;
                while i < self.b.len() && !is_delim(self.b[i]) {
                    i += 1;
                }
                i
            }
        }
    }

    /// Whether the next significant byte can begin a number.
    #[inline]
    pub fn at_number(&mut self) -> bool {
        matches!(self.peek(), Some(b'0'..=b'9' | b'-' | b'+' | b'.'))
    }

    /// A floating-point number (exactly as `str::parse::<f64>` reads it).
    #[inline]
    pub fn float(&mut self) -> Result<f64, LexError> {
        self.ws();
        if let Some((v, end)) = parse_f64(self.b, self.pos) {
            if self.b.get(end).is_none_or(|&c| is_delim(c)) {
                self.pos = end;
                return Ok(v);
            }
        }
        self.float_slow()
    }

    #[cold]
    fn float_slow(&mut self) -> Result<f64, LexError> {
        if self.pos >= self.b.len() {
            return Err(self.expected("a number"));
        }
        let end = self.token_end();
        let text = &self.b[self.pos..end];
        let parsed = std::str::from_utf8(text).ok().and_then(|s| {
            // Only decimal forms: `inf`, `nan` and `infinity` are not VRML numbers.
            let digits = s.bytes().all(|c| c.is_ascii_digit() || matches!(c, b'+' | b'-' | b'.' | b'e' | b'E'));
            if digits {
                s.parse::<f64>().ok()
            } else {
                None
            }
        });
        match parsed {
            Some(v) if v.is_finite() => {
                self.pos = end;
                Ok(v)
            }
            _ if !text.is_empty() && !is_delim(text[0]) => Err(LexError::BadNumber(String::from_utf8_lossy(text).into_owned())),
            _ => Err(self.expected("a number")),
        }
    }

    /// A 32-bit integer: decimal or `0x` hexadecimal (hex values above `i32::MAX` wrap, as
    /// SFImage pixels and colours written as `0xRRGGBBAA` need).
    #[inline]
    pub fn int(&mut self) -> Result<i32, LexError> {
        self.ws();
        let b = self.b;
        let mut i = self.pos;
        let neg = b.get(i) == Some(&b'-');
        if neg || b.get(i) == Some(&b'+') {
            i += 1;
        }
        let start = i;
        let mut v: i64 = 0;
        while let Some(&c) = b.get(i) {
            let d = c.wrapping_sub(b'0');
            if d > 9 || i - start > 10 {
                break;
            }
            v = v * 10 + i64::from(d);
            i += 1;
        }
        if i > start && b.get(i).is_none_or(|&c| is_delim(c)) {
            let v = if neg { -v } else { v };
            if let Ok(v) = i32::try_from(v) {
                self.pos = i;
                return Ok(v);
            }
        }
        self.int_slow()
    }

    #[cold]
    fn int_slow(&mut self) -> Result<i32, LexError> {
        if self.pos >= self.b.len() {
            return Err(self.expected("an integer"));
        }
        let end = self.token_end();
        let text = &self.b[self.pos..end];
        let s = String::from_utf8_lossy(text).into_owned();
        let (neg, body) = match s.strip_prefix('-') {
            Some(r) => (true, r),
            None => (false, s.strip_prefix('+').unwrap_or(&s)),
        };
        let v = if let Some(hex) = body.strip_prefix("0x").or_else(|| body.strip_prefix("0X")) {
            u32::from_str_radix(hex, 16).ok().map(|u| u as i32)
        } else {
            body.parse::<i32>().ok()
        };
        match v {
            Some(v) => {
                self.pos = end;
                Ok(if neg { v.wrapping_neg() } else { v })
            }
            None if !text.is_empty() && !is_delim(text[0]) => Err(LexError::BadNumber(s)),
            None => Err(self.expected("an integer")),
        }
    }

    /// A quoted string with `\"` and `\\` escapes (the quote is the next significant byte).
    pub fn string(&mut self) -> Result<String, LexError> {
        if self.peek() != Some(b'"') {
            return Err(self.expected("a quoted string"));
        }
        self.pos += 1;
        let b = self.b;
        let mut out = Vec::new();
        loop {
            match b.get(self.pos) {
                None => return Err(LexError::UnterminatedString),
                Some(b'"') => {
                    self.pos += 1;
                    break;
                }
                Some(b'\\') => {
                    if let Some(&c) = b.get(self.pos + 1) {
                        out.push(c);
                        self.pos += 2;
                        if c == b'\n' {
                            self.line += 1;
                            self.line_start = self.pos;
                        }
                    } else {
                        return Err(LexError::UnterminatedString);
                    }
                }
                Some(&c) => {
                    out.push(c);
                    self.pos += 1;
                    if c == b'\n' {
                        self.line += 1;
                        self.line_start = self.pos;
                    }
                }
            }
        }
        Ok(match String::from_utf8(out) {
            Ok(s) => s,
            Err(e) => String::from_utf8_lossy(e.as_bytes()).into_owned(),
        })
    }

    /// Skips a string (the quote is the current byte).
    pub fn skip_string(&mut self) -> Result<(), LexError> {
        self.pos += 1;
        let b = self.b;
        while let Some(&c) = b.get(self.pos) {
            self.pos += 1;
            match c {
                b'"' => return Ok(()),
                b'\\' => {
                    if b.get(self.pos) == Some(&b'\n') {
                        self.line += 1;
                        self.line_start = self.pos + 1;
                    }
                    self.pos += 1;
                }
                b'\n' => {
                    self.line += 1;
                    self.line_start = self.pos;
                }
                _ => {}
            }
        }
        Err(LexError::UnterminatedString)
    }

    /// Skips to just past the bracket or brace that closes the one just consumed (any mix of
    /// `[]{}` counts), honouring strings and comments. No DEF bookkeeping: for PROTO bodies.
    pub fn skip_balanced_raw(&mut self) -> Result<(), LexError> {
        let mut depth = 1u32;
        loop {
            self.ws();
            let Some(&c) = self.b.get(self.pos) else {
                return Err(self.expected("a closing \"}\" or \"]\""));
            };
            match c {
                b'[' | b'{' => {
                    depth += 1;
                    self.pos += 1;
                }
                b']' | b'}' => {
                    depth -= 1;
                    self.pos += 1;
                    if depth == 0 {
                        return Ok(());
                    }
                }
                b'"' => self.skip_string()?,
                _ => self.pos = self.token_end(),
            }
        }
    }

    /// Skips one token (a word, a number, or one delimiter byte).
    pub fn skip_token(&mut self) {
        self.ws();
        self.pos = self.token_end();
    }
}
