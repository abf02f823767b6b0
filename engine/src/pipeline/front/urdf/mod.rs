//! URDF front end: a robot description (ROS's Unified Robot Description Format) into the IR.
//!
//! # The format, as read here
//! ```text
//! robot name
//!   link name                      one rigid body; the link frame is the body's CS1
//!     inertial   origin xyz rpy    the CG frame relative to the link frame
//!                mass value, inertia ixx ixy ixz iyy iyz izz (about the CG, CG axes)
//!     visual*    origin, geometry (mesh filename scale | box size | cylinder radius length |
//!                sphere radius), material (rgba, or a name declared under robot)
//!     collision* the same geometry; used only where a link has no readable visual
//!   joint name type                revolute | continuous | prismatic | fixed | floating | planar
//!     parent link, child link, origin xyz rpy (child frame in the parent frame at q = 0),
//!     axis xyz (joint frame; default 1 0 0), limit lower upper velocity effort,
//!     mimic joint multiplier offset, dynamics damping friction
//!   drake:joint name type          Drake's extension: ball, universal (screw and curvilinear
//!                                  are not expressible: welded, with a warning)
//!   loop_joint name type           Drake's closed-chain extension: axis, link1 link xyz rpy,
//!                                  link2 link xyz rpy (the joint frame on each link)
//! ```
//! `rpy` is roll, pitch, yaw about the fixed x, y, z axes (R = Rz(yaw) Ry(pitch) Rx(roll)).
//! Everything is SI already (m, kg, kg·m², rad).
//!
//! # Mapping
//! - Poses: every link's world pose is its parent's composed with the joint origin at the zero
//!   configuration, which is the IR's CAD pose: start values are 0 and Modelica's joint
//!   coordinates equal URDF's.
//! - A joint's base frame is a frame on the parent at the joint origin; its follower frame is the
//!   child's CS1. A joint whose parent is the `world` link (declared or not) gets a ground of its
//!   own at that frame. A root link other than `world` is welded to a ground at its frame, with a
//!   `urdf-root-fixed` warning (URDF cannot say whether a root floats; a `floating` joint from
//!   `world` makes it free).
//! - `floating` leaves the child free; `planar` is two prismatic primitives in the plane and a
//!   revolute about its normal (`axis`); `continuous` is revolute without position limits.
//! - `dynamics damping friction` become the [`Losses`](ir::Losses) of each revolute and prismatic
//!   element of the joint (negative values are refused); other attributes of `<dynamics>`
//!   (Gazebo's, franka's `K`, `D`, `mu_*`) are not URDF and are ignored.
//! - `mimic` becomes a [`Coupling`](ir::Coupling) where both joints have one coordinate, the
//!   multiplier is not zero and the offset is zero (the zero configuration must satisfy it);
//!   otherwise a `mimic-not-expressible` warning. Mimics that form a ring (j1 follows j2 ... follows
//!   j1, any length) would be a ring of gears: each ring's last coupling in file order is dropped
//!   with the same warning naming the ring.
//! - Geometry: visuals are preferred; meshes (`package://NAME/...`, `package:///file`, relative
//!   paths, `file://`) are looked up in the bundle case-insensitively, read by `front::mesh`, scaled
//!   and placed by the visual's origin into the link frame. A missing file is a warning.
//! - `xacro` files (macros, properties, arguments, includes, conditionals, `${...}`/`$(...)`
//!   substitutions) are refused with a message saying to expand them first; a leftover foreign
//!   element in an expanded file (one `<xacro:...>` call, a plugin's namespaced tag) is an
//!   `urdf-element-ignored` warning naming it.

mod assemble;
mod geometry;

pub use geometry::{attach_meshes, locate, UrdfGeometryError};

use std::collections::{BTreeMap, HashMap, VecDeque};

use nalgebra::{Isometry3, Matrix3, Translation3, UnitQuaternion, Vector3};

use crate::pipeline::ir::{
    self, Body, Coupling, Frame, FrameId, FrameOwner, Ground, Joint, JointLimits, Material, Model, Primitive, PrimitiveKind, SourceInfo,
    SourceLoc, Warning,
};

/// Largest URDF read (real ones are well under a megabyte).
pub const MAX_URDF_BYTES: usize = 64 << 20;
/// Most XML nodes read.
const MAX_NODES: u32 = 2_000_000;
/// At most this many `<link>`s (so a chain at most this deep): every later stage walks the
/// tree iteratively, but its work and memory grow with the link count.
pub const MAX_LINKS: usize = 10_000;
/// At most this many `<loop_joint>`s: each closes one independent loop, and the loop analysis
/// takes at most [`crate::pipeline::passes::loops::MAX_LOOPS`].
pub const MAX_LOOP_JOINTS: usize = crate::pipeline::passes::loops::MAX_LOOPS;

/// A fatal problem in a URDF file: where, in which element, and what.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("{}", Shown(self))]
pub struct UrdfError {
    pub file: String,
    pub line: u32,
    pub column: u32,
    /// `link "base"`, `joint "elbow" / axis`, ...; empty when none applies.
    pub element: String,
    pub message: String,
}

struct Shown<'e>(&'e UrdfError);

impl std::fmt::Display for Shown<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let e = self.0;
        ir::fmt_location(f, &e.file, e.line, e.column)?;
        if !e.element.is_empty() {
            write!(f, ": in {}", e.element)?;
        }
        write!(f, ": {}", e.message)
    }
}

/// One visual or collision geometry of a link, in the link frame.
#[derive(Clone, Debug)]
pub struct GeometryRef {
    /// Pose of the geometry in the link frame.
    pub origin: Isometry3<f64>,
    pub shape: Shape,
    /// Whether it came from `<collision>` (used only when the link has no usable visual).
    pub collision: bool,
    pub loc: SourceLoc,
}

#[derive(Clone, Debug)]
pub enum Shape {
    Mesh { filename: String, scale: [f64; 3] },
    Box([f64; 3]),
    Cylinder { radius: f64, length: f64 },
    Sphere(f64),
}

/// A parsed URDF: the model (no meshes yet), warnings, and each body's geometry references.
#[derive(Debug)]
pub struct Urdf {
    pub model: Model,
    pub warnings: Vec<Warning>,
    /// Per body (index = `BodyId`), its visuals then its collisions.
    pub geometry: Vec<Vec<GeometryRef>>,
}

