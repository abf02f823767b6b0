//! Second-generation Simscape Multibody import XML front end. See [`parse`].
//!
//! # The format
//! `SimscapeMultibodyImportXML` (older exporters: `SimMechanicsImportXML`), version 2.0, is what
//! the current MathWorks CAD exporters write: the Onshape "Simscape Multibody Exporter" and the
//! Simscape Multibody Link plug-ins for SolidWorks and PTC Creo.
//!
//! ```text
//! SimscapeMultibodyImportXML version
//!   Created by, from, on, using
//!   ModelUnits length, mass         display units only (Creo: abbreviated, e.g. mm / kg)
//!   DataUnits length, mass          the numbers' units (absent in Creo files: ModelUnits then)
//!   RootAssembly name, uid
//!     InstanceTree/Instance*        name, uid, entityUid (a Part or Assembly uid), grounded,
//!                                   rigid; Transform (Rotation, Translation); child Instances
//!     Constraints/<Mate>*           SolidWorks, Creo: Coincident, Concentric, Distance,
//!                                   Parallel, Angle, Tangent (two ConstraintGeometry: geomType,
//!                                   InstancePath, Position, Axis) and Rigid (two InstancePaths)
//!     Joints/<Kind>*                Onshape: Weld, Revolute, Cylindrical, ... with BaseFrame and
//!                                   FollowerFrame (InstancePath, Transform)
//!   Parts/Part*                     name, uid; MassProperties (Mass, CenterOfMass, Inertia),
//!                                   GeometryFile name, type; VisualProperties (Diffuse ...)
//!   Assemblies/Assembly*            uid; the Constraints and Joints of a sub-assembly, with
//!                                   instance paths relative to each of its instances
//! ```
//!
//! # Conventions (with the evidence)
//! - **Transforms are parent-relative** and the nine rotation numbers are **row-major**
//!   (`p_parent = R p_child + t`). Evidence: composing them this way, the base and follower
//!   frames of every Onshape joint in the fixtures (Arm-Robot, ASU arm, backhoe: 106 joints)
//!   coincide in the world to 3e-9 m (the files print 9 digits), their z axes agree to 1e-9 and
//!   the remaining offsets are a rotation about z (revolute) or a shift along it (cylindrical);
//!   world-absolute or column-major readings miss by up to 0.9 m. Mate geometry (Position, Axis)
//!   is in the frame of the instance its path names: coincident planes then coincide to 1e-13 m
//!   in SERTS, Shroombot and the Creo wrist, and miss by centimetres in any other frame.
//! - **Inertia**: the six numbers are `Ixx Iyy Izz Iyz Izx Ixy`, the tensor's own entries (the
//!   products carry the minus sign: `Ixy = -∫xy dm`), about the centre of mass, in the part
//!   frame's axes; the centre of mass is in the part frame. Evidence: the STL meshes that
//!   onshape-to-robot exported from the same Onshape document (urdf/ErroujiOussama+Arm-Robot),
//!   integrated as uniform solids scaled to the XML mass, give the XML's centre of mass and all
//!   six values for `Gripper Base`, `Waist`, `Arm 01` and `Base` (e.g. Gripper Base: Iyz
//!   -1.856e-6, Izx -1.847e-6, Ixy -4.48e-7 from the mesh, -1.856e-6, -1.847e-6, -4.48e-7 in
//!   the XML; Arm 01 has a positive Izx, matching too).
//! - **Units**: `DataUnits` when present, else the root `ModelUnits` (Creo: numbers in mm, kg
//!   and kg·mm²). Per-part `ModelUnits` are display units and ignored.
//! - **Grounded** means fixed to the parent assembly's frame; the root assembly's frame is the
//!   world. An empty instance path (or one naming the assembly itself) is that assembly's frame.
//!
//! # What it builds
//! - One [`ir::Body`] per part instance (node ID: the instance uids from the root joined by `|`;
//!   `cad_name` the instance name verbatim), CS1 = the part frame in the world, CG at the centre
//!   of mass with the part frame's axes. Colour from the instance's or part's `Diffuse`.
//! - Rigid groups (grounded members with their assembly frame, rigid sub-assemblies, `Rigid`
//!   mates) stay separate bodies joined by weld joints to the group's first part (grounded
//!   groups: to a ground each). Keeping them separate keeps every body's mass and pose exactly
//!   as in the file; the lump pass merges welds when asked.
//! - Onshape joints: primitives about and along the base frame's z axis (planar: x, y, then
//!   z), both joint frames at the base frame's world pose, so they coincide at the CAD pose (a
//!   follower frame off where the kind allows gives `joint-frames-mismatch`). Unknown joint
//!   kinds are errors.
//! - SolidWorks / Creo: the mates between each pair of rigid groups reduce to one joint by the
//!   rank and null space of their constraint Jacobian (see [`mates`]); pairs that reduce to no
//!   single joint, contain unsupported mates or do not hold at the assembly pose are warnings.
//! - Geometry: STL, OBJ and STEP names are kept in `geometry_file` and read by
//!   `passes::geometry` (STEP through `front::mesh::step`, which says why `truck-stepio` and
//!   `truck-meshalgo` after re-checking them in 2026-11: they read and mesh every face of the
//!   Onshape arm's 16 parts, and what they get wrong is detected and warned); any other geometry
//!   type is one `geometry-unsupported` warning per part.
//! - No ground at all: a `no-ground` warning; the bodies float (the pipeline makes them free).

