//! The collision C code a package ships (`Resources/Include/cad2mo_collision.c`), compiled with
//! the system C compiler into `tests/collision/harness.c`: GJK/EPA against parry3d on 10,000
//! random convex pairs, a drop test of the contact law against its coefficient of restitution,
//! the shape file a converted package ships read by the C code from the unzipped package (as a
//! Modelica tool resolves its `modelica://` URI), with its errors, and the `Components.Collision`
//! Modelica text through msl-check and rumoca.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use cad2mo_engine::collision::ConvexPart;
use cad2mo_engine::pipeline::back::modelica::mechatronics::collision;
use cad2mo_tests::common::{modelica_syntax_errors, msl_check, tools_required, workspace_root};
use parry3d_f64::na::{Isometry3, Matrix3, Point3, Quaternion, Translation3, UnitQuaternion, Vector3};
use parry3d_f64::shape::{Ball, ConvexPolyhedron, Segment, Shape};

fn compiler() -> String {
    std::env::var("CC").unwrap_or_else(|_| "cc".to_string())
}

/// The C source as the package ships it.
fn shipped_c() -> String {
    let files = collision::files("P");
    let (_, bytes) = files.iter().find(|(p, _)| p == "P/Resources/Include/cad2mo_collision.c").expect("C source in the package");
    String::from_utf8(bytes.clone()).expect("utf-8")
}

/// Compiles the harness with every warning an error, plain C99 and pedantic too; also the C
/// source alone (as a tool includes it). `None` without a C compiler (tools not required).
fn build(dir: &Path) -> Option<PathBuf> {
    if Command::new(compiler()).arg("--version").output().is_err() {
        assert!(!tools_required(), "the collision tests need a C compiler ({})", compiler());
        println!("NOTICE: no C compiler ({}): the collision harness is not built", compiler());
        return None;
    }
    std::fs::write(dir.join("cad2mo_collision.c"), shipped_c()).expect("write the C source");
    let inc = workspace_root().join("tests/collision");
    let exe = dir.join("harness");
    for flags in [&["-O2"][..], &["-O2", "-std=c99", "-D_POSIX_C_SOURCE=200809L", "-pedantic"][..]] {
        let out = Command::new(compiler())
            .args(flags)
            .args(["-Wall", "-Wextra", "-Werror"])
            .arg("-I")
            .arg(&inc)
            .arg("-I")
            .arg(dir)
            .arg(inc.join("harness.c"))
            .arg("-o")
            .arg(&exe)
            .arg("-lm")
            .output()
            .expect("run the C compiler");
        assert!(out.status.success(), "the harness does not compile with {flags:?}:\n{}", String::from_utf8_lossy(&out.stderr));
        let alone = Command::new(compiler())
            .args(flags)
            .args(["-Wall", "-Wextra", "-Werror", "-c", "-x", "c"])
            .arg("-I")
            .arg(&inc)
            .arg(dir.join("cad2mo_collision.c"))
            .arg("-o")
            .arg(dir.join("alone.o"))
            .output()
            .expect("run the C compiler");
        assert!(alone.status.success(), "the C source alone does not compile with {flags:?}:\n{}", String::from_utf8_lossy(&alone.stderr));
    }
    Some(exe)
}

/// SplitMix64: reproducible random numbers without a dependency.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in [a, b).
    fn uniform(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * ((self.next() >> 11) as f64 / (1u64 << 53) as f64)
    }
    fn normal(&mut self) -> f64 {
        let u = self.uniform(1e-300, 1.0);
        let v = self.uniform(0.0, std::f64::consts::TAU);
        (-2.0 * u.ln()).sqrt() * v.cos()
    }
    fn rotation(&mut self) -> UnitQuaternion<f64> {
        UnitQuaternion::from_quaternion(Quaternion::new(self.normal(), self.normal(), self.normal(), self.normal()))
    }
    fn unit(&mut self) -> Vector3<f64> {
        Vector3::new(self.normal(), self.normal(), self.normal()).normalize()
    }
}

