//! The URDF of a small model built in code, read back with quick-xml: composing the joint
//! origins along the tree reproduces every body's CS1 and CG world pose, inertias are the IR's,
//! and moving a URDF joint by `u` moves the body as the Modelica chain does at `q0 + u`.

use std::collections::BTreeMap;

use nalgebra::{Isometry3, Matrix3, Rotation3, Translation3, Unit, UnitQuaternion, Vector3};
use quick_xml::events::Event;

use super::*;
use crate::pipeline::back::modelica;
use crate::pipeline::ir::*;
use crate::pipeline::passes;
use crate::pipeline::valid::{self, Analysis};

/// An element of the parsed URDF.
#[derive(Clone, Debug, Default)]
struct Node {
    name: String,
    attrs: BTreeMap<String, String>,
    children: Vec<Node>,
}

impl Node {
    fn child(&self, name: &str) -> Option<&Node> {
        self.children.iter().find(|c| c.name == name)
    }
    fn all<'a>(&'a self, name: &'a str) -> impl Iterator<Item = &'a Node> + 'a {
        self.children.iter().filter(move |c| c.name == name)
    }
    fn attr(&self, k: &str) -> &str {
        self.attrs.get(k).map_or("", String::as_str)
    }
    fn nums(&self, k: &str) -> Vec<f64> {
        self.attr(k).split_whitespace().map(|x| x.parse::<f64>().unwrap()).collect()
    }
    fn num(&self, k: &str) -> f64 {
        self.attr(k).parse().unwrap()
    }
}

fn parse(text: &str) -> Node {
    let mut reader = quick_xml::Reader::from_str(text);
    let mut stack = vec![Node::default()];
    let node = |e: &quick_xml::events::BytesStart| Node {
        name: String::from_utf8(e.name().as_ref().to_vec()).unwrap(),
        attrs: e
            .attributes()
            .map(|a| {
                let a = a.unwrap();
                (String::from_utf8(a.key.as_ref().to_vec()).unwrap(), a.unescape_value().unwrap().into_owned())
            })
            .collect(),
        children: Vec::new(),
    };
    loop {
        match reader.read_event().unwrap() {
            Event::Start(e) => stack.push(node(&e)),
            Event::Empty(e) => {
                let n = node(&e);
                stack.last_mut().unwrap().children.push(n);
            }
            Event::End(_) => {
                let n = stack.pop().unwrap();
                stack.last_mut().unwrap().children.push(n);
            }
            Event::Eof => break,
            _ => {}
        }
    }
    stack.pop().unwrap().children.into_iter().find(|c| c.name == "robot").unwrap()
}

fn pose_of(origin: Option<&Node>) -> Isometry3<f64> {
    let Some(o) = origin else { return Isometry3::identity() };
    let xyz = o.nums("xyz");
    let rpy = o.nums("rpy");
    Isometry3::from_parts(Translation3::new(xyz[0], xyz[1], xyz[2]), UnitQuaternion::from_euler_angles(rpy[0], rpy[1], rpy[2]))
}

/// World pose of every link with the joints at `u` (by joint name; 0 when absent).
fn link_poses(robot: &Node, u: &BTreeMap<String, f64>) -> BTreeMap<String, Isometry3<f64>> {
    let mut poses = BTreeMap::from([("world".to_string(), Isometry3::identity())]);
    let joints: Vec<&Node> = robot.all("joint").collect();
    loop {
        let mut progress = false;
        for j in &joints {
            let parent = j.child("parent").unwrap().attr("link");
            let child = j.child("child").unwrap().attr("link");
            if poses.contains_key(child) {
                continue;
            }
            let Some(p) = poses.get(parent).copied() else { continue };
            let q = u.get(j.attr("name")).copied().unwrap_or(0.0);
            let axis = j.child("axis").map_or(Vector3::x(), |a| Vector3::from_column_slice(&a.nums("xyz")));
            let motion = match j.attr("type") {
                "revolute" | "continuous" => {
                    Isometry3::from_parts(Translation3::identity(), UnitQuaternion::from_axis_angle(&Unit::new_normalize(axis), q))
                }
                "prismatic" => Isometry3::translation(axis.x * q, axis.y * q, axis.z * q),
                _ => Isometry3::identity(),
            };
            poses.insert(child.to_string(), p * pose_of(j.child("origin")) * motion);
            progress = true;
        }
        if !progress {
            break;
        }
    }
    poses
}

