//! The front end's error: where (file, line, column, element) and what.

use std::fmt;

/// A fatal problem in a second-generation Simscape Multibody XML file.
///
/// Renders as `arm.xml:12:10: in Instance "Arm 01 <1>" / Transform / Rotation: expected 9
/// numbers, found 8`.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("{}", DisplayError(self))]
pub struct Simscape2Error {
    /// The file name given to [`parse`](super::parse).
    pub file: String,
    /// 1-based line of the offending element's start tag (0 when unknown).
    pub line: u32,
    /// 1-based column (in characters) of the same position.
    pub column: u32,
    /// Which element: its path from the nearest named element, e.g. `Instance "Arm 01 <1>" /
    /// Transform`. Empty when no element applies.
    pub element: String,
    /// What is wrong.
    pub message: String,
}

struct DisplayError<'e>(&'e Simscape2Error);

impl fmt::Display for DisplayError<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let e = self.0;
        crate::pipeline::ir::fmt_location(f, &e.file, e.line, e.column)?;
        if !e.element.is_empty() {
            write!(f, ": in {}", e.element)?;
        }
        write!(f, ": {}", e.message)
    }
}

impl Simscape2Error {
    /// An error at byte `offset` of `bytes`.
    pub(crate) fn at(file: &str, bytes: &[u8], offset: usize, element: String, message: String) -> Self {
        let (line, column) = crate::pipeline::front::simmechanics::error::line_col(bytes, offset);
        Simscape2Error {
            file: file.to_owned(),
            line,
            column,
            element: crate::pipeline::ir::clip(&element, 1024),
            message: crate::pipeline::ir::clip(&message, 2048),
        }
    }

    /// The message without the position, as `Diagnostic::message` wants it.
    pub fn diagnostic_message(&self) -> String {
        if self.element.is_empty() {
            self.message.clone()
        } else {
            format!("in {}: {}", self.element, self.message)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn display_format() {
        let e = Simscape2Error {
            file: "arm.xml".into(),
            line: 12,
            column: 10,
            element: "Instance \"Arm 01 <1>\" / Transform".into(),
            message: "missing element <Rotation>".into(),
        };
        assert_eq!(e.to_string(), "arm.xml:12:10: in Instance \"Arm 01 <1>\" / Transform: missing element <Rotation>");
        assert_eq!(e.diagnostic_message(), "in Instance \"Arm 01 <1>\" / Transform: missing element <Rotation>");
        let e = Simscape2Error { line: 0, element: String::new(), ..e };
        assert_eq!(e.to_string(), "arm.xml: missing element <Rotation>");
    }
}