/// A random convex part: the hull of 4..=24 random points in a random box around a random
/// centre (frame_a coordinates), with a radius or not.
fn random_part(rng: &mut Rng, with_radius: bool) -> (Vec<Point3<f64>>, f64) {
    random_part_of(rng, with_radius, 4, 24)
}

/// [`random_part`] of `min..=max` points.
fn random_part_of(rng: &mut Rng, with_radius: bool, min: usize, max: usize) -> (Vec<Point3<f64>>, f64) {
    let n = min + (rng.next() % (max - min + 1) as u64) as usize;
    let size = Vector3::new(rng.uniform(0.05, 0.5), rng.uniform(0.05, 0.5), rng.uniform(0.05, 0.5));
    let centre = Vector3::new(rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3));
    let pts = (0..n)
        .map(|_| {
            Point3::from(
                centre + Vector3::new(rng.uniform(-1.0, 1.0) * size.x, rng.uniform(-1.0, 1.0) * size.y, rng.uniform(-1.0, 1.0) * size.z),
            )
        })
        .collect();
    let radius = if with_radius { rng.uniform(0.0, 0.1) } else { 0.0 };
    (pts, radius)
}

/// parry's side of a pair: A's core shape at its pose, the radius added to it, B's hull.
type Reference = (Box<dyn Shape>, Isometry3<f64>, f64, ConvexPolyhedron);

struct Case {
    a: (Vec<Point3<f64>>, f64, Isometry3<f64>),
    b: (Vec<Point3<f64>>, f64, Isometry3<f64>),
}

fn fmt(x: f64) -> String {
    format!("{x:.16e}")
}

/// One harness input line: the part's count, radius, vertices, then r_0 and R_T (row major).
fn part_text(pts: &[Point3<f64>], r: f64, pose: &Isometry3<f64>, out: &mut String) {
    out.push_str(&format!("{} {} ", pts.len(), fmt(r)));
    for p in pts {
        out.push_str(&format!("{} {} {} ", fmt(p.x), fmt(p.y), fmt(p.z)));
    }
    let t = pose.translation.vector;
    out.push_str(&format!("{} {} {} ", fmt(t.x), fmt(t.y), fmt(t.z)));
    let rt: Matrix3<f64> = pose.rotation.to_rotation_matrix().matrix().transpose();
    for i in 0..3 {
        for j in 0..3 {
            out.push_str(&format!("{} ", fmt(rt[(i, j)])));
        }
    }
}

fn angle(a: &Vector3<f64>, b: &Vector3<f64>) -> f64 {
    a.cross(b).norm().atan2(a.dot(b))
}

/// Support function of a point set grown by r, along n.
fn support(pts: &[Point3<f64>], r: f64, pose: &Isometry3<f64>, n: &Vector3<f64>) -> f64 {
    pts.iter().map(|p| (pose * p).coords.dot(n)).fold(f64::NEG_INFINITY, f64::max) + r
}

