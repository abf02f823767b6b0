//! Generated first-generation SimMechanics XML for benchmarks: a tree of `n` bodies, each hung
//! from its parent `(i - 1) / 3` by a revolute joint, with rotated frames, in mm/kg.

use std::fmt::Write as _;

fn frame(out: &mut String, name: &str, node: &str, r: Option<usize>, p: [f64; 3], angle: f64) {
    let (s, c) = angle.sin_cos();
    let refattr = r.map(|r| format!(" ref=\"{r}\"")).unwrap_or_default();
    let _ = write!(
        out,
        "          <Frame{refattr}>\n            <name>\"{name}\"</name>\n            <displayName>\"\"</displayName>\n            <nodeID>\"{node}\"</nodeID>\n            <position>{},{},{}</position>\n            <positionOrigin>\"WORLD\"</positionOrigin>\n            <positionReferenceFrame>\"WORLD\"</positionReferenceFrame>\n            <positionUnits>\"mm\"</positionUnits>\n            <orientation>{c},{s},0,{},{c},0,0,0,1</orientation>\n            <orientationType>\"3x3 Transform\"</orientationType>\n            <orientationUnits>\"rad\"</orientationUnits>\n            <orientationReferenceFrame>\"WORLD\"</orientationReferenceFrame>\n          </Frame>\n",
        p[0], p[1], p[2], -s
    );
}

fn body(out: &mut String, name: &str, node: &str, mass: f64, frames: &str) {
    body_with(out, name, node, mass, frames, "")
}

fn body_with(out: &mut String, name: &str, node: &str, mass: f64, frames: &str, geometry: &str) {
    let _ = write!(
        out,
        "      <Body>\n        <name>\"{name}\"</name>\n        <nodeID>\"{node}\"</nodeID>\n        <status>\"\"</status>\n        <mass>{mass}</mass>\n        <massUnits>\"kg\"</massUnits>\n        <inertia>0.001,0,0,0,0.002,0,0,0,0.0025</inertia>\n        <inertiaUnits>\"kg*m^2\"</inertiaUnits>\n        <volume>{}</volume>\n        <volumeUnits>\"mm^3\"</volumeUnits>\n        <surfaceArea>1000</surfaceArea>\n        <surfaceAreaUnits>\"mm^2\"</surfaceAreaUnits>\n        <frames>\n{frames}        </frames>\n        <geometryFileName>\"{geometry}\"</geometryFileName>\n      </Body>\n",
        mass / 2700.0 * 1e9
    );
}

fn joint(out: &mut String, name: &str, node: &str, base: usize, follower: usize, kind: &str, axis: &str) {
    let _ = write!(
        out,
        "      <SimpleJoint>\n        <name>\"{name}\"</name>\n        <nodeID>\"{node}\"</nodeID>\n        <status>\"\"</status>\n        <base>\n          <JointSide>\n            <name>\"\"</name>\n            <connection>\n              <Frame ref=\"{base}\"></Frame>\n            </connection>\n          </JointSide>\n        </base>\n        <follower>\n          <JointSide>\n            <name>\"\"</name>\n            <connection>\n              <Frame ref=\"{follower}\"></Frame>\n            </connection>\n          </JointSide>\n        </follower>\n        <primitives>\n          <Primitive>\n            <name>\"{kind}\"</name>\n            <nodeID>\"\"</nodeID>\n            <referenceFrame>\"WORLD\"</referenceFrame>\n            <axis>{axis}</axis>\n          </Primitive>\n        </primitives>\n      </SimpleJoint>\n"
    );
}

/// An export with `n` bodies plus a RootPart, `n + 1` joints and a ground.
pub fn tree_xml(n: usize) -> String {
    tree_xml_with(n, false)
}

