//! `report.json`: what was converted, how every CAD entity maps to Modelica, and what looks wrong.
//!
//! The report is a data transfer object built from the IR and the back end's [`Layout`]; it is
//! the contract for scripts and the browser UI, so field names are stable.

use nalgebra::{Isometry3, Matrix3, Vector3};
use serde::Serialize;

use crate::pipeline::back::modelica::Layout;
use crate::pipeline::ir::{Model, PrimitiveKind, SourceInfo, Warning};
use crate::pipeline::passes::hierarchy::{LoopKind, Node};
use crate::pipeline::passes::loops::Cut;
use crate::pipeline::passes::lump::Absorbed;
use crate::pipeline::passes::{hierarchy, kinematics};
use crate::pipeline::valid::Validated;

#[derive(Serialize, Debug, Clone)]
pub struct Report {
    pub converter: Converter,
    pub source: SourceInfo,
    pub model_name: String,
    pub package_name: String,
    pub options: ReportOptions,
    pub bodies: Vec<BodyReport>,
    pub joints: Vec<JointReport>,
    pub loops: Vec<LoopReport>,
    pub free_bodies: Vec<String>,
    /// How VRML geometry was matched (null without VRML).
    pub vrml: Option<crate::pipeline::passes::geometry_match::MatchReport>,
    pub warnings: Vec<Warning>,
    /// Collision shapes per body and interferences at the CAD pose (set after the report is
    /// built; absent from reports of earlier versions).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub collision: Option<crate::pipeline::back::collision_shapes::CollisionReport>,
    /// Joint couplings (URDF `mimic`); absent when there are none.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub couplings: Vec<CouplingReport>,
    /// Where the Mechanics diagram put each group (the world, each body with its frames), so
    /// the next version keeps the places of what did not change.
    pub diagram: DiagramReport,
}

#[derive(Serialize, Debug, Clone, Default)]
pub struct DiagramReport {
    /// (column, row) by node ID; `world` for the world.
    pub groups: std::collections::BTreeMap<String, (i32, i32)>,
}

#[derive(Serialize, Debug, Clone)]
pub struct Converter {
    pub name: &'static str,
    pub version: String,
}

#[derive(Serialize, Debug, Clone)]
pub struct ReportOptions {
    pub lump_welds: bool,
    pub gravity: [f64; 3],
}

#[derive(Serialize, Debug, Clone)]
pub struct FrameReport {
    pub name: String,
    pub display_name: String,
    pub node_id: String,
    /// The Modelica connector that carries this frame, when the model has one.
    pub connector: Option<String>,
    pub position_world: [f64; 3],
    pub x_axis_world: [f64; 3],
    pub y_axis_world: [f64; 3],
}

#[derive(Serialize, Debug, Clone)]
pub struct BodyReport {
    pub cad_name: String,
    pub node_id: String,
    pub modelica_name: String,
    pub subsystem: Vec<String>,
    /// kg.
    pub mass: f64,
    /// m.
    pub cg_world: [f64; 3],
    /// kg·m², about the CG in the CG frame's axes (rows).
    pub inertia_cg: [[f64; 3]; 3],
    /// Geometry source files in the bundle.
    pub geometry: Vec<String>,
    /// The shape file in the package, when the body has a mesh.
    pub shape: Option<String>,
    pub triangles: usize,
    /// The shape's colour, RGB in 0..=1 (the CAD material, or the default grey).
    pub color: [f64; 3],
    /// World pose of CS1, the body frame.
    pub cs1: FrameReport,
    pub frames: Vec<FrameReport>,
    /// Node IDs of bodies lumped into this one (with `lump_welds`).
    pub lumped: Vec<String>,
}

#[derive(Serialize, Debug, Clone)]
pub struct ElementReport {
    pub modelica_name: String,
    pub kind: PrimitiveKind,
    /// Unit axis in the element's frame_a.
    pub axis_local: [f64; 3],
    /// Start value: rad or m.
    pub initial_q: f64,
    /// The axis in world coordinates at the CAD pose (zero for spherical): turning (or sliding)
    /// the element by `dq` from `initial_q` moves the follower side about (along) this axis
    /// through `origin_world`.
    pub axis_world: [f64; 3],
    /// The element's frame_a origin in the world at the CAD pose (m).
    pub origin_world: [f64; 3],
    /// How far the emitted axis and origin are from the source's and why, when more than
    /// 1e-12 (rad, m): planar loops' axes made exactly parallel, CAD noise snapped, a rounding
    /// gap moved onto a prismatic's line. Absent when the element is exactly the source's.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub corrections: Option<kinematics::Correction>,
}

