//! The fuzz targets' bodies, as plain functions: each takes the fuzzer's bytes and panics only on
//! a bug (a panic in the pipeline, or an output that breaks the target's check). The libFuzzer
//! binaries in `fuzz_targets/` call them, and `engine/tests/fuzz_regressions.rs` includes this
//! file to replay every input under `fuzz/regressions/<target>/` on a normal `cargo test`.

use cad2mo_engine::pipeline::{
    self,
    front::bundle::{Bundle, Limits},
    front::{mesh, simmechanics, stl, vrml},
};

/// A target's name and body.
pub type Target = (&'static str, fn(&[u8]));

/// The targets by name, as `fuzz/regressions/<name>/` and `cargo fuzz run <name>` call them.
pub const TARGETS: [Target; 11] = [
    ("xml", xml),
    ("stl", stl),
    ("vrml", vrml),
    ("bundle_zip", bundle_zip),
    ("convert", convert),
    ("mat", mat),
    ("live", live),
    ("urdf", urdf),
    ("dae", dae),
    ("urdf_tree", urdf_tree),
    ("step", step),
];

/// A URDF -> `front::urdf::parse`; when it parses, the whole conversion of a bundle holding just
/// that file (no shapes written): errors are fine, panics and non-finite outputs are not.
pub fn urdf(data: &[u8]) {
    match pipeline::front::urdf::parse("fuzz.urdf", data) {
        Ok(_) => {}
        Err(e) => {
            let _ = e.to_string();
            return;
        }
    }
    convert_urdf(data.to_vec());
}

/// The whole conversion of a bundle holding just `robot.urdf` (no shapes written): errors are
/// fine, panics and non-finite masses are not.
fn convert_urdf(urdf: Vec<u8>) {
    let Ok(bundle) = Bundle::from_files("fuzz", [("robot.urdf".to_string(), urdf)]) else { return };
    let opts = pipeline::Options { write_shapes: false, ..Default::default() };
    if let Ok(out) = pipeline::convert(&bundle, &opts) {
        for b in &out.report.bodies {
            assert!(b.mass.is_finite(), "a converted mass is not finite");
        }
    }
}

/// COLLADA bytes -> `front::mesh::read` as a `.dae`; when it reads, the `ir::Mesh` invariants
/// hold (triangles, finite vertices, indices in range).
pub fn dae(data: &[u8]) {
    match mesh::read("fuzz.dae", data) {
        Ok(m) => {
            assert!(!m.triangles.is_empty(), "a mesh without triangles was returned");
            assert!(m.vertices.iter().flatten().all(|x| x.is_finite()), "a vertex is not finite");
            let n = m.vertices.len();
            assert!(m.triangles.iter().flatten().all(|&i| (i as usize) < n), "an index is out of range");
        }
        Err(e) => {
            let _ = e.to_string();
        }
    }
}

/// STEP bytes -> `front::mesh::step::read`; when it reads, the `ir::Mesh` invariants hold and
/// every solid's triangle range lies in the mesh. The reader contains panics of the third-party
/// B-rep crates it calls (`catch_unwind`, reported as errors naming the file), so this target
/// replaces libFuzzer's abort-on-panic hook with a silent one: a contained panic is the reader
/// working as documented, and a panic that escapes `read` still fails the run (libfuzzer-sys
/// aborts on any panic leaving the target).
pub fn step(data: &[u8]) {
    static HOOK: std::sync::Once = std::sync::Once::new();
    HOOK.call_once(|| std::panic::set_hook(Box::new(|_| {})));
    match mesh::step::read("fuzz.step", data) {
        Ok(m) => {
            let n = m.mesh.vertices.len();
            assert!(m.mesh.vertices.iter().flatten().all(|x| x.is_finite()), "a vertex is not finite");
            assert!(m.mesh.triangles.iter().flatten().all(|&i| (i as usize) < n), "an index is out of range");
            assert!(m.solids.iter().all(|r| r.start <= r.end && r.end <= m.mesh.triangles.len()), "a solid's range is out of the mesh");
        }
        Err(e) => assert!(e.to_string().starts_with("fuzz.step: "), "an error not naming the file: {e}"),
    }
}

/// A simulation result (MAT v4 bytes) -> `results::mat::Trajectory::read`; when it reads, what
/// the service does with it: the summary, variable search, every series (of the first 64
/// variables) thinned for a plot, and Dymola's visual shapes with their pose stream.
pub fn mat(data: &[u8]) {
    use cad2mo_engine::results::{self, mat::Trajectory, shapes::Scene};
    let t = match Trajectory::read(data, "fuzz.mat") {
        Ok(t) => t,
        Err(e) => {
            let _ = e.to_string();
            return;
        }
    };
    let _ = results::standalone(&t);
    let _ = results::search(&t, "frame_a", 20);
    let time = t.time();
    for v in 0..t.variables.len().min(64) {
        let y = t.series(v);
        let _ = results::decimate(&time, &y, 100);
    }
    let scene = Scene::find(&t);
    let _ = scene.stream(&t);
    // What the service stores: only a file whose every value is finite, and then its summary
    // must survive JSON (a non-finite number would not).
    if t.check_finite("fuzz.mat").is_ok() {
        let summary = results::standalone(&t);
        let json = serde_json::to_string(&summary).expect("a finite result's summary serialises");
        serde_json::from_str::<results::Summary>(&json).expect("a finite result's summary reads back");
    }
}

/// A live view datagram -> `live::decode`, then the signature check and the poses, as the relay
/// does (with a fixed key: a random frame's tag must not verify, and nothing may panic).
pub fn live(data: &[u8]) {
    use cad2mo_engine::live;
    let Ok(f) = live::decode(data) else { return };
    let _ = f.model_id();
    let key = [7u8; 32];
    let _ = live::verify(&f, &key);
    let mut poses = Vec::new();
    if live::poses_into(&f, &mut poses).is_ok() {
        assert_eq!(poses.len(), 7 * f.body_count());
        assert!(poses.iter().all(|x| x.is_finite()), "a relayed pose is not finite");
    }
    let mut run = live::RunStats::new(f.run);
    let _ = run.accept(f.seq, f.time, f.is_final(), 0.0);
}

/// First-generation SimMechanics XML bytes -> `front::simmechanics::parse` (and the sniffer).
pub fn xml(data: &[u8]) {
    let _ = simmechanics::is_physical_modeling_xml(data);
    if let Err(e) = simmechanics::parse("fuzz.xml", data) {
        // Messages are formatted on demand: run that code too.
        let _ = e.to_string();
    }
}

/// STL bytes (ASCII or binary) -> `front::stl::parse`, in mm (the common export unit).
pub fn stl(data: &[u8]) {
    let _ = stl::is_binary(data);
    match stl::parse("fuzz.stl", data, 0.001) {
        Ok(mesh) => {
            let _ = format!("{mesh:?}").len();
        }
        Err(e) => {
            let _ = e.to_string();
        }
    }
}

/// One VRML file (VRML 97 or 1.0; gzip when it begins with `1f 8b`, which the front end
/// decides) as a bundle with one main file -> `front::vrml::parse`. An Inline or EXTERNPROTO can
/// only name the file itself (a cycle) or nothing.
pub fn vrml(data: &[u8]) {
    let _ = vrml::is_vrml(data);
    let Ok(bundle) = Bundle::from_files("fuzz", [("main.wrl".to_string(), data.to_vec())]) else {
        return;
    };
    let _ = vrml::main_files(&bundle);
    if let Err(e) = vrml::parse(&bundle, "main.wrl") {
        let _ = e.to_string();
    }
}

/// Zip bytes -> `Bundle::from_zip` with the default limits; when it reads, `pipeline::analyse`
/// on it: the whole front end (XML, STL, VRML, matching.json) and the passes (lumping, loops,
/// kinematics, validation). The last byte's low bit turns weld lumping on.
pub fn bundle_zip(data: &[u8]) {
    let bundle = match Bundle::from_zip("fuzz.zip", data, &Limits::default()) {
        Ok(b) => b,
        Err(e) => {
            let _ = e.to_string();
            return;
        }
    };
    let lump_welds = data.last().is_some_and(|b| b & 1 == 1);
    let opts = pipeline::Options { write_shapes: false, lump_welds, ..Default::default() };
    if let Err(e) = pipeline::analyse(&bundle, &opts) {
        let _ = e.diagnostics();
    }
}

/// XML bytes -> the whole conversion (`pipeline::convert`, shapes off). Every `.stl` the XML
/// names is supplied as one 10 mm cube, so bodies get geometry and the geometry checks run. The
/// conversion must not panic, and when it succeeds every number in `Mechanics.mo` must be
/// finite: no `inf` or `NaN` token outside strings and comments.
pub fn convert(data: &[u8]) {
    // The meshes the XML names (when it parses; otherwise the conversion fails the same way).
    let names: Vec<String> = match simmechanics::parse("model.xml", data) {
        Ok((model, _)) => model.bodies.iter().filter_map(|b| b.geometry_file.clone()).collect(),
        Err(_) => Vec::new(),
    };
    let mut files = vec![("model.xml".to_string(), data.to_vec())];
    let cube = cube();
    for n in names {
        if files.iter().any(|(p, _)| p.eq_ignore_ascii_case(&n)) || !n.to_ascii_lowercase().ends_with(".stl") {
            continue;
        }
        files.push((n, cube.clone()));
    }
    // Names that are unsafe paths or duplicates after normalisation: no meshes then.
    let bundle = Bundle::from_files("fuzz", files.clone()).or_else(|_| Bundle::from_files("fuzz", files.into_iter().take(1)));
    let Ok(bundle) = bundle else { return };
    let opts = pipeline::Options { write_shapes: false, ..Default::default() };
    let out = match pipeline::convert(&bundle, &opts) {
        Ok(out) => out,
        Err(e) => {
            let _ = e.diagnostics();
            return;
        }
    };
    let mechanics = out.files.iter().find(|(p, _)| p.ends_with("/Mechanics.mo"));
    let (path, bytes) = mechanics.expect("a successful conversion writes Mechanics.mo");
    let bytes = bytes.bytes();
    let text = std::str::from_utf8(&bytes).expect("Mechanics.mo is UTF-8");
    let bad = non_finite_tokens(text);
    if let Some(&at) = bad.first() {
        let line = text[..at].matches('\n').count() + 1;
        let l = text.lines().nth(line - 1).unwrap_or("");
        panic!("{path}:{line}: non-finite number in the emitted Modelica: {l}");
    }
}

/// A 10 mm cube, ASCII STL (12 facets).
fn cube() -> Vec<u8> {
    let v = |i: u32| [(i & 1) as f64 * 10.0, (i >> 1 & 1) as f64 * 10.0, (i >> 2 & 1) as f64 * 10.0];
    let faces: [[u32; 4]; 6] = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]];
    let mut s = String::from("solid cube\n");
    for f in faces {
        for t in [[f[0], f[1], f[2]], [f[0], f[2], f[3]]] {
            s.push_str(" facet normal 0 0 0\n  outer loop\n");
            for i in t {
                let p = v(i);
                s.push_str(&format!("   vertex {} {} {}\n", p[0], p[1], p[2]));
            }
            s.push_str("  endloop\n endfacet\n");
        }
    }
    s.push_str("endsolid cube\n");
    s.into_bytes()
}

