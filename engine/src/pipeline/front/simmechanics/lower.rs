//! Lowering the element tree to the IR: values, units, poses, references.
//!
//! Every element is found by name among its parent's children; unknown elements are skipped.
//! Frame `ref`s are collected while reading and joints are resolved against them only at the
//! end, because a joint may point at a frame that comes later in the file (for instance inside
//! a child subsystem). Frames placed relative to other frames are turned into world poses after
//! that (`place`), because `ADJOINING` needs the joints. Source positions are recorded as byte offsets and turned into
//! line/column in one pass at the end.

use std::borrow::Cow;
use std::collections::HashMap;
use std::fmt::Write as _;

use nalgebra::{Isometry3, Matrix3, Translation3, UnitQuaternion, Vector3};

use super::dom::{Doc, NodeId};
use super::error::{line_cols_sorted, XmlError, XmlErrorKind};
use super::pose;
use super::units::Quantity;
use crate::pipeline::ir::{
    Body, BodyId, Frame, FrameId, FrameOwner, Ground, GroundId, Joint, Material, Model, Primitive, PrimitiveKind, SourceInfo, SourceLoc,
    Warning,
};
use place::{AxisFrame, FrameRefs};

mod place;

type Result<T> = std::result::Result<T, XmlError>;

/// Deepest subsystem nesting followed (real files have 2 or 3 levels).
const MAX_DEPTH: usize = 64;

/// Element names of the two container spellings.
const CONTAINERS: [&[u8]; 2] = [b"SimMechanics", b"SimscapeMultibody"];

/// Converts a parsed document (whose root is known to be `PhysicalModelingXMLFile`).
pub(crate) fn lower(file: &str, doc: &Doc<'_>) -> Result<(Model, Vec<Warning>)> {
    let mut cx = Lower {
        file,
        doc,
        model: Model::default(),
        warnings: Vec::new(),
        joints: Vec::new(),
        refs: HashMap::new(),
        frame_refs: Vec::new(),
        locs: Vec::new(),
        length_scale: None,
        first_frame_scale: None,
    };
    cx.document()?;
    cx.finish()
}

/// The IR item a recorded source offset belongs to.
#[derive(Clone, Copy)]
enum Slot {
    Body(u32),
    Frame(u32),
    Joint(u32),
    Ground(u32),
    Primitive { joint: u32, index: u32 },
}

/// A joint read but not yet resolved against the frame `ref`s.
struct PendingJoint {
    cad_name: String,
    node_id: String,
    subsystem_path: Vec<String>,
    /// (`ref`, the `Frame` element naming it).
    base: (u32, NodeId),
    follower: (u32, NodeId),
    primitives: Vec<Primitive>,
    /// Per primitive: the frame whose axes its `axis` is given in.
    axis_frames: Vec<AxisFrame>,
}

struct Lower<'d, 'a> {
    file: &'d str,
    doc: &'d Doc<'a>,
    model: Model,
    warnings: Vec<Warning>,
    joints: Vec<PendingJoint>,
    /// Every frame `ref` seen so far: the frame and its element.
    refs: HashMap<u32, (FrameId, NodeId)>,
    /// Per frame (by index): what its pose as given is relative to.
    frame_refs: Vec<FrameRefs>,
    /// (byte offset of the start tag, item) for every body, frame, joint, ground and primitive.
    locs: Vec<(u32, Slot)>,
    /// Metres per unit of the first body frame's `positionUnits`.
    length_scale: Option<f64>,
    /// The same for the first frame of any owner (fallback when there are no bodies).
    first_frame_scale: Option<f64>,
}

/// Keeps the first occurrence of a child element.
fn first(slot: &mut Option<NodeId>, node: NodeId) {
    if slot.is_none() {
        *slot = Some(node);
    }
}