#[test]
fn gjk_epa_agree_with_parry_on_random_pairs() {
    let tmp = tempfile::tempdir().expect("tempdir");
    let Some(exe) = build(tmp.path()) else { return };
    let mut rng = Rng(0x00C0_111D_E5EE_D001);
    let mut cases = Vec::new();
    // parry's shape for A's core (a hull, a point for a sphere, a segment for a capsule), A's
    // radius (left out: added exactly), and the hull of B
    let mut refs: Vec<Reference> = Vec::new();
    while cases.len() < 10_000 {
        let k = cases.len();
        let with_radius = k % 2 == 1;
        // every tenth pair: A a sphere (k % 10 == 3), a capsule (7); big hulls of 50..=300 points (9)
        let (pa, ra) = match k % 10 {
            3 => (random_part_of(&mut rng, false, 1, 1).0, rng.uniform(0.02, 0.2)),
            7 => (random_part_of(&mut rng, false, 2, 2).0, rng.uniform(0.02, 0.1)),
            9 => random_part_of(&mut rng, with_radius, 50, 300),
            _ => random_part(&mut rng, with_radius),
        };
        let (pb, rb) = if k % 10 == 9 { random_part_of(&mut rng, with_radius, 50, 300) } else { random_part(&mut rng, with_radius) };
        let pose_a = Isometry3::from_parts(
            Translation3::from(Vector3::new(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0))),
            rng.rotation(),
        );
        // B near A: from deep inside to well apart (distances from the frame origins).
        let offset = rng.unit() * rng.uniform(0.0, 1.4);
        let pose_b = Isometry3::from_parts(Translation3::from(pose_a.translation.vector + offset), rng.rotation());
        let Some(hb) = ConvexPolyhedron::from_convex_hull(&pb) else { continue };
        let (shape_a, at, left_out): (Box<dyn Shape>, Isometry3<f64>, f64) = match pa.len() {
            // the cores (a point, a segment: parry's GJK converges exactly on polytopes, not on
            // its curved shapes), the radius added analytically as for hulls
            1 => (Box::new(Ball::new(0.0)), Isometry3::from_parts(Translation3::from((pose_a * pa[0]).coords), pose_a.rotation), ra),
            2 => (Box::new(Segment::new(pa[0], pa[1])), pose_a, ra),
            _ => {
                let Some(ha) = ConvexPolyhedron::from_convex_hull(&pa) else { continue };
                (Box::new(ha), pose_a, ra)
            }
        };
        cases.push(Case { a: (pa, ra, pose_a), b: (pb, rb, pose_b) });
        refs.push((shape_a, at, left_out, hb));
    }
    let mut input = String::new();
    for c in &cases {
        part_text(&c.a.0, c.a.1, &c.a.2, &mut input);
        part_text(&c.b.0, c.b.1, &c.b.2, &mut input);
        input.push('\n');
    }
    let input_lines: Vec<String> = input.lines().map(String::from).collect();
    let mut child = Command::new(&exe)
        .arg("query")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("start the harness");
    let mut stdin = child.stdin.take().expect("stdin");
    let feeder = std::thread::spawn(move || stdin.write_all(input.as_bytes()).expect("feed the harness"));
    let out = child.wait_with_output().expect("harness");
    feeder.join().expect("feeder");
    assert!(out.status.success(), "harness failed: {}", String::from_utf8_lossy(&out.stderr));
    let text = String::from_utf8(out.stdout).expect("utf-8");
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), cases.len(), "one answer per pair");

    let (mut max_d, mut max_n, mut max_cert, mut max_gap) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    let (mut separated, mut penetrating, mut normals_checked) = (0, 0, 0);
    let mut parry_off = Vec::new();
    let mut worst = String::new();
    for (k, (c, line)) in cases.iter().zip(&lines).enumerate() {
        let x: Vec<f64> = line.split_whitespace().map(|t| t.parse().expect("number")).collect();
        assert_eq!(x.len(), 11, "{line}");
        let (dist, pa, pb, n) = (x[1], Vector3::new(x[2], x[3], x[4]), Vector3::new(x[5], x[6], x[7]), Vector3::new(x[8], x[9], x[10]));
        let (shape_a, at, left_out, hb) = &refs[k];
        // parry on the hulls; a radius grows the distance exactly: d - ra - rb along the same normal
        let contact =
            parry3d_f64::query::contact(at, shape_a.as_ref(), &c.b.2, hb, 100.0).expect("supported").expect("within the prediction");
        let d_ref = contact.dist - left_out - c.b.1;
        let core = d_ref + c.a.1 + c.b.1; // between the parts' cores (vertices without radii)
        let n_ref = contact.normal1.into_inner();
        if d_ref < 0.0 {
            penetrating += 1;
        } else {
            separated += 1;
        }
        // the signed gap of the supports along a direction: the distance (separated) is the
        // largest over directions, minus the depth (penetrating) is too
        let gap_along = |m: &Vector3<f64>| -support(&c.b.0, c.b.1, &c.b.2, &-m) - support(&c.a.0, c.a.1, &c.a.2, m);
        // certificate of the C answer: the supports of A and B along n are `dist` apart, and the
        // witness points are `dist` apart along n
        let cert = gap_along(&n) - dist;
        max_cert = max_cert.max(cert.abs());
        max_gap = max_gap.max((pb - pa - n * dist).norm());
        // parry's answer must pass the same certificate to be a reference; where it does not (it
        // stopped short), the C answer must be at least as good along parry's own normal
        let cert_ref = gap_along(&n_ref) - d_ref;
        if cert_ref.abs() > 1e-9 {
            assert!(
                dist >= gap_along(&n_ref) - 1e-9,
                "pair {k}: C {dist} worse than the gap {} along parry's normal; harness input:\n{}",
                gap_along(&n_ref),
                input_lines[k]
            );
            parry_off.push(format!("pair {k}: parry {d_ref} (its normal's gap {}), C {dist}", gap_along(&n_ref)));
            continue;
        }
        let ed = (dist - d_ref).abs();
        if ed > max_d {
            max_d = ed;
            worst = format!("pair {k}: C {dist} parry {d_ref} (core {core})");
        }
        assert!(ed <= 1e-9, "pair {k}: distance differs by {ed} m ({worst}); harness input:\n{}", input_lines[k]);
        // the normal is defined where the cores are not touching
        if core.abs() > 1e-9 {
            normals_checked += 1;
            let en = angle(&n, &n_ref);
            max_n = max_n.max(en);
            assert!(
                en <= 1e-9,
                "pair {k}: normal off by {en} rad (C {n:?}, parry {n_ref:?}, core distance {core}); harness input:\n{}",
                input_lines[k]
            );
        }
    }
    println!(
        "collision C vs parry3d on {} pairs ({separated} separated, {penetrating} penetrating; half with radii, 10 % sphere-hull, 10 % capsule-hull, 10 % hulls of 50..=300 points): max |distance - parry| = {max_d:.3e} m, max normal angle = {max_n:.3e} rad over {normals_checked} pairs, max support certificate = {max_cert:.3e} m, max |pb - pa - dist n| = {max_gap:.3e} m; worst: {worst}",
        cases.len()
    );
    println!(
        "{} pairs where parry's own answer fails its certificate (C at least as good there):\n{}",
        parry_off.len(),
        parry_off.join("\n")
    );
    assert!(separated > 1500 && penetrating > 1500, "a mix of separated ({separated}) and penetrating ({penetrating}) pairs");
    assert!(max_cert <= 1e-9, "support certificate {max_cert}");
    assert!(max_gap <= 1e-9, "witness points {max_gap}");
    assert!(parry_off.len() <= 20, "parry is off on {} pairs: too many to call it a reference", parry_off.len());
}

