//! The front end's error type and byte-offset -> line/column conversion.

use std::fmt;

/// A fatal problem in a SimMechanics XML file, with the position of the offending element.
///
/// Renders as `model.xml:123:9: in Body "ARM" (nodeID "59") / positionUnits: unknown length
/// unit "furlong" (expected one of mm, cm, m, in, ft)`.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("{}", DisplayError(self))]
pub struct XmlError {
    /// The file name given to [`parse`](super::parse).
    pub file: String,
    /// 1-based line of the offending element's start tag (or of the syntax error).
    pub line: u32,
    /// 1-based column (in characters) of the same position.
    pub column: u32,
    /// Which element: its path from the nearest body, joint, ground or subsystem, whose name
    /// and `nodeID` are quoted, e.g. `Body "ARM" (nodeID "59") / frames / Frame "CS2"
    /// (nodeID "59::CS2") / positionUnits`. Empty when no element applies.
    pub element: String,
    pub kind: XmlErrorKind,
}

/// Helper rendering [`XmlError`] (thiserror wants a single format string).
struct DisplayError<'e>(&'e XmlError);

impl fmt::Display for DisplayError<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let e = self.0;
        crate::pipeline::ir::fmt_location(f, &e.file, e.line, e.column)?;
        if !e.element.is_empty() {
            write!(f, ": in {}", e.element)?;
        }
        write!(f, ": {}", e.kind)
    }
}