/// [`tree_xml`] with an ASCII STL per body (`LINK_<i>.stl`, in the body's CS1 frame, mm): an
/// 18-sided prism along z (72 triangles, about 18 KB, radius 0.8 to 1.4 mm, 3 to 4 mm long) for
/// most bodies, a concave L-shaped bracket (20 triangles, legs 1.2 to 1.6 mm, 3 mm wide) for every
/// seventh, as bundle files. The tree's bodies stand 3.5 mm apart in y and 7.25 mm in z: the
/// parts are small enough not to interfere. 2,000 bodies: 37 MB of STL.
pub fn tree_with_stl(n: usize) -> Vec<(String, Vec<u8>)> {
    let mut files = vec![("tree.xml".to_string(), tree_xml_with(n, true).into_bytes())];
    for i in 0..n {
        let tris = if i % 7 == 3 {
            bracket(1.2 + (i % 5) as f32 * 0.1)
        } else {
            // Along z: the CS1 frames turn about z.
            prism(18, 0.8 + (i % 4) as f32 * 0.2, 3.0 + (i % 3) as f32 * 0.5).into_iter().map(|t| t.map(|p| [p[1], p[2], p[0]])).collect()
        };
        files.push((format!("LINK_{i}.stl"), ascii_stl(&format!("LINK_{i}"), &tris)));
    }
    files
}

type Tri = [[f32; 3]; 3];

/// A `k`-sided prism of radius `r` along x from 0 to `len`: 4k triangles.
fn prism(k: usize, r: f32, len: f32) -> Vec<Tri> {
    let p = |j: usize, x: f32| {
        let a = std::f32::consts::TAU * j as f32 / k as f32;
        [x, r * a.cos(), r * a.sin()]
    };
    let mut t = Vec::new();
    for j in 0..k {
        let (a0, a1, b0, b1) = (p(j, 0.0), p(j + 1, 0.0), p(j, len), p(j + 1, len));
        t.push([a0, b1, a1]);
        t.push([a0, b0, b1]);
        t.push([[0.0, 0.0, 0.0], a0, a1]);
        t.push([[len, 0.0, 0.0], b1, b0]);
    }
    t
}

/// An L-shaped bracket (two legs of length `s` mm, 0.4 mm thick, 3 mm wide): concave, closed,
/// outward normals.
fn bracket(s: f32) -> Vec<Tri> {
    let (w, th) = (3.0, 0.4);
    // The L profile in the x-y plane, counter-clockwise, extruded along z from 0 to w.
    let prof = [[0.0, 0.0], [s, 0.0], [s, th], [th, th], [th, s], [0.0, s]];
    let mut t = Vec::new();
    let n = prof.len();
    for j in 0..n {
        let (a, b) = (prof[j], prof[(j + 1) % n]);
        let (a0, b0, a1, b1) = ([a[0], a[1], 0.0], [b[0], b[1], 0.0], [a[0], a[1], w], [b[0], b[1], w]);
        t.push([a0, b0, b1]);
        t.push([a0, b1, a1]);
    }
    // Caps: the L split into two convex quads (0,1,2,3 and 0,3,4,5).
    for q in [[0, 1, 2, 3], [0, 3, 4, 5]] {
        let v = |k: usize, z: f32| [prof[q[k]][0], prof[q[k]][1], z];
        t.push([v(0, w), v(1, w), v(2, w)]);
        t.push([v(0, w), v(2, w), v(3, w)]);
        t.push([v(0, 0.0), v(2, 0.0), v(1, 0.0)]);
        t.push([v(0, 0.0), v(3, 0.0), v(2, 0.0)]);
    }
    t
}

fn ascii_stl(name: &str, tris: &[Tri]) -> Vec<u8> {
    let mut s = format!("solid {name}\n");
    for t in tris {
        let (u, v) = ([t[1][0] - t[0][0], t[1][1] - t[0][1], t[1][2] - t[0][2]], [t[2][0] - t[0][0], t[2][1] - t[0][1], t[2][2] - t[0][2]]);
        let nrm = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
        let l = (nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]).sqrt().max(1e-30);
        let _ = writeln!(s, "  facet normal {:e} {:e} {:e}\n    outer loop", nrm[0] / l, nrm[1] / l, nrm[2] / l);
        for p in t {
            let _ = writeln!(s, "      vertex {:.6e} {:.6e} {:.6e}", p[0], p[1], p[2]);
        }
        s.push_str("    endloop\n  endfacet\n");
    }
    let _ = writeln!(s, "endsolid {name}");
    s.into_bytes()
}