/// Cheap sniff: is the root element `<robot>`? (Skips the declaration, a BOM and any number of
/// comments, processing instructions and blank text before it: licence headers written as many
/// one-line comments put the root kilobytes into the file. Every event consumes input, so the
/// loop ends at the root element or the end of the file.)
pub fn is_urdf(bytes: &[u8]) -> bool {
    let bytes = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
    let mut reader = quick_xml::Reader::from_reader(bytes);
    let mut buf = Vec::new();
    loop {
        match reader.read_event_into(&mut buf) {
            Ok(quick_xml::events::Event::Start(e)) | Ok(quick_xml::events::Event::Empty(e)) => {
                return e.local_name().as_ref() == b"robot";
            }
            Ok(quick_xml::events::Event::Eof) | Err(_) => return false,
            _ => {}
        }
        buf.clear();
    }
}

/// Parses a URDF file into the IR (see the module documentation). `file` names it in messages.
pub fn parse(file: &str, bytes: &[u8]) -> Result<Urdf, UrdfError> {
    let at0 = |message: String| UrdfError { file: file.to_string(), line: 0, column: 0, element: String::new(), message };
    if bytes.len() > MAX_URDF_BYTES {
        return Err(at0(format!("file too large ({} bytes; the limit is {} MiB)", bytes.len(), MAX_URDF_BYTES >> 20)));
    }
    let bytes = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
    let text = std::str::from_utf8(bytes).map_err(|e| {
        let (line, column) = line_col(bytes, e.valid_up_to());
        UrdfError { line, column, ..at0("text is not valid UTF-8".into()) }
    })?;
    if file.to_ascii_lowercase().ends_with(".xacro") {
        return Err(at0(xacro_message()));
    }
    let opts = roxmltree::ParsingOptions { allow_dtd: false, nodes_limit: MAX_NODES };
    let doc = roxmltree::Document::parse_with_options(text, opts).map_err(|e| {
        let p = e.pos();
        UrdfError { line: p.row, column: p.col, ..at0(format!("malformed XML: {e}")) }
    })?;
    let line_starts = std::iter::once(0).chain(text.match_indices('\n').map(|(i, _)| i + 1)).collect();
    Reader { file, doc: &doc, text, line_starts }.read()
}

fn xacro_message() -> String {
    "this is a xacro file (macros and properties are not URDF); expand it first, e.g. `xacro robot.urdf.xacro > robot.urdf`, and upload the result".into()
}

fn line_col(bytes: &[u8], offset: usize) -> (u32, u32) {
    let before = &bytes[..offset.min(bytes.len())];
    let line = before.iter().filter(|&&b| b == b'\n').count() as u32 + 1;
    let start = before.iter().rposition(|&b| b == b'\n').map_or(0, |p| p + 1);
    (line, String::from_utf8_lossy(&before[start..]).chars().count() as u32 + 1)
}

const DRAKE_NS: &str = "http://drake.mit.edu";

struct Reader<'d, 'i> {
    file: &'d str,
    doc: &'d roxmltree::Document<'i>,
    text: &'i str,
    /// Byte offset of each line's start (positions are looked up by binary search, not by
    /// counting from the start of the file for every element).
    line_starts: Vec<usize>,
}

/// A joint as read, before links are placed.
struct RawJoint<'a, 'i> {
    node: roxmltree::Node<'a, 'i>,
    name: String,
    kind: String,
    parent: String,
    child: String,
    origin: Isometry3<f64>,
    axis: Vector3<f64>,
    limits: Option<JointLimits>,
    /// `<dynamics damping friction>`: the element, and one value or one per movable element
    /// (zero when absent).
    losses: (roxmltree::Node<'a, 'i>, Vec<f64>, Vec<f64>),
    mimic: Option<(String, f64, f64, roxmltree::Node<'a, 'i>)>,
}

struct RawLink<'a, 'i> {
    node: roxmltree::Node<'a, 'i>,
    name: String,
    mass: f64,
    inertia: Matrix3<f64>,
    cg: Isometry3<f64>,
    geometry: Vec<GeometryRef>,
    material: Option<Material>,
}

impl<'d, 'i> Reader<'d, 'i> {
    fn loc(&self, node: roxmltree::Node) -> SourceLoc {
        let at = node.range().start.min(self.text.len());
        let line = self.line_starts.partition_point(|&s| s <= at);
        let start = self.line_starts[line.saturating_sub(1).min(self.line_starts.len() - 1)];
        let column = self.text.get(start..at).map_or(1, |t| t.chars().count() + 1);
        SourceLoc { file: self.file.to_string(), line: line as u32, column: column as u32 }
    }

    fn describe(&self, node: roxmltree::Node) -> String {
        let mut parts = Vec::new();
        let mut n = Some(node);
        while let Some(cur) = n {
            if !cur.is_element() || cur.parent().is_none_or(|p| p.is_root()) {
                break;
            }
            let tag = cur.tag_name().name();
            parts.push(match cur.attribute("name") {
                Some(name) if matches!(tag, "link" | "joint" | "loop_joint" | "material") => format!("{tag} \"{}\"", ir::clip(name, 200)),
                _ => tag.to_string(),
            });
            n = cur.parent();
        }
        parts.reverse();
        parts.join(" / ")
    }

    fn err(&self, node: roxmltree::Node, message: impl Into<String>) -> UrdfError {
        let loc = self.loc(node);
        UrdfError { file: self.file.to_string(), line: loc.line, column: loc.column, element: self.describe(node), message: message.into() }
    }

    fn warning(&self, node: roxmltree::Node, code: &'static str, message: impl Into<String>) -> Warning {
        let loc = self.loc(node);
        let element = self.describe(node);
        Warning::new(code, message, if element.is_empty() { loc.to_string() } else { format!("{loc} ({element})") })
    }

    fn attr<'a>(&self, node: roxmltree::Node<'a, 'i>, key: &str) -> Result<&'a str, UrdfError> {
        node.attribute(key).ok_or_else(|| self.err(node, format!("missing attribute `{key}`")))
    }

    fn number(&self, node: roxmltree::Node, key: &str, text: &str) -> Result<f64, UrdfError> {
        let v: f64 =
            text.trim().parse().map_err(|_| self.err(node, format!("attribute `{key}` = \"{}\" is not a number", ir::clip(text, 80))))?;
        if !v.is_finite() {
            return Err(self.err(node, format!("attribute `{key}` = \"{}\" is not finite", ir::clip(text, 80))));
        }
        Ok(v)
    }