#[derive(Serialize, Debug, Clone)]
pub struct JointReport {
    pub cad_name: String,
    pub node_id: String,
    pub modelica_name: String,
    pub primitives: Vec<PrimitiveKind>,
    /// Modelica names of the two bodies (or the ground's name).
    pub base_body: String,
    pub follower_body: String,
    /// Unit axis of the first movable primitive in world coordinates (null for rigid joints).
    pub axis_world: Option<[f64; 3]>,
    /// Start values of the movable elements, in order.
    pub initial_q: Vec<f64>,
    pub elements: Vec<ElementReport>,
    /// How the joint appears in Modelica: revolute, prismatic, spherical, chain, connect, fixed,
    /// revolute-planar-loop-constraint, omitted-redundant-weld.
    pub emitted_as: String,
    pub in_tree: bool,
    pub in_loop: bool,
    /// Whether the joint's coordinates are fixed at their start values in the model.
    pub start_fixed: bool,
    /// With `lump_welds`: the Modelica name of the body a weld was absorbed into (the weld itself
    /// has no component then, and `emitted_as` is `lumped`).
    pub lumped_into: Option<String>,
    /// Limits the source states (URDF `<limit>`): position, speed, effort.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub limits: Option<crate::pipeline::ir::JointLimits>,
}

/// A joint whose coordinate follows another's (URDF `mimic`).
#[derive(Serialize, Debug, Clone)]
pub struct CouplingReport {
    pub follower: String,
    pub leader: String,
    pub multiplier: f64,
    pub offset: f64,
    /// The Modelica component(s) coupling the drive flanges; empty when not emitted.
    pub emitted_as: String,
}

#[derive(Serialize, Debug, Clone)]
pub struct LoopReport {
    pub closing_joint: String,
    /// Every joint of the loop, the closing joint first.
    pub joints: Vec<String>,
    /// `planar`, `spatial` or `rigid` (welds only).
    pub kind: &'static str,
    /// Joint coordinates of the loop's joints.
    pub coordinates: usize,
    /// Numerical rank of the loop's joint twists at the CAD pose (singular values above 1e-4,
    /// lengths scaled by the loops' size).
    pub rank: usize,
    /// `coordinates - rank`.
    pub mobility: usize,
    /// Equations the closing joint would impose if emitted plainly.
    pub closing_equations: usize,
    /// Of those, the ones independent of the tree and of earlier loops.
    pub independent_equations: usize,
    /// `closing_equations - independent_equations`: what a plain closing joint would repeat.
    pub redundant_equations: usize,
    /// Redundant equations left in the emitted model (non-zero only with a `loop-redundant`
    /// warning).
    pub redundant_emitted: usize,
    /// The common unit normal of a planar loop.
    pub planar_normal: Option<[f64; 3]>,
    /// How the closing joint was emitted (the joint's `emitted_as`).
    pub cut: String,
    pub why: String,
}

fn frame_report(model: &Model, layout: &Layout, f: crate::pipeline::ir::FrameId) -> FrameReport {
    let fr = model.frame(f);
    let pose: &Isometry3<f64> = &fr.pose;
    let r = pose.rotation.to_rotation_matrix();
    let m = r.matrix();
    FrameReport {
        name: fr.name.clone(),
        display_name: fr.display_name.clone(),
        node_id: fr.node_id.clone(),
        connector: layout.connectors.get(&f).cloned(),
        position_world: pose.translation.vector.into(),
        x_axis_world: m.column(0).into_owned().into(),
        y_axis_world: m.column(1).into_owned().into(),
    }
}

fn rows(m: &Matrix3<f64>) -> [[f64; 3]; 3] {
    [[m[(0, 0)], m[(0, 1)], m[(0, 2)]], [m[(1, 0)], m[(1, 1)], m[(1, 2)]], [m[(2, 0)], m[(2, 1)], m[(2, 2)]]]
}

pub struct ReportInput<'a> {
    pub model: &'a Model,
    pub validated: &'a Validated,
    pub layout: &'a Layout,
    pub package_name: &'a str,
    pub options: ReportOptions,
    pub merged: &'a std::collections::BTreeMap<String, Vec<String>>,
    /// Welds absorbed by lumping.
    pub absorbed: &'a [Absorbed],
    pub vrml: Option<&'a crate::pipeline::passes::geometry_match::MatchReport>,
    pub warnings: Vec<Warning>,
    pub version: &'a str,
}