pub fn tree_xml_with(n: usize, stl: bool) -> String {
    let mut bodies = String::new();
    let mut joints = String::new();
    let mut next_ref = 1usize;
    // RootPart at the origin, welded to the ground; body 0 hangs from it.
    let mut f = String::new();
    frame(&mut f, "CG", "R::CG", None, [0.0; 3], 0.0);
    frame(&mut f, "CS1", "R::CS1", None, [0.0; 3], 0.0);
    let root_ground = next_ref;
    frame(&mut f, "CS2", "R::G", Some(root_ground), [0.0; 3], 0.0);
    let root_child = next_ref + 1;
    frame(&mut f, "CS3", "R::0", Some(root_child), [0.0; 3], 0.0);
    next_ref += 3; // ref 3 is the ground frame
    body(&mut bodies, "RootPart", "BENCH/RootPart", 0.0, &f);
    let ground_ref = 3;
    joint(&mut joints, "RootGround--RootPart", "RootGround:-:BENCH/RootPart", ground_ref, root_ground, "weld", "0.57735,0.57735,0.57735");
    let pos = |i: usize| -> [f64; 3] {
        let depth = ((i + 1) as f64).log(3.0).floor();
        [depth * 120.0, (i % 97) as f64 * 3.5, (i % 13) as f64 * -7.25]
    };
    let mut child_refs: Vec<Vec<(usize, usize)>> = vec![Vec::new(); n];
    let mut parent_ref = vec![0usize; n];
    for (i, slot) in parent_ref.iter_mut().enumerate() {
        *slot = next_ref;
        next_ref += 1;
        if i > 0 {
            let p = (i - 1) / 3;
            child_refs[p].push((i, next_ref));
            next_ref += 1;
        }
    }
    for i in 0..n {
        let mut f = String::new();
        let p = pos(i);
        let angle = (i as f64) * 0.1;
        frame(&mut f, "CG", &format!("{i}::CG"), None, [p[0] + 40.0, p[1] + 5.0, p[2]], angle);
        frame(&mut f, "CS1", &format!("{i}::CS1"), None, p, angle);
        frame(&mut f, "CS2", &format!("{i}::parent"), Some(parent_ref[i]), p, angle);
        for (k, (child, r)) in child_refs[i].iter().enumerate() {
            frame(&mut f, &format!("CS{}", k + 3), &format!("{i}:-:{child}"), Some(*r), pos(*child), angle);
        }
        let geometry = if stl { format!("LINK_{i}.stl") } else { String::new() };
        body_with(&mut bodies, &format!("LINK_{i}"), &format!("{}", 1000 + i), 1.0 + (i % 7) as f64 * 0.25, &f, &geometry);
        let (base, name) = if i == 0 {
            (root_child, "RootPart--LINK_0".to_string())
        } else {
            let p = (i - 1) / 3;
            let r = child_refs[p].iter().find(|(c, _)| *c == i).map(|(_, r)| *r).unwrap_or(0);
            (r, format!("LINK_{p}--LINK_{i}"))
        };
        let axis = ["0,0,1", "0,1,0", "1,0,0"][i % 3];
        joint(&mut joints, &name, &format!("{i}:-:j"), base, parent_ref[i], "revolute", axis);
    }
    let mut ground = String::new();
    frame(&mut ground, "CS1", "RootGround::CS1", Some(ground_ref), [0.0; 3], 0.0);
    format!(
        "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\" ?>\n<PhysicalModelingXMLFile>\n  <formatVersion>\"1.0.4\"</formatVersion>\n  <internalVersion>1</internalVersion>\n  <createdUsing>\"cad2mo benchmark generator\"</createdUsing>\n  <createdFrom>\"generated\"</createdFrom>\n  <createdOn>\"01/01/26||00:00:00\"</createdOn>\n  <createdBy>\"bench\"</createdBy>\n  <name>\"BENCH\"</name>\n  <SimMechanics>\n    <name>\"BENCH\"</name>\n    <nodeID>\"BENCH\"</nodeID>\n    <bodies>\n{bodies}    </bodies>\n    <joints>\n{joints}    </joints>\n    <grounds>\n      <Ground>\n        <name>\"RootGround\"</name>\n        <nodeID>\"RootGround\"</nodeID>\n        <status>\"\"</status>\n        <frame>\n{ground}        </frame>\n      </Ground>\n    </grounds>\n    <subsystems></subsystems>\n    <connectionPorts></connectionPorts>\n    <id>0</id>\n  </SimMechanics>\n</PhysicalModelingXMLFile>\n"
    )
}