fn dist(a: &Isometry3<f64>, b: &Isometry3<f64>) -> f64 {
    (a.to_homogeneous() - b.to_homogeneous()).amax()
}

fn frame(m: &mut Model, owner: FrameOwner, name: &str, pose: Isometry3<f64>) -> FrameId {
    let id = FrameId(m.frames.len() as u32);
    m.frames.push(Frame {
        name: name.into(),
        display_name: String::new(),
        node_id: format!("f{}", id.0),
        owner,
        ref_id: None,
        pose,
        loc: SourceLoc::default(),
    });
    if let FrameOwner::Body(b) = owner {
        m.bodies[b.index()].frames.push(id);
    }
    id
}

fn iso(t: [f64; 3], r: [f64; 3]) -> Isometry3<f64> {
    Isometry3::from_parts(Translation3::new(t[0], t[1], t[2]), UnitQuaternion::from_euler_angles(r[0], r[1], r[2]))
}

/// A body with CS1 at `cs1`, the CG at `cg_local` in CS1 (rotated), a full inertia.
fn body(m: &mut Model, name: &str, cs1: Isometry3<f64>, cg_local: Isometry3<f64>, mass: f64) -> BodyId {
    let id = BodyId(m.bodies.len() as u32);
    let k = id.0 as f64;
    m.bodies.push(Body {
        cad_name: name.into(),
        node_id: format!("{name}-{}", id.0),
        subsystem_path: vec![],
        mass,
        inertia_cg: Matrix3::new(0.3 + k, 0.01, -0.02, 0.01, 0.25 + k, 0.015, -0.02, 0.015, 0.2 + k) * 1e-3,
        volume: None,
        surface_area: None,
        cg: FrameId(0),
        cs1: FrameId(0),
        frames: vec![],
        geometry_file: None,
        mesh: None,
        geometry_sources: vec![],
        material: None,
        loc: SourceLoc::default(),
    });
    let c = frame(m, FrameOwner::Body(id), "CS1", cs1);
    let g = frame(m, FrameOwner::Body(id), "CG", cs1 * cg_local);
    m.bodies[id.index()].cs1 = c;
    m.bodies[id.index()].cg = g;
    id
}

fn joint(
    m: &mut Model,
    name: &str,
    base: FrameId,
    follower: FrameId,
    prims: &[(PrimitiveKind, Vector3<f64>)],
    limits: Option<JointLimits>,
) -> JointId {
    let id = JointId(m.joints.len() as u32);
    m.joints.push(Joint {
        cad_name: name.into(),
        node_id: format!("{name}-j"),
        subsystem_path: vec![],
        base,
        follower,
        primitives: prims
            .iter()
            .map(|(k, a)| Primitive { kind: *k, axis_world: *a, losses: Default::default(), loc: SourceLoc::default() })
            .collect(),
        limits,
        loc: SourceLoc::default(),
    });
    id
}

fn rot(axis: Vector3<f64>, a: f64) -> UnitQuaternion<f64> {
    UnitQuaternion::from_axis_angle(&Unit::new_normalize(axis), a)
}

