//! Throughput of the first-generation SimMechanics XML front end alone (bytes in, IR out):
//! (a) the largest XML fixture, ergoCub 1.0 (423 KB, 67 bodies), when the fixtures are present;
//! (b) a generated 2,000-body revolute chain.
//!
//! `cargo bench -p cad2mo --bench xml`. Fixtures default to `../shared/fixtures` next to the
//! workspace; override with `CAD2MO_FIXTURES`.

use std::fmt::Write as _;
use std::path::PathBuf;

use cad2mo::pipeline::front::simmechanics;
use criterion::{criterion_group, criterion_main, Criterion, Throughput};

fn fixtures() -> Option<PathBuf> {
    let dir = std::env::var_os("CAD2MO_FIXTURES")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../shared/fixtures"));
    if dir.is_dir() {
        Some(dir)
    } else {
        println!(
            "NOTICE: fixtures not found at {}; the fixture benchmark is skipped",
            dir.display()
        );
        None
    }
}

/// One frame in mm, shaped like Creo's output.
fn frame(
    out: &mut String,
    name: &str,
    node_id: &str,
    r: Option<u32>,
    pos: [f64; 3],
    orientation: &str,
) {
    let r = r.map(|r| format!(" ref=\"{r}\"")).unwrap_or_default();
    let _ = write!(
        out,
        r#"          <Frame{r}>
            <name>"{name}"</name>
            <displayName>""</displayName>
            <nodeID>"{node_id}::{name}(AUTOGEN)"</nodeID>
            <position>{},{},{}</position>
            <positionOrigin>"WORLD"</positionOrigin>
            <positionReferenceFrame>"WORLD"</positionReferenceFrame>
            <positionUnits>"mm"</positionUnits>
            <orientation>{orientation}</orientation>
            <orientationType>"3x3 Transform"</orientationType>
            <orientationUnits>"rad"</orientationUnits>
            <orientationReferenceFrame>"WORLD"</orientationReferenceFrame>
          </Frame>
"#,
        pos[0], pos[1], pos[2]
    );
}

