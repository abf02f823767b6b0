//! URDF in → IR → URDF out → IR gives the same model (issue 15): for our URDF golden inputs and
//! the real URDFs in `../shared/fixtures/urdf` (read without meshes), the front end's IR and the
//! IR of the URDF the back end writes from it agree to 1e-12:
//! - bodies by name (the second IR's link names are the first's Modelica names): mass, inertia
//!   about the CG in CG axes, CS1 and CG world poses; the only extra links are the massless
//!   `JOINT__k` links of joints with several elements (Drake ball and universal joints);
//! - joints by name: primitive kinds and world axes (negated when the tree runs a joint from its
//!   follower side), limits (a limit the first IR lacks but URDF requires comes back as the
//!   documented default), loop joints included; several-element joints come back as one URDF
//!   joint per element (planar stays planar);
//! - couplings (mimic) and free bodies.

use std::collections::BTreeMap;
use std::path::PathBuf;

use cad2mo_engine::pipeline::back::modelica::{self, Layout};
use cad2mo_engine::pipeline::back::urdf::{self, DEFAULT_EFFORT, DEFAULT_TRAVEL, DEFAULT_VELOCITY};
use cad2mo_engine::pipeline::front::urdf as front;
use cad2mo_engine::pipeline::ir::{FrameOwner, JointLimits, Model, PrimitiveKind};
use cad2mo_engine::pipeline::passes;
use cad2mo_engine::pipeline::valid::{self, Analysis, Validated};
use cad2mo_tests::common::{files_with_ext, fixtures_dir, sorted_dirs, workspace_root};
use nalgebra::Isometry3;

const TOL: f64 = 1e-12;

struct Read {
    model: Model,
    validated: Validated,
    layout: Layout,
}

fn read(label: &str, bytes: &[u8]) -> Read {
    let u = front::parse(label, bytes).unwrap_or_else(|e| panic!("{label}: {e}"));
    let model = u.model;
    let planned = passes::loops::plan(&model).unwrap_or_else(|e| panic!("{label}: {e}"));
    let analysis = Analysis { hierarchy: planned.hierarchy, chains: planned.chains, loops: planned.loops };
    let validated = valid::validate(&model, analysis).unwrap_or_else(|e| panic!("{label}: {e}"));
    let layout = modelica::write(
        &model,
        &validated,
        &modelica::Options {
            package_name: "P".into(),
            gravity: [0.0, 0.0, -9.81],
            converter_version: String::new(),
            name_hints: Default::default(),
        },
    )
    .layout;
    Read { model, validated, layout }
}

fn dist(a: &Isometry3<f64>, b: &Isometry3<f64>) -> f64 {
    (a.to_homogeneous() - b.to_homogeneous()).amax()
}

/// The limits the written URDF states for a joint whose source stated `l` (URDF type `kind`).
fn written(l: &Option<JointLimits>, revolute: bool) -> Option<JointLimits> {
    let l = l.clone()?;
    if revolute && l.lower.is_none() && l.upper.is_none() {
        // continuous: effort and velocity only, both written when either is.
        return (l.effort.is_some() || l.velocity.is_some()).then(|| JointLimits {
            lower: None,
            upper: None,
            effort: Some(l.effort.unwrap_or(DEFAULT_EFFORT)),
            velocity: Some(l.velocity.unwrap_or(DEFAULT_VELOCITY)),
        });
    }
    Some(JointLimits {
        lower: Some(l.lower.unwrap_or(-DEFAULT_TRAVEL)),
        upper: Some(l.upper.unwrap_or(DEFAULT_TRAVEL)),
        effort: Some(l.effort.unwrap_or(DEFAULT_EFFORT)),
        velocity: Some(l.velocity.unwrap_or(DEFAULT_VELOCITY)),
    })
}

