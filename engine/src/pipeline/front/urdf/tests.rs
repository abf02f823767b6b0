use super::*;

fn ok(text: &str) -> Urdf {
    parse("t.urdf", text.as_bytes()).unwrap_or_else(|e| panic!("{e}"))
}

fn err(text: &str) -> String {
    parse("t.urdf", text.as_bytes()).expect_err("must fail").to_string()
}

const INERTIAL: &str = r#"<inertial><mass value="1"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial>"#;

fn two_links(joint: &str) -> String {
    format!(r#"<robot name="r"><link name="a">{INERTIAL}</link><link name="b">{INERTIAL}</link>{joint}</robot>"#)
}

#[test]
fn sniffs_the_root() {
    assert!(is_urdf(b"\xEF\xBB\xBF<?xml version=\"1.0\"?><!-- c --><robot name=\"x\"/>"));
    assert!(!is_urdf(b"<PhysicalModelingXMLFile/>"));
    assert!(!is_urdf(b"not xml"));
}

#[test]
fn rpy_is_fixed_axis_xyz() {
    // Roll about x, then pitch about the fixed y, then yaw about the fixed z.
    let (r, p, y) = (0.3, -0.4, 1.1);
    let q = rpy_rotation(&Vector3::new(r, p, y));
    let want = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), y)
        * UnitQuaternion::from_axis_angle(&Vector3::y_axis(), p)
        * UnitQuaternion::from_axis_angle(&Vector3::x_axis(), r);
    assert!(q.angle_to(&want) < 1e-15);
}

#[test]
fn places_links_and_inertial_frames() {
    let u = ok(&two_links(
        r#"<joint name="j" type="revolute"><parent link="a"/><child link="b"/><origin xyz="1 0 0" rpy="0 0 1.5707963267948966"/><axis xyz="0 1 0"/><limit lower="-1" upper="2" effort="3" velocity="4"/></joint>"#,
    ));
    let m = &u.model;
    assert_eq!(m.source.format, "urdf");
    let b = &m.bodies[1];
    let cs1 = m.frame(b.cs1).pose;
    assert!((cs1.translation.vector - Vector3::new(1.0, 0.0, 0.0)).norm() < 1e-15);
    // Joint 0 welds the root to the world; joint 1 is the revolute, its axis y turned to -x.
    let j = &m.joints[1];
    assert_eq!(j.cad_name, "j");
    assert!((j.primitives[0].axis_world - Vector3::new(-1.0, 0.0, 0.0)).norm() < 1e-15);
    assert_eq!(j.limits, Some(JointLimits { lower: Some(-1.0), upper: Some(2.0), velocity: Some(4.0), effort: Some(3.0) }));
    assert_eq!(m.frame(j.base).pose, m.frame(j.follower).pose);
    assert!(u.warnings.iter().any(|w| w.code == "urdf-root-fixed"));
}