pub fn build(input: ReportInput) -> Report {
    let ReportInput { model, validated, layout, package_name, options, merged, absorbed, vrml, warnings, version } = input;
    let names = layout.names.as_ref();
    let body_name = |i: usize| names.map(|n| n.bodies[i].clone()).unwrap_or_default();
    let node_name = |n: Node| match n {
        Node::Body(b) => body_name(b.index()),
        Node::Ground(g) => model.ground(g).name.clone(),
    };
    let h = &validated.analysis.hierarchy;
    let bodies = model
        .bodies
        .iter()
        .enumerate()
        .map(|(i, b)| {
            let shape = layout.shapes.get(i).cloned().flatten();
            BodyReport {
                cad_name: b.cad_name.clone(),
                node_id: b.node_id.clone(),
                modelica_name: body_name(i),
                subsystem: b.subsystem_path.clone(),
                mass: b.mass,
                cg_world: model.frame(b.cg).pose.translation.vector.into(),
                inertia_cg: rows(&b.inertia_cg),
                geometry: b.geometry_sources.clone(),
                shape: shape.map(|s| format!("{package_name}/Resources/Shapes/{s}.dxf")),
                triangles: b.mesh.as_ref().map_or(0, |m| m.triangle_count()),
                color: b.display_color(),
                cs1: frame_report(model, layout, b.cs1),
                frames: b.frames.iter().filter(|f| **f != b.cs1).map(|f| frame_report(model, layout, *f)).collect(),
                lumped: merged.get(&b.node_id).cloned().unwrap_or_default(),
            }
        })
        .collect();
    let joints = model
        .joints
        .iter()
        .enumerate()
        .map(|(j, joint)| {
            let chain = &validated.analysis.chains[j];
            let elements_names = &layout.joint_elements[j];
            let elements: Vec<ElementReport> = chain
                .elements
                .iter()
                .enumerate()
                .map(|(k, e)| ElementReport {
                    modelica_name: elements_names.get(k).cloned().unwrap_or_default(),
                    kind: e.kind,
                    axis_local: e.axis.into(),
                    initial_q: e.q0,
                    axis_world: e.axis_world.into(),
                    origin_world: e.origin_world.into(),
                    corrections: e.correction.clone(),
                })
                .collect();
            let axis_world = joint
                .primitives
                .iter()
                .filter(|p| matches!(p.kind, PrimitiveKind::Revolute | PrimitiveKind::Prismatic))
                .find_map(|p| kinematics::clean_axis(&p.axis_world))
                .map(|v: Vector3<f64>| v.into());
            JointReport {
                cad_name: joint.cad_name.clone(),
                node_id: joint.node_id.clone(),
                modelica_name: names.map(|n| n.joints[j].clone()).unwrap_or_default(),
                primitives: joint.primitives.iter().map(|p| p.kind).collect(),
                base_body: node_name(hierarchy::node_of(model, joint.base)),
                follower_body: node_name(hierarchy::node_of(model, joint.follower)),
                axis_world,
                initial_q: chain.elements.iter().map(|e| e.q0).collect(),
                elements,
                emitted_as: layout.emitted_as[j].to_string(),
                in_tree: h.tree.iter().any(|t| t.index() == j),
                in_loop: h.in_loop[j],
                start_fixed: if chain.elements.is_empty() { !h.in_loop[j] } else { chain.elements.iter().all(|e| e.fixed) },
                lumped_into: None,
                limits: joint.limits.clone(),
            }
        })
        .chain(absorbed.iter().map(|a| {
            let body = model.bodies.iter().position(|b| b.node_id == a.body).map(&body_name).unwrap_or_default();
            JointReport {
                cad_name: a.cad_name.clone(),
                node_id: a.node_id.clone(),
                modelica_name: String::new(),
                primitives: vec![PrimitiveKind::Weld],
                base_body: body.clone(),
                follower_body: body.clone(),
                axis_world: None,
                initial_q: Vec::new(),
                elements: Vec::new(),
                emitted_as: "lumped".to_string(),
                in_tree: false,
                in_loop: false,
                start_fixed: true,
                lumped_into: Some(body),
                limits: None,
            }
        }))
        .collect();
    let jname = |j: crate::pipeline::ir::JointId| names.map(|n| n.joints[j.index()].clone()).unwrap_or_default();
    let loops = h
        .loops
        .iter()
        .zip(&validated.analysis.loops.loops)
        .map(|(l, info)| LoopReport {
            closing_joint: jname(l.closing),
            joints: std::iter::once(l.closing).chain(l.path.iter().copied()).map(jname).collect(),
            kind: match (l.kind, info.planar_normal) {
                (LoopKind::Rigid, _) => "rigid",
                (_, Some(_)) => "planar",
                _ => "spatial",
            },
            coordinates: info.coordinates,
            rank: info.rank,
            mobility: info.mobility,
            closing_equations: info.closing_equations,
            independent_equations: info.independent,
            redundant_equations: info.closing_equations - info.independent.min(info.closing_equations),
            redundant_emitted: if info.cut == Cut::Redundant {
                info.closing_equations - info.independent.min(info.closing_equations)
            } else {
                0
            },
            planar_normal: info.planar_normal.map(Into::into),
            cut: layout.emitted_as[l.closing.index()].to_string(),
            why: info.why.clone(),
        })
        .collect();
    Report {
        converter: Converter { name: "cad2mo", version: version.to_string() },
        source: model.source.clone(),
        model_name: model.name.clone(),
        package_name: package_name.to_string(),
        options,
        bodies,
        joints,
        loops,
        free_bodies: h.free_bodies.iter().map(|b| body_name(b.index())).collect(),
        vrml: vrml.cloned(),
        warnings,
        collision: None,
        couplings: model
            .couplings
            .iter()
            .enumerate()
            .map(|(k, c)| CouplingReport {
                follower: names.map(|n| n.joints[c.follower.index()].clone()).unwrap_or_default(),
                leader: names.map(|n| n.joints[c.leader.index()].clone()).unwrap_or_default(),
                multiplier: c.multiplier,
                offset: c.offset,
                emitted_as: layout.couplings.get(k).and_then(|r| r.as_ref().ok()).cloned().unwrap_or_default(),
            })
            .collect(),
        diagram: DiagramReport { groups: layout.diagram_groups.clone() },
    }
}
