//! First-generation SimMechanics XML front end. See [`parse`].
//!
//! # The format
//! `PhysicalModelingXMLFile` is what SimMechanics Link 3.x–4.0 and Simscape Multibody Link
//! 4.8–5.x write from Pro/E–Creo (and, in principle, SolidWorks and Inventor):
//!
//! ```text
//! PhysicalModelingXMLFile   formatVersion, createdUsing, createdFrom, createdOn, createdBy, name
//!   SimMechanics | SimscapeMultibody          (the container; Link >= 4.8 writes the latter)
//!     bodies/Body*          name, nodeID, mass+massUnits, inertia+inertiaUnits,
//!                           volume+volumeUnits, surfaceArea+surfaceAreaUnits,
//!                           frames/Frame*, geometryFileName, MaterialProp
//!     joints/SimpleJoint*   name, nodeID, base|follower/JointSide/connection/Frame@ref,
//!                           primitives/Primitive* (name, referenceFrame, axis)
//!     grounds/Ground*       name, nodeID, frame/Frame
//!     subsystems/Subsystem* the same content, nested to any depth
//! ```
//!
//! Strings are quoted inside the element (`<name>"CS1"</name>`), vectors are comma-separated,
//! every value carries its own unit element. A `Frame` has a position and a 3x3 orientation
//! whose nine numbers are the frame's x, y and z axes (in world coordinates unless the frame
//! says otherwise, see below); frames used by joints carry a `ref` attribute that is unique in
//! the whole file.
//!
//! # What is supported
//! - Both container spellings, subsystems to any depth (`subsystem_path` records them), joints
//!   whose frames live in other subsystems (refs are resolved globally after reading).
//! - Units: length mm, cm, m, in, ft; mass kg, g, lbm, slug; inertia, area and volume as
//!   products of those; orientation units rad and deg. All converted to SI here.
//! - Frames: `orientationType` = `3x3 Transform`; `positionOrigin` X, `positionReferenceFrame`
//!   Y and `orientationReferenceFrame` Z each `WORLD` (absent = `WORLD`), the name of another
//!   frame of the same body (`CG`, `CS1`, ...), or `ADJOINING` (the frame at the other end of
//!   the one joint using this frame; a ground's frame allows only `WORLD` and `ADJOINING`). The
//!   position starts at X's origin with components in Y's axes, the orientation is relative to
//!   Z: `p = origin(X) + R(Y) p`, `R = R(Z) R`, resolved recursively after all joints are read.
//!   Cycles, unknown names and `ADJOINING` frames used by no joint or by several are errors.
//!   The matrix as given is projected onto the nearest rotation first (silently within the
//!   data's precision); a mirrored one gives a `frame-not-orthonormal` warning, and one whose
//!   `max |RᵀR − I|` exceeds 1e-3 (600 times what 6-digit rounding can do) is an error naming
//!   the frame.
//! - Primitives weld, revolute, prismatic and spherical, axes in `WORLD` or in the axes of the
//!   joint's `BASE` or `FOLLOWER` frame.
//! - Elements are found by name; unknown ones are skipped. A non-`SimpleJoint` entry under
//!   `joints` is skipped with a `joint-element-skipped` warning (a constraint would be lost).
//! - Second-generation files (`SimMechanicsImportXML`) are recognised and rejected.
//!
//! Everything else is an [`XmlError`] pointing at the offending element; malformed input never
//! panics. Physical plausibility (inertia, density, loops) is checked by later passes.

pub(crate) mod dom;
pub(crate) mod error;
mod lower;
mod pose;
mod units;

#[cfg(test)]
mod tests;

pub use error::{XmlError, XmlErrorKind};

use crate::pipeline::ir;
use dom::{Doc, Root};

/// Largest XML file read (real exports are a few MB; the element tree's offsets are `u32`).
pub const MAX_XML_BYTES: usize = 256 << 20;

/// Root element name of first-generation files.
const ROOT: &[u8] = b"PhysicalModelingXMLFile";
/// Root element names of second-generation (Simscape Multibody import) files: older exporters
/// write `SimMechanicsImportXML`, newer ones `SimscapeMultibodyImportXML`.
const SECOND_GENERATION_ROOTS: [&[u8]; 2] = [b"SimMechanicsImportXML", b"SimscapeMultibodyImportXML"];

/// Parses a first-generation SimMechanics XML file into the IR (SI units, world poses: frames
/// given relative to other frames are resolved here).
///
/// `file` is only used in messages and source locations. Warnings (currently
/// `frame-not-orthonormal` and `joint-element-skipped`) come back next to the model.
pub fn parse(file: &str, bytes: &[u8]) -> Result<(ir::Model, Vec<ir::Warning>), XmlError> {
    let bytes = strip_bom(bytes);
    if bytes.len() > MAX_XML_BYTES {
        let kind = XmlErrorKind::TooLarge { size: bytes.len() };
        return Err(XmlError { file: file.to_owned(), line: 0, column: 0, element: String::new(), kind });
    }
    match dom::root_element(bytes) {
        Root::Element { name, .. } if name == ROOT => {}
        Root::Element { name, offset } => {
            let root = String::from_utf8_lossy(name).into_owned();
            let kind = if SECOND_GENERATION_ROOTS.contains(&name) {
                XmlErrorKind::SecondGeneration
            } else {
                XmlErrorKind::NotPhysicalModelingXml { root: root.clone() }
            };
            return Err(XmlError::at(file, bytes, offset, root, kind));
        }
        Root::Missing => {
            let kind = XmlErrorKind::Syntax { message: "no root element".into() };
            return Err(XmlError::at(file, bytes, bytes.len(), String::new(), kind));
        }
        Root::Error { offset, message } => {
            let kind = XmlErrorKind::Syntax { message };
            return Err(XmlError::at(file, bytes, offset, String::new(), kind));
        }
    }
    let doc = Doc::build(bytes).map_err(|e| {
        let element = e.open.map(|n| lower::describe(&e.doc, n)).unwrap_or_default();
        XmlError::at(file, bytes, e.offset, element, XmlErrorKind::Syntax { message: e.message })
    })?;
    lower::lower(file, &doc)
}

/// Cheap sniff: is the root element `PhysicalModelingXMLFile`? Skips a UTF-8 byte-order mark,
/// the XML declaration, comments and processing instructions; reads no further than the root's
/// start tag.
pub fn is_physical_modeling_xml(bytes: &[u8]) -> bool {
    matches!(dom::root_element(strip_bom(bytes)), Root::Element { name, .. } if name == ROOT)
}

/// Removes a UTF-8 byte-order mark (positions are then counted from after it).
fn strip_bom(bytes: &[u8]) -> &[u8] {
    bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes)
}