#[test]
fn contact_forces_follow_the_law_and_balance() {
    let tmp = tempfile::tempdir().expect("tempdir");
    let Some(exe) = build(tmp.path()) else { return };
    let mut rng = Rng(0x00F0_12CE_5EED_0002);
    let (k_pair, mu, v_reg) = (1e5, 0.4, 0.01);
    let mut cases = Vec::new();
    let mut input = String::new();
    while cases.len() < 2000 {
        let (pa, ra) = random_part(&mut rng, cases.len() % 2 == 1);
        let (pb, rb) = random_part(&mut rng, cases.len() % 2 == 1);
        if ConvexPolyhedron::from_convex_hull(&pa).is_none() || ConvexPolyhedron::from_convex_hull(&pb).is_none() {
            continue;
        }
        let pose_a = Isometry3::from_parts(
            Translation3::from(Vector3::new(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0))),
            rng.rotation(),
        );
        let offset = rng.unit() * rng.uniform(0.0, 0.8);
        let pose_b = Isometry3::from_parts(Translation3::from(pose_a.translation.vector + offset), rng.rotation());
        let vel: Vec<f64> = (0..12).map(|_| rng.uniform(-1.0, 1.0)).collect();
        part_text(&pa, ra, &pose_a, &mut input);
        part_text(&pb, rb, &pose_b, &mut input);
        for v in &vel {
            input.push_str(&format!("{} ", fmt(*v)));
        }
        input.push_str(&format!("{} {} {}\n", fmt(k_pair), fmt(mu), fmt(v_reg)));
        cases.push((pose_a, pose_b, vel));
    }
    let mut child = Command::new(&exe)
        .arg("eval")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("start the harness");
    let mut stdin = child.stdin.take().expect("stdin");
    let feeder = std::thread::spawn(move || stdin.write_all(input.as_bytes()).expect("feed the harness"));
    let out = child.wait_with_output().expect("harness");
    feeder.join().expect("feeder");
    assert!(out.status.success(), "harness failed: {}", String::from_utf8_lossy(&out.stderr));
    let text = String::from_utf8(out.stdout).expect("utf-8");
    let (mut touching, mut max_rel) = (0, 0.0f64);
    for (k, (line, (pose_a, pose_b, vel))) in text.lines().zip(&cases).enumerate() {
        let x: Vec<f64> = line.split_whitespace().map(|t| t.parse().expect("number")).collect();
        assert_eq!(x.len(), 23, "{line}");
        let v3 = |i: usize| Vector3::new(x[i], x[i + 1], x[i + 2]);
        let (dist, pa, pb, n) = (x[1], v3(2), v3(5), v3(8));
        let (fa, fb, ta, tb) = (v3(11), v3(14), v3(17), v3(20));
        if dist >= 0.0 {
            assert!(fa.norm() + fb.norm() + ta.norm() + tb.norm() == 0.0, "pair {k}: force while apart: {line}");
            continue;
        }
        touching += 1;
        // independently: the velocities of both bodies at the contact point, the law at e = 1
        let c = (pa + pb) / 2.0;
        let (ra0, rb0) = (pose_a.translation.vector, pose_b.translation.vector);
        let wa = pose_a.rotation * Vector3::new(vel[3], vel[4], vel[5]);
        let wb = pose_b.rotation * Vector3::new(vel[9], vel[10], vel[11]);
        let va = Vector3::new(vel[0], vel[1], vel[2]) + wa.cross(&(c - ra0));
        let vb = Vector3::new(vel[6], vel[7], vel[8]) + wb.cross(&(c - rb0));
        let dv = vb - va;
        let vt = dv - n * dv.dot(&n);
        let fnorm = k_pair * (-dist).powf(1.5);
        let f = n * fnorm - vt * (mu * fnorm / (vt.norm_squared() + v_reg * v_reg).sqrt());
        let scale = f.norm() * (1.0 + (c - ra0).norm() + (c - rb0).norm());
        let errs = [(fb - f).norm(), (fa + f).norm(), (tb - (c - rb0).cross(&f)).norm(), (ta + (c - ra0).cross(&f)).norm()];
        // balance: no net force, no net moment about the world origin
        let net_f = (fa + fb).norm();
        let net_t = (ta + ra0.cross(&fa) + tb + rb0.cross(&fb)).norm();
        for e in errs.iter().chain([net_f, net_t].iter()) {
            max_rel = max_rel.max(e / scale);
        }
        assert!(
            errs.iter().all(|e| *e <= 1e-12 * scale) && net_f <= 1e-12 * scale && net_t <= 1e-12 * scale,
            "pair {k}: {errs:?} {net_f} {net_t} (scale {scale}): {line}"
        );
    }
    println!(
        "contact forces: {touching} touching pairs of {}, largest relative deviation from the law and from balance {max_rel:.3e}",
        cases.len()
    );
    assert!(touching > 300, "{touching} touching pairs");
}