/// Byte offsets of `inf`/`nan` tokens used as values (after `=`, `,`, `{`, `(` or a sign;
/// not a component reference) outside strings and comments.
pub fn non_finite_tokens(mo: &str) -> Vec<usize> {
    let b = mo.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    let mut prev = b' ';
    while i < b.len() {
        let c = b[i];
        if c == b'"' {
            i += 1;
            while i < b.len() && b[i] != b'"' {
                i += if b[i] == b'\\' { 2 } else { 1 };
            }
            i += 1;
            prev = b'"';
        } else if b[i..].starts_with(b"//") {
            while i < b.len() && b[i] != b'\n' {
                i += 1;
            }
        } else if b[i..].starts_with(b"/*") {
            i += 2;
            while i < b.len() && !b[i..].starts_with(b"*/") {
                i += 1;
            }
            i += 2;
        } else if c.is_ascii_alphabetic() || c == b'_' {
            let start = i;
            while i < b.len() && (b[i].is_ascii_alphanumeric() || b[i] == b'_') {
                i += 1;
            }
            let word = mo[start..i].to_ascii_lowercase();
            let next = b[i..].iter().copied().find(|c| !c.is_ascii_whitespace()).unwrap_or(b';');
            let as_value = matches!(prev, b'=' | b',' | b'{' | b'(' | b'-' | b'+' | b'*' | b'/');
            if matches!(word.as_str(), "inf" | "nan" | "infinity") && as_value && !matches!(next, b'.' | b'(' | b'[') {
                out.push(start);
            }
            prev = b'a';
        } else {
            if !c.is_ascii_whitespace() {
                prev = c;
            }
            i += 1;
        }
    }
    out
}