    fn opt_number(&self, node: roxmltree::Node, key: &str) -> Result<Option<f64>, UrdfError> {
        node.attribute(key).map(|t| self.number(node, key, t)).transpose()
    }

    fn vec3(&self, node: roxmltree::Node, key: &str, default: [f64; 3]) -> Result<Vector3<f64>, UrdfError> {
        let Some(text) = node.attribute(key) else { return Ok(Vector3::from(default)) };
        let parts: Vec<&str> = text.split_whitespace().collect();
        if parts.len() != 3 {
            return Err(self.err(node, format!("attribute `{key}` = \"{}\" must be three numbers", ir::clip(text, 80))));
        }
        let mut v = [0.0; 3];
        for (k, p) in parts.iter().enumerate() {
            v[k] = self.number(node, key, p)?;
        }
        Ok(Vector3::from(v))
    }

    /// `<origin xyz rpy>` under `node` (identity when absent).
    fn origin(&self, node: roxmltree::Node) -> Result<Isometry3<f64>, UrdfError> {
        match child(node, "origin") {
            Some(o) => self.pose(o),
            None => Ok(Isometry3::identity()),
        }
    }

    /// `xyz` and `rpy` attributes of `node` as a pose.
    fn pose(&self, node: roxmltree::Node) -> Result<Isometry3<f64>, UrdfError> {
        let xyz = self.vec3(node, "xyz", [0.0; 3])?;
        let rpy = self.vec3(node, "rpy", [0.0; 3])?;
        Ok(Isometry3::from_parts(Translation3::from(xyz), rpy_rotation(&rpy)))
    }

    fn read(self) -> Result<Urdf, UrdfError> {
        let root = self.doc.root_element();
        if root.tag_name().name() != "robot" {
            return Err(self.err(root, format!("not a URDF file: the root element is <{}>, expected <robot>", root.tag_name().name())));
        }
        if let Some(x) = root.descendants().find(|n| is_real_xacro(n)) {
            return Err(self.err(x, xacro_message()));
        }
        let mut warnings = Vec::new();
        // Expanded files keep stray tool elements (one leftover `<xacro:...>`, a plugin's
        // namespaced tag): none of them says anything URDF reads, so each is named and ignored.
        for n in root.descendants().filter(|n| n.is_element() && n.tag_name().namespace().is_some_and(|ns| ns != DRAKE_NS)) {
            if n.ancestors().skip(1).any(|a| a.is_element() && a.tag_name().namespace().is_some_and(|ns| ns != DRAKE_NS)) {
                continue; // named with its outermost foreign ancestor
            }
            let tag = match n.tag_name().namespace().and_then(|ns| n.lookup_prefix(ns)) {
                Some(prefix) if !prefix.is_empty() => format!("{prefix}:{}", n.tag_name().name()),
                _ => n.tag_name().name().to_string(),
            };
            warnings.push(self.warning(
                n,
                "urdf-element-ignored",
                format!(
                    "<{}> (namespace {}) is not URDF; ignored",
                    ir::clip(&tag, 80),
                    ir::clip(n.tag_name().namespace().unwrap_or_default(), 120)
                ),
            ));
        }
        let materials = self.named_materials(root)?;
        let mut links: Vec<RawLink> = Vec::new();
        let mut joints: Vec<RawJoint> = Vec::new();
        let mut loops = Vec::new();
        for n in root.children().filter(|n| n.is_element()) {
            let drake = n.tag_name().namespace() == Some(DRAKE_NS);
            match (n.tag_name().name(), drake) {
                ("link", false) => {
                    if links.len() == MAX_LINKS {
                        return Err(self.err(n, format!("more than {MAX_LINKS} links (the limit on links, and so on a chain's depth)")));
                    }
                    links.push(self.link(n, &materials, &mut warnings)?)
                }
                ("joint", _) => joints.push(self.joint(n, drake, &mut warnings)?),
                ("loop_joint", _) => {
                    // Each loop joint closes one independent loop; refused here, before the
                    // assembly and the rank tests whose work grows with the loops' count.
                    if loops.len() == MAX_LOOP_JOINTS {
                        return Err(self.err(
                            n,
                            format!("more than {MAX_LOOP_JOINTS} loop joints (the limit on independent closed loops; a real mechanism has a few)"),
                        ));
                    }
                    loops.push(n)
                }
                ("material", false) | ("gazebo", _) | ("transmission", _) | ("sensor", _) => {}
                ("inertial", false) => {
                    warnings.push(self.warning(n, "urdf-element-ignored", "an <inertial> outside any <link> belongs to no body; ignored"))
                }
                _ => {}
            }
        }
        if links.is_empty() {
            return Err(self.err(root, "the robot has no <link>"));
        }
        self.build(root, links, joints, loops, warnings)
    }

    fn named_materials(&self, root: roxmltree::Node) -> Result<HashMap<String, [f64; 4]>, UrdfError> {
        let mut out = HashMap::new();
        for m in root.children().filter(|n| n.has_tag_name("material")) {
            if let (Some(name), Some(c)) = (m.attribute("name"), child(m, "color")) {
                out.insert(name.to_string(), self.rgba(c)?);
            }
        }
        Ok(out)
    }

    fn rgba(&self, c: roxmltree::Node) -> Result<[f64; 4], UrdfError> {
        let text = self.attr(c, "rgba")?;
        let v: Vec<f64> = text.split_whitespace().map(|p| self.number(c, "rgba", p)).collect::<Result<_, _>>()?;
        match v.as_slice() {
            [r, g, b, a] => Ok([*r, *g, *b, *a]),
            [r, g, b] => Ok([*r, *g, *b, 1.0]),
            _ => Err(self.err(c, format!("attribute `rgba` = \"{}\" must be four numbers", ir::clip(text, 80)))),
        }
    }

