use nalgebra::{Vector3, Vector6};

use super::mates::{mate_rows, reduce, Geom, GeomKind, MateKind, Reduction};
use super::{is_simscape2_xml, parse};
use crate::pipeline::ir::PrimitiveKind;

fn plane(p: [f64; 3], n: [f64; 3]) -> Geom {
    Geom { kind: GeomKind::Plane, point: Vector3::from(p), axis: Vector3::from(n).normalize() }
}
fn line(p: [f64; 3], d: [f64; 3]) -> Geom {
    Geom { kind: GeomKind::Line, point: Vector3::from(p), axis: Vector3::from(d).normalize() }
}
fn circle(p: [f64; 3], d: [f64; 3]) -> Geom {
    Geom { kind: GeomKind::Circle, point: Vector3::from(p), axis: Vector3::from(d).normalize() }
}
fn point(p: [f64; 3]) -> Geom {
    Geom { kind: GeomKind::Point, point: Vector3::from(p), axis: Vector3::zeros() }
}

/// Rows and points of a set of mates, then the reduction.
fn reduce_mates(mates: &[(MateKind, Geom, Geom)]) -> Reduction {
    let mut rows: Vec<Vector6<f64>> = Vec::new();
    let mut pts = Vec::new();
    for (k, a, b) in mates {
        let r = mate_rows(*k, a, b).expect("supported");
        if let Some(res) = r.residual {
            assert!(res < 1e-9, "{k:?} does not hold: {res}");
        }
        rows.extend(r.rows);
        pts.push(a.point);
        pts.push(b.point);
    }
    reduce(&rows, &pts)
}

fn near(a: &Vector3<f64>, b: [f64; 3]) -> bool {
    (a - Vector3::from(b)).norm() < 1e-9
}

#[test]
fn concentric_and_plane_is_revolute_through_the_axis() {
    // A pin along z through (0.1, 0.2, *) plus a face contact z = 0.05.
    let r = reduce_mates(&[
        (MateKind::Concentric, line([0.1, 0.2, 0.0], [0.0, 0.0, 1.0]), line([0.1, 0.2, 0.3], [0.0, 0.0, -1.0])),
        (MateKind::Coincident, plane([0.0, 0.0, 0.05], [0.0, 0.0, 1.0]), plane([0.5, -0.4, 0.05], [0.0, 0.0, -1.0])),
    ]);
    let Reduction::Revolute { origin, axis } = r else { panic!("{r:?}") };
    assert!(near(&axis, [0.0, 0.0, 1.0]), "{axis}");
    // The origin lies on the axis.
    assert!((origin.xy() - nalgebra::Vector2::new(0.1, 0.2)).norm() < 1e-9, "{origin}");
}

#[test]
fn concentric_alone_is_cylindrical() {
    let r = reduce_mates(&[(MateKind::Concentric, line([1.0, 2.0, 3.0], [1.0, 1.0, 0.0]), line([2.0, 3.0, 3.0], [1.0, 1.0, 0.0]))]);
    let Reduction::Cylindrical { origin, axis } = r else { panic!("{r:?}") };
    let d = Vector3::new(1.0, 1.0, 0.0).normalize();
    assert!((axis - d).norm() < 1e-9, "{axis}");
    let off = origin - Vector3::new(1.0, 2.0, 3.0);
    assert!((off - d * d.dot(&off)).norm() < 1e-9, "{origin} not on the axis");
}

#[test]
fn two_plane_pairs_are_prismatic_along_their_intersection() {
    let r = reduce_mates(&[
        (MateKind::Coincident, plane([0.0, 0.0, 0.0], [0.0, 0.0, 1.0]), plane([0.3, 0.1, 0.0], [0.0, 0.0, 1.0])),
        (MateKind::Coincident, plane([0.0, 0.0, 0.0], [0.0, 1.0, 0.0]), plane([0.7, 0.0, 0.2], [0.0, -1.0, 0.0])),
    ]);
    let Reduction::Prismatic { axes, .. } = r else { panic!("{r:?}") };
    assert_eq!(axes.len(), 1);
    assert!(near(&axes[0], [1.0, 0.0, 0.0]), "{}", axes[0]);
}