/// What went wrong; one variant per failure class.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum XmlErrorKind {
    /// The bytes are not well-formed XML (includes truncated files).
    #[error("malformed XML: {message}")]
    Syntax { message: String },
    /// Text that must be read is not UTF-8.
    #[error("text is not valid UTF-8")]
    InvalidUtf8,
    /// The file is larger than any real export (256 MiB).
    #[error("file too large ({size} bytes; the limit is 256 MiB)")]
    TooLarge { size: usize },
    /// The root element is something other than `PhysicalModelingXMLFile`.
    #[error("not a first-generation SimMechanics XML file: the root element is <{root}>, expected <PhysicalModelingXMLFile>")]
    NotPhysicalModelingXml { root: String },
    /// The root element is `SimMechanicsImportXML`.
    #[error("this is a second-generation Simscape Multibody XML file (root <SimMechanicsImportXML>), which is not supported yet; only first-generation SimMechanics XML (root <PhysicalModelingXMLFile>) can be read")]
    SecondGeneration,
    /// Neither `SimMechanics` nor `SimscapeMultibody` under the root.
    #[error("no <SimMechanics> or <SimscapeMultibody> element under <PhysicalModelingXMLFile>")]
    NoContainer,
    /// More than one `SimMechanics` / `SimscapeMultibody` element under the root.
    #[error("more than one <SimMechanics> / <SimscapeMultibody> element under <PhysicalModelingXMLFile>")]
    MultipleContainers,
    /// A required child element is absent.
    #[error("missing element <{name}>")]
    MissingElement { name: &'static str },
    /// A required attribute is absent.
    #[error("missing attribute {name}=\"...\"")]
    MissingAttribute { name: &'static str },
    /// A body lacks its `CG` or `CS1` frame.
    #[error("body has no \"{name}\" frame")]
    MissingBodyFrame { name: &'static str },
    /// A unit string that is not in the table.
    #[error("unknown {quantity} unit \"{unit}\" (expected one of {allowed})")]
    UnknownUnit { quantity: &'static str, unit: String, allowed: &'static str },
    /// A joint names a frame `ref` that no frame carries.
    #[error("frame ref=\"{ref_id}\" does not match any frame in the file")]
    DanglingRef { ref_id: u32 },
    /// Two frames carry the same `ref`.
    #[error("frame ref=\"{ref_id}\" is already used by {first}")]
    DuplicateRef { ref_id: u32, first: String },
    /// `positionOrigin`, `positionReferenceFrame`, `orientationReferenceFrame` or a primitive's
    /// `referenceFrame` names something the format does not allow there.
    #[error("reference frame \"{value}\" is not supported (expected {expected})")]
    UnsupportedReferenceFrame { value: String, expected: &'static str },
    /// A frame is placed relative to a frame name its body does not have.
    #[error("frame \"{frame}\" refers to frame \"{name}\", which its body does not have")]
    UnknownFrameName { frame: String, name: String },
    /// A frame is placed relative to `ADJOINING`, but not exactly one joint uses it.
    #[error("frame \"{frame}\" refers to ADJOINING, but {joints} joints use it (expected exactly one)")]
    AdjoiningNotOneJoint { frame: String, joints: usize },
    /// Frames placed relative to each other in a circle.
    #[error("frame references form a cycle: {cycle}")]
    FrameCycle { cycle: String },
    /// `orientationType` is not `3x3 Transform`.
    #[error("orientation type \"{value}\" is not supported (only \"3x3 Transform\")")]
    UnsupportedOrientationType { value: String },
    /// A number that is NaN or infinite.
    #[error("non-finite number \"{text}\"")]
    NonFinite { text: String },
    /// Text that is not a number.
    #[error("cannot read \"{text}\" as a number")]
    BadNumber { text: String },
    /// A vector with the wrong number of components.
    #[error("expected {expected} comma-separated numbers, found {got}")]
    WrongCount { expected: usize, got: usize },
    /// A joint primitive other than weld, revolute, prismatic or spherical.
    #[error("unknown joint primitive \"{name}\" (expected weld, revolute, prismatic or spherical)")]
    UnknownPrimitive { name: String },
    /// A joint without any primitive.
    #[error("joint has no primitives")]
    NoPrimitives,
    /// A frame orientation too far from orthonormal to be a rounded rotation (see
    /// `pose::TOLERANCE`).
    #[error("orientation of frame \"{frame}\" is not a rotation: determinant {det:.6}, max |R^T R - I| = {error:.3e}, far beyond what 6-digit rounding explains (about 1.7e-6; refused above 1e-3)")]
    NotARotation { frame: String, det: f64, error: f64 },
    /// Subsystems nested deeper than the front end follows.
    #[error("subsystems nested deeper than {limit} levels")]
    TooDeep { limit: usize },
}

impl XmlError {
    /// Builds an error at byte `offset` of `bytes`, computing the line and column now.
    pub(crate) fn at(file: &str, bytes: &[u8], offset: usize, element: String, kind: XmlErrorKind) -> Self {
        let (line, column) = line_col(bytes, offset);
        XmlError { file: file.to_owned(), line, column, element, kind }
    }
}

/// 1-based line and column (in characters) of byte `offset`.
pub(crate) fn line_col(bytes: &[u8], offset: usize) -> (u32, u32) {
    let head = bytes.get(..offset).unwrap_or(bytes);
    let line = newlines(head) + 1;
    let line_start = head.iter().rposition(|&b| b == b'\n').map_or(0, |i| i + 1);
    let column = chars(head.get(line_start..).unwrap_or_default()) + 1;
    (saturate(line), saturate(column))
}

/// Line and column of every offset in `sorted` (ascending), in one forward scan over `bytes`.
pub(crate) fn line_cols_sorted(bytes: &[u8], sorted: &[u32]) -> Vec<(u32, u32)> {
    let mut out = Vec::with_capacity(sorted.len());
    let mut pos = 0usize;
    let mut line = 1usize;
    let mut line_start = 0usize;
    for &off in sorted {
        let off = (off as usize).clamp(pos, bytes.len());
        let chunk = bytes.get(pos..off).unwrap_or_default();
        let n = newlines(chunk);
        if n > 0 {
            line += n;
            line_start = pos + chunk.iter().rposition(|&b| b == b'\n').map_or(0, |i| i + 1);
        }
        pos = off;
        let column = chars(bytes.get(line_start..off).unwrap_or_default()) + 1;
        out.push((saturate(line), saturate(column)));
    }
    out
}

/// Number of `\n` in `bytes`, 64 bytes at a time (the per-chunk `u8` sum vectorises).
fn newlines(bytes: &[u8]) -> usize {
    let mut chunks = bytes.chunks_exact(64);
    let mut n: usize = (&mut chunks).map(|c| usize::from(c.iter().map(|&b| u8::from(b == b'\n')).sum::<u8>())).sum();
    n += chunks.remainder().iter().filter(|&&b| b == b'\n').count();
    n
}

/// Number of UTF-8 characters in `bytes` (continuation bytes are not counted).
fn chars(bytes: &[u8]) -> usize {
    bytes.iter().filter(|&&b| (b & 0xC0) != 0x80).count()
}

fn saturate(n: usize) -> u32 {
    u32::try_from(n).unwrap_or(u32::MAX)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn line_col_counts_lines_and_chars() {
        let s = "ab\ncdé\nxyz".as_bytes();
        assert_eq!(line_col(s, 0), (1, 1));
        assert_eq!(line_col(s, 3), (2, 1));
        // after "cdé" (é is 2 bytes): column 4
        assert_eq!(line_col(s, 7), (2, 4));
        assert_eq!(line_col(s, 9), (3, 2));
        let offs = [0u32, 3, 7, 9, 9, 100];
        let batch = line_cols_sorted(s, &offs);
        let one: Vec<_> = offs.iter().map(|&o| line_col(s, o as usize)).collect();
        assert_eq!(batch, one);
    }

    #[test]
    fn newline_count_matches_naive_count() {
        let text: Vec<u8> = (0..1000u32).map(|i| if i % 7 == 0 { b'\n' } else { b'x' }).collect();
        for len in [0, 1, 63, 64, 65, 500, 1000] {
            let naive = text[..len].iter().filter(|&&b| b == b'\n').count();
            assert_eq!(newlines(&text[..len]), naive, "{len}");
        }
    }

    #[test]
    fn display_format() {
        let e = XmlError {
            file: "model.xml".into(),
            line: 123,
            column: 9,
            element: "Body \"ARM\" (nodeID \"59\") / positionUnits".into(),
            kind: XmlErrorKind::UnknownUnit { quantity: "length", unit: "furlong".into(), allowed: "mm, cm, m, in, ft" },
        };
        assert_eq!(
            e.to_string(),
            "model.xml:123:9: in Body \"ARM\" (nodeID \"59\") / positionUnits: unknown length unit \"furlong\" (expected one of mm, cm, m, in, ft)"
        );
    }
}
