//! The intermediate representation every front end produces and every pass and back end reads.
//!
//! # Invariants
//! - **Units**: SI everywhere (m, kg, kg·m², m³, m²) and radians. Front ends convert once; nothing
//!   downstream knows about `mm`, `in` or `lbm`.
//! - **Poses**: every [`Frame`] carries its pose in the *world* frame of the CAD assembly as an
//!   [`Isometry3`] mapping frame coordinates to world coordinates (`p_world = pose * p_frame`).
//!   Its rotation's columns are the frame's x, y and z axes resolved in world.
//! - **Inertia**: [`Body::inertia_cg`] is the tensor about the centre of gravity, resolved in the axes
//!   of the body's `CG` frame (as the XML gives it). Symmetry and positivity are *not* guaranteed:
//!   the validator reports violations.
//! - **Handles**: bodies, frames, joints and grounds live in `Vec`s of [`Model`]; [`BodyId`],
//!   [`FrameId`], [`JointId`] and [`GroundId`] are indices into them and are always in range.
//!   A frame belongs to exactly one owner (a body or a ground).
//! - **Identity**: `node_id` strings are the CAD's stable identity and are unique per kind; names are
//!   not. Derived facts (tree, loops, Modelica names) live in side tables built by passes, never here.
//! - **Meshes**: [`Mesh`] vertices are in the owning body's `CS1` frame, in metres. A body holds
//!   its mesh through an `Arc`: bodies with the same geometry in the same frame share one.
//! - **Order**: vectors keep the source file's order; passes that need a stable order sort by
//!   `node_id`, never by position.

pub mod dump;
mod mass;

pub use mass::MassProperties;

use nalgebra::{Isometry3, Matrix3, Vector3};
use serde::Serialize;
use std::sync::Arc;

macro_rules! handle {
    ($(#[$m:meta])* $name:ident) => {
        $(#[$m])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
        pub struct $name(pub u32);
        impl $name {
            pub fn index(self) -> usize {
                self.0 as usize
            }
        }
    };
}

handle!(
    /// Index into [`Model::bodies`].
    BodyId
);
handle!(
    /// Index into [`Model::frames`].
    FrameId
);
handle!(
    /// Index into [`Model::joints`].
    JointId
);
handle!(
    /// Index into [`Model::grounds`].
    GroundId
);

/// Where something came from in a source file (1-based line and column; 0 when unknown).
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize)]
pub struct SourceLoc {
    pub file: String,
    pub line: u32,
    pub column: u32,
}

impl std::fmt::Display for SourceLoc {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        fmt_location(f, &self.file, self.line, self.column)
    }
}

/// Writes `file`, or `file:line:column` when the line is known (0 = unknown): how every stage
/// renders a position.
pub fn fmt_location(f: &mut std::fmt::Formatter<'_>, file: &str, line: u32, column: u32) -> std::fmt::Result {
    if line == 0 {
        write!(f, "{file}")
    } else {
        write!(f, "{file}:{line}:{column}")
    }
}

/// At most `max` items joined with `, `, then "and N more": lists in messages stay bounded.
pub fn bounded_list<S: AsRef<str>>(items: &[S], max: usize) -> String {
    let mut out = items.iter().take(max).map(AsRef::as_ref).collect::<Vec<_>>().join(", ");
    if items.len() > max {
        out.push_str(&format!(" and {} more", items.len() - max));
    }
    out
}

/// `s` cut to at most `max` bytes (at a character boundary), saying how much was cut.
pub fn clip(s: &str, max: usize) -> String {
    if s.len() <= max {
        return s.to_string();
    }
    let mut end = max;
    while !s.is_char_boundary(end) {
        end -= 1;
    }
    format!("{} ... ({} more bytes)", &s[..end], s.len() - end)
}

/// Facts about the export itself, copied verbatim from the XML header.
#[derive(Clone, Debug, Default, Serialize)]
pub struct SourceInfo {
    /// Path of the XML inside the bundle.
    pub file: String,
    pub format_version: String,
    pub created_using: String,
    pub created_from: String,
    pub created_on: String,
    pub created_by: String,
    /// `SimMechanics` or `SimscapeMultibody` (the container element's name; the root element's
    /// for the other formats).
    pub container: String,
    /// Which front end read it: `simmechanics` (first generation), `simscape2` (second
    /// generation) or `urdf`.
    pub format: String,
}

/// A whole converted assembly.
#[derive(Clone, Debug, Default)]
pub struct Model {
    /// The assembly's name (top-level `name`).
    pub name: String,
    pub source: SourceInfo,
    pub bodies: Vec<Body>,
    pub frames: Vec<Frame>,
    pub joints: Vec<Joint>,
    pub grounds: Vec<Ground>,
    /// Length unit of the export, in metres per unit (1e-3 for `mm`). Meshes named by the XML are
    /// in this unit.
    pub length_scale: f64,
    /// Joints whose coordinate follows another joint's (URDF `<mimic>`), in file order.
    pub couplings: Vec<Coupling>,
}