#[test]
fn one_plane_pair_is_planar() {
    let r = reduce_mates(&[(MateKind::Coincident, plane([0.0, 0.0, 2.0], [0.0, 0.0, 1.0]), plane([5.0, 1.0, 2.0], [0.0, 0.0, -1.0]))]);
    let Reduction::Planar { normal, in_plane, .. } = r else { panic!("{r:?}") };
    assert!(near(&normal, [0.0, 0.0, 1.0]));
    assert!(in_plane.iter().all(|t| t.z.abs() < 1e-9));
}

#[test]
fn sphere_centres_are_spherical_and_plus_a_pin_is_universal() {
    let s = (MateKind::Concentric, point([0.2, 0.0, 0.1]), point([0.2, 0.0, 0.1]));
    let r = reduce_mates(&[s]);
    let Reduction::Spherical { origin } = r else { panic!("{r:?}") };
    assert!(near(&origin, [0.2, 0.0, 0.1]));
    // A fixed angle between two directions on top of the ball: two rotations about the centre.
    let r = reduce_mates(&[s, (MateKind::Angle, plane([0.2, 0.0, 0.1], [1.0, 0.0, 0.0]), plane([0.2, 0.0, 0.1], [1.0, 1.0, 0.0]))]);
    let Reduction::Universal { origin, axes } = r else { panic!("{r:?}") };
    assert!(near(&origin, [0.2, 0.0, 0.1]), "{origin}");
    assert!(axes[0].dot(&axes[1]).abs() < 1e-9);
}

#[test]
fn fully_constrained_is_weld_and_redundant_mates_do_not_change_it() {
    let base = [
        (MateKind::Coincident, plane([0.0, 0.0, 0.0], [0.0, 0.0, 1.0]), plane([0.0, 0.0, 0.0], [0.0, 0.0, -1.0])),
        (MateKind::Coincident, plane([0.0, 0.0, 0.0], [0.0, 1.0, 0.0]), plane([0.0, 0.0, 0.0], [0.0, 1.0, 0.0])),
        (MateKind::Coincident, plane([0.0, 0.0, 0.0], [1.0, 0.0, 0.0]), plane([0.0, 0.0, 0.0], [1.0, 0.0, 0.0])),
    ];
    assert!(matches!(reduce_mates(&base), Reduction::Weld { .. }));
    // Rank deficiency: a parallel mate repeats what the plane pairs already fix.
    let mut more = base.to_vec();
    more.push((MateKind::Parallel, plane([1.0, 1.0, 1.0], [0.0, 0.0, 1.0]), plane([3.0, 1.0, 1.0], [0.0, 0.0, 1.0])));
    assert!(matches!(reduce_mates(&more), Reduction::Weld { .. }));
    // Two of the three planes: 1 DoF left (prismatic along z x y = x).
    assert_eq!(reduce_mates(&base[..2]).dof(), 1);
}

#[test]
fn no_rows_is_free_and_a_screw_is_unreducible() {
    assert_eq!(reduce(&[], &[Vector3::zeros()]), Reduction::Free);
    // A screw about z with pitch h: rows fixing everything but ω = e_z, v = h e_z.
    let h = 0.01;
    let rows = [
        Vector6::new(1.0, 0.0, 0.0, 0.0, 0.0, 0.0),
        Vector6::new(0.0, 1.0, 0.0, 0.0, 0.0, 0.0),
        Vector6::new(0.0, 0.0, 0.0, 1.0, 0.0, 0.0),
        Vector6::new(0.0, 0.0, 0.0, 0.0, 1.0, 0.0),
        Vector6::new(0.0, 0.0, h, 0.0, 0.0, -1.0),
    ];
    let r = reduce(&rows, &[Vector3::zeros(), Vector3::new(0.1, 0.0, 0.0)]);
    assert!(matches!(r, Reduction::Unreducible { .. }), "{r:?}");
    // A rotation about z plus a translation along x (a pin in a slot): not one joint.
    let rows = [
        Vector6::new(1.0, 0.0, 0.0, 0.0, 0.0, 0.0),
        Vector6::new(0.0, 1.0, 0.0, 0.0, 0.0, 0.0),
        Vector6::new(0.0, 0.0, 0.0, 0.0, 1.0, 0.0),
        Vector6::new(0.0, 0.0, 0.0, 0.0, 0.0, 1.0),
    ];
    let r = reduce(&rows, &[Vector3::zeros(), Vector3::new(0.1, 0.0, 0.0)]);
    assert!(matches!(r, Reduction::Unreducible { .. }), "{r:?}");
}