/// A serial arm of `n` revolute joints (6: a PUMA-like arm with a spherical wrist, axes z y y x
/// y x; otherwise an iiwa-like column, axes alternating z and y), each link's CS3 the next joint's
/// frame, the last link carrying the tool frame (nodeID `TOOL`), in mm/kg. Links have a
/// generic inertia tensor (all six entries non-zero) and a CG off every axis.
pub fn serial_arm_xml(n: usize) -> String {
    // Joint positions (mm) and axes.
    let (pos, axes): (Vec<[f64; 3]>, Vec<&str>) = if n == 6 {
        (
            vec![[0.0, 0.0, 0.0], [0.0, 0.0, 350.0], [0.0, 60.0, 750.0], [120.0, 0.0, 800.0], [420.0, 0.0, 800.0], [420.0, 0.0, 800.0]],
            vec!["0,0,1", "0,1,0", "0,1,0", "1,0,0", "0,1,0", "1,0,0"],
        )
    } else {
        let p = (0..n).map(|i| [0.0, 0.0, 340.0 * i.div_ceil(2) as f64]).collect();
        let a = (0..n).map(|i| if i % 2 == 0 { "0,0,1" } else { "0,1,0" }).collect();
        (p, a)
    };
    let tool = {
        let last = pos[n - 1];
        if n == 6 {
            [last[0] + 100.0, last[1] + 20.0, last[2] - 30.0]
        } else {
            [last[0] + 25.0, last[1], last[2] + 130.0]
        }
    };
    let mut bodies = String::new();
    let mut joints = String::new();
    // Refs: ground 1; joint i: base ref 10 + 2i, follower ref 11 + 2i.
    let mut base = String::new();
    frame(&mut base, "CG", "BASE::CG", None, [0.0, 0.0, -50.0], 0.0);
    frame(&mut base, "CS1", "BASE::CS1", None, [0.0; 3], 0.0);
    frame(&mut base, "CS2", "BASE::G", Some(2), [0.0; 3], 0.0);
    frame(&mut base, "CS3", "BASE::J1", Some(10), pos[0], 0.0);
    body(&mut bodies, "BASE", "ARM/BASE", 4.0, &base);
    joint(&mut joints, "Ground--BASE", "G:-:BASE", 1, 2, "weld", "0,0,1");
    for i in 0..n {
        let next = if i + 1 < n { pos[i + 1] } else { tool };
        let mid = [(pos[i][0] + next[0]) / 2.0 + 7.0, (pos[i][1] + next[1]) / 2.0 - 5.0, (pos[i][2] + next[2]) / 2.0 + 3.0];
        let angle = 0.3 * i as f64;
        let mut f = String::new();
        frame(&mut f, "CG", &format!("L{i}::CG"), None, mid, angle + 0.2);
        frame(&mut f, "CS1", &format!("L{i}::CS1"), None, pos[i], angle);
        frame(&mut f, "CS2", &format!("L{i}::parent"), Some(11 + 2 * i), pos[i], angle);
        if i + 1 < n {
            frame(&mut f, "CS3", &format!("L{i}::child"), Some(12 + 2 * i), next, angle);
        } else {
            frame(&mut f, "CS3", "TOOL", None, next, angle);
        }
        let mut b = String::new();
        body(&mut b, &format!("LINK{}", i + 1), &format!("ARM/LINK{}", i + 1), 3.0 - 0.3 * i as f64, &f);
        bodies.push_str(&b.replace(
            "<inertia>0.001,0,0,0,0.002,0,0,0,0.0025</inertia>",
            "<inertia>0.021,0.0013,-0.0021,0.0013,0.018,0.0011,-0.0021,0.0011,0.012</inertia>",
        ));
        let parent = if i == 0 { "BASE".to_string() } else { format!("LINK{i}") };
        joint(&mut joints, &format!("{parent}--LINK{}", i + 1), &format!("J{}:-:j", i + 1), 10 + 2 * i, 11 + 2 * i, "revolute", axes[i]);
    }
    let mut ground = String::new();
    frame(&mut ground, "CS1", "Ground::CS1", Some(1), [0.0; 3], 0.0);
    format!(
        "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\" ?>\n<PhysicalModelingXMLFile>\n  <formatVersion>\"1.0.4\"</formatVersion>\n  <internalVersion>1</internalVersion>\n  <createdUsing>\"cad2mo arm generator\"</createdUsing>\n  <createdFrom>\"generated\"</createdFrom>\n  <createdOn>\"01/01/26||00:00:00\"</createdOn>\n  <createdBy>\"bench\"</createdBy>\n  <name>\"ARM\"</name>\n  <SimMechanics>\n    <name>\"ARM\"</name>\n    <nodeID>\"ARM\"</nodeID>\n    <bodies>\n{bodies}    </bodies>\n    <joints>\n{joints}    </joints>\n    <grounds>\n      <Ground>\n        <name>\"Ground\"</name>\n        <nodeID>\"Ground\"</nodeID>\n        <status>\"\"</status>\n        <frame>\n{ground}        </frame>\n      </Ground>\n    </grounds>\n    <subsystems></subsystems>\n    <connectionPorts></connectionPorts>\n    <id>0</id>\n  </SimMechanics>\n</PhysicalModelingXMLFile>\n"
    )
}

