//! The ASCII STL reader (grammar in the parent module's docs).

use super::dedup::MeshBuilder;
use super::number;
use super::{ErrorKind, MAX_TRIANGLES};
use crate::pipeline::ir;

/// An error of the ASCII reader: kind and 1-based line.
pub(crate) type AsciiError = (ErrorKind, usize);

struct Reader<'a> {
    b: &'a [u8],
    pos: usize,
    /// 1-based line of `pos` once whitespace has been skipped.
    line: usize,
    scale: f64,
    facets: u64,
}

/// Bytes up to and including the space are whitespace (space, tab, CR, LF, other control
/// characters, NUL padding); everything else belongs to a token.
#[inline]
fn is_ws(c: u8) -> bool {
    c <= b' '
}

/// Keyword comparison: exact bytes first (the common case), then ASCII case-insensitively.
#[inline]
fn is_kw(tok: &[u8], kw: &[u8]) -> bool {
    tok == kw || tok.eq_ignore_ascii_case(kw)
}

#[inline]
fn starts_with_kw(tok: &[u8], kw: &[u8]) -> bool {
    tok.len() >= kw.len() && tok[..kw.len()].eq_ignore_ascii_case(kw)
}

fn unexpected(expected: &'static str, found: Option<&[u8]>) -> ErrorKind {
    ErrorKind::UnexpectedToken { expected, found: found.map(token_text) }
}

/// A token for an error message: lossy UTF-8, at most 40 characters.
fn token_text(t: &[u8]) -> String {
    let s = String::from_utf8_lossy(t);
    if s.chars().count() > 40 {
        let mut short: String = s.chars().take(40).collect();
        short.push('…');
        short
    } else {
        s.into_owned()
    }
}

impl<'a> Reader<'a> {
    #[inline]
    fn skip_ws(&mut self) {
        while let Some(&c) = self.b.get(self.pos) {
            if !is_ws(c) {
                break;
            }
            if c == b'\n' || (c == b'\r' && self.b.get(self.pos + 1) != Some(&b'\n')) {
                self.line += 1;
            }
            self.pos += 1;
        }
    }

    /// The next token, `None` at end of input.
    #[inline]
    fn token(&mut self) -> Option<&'a [u8]> {
        self.skip_ws();
        let start = self.pos;
        while let Some(&c) = self.b.get(self.pos) {
            if is_ws(c) {
                break;
            }
            self.pos += 1;
        }
        (self.pos > start).then(|| &self.b[start..self.pos])
    }

    #[inline]
    fn keyword(&mut self, kw: &'static [u8], expected: &'static str) -> Result<(), ErrorKind> {
        match self.token() {
            Some(t) if is_kw(t, kw) => Ok(()),
            t => Err(unexpected(expected, t)),
        }
    }

    /// Moves to the end of the current line (the line break itself is left for `skip_ws`).
    fn skip_line(&mut self) {
        while let Some(&c) = self.b.get(self.pos) {
            if c == b'\n' || c == b'\r' {
                break;
            }
            self.pos += 1;
        }
    }

    /// One coordinate, scaled, as `f32`.
    #[inline]
    fn coordinate(&mut self) -> Result<f32, ErrorKind> {
        self.skip_ws();
        let v = match number::parse_f64(self.b, self.pos) {
            Some((v, end)) if self.b.get(end).is_none_or(|&c| is_ws(c)) => {
                self.pos = end;
                v
            }
            _ => {
                let Some(t) = self.token() else {
                    return Err(unexpected("a number", None));
                };
                match std::str::from_utf8(t).ok().and_then(|s| s.parse::<f64>().ok()) {
                    Some(v) => v,
                    None if t.first().is_some_and(u8::is_ascii_alphabetic) && !is_number_word(t) => {
                        return Err(unexpected("a number", Some(t)))
                    }
                    None => return Err(ErrorKind::BadNumber { text: token_text(t) }),
                }
            }
        };
        let x = (v * self.scale) as f32;
        if !x.is_finite() {
            return Err(ErrorKind::NonFinite { facet: self.facets + 1 });
        }
        Ok(x)
    }

    fn vertex(&mut self) -> Result<[f32; 3], ErrorKind> {
        self.keyword(b"vertex", "\"vertex\"")?;
        Ok([self.coordinate()?, self.coordinate()?, self.coordinate()?])
    }

    /// A facet after its `facet` keyword, up to and including `endfacet`.
    fn facet(&mut self, mesh: &mut MeshBuilder) -> Result<(), ErrorKind> {
        let mut t = self.token();
        if t.is_some_and(|t| is_kw(t, b"normal")) {
            // The normal is ignored (it is often wrong and is recomputed by consumers); its three
            // tokens only have to be present and not keywords.
            for _ in 0..3 {
                match self.token() {
                    Some(n) if !n.first().is_some_and(u8::is_ascii_alphabetic) || is_number_word(n) => {}
                    n => return Err(unexpected("a number", n)),
                }
            }
            t = self.token();
        }
        match t {
            Some(t) if is_kw(t, b"outer") => {}
            t => return Err(unexpected("\"outer\"", t)),
        }
        self.keyword(b"loop", "\"loop\"")?;
        let corners = [self.vertex()?, self.vertex()?, self.vertex()?];
        self.keyword(b"endloop", "\"endloop\"")?;
        self.keyword(b"endfacet", "\"endfacet\"")?;
        if self.facets >= MAX_TRIANGLES {
            return Err(ErrorKind::TooManyTriangles { max: MAX_TRIANGLES });
        }
        mesh.triangle(corners);
        self.facets += 1;
        Ok(())
    }
}

/// `nan`, `inf`, `infinity` in any case (words the std parser reads as numbers).
fn is_number_word(t: &[u8]) -> bool {
    let t = t.strip_prefix(b"-").or_else(|| t.strip_prefix(b"+")).unwrap_or(t);
    is_kw(t, b"nan") || is_kw(t, b"inf") || is_kw(t, b"infinity")
}

/// Parses an ASCII STL. `start` is the index after an optional UTF-8 byte order mark.
pub(crate) fn parse(b: &[u8], start: usize, scale: f64) -> Result<ir::Mesh, AsciiError> {
    // Writers produce 150-260 bytes a facet; the hint only saves reallocations.
    let hint = (b.len() / 256).min(MAX_TRIANGLES as usize);
    let mut mesh = MeshBuilder::with_capacity(hint);
    let mut r = Reader { b, pos: start, line: 1, scale, facets: 0 };
    let mut in_solid = false;
    let result = (|| {
        while let Some(t) = r.token() {
            if in_solid {
                if is_kw(t, b"facet") {
                    r.facet(&mut mesh)?;
                } else if starts_with_kw(t, b"endsolid") {
                    r.skip_line();
                    in_solid = false;
                } else {
                    return Err(unexpected("\"facet\" or \"endsolid\"", Some(t)));
                }
            } else if starts_with_kw(t, b"solid") {
                r.skip_line();
                in_solid = true;
            } else {
                return Err(unexpected("\"solid\"", Some(t)));
            }
        }
        Ok(())
    })();
    match result {
        Ok(()) => Ok(mesh.finish()),
        Err(kind) => Err((kind, r.line)),
    }
}
