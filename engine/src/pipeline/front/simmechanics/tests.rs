//! Tests of the SimMechanics XML front end on small inline files and on the shared fixtures.

use super::*;
use crate::pipeline::ir::{FrameOwner, Model, PrimitiveKind, Warning};
use nalgebra::{Point3, Vector3};

// ----- builders for small files --------------------------------------------------------------

const IDENTITY: &str = "1,0,0,0,1,0,0,0,1";

fn frame(name: &str, r: Option<u32>, pos: &str, units: &str, orientation: &str) -> String {
    frame_in(name, r, pos, units, orientation, ["WORLD"; 3])
}

/// A frame whose `positionOrigin`, `positionReferenceFrame` and `orientationReferenceFrame`
/// are `refs`.
fn frame_in(name: &str, r: Option<u32>, pos: &str, units: &str, orientation: &str, [origin, axes, orient_ref]: [&str; 3]) -> String {
    let r = r.map(|r| format!(" ref=\"{r}\"")).unwrap_or_default();
    format!(
        r#"<Frame{r}>
            <name>"{name}"</name>
            <displayName>""</displayName>
            <nodeID>"{name}-id{r_id}"</nodeID>
            <position>{pos}</position>
            <positionOrigin>"{origin}"</positionOrigin>
            <positionReferenceFrame>"{axes}"</positionReferenceFrame>
            <positionUnits>"{units}"</positionUnits>
            <orientation>{orientation}</orientation>
            <orientationType>"3x3 Transform"</orientationType>
            <orientationUnits>"rad"</orientationUnits>
            <orientationReferenceFrame>"{orient_ref}"</orientationReferenceFrame>
          </Frame>
"#,
        r_id = r.len()
    )
}

fn body(name: &str, node_id: &str, frames: &[String]) -> String {
    format!(
        r#"<Body>
        <name>"{name}"</name>
        <nodeID>"{node_id}"</nodeID>
        <status>""</status>
        <mass>1.5</mass>
        <massUnits>"kg"</massUnits>
        <inertia>1,0,0,0,2,0,0,0,3</inertia>
        <inertiaUnits>"kg*m^2"</inertiaUnits>
        <volume>1000</volume>
        <volumeUnits>"mm^3"</volumeUnits>
        <frames>
{}        </frames>
        <geometryFileName>"{name}_prt.stl"</geometryFileName>
      </Body>
"#,
        frames.concat()
    )
}

/// A body with CG, CS1 and one referenced frame CS2 at `pos` (mm).
fn simple_body(name: &str, r: u32, pos: &str) -> String {
    body(
        name,
        name,
        &[frame("CG", None, pos, "mm", IDENTITY), frame("CS1", None, "0,0,0", "mm", IDENTITY), frame("CS2", Some(r), pos, "mm", IDENTITY)],
    )
}

fn joint(name: &str, base: u32, follower: u32, primitives: &[(&str, &str)]) -> String {
    let prims: String = primitives
        .iter()
        .map(|(kind, axis)| {
            format!(
                r#"<Primitive><name>"{kind}"</name><nodeID>""</nodeID><referenceFrame>"WORLD"</referenceFrame><axis>{axis}</axis></Primitive>
"#
            )
        })
        .collect();
    format!(
        r#"<SimpleJoint>
        <name>"{name}"</name>
        <nodeID>"{name}"</nodeID>
        <status>""</status>
        <base><JointSide><name>""</name><connection><Frame ref="{base}"></Frame></connection></JointSide></base>
        <follower><JointSide><name>""</name><connection><Frame ref="{follower}"></Frame></connection></JointSide></follower>
        <primitives>
{prims}        </primitives>
      </SimpleJoint>
"#
    )
}

fn ground(r: u32) -> String {
    format!(
        r#"<Ground><name>"RootGround"</name><nodeID>"RootGround"</nodeID><status>""</status><frame>
{}</frame></Ground>
"#,
        frame("CS1", Some(r), "0,0,0", "mm", IDENTITY)
    )
}

fn system(bodies: &[String], joints: &[String], grounds: &[String], subsystems: &[String]) -> String {
    format!(
        "<bodies>\n{}</bodies>\n<joints>\n{}</joints>\n<grounds>\n{}</grounds>\n<subsystems>\n{}</subsystems>\n<connectionPorts></connectionPorts>\n<id>0</id>\n",
        bodies.concat(),
        joints.concat(),
        grounds.concat(),
        subsystems.concat()
    )
}

fn subsystem(name: &str, content: &str) -> String {
    format!("<Subsystem>\n<name>\"{name}\"</name>\n<nodeID>\"{name}\"</nodeID>\n<status>\"\"</status>\n{content}</Subsystem>\n")
}

fn document(container: &str, content: &str) -> String {
    format!(
        r#"<?xml version="1.0" encoding="UTF-8" standalone="no" ?>
<PhysicalModelingXMLFile>
  <formatVersion>"1.0.4"</formatVersion>
  <internalVersion>1</internalVersion>
  <createdUsing>"SimMechanics Link Version 4.0"</createdUsing>
  <createdFrom>"Pro/E Wildfire Creo 2.0 - 2012360"</createdFrom>
  <createdOn>"11/10/09||14:08:16"</createdOn>
  <createdBy>"someone"</createdBy>
  <name>"ASM"</name>
  <{container}>
    <name>"ASM"</name>
    <nodeID>"ASM"</nodeID>
{content}  </{container}>
</PhysicalModelingXMLFile>
"#
    )
}

/// Two bodies, a ground welded to the first, a revolute between them.
fn two_bodies(container: &str) -> String {
    document(
        container,
        &system(
            &[simple_body("A", 1, "10,0,0"), simple_body("B", 2, "20,0,0")],
            &[joint("RootGround--A", 9, 1, &[("weld", "0.57735,0.57735,0.57735")]), joint("A--B", 1, 2, &[("revolute", "0,0,1")])],
            &[ground(9)],
            &[],
        ),
    )
}

fn ok(xml: &str) -> (Model, Vec<Warning>) {
    match parse("t.xml", xml.as_bytes()) {
        Ok(r) => r,
        Err(e) => panic!("unexpected error: {e}"),
    }
}

fn fails(xml: &str) -> XmlError {
    match parse("t.xml", xml.as_bytes()) {
        Ok(_) => panic!("expected an error"),
        Err(e) => e,
    }
}

/// 1-based line of the first occurrence of `needle` in `xml`.
fn line_of(xml: &str, needle: &str) -> u32 {
    let at = xml.find(needle).expect("needle present");
    xml[..at].matches('\n').count() as u32 + 1
}

// ----- happy paths -----------------------------------------------------------------------------