#[test]
fn coincident_circles_fix_the_centre_and_axis() {
    // Same centre and axis: only the rotation about the axis is left.
    let r = reduce_mates(&[(MateKind::Coincident, circle([0.0, 0.1, 0.0], [0.0, 1.0, 0.0]), circle([0.0, 0.1, 0.0], [0.0, -1.0, 0.0]))]);
    let Reduction::Revolute { axis, origin } = r else { panic!("{r:?}") };
    assert!(near(&axis, [0.0, 1.0, 0.0]));
    assert!(origin.x.abs() < 1e-9 && origin.z.abs() < 1e-9);
}

#[test]
fn inconsistent_mates_report_a_residual_and_unknown_pairs_are_errors() {
    let r = mate_rows(MateKind::Coincident, &plane([0.0, 0.0, 0.0], [0.0, 0.0, 1.0]), &plane([0.0, 0.0, 0.002], [0.0, 0.0, 1.0]))
        .expect("rows");
    assert!((r.residual.expect("checked") - 0.002).abs() < 1e-12);
    assert!(mate_rows(MateKind::Tangent, &point([0.0; 3]), &point([0.0; 3])).is_err());
}

// ----- whole files ---------------------------------------------------------------------------

const ONSHAPE: &str = r#"<?xml version="1.0" encoding="utf-8"?>
<SimscapeMultibodyImportXML xmlns="urn:mathworks:SimscapeMultibody:import" version="2.0">
  <Created by="t" from="Onshape" on="1/1/25" using="Simscape Multibody Exporter"/>
  <ModelUnits length="millimeter" mass="pound"/>
  <DataUnits length="meter" mass="kilogram"/>
  <RootAssembly name="arm" uid="A">
    <InstanceTree>
      <Instance entityUid="P1" grounded="true" name="Base &lt;1&gt;" uid="b">
        <Transform><Rotation>1 0 0 0 1 0 0 0 1</Rotation><Translation>0 0 0.1</Translation></Transform>
      </Instance>
      <Instance entityUid="SUB" name="Sub &lt;1&gt;" uid="s">
        <Transform><Rotation>0 -1 0 1 0 0 0 0 1</Rotation><Translation>1 0 0</Translation></Transform>
        <Instance entityUid="P1" name="Arm &lt;1&gt;" uid="a">
          <Transform><Rotation>1 0 0 0 1 0 0 0 1</Rotation><Translation>0.5 0 0</Translation></Transform>
        </Instance>
      </Instance>
    </InstanceTree>
    <Joints>
      <Revolute name="j1">
        <BaseFrame><InstancePath><Uid>b</Uid></InstancePath>
          <Transform><Rotation>1 0 0 0 1 0 0 0 1</Rotation><Translation>1 0.5 0</Translation></Transform></BaseFrame>
        <FollowerFrame><InstancePath><Uid>s</Uid><Uid>a</Uid></InstancePath>
          <Transform><Rotation>0 1 0 -1 0 0 0 0 1</Rotation><Translation>0 0 0.1</Translation></Transform></FollowerFrame>
      </Revolute>
    </Joints>
  </RootAssembly>
  <Parts>
    <Part name="P" uid="P1">
      <MassProperties><Mass>2</Mass><CenterOfMass>0.1 0 0</CenterOfMass><Inertia>1 2 3 0.4 0.5 0.6</Inertia></MassProperties>
      <GeometryFile name="P.step" type="STEP"/>
      <VisualProperties><Diffuse r="1" g="0.5" b="0" a="1"/></VisualProperties>
    </Part>
  </Parts>
</SimscapeMultibodyImportXML>"#;