#[test]
fn continuous_drops_position_limits_and_planar_spans_the_plane() {
    let u = ok(&two_links(
        r#"<joint name="j" type="continuous"><parent link="a"/><child link="b"/><axis xyz="0 0 2"/><limit lower="-1" upper="1" velocity="5"/></joint>"#,
    ));
    let j = &u.model.joints[1];
    assert_eq!(j.limits, Some(JointLimits { lower: None, upper: None, velocity: Some(5.0), effort: None }));
    assert!((j.primitives[0].axis_world - Vector3::z()).norm() < 1e-15, "axis normalised");
    let u = ok(&two_links(r#"<joint name="p" type="planar"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/></joint>"#));
    let p = &u.model.joints[1].primitives;
    let kinds: Vec<_> = p.iter().map(|x| x.kind).collect();
    assert_eq!(kinds, [PrimitiveKind::Prismatic, PrimitiveKind::Prismatic, PrimitiveKind::Revolute]);
    assert!(p[0].axis_world.dot(&Vector3::z()).abs() < 1e-15 && p[1].axis_world.dot(&Vector3::z()).abs() < 1e-15);
    assert!((p[0].axis_world.cross(&p[1].axis_world) - Vector3::z()).norm() < 1e-15);
}

#[test]
fn world_joints_get_grounds_and_floating_leaves_free() {
    let text = format!(
        r#"<robot name="r"><link name="world"/><link name="a">{INERTIAL}</link><link name="b">{INERTIAL}</link>
        <joint name="fix" type="fixed"><parent link="world"/><child link="a"/><origin xyz="0 0 2"/></joint>
        <joint name="fly" type="floating"><parent link="world"/><child link="b"/><origin xyz="1 0 0"/></joint></robot>"#
    );
    let u = ok(&text);
    assert_eq!(u.model.bodies.len(), 2, "world is no body");
    assert_eq!(u.model.grounds.len(), 1);
    assert_eq!(u.model.joints.len(), 1);
    assert!((u.model.frame(u.model.grounds[0].frame).pose.translation.vector.z - 2.0).abs() < 1e-15);
    assert!(u.warnings.iter().any(|w| w.code == "urdf-floating"));
    assert!((u.model.frame(u.model.bodies[1].cs1).pose.translation.vector.x - 1.0).abs() < 1e-15);
}

#[test]
fn mimic_becomes_a_coupling_or_a_warning() {
    let text = format!(
        r#"<robot name="r"><link name="a">{INERTIAL}</link><link name="b">{INERTIAL}</link><link name="c">{INERTIAL}</link><link name="d">{INERTIAL}</link>
        <joint name="j1" type="revolute"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
        <joint name="j2" type="prismatic"><parent link="a"/><child link="c"/><mimic joint="j1" multiplier="-0.5"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
        <joint name="j3" type="revolute"><parent link="a"/><child link="d"/><mimic joint="nope"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint></robot>"#
    );
    let u = ok(&text);
    assert_eq!(u.model.couplings.len(), 1);
    let c = &u.model.couplings[0];
    assert_eq!((u.model.joint(c.follower).cad_name.as_str(), u.model.joint(c.leader).cad_name.as_str(), c.multiplier), ("j2", "j1", -0.5));
    let w = u.warnings.iter().find(|w| w.code == "mimic-not-expressible").expect("warning");
    assert!(w.message.contains("\"nope\""), "{}", w.message);
}

#[test]
fn a_ring_of_mimics_loses_its_last_coupling_with_a_warning_naming_the_ring() {
    // j1 follows j2, j2 follows j3, j3 follows j1 (a three-gear ring), j4 follows j1 (a chain),
    // and j5 and j6 follow each other (a ring of two).
    let joint = |name: &str, child: &str, leader: &str| {
        format!(
            r#"<joint name="{name}" type="revolute"><parent link="a"/><child link="{child}"/><axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/><mimic joint="{leader}" multiplier="2"/></joint>"#
        )
    };
    let links: String = ["a", "b", "c", "d", "e", "f", "g"].iter().map(|l| format!(r#"<link name="{l}">{INERTIAL}</link>"#)).collect();
    let text = format!(
        r#"<robot name="r">{links}{}{}{}{}{}{}</robot>"#,
        joint("j1", "b", "j2"),
        joint("j2", "c", "j3"),
        joint("j3", "d", "j1"),
        joint("j4", "e", "j1"),
        joint("j5", "f", "j6"),
        joint("j6", "g", "j5"),
    );
    let u = ok(&text);
    let name = |j: ir::JointId| u.model.joint(j).cad_name.as_str();
    let kept: Vec<(&str, &str)> = u.model.couplings.iter().map(|c| (name(c.follower), name(c.leader))).collect();
    assert_eq!(kept, [("j1", "j2"), ("j2", "j3"), ("j4", "j1"), ("j5", "j6")]);
    let rings: Vec<&str> = u.warnings.iter().filter(|w| w.code == "mimic-not-expressible").map(|w| w.message.as_str()).collect();
    assert_eq!(rings.len(), 2, "{rings:?}");
    assert!(rings[0].contains("joint \"j3\" is left uncoupled") && rings[0].contains("(j3, j1, j2: each mimics the next"), "{}", rings[0]);
    assert!(rings[1].contains("joint \"j6\" is left uncoupled") && rings[1].contains("(j6, j5: each"), "{}", rings[1]);
}

#[test]
fn loop_joints_are_closed_by_assembly() {
    // A parallelogram whose coupler is built 0.2 rad open: the front end assembles it.
    let text = format!(
        r#"<robot name="r"><link name="g">{INERTIAL}</link><link name="c">{INERTIAL}</link><link name="k">{INERTIAL}</link><link name="o">{INERTIAL}</link>
        <joint name="crank" type="continuous"><parent link="g"/><child link="c"/><axis xyz="0 0 1"/></joint>
        <joint name="cup" type="continuous"><parent link="c"/><child link="k"/><origin xyz="0 1 0" rpy="0 0 0.2"/><axis xyz="0 0 1"/></joint>
        <joint name="rock" type="continuous"><parent link="g"/><child link="o"/><origin xyz="2 0 0"/><axis xyz="0 0 1"/></joint>
        <loop_joint name="close" type="continuous"><axis xyz="0 0 1"/><link1 link="k" xyz="2 0 0" rpy="0 0 0"/><link2 link="o" xyz="0 1 0" rpy="0 0 0"/></loop_joint></robot>"#
    );
    let u = ok(&text);
    let close = u.model.joints.iter().find(|j| j.cad_name == "close").expect("loop joint");
    let (a, b) = (u.model.frame(close.base).pose, u.model.frame(close.follower).pose);
    assert!((a.translation.vector - b.translation.vector).norm() < 1e-12);
    assert!(u.warnings.iter().any(|w| w.code == "urdf-loops-assembled"));
}

#[test]
fn errors_name_the_element_and_line() {
    let e = err(&two_links(r#"<joint name="j" type="gimbal"><parent link="a"/><child link="b"/></joint>"#));
    assert!(e.starts_with("t.urdf:1:") && e.contains("joint \"j\"") && e.contains("unknown joint type \"gimbal\""), "{e}");
    let e = err(&two_links(r#"<joint name="j" type="fixed"><parent link="a"/><child link="zz"/></joint>"#));
    assert!(e.contains("child link \"zz\" is not declared"), "{e}");
    let e = err(&two_links(
        r#"<joint name="j" type="fixed"><parent link="a"/><child link="b"/></joint><joint name="k" type="fixed"><parent link="b"/><child link="a"/></joint>"#,
    ));
    assert!(e.contains("cycle"), "{e}");
    let e = err(&two_links(r#"<joint name="j" type="fixed"><parent link="a"/><child link="b"/><origin xyz="1 nan 0"/></joint>"#));
    assert!(e.contains("not finite") || e.contains("not a number"), "{e}");
    let e = err(r#"<robot name="r"><link name="a"><inertial><mass value="-1"/></inertial></link></robot>"#);
    assert!(e.contains("negative mass"), "{e}");
    let e = err(r#"<robot xmlns:xacro="http://www.ros.org/wiki/xacro"><xacro:property name="x" value="1"/></robot>"#);
    assert!(e.contains("xacro") && e.contains("expand it first"), "{e}");
    let e = err("<robot><link name=\"a\">");
    assert!(e.contains("malformed XML"), "{e}");
    let e = err(r#"<robot name="r"><link name="a"/><link name="a"/></robot>"#);
    assert!(e.contains("a second link named \"a\""), "{e}");
}

#[test]
fn package_uris_resolve_inside_the_bundle() {
    use crate::pipeline::front::bundle::Bundle;
    let b = Bundle::from_files(
        "b",
        [
            ("set/robots/r_description/urdf/r.urdf".to_string(), Vec::new()),
            ("set/robots/r_description/meshes/Link.STL".to_string(), Vec::new()),
            ("set/robots/q_description/meshes/link.stl".to_string(), Vec::new()),
            ("set/robots/r_description/urdf/local.stl".to_string(), Vec::new()),
        ],
    )
    .expect("bundle");
    let from = "set/robots/r_description/urdf/r.urdf";
    assert_eq!(
        locate(&b, from, "package://ex/robots/r_description/meshes/link.stl").unwrap(),
        Some("set/robots/r_description/meshes/Link.STL")
    );
    assert_eq!(locate(&b, from, "package:///local.stl").unwrap(), Some("set/robots/r_description/urdf/local.stl"));
    assert_eq!(locate(&b, from, "local.stl").unwrap(), Some("set/robots/r_description/urdf/local.stl"));
    assert_eq!(locate(&b, from, "package://ex/robots/none.stl").unwrap(), None);
    // Two candidates by file name alone: an error naming both.
    assert!(locate(&b, from, "package://ex/meshes/link.stl").is_err());
}

#[test]
fn the_root_is_found_after_a_long_licence_header() {
    // A licence written as one comment per line puts <robot> kilobytes into the file (the
    // iiwa's at byte 3,200): more events than any fixed look-ahead.
    let header: String =
        (0..120).map(|i| format!("<!-- licence line {i:03}: permission is hereby granted, free of charge -->\n")).collect();
    let text = format!("<?xml version=\"1.0\"?>\n{header}{}", two_links(""));
    assert!(text.find("<robot").expect("root") > 8_000);
    assert!(is_urdf(text.as_bytes()));
    assert_eq!(ok(&text).model.bodies.len(), 2);
}

#[test]
fn a_leftover_namespaced_element_is_a_warning_and_real_xacro_is_refused() {
    let leftover = format!(
        r#"<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro" xmlns:foo="urn:foo"><link name="a">{INERTIAL}</link><link name="b">{INERTIAL}<foo:tag x="1"><foo:inner/></foo:tag></link><xacro:leftover_call name="x"/><gazebo reference="a"/><transmission name="t"/><joint name="j" type="revolute"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/></joint></robot>"#
    );
    let u = ok(&leftover);
    let ignored: Vec<&Warning> = u.warnings.iter().filter(|w| w.code == "urdf-element-ignored").collect();
    assert_eq!(ignored.len(), 2, "{ignored:?}");
    assert!(ignored.iter().any(|w| w.message.contains("<xacro:leftover_call>") && w.location.contains("t.urdf:1:")), "{ignored:?}");
    assert!(ignored.iter().any(|w| w.message.contains("<foo:tag>")), "{ignored:?}");
    assert_eq!(u.model.joints.len(), 2);
    // Macros, properties and substitutions are xacro proper: refused, naming the element.
    for body in [
        r#"<xacro:property name="l" value="0.3"/>"#,
        r#"<xacro:macro name="m"><link name="c"/></xacro:macro>"#,
        r#"<link name="c"><visual><geometry><box size="${l} 1 1"/></geometry></visual></link>"#,
    ] {
        let text = format!(r#"<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro"><link name="a"/>{body}</robot>"#);
        let e = err(&text);
        assert!(e.contains("xacro file") && e.contains("t.urdf:1:"), "{e}");
    }
}

/// A serial chain of `n` links (`l0` the root), revolute joints 0.1 m apart about alternating axes.
fn chain(n: usize) -> String {
    use std::fmt::Write as _;
    let mut u = String::from("<robot name=\"chain\">\n");
    for i in 0..n {
        let _ = writeln!(u, "<link name=\"l{i}\">{INERTIAL}</link>");
    }
    for i in 1..n {
        let axis = ["0 0 1", "0 1 0", "1 0 0"][i % 3];
        let _ = writeln!(
            u,
            "<joint name=\"j{i}\" type=\"revolute\"><parent link=\"l{}\"/><child link=\"l{i}\"/><origin xyz=\"0 0 0.1\"/><axis xyz=\"{axis}\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/></joint>",
            i - 1
        );
    }
    u.push_str("</robot>\n");
    u
}

#[test]
fn a_chain_past_the_link_limit_is_refused_naming_the_limit() {
    let e = err(&chain(20_000));
    assert!(e.contains("more than 10000 links") && e.contains("link \"l10000\""), "{e}");
}

#[test]
fn a_chain_just_under_the_link_limit_converts_on_a_default_thread_stack() {
    let n = MAX_LINKS;
    let text = chain(n);
    // The default stack of a spawned thread (2 MiB), as the service's workers have.
    let out = std::thread::Builder::new()
        .stack_size(2 << 20)
        .spawn(move || {
            let b = crate::pipeline::front::bundle::Bundle::from_files("chain", [("chain.urdf".to_string(), text.into_bytes())])
                .expect("bundle");
            // The service's mechanism (forward kinematics along the chain) too.
            let a = crate::pipeline::analyse(&b, &crate::pipeline::Options::default()).expect("analyses");
            let m = crate::mechanism::Mechanism::from_validated(&a.model, &a.validated).expect("mechanism");
            m.forward(&m.q0()).expect("forward kinematics");
            crate::pipeline::convert(&b, &crate::pipeline::Options::default())
                .map(|o| o.files.iter().find(|(p, _)| p.ends_with(".mjcf.xml")).map(|(_, bytes)| bytes.len()).expect("an MJCF"))
        })
        .expect("thread")
        .join()
        .expect("no stack overflow, no panic");
    // Linear in the links (indentation stops growing): about 500 bytes a body, not O(n²).
    let mjcf = out.expect("converts");
    assert!(mjcf < 1_000 * n, "MJCF of {mjcf} bytes for {n} links");
}

/// A flat square grid of `k` × `k` vertices as OBJ text: 2 (k - 1)² triangles in a few MB.
fn grid_obj(k: usize) -> Vec<u8> {
    use std::fmt::Write as _;
    let mut s = String::new();
    for i in 0..k {
        for j in 0..k {
            let _ = writeln!(s, "v {i} {j} 0");
        }
    }
    for i in 0..k - 1 {
        for j in 0..k - 1 {
            let (a, b, c, d) = (i * k + j + 1, i * k + j + 2, (i + 1) * k + j + 1, (i + 1) * k + j + 2);
            let _ = writeln!(s, "f {a} {b} {d}\nf {a} {d} {c}");
        }
    }
    s.into_bytes()
}

#[test]
fn a_mesh_named_by_many_links_counts_every_use_against_the_bundle_budget() {
    // 199,712 triangles in one 4 MB file, named by 26 links: 5.19 M triangles after instancing.
    let obj = grid_obj(317);
    let per = 2 * 316 * 316;
    let links = 26;
    assert!(per * (links - 1) <= geometry::MAX_BUNDLE_TRIANGLES && per * links > geometry::MAX_BUNDLE_TRIANGLES);
    let mut u = String::from("<robot name=\"many\">\n");
    for i in 0..links {
        u.push_str(&format!(
            "<link name=\"l{i}\">{INERTIAL}<visual><geometry><mesh filename=\"package://many/meshes/plate.obj\"/></geometry></visual></link>\n"
        ));
    }
    for i in 1..links {
        u.push_str(&format!("<joint name=\"j{i}\" type=\"fixed\"><parent link=\"l{}\"/><child link=\"l{i}\"/></joint>\n", i - 1));
    }
    u.push_str("</robot>\n");
    let b = crate::pipeline::front::bundle::Bundle::from_files(
        "many",
        [("many/urdf/many.urdf".to_string(), u.into_bytes()), ("many/meshes/plate.obj".to_string(), obj)],
    )
    .expect("bundle");
    let e = crate::pipeline::analyse(&b, &crate::pipeline::Options::default()).err().expect("over the budget").to_string();
    assert!(
        e.contains("many/meshes/plate.obj")
            && e.contains("link \"l25\"")
            && e.contains("5192512 triangles")
            && e.contains("limit of 5000000 triangles per bundle"),
        "{e}"
    );
}

#[test]
fn links_naming_one_mesh_the_same_way_share_it() {
    // l0..l2: the plate alone (l2 with a collision too: its visual is what it uses); l3: with an
    // origin; l4: scaled; l5: two visuals. Only the first three can share one placed mesh.
    let plate = r#"<mesh filename="package://many/meshes/plate.obj"/>"#;
    let links = [
        format!("<visual><geometry>{plate}</geometry></visual>"),
        format!("<visual><geometry>{plate}</geometry></visual>"),
        format!("<visual><geometry>{plate}</geometry></visual><collision><geometry><box size=\"1 1 1\"/></geometry></collision>"),
        format!("<visual><origin xyz=\"0 0 1\"/><geometry>{plate}</geometry></visual>"),
        r#"<visual><geometry><mesh filename="package://many/meshes/plate.obj" scale="2 2 2"/></geometry></visual>"#.to_string(),
        format!("<visual><geometry>{plate}</geometry></visual><visual><geometry>{plate}</geometry></visual>"),
    ];
    let mut u = String::from("<robot name=\"many\">\n");
    for (i, g) in links.iter().enumerate() {
        u.push_str(&format!("<link name=\"l{i}\">{INERTIAL}{g}</link>\n"));
    }
    for i in 1..links.len() {
        u.push_str(&format!(
            "<joint name=\"j{i}\" type=\"revolute\"><parent link=\"l{}\"/><child link=\"l{i}\"/><axis xyz=\"0 0 1\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/></joint>\n",
            i - 1
        ));
    }
    u.push_str("</robot>\n");
    let b = crate::pipeline::front::bundle::Bundle::from_files(
        "many",
        [("many/urdf/many.urdf".to_string(), u.into_bytes()), ("many/meshes/plate.obj".to_string(), grid_obj(5))],
    )
    .expect("bundle");
    let a = crate::pipeline::analyse(&b, &crate::pipeline::Options::default()).expect("converts");
    let mesh = |name: &str| a.model.bodies.iter().find(|b| b.cad_name == name).and_then(|b| b.mesh.clone()).expect(name);
    let (m0, m1, m2, m3, m4, m5) = (mesh("l0"), mesh("l1"), mesh("l2"), mesh("l3"), mesh("l4"), mesh("l5"));
    assert!(std::sync::Arc::ptr_eq(&m0, &m1) && std::sync::Arc::ptr_eq(&m0, &m2), "one mesh for the three links");
    for other in [&m3, &m4, &m5] {
        assert!(!std::sync::Arc::ptr_eq(&m0, other));
    }
    // Each placed as before: the shared one as read, the others moved, scaled or doubled.
    assert_eq!(m0.triangles.len(), 32);
    assert_eq!((m3.triangles.len(), m4.triangles.len(), m5.triangles.len()), (32, 32, 64));
    assert_eq!(m3.vertices[7], [m0.vertices[7][0], m0.vertices[7][1], m0.vertices[7][2] + 1.0]);
    assert_eq!(m4.vertices[7], m0.vertices[7].map(|c| c * 2.0));
    // Every use still counts: the six links hold 5 × 32 + 64 triangles.
    let per_body: usize = a.model.bodies.iter().filter_map(|b| b.mesh.as_ref()).map(|m| m.triangles.len()).sum();
    assert_eq!(per_body, 32 * 5 + 64);
}

/// `n` parallelogram four-bars on one base, each built 0.1 rad open and closed by a loop joint.
fn four_bars(n: usize) -> String {
    let mut s = format!(r#"<robot name="r"><link name="g">{INERTIAL}</link>"#);
    for k in 0..n {
        let z = 3 * k;
        s += &format!(
            r#"<link name="a{k}">{INERTIAL}</link><link name="b{k}">{INERTIAL}</link><link name="c{k}">{INERTIAL}</link>
            <joint name="ja{k}" type="revolute"><parent link="g"/><child link="a{k}"/><origin xyz="0 0 {z}"/><axis xyz="0 0 1"/></joint>
            <joint name="jb{k}" type="revolute"><parent link="a{k}"/><child link="b{k}"/><origin xyz="0 1 0" rpy="0 0 0.1"/><axis xyz="0 0 1"/></joint>
            <joint name="jc{k}" type="revolute"><parent link="g"/><child link="c{k}"/><origin xyz="2 0 {z}"/><axis xyz="0 0 1"/></joint>
            <loop_joint name="q{k}" type="revolute"><link1 link="b{k}" xyz="2 0 0"/><link2 link="c{k}" xyz="0 1 0"/><axis xyz="0 0 1"/></loop_joint>"#
        );
    }
    s + "</robot>"
}

#[test]
fn more_loop_joints_than_the_loop_analysis_takes_are_refused_before_assembly() {
    // 300 open four-bars: refused at the 257th loop joint, before Gauss-Newton (which took a
    // minute for all of them together) and the rank tests.
    let e = err(&four_bars(MAX_LOOP_JOINTS + 44));
    assert!(e.starts_with("t.urdf:") && e.contains("loop_joint \"q256\"") && e.contains("more than 256 loop joints"), "{e}");
}

#[test]
fn independent_loops_are_assembled_one_group_at_a_time() {
    // 256 four-bars, each open: closed group by group, within the assembly budget.
    let u = ok(&four_bars(MAX_LOOP_JOINTS));
    assert!(u.warnings.iter().any(|w| w.code == "urdf-loops-assembled"));
    for k in [0, 255] {
        let close = u.model.joints.iter().find(|j| j.cad_name == format!("q{k}")).expect("loop joint");
        let (a, b) = (u.model.frame(close.base).pose, u.model.frame(close.follower).pose);
        assert!((a.translation.vector - b.translation.vector).norm() < 1e-12);
    }
}

#[test]
fn a_loop_across_a_chain_too_long_to_assemble_is_refused_naming_the_limit() {
    // One loop joint from the tip of a 6,000-link chain back to its base, open: one Gauss-Newton
    // step evaluates the chain for each of its 6,000 joints: past the work limit before the first step.
    let mut s = format!(r#"<robot name="r"><link name="l0">{INERTIAL}</link>"#);
    for k in 1..6_000 {
        s += &format!(
            r#"<link name="l{k}">{INERTIAL}</link><joint name="j{k}" type="revolute"><parent link="l{}"/><child link="l{k}"/><origin xyz="0 0 0.001"/><axis xyz="0 1 0"/></joint>"#,
            k - 1
        );
    }
    s += r#"<loop_joint name="close" type="revolute"><link1 link="l5999" xyz="0 0 0"/><link2 link="l0" xyz="1 0 0"/><axis xyz="0 0 1"/></loop_joint></robot>"#;
    let e = err(&s);
    assert!(e.contains("loop_joint \"close\"") && e.contains(&format!("the limit is {}", assemble::MAX_ASSEMBLY_WORK)), "{e}");
}