    fn link<'a>(
        &self,
        n: roxmltree::Node<'a, 'i>,
        materials: &HashMap<String, [f64; 4]>,
        warnings: &mut Vec<Warning>,
    ) -> Result<RawLink<'a, 'i>, UrdfError> {
        let name = self.attr(n, "name")?.to_string();
        let (mut mass, mut inertia, mut cg) = (0.0, Matrix3::zeros(), Isometry3::identity());
        if let Some(inertial) = child(n, "inertial") {
            cg = self.origin(inertial)?;
            if let Some(m) = child(inertial, "mass") {
                mass = self.number(m, "value", self.attr(m, "value")?)?;
                if mass < 0.0 {
                    return Err(self.err(m, format!("negative mass {mass} kg")));
                }
            }
            if let Some(i) = child(inertial, "inertia") {
                let g = |k: &str| -> Result<f64, UrdfError> { Ok(self.opt_number(i, k)?.unwrap_or(0.0)) };
                let (xx, xy, xz, yy, yz, zz) = (g("ixx")?, g("ixy")?, g("ixz")?, g("iyy")?, g("iyz")?, g("izz")?);
                inertia = Matrix3::new(xx, xy, xz, xy, yy, yz, xz, yz, zz);
            }
        }
        let mut geometry = Vec::new();
        let mut material = None;
        for (tag, collision) in [("visual", false), ("collision", true)] {
            for v in n.children().filter(|c| c.has_tag_name(tag)) {
                let Some(g) = child(v, "geometry") else {
                    warnings.push(self.warning(v, "urdf-element-ignored", format!("<{tag}> without <geometry>; ignored")));
                    continue;
                };
                let Some(shape) = self.shape(g, warnings)? else { continue };
                geometry.push(GeometryRef { origin: self.origin(v)?, shape, collision, loc: self.loc(v) });
                if !collision && material.is_none() {
                    if let Some(m) = child(v, "material") {
                        let rgba = match child(m, "color") {
                            Some(c) => Some(self.rgba(c)?),
                            None => m.attribute("name").and_then(|k| materials.get(k).copied()),
                        };
                        material = rgba.map(|c| Material { color: [c[0], c[1], c[2]], transparency: 1.0 - c[3], specular: 0.0 });
                    }
                }
            }
        }
        Ok(RawLink { node: n, name, mass, inertia, cg, geometry, material })
    }

    fn shape(&self, g: roxmltree::Node, warnings: &mut Vec<Warning>) -> Result<Option<Shape>, UrdfError> {
        let Some(s) = g.children().find(|c| c.is_element()) else {
            return Err(self.err(g, "<geometry> is empty"));
        };
        let positive = |v: f64, what: &str| -> Result<f64, UrdfError> {
            if v > 0.0 {
                Ok(v)
            } else {
                Err(self.err(s, format!("{what} must be positive, got {v}")))
            }
        };
        Ok(Some(match s.tag_name().name() {
            "mesh" => {
                let filename = self.attr(s, "filename")?.to_string();
                let scale = self.vec3(s, "scale", [1.0; 3])?;
                if scale.iter().any(|&c| c == 0.0) {
                    return Err(self.err(s, format!("mesh scale {} {} {} has a zero component", scale.x, scale.y, scale.z)));
                }
                Shape::Mesh { filename, scale: scale.into() }
            }
            "box" => {
                let size = self.vec3(s, "size", [0.0; 3])?;
                for c in size.iter() {
                    positive(*c, "box size")?;
                }
                Shape::Box(size.into())
            }
            "cylinder" => Shape::Cylinder {
                radius: positive(self.number(s, "radius", self.attr(s, "radius")?)?, "cylinder radius")?,
                length: positive(self.number(s, "length", self.attr(s, "length")?)?, "cylinder length")?,
            },
            "sphere" => Shape::Sphere(positive(self.number(s, "radius", self.attr(s, "radius")?)?, "sphere radius")?),
            other => {
                warnings.push(self.warning(
                    s,
                    "urdf-element-ignored",
                    format!("geometry <{other}> is not supported (mesh, box, cylinder, sphere are); ignored"),
                ));
                return Ok(None);
            }
        }))
    }

    fn joint<'a>(&self, n: roxmltree::Node<'a, 'i>, drake: bool, warnings: &mut Vec<Warning>) -> Result<RawJoint<'a, 'i>, UrdfError> {
        let name = self.attr(n, "name")?.to_string();
        let kind = self.attr(n, "type")?.to_string();
        let known: &[&str] = if drake {
            &["ball", "universal", "screw", "curvilinear", "revolute", "continuous", "prismatic", "fixed", "planar", "floating"]
        } else {
            &["revolute", "continuous", "prismatic", "fixed", "floating", "planar"]
        };
        if !known.contains(&kind.as_str()) {
            return Err(self.err(n, format!("unknown joint type \"{}\" (URDF knows {})", ir::clip(&kind, 80), known.join(", "))));
        }
        let link_of = |tag: &str| -> Result<String, UrdfError> {
            let c = child(n, tag).ok_or_else(|| self.err(n, format!("missing <{tag} link=\"...\"/>")))?;
            Ok(self.attr(c, "link")?.to_string())
        };
        let (parent, child_link) = (link_of("parent")?, link_of("child")?);
        let origin = self.origin(n)?;
        let axis = match child(n, "axis") {
            Some(a) => {
                let v = self.vec3(a, "xyz", [1.0, 0.0, 0.0])?;
                if v.norm() < 1e-12 && matches!(kind.as_str(), "revolute" | "continuous" | "prismatic" | "planar" | "screw") {
                    return Err(self.err(a, "the joint axis is the zero vector"));
                }
                if v.norm() < 1e-12 {
                    Vector3::x()
                } else {
                    v.normalize()
                }
            }
            None => Vector3::x(),
        };
        let limits = match child(n, "limit") {
            Some(l) => {
                let mut lim = JointLimits {
                    lower: self.opt_number(l, "lower")?,
                    upper: self.opt_number(l, "upper")?,
                    velocity: self.opt_number(l, "velocity")?,
                    effort: self.opt_number(l, "effort")?,
                };
                if kind == "continuous" {
                    // The URDF spec: a continuous joint has no position limits.
                    lim.lower = None;
                    lim.upper = None;
                }
                if let (Some(lo), Some(hi)) = (lim.lower, lim.upper) {
                    if lo > hi {
                        return Err(self.err(l, format!("lower limit {lo} is above upper limit {hi}")));
                    }
                    if lo == 0.0 && hi == 0.0 && kind != "fixed" {
                        // ROS writes lower = upper = 0 for "unset" in some exporters.
                        lim.lower = None;
                        lim.upper = None;
                        warnings.push(self.warning(
                            l,
                            "urdf-limits-ignored",
                            "lower = upper = 0 read as \"no position limits\" (the joint could not move otherwise)",
                        ));
                    }
                }
                for (k, v) in [("velocity", lim.velocity), ("effort", lim.effort)] {
                    if v.is_some_and(|v| v < 0.0) {
                        return Err(self.err(l, format!("{k} limit {} is negative", v.unwrap_or_default())));
                    }
                }
                Some(lim).filter(|l| *l != JointLimits::default())
            }
            None => None,
        };
        let mimic = match child(n, "mimic") {
            Some(m) => Some((
                self.attr(m, "joint")?.to_string(),
                self.opt_number(m, "multiplier")?.unwrap_or(1.0),
                self.opt_number(m, "offset")?.unwrap_or(0.0),
                m,
            )),
            None => None,
        };
        // One value for every movable element, or one per element (Drake writes planar's as
        // three numbers).
        let losses = match child(n, "dynamics") {
            Some(d) => {
                let list = |k: &str| -> Result<Vec<f64>, UrdfError> {
                    let Some(text) = d.attribute(k) else { return Ok(vec![0.0]) };
                    let v = text.split_whitespace().map(|t| self.number(d, k, t)).collect::<Result<Vec<f64>, _>>()?;
                    if v.is_empty() {
                        return Err(self.err(d, format!("attribute `{k}` is empty")));
                    }
                    if let Some(x) = v.iter().find(|x| **x < 0.0) {
                        return Err(self.err(d, format!("attribute `{k}` = {x} is negative (a passive loss must be 0 or more)")));
                    }
                    Ok(v)
                };
                let (damping, friction) = (list("damping")?, list("friction")?);
                (d, damping, friction)
            }
            None => (n, vec![0.0], vec![0.0]),
        };
        Ok(RawJoint { node: n, name, kind, parent, child: child_link, origin, axis, limits, losses, mimic })
    }

    fn build(
        &self,
        root: roxmltree::Node,
        links: Vec<RawLink>,
        joints: Vec<RawJoint>,
        loops: Vec<roxmltree::Node>,
        mut warnings: Vec<Warning>,
    ) -> Result<Urdf, UrdfError> {
        // Links by name; `world` is the ground, never a body.
        let mut index: HashMap<&str, usize> = HashMap::new();
        for (i, l) in links.iter().enumerate() {
            if index.insert(l.name.as_str(), i).is_some() {
                return Err(self.err(l.node, format!("a second link named \"{}\" (link names must be unique)", ir::clip(&l.name, 200))));
            }
        }
        if let Some(&w) = index.get("world") {
            if links[w].mass > 0.0 {
                warnings.push(self.warning(
                    links[w].node,
                    "urdf-element-ignored",
                    "the link \"world\" is the fixed world; its inertial is ignored",
                ));
            }
        }
        let mut joint_names: HashMap<&str, usize> = HashMap::new();
        let mut parent_of: Vec<Option<usize>> = vec![None; links.len()];
        for (k, j) in joints.iter().enumerate() {
            if joint_names.insert(j.name.as_str(), k).is_some() {
                return Err(self.err(j.node, format!("a second joint named \"{}\" (joint names must be unique)", ir::clip(&j.name, 200))));
            }
            if j.child == "world" {
                return Err(self.err(j.node, "the link \"world\" cannot be a joint's child"));
            }
            let c = *index
                .get(j.child.as_str())
                .ok_or_else(|| self.err(j.node, format!("child link \"{}\" is not declared", ir::clip(&j.child, 200))))?;
            if j.parent != "world" && !index.contains_key(j.parent.as_str()) {
                return Err(self.err(j.node, format!("parent link \"{}\" is not declared", ir::clip(&j.parent, 200))));
            }
            if j.parent == j.child {
                return Err(self.err(j.node, format!("joint connects link \"{}\" to itself", ir::clip(&j.child, 200))));
            }
            if let Some(other) = parent_of[c] {
                return Err(self.err(
                    j.node,
                    format!(
                        "link \"{}\" is already the child of joint \"{}\": a link has one parent (close loops with Drake's <loop_joint>)",
                        ir::clip(&j.child, 200),
                        ir::clip(&joints[other].name, 200)
                    ),
                ));
            }
            parent_of[c] = Some(k);
        }
        // World poses, breadth-first from the roots; a cycle leaves links unplaced.
        let mut children: BTreeMap<&str, Vec<usize>> = BTreeMap::new();
        for (k, j) in joints.iter().enumerate() {
            children.entry(j.parent.as_str()).or_default().push(k);
        }
        let mut pose: Vec<Option<Isometry3<f64>>> = vec![None; links.len()];
        let mut order: Vec<usize> = Vec::new();
        let mut queue: VecDeque<usize> = VecDeque::new();
        for (i, l) in links.iter().enumerate() {
            if parent_of[i].is_none() {
                pose[i] = Some(Isometry3::identity());
                if l.name != "world" {
                    queue.push_back(i);
                }
            }
        }
        for &k in children.get("world").into_iter().flatten() {
            let c = index[joints[k].child.as_str()];
            pose[c] = Some(joints[k].origin);
            order.push(k);
            queue.push_back(c);
        }
        while let Some(i) = queue.pop_front() {
            let p = pose[i].unwrap_or_else(Isometry3::identity);
            for &k in children.get(links[i].name.as_str()).into_iter().flatten() {
                let c = index[joints[k].child.as_str()];
                if pose[c].is_none() {
                    pose[c] = Some(p * joints[k].origin);
                    order.push(k);
                    queue.push_back(c);
                }
            }
        }
        if let Some(i) = (0..links.len()).find(|&i| pose[i].is_none()) {
            let mut cycle = vec![links[i].name.clone()];
            let mut cur = i;
            while let Some(k) = parent_of[cur] {
                let Some(&p) = index.get(joints[k].parent.as_str()) else { break };
                if cycle.len() > 50 || p == i {
                    break;
                }
                cycle.push(links[p].name.clone());
                cur = p;
            }
            return Err(self.err(links[i].node, format!("the links form a cycle ({}): URDF describes a tree", ir::bounded_list(&cycle, 8))));
        }

        // Drake loop joints: read, then close them (the zero configuration need not).
        let mut loop_specs = Vec::new();
        for &n in &loops {
            let name = self.attr(n, "name")?.to_string();
            let kind = self.attr(n, "type")?;
            let motion = match kind {
                "continuous" | "revolute" => assemble::Motion::Revolute,
                "prismatic" => assemble::Motion::Prismatic,
                "fixed" => assemble::Motion::None,
                other => {
                    return Err(self
                        .err(n, format!("unknown loop joint type \"{}\" (continuous, revolute, prismatic, fixed)", ir::clip(other, 80))))
                }
            };
            let side = |tag: &str| -> Result<(usize, Isometry3<f64>), UrdfError> {
                let c = child(n, tag).ok_or_else(|| self.err(n, format!("missing <{tag} link=\"...\" xyz rpy/>")))?;
                let link = self.attr(c, "link")?;
                let i = *index.get(link).ok_or_else(|| self.err(c, format!("link \"{}\" is not declared", ir::clip(link, 200))))?;
                if link == "world" {
                    return Err(self.err(c, "a loop joint cannot end on the world link"));
                }
                Ok((i, self.pose(c)?))
            };
            let ((a, ta), (b, tb)) = (side("link1")?, side("link2")?);
            let axis = match child(n, "axis") {
                Some(x) => self.vec3(x, "xyz", [1.0, 0.0, 0.0])?,
                None => Vector3::x(),
            };
            if axis.norm() < 1e-12 {
                return Err(self.err(n, "the loop joint axis is the zero vector"));
            }
            let spec = assemble::LoopSpec { a, ta, b, tb, axis: axis.normalize(), motion, fixed: kind == "fixed" };
            loop_specs.push((n, name, spec));
        }
        if !loop_specs.is_empty() {
            let tree: Vec<assemble::TreeJoint> = joints
                .iter()
                .map(|j| assemble::TreeJoint {
                    parent: index.get(j.parent.as_str()).copied().filter(|_| j.parent != "world"),
                    child: index[j.child.as_str()],
                    origin: j.origin,
                    axis: j.axis,
                    motion: match j.kind.as_str() {
                        "revolute" | "continuous" => assemble::Motion::Revolute,
                        "prismatic" => assemble::Motion::Prismatic,
                        _ => assemble::Motion::None,
                    },
                })
                .collect();
            let specs: Vec<assemble::LoopSpec> = loop_specs.iter().map(|(_, _, s)| s.clone()).collect();
            match assemble::assemble(links.len(), &tree, &order, &specs) {
                Ok(closed) => {
                    let moved = closed.iter().filter(|v| **v != 0.0).count();
                    if moved > 0 {
                        warnings.push(self.warning(
                            loops[0],
                            "urdf-loops-assembled",
                            format!(
                                "the zero configuration does not close the {} loop joint(s); the model starts in the nearest closed configuration ({moved} joints moved, largest by {:.6})",
                                loop_specs.len(),
                                closed.iter().fold(0.0f64, |m, v| m.max(v.abs()))
                            ),
                        ));
                    }
                    let assembled = assemble::poses(links.len(), &tree, &order, &closed);
                    for (i, p) in pose.iter_mut().enumerate() {
                        if p.is_some() {
                            *p = Some(assembled[i]);
                        }
                    }
                }
                Err(assemble::NotClosed::TooCostly { work }) => {
                    return Err(self.err(
                        loops[0],
                        format!(
                            "closing the {} loop joints needs more than {} units of assembly work (the limit is {}: a loop across a very long chain, or many loops coupled through one)",
                            loop_specs.len(),
                            work,
                            assemble::MAX_ASSEMBLY_WORK
                        ),
                    ))
                }
                Err(assemble::NotClosed::Open(v)) => warnings.push(self.warning(
                    loops[0],
                    "urdf-loops-open",
                    format!("the loop joints cannot be closed near the zero configuration (violation {v:.3e}); the model keeps the zero configuration and each loop joint its offset"),
                )),
            }
        }

        let mut model = Model {
            name: root.attribute("name").unwrap_or("robot").to_string(),
            source: SourceInfo {
                file: self.file.to_string(),
                format_version: root.attribute("version").unwrap_or("1.0").to_string(),
                created_using: "URDF".into(),
                container: "robot".into(),
                format: "urdf".into(),
                ..SourceInfo::default()
            },
            length_scale: 1.0,
            ..Model::default()
        };
        let mut body_of: Vec<Option<ir::BodyId>> = vec![None; links.len()];
        let mut geometry = Vec::new();
        for (i, l) in links.iter().enumerate() {
            if l.name == "world" {
                continue;
            }
            let world = pose[i].unwrap_or_else(Isometry3::identity);
            let id = ir::BodyId(model.bodies.len() as u32);
            let loc = self.loc(l.node);
            let cs1 = push_frame(&mut model, "CS1", format!("{}::CS1", l.name), FrameOwner::Body(id), world, &loc);
            let cg = push_frame(&mut model, "CG", format!("{}::CG", l.name), FrameOwner::Body(id), world * l.cg, &loc);
            model.bodies.push(Body {
                cad_name: l.name.clone(),
                node_id: l.name.clone(),
                subsystem_path: Vec::new(),
                mass: l.mass,
                inertia_cg: l.inertia,
                volume: None,
                surface_area: None,
                cg,
                cs1,
                frames: vec![cs1, cg],
                geometry_file: None,
                mesh: None,
                geometry_sources: Vec::new(),
                material: l.material.clone(),
                loc,
            });
            body_of[i] = Some(id);
            geometry.push(l.geometry.clone());
        }
        // Root links other than `world` are welded to the world where they are.
        for (i, l) in links.iter().enumerate() {
            let Some(b) = body_of[i] else { continue };
            if parent_of[i].is_some() {
                continue;
            }
            warnings.push(self.warning(
                l.node,
                "urdf-root-fixed",
                format!(
                    "root link \"{}\" is fixed to the world at its origin (URDF cannot say whether a root floats; to make it a free body, add a `floating` joint from a `world` link)",
                    ir::clip(&l.name, 200)
                ),
            ));
            let cs1 = model.body(b).cs1;
            let g = push_ground(&mut model, &l.name, Isometry3::identity(), self.loc(l.node));
            model.joints.push(Joint {
                cad_name: format!("{}_fixed_to_world", l.name),
                node_id: format!("world::{}", l.name),
                subsystem_path: Vec::new(),
                base: g,
                follower: cs1,
                primitives: vec![prim(PrimitiveKind::Weld, Vector3::x(), self.loc(l.node))],
                limits: None,
                loc: self.loc(l.node),
            });
        }
        // Joints.
        let mut joint_id: HashMap<&str, ir::JointId> = HashMap::new();
        for j in &joints {
            let loc = self.loc(j.node);
            let c = index[j.child.as_str()];
            let Some(child_body) = body_of[c] else { continue };
            let follower = model.body(child_body).cs1;
            let parent_pose = if j.parent == "world" {
                Isometry3::identity()
            } else {
                pose[index[j.parent.as_str()]].unwrap_or_else(Isometry3::identity)
            };
            let frame_pose = parent_pose * j.origin;
            let r = frame_pose.rotation;
            let world_axis = r * j.axis;
            let primitives = match j.kind.as_str() {
                "revolute" | "continuous" => vec![prim(PrimitiveKind::Revolute, world_axis, loc.clone())],
                "prismatic" => vec![prim(PrimitiveKind::Prismatic, world_axis, loc.clone())],
                "fixed" => vec![prim(PrimitiveKind::Weld, world_axis, loc.clone())],
                "planar" => {
                    let (u, v) = plane_axes(&j.axis);
                    vec![
                        prim(PrimitiveKind::Prismatic, r * u, loc.clone()),
                        prim(PrimitiveKind::Prismatic, r * v, loc.clone()),
                        prim(PrimitiveKind::Revolute, world_axis, loc.clone()),
                    ]
                }
                "ball" => vec![prim(PrimitiveKind::Spherical, Vector3::x(), loc.clone())],
                "universal" => vec![
                    prim(PrimitiveKind::Revolute, r * Vector3::x(), loc.clone()),
                    prim(PrimitiveKind::Revolute, r * Vector3::y(), loc.clone()),
                ],
                "floating" => {
                    warnings.push(self.warning(
                        j.node,
                        "urdf-floating",
                        format!(
                            "floating joint: link \"{}\" and what hangs on it form a free body (6 degrees of freedom)",
                            ir::clip(&j.child, 200)
                        ),
                    ));
                    continue;
                }
                other => {
                    warnings.push(self.warning(
                        j.node,
                        "joint-not-expressible",
                        format!("Drake joint type \"{other}\" has no Modelica MultiBody counterpart; converted as a weld at the zero configuration (its motion is lost)"),
                    ));
                    vec![prim(PrimitiveKind::Weld, world_axis, loc.clone())]
                }
            };
            let mut primitives = primitives;
            let movable = primitives.iter().filter(|p| matches!(p.kind, PrimitiveKind::Revolute | PrimitiveKind::Prismatic)).count();
            let (dyn_node, damping, friction) = &j.losses;
            for (k, v) in [("damping", damping), ("friction", friction)] {
                if v.len() > 1 && v.len() != movable {
                    return Err(self.err(*dyn_node, format!("attribute `{k}` has {} values; joint \"{}\" has {movable} movable element(s) (give one value, or one per element)", v.len(), ir::clip(&j.name, 200))));
                }
            }
            let pick = |v: &Vec<f64>, k: usize| if v.len() == 1 { v[0] } else { v[k] };
            for (k, p) in primitives.iter_mut().filter(|p| matches!(p.kind, PrimitiveKind::Revolute | PrimitiveKind::Prismatic)).enumerate()
            {
                p.losses = ir::Losses { damping: pick(damping, k), friction: pick(friction, k) };
            }
            let base = if j.parent == "world" {
                push_ground(&mut model, &j.name, frame_pose, loc.clone())
            } else {
                let p = index[j.parent.as_str()];
                // Every declared link but `world` is a body.
                let Some(pb) = body_of[p] else { continue };
                let f = push_frame(&mut model, &j.name, format!("{}::{}", links[p].name, j.name), FrameOwner::Body(pb), frame_pose, &loc);
                model.bodies[pb.index()].frames.push(f);
                f
            };
            joint_id.insert(j.name.as_str(), ir::JointId(model.joints.len() as u32));
            model.joints.push(Joint {
                cad_name: j.name.clone(),
                node_id: j.name.clone(),
                subsystem_path: Vec::new(),
                base,
                follower,
                primitives,
                limits: j.limits.clone().filter(|_| matches!(j.kind.as_str(), "revolute" | "continuous" | "prismatic")),
                loc,
            });
        }
        // Drake loop joints: a joint between a frame on each link.
        for (n, name, spec) in loop_specs {
            let loc = self.loc(n);
            let (Some(b1), Some(b2)) = (body_of[spec.a], body_of[spec.b]) else { continue };
            let p1 = pose[spec.a].unwrap_or_else(Isometry3::identity) * spec.ta;
            let p2 = pose[spec.b].unwrap_or_else(Isometry3::identity) * spec.tb;
            let world_axis = p1.rotation * spec.axis;
            let primitives = match spec.motion {
                assemble::Motion::Revolute => vec![prim(PrimitiveKind::Revolute, world_axis, loc.clone())],
                assemble::Motion::Prismatic => vec![prim(PrimitiveKind::Prismatic, world_axis, loc.clone())],
                assemble::Motion::None => vec![prim(PrimitiveKind::Weld, world_axis, loc.clone())],
            };
            let (l1, l2) = (&links[spec.a].name, &links[spec.b].name);
            let f1 = push_frame(&mut model, &name, format!("{l1}::{name}"), FrameOwner::Body(b1), p1, &loc);
            model.bodies[b1.index()].frames.push(f1);
            let f2 = push_frame(&mut model, &name, format!("{l2}::{name}"), FrameOwner::Body(b2), p2, &loc);
            model.bodies[b2.index()].frames.push(f2);
            if joint_id.contains_key(name.as_str()) || model.joints.iter().any(|j| j.node_id == name) {
                return Err(self.err(n, format!("a second joint named \"{}\" (joint names must be unique)", ir::clip(&name, 200))));
            }
            model.joints.push(Joint {
                cad_name: name.clone(),
                node_id: name,
                subsystem_path: Vec::new(),
                base: f1,
                follower: f2,
                primitives,
                limits: None,
                loc,
            });
        }
        // Mimic couplings.
        let mut coupled: Vec<(Coupling, roxmltree::Node)> = Vec::new();
        for j in &joints {
            let Some((leader, multiplier, offset, node)) = &j.mimic else { continue };
            let Some(&follower) = joint_id.get(j.name.as_str()) else { continue };
            let single = |id: ir::JointId| {
                let p = &model.joint(id).primitives;
                p.len() == 1 && matches!(p[0].kind, PrimitiveKind::Revolute | PrimitiveKind::Prismatic)
            };
            let why = match joint_id.get(leader.as_str()) {
                None => Some(format!("it mimics \"{}\", which is not a movable joint of this robot", ir::clip(leader, 200))),
                Some(&l) if l == follower => Some("it mimics itself".to_string()),
                Some(&l) if !single(l) || !single(follower) => Some("both joints must be revolute, continuous or prismatic".to_string()),
                Some(_) if *multiplier == 0.0 => Some("the multiplier is 0 (the joint would be fixed)".to_string()),
                Some(_) if *offset != 0.0 => Some(format!(
                    "the offset {offset} is not zero, so the zero configuration (the pose the model starts in) does not satisfy it"
                )),
                Some(_) => None,
            };
            match (why, joint_id.get(leader.as_str())) {
                (None, Some(&l)) => {
                    coupled.push((Coupling { follower, leader: l, multiplier: *multiplier, offset: *offset, loc: self.loc(*node) }, *node))
                }
                (why, _) => warnings.push(self.warning(
                    *node,
                    "mimic-not-expressible",
                    format!("joint \"{}\" is left uncoupled: {}", ir::clip(&j.name, 200), why.unwrap_or_default()),
                )),
            }
        }
        // A ring of mimics (j1 follows j2 follows ... follows j1) would be a ring of gears: each
        // cycle loses its last coupling in file order, with a warning naming the ring.
        let cycles = mimic_cycles(&coupled.iter().map(|(c, _)| (c.follower, c.leader)).collect::<Vec<_>>());
        for (i, cycle) in &cycles {
            let names: Vec<String> = cycle.iter().map(|&j| model.joint(j).cad_name.clone()).collect();
            let (c, node) = &coupled[*i];
            warnings.push(self.warning(
                *node,
                "mimic-not-expressible",
                format!(
                    "joint \"{}\" is left uncoupled: the mimic couplings form a cycle ({}: each mimics the next, the last the first), a ring of gears that over-constrains its joints",
                    ir::clip(&model.joint(c.follower).cad_name, 200),
                    ir::bounded_list(&names, 8)
                ),
            ));
        }
        let cut: std::collections::HashSet<usize> = cycles.iter().map(|(i, _)| *i).collect();
        model.couplings = coupled.into_iter().enumerate().filter(|(i, _)| !cut.contains(i)).map(|(_, (c, _))| c).collect();
        Ok(Urdf { model, warnings, geometry })
    }
}