/// A URDF tree of `n` links (branching like `tree_xml`: each link hangs from link `(i - 1) / 3`),
/// siblings side by side 0.15 m apart, revolute joints about varying axes with limits, rotated
/// inertial frames, and one binary STL
/// per link (`meshes/link_<i>.stl`, a 16-sided prism of 64 triangles), as bundle files.
pub fn urdf_tree(n: usize) -> Vec<(String, Vec<u8>)> {
    use std::fmt::Write as _;
    let mut u = String::from("<?xml version=\"1.0\"?>\n<robot name=\"gen_tree\">\n  <link name=\"world\"/>\n");
    let mut files = Vec::new();
    for i in 0..n {
        let _ = write!(
            u,
            "  <link name=\"link_{i}\">\n    <inertial>\n      <origin xyz=\"0.01 0.02 0.05\" rpy=\"0.1 0.2 {}\"/>\n      <mass value=\"{}\"/>\n      <inertia ixx=\"0.003\" ixy=\"0.0001\" ixz=\"0\" iyy=\"0.002\" iyz=\"0\" izz=\"0.001\"/>\n    </inertial>\n    <visual>\n      <origin xyz=\"0 0 0.05\"/>\n      <geometry><mesh filename=\"package://gen/meshes/link_{i}.stl\" scale=\"0.001 0.001 0.001\"/></geometry>\n    </visual>\n  </link>\n",
            0.01 * (i % 7) as f64,
            1.0 + (i % 5) as f64 * 0.1
        );
        // A 16-sided prism, radius 20 mm, length 100 mm, centred: 64 triangles.
        let k = 16;
        let p = |j: usize, z: f32| {
            let a = std::f32::consts::TAU * j as f32 / k as f32;
            [20.0 * a.cos(), 20.0 * a.sin(), z]
        };
        let mut tris: Vec<[[f32; 3]; 3]> = Vec::new();
        for j in 0..k {
            let (a0, a1, b0, b1) = (p(j, -50.0), p(j + 1, -50.0), p(j, 50.0), p(j + 1, 50.0));
            tris.push([a0, a1, b1]);
            tris.push([a0, b1, b0]);
            tris.push([[0.0, 0.0, -50.0], a1, a0]);
            tris.push([[0.0, 0.0, 50.0], b0, b1]);
        }
        let mut stl = vec![0u8; 80];
        stl.extend_from_slice(&(tris.len() as u32).to_le_bytes());
        for t in &tris {
            stl.extend_from_slice(&[0u8; 12]);
            for v in t {
                for c in v {
                    stl.extend_from_slice(&c.to_le_bytes());
                }
            }
            stl.extend_from_slice(&[0u8; 2]);
        }
        files.push((format!("gen/meshes/link_{i}.stl"), stl));
    }
    for i in 0..n {
        let parent = if i == 0 { "world".to_string() } else { format!("link_{}", (i - 1) / 3) };
        let axis = ["0 0 1", "0 1 0", "1 0 0"][i % 3];
        let _ = write!(
            u,
            "  <joint name=\"joint_{i}\" type=\"revolute\">\n    <parent link=\"{parent}\"/>\n    <child link=\"link_{i}\"/>\n    <origin xyz=\"0.0{} {} 0.12\" rpy=\"0 0 {}\"/>\n    <axis xyz=\"{axis}\"/>\n    <limit lower=\"-2\" upper=\"2\" effort=\"50\" velocity=\"3\"/>\n  </joint>\n",
            i % 9,
            0.15 * ((i % 3) as f64 - 1.0),
            0.1 * (i % 4) as f64
        );
    }
    u.push_str("</robot>\n");
    files.push(("gen/urdf/gen_tree.urdf".to_string(), u.into_bytes()));
    files
}