#[test]
fn onshape_file_world_poses_inertia_joint() {
    assert!(is_simscape2_xml(ONSHAPE.as_bytes()));
    assert!(!is_simscape2_xml(b"<PhysicalModelingXMLFile/>"));
    let (m, w) = parse("t.xml", ONSHAPE.as_bytes()).expect("parses");
    assert_eq!(m.bodies.len(), 2);
    let arm = &m.bodies[1];
    assert_eq!(arm.cad_name, "Arm <1>");
    assert_eq!(arm.node_id, "s|a");
    assert_eq!(arm.subsystem_path, vec!["Sub <1>".to_string()]);
    // Arm: sub at (1,0,0) turned +90° about z; arm 0.5 along the sub's x = world y.
    let p = m.frame(arm.cs1).pose.translation.vector;
    assert!(near(&p, [1.0, 0.5, 0.0]), "{p}");
    let cg = m.frame(arm.cg).pose.translation.vector;
    assert!(near(&cg, [1.0, 0.6, 0.0]), "{cg}");
    // Ixx Iyy Izz Iyz Izx Ixy.
    let i = arm.inertia_cg;
    assert_eq!((i[(0, 0)], i[(1, 1)], i[(2, 2)], i[(1, 2)], i[(2, 0)], i[(0, 1)]), (1.0, 2.0, 3.0, 0.4, 0.5, 0.6));
    assert_eq!(arm.material.as_ref().map(|m| m.color), Some([1.0, 0.5, 0.0]));
    // The grounded base is welded to a ground; the revolute runs about the base frame's z.
    assert_eq!(m.grounds.len(), 1);
    assert_eq!(m.joints.len(), 2);
    let j = &m.joints[1];
    assert_eq!(j.primitives[0].kind, PrimitiveKind::Revolute);
    assert!(near(&j.primitives[0].axis_world, [0.0, 0.0, 1.0]));
    assert_eq!(m.frame(j.base).pose, m.frame(j.follower).pose);
    assert!(near(&m.frame(j.base).pose.translation.vector, [1.0, 0.5, 0.1]));
    // No warning: the STEP file is kept for the geometry pass; no frame mismatch (the follower
    // is turned about z).
    assert!(w.is_empty(), "{w:?}");
    assert!(arm.geometry_file.as_deref().is_some_and(|f| f.to_ascii_lowercase().ends_with(".step")), "{:?}", arm.geometry_file);
}

#[test]
fn unknown_joint_kind_and_bad_numbers_are_located_errors() {
    let bad = ONSHAPE.replace("<Revolute name=\"j1\">", "<Screw name=\"j1\">").replace("</Revolute>", "</Screw>");
    let e = parse("t.xml", bad.as_bytes()).expect_err("unknown kind");
    assert!(e.to_string().starts_with("t.xml:19:7: in Screw \"j1\": unknown joint kind <Screw>"), "{e}");
    let bad = ONSHAPE.replace("<Translation>0.5 0 0</Translation>", "<Translation>0.5 0</Translation>");
    let e = parse("t.xml", bad.as_bytes()).expect_err("short");
    assert_eq!(e.element, "Instance \"Arm <1>\" / Transform / Translation");
    assert!(e.message.contains("expected 3 numbers, found 2"), "{e}");
    let bad = ONSHAPE.replace("<DataUnits length=\"meter\"", "<DataUnits length=\"furlong\"");
    assert!(parse("t.xml", bad.as_bytes()).expect_err("unit").message.contains("unknown length unit \"furlong\""));
    assert!(parse("t.xml", &ONSHAPE.as_bytes()[..400]).is_err());
}

#[test]
fn follower_frame_off_axis_is_warned() {
    let off = ONSHAPE.replace(
        "<Translation>0 0 0.1</Translation></Transform></FollowerFrame>",
        "<Translation>0.01 0 0.1</Translation></Transform></FollowerFrame>",
    );
    let (_, w) = parse("t.xml", off.as_bytes()).expect("parses");
    assert!(w.iter().any(|w| w.code == "joint-frames-mismatch"), "{w:?}");
}

const SOLIDWORKS: &str = r#"<?xml version="1.0"?>
<SimscapeMultibodyImportXML version="2.0" xmlns="urn:mathworks:SimscapeMultibody:import">
<Created by="" on="x" using="Simscape Multibody Link" from="SolidWorks"/>
<ModelUnits mass="kg" length="mm"/>
<RootAssembly name="rig" uid="rig">
<InstanceTree>
<Instance name="frame-1" uid="frame-1" grounded="true" entityUid="box"><Transform><Rotation>1 0 0 0 1 0 0 0 1</Rotation><Translation>0 0 0</Translation></Transform></Instance>
<Instance name="crank-1" uid="crank-1" entityUid="box"><Transform><Rotation>1 0 0 0 1 0 0 0 1</Rotation><Translation>100 0 0</Translation></Transform></Instance>
</InstanceTree>
<Constraints>
<Concentric name="Concentric1">
<ConstraintGeometry geomType="cylinder"><InstancePath><Uid>frame-1</Uid></InstancePath><Position>100 0 0</Position><Axis>0 0 1</Axis></ConstraintGeometry>
<ConstraintGeometry geomType="cylinder"><InstancePath><Uid>crank-1</Uid></InstancePath><Position>0 0 5</Position><Axis>0 0 -1</Axis></ConstraintGeometry>
</Concentric>
<Coincident name="Coincident1">
<ConstraintGeometry geomType="plane"><Position>0 0 10</Position><Axis>0 0 1</Axis></ConstraintGeometry>
<ConstraintGeometry geomType="plane"><InstancePath><Uid>crank-1</Uid></InstancePath><Position>3 4 10</Position><Axis>0 0 1</Axis></ConstraintGeometry>
</Coincident>
</Constraints>
</RootAssembly>
<Parts>
<Part name="box" uid="box"><MassProperties><Mass>1.5</Mass><CenterOfMass>10 0 0</CenterOfMass><Inertia>100 200 300 0 0 0</Inertia></MassProperties><GeometryFile name="box.STL" type="STL"/></Part>
</Parts>
</SimscapeMultibodyImportXML>"#;