#[test]
fn reads_header_bodies_joints_grounds() {
    let xml = two_bodies("SimMechanics");
    let (m, warnings) = ok(&xml);
    assert!(warnings.is_empty(), "{warnings:?}");
    assert_eq!(m.name, "ASM");
    assert_eq!(m.source.file, "t.xml");
    assert_eq!(m.source.container, "SimMechanics");
    assert_eq!(m.source.format_version, "1.0.4");
    assert_eq!(m.source.created_using, "SimMechanics Link Version 4.0");
    assert_eq!(m.source.created_from, "Pro/E Wildfire Creo 2.0 - 2012360");
    assert_eq!(m.source.created_on, "11/10/09||14:08:16");
    assert_eq!(m.source.created_by, "someone");
    assert_eq!(m.length_scale, 1e-3);
    assert_eq!((m.bodies.len(), m.joints.len(), m.grounds.len(), m.frames.len()), (2, 2, 1, 7));

    let a = &m.bodies[0];
    assert_eq!(a.cad_name, "A");
    assert_eq!(a.mass, 1.5);
    assert_eq!(a.inertia_cg[(1, 1)], 2.0);
    assert_eq!(a.volume, Some(1000.0 * 1e-9));
    assert_eq!(a.surface_area, None);
    assert_eq!(a.geometry_file.as_deref(), Some("A_prt.stl"));
    assert_eq!(m.frame(a.cg).name, "CG");
    assert_eq!(m.frame(a.cs1).name, "CS1");
    assert_eq!(a.frames.len(), 3);
    assert!(a.subsystem_path.is_empty());
    let cg = m.frame(a.cg);
    assert_eq!(cg.owner, FrameOwner::Body(crate::pipeline::ir::BodyId(0)));
    assert!((cg.pose.translation.vector - Vector3::new(0.01, 0.0, 0.0)).norm() < 1e-15);

    let g = &m.grounds[0];
    assert_eq!(g.name, "RootGround");
    assert_eq!(m.frame(g.frame).owner, FrameOwner::Ground(crate::pipeline::ir::GroundId(0)));
    assert_eq!(m.frame(g.frame).ref_id, Some(9));

    let weld = &m.joints[0];
    assert!(weld.is_weld());
    assert_eq!(weld.base, g.frame, "a joint may name a ground's frame");
    let rev = &m.joints[1];
    assert_eq!(rev.cad_name, "A--B");
    assert_eq!(m.frame(rev.base).ref_id, Some(1));
    assert_eq!(m.frame(rev.follower).ref_id, Some(2));
    assert_eq!(rev.primitives[0].kind, PrimitiveKind::Revolute);
    assert_eq!(rev.primitives[0].axis_world, Vector3::new(0.0, 0.0, 1.0));
}

#[test]
fn source_locations_point_at_start_tags() {
    let xml = two_bodies("SimMechanics");
    let (m, _) = ok(&xml);
    let body_line = line_of(&xml, "<Body>");
    assert_eq!(m.bodies[0].loc.file, "t.xml");
    assert_eq!((m.bodies[0].loc.line, m.bodies[0].loc.column), (body_line, 1));
    let cs1_line = line_of(&xml, "<name>\"CS1\"") - 1;
    assert_eq!(m.frame(m.bodies[0].cs1).loc.line, cs1_line);
    let joint_line = line_of(&xml, "<name>\"A--B\"") - 1;
    assert_eq!(m.joints[1].loc.line, joint_line);
    assert_eq!(m.joints[1].primitives[0].loc.line, line_of(&xml, "<Primitive><name>\"revolute\""));
    assert_eq!(m.joints[1].primitives[0].loc.column, 1);
    assert_eq!(m.grounds[0].loc.line, line_of(&xml, "<Ground>"));
    for f in &m.frames {
        assert!(f.loc.line > 0 && f.loc.column > 0);
    }
}

#[test]
fn simscape_multibody_container() {
    let (m, _) = ok(&two_bodies("SimscapeMultibody"));
    assert_eq!(m.source.container, "SimscapeMultibody");
    assert_eq!(m.bodies.len(), 2);
}

#[test]
fn imperial_units_convert_exactly() {
    let f = |name: &str, r: Option<u32>| frame(name, r, "1,2,-1", "in", IDENTITY);
    let b = format!(
        r#"<Body><name>"P"</name><nodeID>"39"</nodeID>
        <mass>1</mass><massUnits>"lbm"</massUnits>
        <inertia>1,0,0,0,1,0,0,0,1</inertia><inertiaUnits>"lbm*in^2"</inertiaUnits>
        <volume>1</volume><volumeUnits>"in^3"</volumeUnits>
        <surfaceArea>1</surfaceArea><surfaceAreaUnits>"in^2"</surfaceAreaUnits>
        <frames>{}{}</frames><geometryFileName>""</geometryFileName></Body>"#,
        f("CG", None),
        f("CS1", Some(1))
    );
    let (m, _) = ok(&document("SimMechanics", &system(&[b], &[], &[], &[])));
    let body = &m.bodies[0];
    assert_eq!(m.length_scale, 0.0254);
    assert_eq!(body.mass, 0.45359237);
    assert_eq!(body.inertia_cg[(0, 0)], 0.45359237 * (0.0254 * 0.0254));
    assert_eq!(body.inertia_cg[(0, 1)], 0.0);
    assert_eq!(body.volume, Some(0.0254 * 0.0254 * 0.0254));
    assert_eq!(body.surface_area, Some(0.0254 * 0.0254));
    assert_eq!(body.geometry_file, None, "empty geometryFileName is None");
    let t = m.frame(body.cs1).pose.translation.vector;
    assert_eq!(t, Vector3::new(0.0254, 2.0 * 0.0254, -0.0254));
}

#[test]
fn mixed_length_units_convert_each_frame_and_scale_comes_from_the_first() {
    let b = body("A", "1", &[frame("CG", None, "1,0,0", "m", IDENTITY), frame("CS1", None, "100,0,0", "cm", IDENTITY)]);
    let (m, _) = ok(&document("SimMechanics", &system(&[b], &[], &[], &[])));
    assert_eq!(m.length_scale, 1.0);
    assert!((m.frame(m.bodies[0].cs1).pose.translation.x - 1.0).abs() < 1e-15);
}

#[test]
fn inertia_keeps_all_nine_entries_row_major() {
    let xml = two_bodies("SimMechanics").replacen("<inertia>1,0,0,0,2,0,0,0,3</inertia>", "<inertia>1,2,3,4,5,6,7,8,9</inertia>", 1);
    let (m, _) = ok(&xml);
    let i = m.bodies[0].inertia_cg;
    assert_eq!((i[(0, 1)], i[(0, 2)], i[(1, 0)], i[(2, 1)]), (2.0, 3.0, 4.0, 8.0));
}

#[test]
fn orientation_is_read_as_columns() {
    // Rotated 90 degrees about z: the frame's x axis is world y, its y axis is world -x.
    let b = body("A", "1", &[frame("CG", None, "0,0,0", "mm", "0,1,0,-1,0,0,0,0,1"), frame("CS1", None, "0,0,0", "mm", IDENTITY)]);
    let (m, warnings) = ok(&document("SimMechanics", &system(&[b], &[], &[], &[])));
    assert!(warnings.is_empty());
    let pose = m.frame(m.bodies[0].cg).pose;
    let x_axis = pose.rotation * Vector3::x();
    let y_axis = pose.rotation * Vector3::y();
    assert!((x_axis - Vector3::y()).norm() < 1e-12, "{x_axis}");
    assert!((y_axis + Vector3::x()).norm() < 1e-12, "{y_axis}");
    // p_world = pose * p_frame
    let p = pose * Point3::new(1.0, 0.0, 0.0);
    assert!((p.coords - Vector3::y()).norm() < 1e-12);
}

#[test]
fn cad_noise_is_orthonormalised_silently_and_mirrors_warn() {
    let noisy = "-0.319989,0.947421,0,0,0,1,0.947421,0.319989,0";
    let mirrored = "1,0,0,0,1,0,0,0,-1";
    let b = body("A", "1", &[frame("CG", None, "0,0,0", "mm", noisy), frame("CS1", None, "0,0,0", "mm", mirrored)]);
    let (m, warnings) = ok(&document("SimMechanics", &system(&[b], &[], &[], &[])));
    let r = m.frame(m.bodies[0].cg).pose.rotation.to_rotation_matrix();
    assert!((r.matrix().determinant() - 1.0).abs() < 1e-12);
    assert!((r * Vector3::x() - Vector3::new(-0.319989, 0.947421, 0.0)).norm() < 1e-5);
    assert_eq!(warnings.len(), 1, "{warnings:?}");
    assert_eq!(warnings[0].code, "frame-not-orthonormal");
    assert!(warnings[0].message.contains("mirrored"), "{}", warnings[0].message);
    assert!(warnings[0].location.starts_with("t.xml:"), "{}", warnings[0].location);
    assert!(warnings[0].location.contains("Frame \"CS1\""), "{}", warnings[0].location);
}