impl<'a> Lower<'_, 'a> {
    // ----- structure ---------------------------------------------------------------------

    fn document(&mut self) -> Result<()> {
        let doc = self.doc;
        let root = doc.root();
        let mut source = SourceInfo { file: self.file.to_owned(), format: "simmechanics".into(), ..SourceInfo::default() };
        let mut container = None;
        for c in doc.children(root) {
            match doc.name(c) {
                b"formatVersion" => source.format_version = self.string(c)?,
                b"createdUsing" => source.created_using = self.string(c)?,
                b"createdFrom" => source.created_from = self.string(c)?,
                b"createdOn" => source.created_on = self.string(c)?,
                b"createdBy" => source.created_by = self.string(c)?,
                b"name" => self.model.name = self.string(c)?,
                name if CONTAINERS.contains(&name) => {
                    if container.is_some() {
                        return Err(self.err(c, XmlErrorKind::MultipleContainers));
                    }
                    container = Some(c);
                }
                _ => {}
            }
        }
        let container = container.ok_or_else(|| self.err(root, XmlErrorKind::NoContainer))?;
        source.container = String::from_utf8_lossy(doc.name(container)).into_owned();
        self.model.source = source;
        self.system(container, &mut Vec::new())
    }

    /// The content of the container or of a `Subsystem`.
    fn system(&mut self, node: NodeId, path: &mut Vec<String>) -> Result<()> {
        if path.len() > MAX_DEPTH {
            return Err(self.err(node, XmlErrorKind::TooDeep { limit: MAX_DEPTH }));
        }
        let doc = self.doc;
        for list in doc.children(node) {
            let kind = doc.name(list);
            if !matches!(kind, b"bodies" | b"joints" | b"grounds" | b"subsystems") {
                continue;
            }
            for c in doc.children(list) {
                match (kind, doc.name(c)) {
                    (b"bodies", b"Body") => self.body(c, path)?,
                    (b"joints", b"SimpleJoint") => self.joint(c, path)?,
                    (b"grounds", b"Ground") => self.ground(c)?,
                    (b"subsystems", b"Subsystem") => self.subsystem(c, path)?,
                    (b"joints", other) => {
                        // Not an element to skip silently: a constraint would be lost.
                        let message = format!("joint entry <{}> is not a SimpleJoint and was ignored", String::from_utf8_lossy(other));
                        self.warn("joint-element-skipped", message, c);
                    }
                    _ => {}
                }
            }
        }
        Ok(())
    }

    fn subsystem(&mut self, node: NodeId, path: &mut Vec<String>) -> Result<()> {
        let name = self.doc.child(node, b"name").ok_or_else(|| self.missing(node, "name"))?;
        path.push(self.string(name)?);
        self.system(node, path)?;
        path.pop();
        Ok(())
    }

    // ----- items -------------------------------------------------------------------------

    fn body(&mut self, node: NodeId, path: &[String]) -> Result<()> {
        let doc = self.doc;
        let (mut name, mut node_id, mut frames, mut geometry, mut material) = (None, None, None, None, None);
        let (mut mass, mut mass_u, mut inertia, mut inertia_u) = (None, None, None, None);
        let (mut volume, mut volume_u, mut area, mut area_u) = (None, None, None, None);
        for c in doc.children(node) {
            match doc.name(c) {
                b"name" => first(&mut name, c),
                b"nodeID" => first(&mut node_id, c),
                b"mass" => first(&mut mass, c),
                b"massUnits" => first(&mut mass_u, c),
                b"inertia" => first(&mut inertia, c),
                b"inertiaUnits" => first(&mut inertia_u, c),
                b"volume" => first(&mut volume, c),
                b"volumeUnits" => first(&mut volume_u, c),
                b"surfaceArea" => first(&mut area, c),
                b"surfaceAreaUnits" => first(&mut area_u, c),
                b"frames" => first(&mut frames, c),
                b"geometryFileName" => first(&mut geometry, c),
                b"MaterialProp" => first(&mut material, c),
                _ => {}
            }
        }
        let cad_name = self.required_string(node, name, "name")?;
        let node_id = self.required_string(node, node_id, "nodeID")?;
        let mass = self.quantity::<1>(node, mass, "mass", mass_u, "massUnits", Quantity::Mass)?;
        let inertia = self.quantity::<9>(node, inertia, "inertia", inertia_u, "inertiaUnits", Quantity::Inertia)?;
        let volume = match volume {
            Some(v) => Some(self.quantity::<1>(node, Some(v), "volume", volume_u, "volumeUnits", Quantity::Volume)?[0]),
            None => None,
        };
        let surface_area = match area {
            Some(a) => Some(self.quantity::<1>(node, Some(a), "surfaceArea", area_u, "surfaceAreaUnits", Quantity::Area)?[0]),
            None => None,
        };
        let geometry_file = match geometry {
            Some(g) => Some(self.string(g)?).filter(|s| !s.is_empty()),
            None => None,
        };
        let material = match material {
            Some(m) => Some(self.material(m)?),
            None => None,
        };

        let id = BodyId(self.model.bodies.len() as u32);
        let (mut cg, mut cs1, mut frame_ids) = (None, None, Vec::new());
        for f in frames.iter().flat_map(|&fs| doc.children(fs)) {
            if doc.name(f) != b"Frame" {
                continue;
            }
            let (fid, scale) = self.frame(f, FrameOwner::Body(id))?;
            self.length_scale.get_or_insert(scale);
            match self.model.frames.last().map(|f| f.name.as_str()) {
                Some("CG") => {
                    cg.get_or_insert(fid);
                }
                Some("CS1") => {
                    cs1.get_or_insert(fid);
                }
                _ => {}
            }
            frame_ids.push(fid);
        }
        let cg = cg.ok_or_else(|| self.err(node, XmlErrorKind::MissingBodyFrame { name: "CG" }))?;
        let cs1 = cs1.ok_or_else(|| self.err(node, XmlErrorKind::MissingBodyFrame { name: "CS1" }))?;

        self.locs.push((self.offset(node), Slot::Body(id.0)));
        self.model.bodies.push(Body {
            cad_name,
            node_id,
            subsystem_path: path.to_vec(),
            mass: mass[0],
            inertia_cg: Matrix3::from_row_slice(&inertia),
            volume,
            surface_area,
            cg,
            cs1,
            frames: frame_ids,
            geometry_file,
            mesh: None,
            geometry_sources: Vec::new(),
            material,
            loc: SourceLoc::default(),
        });
        Ok(())
    }

    /// `MaterialProp`: `color` is required; `transparency` and `specular` default to 0.
    fn material(&self, node: NodeId) -> Result<Material> {
        let (mut color, mut transparency, mut specular) = (None, None, None);
        for c in self.doc.children(node) {
            match self.doc.name(c) {
                b"color" => first(&mut color, c),
                b"transparency" => first(&mut transparency, c),
                b"specular" => first(&mut specular, c),
                _ => {}
            }
        }
        let color = self.numbers::<3>(color.ok_or_else(|| self.missing(node, "color"))?)?;
        let scalar = |n: Option<NodeId>| -> Result<f64> { n.map_or(Ok(0.0), |n| self.numbers::<1>(n).map(|[v]| v)) };
        Ok(Material { color, transparency: scalar(transparency)?, specular: scalar(specular)? })
    }

    /// Reads a frame definition, appends it to the model and registers its `ref`. Returns its
    /// id and the metres-per-unit of its `positionUnits`.
    fn frame(&mut self, node: NodeId, owner: FrameOwner) -> Result<(FrameId, f64)> {
        let doc = self.doc;
        let (mut name, mut display, mut node_id) = (None, None, None);
        let (mut position, mut pos_units, mut orientation, mut o_type, mut o_units) = (None, None, None, None, None);
        let mut ref_nodes = [None; 3];
        for c in doc.children(node) {
            match doc.name(c) {
                b"name" => first(&mut name, c),
                b"displayName" => first(&mut display, c),
                b"nodeID" => first(&mut node_id, c),
                b"position" => first(&mut position, c),
                b"positionUnits" => first(&mut pos_units, c),
                b"orientation" => first(&mut orientation, c),
                b"orientationType" => first(&mut o_type, c),
                b"orientationUnits" => first(&mut o_units, c),
                b"positionOrigin" => first(&mut ref_nodes[place::ORIGIN], c),
                b"positionReferenceFrame" => first(&mut ref_nodes[place::AXES], c),
                b"orientationReferenceFrame" => first(&mut ref_nodes[place::ORIENTATION], c),
                _ => {}
            }
        }
        let name = self.required_string(node, name, "name")?;
        let display_name = match display {
            Some(d) => self.string(d)?,
            None => String::new(),
        };
        let node_id = self.required_string(node, node_id, "nodeID")?;
        let ref_id = self.ref_attr(node)?;
        let mut frame_refs = FrameRefs::default();
        for (slot, n) in frame_refs.iter_mut().zip(ref_nodes) {
            if let Some(n) = n {
                *slot = self.frame_reference(n, owner)?.map(|r| (r, n));
            }
        }

        let [x, y, z] = self.numbers::<3>(position.ok_or_else(|| self.missing(node, "position"))?)?;
        let units = pos_units.ok_or_else(|| self.missing(node, "positionUnits"))?;
        let scale = self.unit(units, Quantity::Length)?;
        // Orientation type and units first, so that an unsupported type is reported as such
        // rather than as a wrong number count.
        if let Some(t) = o_type {
            let value = self.value(t)?;
            if value != "3x3 Transform" {
                let value = value.into_owned();
                return Err(self.err(t, XmlErrorKind::UnsupportedOrientationType { value }));
            }
        }
        if let Some(u) = o_units {
            // A direction-cosine matrix has no unit; the unit is only validated.
            self.unit(u, Quantity::Angle)?;
        }
        let o = orientation.ok_or_else(|| self.missing(node, "orientation"))?;
        let columns = self.numbers::<9>(o)?;
        let (rotation, defect) = pose::nearest_rotation(&Matrix3::from_column_slice(&columns));
        if let Some(d) = defect.filter(|d| d.error > pose::TOLERANCE || !d.det.is_finite()) {
            return Err(self.err(o, XmlErrorKind::NotARotation { frame: name.to_string(), det: d.det, error: d.error }));
        }
        if let Some(d) = defect {
            let what = if d.det < 0.0 { "mirrored (determinant < 0)" } else { "not orthonormal" };
            self.warn(
                "frame-not-orthonormal",
                format!(
                    "orientation of frame \"{name}\" is {what}: determinant {:.6}, max |R^T R - I| = {:.3e}; the nearest rotation is used",
                    d.det, d.error
                ),
                o,
            );
        }
        let pose =
            Isometry3::from_parts(Translation3::from(Vector3::new(x, y, z) * scale), UnitQuaternion::from_rotation_matrix(&rotation));

        let id = FrameId(self.model.frames.len() as u32);
        if let Some(r) = ref_id {
            if let Some(&(_, first_node)) = self.refs.get(&r) {
                let first = self.located(first_node);
                return Err(self.err(node, XmlErrorKind::DuplicateRef { ref_id: r, first }));
            }
            self.refs.insert(r, (id, node));
        }
        self.first_frame_scale.get_or_insert(scale);
        self.frame_refs.push(frame_refs);
        self.locs.push((self.offset(node), Slot::Frame(id.0)));
        self.model.frames.push(Frame { name, display_name, node_id, owner, ref_id, pose, loc: SourceLoc::default() });
        Ok((id, scale))
    }

    fn joint(&mut self, node: NodeId, path: &[String]) -> Result<()> {
        let doc = self.doc;
        let (mut name, mut node_id, mut base, mut follower, mut prims) = (None, None, None, None, None);
        for c in doc.children(node) {
            match doc.name(c) {
                b"name" => first(&mut name, c),
                b"nodeID" => first(&mut node_id, c),
                b"base" => first(&mut base, c),
                b"follower" => first(&mut follower, c),
                b"primitives" => first(&mut prims, c),
                _ => {}
            }
        }
        let cad_name = self.required_string(node, name, "name")?;
        let node_id = self.required_string(node, node_id, "nodeID")?;
        let base = self.side(base.ok_or_else(|| self.missing(node, "base"))?)?;
        let follower = self.side(follower.ok_or_else(|| self.missing(node, "follower"))?)?;
        let prims = prims.ok_or_else(|| self.missing(node, "primitives"))?;
        let joint = self.joints.len() as u32;
        let (mut primitives, mut axis_frames) = (Vec::new(), Vec::new());
        for p in doc.children(prims) {
            if doc.name(p) == b"Primitive" {
                let index = primitives.len() as u32;
                let (primitive, axis_frame) = self.primitive(p)?;
                primitives.push(primitive);
                axis_frames.push(axis_frame);
                self.locs.push((self.offset(p), Slot::Primitive { joint, index }));
            }
        }
        if primitives.is_empty() {
            return Err(self.err(prims, XmlErrorKind::NoPrimitives));
        }
        self.locs.push((self.offset(node), Slot::Joint(joint)));
        self.joints.push(PendingJoint { cad_name, node_id, subsystem_path: path.to_vec(), base, follower, primitives, axis_frames });
        Ok(())
    }

    /// `base` / `follower`: `JointSide/connection/Frame@ref`.
    fn side(&self, node: NodeId) -> Result<(u32, NodeId)> {
        let frame = self
            .doc
            .descend(node, &[b"JointSide", b"connection", b"Frame"])
            .ok_or_else(|| self.missing(node, "JointSide/connection/Frame"))?;
        let r = self.ref_attr(frame)?.ok_or_else(|| self.err(frame, XmlErrorKind::MissingAttribute { name: "ref" }))?;
        Ok((r, frame))
    }

    /// A primitive (axis as given) and the frame its axis is given in.
    fn primitive(&self, node: NodeId) -> Result<(Primitive, AxisFrame)> {
        let (mut name, mut axis, mut axis_frame) = (None, None, AxisFrame::World);
        for c in self.doc.children(node) {
            match self.doc.name(c) {
                b"name" => first(&mut name, c),
                b"axis" => first(&mut axis, c),
                b"referenceFrame" => axis_frame = self.axis_frame(c)?,
                _ => {}
            }
        }
        let name = name.ok_or_else(|| self.missing(node, "name"))?;
        let value = self.value(name)?;
        let kind = match value.to_ascii_lowercase().as_str() {
            "weld" => PrimitiveKind::Weld,
            "revolute" => PrimitiveKind::Revolute,
            "prismatic" => PrimitiveKind::Prismatic,
            "spherical" => PrimitiveKind::Spherical,
            _ => {
                let name = value.into_owned();
                return Err(self.err(node, XmlErrorKind::UnknownPrimitive { name }));
            }
        };
        let axis = self.numbers::<3>(axis.ok_or_else(|| self.missing(node, "axis"))?)?;
        let primitive = Primitive { kind, axis_world: Vector3::from(axis), losses: Default::default(), loc: SourceLoc::default() };
        Ok((primitive, axis_frame))
    }

    fn ground(&mut self, node: NodeId) -> Result<()> {
        let doc = self.doc;
        let (mut name, mut node_id) = (None, None);
        for c in doc.children(node) {
            match doc.name(c) {
                b"name" => first(&mut name, c),
                b"nodeID" => first(&mut node_id, c),
                _ => {}
            }
        }
        let name = self.required_string(node, name, "name")?;
        let node_id = self.required_string(node, node_id, "nodeID")?;
        let frame = doc.descend(node, &[b"frame", b"Frame"]).ok_or_else(|| self.missing(node, "frame/Frame"))?;
        let id = GroundId(self.model.grounds.len() as u32);
        let (frame, _) = self.frame(frame, FrameOwner::Ground(id))?;
        self.locs.push((self.offset(node), Slot::Ground(id.0)));
        self.model.grounds.push(Ground { name, node_id, frame, loc: SourceLoc::default() });
        Ok(())
    }

    /// Resolves joints, places frames in the world, sets `length_scale` and every item's
    /// line/column.
    fn finish(mut self) -> Result<(Model, Vec<Warning>)> {
        let pending = std::mem::take(&mut self.joints);
        self.model.joints.reserve(pending.len());
        let mut axis_frames = Vec::with_capacity(pending.len());
        for j in pending {
            axis_frames.push(j.axis_frames);
            let base = self.resolve(j.base)?;
            let follower = self.resolve(j.follower)?;
            self.model.joints.push(Joint {
                cad_name: j.cad_name,
                node_id: j.node_id,
                subsystem_path: j.subsystem_path,
                base,
                follower,
                primitives: j.primitives,
                limits: None,
                loc: SourceLoc::default(),
            });
        }
        self.place_frames()?;
        self.rotate_axes(&axis_frames);
        self.model.length_scale = self.length_scale.or(self.first_frame_scale).unwrap_or(1.0);

        // Recorded in document order already, except primitives before their joint.
        self.locs.sort_by_key(|&(offset, _)| offset);
        let offsets: Vec<u32> = self.locs.iter().map(|&(o, _)| o).collect();
        let positions = line_cols_sorted(self.doc.bytes, &offsets);
        let m = &mut self.model;
        for (&(_, slot), (line, column)) in self.locs.iter().zip(positions) {
            let loc = SourceLoc { file: self.file.to_owned(), line, column };
            let target = match slot {
                Slot::Body(i) => m.bodies.get_mut(i as usize).map(|b| &mut b.loc),
                Slot::Frame(i) => m.frames.get_mut(i as usize).map(|f| &mut f.loc),
                Slot::Joint(i) => m.joints.get_mut(i as usize).map(|j| &mut j.loc),
                Slot::Ground(i) => m.grounds.get_mut(i as usize).map(|g| &mut g.loc),
                Slot::Primitive { joint, index } => {
                    m.joints.get_mut(joint as usize).and_then(|j| j.primitives.get_mut(index as usize)).map(|p| &mut p.loc)
                }
            };
            if let Some(target) = target {
                *target = loc;
            }
        }
        Ok((self.model, self.warnings))
    }

    fn resolve(&self, (r, node): (u32, NodeId)) -> Result<FrameId> {
        match self.refs.get(&r) {
            Some(&(id, _)) => Ok(id),
            None => Err(self.err(node, XmlErrorKind::DanglingRef { ref_id: r })),
        }
    }

    // ----- values ------------------------------------------------------------------------

    /// A string value: trimmed, one pair of surrounding double quotes removed, entities
    /// decoded.
    fn value(&self, node: NodeId) -> Result<Cow<'a, str>> {
        let raw = unquote(self.doc.text(node));
        let s = std::str::from_utf8(raw).map_err(|_| self.err(node, XmlErrorKind::InvalidUtf8))?;
        if !s.contains('&') {
            return Ok(Cow::Borrowed(s));
        }
        quick_xml::escape::unescape(s).map_err(|e| self.err(node, XmlErrorKind::Syntax { message: e.to_string() }))
    }

    fn string(&self, node: NodeId) -> Result<String> {
        self.value(node).map(Cow::into_owned)
    }

    fn required_string(&self, parent: NodeId, node: Option<NodeId>, name: &'static str) -> Result<String> {
        self.string(node.ok_or_else(|| self.missing(parent, name))?)
    }

    /// Exactly `N` comma-separated finite numbers.
    fn numbers<const N: usize>(&self, node: NodeId) -> Result<[f64; N]> {
        let text = self.doc.text(node).trim_ascii();
        let text = std::str::from_utf8(text).map_err(|_| self.err(node, XmlErrorKind::InvalidUtf8))?;
        let mut out = [0.0; N];
        let mut got = 0;
        if !text.is_empty() {
            for piece in text.split(',') {
                if let Some(slot) = out.get_mut(got) {
                    *slot = number(piece).map_err(|kind| self.err(node, kind))?;
                }
                got += 1;
            }
        }
        if got != N {
            return Err(self.err(node, XmlErrorKind::WrongCount { expected: N, got }));
        }
        Ok(out)
    }

    /// A numeric element and its unit element, converted to SI.
    fn quantity<const N: usize>(
        &self,
        parent: NodeId,
        value: Option<NodeId>,
        value_name: &'static str,
        unit: Option<NodeId>,
        unit_name: &'static str,
        quantity: Quantity,
    ) -> Result<[f64; N]> {
        let mut v = self.numbers::<N>(value.ok_or_else(|| self.missing(parent, value_name))?)?;
        let factor = self.unit(unit.ok_or_else(|| self.missing(parent, unit_name))?, quantity)?;
        for x in &mut v {
            *x *= factor;
        }
        Ok(v)
    }

    /// SI factor of a unit element.
    fn unit(&self, node: NodeId, quantity: Quantity) -> Result<f64> {
        let unit = self.value(node)?;
        quantity.factor(&unit).ok_or_else(|| {
            self.err(node, XmlErrorKind::UnknownUnit { quantity: quantity.name(), unit: unit.into_owned(), allowed: quantity.allowed() })
        })
    }

    /// The `ref` attribute as a number.
    fn ref_attr(&self, node: NodeId) -> Result<Option<u32>> {
        let raw = self.doc.attr(node, b"ref").map_err(|message| self.err(node, XmlErrorKind::Syntax { message }))?;
        let Some(raw) = raw else { return Ok(None) };
        let text = String::from_utf8_lossy(raw.trim_ascii());
        text.parse::<u32>().map(Some).map_err(|_| self.err(node, XmlErrorKind::BadNumber { text: text.into_owned() }))
    }

    // ----- diagnostics -------------------------------------------------------------------

    fn offset(&self, node: NodeId) -> u32 {
        self.doc.offset(node) as u32
    }

    fn err(&self, node: NodeId, kind: XmlErrorKind) -> XmlError {
        XmlError::at(self.file, self.doc.bytes, self.doc.offset(node), describe(self.doc, node), kind)
    }

    fn missing(&self, parent: NodeId, name: &'static str) -> XmlError {
        self.err(parent, XmlErrorKind::MissingElement { name })
    }

    /// `file:line:column: element` for messages that point at another element.
    fn located(&self, node: NodeId) -> String {
        let (line, column) = super::error::line_col(self.doc.bytes, self.doc.offset(node));
        format!("{} at {}:{}:{}", describe(self.doc, node), self.file, line, column)
    }

    fn warn(&mut self, code: &'static str, message: String, node: NodeId) {
        let (line, column) = super::error::line_col(self.doc.bytes, self.doc.offset(node));
        let location = format!("{}:{}:{}: {}", self.file, line, column, describe(self.doc, node));
        self.warnings.push(Warning::new(code, message, location));
    }
}