/// The cycles among mimic couplings given as `(follower, leader)` in file order (each follower
/// has one leader, so the cycles are disjoint): for each, the index of its last coupling and the
/// joints around it, starting at that coupling's follower. Iterative, linear in the couplings.
fn mimic_cycles(couplings: &[(ir::JointId, ir::JointId)]) -> Vec<(usize, Vec<ir::JointId>)> {
    let of: HashMap<ir::JointId, usize> = couplings.iter().enumerate().map(|(i, &(f, _))| (f, i)).collect();
    // 0: not seen, 1: on the walk under way, 2: done.
    let mut state: HashMap<ir::JointId, u8> = HashMap::new();
    let mut cycles = Vec::new();
    for &(start, _) in couplings {
        let mut path = Vec::new();
        let mut cur = start;
        // Follows the leaders until a joint that follows nobody (no cycle), or
        // one already seen (on this walk: a cycle).
        let mut ended = false;
        while state.get(&cur).copied().unwrap_or(0) == 0 {
            state.insert(cur, 1);
            path.push(cur);
            match of.get(&cur) {
                Some(&i) => cur = couplings[i].1,
                None => {
                    ended = true;
                    break;
                }
            }
        }
        if !ended && state.get(&cur) == Some(&1) {
            if let Some(at) = path.iter().position(|&j| j == cur) {
                let ring = &path[at..];
                let last = ring.iter().filter_map(|j| of.get(j).copied()).max().unwrap_or(0);
                let from = ring.iter().position(|&j| couplings[last].0 == j).unwrap_or(0);
                cycles.push((last, ring[from..].iter().chain(&ring[..from]).copied().collect()));
            }
        }
        for j in path {
            state.insert(j, 2);
        }
    }
    cycles
}