#[test]
fn drop_test_rebounds_with_the_coefficient_of_restitution() {
    let tmp = tempfile::tempdir().expect("tempdir");
    let Some(exe) = build(tmp.path()) else { return };
    // sphere of radius 5 cm and 1 kg, dropped from 0.2 m on a box, Hertz exponent, stiff contact
    // (contact time ~0.3 ms: gravity changes the speed by ~0.2 % during it), step 0.1 µs
    let handles: Vec<_> = [0.9, 0.7, 0.5, 0.3]
        .into_iter()
        .map(|e: f64| {
            let exe = exe.clone();
            std::thread::spawn(move || {
                let out = Command::new(&exe)
                    .args(["drop", &e.to_string(), "1e10", "1.5", "1", "0.05", "0.2", "1e-7"])
                    .output()
                    .expect("run the harness");
                assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
                (e, String::from_utf8(out.stdout).expect("utf-8"))
            })
        })
        .collect();
    for h in handles {
        let (e, text) = h.join().expect("drop");
        let first: Vec<f64> = text.lines().next().expect("a bounce").split_whitespace().map(|t| t.parse().expect("number")).collect();
        let (v_in, v_out, apex) = (first[0], first[1], first[2]);
        let ratio = v_out / v_in;
        let energy = apex / 0.2;
        println!("drop e = {e}: impact {v_in:.4} m/s, rebound {v_out:.4} m/s, ratio {ratio:.5} ({:+.3} %), apex ratio {energy:.5} vs e^2 = {:.5}", 100.0 * (ratio / e - 1.0), e * e);
        assert!((ratio / e - 1.0).abs() <= 0.01, "e = {e}: rebound ratio {ratio}");
        assert!((energy / (e * e) - 1.0).abs() <= 0.02, "e = {e}: energy ratio {energy}");
    }
}