/// Every file under `dir` as (path relative to `dir` with `/` separators, bytes), in a stable
/// order: how tests, benchmarks and examples read a bundle folder (the command line's bounded
/// reader is `cad2mo::read_bundle`; the engine itself never touches the file system).
pub fn files_under(dir: &std::path::Path) -> Vec<(String, Vec<u8>)> {
    let mut files = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        let Ok(entries) = std::fs::read_dir(&d) else { continue };
        for entry in entries.flatten() {
            let p = entry.path();
            if p.is_dir() {
                stack.push(p);
            } else if let (Ok(bytes), Ok(rel)) = (std::fs::read(&p), p.strip_prefix(dir)) {
                let rel = rel.components().map(|c| c.as_os_str().to_string_lossy()).collect::<Vec<_>>().join("/");
                files.push((rel, bytes));
            }
        }
    }
    files.sort();
    files
}

/// A URDF chain of `links` revolute links whose visuals all name one OBJ: a `k`×`k` grid of
/// vertices, `2(k-1)²` triangles (k = 317: 199,712), with no visual origin or scale (issue 26's
/// reproducer of a mesh named by many links: 25 links of k = 317 are 4.99 M triangles after
/// instancing, just within the bundle's budget).
pub fn urdf_shared_obj(links: usize, k: usize) -> Vec<(String, Vec<u8>)> {
    use std::fmt::Write as _;
    let mut obj = String::new();
    for i in 0..k {
        for j in 0..k {
            let (x, y) = (i as f64 / k as f64 * 0.1, j as f64 / k as f64 * 0.1);
            let _ = writeln!(obj, "v {x} {y} {}", 0.002 * ((i * 7 + j * 3) % 5) as f64);
        }
    }
    for i in 0..k - 1 {
        for j in 0..k - 1 {
            let (a, b, c, d) = (i * k + j + 1, i * k + j + 2, (i + 1) * k + j + 1, (i + 1) * k + j + 2);
            let _ = writeln!(obj, "f {a} {b} {d}\nf {a} {d} {c}");
        }
    }
    let mut u = String::from("<?xml version=\"1.0\"?>\n<robot name=\"shared\">\n");
    for i in 0..links {
        let _ = writeln!(
            u,
            "  <link name=\"l{i}\">\n    <inertial><mass value=\"1\"/><inertia ixx=\"0.01\" ixy=\"0\" ixz=\"0\" iyy=\"0.01\" iyz=\"0\" izz=\"0.01\"/></inertial>\n    <visual><geometry><mesh filename=\"package://shared/meshes/plate.obj\"/></geometry></visual>\n  </link>"
        );
    }
    for i in 1..links {
        let _ = writeln!(
            u,
            "  <joint name=\"j{i}\" type=\"revolute\"><parent link=\"l{}\"/><child link=\"l{i}\"/><origin xyz=\"0 0 0.1\"/><axis xyz=\"0 0 1\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/></joint>",
            i - 1
        );
    }
    u.push_str("</robot>\n");
    vec![("shared/urdf/shared.urdf".to_string(), u.into_bytes()), ("shared/meshes/plate.obj".to_string(), obj.into_bytes())]
}