/// Ground; pendulum A (revolute with limits, CS1 off the axis, CG offset and rotated, start
/// 0.3 rad); B on a prismatic from A (start 0.05 m, no limits); C welded to B; D on a
/// revolute+prismatic composite whose base frame is on D (traversed backwards); S on a
/// spherical; E free; a coupling B follows A; a four-bar G-A-F-K-G closed by a revolute.
fn model() -> Model {
    let mut m = Model { name: "t".into(), length_scale: 1.0, ..Default::default() };
    m.grounds.push(Ground { name: "G".into(), node_id: "g".into(), frame: FrameId(0), loc: SourceLoc::default() });
    let g_pose = iso([0.0, 0.0, 0.5], [0.0, 0.0, 0.0]);
    let g = frame(&mut m, FrameOwner::Ground(GroundId(0)), "G", g_pose);
    m.grounds[0].frame = g;
    let z = Vector3::z();

    // A: pendulum about world z through g, started at 0.3 rad.
    let a = body(&mut m, "A", iso([0.2, 0.1, 0.45], [0.1, 0.2, 0.3]), iso([0.05, -0.02, 0.01], [0.4, -0.3, 0.9]), 2.0);
    let a_j = frame(&mut m, FrameOwner::Body(a), "CS2", Isometry3::from_parts(g_pose.translation, rot(z, 0.3)));
    let lim = JointLimits { lower: Some(-1.0), upper: Some(1.5), velocity: Some(2.0), effort: Some(30.0) };
    joint(&mut m, "JA", g, a_j, &[(PrimitiveKind::Revolute, z)], Some(lim));

    // B: prismatic from A along a tilted axis, started at 0.05 m.
    let axis_b = Vector3::new(1.0, 1.0, 0.5).normalize();
    let base_b = Isometry3::from_parts(Translation3::new(0.3, 0.1, 0.5), rot(Vector3::new(0.0, 1.0, 1.0), 0.7));
    let a_b = frame(&mut m, FrameOwner::Body(a), "CS3", base_b);
    let b = body(&mut m, "B", iso([0.4, 0.3, 0.7], [-0.5, 0.1, 0.2]), iso([0.0, 0.01, 0.0], [0.0, 0.0, 0.0]), 1.0);
    let fol_b = Isometry3::from_parts(Translation3::from(base_b.translation.vector + axis_b * 0.05), base_b.rotation);
    let b_a = frame(&mut m, FrameOwner::Body(b), "CS2", fol_b);
    joint(&mut m, "JB", a_b, b_a, &[(PrimitiveKind::Prismatic, axis_b)], None);

    // C welded to B.
    let c = body(&mut m, "C", iso([0.5, 0.3, 0.8], [0.2, 0.2, 0.2]), iso([0.01, 0.0, 0.0], [0.0, 1.0, 0.0]), 0.5);
    let weld = iso([0.45, 0.3, 0.75], [0.3, 0.0, 0.0]);
    let b_c = frame(&mut m, FrameOwner::Body(b), "CS3", weld);
    let c_b = frame(&mut m, FrameOwner::Body(c), "CS2", weld);
    joint(&mut m, "JC", b_c, c_b, &[(PrimitiveKind::Weld, Vector3::zeros())], None);

    // D: revolute + prismatic, base frame on D, follower on C (the tree goes C -> D).
    let d = body(&mut m, "D", iso([0.7, 0.2, 0.9], [0.0, 0.5, -0.4]), iso([0.0, 0.0, 0.02], [0.1, 0.0, 0.0]), 0.7);
    let base_d = iso([0.65, 0.25, 0.85], [0.3, -0.2, 0.1]);
    let d_c = frame(&mut m, FrameOwner::Body(d), "CS2", base_d);
    let (ax_r, ax_p) = (Vector3::new(0.0, 1.0, 0.0), Vector3::new(1.0, 0.0, 0.0));
    let fol_d = Isometry3::from_parts(Translation3::from(base_d.translation.vector + ax_p * 0.02), rot(ax_r, -0.4) * base_d.rotation);
    let c_d = frame(&mut m, FrameOwner::Body(c), "CS3", fol_d);
    joint(&mut m, "JD", d_c, c_d, &[(PrimitiveKind::Revolute, ax_r), (PrimitiveKind::Prismatic, ax_p)], None);

    // S on a spherical from D, centre off S's CS1.
    let s = body(&mut m, "S", iso([0.8, 0.1, 1.0], [1.0, 0.2, 0.3]), iso([0.0, 0.0, 0.0], [0.0, 0.0, 0.0]), 0.3);
    let centre = iso([0.75, 0.15, 0.95], [0.0, 0.1, 0.0]);
    let d_s = frame(&mut m, FrameOwner::Body(d), "CS3", centre);
    let s_d = frame(&mut m, FrameOwner::Body(s), "CS2", centre);
    joint(&mut m, "JS", d_s, s_d, &[(PrimitiveKind::Spherical, Vector3::zeros())], None);

    // E: free.
    body(&mut m, "E", iso([-0.3, 0.2, 0.1], [0.3, 0.3, 0.3]), iso([0.01, 0.02, 0.03], [0.5, 0.0, 0.0]), 0.2);

    // Four-bar on the ground at z = 0.2 (parallel z axes): G -(JF1)- F -(JF2)- K -(JF3)- G.
    let p0 = Vector3::new(1.0, 0.0, 0.2);
    let p1 = Vector3::new(1.1, 0.2, 0.2);
    let p2 = Vector3::new(1.4, 0.25, 0.2);
    let p3 = Vector3::new(1.5, 0.0, 0.2);
    let at = |p: Vector3<f64>| Isometry3::from_parts(Translation3::from(p), UnitQuaternion::identity());
    let g2 = frame(&mut m, FrameOwner::Ground(GroundId(0)), "G2", at(p0));
    let g3 = frame(&mut m, FrameOwner::Ground(GroundId(0)), "G3", at(p3));
    let f = body(&mut m, "F", at(p0), iso([0.05, 0.1, 0.0], [0.0, 0.0, 0.0]), 0.1);
    let k = body(&mut m, "K", at(p1), iso([0.15, 0.02, 0.0], [0.0, 0.0, 0.0]), 0.1);
    let l = body(&mut m, "L", at(p3), iso([-0.05, 0.1, 0.0], [0.0, 0.0, 0.0]), 0.1);
    let f0 = frame(&mut m, FrameOwner::Body(f), "CS2", at(p0));
    let f1 = frame(&mut m, FrameOwner::Body(f), "CS3", at(p1));
    let k1 = frame(&mut m, FrameOwner::Body(k), "CS2", at(p1));
    let k2 = frame(&mut m, FrameOwner::Body(k), "CS3", at(p2));
    let l2 = frame(&mut m, FrameOwner::Body(l), "CS2", at(p2));
    let l3 = frame(&mut m, FrameOwner::Body(l), "CS3", at(p3));
    joint(&mut m, "JF1", g2, f0, &[(PrimitiveKind::Revolute, z)], None);
    joint(&mut m, "JF2", f1, k1, &[(PrimitiveKind::Revolute, z)], None);
    joint(&mut m, "JF3", k2, l2, &[(PrimitiveKind::Revolute, z)], None);
    joint(&mut m, "JF4", l3, g3, &[(PrimitiveKind::Revolute, z)], None);

    m.couplings.push(Coupling { follower: JointId(1), leader: JointId(0), multiplier: 0.5, offset: 0.01, loc: SourceLoc::default() });
    m
}