fn is_xacro(n: &roxmltree::Node) -> bool {
    n.tag_name().namespace().is_some_and(|ns| ns.contains("ros.org/wiki/xacro"))
}

/// What only an unexpanded xacro file has: a macro, property, argument, include or conditional
/// element, or a `${...}` / `$(...)` substitution in an attribute or text. (A single leftover
/// `<xacro:...>` call in an otherwise expanded file is not: it is warned about and ignored.)
fn is_real_xacro(n: &roxmltree::Node) -> bool {
    const DIRECTIVES: [&str; 6] = ["macro", "property", "arg", "include", "if", "unless"];
    let substitution = |t: &str| t.contains("${") || t.contains("$(");
    if n.is_text() {
        return n.text().is_some_and(substitution);
    }
    n.is_element() && ((is_xacro(n) && DIRECTIVES.contains(&n.tag_name().name())) || n.attributes().any(|a| substitution(a.value())))
}

fn child<'a, 'i>(n: roxmltree::Node<'a, 'i>, tag: &str) -> Option<roxmltree::Node<'a, 'i>> {
    n.children().find(|c| c.is_element() && c.tag_name().name() == tag)
}

/// URDF's roll-pitch-yaw: rotations about the fixed x, y and z axes, in that order.
pub fn rpy_rotation(rpy: &Vector3<f64>) -> UnitQuaternion<f64> {
    UnitQuaternion::from_euler_angles(rpy.x, rpy.y, rpy.z)
}

