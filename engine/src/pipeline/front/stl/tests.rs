//! Unit tests of the STL front end: test-only code, declared by the parent under `#[cfg(test)]`.

use super::*;
use std::path::PathBuf;

/// Every `.stl`/`.STL` under `fixtures/stl`, sorted.
pub(crate) fn fixture_stls() -> Vec<PathBuf> {
    crate::pipeline::testutil::fixtures_dir()
        .map(|dir| crate::pipeline::testutil::files_with_ext(&dir.join("stl"), "stl"))
        .unwrap_or_default()
}

fn tri_mesh() -> ir::Mesh {
    ir::Mesh {
        vertices: vec![[0.0, 0.0, 0.0], [1.5, 0.0, 0.0], [0.0, 2.25, 0.0], [0.0, 0.0, -3.0], [1e-7, 1e30, -0.0]],
        triangles: vec![[0, 1, 2], [0, 2, 3], [1, 3, 4], [4, 4, 4]],
    }
}

/// Triangles as corner positions (independent of vertex numbering).
fn soup(m: &ir::Mesh) -> Vec<[[u32; 3]; 3]> {
    m.triangles.iter().map(|t| t.map(|i| m.vertices[i as usize].map(f32::to_bits))).collect()
}

fn ascii_of(m: &ir::Mesh, name: &str) -> String {
    let mut s = format!("solid {name}\n");
    for t in &m.triangles {
        s += "  facet normal 0 0 1\n    outer loop\n";
        for &i in t {
            let v = m.vertices[i as usize];
            s += &format!("      vertex {:e} {:e} {:e}\n", v[0], v[1], v[2]);
        }
        s += "    endloop\n  endfacet\n";
    }
    s + &format!("endsolid {name}\n")
}

fn kind(r: Result<ir::Mesh, StlError>) -> ErrorKind {
    r.expect_err("should fail").kind
}

#[test]
fn binary_round_trip() {
    let m = tri_mesh();
    let bytes = crate::pipeline::back::stl::write_binary(&m, "part");
    assert!(is_binary(&bytes));
    let back = parse("part.stl", &bytes, 1.0).expect("parses");
    assert_eq!(soup(&back), soup(&m));
}

#[test]
fn ascii_round_trip_and_welding() {
    let m = tri_mesh();
    let back = parse("part.stl", ascii_of(&m, "part").as_bytes(), 1.0).expect("parses");
    assert_eq!(soup(&back), soup(&m));
    assert_eq!(back.vertices.len(), 5, "shared corners are welded");
}

#[test]
fn scale_is_applied_in_f64() {
    let text = "solid s\nfacet normal 0 0 0\nouter loop\nvertex 1 2 3\nvertex 1000 0.1 -7\nvertex 0 0 0\nendloop\nendfacet\nendsolid s\n";
    let m = parse("s.stl", text.as_bytes(), 0.001).expect("parses");
    let f = |x: f64| (x * 0.001) as f32;
    assert_eq!(m.vertices[0], [f(1.0), f(2.0), f(3.0)]);
    assert_eq!(m.vertices[1], [1.0, f(0.1), f(-7.0)]);
    let bin = crate::pipeline::back::stl::write_binary(&m, "s");
    let m2 = parse("s.stl", &bin, 1000.0).expect("parses");
    assert_eq!(m2.vertices[1][0], 1000.0);
    assert_eq!(m2.vertices[0][2], (f64::from(0.003f32) * 1000.0) as f32);
}

/// A binary file whose header begins with `solid` and whose size fits the rule is binary.
#[test]
fn solid_header_binary_trap() {
    let mut bytes = crate::pipeline::back::stl::write_binary(&tri_mesh(), "x");
    let header = b"solid trap facet normal outer loop vertex";
    bytes[..80].fill(b' ');
    bytes[..header.len()].copy_from_slice(header);
    assert!(is_binary(&bytes));
    let m = parse("trap.stl", &bytes, 1.0).expect("binary");
    assert_eq!(m.triangles.len(), 4);
    // The same file, truncated: reported as a truncated binary file, not an ASCII syntax error.
    let e = parse("trap.stl", &bytes[..bytes.len() - 7], 1.0).expect_err("truncated");
    assert_eq!(e.kind, ErrorKind::TruncatedBinary { declared: 4, available: bytes.len() - 7 });
    assert_eq!(e.line, 0);
}