#[test]
fn nested_subsystems_and_cross_subsystem_refs() {
    // The parent's joint names frame 2, which lives in a body two subsystems down.
    let inner = subsystem("INNER", &system(&[simple_body("C", 2, "0,5,0")], &[], &[], &[]));
    let outer = subsystem("OUTER", &system(&[simple_body("B", 3, "0,0,5")], &[joint("B--C", 3, 4, &[("weld", "1,1,1")])], &[], &[inner]));
    // A frame referenced before it is defined is fine too (ref 4 is in the last body).
    let last = simple_body("D", 4, "1,1,1");
    let xml = document(
        "SimMechanics",
        &system(
            &[simple_body("A", 1, "0,0,0")],
            &[joint("A--C", 1, 2, &[("revolute", "1,0,0")])],
            &[ground(9)],
            &[outer, subsystem("LAST", &system(&[last], &[], &[], &[]))],
        ),
    );
    let (m, _) = ok(&xml);
    let names: Vec<_> = m.bodies.iter().map(|b| b.cad_name.as_str()).collect();
    assert_eq!(names, ["A", "B", "C", "D"]);
    assert!(m.bodies[0].subsystem_path.is_empty());
    assert_eq!(m.bodies[1].subsystem_path, ["OUTER"]);
    assert_eq!(m.bodies[2].subsystem_path, ["OUTER", "INNER"]);
    assert_eq!(m.bodies[3].subsystem_path, ["LAST"]);
    let j = &m.joints[0];
    assert_eq!(j.cad_name, "A--C");
    assert!(j.subsystem_path.is_empty());
    assert_eq!(m.frame(j.follower).owner, FrameOwner::Body(crate::pipeline::ir::BodyId(2)));
    let j = &m.joints[1];
    assert_eq!(j.subsystem_path, ["OUTER"]);
    assert_eq!(m.frame(j.follower).owner, FrameOwner::Body(crate::pipeline::ir::BodyId(3)));
}

#[test]
fn multiple_primitives_and_material() {
    let b = simple_body("A", 1, "0,0,0").replace(
        "</Body>",
        "<MaterialProp><color>0.5,0.25,1</color><ambient>0.4</ambient><specular>0.9</specular><transparency>0.1</transparency></MaterialProp></Body>",
    );
    let prims = [("prismatic", "1,0,0"), ("prismatic", "0,1,0"), ("PRISMATIC", "0,0,1"), ("Spherical", "0,0,1")];
    let xml = document("SimMechanics", &system(&[b, simple_body("B", 2, "0,0,0")], &[joint("A--B", 1, 2, &prims)], &[], &[]));
    let (m, _) = ok(&xml);
    let kinds: Vec<_> = m.joints[0].primitives.iter().map(|p| p.kind).collect();
    use PrimitiveKind::*;
    assert_eq!(kinds, [Prismatic, Prismatic, Prismatic, Spherical]);
    let mat = m.bodies[0].material.as_ref().expect("material");
    assert_eq!(mat.color, [0.5, 0.25, 1.0]);
    assert_eq!((mat.transparency, mat.specular), (0.1, 0.9));
    assert!(m.bodies[1].material.is_none());
}

#[test]
fn elements_are_found_by_name_not_position_and_unknown_ones_skipped() {
    let f = r#"<Frame ref="1"><orientationReferenceFrame>"WORLD"</orientationReferenceFrame>
        <surprise><name>"NOT THIS"</name></surprise><orientation>1,0,0,0,1,0,0,0,1</orientation>
        <positionUnits>"m"</positionUnits><position>1,2,3</position><nodeID>"x"</nodeID><name>"CS1"</name></Frame>"#;
    let b = format!(
        r#"<Body><frames>{}{f}</frames><inertiaUnits>"kg*m^2"</inertiaUnits><inertia>0,0,0,0,0,0,0,0,0</inertia>
        <massUnits>"kg"</massUnits><mass>0</mass><nodeID>"1"</nodeID><name>"A"</name><id>7</id></Body>"#,
        frame("CG", None, "0,0,0", "m", IDENTITY)
    );
    let (m, _) = ok(&document("SimMechanics", &system(&[b], &[], &[], &[])));
    let cs1 = m.frame(m.bodies[0].cs1);
    assert_eq!(cs1.name, "CS1");
    assert_eq!(cs1.display_name, "");
    assert_eq!(cs1.pose.translation.vector, Vector3::new(1.0, 2.0, 3.0));
}

#[test]
fn strings_unquote_exactly_once_and_decode_entities() {
    let xml = two_bodies("SimMechanics").replacen("<name>\"A\"</name>", "<name>\"\"A&amp;B\"\"</name>", 1).replacen(
        "<createdBy>\"someone\"</createdBy>",
        "<createdBy>\"\"</createdBy>",
        1,
    );
    let (m, _) = ok(&xml);
    assert_eq!(m.bodies[0].cad_name, "\"A&B\"");
    assert_eq!(m.source.created_by, "");
}

#[test]
fn three_digit_exponents() {
    let xml = two_bodies("SimMechanics").replacen("<mass>1.5</mass>", "<mass>6.63933e-005</mass>", 1);
    let (m, _) = ok(&xml);
    assert_eq!(m.bodies[0].mass, 6.63933e-5);
}