/// A chain of `n` bodies (frames CG, CS1, CS2, CS3 in mm), revolute joints between consecutive
/// bodies, and a ground welded to the first. Body `i`'s CS2 has ref `2i+1`, its CS3 `2i+2`.
fn chain_xml(n: u32) -> String {
    let mut s = String::with_capacity(n as usize * 5000);
    s.push_str(
        r#"<?xml version="1.0" encoding="UTF-8" standalone="no" ?>
<PhysicalModelingXMLFile>

  <formatVersion>"1.0.4"</formatVersion>

  <internalVersion>1</internalVersion>

  <createdUsing>"Simscape Multibody Link Version 5.0"</createdUsing>

  <createdFrom>"Pro/E Wildfire Creo 7.0 - 2020454"</createdFrom>

  <createdOn>"01/01/24||00:00:00"</createdOn>

  <createdBy>"bench"</createdBy>

  <name>"CHAIN"</name>

  <SimscapeMultibody>
    <name>"CHAIN"</name>
    <nodeID>"CHAIN"</nodeID>
    <bodies>
"#,
    );
    // Slightly noisy rotations exercise the orthonormalisation like real exports do.
    let tilted = "0.866025,0.5,0,-0.5,0.866025,0,0,0,1";
    for i in 0..n {
        let x = f64::from(i) * 107.254;
        let id = format!("{}", 100 + i);
        let _ = write!(
            s,
            r#"      <Body>
        <name>"LINK_{i}"</name>
        <nodeID>"{id}"</nodeID>
        <status>""</status>
        <mass>0.847834</mass>
        <massUnits>"kg"</massUnits>
        <inertia>0.000642193,-5.50228e-005,8.43781e-006,-5.50228e-005,0.000791101,6.75903e-007,8.43781e-006,6.75903e-007,0.000848022</inertia>
        <inertiaUnits>"kg*m^2"</inertiaUnits>
        <volume>205013</volume>
        <volumeUnits>"mm^3"</volumeUnits>
        <surfaceArea>152121</surfaceArea>
        <surfaceAreaUnits>"mm^2"</surfaceAreaUnits>
        <frames>
"#
        );
        frame(
            &mut s,
            "CG",
            &id,
            None,
            [x + 53.6, 6.92386, -0.122126],
            "1,0,0,0,1,0,0,0,1",
        );
        frame(&mut s, "CS1", &id, None, [x, 0.0, 0.0], "1,0,0,0,1,0,0,0,1");
        frame(&mut s, "CS2", &id, Some(2 * i + 1), [x, 0.0, 0.0], tilted);
        frame(
            &mut s,
            "CS3",
            &id,
            Some(2 * i + 2),
            [x + 107.254, 0.0, 0.0],
            tilted,
        );
        let _ = write!(
            s,
            r#"        </frames>
        <geometryFileName>"LINK_{i}_prt.stl"</geometryFileName>
      </Body>
"#
        );
    }
    s.push_str("    </bodies>\n    <joints>\n");
    let joint = |s: &mut String,
                 name: &str,
                 node: &str,
                 base: u32,
                 follower: u32,
                 prim: &str,
                 axis: &str| {
        let _ = write!(
            s,
            r#"      <SimpleJoint>
        <name>"{name}"</name>
        <nodeID>"{node}"</nodeID>
        <status>""</status>
        <base>
          <JointSide>
            <name>""</name>
            <connection>
              <Frame ref="{base}"></Frame>
            </connection>
          </JointSide>
        </base>
        <follower>
          <JointSide>
            <name>""</name>
            <connection>
              <Frame ref="{follower}"></Frame>
            </connection>
          </JointSide>
        </follower>
        <primitives>
          <Primitive>
            <name>"{prim}"</name>
            <nodeID>""</nodeID>
            <referenceFrame>"WORLD"</referenceFrame>
            <axis>{axis}</axis>
          </Primitive>
        </primitives>
      </SimpleJoint>
"#
        );
    };
    let ground_ref = 2 * n + 1;
    joint(
        &mut s,
        "RootGround--LINK_0",
        "100:-:RootGround",
        ground_ref,
        1,
        "weld",
        "0.57735,0.57735,0.57735",
    );
    for i in 1..n {
        let name = format!("LINK_{}--LINK_{i}", i - 1);
        let node = format!("{}:-:{}", 99 + i, 100 + i);
        joint(
            &mut s,
            &name,
            &node,
            2 * i,
            2 * i + 1,
            "revolute",
            "0,-1.61681e-010,-1",
        );
    }
    s.push_str("    </joints>\n    <grounds>\n      <Ground>\n        <name>\"RootGround\"</name>\n        <nodeID>\"RootGround\"</nodeID>\n        <status>\"\"</status>\n        <frame>\n");
    frame(
        &mut s,
        "CS1",
        "RootGround",
        Some(ground_ref),
        [0.0, 0.0, 0.0],
        "1,0,0,0,1,0,0,0,1",
    );
    s.push_str(
        "        </frame>\n      </Ground>\n    </grounds>\n    <subsystems></subsystems>\n    <connectionPorts></connectionPorts>\n    <id>0</id>\n  </SimscapeMultibody>\n\n</PhysicalModelingXMLFile>\n",
    );
    s
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("xml");

    if let Some(dir) = fixtures() {
        let path = dir.join("xml/icub-tech-iit+ergocub-software/1fe125d3/SIM_ERGOCUB_1-0.xml");
        match std::fs::read(&path) {
            Ok(bytes) => {
                let (m, _) =
                    simmechanics::parse("SIM_ERGOCUB_1-0.xml", &bytes).expect("fixture parses");
                assert_eq!(m.bodies.len(), 67);
                g.throughput(Throughput::Bytes(bytes.len() as u64));
                g.bench_function("ergocub_1fe125d3", |b| {
                    b.iter(|| simmechanics::parse("SIM_ERGOCUB_1-0.xml", &bytes).expect("parses"))
                });
            }
            Err(e) => println!("NOTICE: {} not readable ({e}); skipped", path.display()),
        }
    }

    let xml = chain_xml(2000);
    let (m, _) = simmechanics::parse("chain.xml", xml.as_bytes()).expect("generated chain parses");
    assert_eq!(
        (m.bodies.len(), m.joints.len(), m.frames.len()),
        (2000, 2000, 8001)
    );
    g.throughput(Throughput::Bytes(xml.len() as u64));
    g.bench_function("chain_2000_bodies", |b| {
        b.iter(|| simmechanics::parse("chain.xml", xml.as_bytes()).expect("parses"))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