fn convert(m: &Model) -> (Validated, Layout, String) {
    let planned = passes::loops::plan(m).unwrap();
    let analysis = Analysis { hierarchy: planned.hierarchy, chains: planned.chains, loops: planned.loops };
    let v = valid::validate(m, analysis).unwrap();
    let pkg = modelica::write(
        m,
        &v,
        &modelica::Options {
            package_name: "T".into(),
            gravity: [0.0, 0.0, -9.81],
            converter_version: "test".into(),
            name_hints: Default::default(),
        },
    );
    let (path, bytes) = file(m, &v, &pkg.layout, "T", true);
    assert_eq!(path, "T/T.urdf");
    (v, pkg.layout, String::from_utf8(bytes).unwrap())
}

#[test]
fn links_reproduce_cad_poses_and_inertias() {
    let m = model();
    let (_, layout, text) = convert(&m);
    let robot = parse(&text);
    let names = layout.names.as_ref().unwrap();
    let poses = link_poses(&robot, &BTreeMap::new());
    // Every link (bodies, helpers, world) is reached from the world, each exactly once as a child.
    let links: Vec<&str> = robot.all("link").map(|l| l.attr("name")).collect();
    assert_eq!(poses.len(), links.len(), "{text}");
    let mut children: Vec<&str> = robot.all("joint").map(|j| j.child("child").unwrap().attr("link")).collect();
    children.sort();
    children.dedup();
    assert_eq!(children.len(), robot.all("joint").count());
    for (i, b) in m.bodies.iter().enumerate() {
        let name = &names.bodies[i];
        let link = robot.all("link").find(|l| l.attr("name") == name).unwrap();
        let p = poses[name.as_str()];
        assert!(dist(&p, &m.frame(b.cs1).pose) < 1e-12, "{name}: {p} vs {}", m.frame(b.cs1).pose);
        let inertial = link.child("inertial").unwrap();
        let cg = p * pose_of(inertial.child("origin"));
        assert!(dist(&cg, &m.frame(b.cg).pose) < 1e-12, "{name} CG");
        assert_eq!(inertial.child("mass").unwrap().num("value"), b.mass);
        let i = inertial.child("inertia").unwrap();
        let ii = &b.inertia_cg;
        for (k, (r, c)) in [("ixx", (0, 0)), ("ixy", (0, 1)), ("ixz", (0, 2)), ("iyy", (1, 1)), ("iyz", (1, 2)), ("izz", (2, 2))] {
            assert_eq!(i.num(k), ii[(r, c)], "{name} {k}");
        }
    }
}