impl Model {
    pub fn body(&self, id: BodyId) -> &Body {
        &self.bodies[id.index()]
    }
    pub fn frame(&self, id: FrameId) -> &Frame {
        &self.frames[id.index()]
    }
    pub fn joint(&self, id: JointId) -> &Joint {
        &self.joints[id.index()]
    }
    pub fn ground(&self, id: GroundId) -> &Ground {
        &self.grounds[id.index()]
    }
    pub fn body_ids(&self) -> impl Iterator<Item = BodyId> {
        (0..self.bodies.len() as u32).map(BodyId)
    }
    pub fn joint_ids(&self) -> impl Iterator<Item = JointId> {
        (0..self.joints.len() as u32).map(JointId)
    }
    pub fn ground_ids(&self) -> impl Iterator<Item = GroundId> {
        (0..self.grounds.len() as u32).map(GroundId)
    }
}

/// A rigid body (a CAD part, or a `RootPart`).
#[derive(Clone, Debug)]
pub struct Body {
    pub cad_name: String,
    pub node_id: String,
    /// Names of the enclosing subsystems, outermost first (empty at top level).
    pub subsystem_path: Vec<String>,
    /// kg.
    pub mass: f64,
    /// kg·m², about the centre of gravity, in the axes of the `CG` frame.
    pub inertia_cg: Matrix3<f64>,
    /// m³, when given.
    pub volume: Option<f64>,
    /// m², when given.
    pub surface_area: Option<f64>,
    /// The `CG` frame.
    pub cg: FrameId,
    /// The `CS1` frame: the body frame and the frame of its geometry.
    pub cs1: FrameId,
    /// Every frame of the body, in file order (includes `cg` and `cs1`).
    pub frames: Vec<FrameId>,
    /// `geometryFileName` as written in the XML (`None` when empty or missing).
    pub geometry_file: Option<String>,
    /// Triangles in CS1, metres, once a geometry source has been read. Shared: bodies whose
    /// geometry is the same file in the same frame (a URDF mesh named by several links without
    /// an origin or scale, an STL named by several bodies) hold one mesh, read once; a pass that
    /// changes a body's mesh makes its own ([`Arc::make_mut`] or a new one).
    pub mesh: Option<Arc<Mesh>>,
    /// Where the geometry came from (bundle paths), for the report.
    pub geometry_sources: Vec<String>,
    pub material: Option<Material>,
    pub loc: SourceLoc,
}

impl Body {
    /// The colour the body's shape is drawn in (0..=1): its CAD material, or light grey.
    pub fn display_color(&self) -> [f64; 3] {
        self.material.as_ref().map_or([0.7; 3], |m| m.color.map(|c| c.clamp(0.0, 1.0)))
    }

    /// [`Body::display_color`] as 8-bit RGB.
    pub fn display_rgb(&self) -> [u8; 3] {
        self.display_color().map(|c| (c * 255.0).round() as u8)
    }
}

/// Colour and finish from `MaterialProp`, components in 0..=1.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Material {
    pub color: [f64; 3],
    pub transparency: f64,
    pub specular: f64,
}

/// Who a frame belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FrameOwner {
    Body(BodyId),
    Ground(GroundId),
}

/// A coordinate frame of a body or ground.
#[derive(Clone, Debug)]
pub struct Frame {
    /// `CG`, `CS1`, `CS2`, ...
    pub name: String,
    /// `displayName` (user-added CAD coordinate systems carry their human name here).
    pub display_name: String,
    pub node_id: String,
    pub owner: FrameOwner,
    /// The global `ref` number joints and grounds use, when present.
    pub ref_id: Option<u32>,
    /// World pose (frame -> world), metres.
    pub pose: Isometry3<f64>,
    pub loc: SourceLoc,
}

/// Kind of one joint primitive.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum PrimitiveKind {
    Weld,
    Revolute,
    Prismatic,
    Spherical,
}

impl PrimitiveKind {
    pub fn as_str(self) -> &'static str {
        match self {
            PrimitiveKind::Weld => "weld",
            PrimitiveKind::Revolute => "revolute",
            PrimitiveKind::Prismatic => "prismatic",
            PrimitiveKind::Spherical => "spherical",
        }
    }
}

/// One degree-of-freedom group of a joint.
#[derive(Clone, Debug)]
pub struct Primitive {
    pub kind: PrimitiveKind,
    /// Axis in world coordinates at the CAD pose, as written (not normalised; weld and spherical
    /// carry a dummy axis).
    pub axis_world: Vector3<f64>,
    /// Passive losses on the element's coordinate (URDF `<dynamics>`); zero when the source
    /// states none. Only revolute and prismatic elements carry them.
    pub losses: Losses,
    pub loc: SourceLoc,
}