/// Compares the two IRs; returns (bodies, joints, joints off their source zero) compared.
fn round_trip(label: &str, bytes: &[u8]) -> (usize, usize, usize) {
    let first = read(label, bytes);
    let (m1, names1) = (&first.model, first.layout.names.as_ref().expect("names"));
    let text = urdf::write(m1, &first.validated, &first.layout, "P", false);
    let second = read(&format!("{label} (written)"), text.as_bytes());
    let m2 = &second.model;
    let ctx = || format!("{label}; written URDF:\n{}", cad2mo_engine::pipeline::ir::clip(&text, 20_000));

    // Bodies.
    let bodies2: BTreeMap<&str, usize> = m2.bodies.iter().enumerate().map(|(i, b)| (b.cad_name.as_str(), i)).collect();
    for (i, b1) in m1.bodies.iter().enumerate() {
        let name = &names1.bodies[i];
        let &j = bodies2.get(name.as_str()).unwrap_or_else(|| panic!("{label}: body {name} lost\n{}", ctx()));
        let b2 = &m2.bodies[j];
        assert!((b1.mass - b2.mass).abs() <= TOL * b1.mass.max(1.0), "{label}: {name} mass {} vs {}", b1.mass, b2.mass);
        let scale = b1.inertia_cg.amax().max(1e-300);
        let di = (b1.inertia_cg - b2.inertia_cg).amax();
        assert!(di <= TOL * scale, "{label}: {name} inertia off by {di:e} (of {scale:e})");
        for (what, f1, f2) in [("CS1", b1.cs1, b2.cs1), ("CG", b1.cg, b2.cg)] {
            let d = dist(&m1.frame(f1).pose, &m2.frame(f2).pose);
            assert!(d <= TOL, "{label}: {name} {what} world pose off by {d:e}\n{}", ctx());
        }
    }
    let composite = first.validated.analysis.chains.iter().any(expanded);
    for b2 in &m2.bodies {
        if !names1.bodies.contains(&b2.cad_name) {
            assert!(composite && b2.cad_name.contains("__") && b2.mass == 0.0, "{label}: extra body {}\n{}", b2.cad_name, ctx());
        }
    }

    // Joints.
    let joints2: BTreeMap<&str, usize> = m2.joints.iter().enumerate().map(|(i, j)| (j.cad_name.as_str(), i)).collect();
    let body_name = |m: &Model, names: Option<&Vec<String>>, f| match m.frame(f).owner {
        FrameOwner::Body(b) => names.map_or_else(|| m.body(b).cad_name.clone(), |n| n[b.index()].clone()),
        FrameOwner::Ground(_) => "world".to_string(),
    };
    let mut joints = 0;
    for (i, j1) in m1.joints.iter().enumerate() {
        let name = &names1.joints[i];
        let chain = &first.validated.analysis.chains[i];
        let omitted = first.validated.analysis.hierarchy.loops.iter().zip(&first.validated.analysis.loops.loops).any(|(l, info)| {
            l.closing.index() == i && (l.kind == passes::hierarchy::LoopKind::Rigid || info.cut == passes::loops::Cut::Omitted)
        });
        if omitted {
            continue;
        }
        if expanded(chain) {
            // One URDF joint per element (three per spherical one).
            for (k, e) in chain.elements.iter().enumerate() {
                let base = first.layout.joint_elements[i].get(k).unwrap_or(name);
                let want: Vec<String> = if e.kind == PrimitiveKind::Spherical {
                    ["x", "y", "z"].iter().map(|s| format!("{base}_{s}")).collect()
                } else {
                    vec![base.clone()]
                };
                for w in want {
                    assert!(joints2.contains_key(w.as_str()), "{label}: joint {name}: element {w} not written\n{}", ctx());
                }
            }
            joints += 1;
            continue;
        }
        let &k = joints2.get(name.as_str()).unwrap_or_else(|| panic!("{label}: joint {name} lost\n{}", ctx()));
        let j2 = &m2.joints[k];
        let kinds = |j: &cad2mo_engine::pipeline::ir::Joint| j.primitives.iter().map(|p| p.kind).collect::<Vec<_>>();
        assert_eq!(kinds(j1), kinds(j2), "{label}: joint {name} kinds");
        let (b1, f1) = (body_name(m1, Some(&names1.bodies), j1.base), body_name(m1, Some(&names1.bodies), j1.follower));
        let (b2, f2) = (body_name(m2, None, j2.base), body_name(m2, None, j2.follower));
        let sign = if (b1.as_str(), f1.as_str()) == (b2.as_str(), f2.as_str()) {
            1.0
        } else {
            assert_eq!((b1.as_str(), f1.as_str()), (f2.as_str(), b2.as_str()), "{label}: joint {name} joins other bodies");
            -1.0
        };
        for (p1, p2) in j1.primitives.iter().zip(&j2.primitives) {
            if matches!(p1.kind, PrimitiveKind::Revolute | PrimitiveKind::Prismatic) {
                let d = (p1.axis_world.normalize() * sign - p2.axis_world.normalize()).amax();
                assert!(d <= TOL, "{label}: joint {name} axis {} vs {} ({d:e})", p1.axis_world, p2.axis_world);
            }
        }
        if chain.elements.len() == 1 {
            // A tree joint's limits move to URDF's coordinate (q − q0); a loop joint's stay.
            let e = &chain.elements[0];
            let cut = text.contains(&format!("<loop_joint name=\"{name}\""));
            let shift = if cut { 0.0 } else { e.q0 };
            let l1 = j1.limits.clone().map(|l| JointLimits { lower: l.lower.map(|x| x - shift), upper: l.upper.map(|x| x - shift), ..l });
            assert_eq!(written(&l1, e.kind == PrimitiveKind::Revolute), j2.limits, "{label}: joint {name} limits (start {})", e.q0);
        }
        joints += 1;
    }

    // Couplings and free bodies.
    // Offsets in URDF's coordinates (q − q0 on both sides).
    let couplings = |m: &Model, v: &Validated, names: Option<&Vec<String>>| {
        let name = |j: cad2mo_engine::pipeline::ir::JointId| names.map_or_else(|| m.joint(j).cad_name.clone(), |n| n[j.index()].clone());
        let q0 = |j: cad2mo_engine::pipeline::ir::JointId| v.analysis.chains[j.index()].elements.first().map_or(0.0, |e| e.q0);
        let mut v: Vec<(String, String, f64, f64)> = m
            .couplings
            .iter()
            .map(|c| (name(c.follower), name(c.leader), c.multiplier, c.offset + c.multiplier * q0(c.leader) - q0(c.follower)))
            .collect();
        v.sort_by(|a, b| a.0.cmp(&b.0));
        v
    };
    assert_eq!(couplings(m1, &first.validated, Some(&names1.joints)), couplings(m2, &second.validated, None), "{label}: couplings");
    let free = |r: &Read, names: Option<&Vec<String>>| {
        let mut v: Vec<String> = r
            .validated
            .analysis
            .hierarchy
            .free_bodies
            .iter()
            .map(|b| names.map_or_else(|| r.model.body(*b).cad_name.clone(), |n| n[b.index()].clone()))
            .collect();
        v.sort();
        v
    };
    assert_eq!(free(&first, Some(&names1.bodies)), free(&second, None), "{label}: free bodies");
    let moved = first.validated.analysis.chains.iter().filter(|c| c.elements.iter().any(|e| e.q0 != 0.0)).count();
    (m1.bodies.len(), joints, moved)
}