/// A URDF built from the bytes, so that the fuzzer explores structures rather than syntax:
/// every 12 bytes are one link hanging from an earlier link (or the base) by a joint of a type,
/// axis (zero allowed), origin and rotation the bytes choose, with a mass and inertia the bytes
/// choose (zero and degenerate allowed); a joint byte may also make it a mimic of the previous
/// joint, and the last bytes may close a Drake loop joint between two links. The conversion
/// may refuse it (errors are fine); it must not panic, and what it accepts is finite.
pub fn urdf_tree(data: &[u8]) {
    convert_urdf(urdf_of_bytes(data).into_bytes());
}

/// The URDF text `urdf_tree` converts (at most 64 links).
pub fn urdf_of_bytes(data: &[u8]) -> String {
    use std::fmt::Write as _;
    const KINDS: [&str; 6] = ["fixed", "revolute", "continuous", "prismatic", "floating", "planar"];
    let signed = |b: u8| f64::from(b as i8) / 64.0;
    let mut links = String::from("  <link name=\"base\"/>\n");
    let mut joints = String::new();
    let chunks: Vec<&[u8]> = data.chunks_exact(12).take(64).collect();
    for (i, c) in chunks.iter().enumerate() {
        let parent = if c[0] as usize % (i + 1) == 0 { "base".to_string() } else { format!("l{}", c[0] as usize % (i + 1) - 1) };
        let kind = KINDS[c[1] as usize % KINDS.len()];
        let (mass, inertia) = (f64::from(c[8]) / 16.0, f64::from(c[9]) / 256.0);
        let _ = writeln!(
            links,
            "  <link name=\"l{i}\"><inertial><mass value=\"{mass}\"/><origin xyz=\"{} 0 0\"/><inertia ixx=\"{inertia}\" iyy=\"{inertia}\" izz=\"{}\" ixy=\"{}\" ixz=\"0\" iyz=\"0\"/></inertial></link>",
            signed(c[10]),
            inertia * 2.0,
            signed(c[11]) / 64.0,
        );
        let limit =
            if kind == "revolute" || kind == "prismatic" { "<limit lower=\"-1\" upper=\"1\" effort=\"10\" velocity=\"1\"/>" } else { "" };
        // Any joint, before or after this one: chains and rings of mimics.
        let mimic = if c[1] >= 200 && i > 0 {
            format!("<mimic joint=\"j{}\" multiplier=\"{}\"/>", c[11] as usize % chunks.len(), signed(c[7]))
        } else {
            String::new()
        };
        let _ = writeln!(
            joints,
            "  <joint name=\"j{i}\" type=\"{kind}\"><parent link=\"{parent}\"/><child link=\"l{i}\"/><origin xyz=\"{} {} {}\" rpy=\"{} {} {}\"/><axis xyz=\"{} {} {}\"/>{limit}{mimic}</joint>",
            signed(c[5]),
            signed(c[6]),
            signed(c[7]) / 4.0,
            signed(c[2]) * 3.0,
            signed(c[3]) * 3.0,
            signed(c[4]) * 3.0,
            signed(c[2]).round(),
            signed(c[3]).round(),
            signed(c[4]),
        );
    }
    let rest = &data[chunks.len() * 12..];
    if let [a, b, ..] = rest {
        if !chunks.is_empty() {
            let (a, b) = (*a as usize % chunks.len(), *b as usize % chunks.len());
            let _ = writeln!(
                joints,
                "  <loop_joint name=\"loop\" type=\"revolute\"><axis xyz=\"0 0 1\"/><link1 link=\"l{a}\" xyz=\"0 0 0\" rpy=\"0 0 0\"/><link2 link=\"l{b}\" xyz=\"0 0 0\" rpy=\"0 0 0\"/></loop_joint>"
            );
        }
    }
    format!("<?xml version=\"1.0\"?>\n<robot name=\"fuzz\">\n{links}{joints}</robot>\n")
}