/// Passive losses on one joint coordinate, as the source states them: the generalised force
/// the joint's bearing exerts *against* the motion is `damping * qd + friction * sign(qd)`
/// (viscous in N·m·s/rad or N·s/m, Coulomb in N·m or N; both ≥ 0, finite). The law as used by
/// the mechanism (with its regularisation of `sign` at rest) is stated on
/// `mechanism::Mechanism::passive_torques`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct Losses {
    pub damping: f64,
    pub friction: f64,
}

impl Losses {
    /// No damping and no friction.
    pub fn is_zero(&self) -> bool {
        self.damping == 0.0 && self.friction == 0.0
    }
}

/// A joint between two frames: a serial chain of primitives from `base` to `follower`.
#[derive(Clone, Debug)]
pub struct Joint {
    pub cad_name: String,
    pub node_id: String,
    pub subsystem_path: Vec<String>,
    pub base: FrameId,
    pub follower: FrameId,
    /// In XML order; never empty.
    pub primitives: Vec<Primitive>,
    /// Limits the source states for the joint's (single) coordinate (URDF `<limit>`), SI units.
    pub limits: Option<JointLimits>,
    pub loc: SourceLoc,
}

/// A joint's limits as the source states them: position range (rad or m, in the source's joint
/// coordinate, zero at the source's zero configuration), speed (rad/s or m/s) and effort (N·m or
/// N). Absent values are `None`.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct JointLimits {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lower: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub upper: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub velocity: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub effort: Option<f64>,
}

/// `follower`'s coordinate = `multiplier` × `leader`'s + `offset` (URDF `<mimic>`; both joints
/// have exactly one revolute or prismatic primitive; coordinates in the source's convention, zero
/// at the source's zero configuration).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Coupling {
    pub follower: JointId,
    pub leader: JointId,
    pub multiplier: f64,
    pub offset: f64,
    pub loc: SourceLoc,
}

impl Joint {
    /// True when every primitive is a weld: a rigid connection.
    pub fn is_weld(&self) -> bool {
        self.primitives.iter().all(|p| p.kind == PrimitiveKind::Weld)
    }
}

/// A ground: a frame fixed in the world.
#[derive(Clone, Debug)]
pub struct Ground {
    pub name: String,
    pub node_id: String,
    pub frame: FrameId,
    pub loc: SourceLoc,
}

/// A triangle mesh. Vertices in the owning body's CS1 frame, metres; every vertex is finite and
/// every index is below `vertices.len()` (front ends guarantee both).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mesh {
    pub vertices: Vec<[f32; 3]>,
    pub triangles: Vec<[u32; 3]>,
}

impl Mesh {
    pub fn triangle_count(&self) -> usize {
        self.triangles.len()
    }

    /// Appends another mesh's triangles.
    pub fn append(&mut self, other: &Mesh) {
        let base = self.vertices.len() as u32;
        self.vertices.extend_from_slice(&other.vertices);
        self.triangles.extend(other.triangles.iter().map(|t| [t[0] + base, t[1] + base, t[2] + base]));
    }

    /// Applies `iso` to every vertex (used when a mesh moves to another body frame).
    pub fn transform(&mut self, iso: &Isometry3<f64>) {
        for v in &mut self.vertices {
            let p = iso * nalgebra::Point3::new(v[0] as f64, v[1] as f64, v[2] as f64);
            *v = [p.x as f32, p.y as f32, p.z as f32];
        }
    }

    /// Axis-aligned bounds `(min, max)`, `None` when empty.
    pub fn bounds(&self) -> Option<([f32; 3], [f32; 3])> {
        let first = *self.vertices.first()?;
        let mut lo = first;
        let mut hi = first;
        for v in &self.vertices {
            for k in 0..3 {
                lo[k] = lo[k].min(v[k]);
                hi[k] = hi[k].max(v[k]);
            }
        }
        Some((lo, hi))
    }
}

/// A non-fatal finding, returned next to the output (never only logged).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Warning {
    /// Stable, machine-readable code such as `inertia-not-symmetric`.
    pub code: &'static str,
    pub message: String,
    /// Where it applies: a file position, or an element such as `body "ARM" (nodeID 59)`.
    pub location: String,
}

impl Warning {
    pub fn new(code: &'static str, message: impl Into<String>, location: impl Into<String>) -> Self {
        Warning { code, message: message.into(), location: location.into() }
    }
}

#[cfg(test)]
mod message_tests {
    use super::*;

    #[test]
    fn messages_stay_bounded() {
        assert_eq!(bounded_list(&["a", "b", "c"], 5), "a, b, c");
        assert_eq!(bounded_list(&["a", "b", "c"], 2), "a, b and 1 more");
        assert_eq!(clip("héllo", 10), "héllo");
        assert_eq!(clip("héllo", 2), "h ... (5 more bytes)");
    }
}
