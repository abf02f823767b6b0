//! STL front end: ASCII and binary STL bytes in, an [`ir::Mesh`] in metres out. See [`parse`].
//!
//! # Which flavour
//! 1. **Binary** when the size rule holds: the file has at least 84 bytes and its length is exactly
//!    `84 + 50 × n`, `n` being the little-endian `u32` at offset 80. This is decided first, so a
//!    binary file whose 80-byte header begins with `solid` (SolidWorks writes `solid <name>` there)
//!    is read as binary.
//! 2. Otherwise **ASCII** when the file begins with `solid` (any case), after an optional UTF-8 byte
//!    order mark and whitespace.
//! 3. Otherwise an error: [`ErrorKind::TooShort`] below 84 bytes, [`ErrorKind::TruncatedBinary`]
//!    when the declared triangles need more bytes than the file has, [`ErrorKind::NotStl`] when it
//!    has more. A file that begins with `solid` but has NUL bytes in its first 284 bytes (a binary
//!    file with a `solid` header whose size does not fit) gets the same binary size error when the
//!    ASCII reading fails or finds no facet. (An ASCII file cannot pass the size rule by accident:
//!    bytes 80..84 of text read as a count of at least 0x2020_2020, a file of over 26 GB.)
//!
//! # Binary
//! 80-byte header (ignored, whatever it holds: zeros, `solid ...`, `COLOR=`/`MATERIAL=`, MeshLab's
//! text), `u32` triangle count, then per triangle 50 bytes: normal (3 × `f32`, ignored), three
//! corners (9 × `f32` little endian), `u16` attribute (ignored; some writers keep a colour there).
//!
//! # ASCII
//! ```text
//! solid [name...]          name = rest of the line
//!   facet [normal nx ny nz] normal ignored
//!     outer loop
//!       vertex x y z       exactly three
//!     endloop
//!   endfacet
//! endsolid [name...]       optional at end of file
//! ```
//! Tokens are separated by any whitespace: every byte up to and including space (CR/LF or CR-only
//! line ends, tabs, NUL padding). Keywords are matched case-insensitively. Several `solid` blocks
//! may follow each other. Numbers are decimal, with optional sign, fraction and exponent of any
//! number of digits (`1.5e-005`); they are read exactly as `str::parse::<f64>` reads them (a fast
//! path that is exact by construction, the standard parser for anything else). A facet with fewer
//! or more than three vertices is an error.
//!
//! # Output
//! Every coordinate is `file value × scale` computed in `f64`, stored as `f32`; a non-finite result
//! is an error. Corners with bitwise-equal `f32` positions are welded into one vertex (exactly; no
//! tolerance). Triangles keep file order and corner order; degenerate triangles are kept. At most
//! [`MAX_TRIANGLES`] triangles are read.
//!
//! Errors carry the file name, the 1-based line for ASCII (0 for binary) and an [`ErrorKind`], and
//! display as `meshes/arm.stl:812: expected "vertex", found "endloop"`. No input makes the reader
//! panic.

mod ascii;
mod dedup;
pub(crate) mod number;
#[cfg(test)]
pub(crate) mod tests;

use crate::pipeline::ir;
use dedup::MeshBuilder;

/// Upper bound on triangles in one file (a binary STL of this size is 2.5 GB).
pub const MAX_TRIANGLES: u64 = 50_000_000;

/// A file that could not be read as STL.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("{}{kind}", location(.file, .line))]
pub struct StlError {
    /// The name the caller gave (a bundle path).
    pub file: String,
    /// 1-based line of an ASCII file; 0 for binary files and whole-file errors.
    pub line: u32,
    pub kind: ErrorKind,
}

fn location(file: &str, line: &u32) -> String {
    if *line == 0 {
        format!("{file}: ")
    } else {
        format!("{file}:{line}: ")
    }
}

fn found_text(found: &Option<String>) -> String {
    match found {
        Some(t) => format!("\"{t}\""),
        None => "end of file".to_string(),
    }
}

/// What is wrong with an STL file.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ErrorKind {
    #[error("too short to be an STL file ({len} bytes; it neither begins with \"solid\" nor has the 84 bytes of a binary STL header)")]
    TooShort { len: usize },
    #[error("truncated binary STL: the header declares {declared} triangles, which need {} bytes, but the file has {available}", binary_len(.declared))]
    TruncatedBinary { declared: u32, available: usize },
    #[error("not an STL file: it does not begin with \"solid\" (ASCII) and its size, {len} bytes, is not 84 + 50 × {declared} = {} (binary)", binary_len(.declared))]
    NotStl { len: usize, declared: u32 },
    #[error("bad number \"{text}\"")]
    BadNumber { text: String },
    /// `expected` is quoted already (`"vertex"`, or `a number`); `found` is `None` at end of file.
    #[error("expected {expected}, found {}", found_text(.found))]
    UnexpectedToken { expected: &'static str, found: Option<String> },
    /// A coordinate is NaN or infinite (in the file, or after scaling to `f32`). `facet` counts
    /// from 1 in file order.
    #[error("coordinate of facet {facet} is not finite")]
    NonFinite { facet: u64 },
    #[error("more than {max} triangles")]
    TooManyTriangles { max: u64 },
}