/// One finite number.
fn number(piece: &str) -> std::result::Result<f64, XmlErrorKind> {
    let piece = piece.trim_ascii();
    match piece.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        Ok(_) => Err(XmlErrorKind::NonFinite { text: piece.to_owned() }),
        // MSVC-style spellings: 1.#INF, -1.#IND, 1.#QNAN.
        Err(_) if piece.contains('#') => Err(XmlErrorKind::NonFinite { text: piece.to_owned() }),
        Err(_) => Err(XmlErrorKind::BadNumber { text: piece.to_owned() }),
    }
}

/// Trims whitespace and removes one pair of surrounding double quotes.
fn unquote(raw: &[u8]) -> &[u8] {
    let t = raw.trim_ascii();
    match t {
        [b'"', inner @ .., b'"'] => inner,
        _ => t,
    }
}

/// Describes an element for messages: its path from the nearest body, joint, ground or
/// subsystem, with names and `nodeID`s of the elements that have them, e.g.
/// `Body "ARM" (nodeID "59") / frames / Frame "CS2" (nodeID "59::CS2") / positionUnits`.
pub(crate) fn describe(doc: &Doc<'_>, node: NodeId) -> String {
    const MAX_PATH_SEGMENTS: usize = 12;
    const MAX_SEGMENT_BYTES: usize = 160;
    let mut segments: Vec<(bool, String)> = Vec::new();
    let mut cur = Some(node);
    while let Some(id) = cur {
        let name = doc.name(id);
        let item = matches!(name, b"Body" | b"SimpleJoint" | b"Ground" | b"Subsystem");
        if item || matches!(name, b"Frame" | b"Primitive") {
            segments.push((true, describe_one(doc, id)));
        } else {
            segments.push((false, String::from_utf8_lossy(name).into_owned()));
        }
        if item {
            break;
        }
        cur = doc.parent(id);
        // The root is implied, except when it is the element itself.
        if cur.is_some_and(|p| doc.parent(p).is_none()) {
            break;
        }
    }
    // Bounded whatever the input: the innermost segments (where the problem is) and the
    // outermost one, each clipped.
    if segments.len() > MAX_PATH_SEGMENTS {
        let skipped = segments.len() - MAX_PATH_SEGMENTS;
        let outer = segments.pop();
        segments.truncate(MAX_PATH_SEGMENTS - 1);
        segments.push((false, format!("({skipped} levels)")));
        segments.extend(outer);
    }
    for (_, text) in &mut segments {
        if text.len() > MAX_SEGMENT_BYTES {
            *text = crate::pipeline::ir::clip(text, MAX_SEGMENT_BYTES);
        }
    }
    let mut out = String::new();
    let mut prev_described = false;
    for (i, (described, text)) in segments.iter().rev().enumerate() {
        if i > 0 {
            out.push_str(if prev_described || *described { " / " } else { "/" });
        }
        out.push_str(text);
        prev_described = *described;
    }
    out
}

/// `Kind "name" (nodeID "id") ref="N"`, leaving out what the element does not have.
fn describe_one(doc: &Doc<'_>, id: NodeId) -> String {
    let mut s = String::from_utf8_lossy(doc.name(id)).into_owned();
    let child =
        |name: &[u8]| doc.child(id, name).map(|c| String::from_utf8_lossy(unquote(doc.text(c))).into_owned()).filter(|v| !v.is_empty());
    if let Some(name) = child(b"name") {
        let _ = write!(s, " \"{name}\"");
    }
    if let Some(node_id) = child(b"nodeID") {
        let _ = write!(s, " (nodeID \"{node_id}\")");
    }
    if let Ok(Some(r)) = doc.attr(id, b"ref") {
        let _ = write!(s, " ref=\"{}\"", String::from_utf8_lossy(r));
    }
    s
}