fn cube(size: f64, radius: f64) -> ConvexPart {
    let mut v = Vec::new();
    for i in 0..8 {
        v.push([(i & 1) as f64 * size, ((i >> 1) & 1) as f64 * size, ((i >> 2) & 1) as f64 * size]);
    }
    ConvexPart { vertices: v, faces: Vec::new(), radius }
}

#[test]
fn collision_package_passes_msl_check_and_rumoca() {
    let tmp = tempfile::tempdir().expect("tempdir");
    let root = tmp.path();
    let pkg = "CollisionDemo";
    let mut files = collision::files(pkg);
    files.push((format!("{pkg}/package.mo"), format!("within ;\npackage {pkg} \"Collision test package\"\n  extends Modelica.Icons.Package;\n  annotation (uses(Modelica(version=\"4.0.0\")));\nend {pkg};\n").into_bytes()));
    files.push((
        format!("{pkg}/Components/package.mo"),
        format!("within {pkg};\npackage Components \"Components\"\n  extends Modelica.Icons.Package;\nend Components;\n").into_bytes(),
    ));
    let bodies: Vec<String> = ["B1", "B2", "B3"].iter().map(|s| s.to_string()).collect();
    let shapes = vec![
        Some(vec![cube(0.1, 0.0)]),
        None,
        Some(vec![cube(0.05, 0.0), ConvexPart { vertices: vec![[0.0, 0.0, 0.2]], faces: Vec::new(), radius: 0.03 }]),
    ];
    let contacts = collision::declarations(pkg, &bodies, &shapes, &[]).expect("contacts");
    let decl = contacts.declarations.clone();
    files.push((format!("{pkg}/{}", collision::SHAPE_FILE), contacts.shape_file.clone()));
    assert!(!decl.contains(" model "), "`model` is a keyword");
    // laid out as Mechatronics is: declarations, then the equation section
    let text = format!(
        "within {pkg};\nmodel Mechatronics \"Test model\"\n  inner Modelica.Mechanics.MultiBody.World world;\n  Modelica.Mechanics.MultiBody.Parts.Body B1(m=1, r_CM={{0.05, 0.05, 0.05}});\n  Modelica.Mechanics.MultiBody.Parts.Body B2(m=1, r_CM={{0, 0, 0}});\n  Modelica.Mechanics.MultiBody.Parts.Body B3(m=1, r_CM={{0, 0, 0.1}});\n{}\nequation\n  annotation (experiment(StopTime=1));\nend Mechatronics;\n",
        decl.trim_end_matches('\n')
    );
    // every modifier of collisionWorld names a component of our World model (msl-check checks
    // only MSL classes)
    let collision_mo =
        String::from_utf8(files.iter().find(|(p, _)| p.ends_with("Components/Collision.mo")).expect("Collision.mo").1.clone())
            .expect("utf-8");
    let world_text = &collision_mo[collision_mo.find("model World").expect("World")..collision_mo.find("end World;").expect("end World")];
    let start = decl.find("collisionWorld(").expect("collisionWorld") + "collisionWorld(".len();
    let (mut depth, mut names, mut token) = (0i32, Vec::new(), String::new());
    for ch in decl[start..].chars() {
        match ch {
            '(' | '{' | '[' => depth += 1,
            ')' | '}' | ']' if depth == 0 => break,
            ')' | '}' | ']' => depth -= 1,
            '=' if depth == 0 => names.push(token.trim().to_string()),
            ',' if depth == 0 => token.clear(),
            _ if depth == 0 => token.push(ch),
            _ => {}
        }
    }
    assert!(names.len() >= 7, "{names:?}");
    for n in &names {
        let declared =
            [format!(" {n}["), format!(" {n}("), format!(" {n} ="), format!(" {n} \"")].iter().any(|p| world_text.contains(p.as_str()));
        assert!(declared, "collisionWorld modifier `{n}` is not a component of Components.Collision.World");
    }
    files.push((format!("{pkg}/Mechatronics.mo"), text.into_bytes()));
    for (p, b) in &files {
        let path = root.join(p);
        std::fs::create_dir_all(path.parent().expect("folder")).expect("mkdir");
        std::fs::write(&path, b).expect("write");
    }
    match msl_check(&root.join(pkg)) {
        Some(Ok(_)) => {}
        Some(Err(e)) => panic!("msl-check found problems:\n{e}"),
        None => {
            assert!(!tools_required(), "msl-check is required");
            println!("NOTICE: msl-check not found; skipped");
        }
    }
    if let Some(errors) = modelica_syntax_errors(&root.join(pkg)) {
        assert!(errors.is_empty(), "rumoca parse errors:\n{}", errors.join("\n"));
    }
}