#[test]
fn joint_kinds_limits_mimic_loops() {
    let m = model();
    let (_, _, text) = convert(&m);
    let robot = parse(&text);
    let j = |n: &str| robot.all("joint").find(|j| j.attr("name") == n).unwrap_or_else(|| panic!("{n} in {text}"));
    assert_eq!(j("JA").attr("type"), "revolute");
    let l = j("JA").child("limit").unwrap();
    // Limits move to URDF's coordinate: q − q0 with q0 = 0.3.
    assert!((l.num("lower") + 1.3).abs() < 1e-15 && (l.num("upper") - 1.2).abs() < 1e-15, "{l:?}");
    assert_eq!((l.num("velocity"), l.num("effort")), (2.0, 30.0));
    // A's CS1 is off the axis: the revolute ends in a helper link and a fixed offset.
    assert_eq!(j("JA").child("child").unwrap().attr("link"), "JA__1");
    assert_eq!(j("JA__offset").attr("type"), "fixed");
    assert_eq!(j("JB").attr("type"), "prismatic");
    let l = j("JB").child("limit").unwrap();
    assert_eq!((l.num("lower"), l.num("upper")), (-DEFAULT_TRAVEL, DEFAULT_TRAVEL));
    let mimic = j("JB").child("mimic").unwrap();
    // q_B = 0.5 q_A + 0.01 with q0_A = 0.3, q0_B = 0.05: u_B = 0.5 u_A + 0.11.
    assert_eq!((mimic.attr("joint"), mimic.num("multiplier")), ("JA", 0.5));
    assert!((mimic.num("offset") - 0.11).abs() < 1e-15, "{mimic:?}");
    assert_eq!(j("JC").attr("type"), "fixed");
    assert_eq!(j("JD_1").attr("type"), "continuous");
    assert_eq!(j("JD_2").attr("type"), "prismatic");
    for s in ["x", "y", "z"] {
        assert_eq!(j(&format!("JS_{s}")).attr("type"), "continuous");
    }
    assert_eq!(j("E_free").attr("type"), "floating");
    assert_eq!(j("E_free").child("parent").unwrap().attr("link"), "world");
    // One joint of the four-bar closes the loop: a Drake loop_joint between two bodies.
    let loops: Vec<&Node> = robot.all("loop_joint").collect();
    assert_eq!(loops.len(), 1, "{text}");
    assert_eq!(loops[0].attr("type"), "continuous");
    assert!(["JF1", "JF2", "JF3", "JF4"].contains(&loops[0].attr("name")));
    assert!(robot.all("joint").all(|j| j.attr("name") != loops[0].attr("name")));
    // Meshes only with shapes: none here (no mesh).
    assert!(!text.contains("<mesh"));
}

/// The loop joint's two frames are the IR joint's base and follower frames.
#[test]
fn loop_joint_frames_are_the_joint_frames() {
    let m = model();
    let (v, layout, text) = convert(&m);
    let robot = parse(&text);
    let names = layout.names.as_ref().unwrap();
    let poses = link_poses(&robot, &BTreeMap::new());
    let l = robot.all("loop_joint").next().unwrap();
    // The writer cuts the joint that needs a helper link in the tree: JF3 (L's CS1 is off its axis).
    assert_eq!(l.attr("name"), "JF3");
    let closing = names.joints.iter().position(|n| n == l.attr("name")).unwrap();
    let joint = &m.joints[closing];
    let _ = &v;
    for (side, f) in [("link1", joint.base), ("link2", joint.follower)] {
        let n = l.child(side).unwrap();
        let p = poses[n.attr("link")] * pose_of(Some(n));
        assert!(dist(&p, &m.frame(f).pose) < 1e-12, "{side}");
    }
}