mod error;
mod lower;
pub mod mates;

#[cfg(test)]
mod tests;

pub use error::Simscape2Error;

use crate::pipeline::front::simmechanics::dom::{self, Doc, Root};
use crate::pipeline::ir;

/// Largest XML file read.
pub const MAX_XML_BYTES: usize = 256 << 20;

const ROOTS: [&[u8]; 2] = [b"SimscapeMultibodyImportXML", b"SimMechanicsImportXML"];

/// Cheap sniff: is the root element `SimscapeMultibodyImportXML` or `SimMechanicsImportXML`?
/// Reads no further than the root's start tag.
pub fn is_simscape2_xml(bytes: &[u8]) -> bool {
    matches!(dom::root_element(strip_bom(bytes)), Root::Element { name, .. } if ROOTS.contains(&local(name)))
}

fn local(name: &[u8]) -> &[u8] {
    match name.iter().rposition(|&b| b == b':') {
        Some(i) => &name[i + 1..],
        None => name,
    }
}

fn strip_bom(bytes: &[u8]) -> &[u8] {
    bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes)
}

/// Parses a second-generation Simscape Multibody XML file into the IR (SI units, world poses).
/// `file` is used in messages and source locations; warnings come back next to the model.
pub fn parse(file: &str, bytes: &[u8]) -> Result<(ir::Model, Vec<ir::Warning>), Simscape2Error> {
    let bytes = strip_bom(bytes);
    let fail = |offset: usize, element: String, message: String| Simscape2Error::at(file, bytes, offset, element, message);
    if bytes.len() > MAX_XML_BYTES {
        return Err(Simscape2Error {
            file: file.to_owned(),
            line: 0,
            column: 0,
            element: String::new(),
            message: format!("file too large ({} bytes; the limit is 256 MiB)", bytes.len()),
        });
    }
    match dom::root_element(bytes) {
        Root::Element { name, .. } if ROOTS.contains(&local(name)) => {}
        Root::Element { name, offset } => {
            let root = String::from_utf8_lossy(name).into_owned();
            return Err(fail(
                offset,
                root.clone(),
                format!(
                    "not a second-generation Simscape Multibody XML file: the root element is <{}>, expected <SimscapeMultibodyImportXML>",
                    ir::clip(&root, 80)
                ),
            ));
        }
        Root::Missing => return Err(fail(bytes.len(), String::new(), "malformed XML: no root element".into())),
        Root::Error { offset, message } => return Err(fail(offset, String::new(), format!("malformed XML: {message}"))),
    }
    let doc = Doc::build(bytes).map_err(|e| {
        let element = e.open.map(|n| String::from_utf8_lossy(e.doc.name(n)).into_owned()).unwrap_or_default();
        fail(e.offset, element, format!("malformed XML: {}", e.message))
    })?;
    lower::Lower::new(file, &doc).run()
}