#[test]
fn ascii_tolerance() {
    let text = "\u{feff}  SOLID Part One\r\n facet normal 1.0E+000 0 0\r\n\touter loop\r\n vertex 1.5e-005 +2 -3.\r\nvertex .5 0 0 vertex 0 0 0\r\nendloop endfacet\r\nendsolid\r\nsolid second\nfacet outer loop vertex 1 1 1 vertex 2 2 2 vertex 3 3 3 endloop endfacet\n\0\0";
    let m = parse("t.stl", text.as_bytes(), 1.0).expect("parses");
    assert_eq!(m.triangles.len(), 2);
    assert_eq!(m.vertices[0], [1.5e-5, 2.0, -3.0]);
    // Old-Mac CR-only line ends.
    let cr = "solid a\rfacet normal 0 0 1\router loop\rvertex 0 0 0\rvertex 1 0 0\rvertex 0 1 0\rendloop\rendfacet\rendsolid a\r";
    assert_eq!(parse("cr.stl", cr.as_bytes(), 1.0).expect("parses").triangles.len(), 1);
    // Empty solid.
    assert_eq!(parse("e.stl", b"solid empty\nendsolid empty\n", 1.0).expect("parses").triangles.len(), 0);
}

#[test]
fn ascii_errors_name_file_and_line() {
    let two = "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\nendfacet\nendsolid\n";
    let e = parse("meshes/arm.stl", two.as_bytes(), 1.0).expect_err("two vertices");
    assert_eq!(e.to_string(), "meshes/arm.stl:6: expected \"vertex\", found \"endloop\"");
    let four = two.replace("endloop", "vertex 0 1 0\nvertex 1 1 0\nendloop");
    let e = parse("a.stl", four.as_bytes(), 1.0).expect_err("four vertices");
    assert_eq!((e.line, e.kind), (7, ErrorKind::UnexpectedToken { expected: "\"endloop\"", found: Some("vertex".into()) }));
    let bad = two.replace("vertex 1 0 0", "vertex 1 0x 0");
    let e = parse("a.stl", bad.as_bytes(), 1.0).expect_err("bad number");
    assert_eq!((e.line, e.kind), (5, ErrorKind::BadNumber { text: "0x".into() }));
    let inf = two.replace("vertex 1 0 0", "vertex 1 1e39 0");
    assert_eq!(kind(parse("a.stl", inf.as_bytes(), 1.0)), ErrorKind::NonFinite { facet: 1 });
    let nan = two.replace("vertex 1 0 0", "vertex 1 NaN 0");
    assert_eq!(kind(parse("a.stl", nan.as_bytes(), 1.0)), ErrorKind::NonFinite { facet: 1 });
    let e = parse("a.stl", b"solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0", 1.0).expect_err("eof");
    assert_eq!(e.to_string(), "a.stl:4: expected a number, found end of file");
    let e = parse("a.stl", b"solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 endloop", 1.0).expect_err("word");
    assert_eq!(e.kind, ErrorKind::UnexpectedToken { expected: "a number", found: Some("endloop".into()) });
    let e = parse("a.stl", b"solid s\n  facets", 1.0).expect_err("junk");
    assert_eq!(e.to_string(), "a.stl:2: expected \"facet\" or \"endsolid\", found \"facets\"");
    let e = parse("a.stl", b"solid s\nendsolid s\ngarbage", 1.0).expect_err("junk after endsolid");
    assert_eq!(e.line, 3);
}