/// Moving URDF joints by `u` moves each child as the Modelica chain does at `q0 + u`.
#[test]
fn urdf_coordinate_is_modelica_minus_start() {
    let m = model();
    let (v, layout, text) = convert(&m);
    let robot = parse(&text);
    let names = layout.names.as_ref().unwrap();
    let a = &v.analysis;
    let mut u = BTreeMap::new();
    let mut delta = 0.1;
    for (j, elements) in layout.joint_elements.iter().enumerate() {
        let chain = &a.chains[j];
        if chain.elements.iter().any(|e| e.kind == PrimitiveKind::Spherical) {
            continue;
        }
        let ns: Vec<String> = if chain.elements.len() == 1 { vec![names.joints[j].clone()] } else { elements.clone() };
        for (k, _) in chain.elements.iter().enumerate() {
            u.insert(ns[k].clone(), delta);
            delta += 0.07;
        }
    }
    let poses = link_poses(&robot, &u);
    let cuts: Vec<&str> = robot.all("loop_joint").map(|l| l.attr("name")).collect();
    let tree = m.joint_ids().filter(|j| !cuts.contains(&names.joints[j.index()].as_str()));
    let mut checked = 0;
    for j in tree {
        checked += 1;
        let joint = m.joint(j);
        let chain = &a.chains[j.index()];
        if chain.elements.iter().any(|e| e.kind == PrimitiveKind::Spherical) || chain.elements.is_empty() {
            continue;
        }
        let ns: Vec<String> =
            if chain.elements.len() == 1 { vec![names.joints[j.index()].clone()] } else { layout.joint_elements[j.index()].clone() };
        // Modelica: follower = base * Π M(q0 + u) * residual (relative to the CAD pose).
        let mut motion = Isometry3::identity();
        for (k, e) in chain.elements.iter().enumerate() {
            motion *= e.motion(e.q0 + u[&ns[k]]);
        }
        let (b, f) = (m.frame(joint.base).pose, m.frame(joint.follower).pose);
        let owner = |fr: FrameId| match m.frame(fr).owner {
            FrameOwner::Body(b) => (names.bodies[b.index()].clone(), m.frame(m.body(b).cs1).pose),
            FrameOwner::Ground(_) => ("world".to_string(), Isometry3::identity()),
        };
        let (bl, bc) = owner(joint.base);
        let (fl, fc) = owner(joint.follower);
        // Follower's link frame relative to the base's link frame.
        let want = bc.inverse() * b * motion * chain.residual * f.inverse() * fc;
        let got = poses[bl.as_str()].inverse() * poses[fl.as_str()];
        assert!(dist(&want, &got) < 1e-12, "{}: {want} vs {got}", names.joints[j.index()]);
    }
    assert_eq!(checked, m.joints.len() - 1);
}

#[test]
fn rpy_round_trips_at_gimbal_lock() {
    let mut worst: f64 = 0.0;
    let half = std::f64::consts::FRAC_PI_2;
    for (r, p, y) in [(0.3, half, -0.2), (0.3, -half, 1.0), (1.0, half - 1e-9, 2.0), (-3.0, 0.1, 3.1), (0.0, 0.0, 0.0), (2.0, -1.2, -2.9)] {
        let q = UnitQuaternion::from_euler_angles(r, p, y);
        let [a, b, c] = rpy(&q);
        let back = Rotation3::from_euler_angles(a, b, c);
        worst = worst.max((back.into_inner() - q.to_rotation_matrix().into_inner()).amax());
    }
    assert!(worst < 1e-15, "{worst}");
}