/// The world's body names as `Mechatronics` lists them (`bodyNames={"A", "B"}`).
fn body_names(mechatronics: &str) -> Vec<String> {
    let start = mechatronics.find("bodyNames={").expect("bodyNames") + "bodyNames={".len();
    let end = start + mechatronics[start..].find('}').expect("end of bodyNames");
    mechatronics[start..end].split(',').map(|s| s.trim().trim_matches('"').to_string()).collect()
}

/// Runs `harness load FILE NAMES...` with `stdin`; (status, stdout, stderr).
fn run_load(exe: &Path, file: &Path, names: &[String], stdin: &str) -> (bool, String, String) {
    let mut child = Command::new(exe)
        .arg("load")
        .arg(file)
        .args(names)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("run the harness");
    child.stdin.take().expect("stdin").write_all(stdin.as_bytes()).expect("write stdin");
    let out = child.wait_with_output().expect("harness output");
    (out.status.success(), String::from_utf8_lossy(&out.stdout).to_string(), String::from_utf8_lossy(&out.stderr).to_string())
}

/// A converted package unzipped to a folder: the C code reads `Resources/Collision/contact.txt`
/// (where `Modelica.Utilities.Files.loadResource` resolves the world's default `shapeFile`) and
/// finds the parts, vertices and checked pairs of the report, and contact forces exactly on the
/// bodies the report says interfere at the CAD pose (and none elsewhere). `Mechatronics.mo` holds
/// no vertex. A damaged, truncated or foreign shape file is refused naming the file and line.
#[test]
fn shape_file_of_a_converted_package_is_read_by_the_c_code() {
    let tmp = tempfile::tempdir().expect("tempdir");
    let Some(exe) = build(tmp.path()) else { return };
    let case = cad2mo_tests::common::workspace_root().join("tests/in/vrml_pinned");
    let opts = cad2mo_engine::pipeline::Options::default();
    let out = cad2mo_tests::common::convert_path(&case, &opts).expect("converts");
    let pkg_dir = tmp.path().join("unzipped");
    for (p, b) in &out.files {
        let path = pkg_dir.join(p);
        std::fs::create_dir_all(path.parent().expect("folder")).expect("mkdir");
        std::fs::write(&path, b.bytes()).expect("write");
    }
    let pkg = &out.report.package_name;
    let mech = std::fs::read_to_string(pkg_dir.join(pkg).join("Mechatronics.mo")).expect("Mechatronics.mo");
    let world = std::fs::read_to_string(pkg_dir.join(pkg).join("Components/Collision.mo")).expect("Collision.mo");
    assert!(
        world.contains(&format!("Modelica.Utilities.Files.loadResource(\"modelica://{pkg}/{}\")", collision::SHAPE_FILE)),
        "the world finds its shape file through a modelica:// URI"
    );
    let file = pkg_dir.join(pkg).join(collision::SHAPE_FILE);
    assert!(file.is_file(), "the package ships {}", collision::SHAPE_FILE);
    let names = body_names(&mech);
    let coll = out.report.collision.as_ref().expect("collision report");
    // No vertices in the text: every number in the world's modifiers is a size or an index.
    assert!(!mech.contains("vertices="), "Mechatronics.mo carries vertices");
    // The CAD poses of the named bodies.
    let bundle = cad2mo::read_bundle(&case, &Default::default()).expect("bundle");
    let analysed = cad2mo_engine::pipeline::analyse(&bundle, &opts).expect("analyses");
    let poses = cad2mo_engine::pipeline::back::collision_shapes::cad_poses(&analysed.model);
    let index: std::collections::BTreeMap<&str, usize> = coll.bodies.iter().enumerate().map(|(i, b)| (b.body.as_str(), i)).collect();
    let mut stdin = String::new();
    for n in &names {
        let pose = poses[*index.get(n.as_str()).expect("a report body")];
        let r: Matrix3<f64> = pose.rotation.to_rotation_matrix().matrix().transpose();
        let t = pose.translation.vector;
        stdin.push_str(&format!("{} {} {} ", fmt(t.x), fmt(t.y), fmt(t.z)));
        for i in 0..3 {
            for j in 0..3 {
                stdin.push_str(&format!("{} ", fmt(r[(i, j)])));
            }
        }
        stdin.push('\n');
    }
    let (ok, stdout, stderr) = run_load(&exe, &file, &names, &stdin);
    assert!(ok, "load failed: {stderr}");
    let mut lines = stdout.lines();
    let head: Vec<usize> = lines.next().expect("summary").split_whitespace().map(|x| x.parse().expect("count")).collect();
    let shaped: Vec<_> = coll.bodies.iter().filter(|b| b.parts > 0).collect();
    assert_eq!(names.len(), shaped.len(), "every shaped body is in the world");
    assert_eq!(head[0], shaped.iter().map(|b| b.parts).sum::<usize>(), "parts");
    assert_eq!(head[1], shaped.iter().map(|b| b.vertices).sum::<usize>(), "vertices");
    assert_eq!(head[2], coll.checked_pairs, "checked pairs");
    assert!(!coll.interferences.is_empty(), "the case interferes at the CAD pose");
    let touching: std::collections::BTreeSet<&str> = coll.interferences.iter().flat_map(|i| [i.a.as_str(), i.b.as_str()]).collect();
    for (n, line) in names.iter().zip(lines) {
        let v: Vec<f64> = line.split_whitespace().map(|x| x.parse().expect("number")).collect();
        let pushed = v[..3].iter().any(|x| x.abs() > 0.0);
        assert_eq!(pushed, touching.contains(n.as_str()), "{n}: force {v:?}, interferences {touching:?}");
    }

    // Refusals name the file and the line.
    let text = std::fs::read_to_string(&file).expect("shape file");
    let bad = tmp.path().join("bad.txt");
    let truncated = &text[..text.rfind("end").expect("end")];
    for (what, content, expect) in [
        ("truncated", truncated.to_string(), "ends without \"end\""),
        ("unknown entry", text.replacen("\npart ", "\nslab ", 1), "unknown entry \"slab\""),
        ("not a number", text.replacen("\npart 1 ", "\npart 1 x", 1), "expected \"part"),
        ("foreign", text.replacen(&format!("body 1 {}", names[0]), "body 1 SOMEONE_ELSE", 1), "a shape file of another model"),
        ("other format", "solid x\nendsolid x\n".to_string(), "not a cad2mo collision shape file"),
    ] {
        std::fs::write(&bad, &content).expect("write");
        let (ok, _, stderr) = run_load(&exe, &bad, &names, &stdin);
        assert!(!ok, "{what}: accepted");
        assert!(
            stderr.contains(expect) && stderr.contains("bad.txt") && (stderr.contains("line ") || what == "truncated"),
            "{what}: {stderr}"
        );
    }
    let (ok, _, stderr) = run_load(&exe, &tmp.path().join("missing.txt"), &names, &stdin);
    assert!(!ok && stderr.contains("cannot open the collision shape file"), "{stderr}");
}