#[test]
fn whole_file_errors() {
    assert_eq!(kind(parse("a.stl", b"", 1.0)), ErrorKind::TooShort { len: 0 });
    assert_eq!(kind(parse("a.stl", b"hello", 1.0)), ErrorKind::TooShort { len: 5 });
    let mut b = vec![0u8; 84 + 50 * 3];
    b[80] = 4;
    assert_eq!(kind(parse("a.stl", &b, 1.0)), ErrorKind::TruncatedBinary { declared: 4, available: 234 });
    b[80] = 2;
    let e = parse("a.stl", &b, 1.0).expect_err("too long");
    assert_eq!(e.kind, ErrorKind::NotStl { len: 234, declared: 2 });
    assert_eq!(
        e.to_string(),
        "a.stl: not an STL file: it does not begin with \"solid\" (ASCII) and its size, 234 bytes, is not 84 + 50 × 2 = 184 (binary)"
    );
    b[80] = 3;
    assert_eq!(parse("a.stl", &b, 1.0).expect("binary").triangles.len(), 3);
    // A NaN corner in a binary file.
    b[84 + 50 + 12..84 + 50 + 16].copy_from_slice(&f32::NAN.to_le_bytes());
    assert_eq!(kind(parse("a.stl", &b, 1.0)), ErrorKind::NonFinite { facet: 2 });
}

#[test]
fn is_binary_is_the_size_rule() {
    assert!(!is_binary(&[0; 83]));
    assert!(is_binary(&[0; 84]));
    assert!(!is_binary(&[0; 85]));
    let mut b = vec![b' '; 134];
    b[80..84].copy_from_slice(&1u32.to_le_bytes());
    assert!(is_binary(&b));
}

/// Triangle count of a fixture as the file itself states it: the binary header count, or the
/// number of `facet` keywords (`endfacet` excluded).
fn stated_count(bytes: &[u8]) -> usize {
    if is_binary(bytes) {
        u32::from_le_bytes([bytes[80], bytes[81], bytes[82], bytes[83]]) as usize
    } else {
        bytes.split(|c| c.is_ascii_whitespace()).filter(|t| t.eq_ignore_ascii_case(b"facet")).count()
    }
}

#[test]
fn every_fixture_parses() {
    let files = fixture_stls();
    if files.is_empty() {
        return;
    }
    let mut seen_trap = false;
    for p in &files {
        let bytes = std::fs::read(p).expect("read fixture");
        let name = p.display().to_string();
        let m = parse(&name, &bytes, 0.001).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(m.triangles.len(), stated_count(&bytes), "{name}");
        assert!(!m.triangles.is_empty(), "{name}");
        assert!(m.vertices.len() < 3 * m.triangles.len(), "{name}: nothing welded");
        assert!(m.triangles.iter().flatten().all(|&i| (i as usize) < m.vertices.len()));
        let (lo, hi) = m.bounds().expect("bounds");
        let size = (0..3).map(|k| hi[k] - lo[k]).fold(0.0f32, f32::max);
        assert!(size > 0.0 && size.is_finite(), "{name}: size {size}");
        if bytes.starts_with(b"solid") && is_binary(&bytes) {
            seen_trap = true;
        }
    }
    assert!(seen_trap, "the fixtures include a binary file with a `solid` header");
    eprintln!("{} fixture STL files parsed", files.len());
}

/// Every number token of every ASCII fixture: the fast parser gives exactly the std result.
#[test]
fn fast_number_parser_matches_std_on_fixture_tokens() {
    let (mut n, mut slow) = (0usize, 0usize);
    for p in fixture_stls() {
        let bytes = std::fs::read(&p).expect("read fixture");
        if is_binary(&bytes) {
            continue;
        }
        for t in bytes.split(|c| c.is_ascii_whitespace()) {
            let Ok(s) = std::str::from_utf8(t) else { continue };
            let Ok(want) = s.parse::<f64>() else { continue };
            // What the reader does: the fast path when it takes the whole token, else std.
            let got = match number::parse_f64(t, 0) {
                Some((v, end)) if end == t.len() => {
                    assert_eq!(v.to_bits(), want.to_bits(), "{s}");
                    v
                }
                _ => {
                    slow += 1;
                    want
                }
            };
            // With scale 1 the stored f32 equals a direct f32 parse (no double rounding on
            // 7-digit tokens).
            assert_eq!((got as f32).to_bits(), s.parse::<f32>().expect("f32").to_bits(), "{s}");
            n += 1;
        }
    }
    eprintln!("{n} fixture number tokens checked, {slow} of them through the std parser");
    assert!(slow * 100 <= n, "the fast path takes almost every real token");
}