#[test]
fn bom_comments_and_sniffing() {
    let xml = format!(
        "\u{feff}<!-- exported --><?pi x?>{}",
        two_bodies("SimMechanics").replacen(r#"<?xml version="1.0" encoding="UTF-8" standalone="no" ?>"#, "", 1,)
    );
    assert!(is_physical_modeling_xml(xml.as_bytes()));
    let (m, _) = ok(&xml);
    assert_eq!(m.bodies.len(), 2);
    assert!(is_physical_modeling_xml(two_bodies("SimMechanics").as_bytes()));
    assert!(!is_physical_modeling_xml(b"<SimMechanicsImportXML/>"));
    assert!(!is_physical_modeling_xml(b"solid x\nfacet normal 0 0 1"));
    assert!(!is_physical_modeling_xml(b""));
    assert!(!is_physical_modeling_xml(b"<?xml version=\"1.0\"?><!-- <PhysicalModelingXMLFile> --><other/>"));
}

// ----- errors ----------------------------------------------------------------------------------

#[test]
fn second_generation_is_rejected() {
    let e = fails(
        "<?xml version=\"1.0\"?>\n<SimMechanicsImportXML version=\"1.0\" xmlns=\"urn:mathworks:simmechanics:import\">\n</SimMechanicsImportXML>",
    );
    assert_eq!(e.kind, XmlErrorKind::SecondGeneration);
    assert_eq!((e.line, e.column), (2, 1));
    assert!(e.to_string().contains("second-generation"), "{e}");
}

#[test]
fn other_roots_are_rejected() {
    let e = fails("<svg></svg>");
    assert_eq!(e.kind, XmlErrorKind::NotPhysicalModelingXml { root: "svg".into() });
    let e = fails("<PhysicalModelingXMLFile><name>\"x\"</name></PhysicalModelingXMLFile>");
    assert_eq!(e.kind, XmlErrorKind::NoContainer);
}

#[test]
fn dangling_ref_names_joint_and_ref_with_position() {
    let xml = two_bodies("SimMechanics").replace(r#"<Frame ref="2"></Frame>"#, r#"<Frame ref="42"></Frame>"#);
    let e = fails(&xml);
    assert_eq!(e.kind, XmlErrorKind::DanglingRef { ref_id: 42 });
    let at = xml.find(r#"<Frame ref="42">"#).expect("present");
    let line = xml[..at].matches('\n').count() as u32 + 1;
    let column = (at - xml[..at].rfind('\n').map_or(0, |i| i + 1)) as u32 + 1;
    assert_eq!((e.line, e.column), (line, column));
    assert!(e.element.starts_with("SimpleJoint \"A--B\" (nodeID \"A--B\")"), "{}", e.element);
    assert!(e.element.ends_with("Frame ref=\"42\""), "{}", e.element);
    let text = e.to_string();
    assert!(text.starts_with(&format!("t.xml:{line}:{column}: in SimpleJoint \"A--B\"")), "{text}");
    assert!(text.contains("ref=\"42\""), "{text}");
}

#[test]
fn duplicate_ref_is_an_error() {
    let xml = document("SimMechanics", &system(&[simple_body("A", 1, "0,0,0"), simple_body("B", 1, "0,0,0")], &[], &[], &[]));
    let e = fails(&xml);
    assert!(matches!(&e.kind, XmlErrorKind::DuplicateRef { ref_id: 1, first } if first.contains("Body")), "{e}");
}

#[test]
fn unknown_unit_error() {
    let xml = two_bodies("SimMechanics").replacen("<positionUnits>\"mm\"</positionUnits>", "<positionUnits>\"furlong\"</positionUnits>", 1);
    let e = fails(&xml);
    assert_eq!(e.kind, XmlErrorKind::UnknownUnit { quantity: "length", unit: "furlong".into(), allowed: "mm, cm, m, in, ft" });
    assert_eq!(e.line, line_of(&xml, "furlong"));
    assert_eq!(e.element, "Body \"A\" (nodeID \"A\") / frames / Frame \"CG\" (nodeID \"CG-id0\") / positionUnits");
    assert!(e.to_string().ends_with(
        ": in Body \"A\" (nodeID \"A\") / frames / Frame \"CG\" (nodeID \"CG-id0\") / positionUnits: unknown length unit \"furlong\" (expected one of mm, cm, m, in, ft)"
    ), "{e}");
    let xml = two_bodies("SimMechanics").replacen("\"kg*m^2\"", "\"stone*m^2\"", 1);
    assert!(matches!(fails(&xml).kind, XmlErrorKind::UnknownUnit { quantity: "inertia", .. }));
}

#[test]
fn non_finite_and_bad_numbers_are_rejected() {
    for (bad, non_finite) in [("NaN", true), ("nan", true), ("inf", true), ("-1.#IND", true), ("1.2.3", false), ("", false), ("1e", false)]
    {
        let xml = two_bodies("SimMechanics").replacen("<position>10,0,0</position>", &format!("<position>10,{bad},0</position>"), 1);
        let e = fails(&xml);
        match e.kind {
            XmlErrorKind::NonFinite { ref text } => {
                assert!(non_finite && text == bad, "{bad}: {e}")
            }
            XmlErrorKind::BadNumber { ref text } => {
                assert!(!non_finite && text == bad, "{bad}: {e}")
            }
            _ => panic!("{bad}: {e}"),
        }
        assert_eq!(e.line, line_of(&xml, "<position>10,"));
        assert!(e.element.ends_with("/ position"), "{}", e.element);
    }
    let xml = two_bodies("SimMechanics").replacen("<mass>1.5</mass>", "<mass>NaN</mass>", 1);
    assert!(matches!(fails(&xml).kind, XmlErrorKind::NonFinite { .. }));
}

#[test]
fn wrong_counts_are_rejected() {
    let xml = two_bodies("SimMechanics").replacen("<position>10,0,0</position>", "<position>10,0</position>", 1);
    assert_eq!(fails(&xml).kind, XmlErrorKind::WrongCount { expected: 3, got: 2 });
    let xml = two_bodies("SimMechanics").replacen("<inertia>1,0,0,0,2,0,0,0,3</inertia>", "<inertia>1,0,0,0,2,0,0,0,3,4</inertia>", 1);
    assert_eq!(fails(&xml).kind, XmlErrorKind::WrongCount { expected: 9, got: 10 });
    let xml = two_bodies("SimMechanics").replacen("<axis>0,0,1</axis>", "<axis></axis>", 1);
    assert_eq!(fails(&xml).kind, XmlErrorKind::WrongCount { expected: 3, got: 0 });
}

#[test]
fn unsupported_frames_orientations_and_primitives() {
    let base = two_bodies("SimMechanics");
    let e = fails(&base.replacen("<positionReferenceFrame>\"WORLD\"", "<positionReferenceFrame>\"CS1 of BASE\"", 1));
    assert_eq!(
        e.kind,
        XmlErrorKind::UnsupportedReferenceFrame {
            value: "CS1 of BASE".into(),
            expected: "WORLD, ADJOINING or the name of a frame of the same body",
        }
    );
    assert_eq!(e.line, line_of(&base, "<positionReferenceFrame>"));
    // A ground's frame has no sibling to name.
    let ground_frame = base.find("<Ground>").expect("ground");
    let (head, tail) = base.split_at(ground_frame);
    let grounded = format!("{head}{}", tail.replacen("<orientationReferenceFrame>\"WORLD\"", "<orientationReferenceFrame>\"CS1\"", 1));
    let e = fails(&grounded);
    assert_eq!(e.kind, XmlErrorKind::UnsupportedReferenceFrame { value: "CS1".into(), expected: "WORLD or ADJOINING" });
    assert_eq!(e.line, line_of(&grounded, "<orientationReferenceFrame>\"CS1\""));
    assert!(e.element.starts_with("Ground \"RootGround\""), "{e}");
    let e = fails(&base.replacen(
        "<orientation>1,0,0,0,1,0,0,0,1</orientation>\n            <orientationType>\"3x3 Transform\"",
        "<orientation>1,0,0,0</orientation>\n            <orientationType>\"Quaternion\"",
        1,
    ));
    assert_eq!(e.kind, XmlErrorKind::UnsupportedOrientationType { value: "Quaternion".into() });
    let e = fails(&base.replacen("\"revolute\"", "\"planar\"", 1));
    assert_eq!(e.kind, XmlErrorKind::UnknownPrimitive { name: "planar".into() });
    let e = fails(&base.replacen("<referenceFrame>\"WORLD\"", "<referenceFrame>\"CS2\"", 1));
    assert_eq!(e.kind, XmlErrorKind::UnsupportedReferenceFrame { value: "CS2".into(), expected: "WORLD, BASE or FOLLOWER" });
    let e = fails(&base.replacen("<orientationUnits>\"rad\"", "<orientationUnits>\"grad\"", 1));
    assert!(matches!(e.kind, XmlErrorKind::UnknownUnit { quantity: "angle", .. }), "{e}");
    // Missing reference-frame elements mean WORLD.
    let (m, _) = ok(&base.replace("<positionOrigin>\"WORLD\"</positionOrigin>", ""));
    assert_eq!(m.bodies.len(), 2);
}

// ----- frames relative to other frames -----------------------------------------------------

/// Rz(90): x -> y, y -> -x (columns: the frame's axes).
const RZ90: &str = "0,1,0,-1,0,0,0,0,1";
/// Rx(90): y -> z, z -> -y.
const RX90: &str = "1,0,0,0,0,1,0,-1,0";

fn rot(columns: &str) -> nalgebra::Rotation3<f64> {
    let v: Vec<f64> = columns.split(',').map(|x| x.parse().expect("number")).collect();
    nalgebra::Rotation3::from_matrix_unchecked(nalgebra::Matrix3::from_column_slice(&v))
}

fn assert_pose(m: &Model, id: crate::pipeline::ir::FrameId, p_mm: [f64; 3], r: nalgebra::Rotation3<f64>) {
    let f = m.frame(id);
    let p = Vector3::from(p_mm) * 1e-3;
    assert!((f.pose.translation.vector - p).norm() < 1e-15, "{}: {} vs {p}", f.name, f.pose.translation.vector);
    let got = f.pose.rotation.to_rotation_matrix();
    assert!((got.matrix() - r.matrix()).amax() < 1e-15, "{}: {got} vs {r}", f.name);
}

/// The body's frame called `name`.
fn named(m: &Model, body: usize, name: &str) -> crate::pipeline::ir::FrameId {
    let b = &m.bodies[body];
    *b.frames.iter().find(|&&f| m.frame(f).name == name).expect("frame")
}

fn one_body(frames: &[String]) -> String {
    document("SimMechanics", &system(&[body("A", "A", frames)], &[], &[], &[]))
}

#[test]
fn frame_chain_cs2_cg_cs1_world() {
    let rel = |r: &'static str| [r; 3];
    let xml = one_body(&[
        frame_in("CG", None, "5,0,0", "mm", IDENTITY, rel("CS1")),
        frame("CS1", None, "10,0,0", "mm", RZ90),
        frame_in("CS2", None, "0,0,2", "mm", RX90, rel("CG")),
    ]);
    let (m, warnings) = ok(&xml);
    assert!(warnings.is_empty());
    assert_pose(&m, named(&m, 0, "CS1"), [10.0, 0.0, 0.0], rot(RZ90));
    assert_pose(&m, named(&m, 0, "CG"), [10.0, 5.0, 0.0], rot(RZ90));
    assert_pose(&m, named(&m, 0, "CS2"), [10.0, 5.0, 2.0], rot(RZ90) * rot(RX90));
}

#[test]
fn position_origin_axes_and_orientation_from_different_frames() {
    let xml = one_body(&[
        // Starts at CS2's origin, components in CS1's axes, orientation relative to CS1.
        frame_in("CG", None, "1,0,0", "mm", IDENTITY, ["CS2", "CS1", "CS1"]),
        frame("CS1", None, "0,0,0", "mm", RZ90),
        frame("CS2", None, "100,0,0", "mm", RX90),
        // Position relative to CS1, orientation relative to CS2.
        frame_in("CS3", None, "0,0,3", "mm", RZ90, ["CS1", "CS1", "CS2"]),
        // Origin WORLD, axes CS2, orientation CS1.
        frame_in("CS4", None, "0,1,0", "m", IDENTITY, ["WORLD", "CS2", "CS1"]),
    ]);
    let (m, _) = ok(&xml);
    assert_pose(&m, named(&m, 0, "CG"), [100.0, 1.0, 0.0], rot(RZ90));
    assert_pose(&m, named(&m, 0, "CS3"), [0.0, 0.0, 3.0], rot(RX90) * rot(RZ90));
    assert_pose(&m, named(&m, 0, "CS4"), [0.0, 0.0, 1000.0], rot(RZ90));
}

/// A, B joined by a joint from A's CS2 (ref 1) to B's CS2 (ref 2), which is given ADJOINING
/// (turned Rz(90) more); B's CG is given relative to its CS2.
fn adjoining_pair(prims: &[(&str, &str)]) -> String {
    let adj = ["ADJOINING"; 3];
    let a = body(
        "A",
        "A",
        &[
            frame("CG", None, "0,0,0", "mm", IDENTITY),
            frame("CS1", None, "0,0,0", "mm", IDENTITY),
            frame("CS2", Some(1), "20,30,0", "mm", RZ90),
        ],
    );
    let b = body(
        "B",
        "B",
        &[
            frame_in("CG", None, "10,0,0", "mm", IDENTITY, ["CS2"; 3]),
            frame("CS1", None, "0,0,0", "mm", IDENTITY),
            frame_in("CS2", Some(2), "0,0,0", "mm", RZ90, adj),
        ],
    );
    document("SimMechanics", &system(&[a, b], &[joint("A--B", 1, 2, prims)], &[], &[]))
}

#[test]
fn adjoining_follower_frame_is_placed_from_the_base_frame_and_axes_in_joint_frames() {
    let xml = adjoining_pair(&[("revolute", "1,0,0"), ("prismatic", "1,0,0"), ("prismatic", "0,0,1")])
        .replacen("<referenceFrame>\"WORLD\"", "<referenceFrame>\"BASE\"", 1)
        .replacen("<referenceFrame>\"WORLD\"", "<referenceFrame>\"FOLLOWER\"", 1);
    let (m, _) = ok(&xml);
    let rz180 = rot(RZ90) * rot(RZ90);
    assert_pose(&m, named(&m, 1, "CS2"), [20.0, 30.0, 0.0], rz180);
    // B's CG: 10 mm along B's CS2 x axis, which points along -x.
    assert_pose(&m, named(&m, 1, "CG"), [10.0, 30.0, 0.0], rz180);
    let axes: Vec<_> = m.joints[0].primitives.iter().map(|p| p.axis_world).collect();
    assert!((axes[0] - Vector3::new(0.0, 1.0, 0.0)).norm() < 1e-15, "BASE: {}", axes[0]);
    assert!((axes[1] - Vector3::new(-1.0, 0.0, 0.0)).norm() < 1e-15, "FOLLOWER: {}", axes[1]);
    assert_eq!(axes[2], Vector3::new(0.0, 0.0, 1.0), "WORLD");
}

#[test]
fn frame_reference_errors_name_frames_and_lines() {
    // A cycle inside one body: CG -> CS1 -> CG.
    let xml = one_body(&[
        frame_in("CG", None, "0,0,0", "mm", IDENTITY, ["CS1", "WORLD", "WORLD"]),
        frame_in("CS1", None, "0,0,0", "mm", IDENTITY, ["WORLD", "WORLD", "CG"]),
    ]);
    let e = fails(&xml);
    assert_eq!(e.line, line_of(&xml, "<positionOrigin>\"CS1\""));
    assert!(
        e.to_string().ends_with("Frame \"CG\" (nodeID \"CG-id0\") / positionOrigin: frame references form a cycle: CG -> CS1 -> CG"),
        "{e}"
    );
    // A frame relative to itself.
    let xml =
        one_body(&[frame("CG", None, "0,0,0", "mm", IDENTITY), frame_in("CS1", None, "0,0,0", "mm", IDENTITY, ["WORLD", "CS1", "WORLD"])]);
    let e = fails(&xml);
    assert_eq!(e.kind, XmlErrorKind::FrameCycle { cycle: "CS1 -> CS1".into() });
    // Two joint frames ADJOINING each other.
    let xml = adjoining_pair(&[("revolute", "0,0,1")]).replacen(
        "<positionOrigin>\"WORLD\"</positionOrigin>\n            <positionReferenceFrame>\"WORLD\"</positionReferenceFrame>\n            <positionUnits>\"mm\"</positionUnits>\n            <orientation>0,1,0",
        "<positionOrigin>\"ADJOINING\"</positionOrigin>\n            <positionReferenceFrame>\"WORLD\"</positionReferenceFrame>\n            <positionUnits>\"mm\"</positionUnits>\n            <orientation>0,1,0",
        1,
    );
    let e = fails(&xml);
    assert_eq!(e.kind, XmlErrorKind::FrameCycle { cycle: "CS2 -> CS2 of body \"B\" -> CS2".into() });
    assert_eq!(e.line, line_of(&xml, "<positionOrigin>\"ADJOINING\""));
    // A name the body does not have.
    let xml =
        one_body(&[frame_in("CG", None, "0,0,0", "mm", IDENTITY, ["WORLD", "CS9", "WORLD"]), frame("CS1", None, "0,0,0", "mm", IDENTITY)]);
    let e = fails(&xml);
    assert_eq!(e.line, line_of(&xml, "<positionReferenceFrame>\"CS9\""));
    assert!(
        e.to_string().ends_with(
            "Frame \"CG\" (nodeID \"CG-id0\") / positionReferenceFrame: frame \"CG\" refers to frame \"CS9\", which its body does not have"
        ),
        "{e}"
    );
    // ADJOINING on a frame no joint uses.
    let xml = one_body(&[
        frame("CG", None, "0,0,0", "mm", IDENTITY),
        frame_in("CS1", None, "0,0,0", "mm", IDENTITY, ["WORLD", "WORLD", "ADJOINING"]),
    ]);
    let e = fails(&xml);
    assert_eq!(e.line, line_of(&xml, "<orientationReferenceFrame>\"ADJOINING\""));
    assert_eq!(e.kind.to_string(), "frame \"CS1\" refers to ADJOINING, but 0 joints use it (expected exactly one)");
    // ... or that two joints use.
    let xml =
        adjoining_pair(&[("revolute", "0,0,1")]).replace("</joints>", &format!("{}</joints>", joint("A--B 2", 1, 2, &[("weld", "1,1,1")])));
    let e = fails(&xml);
    assert_eq!(e.kind, XmlErrorKind::AdjoiningNotOneJoint { frame: "CS2".into(), joints: 2 });
}

#[test]
fn structural_errors() {
    let base = two_bodies("SimMechanics");
    let e = fails(&base.replacen("<name>\"CG\"</name>", "<name>\"CGX\"</name>", 1));
    assert_eq!(e.kind, XmlErrorKind::MissingBodyFrame { name: "CG" });
    assert_eq!(e.element, "Body \"A\" (nodeID \"A\")");
    let e = fails(&base.replacen("<name>\"CS1\"</name>", "<name>\"CSX\"</name>", 1));
    assert_eq!(e.kind, XmlErrorKind::MissingBodyFrame { name: "CS1" });
    let e = fails(&base.replacen("<mass>1.5</mass>", "", 1));
    assert_eq!(e.kind, XmlErrorKind::MissingElement { name: "mass" });
    let e = fails(&base.replacen(
        "<Primitive><name>\"revolute\"</name><nodeID>\"\"</nodeID><referenceFrame>\"WORLD\"</referenceFrame><axis>0,0,1</axis></Primitive>",
        "",
        1,
    ));
    assert_eq!(e.kind, XmlErrorKind::NoPrimitives);
    let e = fails(&base.replacen(r#"<Frame ref="2"></Frame>"#, "<Frame></Frame>", 1));
    assert_eq!(e.kind, XmlErrorKind::MissingAttribute { name: "ref" });
    let e = fails(&base.replacen(r#"<Frame ref="2"></Frame>"#, r#"<Frame ref="two"></Frame>"#, 1));
    assert_eq!(e.kind, XmlErrorKind::BadNumber { text: "two".into() });
    let doubled = base.replacen("<SimMechanics>", "<SimMechanics></SimMechanics><SimMechanics>", 1);
    assert_eq!(fails(&doubled).kind, XmlErrorKind::MultipleContainers);
}

#[test]
fn deep_nesting_is_an_error_not_a_stack_overflow() {
    let mut content = system(&[], &[], &[], &[]);
    for i in 0..200 {
        content = system(&[], &[], &[], &[subsystem(&format!("S{i}"), &content)]);
    }
    // 200 subsystems nest 400 elements deep: the element tree's nesting bound (256) refuses
    // it before the lowering's subsystem bound (64) would.
    let kind = fails(&document("SimMechanics", &content)).kind;
    assert!(
        matches!(&kind, XmlErrorKind::TooDeep { .. })
            || matches!(&kind, XmlErrorKind::Syntax { message } if message.contains("nested more than 256")),
        "{kind:?}"
    );
    // 100 subsystems (200 levels) pass the element tree and stop at the subsystem bound.
    let mut content = system(&[], &[], &[], &[]);
    for i in 0..100 {
        content = system(&[], &[], &[], &[subsystem(&format!("S{i}"), &content)]);
    }
    assert!(matches!(fails(&document("SimMechanics", &content)).kind, XmlErrorKind::TooDeep { .. }));
}

#[test]
fn malformed_xml_is_an_error_at_every_truncation() {
    let xml = two_bodies("SimMechanics");
    let root_end = xml.find("</PhysicalModelingXMLFile>").expect("present");
    // Every cut before the root is closed must be an error, never a panic.
    for cut in 0..root_end {
        let e = match parse("t.xml", &xml.as_bytes()[..cut]) {
            Ok(_) => panic!("truncated at {cut} parsed"),
            Err(e) => e,
        };
        assert!(e.line >= 1, "cut {cut}: {e}");
    }
    let e = fails(&xml[..xml.len() / 2]);
    assert!(matches!(e.kind, XmlErrorKind::Syntax { .. }), "{e}");
    assert!(e.to_string().contains("not closed"), "{e}");
    let e = fails(&xml.replacen("</mass>", "</massX>", 1));
    assert!(matches!(e.kind, XmlErrorKind::Syntax { .. }), "{e}");
    assert_eq!(e.line, line_of(&xml, "</mass>"));
    // Garbage bytes must not panic either.
    let mut garbage = xml.clone().into_bytes();
    for (i, b) in garbage.iter_mut().enumerate() {
        if i % 97 == 13 {
            *b = 0xFF;
        }
    }
    let _ = parse("t.xml", &garbage);
}

// ----- real exports ----------------------------------------------------------------------------

/// Body and joint counts from `MANIFEST.md` (path relative to the fixtures directory).
const EXPECTED: [(&str, usize, usize); 18] = [
    ("xml/robotology+icub-models-generator/6af98216/iCubGenova02_SIM_MODEL.xml", 39, 39),
    ("xml/robotology+icub-models-generator/e780c99f/ICUB_2-5_BB_SIM_MODEL.xml", 47, 47),
    ("xml/robotology+icub-models-generator/47ce5a54/ICUB_2-5_BB_SIM_MODEL.xml", 47, 47),
    ("xml/robotology+icub-models-generator/08c7f3a5/ICUB_2-5_BB_SIM_MODEL.xml", 47, 47),
    ("xml/robotology+icub-models-generator/4dd88947/ICUB_2-5_plus_BB_SIM_MODEL.xml", 47, 47),
    ("xml/robotology+icub-models-generator/67275682/SIM_LEFT_HAND_Mk3.xml", 13, 13),
    ("xml/robotology+icub-models-generator/85fdaa3f/SIM_L_WRIST.xml", 5, 5),
    ("xml/robotology+icub-models-generator/2d4a19cf/ICUB3_UPPERBODY_SIM_MODEL.xml", 13, 13),
    ("xml/robotology+icub-models-generator/d1456816/ICUB3_L_LEG_SIM_MODEL.xml", 10, 10),
    ("xml/robotology+icub-models-generator/d1456816/ICUB3_R_LEG_SIM_MODEL.xml", 10, 10),
    ("xml/robotology+icub-models-generator/3ca3b152/ICUB3_ALL_SIM_MODEL.xml", 43, 43),
    ("xml/robotology+icub-models-generator/cf367280/ICUB3_ALL_SIM_MODEL.xml", 43, 43),
    ("xml/robotology+simmechanics-to-urdf/a83a61f/LEGS_MECHANISM.xml", 29, 33),
    ("xml/robotology+simmechanics-to-urdf/5beb5f5/LEGS_MECHANISM.xml", 14, 14),
    ("xml/steventen+SimMechanics-Parsing-Tools/fourbar.xml", 5, 6),
    ("xml/icub-tech-iit+ergocub-software/0a049c74/SIM_ERGOCUB_1-0.xml", 43, 42),
    ("xml/icub-tech-iit+ergocub-software/1fe125d3/SIM_ERGOCUB_1-0.xml", 67, 67),
    ("stl/robotology+icub-models-generator/25e4033/left_hand_mk3/SIM_LEFT_HAND.xml", 13, 13),
];

#[test]
fn real_fixtures_parse_with_manifest_counts() {
    let Some(dir) = crate::pipeline::testutil::fixtures_dir() else { return };
    let mut files = crate::pipeline::testutil::files_with_ext(&dir.join("xml"), "xml");
    files.extend(crate::pipeline::testutil::files_with_ext(&dir.join("stl"), "xml"));
    files.sort();
    let mut parsed = 0;
    let mut checked = 0;
    for path in &files {
        let rel = path.strip_prefix(&dir).unwrap_or(path).to_string_lossy().replace('\\', "/");
        let bytes = std::fs::read(path).expect("readable fixture");
        if !is_physical_modeling_xml(&bytes) {
            continue;
        }
        let (m, warnings) = match parse(&rel, &bytes) {
            Ok(r) => r,
            Err(e) => panic!("{e}"),
        };
        parsed += 1;
        println!(
            "{rel}: {} bodies, {} joints, {} frames, {} warnings, container {}",
            m.bodies.len(),
            m.joints.len(),
            m.frames.len(),
            warnings.len(),
            m.source.container
        );
        for w in &warnings {
            println!("  {} {}: {}", w.code, w.location, w.message);
        }
        if let Some(&(_, bodies, joints)) = EXPECTED.iter().find(|(p, _, _)| *p == rel) {
            assert_eq!((m.bodies.len(), m.joints.len()), (bodies, joints), "{rel}");
            checked += 1;
        }
        // Sanity of what the IR promises.
        for j in &m.joints {
            assert!(!j.primitives.is_empty());
            assert!(j.base.index() < m.frames.len() && j.follower.index() < m.frames.len());
            assert!(j.loc.line > 0);
        }
        for f in &m.frames {
            let r = f.pose.rotation.to_rotation_matrix();
            assert!((r.matrix().determinant() - 1.0).abs() < 1e-9, "{rel} {}", f.node_id);
        }
        if rel.ends_with("fourbar.xml") {
            assert_eq!(m.length_scale, 0.0254);
            assert_eq!(m.source.container, "SimMechanics");
        } else {
            assert_eq!(m.length_scale, 1e-3, "{rel}");
        }
        if rel.contains("47ce5a54") {
            assert_eq!(m.source.container, "SimscapeMultibody");
        }
        if rel.contains("3ca3b152") {
            let prismatic = m.joints.iter().flat_map(|j| &j.primitives).filter(|p| p.kind == PrimitiveKind::Prismatic);
            assert_eq!(prismatic.count(), 1);
        }
        if rel.contains("0a049c74") {
            use PrimitiveKind::*;
            for j in &m.joints {
                let kinds: Vec<_> = j.primitives.iter().map(|p| p.kind).collect();
                assert_eq!(kinds, [Prismatic, Prismatic, Prismatic, Spherical], "{}", j.node_id);
            }
        }
        if rel.contains("6af98216") {
            assert!(m.bodies.iter().any(|b| b.subsystem_path.len() >= 2), "nested subsystems");
        }
    }
    assert_eq!(checked, EXPECTED.len(), "every manifest file was found and checked");
    assert_eq!(parsed, EXPECTED.len());

    let second = dir.join("xml/yoggi56+hexapod_simmechanics/Link1.xml");
    let bytes = std::fs::read(second).expect("Link1.xml");
    assert!(!is_physical_modeling_xml(&bytes));
    let e = match parse("Link1.xml", &bytes) {
        Ok(_) => panic!("second-generation file parsed"),
        Err(e) => e,
    };
    assert_eq!(e.kind, XmlErrorKind::SecondGeneration);
    assert_eq!(e.line, 2);
}

#[test]
fn non_simple_joint_entries_warn() {
    let xml = two_bodies("SimMechanics").replacen("</joints>", "<UnknownConstraint><name>\"x\"</name></UnknownConstraint>\n</joints>", 1);
    let (m, warnings) = ok(&xml);
    assert_eq!(m.joints.len(), 2);
    assert_eq!(warnings.len(), 1);
    assert_eq!(warnings[0].code, "joint-element-skipped");
    assert!(warnings[0].message.contains("UnknownConstraint"));
}

/// An unclosed, deeply nested file with a 100 KB name gives a short message that still names
/// the innermost element and the body.
#[test]
fn error_paths_are_bounded() {
    let xml = format!(
        "<PhysicalModelingXMLFile><SimMechanics><bodies><Body><name>\"{}\"</name>{}",
        "N".repeat(100_000),
        (0..200).map(|i| format!("<x{i}>")).collect::<String>()
    );
    let e = super::parse("deep.xml", xml.as_bytes()).expect_err("refused");
    let text = e.to_string();
    assert!(text.len() < 800, "{} bytes: {text}", text.len());
    assert!(text.contains("x199") && text.contains("levels") && text.contains("Body \"NNN"), "{text}");
}

#[test]
fn a_rotation_far_from_orthonormal_is_an_error_naming_the_frame() {
    // Rz(30°) printed to 6 digits converts silently; the same with its first column scaled by
    // 1.08 (determinant 1.08, max |R^T R - I| = 0.166) is corrupt, not rounded.
    let rounded = "0.866025,0.5,0,-0.5,0.866025,0,0,0,1";
    let corrupt = "0.935307,0.54,0,-0.5,0.866025,0,0,0,1";
    let xml = |o: &str| {
        document(
            "SimMechanics",
            &system(
                &[body("A", "1", &[frame("CG", None, "0,0,0", "mm", "1,0,0,0,1,0,0,0,1"), frame("CS1", None, "0,0,0", "mm", o)])],
                &[],
                &[],
                &[],
            ),
        )
    };
    let (_, warnings) = ok(&xml(rounded));
    assert!(warnings.is_empty(), "{warnings:?}");
    let text = xml(corrupt);
    let e = fails(&text);
    let shown = e.to_string();
    assert!(matches!(e.kind, XmlErrorKind::NotARotation { .. }), "{shown}");
    assert!(shown.contains("frame \"CS1\"") && shown.contains("determinant 1.0799"), "{shown}");
    assert_eq!(e.line, line_of(&text, corrupt), "{shown}");
}

#[test]
fn an_all_zero_rotation_is_an_error_naming_the_frame() {
    let zero = "0,0,0,0,0,0,0,0,0";
    let text = document(
        "SimMechanics",
        &system(
            &[body("A", "1", &[frame("CG", None, "0,0,0", "mm", "1,0,0,0,1,0,0,0,1"), frame("CS1", None, "0,0,0", "mm", zero)])],
            &[],
            &[],
            &[],
        ),
    );
    let e = fails(&text);
    let shown = e.to_string();
    assert!(matches!(e.kind, XmlErrorKind::NotARotation { .. }), "{shown}");
    assert!(shown.contains("frame \"CS1\""), "{shown}");
}

// ----- property test: random loops, composite joints, relative frames, 6-digit rounding ------

/// 6 significant digits, as CAD writes.
fn d6(x: f64) -> String {
    format!("{x:.5e}")
}

fn v6(v: &Vector3<f64>) -> String {
    format!("{},{},{}", d6(v.x), d6(v.y), d6(v.z))
}

/// Column-major 3x3, 6 digits (the XML's orientation order).
fn r6(r: &nalgebra::Rotation3<f64>) -> String {
    r.matrix().iter().map(|x| d6(*x)).collect::<Vec<_>>().join(",")
}

/// A random planar four-bar (ground pivots A, D; crank, coupler, rocker about a random common
/// normal written to 6 digits per joint) with a slider hung off the coupler by a composite
/// prismatic + revolute joint whose follower frame is written relative to the slider's CS1:
/// the XML and each body's exact CS1 pose.
fn random_mechanism(rng: &mut crate::mechanism::XorShift) -> (String, Vec<(&'static str, nalgebra::Isometry3<f64>)>) {
    use nalgebra::{Isometry3, Rotation3, Translation3, UnitQuaternion};
    let draws: Vec<f64> = (0..64).map(|_| rng.uniform()).collect();
    let next = std::cell::Cell::new(0);
    let r01 = || {
        next.set(next.get() + 1);
        draws[next.get() - 1]
    };
    let u = |lo: f64, hi: f64| lo + (hi - lo) * r01();
    let tilt = Rotation3::from_euler_angles(u(-3.0, 3.0), u(-1.5, 1.5), u(-3.0, 3.0));
    let (ex, ey, n) = (tilt * Vector3::x(), tilt * Vector3::y(), tilt * Vector3::z());
    let pt = |scale: f64| ex * u(-scale, scale) + ey * u(-scale, scale);
    let (a, b, c, d, q) = (pt(0.5), pt(0.5), pt(0.5), pt(0.5), pt(0.5));
    let s = 0.05 + 0.1 * r01();
    let slide = (ex * r01() + ey * (r01() + 0.1)).normalize();
    let theta = u(-1.0, 1.0);
    let pose = || {
        Isometry3::from_parts(
            Translation3::new(u(-1.0, 1.0), u(-1.0, 1.0), u(-1.0, 1.0)),
            UnitQuaternion::from_euler_angles(u(-3.0, 3.0), u(-1.5, 1.5), u(-3.0, 3.0)),
        )
    };
    let cs1: Vec<(&'static str, Isometry3<f64>)> = vec![("CRANK", pose()), ("COUPLER", pose()), ("ROCKER", pose()), ("SLIDER", pose())];
    let world = |name: &str, r: Option<u32>, p: &Vector3<f64>, rot: &Rotation3<f64>| frame(name, r, &v6(p), "m", &r6(rot));
    let plain = |_name: &'static str, iso: &Isometry3<f64>, joints: &[(u32, Vector3<f64>)]| {
        let rot = iso.rotation.to_rotation_matrix();
        let mut frames = vec![world("CG", None, &iso.translation.vector, &rot), world("CS1", None, &iso.translation.vector, &rot)];
        for (k, (r, p)) in joints.iter().enumerate() {
            frames.push(world(&format!("CS{}", k + 2), Some(*r), p, &tilt));
        }
        frames
    };
    let mut bodies = vec![body("RootPart", "ROOT", &{
        let mut f = plain("RootPart", &Isometry3::identity(), &[(1, a), (2, d)]);
        f.push(world("CS4", Some(3), &Vector3::zeros(), &Rotation3::identity()));
        f
    })];
    bodies.push(body("CRANK", "CRANK", &plain("CRANK", &cs1[0].1, &[(11, a), (12, b)])));
    bodies.push(body("COUPLER", "COUPLER", &plain("COUPLER", &cs1[1].1, &[(21, b), (22, c), (23, q)])));
    bodies.push(body("ROCKER", "ROCKER", &plain("ROCKER", &cs1[2].1, &[(31, c), (32, d)])));
    // The slider's joint frame: at q + slide * s, turned theta about n, written in its CS1.
    let sl = cs1[3].1;
    let follower_rot = Rotation3::from_axis_angle(&nalgebra::Unit::new_normalize(n), theta) * tilt;
    let local_p = sl.rotation.inverse() * (q + slide * s - sl.translation.vector);
    let local_r = sl.rotation.to_rotation_matrix().inverse() * follower_rot;
    let mut sframes = plain("SLIDER", &sl, &[]);
    sframes.push(frame_in("CS2", Some(41), &v6(&local_p), "m", &r6(&local_r), ["CS1", "CS1", "CS1"]));
    bodies.push(body("SLIDER", "SLIDER", &sframes));
    let axis = |v: &Vector3<f64>| v6(v);
    let joints = [
        joint("RootGround--RootPart", 4, 3, &[("weld", "0,0,1")]),
        // Each axis scaled before rounding, so each is rounded differently (parallel to ~1e-6).
        joint("RootPart--CRANK", 1, 11, &[("revolute", &axis(&(n * u(0.2, 3.0))))]),
        joint("CRANK--COUPLER", 12, 21, &[("revolute", &axis(&(n * u(0.2, 3.0))))]),
        joint("COUPLER--ROCKER", 22, 31, &[("revolute", &axis(&(n * u(0.2, 3.0))))]),
        joint("ROCKER--RootPart", 32, 2, &[("revolute", &axis(&(n * -u(0.2, 3.0))))]),
        joint("COUPLER--SLIDER", 23, 41, &[("prismatic", &axis(&slide)), ("revolute", &axis(&n))]),
    ];
    (document("SimMechanics", &system(&bodies, &joints, &[ground(4)], &[])), cs1)
}

#[test]
fn random_mechanisms_convert_exactly_within_their_stated_corrections() {
    let mut rng = crate::mechanism::XorShift::new(25);
    let (mut worst_pose, mut worst_axis, mut worst_origin, mut stated) = (0.0f64, 0.0f64, 0.0f64, 0usize);
    let cases = 300;
    for case in 0..cases {
        let (xml, truth) = random_mechanism(&mut rng);
        let bundle =
            crate::pipeline::front::bundle::Bundle::from_files("gen", [("GEN.xml".to_string(), xml.into_bytes())]).expect("bundle");
        let opts = crate::pipeline::Options { write_shapes: false, ..Default::default() };
        let a = crate::pipeline::analyse(&bundle, &opts).unwrap_or_else(|e| panic!("case {case}: {e}"));
        let (m, v) = (&a.model, &a.validated);
        // Every element: the emitted axis and point against the XML's, exact unless stated,
        // and stated deviations within the data's precision: 1e-5 rad, and 1e-5 of the
        // model's size (coordinates up to 1 m written to 6 digits are off by up to 5e-6 m).
        for (j, joint) in m.joints.iter().enumerate() {
            let chain = &v.analysis.chains[j];
            let (bp, fp) = (m.frame(joint.base).pose.translation.vector, m.frame(joint.follower).pose.translation.vector);
            let movable: Vec<_> = joint.primitives.iter().filter(|p| p.kind != PrimitiveKind::Weld).collect();
            for (k, (e, p)) in chain.elements.iter().zip(&movable).enumerate() {
                let src = p.axis_world.normalize();
                let angle = src.cross(&e.axis_world).norm().atan2(src.dot(&e.axis_world));
                let point = if movable[..k].iter().any(|p| p.kind == PrimitiveKind::Prismatic) { fp } else { bp };
                let miss = if e.kind == PrimitiveKind::Revolute { (point - e.origin_world).cross(&e.axis_world).norm() } else { 0.0 };
                let said = e.correction.as_ref();
                let (ca, co) = said.map_or((0.0, 0.0), |c| (c.axis_rad, c.origin_m));
                assert!(
                    angle <= 1e-12 || (angle - ca).abs() <= 1e-12,
                    "case {case}, {}: axis moved {angle:e} rad, stated {said:?}",
                    joint.cad_name
                );
                assert!(
                    miss <= 1e-12 || (miss - co).abs() <= 1e-12,
                    "case {case}, {}: hinge misses its point by {miss:e} m, stated {said:?}",
                    joint.cad_name
                );
                assert!(ca <= 1e-5 && co <= 1e-5, "case {case}, {}: {said:?} beyond the data's precision", joint.cad_name);
                worst_axis = worst_axis.max(ca);
                worst_origin = worst_origin.max(co);
                stated += usize::from(said.is_some());
                if e.kind == PrimitiveKind::Revolute && joint.primitives.len() > 1 {
                    assert!(miss <= 1e-12, "case {case}: the composite's hinge misses the follower frame by {miss:e} m");
                }
            }
        }
        // Forward kinematics at the start values: every body where the generator put it, to
        // the XML's 6 digits.
        let mech = crate::mechanism::Mechanism::from_validated(m, v).unwrap_or_else(|e| panic!("case {case}: {e}"));
        let k = mech.forward(&mech.q0()).expect("fk");
        for (name, want) in &truth {
            let b = m.bodies.iter().position(|b| b.cad_name == *name).expect("body");
            let got = mech.body_pose(&k, crate::pipeline::ir::BodyId(b as u32)).expect("pose");
            let dp = (got.translation.vector - want.translation.vector).norm();
            let dr = got.rotation.angle_to(&want.rotation);
            worst_pose = worst_pose.max(dp).max(dr);
            assert!(dp < 2e-5 && dr < 2e-5, "case {case}, {name}: {dp:e} m, {dr:e} rad from the generator");
        }
        let info = &v.analysis.loops.loops;
        assert!(info.iter().any(|l| l.cut == crate::pipeline::passes::loops::Cut::PlanarLoopConstraint), "case {case}: {info:?}");
    }
    println!("{cases} random mechanisms: poses within {worst_pose:.2e} of the generator; {stated} corrections stated, largest {worst_axis:.2e} rad, {worst_origin:.2e} m");
}