/// Size of a binary STL with `n` triangles.
fn binary_len(n: &u32) -> u64 {
    84 + 50 * u64::from(*n)
}

fn declared_count(bytes: &[u8]) -> Option<u32> {
    let c = bytes.get(80..84)?;
    Some(u32::from_le_bytes([c[0], c[1], c[2], c[3]]))
}

/// The binary size rule: at least 84 bytes and exactly `84 + 50 × count` of them.
pub fn is_binary(bytes: &[u8]) -> bool {
    declared_count(bytes).is_some_and(|n| binary_len(&n) == bytes.len() as u64)
}

/// Index after an optional UTF-8 BOM when the text then begins (after whitespace) with `solid`.
fn ascii_start(bytes: &[u8]) -> Option<usize> {
    let start = if bytes.starts_with(&[0xEF, 0xBB, 0xBF]) { 3 } else { 0 };
    let rest = &bytes[start..];
    let ws = rest.iter().take_while(|&&c| c <= b' ').count();
    let word = rest.get(ws..ws + 5)?;
    word.eq_ignore_ascii_case(b"solid").then_some(start)
}

/// The error for a file that is not binary by the size rule and not readable as ASCII.
fn binary_size_error(bytes: &[u8]) -> ErrorKind {
    match declared_count(bytes) {
        None => ErrorKind::TooShort { len: bytes.len() },
        Some(n) if binary_len(&n) > bytes.len() as u64 => ErrorKind::TruncatedBinary { declared: n, available: bytes.len() },
        Some(n) => ErrorKind::NotStl { len: bytes.len(), declared: n },
    }
}

/// Reads an STL file (binary or ASCII, see the module docs). `file` names it in errors; `scale` is
/// metres per unit of the file (0.001 for mm).
pub fn parse(file: &str, bytes: &[u8], scale: f64) -> Result<ir::Mesh, StlError> {
    let err = |line: usize, kind| StlError { file: file.to_string(), line: u32::try_from(line).unwrap_or(u32::MAX), kind };
    if is_binary(bytes) {
        return parse_binary(bytes, scale).map_err(|kind| err(0, kind));
    }
    match ascii_start(bytes) {
        Some(start) => {
            // A binary file with a `solid` header whose size is off fails as ASCII (or, when its
            // header has no line break, reads as an empty solid): report the binary size instead.
            let head = &bytes[..bytes.len().min(84 + 200)];
            let looks_binary = bytes.len() >= 84 && head.contains(&0);
            match ascii::parse(bytes, start, scale) {
                Ok(m) if m.triangles.is_empty() && looks_binary => Err(err(0, binary_size_error(bytes))),
                Ok(m) => Ok(m),
                Err(_) if looks_binary => Err(err(0, binary_size_error(bytes))),
                Err((kind, line)) => Err(err(line, kind)),
            }
        }
        None => Err(err(0, binary_size_error(bytes))),
    }
}

#[inline]
fn f32_at(rec: &[u8], o: usize) -> f32 {
    f32::from_le_bytes([rec[o], rec[o + 1], rec[o + 2], rec[o + 3]])
}

/// Reads a file for which [`is_binary`] holds.
fn parse_binary(bytes: &[u8], scale: f64) -> Result<ir::Mesh, ErrorKind> {
    let n = declared_count(bytes).unwrap_or(0);
    if u64::from(n) > MAX_TRIANGLES {
        return Err(ErrorKind::TooManyTriangles { max: MAX_TRIANGLES });
    }
    let mut mesh = MeshBuilder::with_capacity(n as usize);
    for (i, rec) in bytes[84..].chunks_exact(50).enumerate() {
        let mut corners = [[0f32; 3]; 3];
        for (k, c) in corners.iter_mut().enumerate() {
            for (j, x) in c.iter_mut().enumerate() {
                *x = (f64::from(f32_at(rec, 12 + 12 * k + 4 * j)) * scale) as f32;
            }
        }
        if !corners.iter().flatten().all(|x| x.is_finite()) {
            return Err(ErrorKind::NonFinite { facet: i as u64 + 1 });
        }
        mesh.triangle(corners);
    }
    Ok(mesh.finish())
}