/// Two unit vectors spanning the plane normal to `n` (right-handed: u × v = n).
fn plane_axes(n: &Vector3<f64>) -> (Vector3<f64>, Vector3<f64>) {
    let n = n.normalize();
    let e = if n.x.abs() < 0.9 { Vector3::x() } else { Vector3::y() };
    let u = (e - n * n.dot(&e)).normalize();
    (u, n.cross(&u))
}

fn prim(kind: PrimitiveKind, axis_world: Vector3<f64>, loc: SourceLoc) -> Primitive {
    Primitive { kind, axis_world, losses: ir::Losses::default(), loc }
}

fn push_frame(model: &mut Model, name: &str, node_id: String, owner: FrameOwner, pose: Isometry3<f64>, loc: &SourceLoc) -> FrameId {
    let id = FrameId(model.frames.len() as u32);
    model.frames.push(Frame { name: name.to_string(), display_name: String::new(), node_id, owner, ref_id: None, pose, loc: loc.clone() });
    id
}

fn push_ground(model: &mut Model, what: &str, pose: Isometry3<f64>, loc: SourceLoc) -> FrameId {
    let g = ir::GroundId(model.grounds.len() as u32);
    let f = push_frame(model, "world", format!("world::{what}"), FrameOwner::Ground(g), pose, &loc);
    model.grounds.push(Ground { name: "world".into(), node_id: format!("world::{what}"), frame: f, loc });
    f
}

#[cfg(test)]
mod tests;