#[test]
fn solidworks_mates_become_a_revolute_in_mm_units() {
    let (m, w) = parse("sw.xml", SOLIDWORKS.as_bytes()).expect("parses");
    assert!(w.is_empty(), "{w:?}");
    assert_eq!(m.length_scale, 1e-3);
    let crank = &m.bodies[1];
    assert!(near(&m.frame(crank.cs1).pose.translation.vector, [0.1, 0.0, 0.0]));
    // kg·mm² -> kg·m².
    assert!((crank.inertia_cg[(1, 1)] - 2e-4).abs() < 1e-18);
    assert_eq!(crank.geometry_file.as_deref(), Some("box.STL"));
    // frame welded to the ground; crank revolves about z through (0.1, 0).
    assert_eq!(m.joints.len(), 2);
    let j = &m.joints[1];
    assert_eq!(j.primitives.len(), 1);
    assert_eq!(j.primitives[0].kind, PrimitiveKind::Revolute);
    assert!(near(&j.primitives[0].axis_world, [0.0, 0.0, 1.0]));
    let o = m.frame(j.base).pose.translation.vector;
    assert!((o.xy() - nalgebra::Vector2::new(0.1, 0.0)).norm() < 1e-12, "{o}");
}

#[test]
fn solidworks_inconsistent_and_unreducible_pairs_are_warned() {
    let off = SOLIDWORKS.replace("<Position>3 4 10</Position>", "<Position>3 4 12</Position>");
    let (_, w) = parse("sw.xml", off.as_bytes()).expect("parses");
    assert!(w.iter().any(|w| w.code == "mate-inconsistent" && w.message.contains("Coincident \"Coincident1\"")), "{w:?}");
    // Replace the concentric pin by a line in a plane: rotation about z and a slide are left
    // together with the plane contact... a pin-in-slot like motion that no joint allows.
    let slot = SOLIDWORKS
        .replace("<Concentric name=\"Concentric1\">", "<Coincident name=\"Slot\">")
        .replace("</Concentric>", "</Coincident>")
        .replace(
            "geomType=\"cylinder\"><InstancePath><Uid>frame-1</Uid></InstancePath><Position>100 0 0</Position><Axis>0 0 1</Axis>",
            "geomType=\"plane\"><InstancePath><Uid>frame-1</Uid></InstancePath><Position>100 0 0</Position><Axis>0 1 0</Axis>",
        );
    let (m, w) = parse("sw.xml", slot.as_bytes()).expect("parses");
    assert!(w.iter().any(|w| w.code == "mate-unreducible" && w.message.contains("\"Slot\"")), "{w:?}");
    assert_eq!(m.joints.len(), 1, "only the ground weld");
}

#[test]
fn non_finite_geometry_is_unreducible_not_a_hang() {
    let rows = [Vector6::new(f64::INFINITY, 0.0, 0.0, 0.0, 0.0, 1.0)];
    assert!(matches!(reduce(&rows, &[Vector3::zeros()]), Reduction::Unreducible { .. }));
    // Translations so large that composing them overflows: the file still parses or fails with
    // a message, never hangs.
    let huge = SOLIDWORKS.replace("<Translation>100 0 0</Translation>", "<Translation>1e308 1e308 0</Translation>");
    let _ = parse("sw.xml", huge.as_bytes());
    let scaled = ONSHAPE.replace("<Rotation>0 -1 0 1 0 0 0 0 1</Rotation>", "<Rotation>0 -1e300 0 1 0 0 0 0 1</Rotation>");
    let e = parse("t.xml", scaled.as_bytes()).expect_err("not a rotation");
    assert!(e.message.contains("not a rotation"), "{e}");
}