#[test]
fn numbers_round_trip_and_names_are_escaped() {
    assert_eq!(n(-0.0), "0.0");
    let x = 0.1 + 0.2;
    assert_eq!(n(x).parse::<f64>().unwrap(), x);
    let mut m = model();
    m.source.file = "a--b<c>.xml".into();
    let (_, _, text) = convert(&m);
    // In a comment only "--" needs care.
    assert!(text.contains("from a- -b<c>.xml."), "{}", &text[..400]);
    parse(&text);
    // Shapes: a body with a mesh gets a visual and a collision at the identity.
    let mut m = model();
    m.bodies[0].mesh =
        Some(std::sync::Arc::new(Mesh { vertices: vec![[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]], triangles: vec![[0, 1, 2]] }));
    let (v, _, _) = convert(&m);
    let mut layout = modelica::write(
        &m,
        &v,
        &modelica::Options { package_name: "T".into(), gravity: [0.0; 3], converter_version: "t".into(), name_hints: Default::default() },
    )
    .layout;
    assert!(layout.shapes[0].is_some());
    let text = write(&m, &v, &layout, "T", true);
    let robot = parse(&text);
    let link = robot.all("link").find(|l| l.attr("name") == "A").unwrap();
    let mesh = link.child("visual").unwrap().child("geometry").unwrap().child("mesh").unwrap();
    assert_eq!(mesh.attr("filename"), format!("package://T/Resources/Shapes/{}.stl", layout.shapes[0].as_ref().unwrap()));
    assert!(link.child("collision").is_some());
    assert!(!write(&m, &v, &layout, "T", false).contains("<mesh"));
    layout.shapes[0] = None;
    assert!(!write(&m, &v, &layout, "T", true).contains("<mesh"));
}

/// A body hung from the ground by two joints: the loop closes at the world, which a loop joint
/// cannot end on: a comment, no loop joint, and the body hangs from one of them.
#[test]
fn loops_at_the_world_are_comments() {
    let mut m = Model { name: "w".into(), length_scale: 1.0, ..Default::default() };
    m.grounds.push(Ground { name: "G".into(), node_id: "g".into(), frame: FrameId(0), loc: SourceLoc::default() });
    let g1 = frame(&mut m, FrameOwner::Ground(GroundId(0)), "G1", iso([0.0, 0.0, 0.0], [0.0, 0.0, 0.0]));
    let g2 = frame(&mut m, FrameOwner::Ground(GroundId(0)), "G2", iso([0.0, 0.0, 0.3], [0.0, 0.0, 0.0]));
    let x = body(&mut m, "X", iso([0.1, 0.0, 0.1], [0.0, 0.0, 0.0]), iso([0.0, 0.0, 0.0], [0.0, 0.0, 0.0]), 1.0);
    let x1 = frame(&mut m, FrameOwner::Body(x), "CS2", iso([0.0, 0.0, 0.0], [0.0, 0.0, 0.0]));
    let x2 = frame(&mut m, FrameOwner::Body(x), "CS3", iso([0.0, 0.0, 0.3], [0.0, 0.0, 0.0]));
    joint(&mut m, "J1", g1, x1, &[(PrimitiveKind::Revolute, Vector3::z())], None);
    joint(&mut m, "J2", g2, x2, &[(PrimitiveKind::Revolute, Vector3::z())], None);
    let (_, _, text) = convert(&m);
    assert!(!text.contains("<loop_joint"), "{text}");
    assert!(text.contains("not written"), "{text}");
    let robot = parse(&text);
    let poses = link_poses(&robot, &BTreeMap::new());
    assert!(dist(&poses["X"], &m.frame(m.bodies[0].cs1).pose) < 1e-12);
}

#[test]
fn the_relative_variant_names_meshes_beside_the_file() {
    // MuJoCo cannot open package:// paths (measured: it refuses urdf_arm.urdf and opens
    // urdf_arm.mujoco.urdf with all six meshes).
    let ros =
        ("P/P.urdf".to_string(), b"<mesh filename=\"package://P/Resources/Shapes/a.stl\"/><mesh filename=\"package://Q/x.stl\"/>".to_vec());
    let (path, bytes) = relative_file(&ros, "P");
    assert_eq!(path, "P/P.mujoco.urdf");
    assert_eq!(String::from_utf8(bytes).unwrap(), "<mesh filename=\"Resources/Shapes/a.stl\"/><mesh filename=\"package://Q/x.stl\"/>");
}