fn check_no_panic(name: &str, bytes: &[u8]) {
    // Any result is fine; the point is not panicking (and not allocating absurdly).
    let _ = parse(name, bytes, 0.001);
}

#[test]
fn truncated_and_garbled_inputs_never_panic() {
    // Whole binary fixtures; the first 64 KB of ASCII ones (cut at a line end: still valid, and
    // any cut point of a long file is like any other) to keep the test fast in debug builds.
    let mut inputs: Vec<(String, Vec<u8>)> = fixture_stls()
        .into_iter()
        .filter_map(|p| {
            let mut b = std::fs::read(&p).ok()?;
            if !is_binary(&b) && b.len() > 65_536 {
                let end = b[..65_536].iter().rposition(|&c| c == b'\n').unwrap_or(65_536);
                b.truncate(end + 1);
            }
            Some((p.display().to_string(), b))
        })
        .collect();
    let m = tri_mesh();
    inputs.push(("own.stl".into(), crate::pipeline::back::stl::write_binary(&m, "own")));
    inputs.push(("own-ascii.stl".into(), ascii_of(&m, "own").into_bytes()));
    let mut x: u64 = 0x2545_F491_4F6C_DD1D;
    let mut rnd = move || {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        x
    };
    for (name, bytes) in &inputs {
        // Truncated prefixes: every length for the first 600 bytes, then spread over the file.
        let len = bytes.len();
        let cuts: Vec<usize> = (0..len.min(600)).chain((0..200).map(|k| k * len / 200)).collect();
        for cut in cuts {
            let r = parse(name, &bytes[..cut], 1.0);
            if cut < len && is_binary(bytes) {
                // A cut binary file is an error, except a prefix that happens to fit the size rule
                // and a cut inside a `solid ...` header (a valid empty ASCII STL).
                let ok = match &r {
                    Err(_) => true,
                    Ok(m) => is_binary(&bytes[..cut]) || (cut < 84 && m.triangles.is_empty()),
                };
                assert!(ok, "{name} cut at {cut}");
            }
        }
        // Random byte flips, insertions of keywords and digits.
        for _ in 0..60 {
            let mut b = bytes.clone();
            for _ in 0..1 + rnd() % 8 {
                let i = (rnd() as usize) % b.len().max(1);
                if b.is_empty() {
                    break;
                }
                match rnd() % 4 {
                    0 => b[i] = rnd() as u8,
                    1 => b[i] = b" 0123456789.eE+-\n"[(rnd() % 17) as usize],
                    2 => b.truncate(i),
                    _ => {
                        let words: [&[u8]; 6] = [b"vertex", b"endloop", b"facet", b"solid", b"1e999", b"nan"];
                        let w = words[(rnd() % 6) as usize];
                        b.splice(i..i, w.iter().copied());
                    }
                }
            }
            check_no_panic(name, &b);
        }
    }
    // Pure garbage, including "solid" followed by random bytes and a huge declared count.
    for k in 0..300 {
        let mut b: Vec<u8> = (0..(rnd() % 400) as usize).map(|_| rnd() as u8).collect();
        if k % 3 == 0 {
            b.splice(0..0, b"solid ".iter().copied());
        }
        if k % 5 == 0 && b.len() >= 84 {
            b[80..84].copy_from_slice(&u32::MAX.to_le_bytes());
        }
        check_no_panic("garbage.stl", &b);
    }
}

#[test]
fn too_many_triangles_in_header() {
    // A binary file can't declare more than the cap without being that big; check the guard
    // directly through the size error path and the cap constant.
    let mut b = vec![0u8; 84];
    b[80..84].copy_from_slice(&u32::MAX.to_le_bytes());
    assert_eq!(kind(parse("a.stl", &b, 1.0)), ErrorKind::TruncatedBinary { declared: u32::MAX, available: 84 });
    assert!(MAX_TRIANGLES < u64::from(u32::MAX));
}