/// Written as one URDF joint per element (three per spherical one) through helper links.
fn expanded(c: &passes::kinematics::Chain) -> bool {
    (c.elements.len() > 1 && !is_planar(c)) || c.elements.iter().any(|e| e.kind == PrimitiveKind::Spherical)
}

fn is_planar(c: &passes::kinematics::Chain) -> bool {
    let e = &c.elements;
    e.len() == 3
        && e[0].kind == PrimitiveKind::Prismatic
        && e[1].kind == PrimitiveKind::Prismatic
        && e[2].kind == PrimitiveKind::Revolute
        && (e[0].axis.cross(&e[1].axis) - e[2].axis).norm() <= 1e-12
}

#[test]
fn urdf_in_ir_urdf_out_ir_is_the_same_model() {
    let mut inputs: Vec<(String, PathBuf)> = Vec::new();
    for d in sorted_dirs(&workspace_root().join("tests/in")) {
        let name = d.file_name().unwrap_or_default().to_string_lossy().to_string();
        if name.starts_with("urdf") {
            for f in files_with_ext(&d, &[".urdf"]) {
                inputs.push((format!("golden {name}"), f));
            }
        }
    }
    let own = inputs.len();
    assert!(own >= 3, "our URDF inputs: {own}");
    if let Some(fx) = fixtures_dir("urdf_roundtrip") {
        for f in files_with_ext(&fx.join("urdf"), &[".urdf"]) {
            inputs.push((f.strip_prefix(&fx).unwrap_or(&f).display().to_string(), f));
        }
    }
    for (label, path) in &inputs {
        let bytes = std::fs::read(path).expect("read");
        let (b, j, moved) = round_trip(label, &bytes);
        println!("{label}: {b} bodies, {j} joints ({moved} started off the source's zero): the same after URDF out and in");
    }
}
