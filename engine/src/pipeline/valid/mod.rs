//! Validation: the checks no CAD tool makes, run once before any back end.
//!
//! Hard errors stop the conversion ([`ValidationError`]); everything else becomes a [`Warning`]
//! with the offending values, returned next to the output. Back ends take a [`Validated`], so
//! unvalidated IR cannot reach them.

use nalgebra::{Matrix3, SymmetricEigen};

use crate::pipeline::ir::{Body, Model, PrimitiveKind, SourceLoc, Warning};
use crate::pipeline::passes::hierarchy::{self, Hierarchy, Node};
use crate::pipeline::passes::kinematics::{self, Chain};
use crate::pipeline::passes::loops::LoopAnalysis;

/// The passes' side tables for one model.
#[derive(Clone, Debug)]
pub struct Analysis {
    pub hierarchy: Hierarchy,
    /// One chain per joint, indexed like `Model::joints`.
    pub chains: Vec<Chain>,
    /// How each loop of `hierarchy.loops` is cut.
    pub loops: LoopAnalysis,
}

/// Proof that a model passed validation, with the analysis back ends need.
#[derive(Clone, Debug)]
pub struct Validated {
    pub analysis: Analysis,
    pub warnings: Vec<Warning>,
}

#[derive(Debug, thiserror::Error, PartialEq)]
pub enum ValidationError {
    #[error("{loc}: joint \"{joint}\" connects a {what} to itself (base and follower frames {base} and {follower} both belong to it)")]
    SelfJoint { loc: SourceLoc, joint: String, what: &'static str, base: String, follower: String },
    #[error("{loc}: body \"{body}\" has negative mass {} kg", readable(*mass))]
    NegativeMass { loc: SourceLoc, body: String, mass: f64 },
    #[error("{loc}: the model has no bodies")]
    Empty { loc: SourceLoc },
    /// A value that is not a finite number after unit conversion (e.g. `1.7e308` slug).
    #[error("{loc}: {what} is not a finite number after conversion to SI units ({value})")]
    NotFinite { loc: SourceLoc, what: String, value: String },
    /// A magnitude beyond any real machine: a unit error or a corrupt export.
    #[error("{loc}: {what} is {} {unit}, beyond any real machine (at most {} {unit}); check the export's units", readable(*value), readable(*limit))]
    Implausible { loc: SourceLoc, what: String, value: f64, limit: f64, unit: &'static str },
}

impl ValidationError {
    /// Where in the source the problem is.
    pub fn loc(&self) -> &SourceLoc {
        match self {
            ValidationError::SelfJoint { loc, .. }
            | ValidationError::NegativeMass { loc, .. }
            | ValidationError::Empty { loc }
            | ValidationError::NotFinite { loc, .. }
            | ValidationError::Implausible { loc, .. } => loc,
        }
    }
}

/// Largest distance from the world origin of any frame or mesh vertex, m.
pub const MAX_LENGTH_M: f64 = 1e5;
/// Largest body mass, kg (the heaviest machines weigh about 1e7 kg).
pub const MAX_MASS_KG: f64 = 1e9;
/// Largest inertia tensor entry, kg·m².
pub const MAX_INERTIA: f64 = 1e15;
/// Largest volume, m³, and surface area, m².
pub const MAX_VOLUME_M3: f64 = 1e9;
pub const MAX_AREA_M2: f64 = 1e10;

/// A number for a message: plain in the usual range, with an exponent outside it, never a
/// 300-digit expansion of a denormal.
pub fn readable(x: f64) -> String {
    if x == 0.0 || (1e-4..1e7).contains(&x.abs()) {
        let r: f64 = format!("{x:.6e}").parse().unwrap_or(x);
        format!("{r}")
    } else {
        format!("{x:.6e}")
    }
}

/// Every number of the model is finite and within what a real machine can have.
fn check_magnitudes(model: &Model) -> Result<(), ValidationError> {
    fn check(loc: &SourceLoc, what: &dyn Fn() -> String, value: f64, limit: f64, unit: &'static str) -> Result<(), ValidationError> {
        if !value.is_finite() {
            return Err(ValidationError::NotFinite { loc: loc.clone(), what: what(), value: format!("{value}") });
        }
        if value.abs() > limit {
            return Err(ValidationError::Implausible { loc: loc.clone(), what: what(), value, limit, unit });
        }
        Ok(())
    }
    for f in &model.frames {
        let what = || format!("the position of frame \"{}\" (nodeID \"{}\")", f.name, f.node_id);
        check(&f.loc, &what, f.pose.translation.vector.norm(), MAX_LENGTH_M, "m")?;
        let q = f.pose.rotation.quaternion();
        let what = || format!("the orientation of frame \"{}\" (nodeID \"{}\")", f.name, f.node_id);
        check(&f.loc, &what, q.norm(), 2.0, "")?;
    }
    for b in &model.bodies {
        let name = || format!("body \"{}\" (nodeID \"{}\")", b.cad_name, b.node_id);
        check(&b.loc, &|| format!("the mass of {}", name()), b.mass, MAX_MASS_KG, "kg")?;
        for v in b.inertia_cg.iter() {
            check(&b.loc, &|| format!("an inertia entry of {}", name()), *v, MAX_INERTIA, "kg*m^2")?;
        }
        if let Some(v) = b.volume {
            check(&b.loc, &|| format!("the volume of {}", name()), v, MAX_VOLUME_M3, "m^3")?;
        }
        if let Some(a) = b.surface_area {
            check(&b.loc, &|| format!("the surface area of {}", name()), a, MAX_AREA_M2, "m^2")?;
        }
        if let Some(mesh) = &b.mesh {
            // The largest coordinate, or the first one that is not finite.
            let worst = mesh
                .vertices
                .iter()
                .flatten()
                .map(|c| f64::from(c.abs()))
                .find(|c| !c.is_finite())
                .unwrap_or_else(|| mesh.vertices.iter().flatten().map(|c| f64::from(c.abs())).fold(0.0, f64::max));
            let what = || format!("a vertex coordinate of the mesh of {} ({})", name(), b.geometry_sources.join(", "));
            check(&b.loc, &what, worst, MAX_LENGTH_M, "m")?;
        }
    }
    for j in &model.joints {
        for p in &j.primitives {
            let what = || format!("the axis of a {} primitive of joint \"{}\" (nodeID \"{}\")", p.kind.as_str(), j.cad_name, j.node_id);
            check(&p.loc, &what, p.axis_world.norm(), f64::MAX, "")?;
        }
    }
    Ok(())
}

/// Densities (kg/m³) at which mass and volume are numerically equal in a common unit pair: the
/// mark of a part exported without a material.
const UNIT_DENSITIES: &[(f64, &str)] = &[
    (1e9, "kg and mm^3"),
    (1.0, "kg and m^3"),
    (1e6, "g and mm^3"),
    (1e3, "g and cm^3"),
    (1e6, "kg and cm^3"),
    (27_679.904_710_203_12, "lbm and in^3"),
    (890_574.598_127, "slug and in^3"),
];

pub fn validate(model: &Model, analysis: Analysis) -> Result<Validated, ValidationError> {
    if model.bodies.is_empty() {
        return Err(ValidationError::Empty { loc: SourceLoc { file: model.source.file.clone(), line: 0, column: 0 } });
    }
    check_magnitudes(model)?;
    let mut warnings = Vec::new();
    for body in &model.bodies {
        if body.mass < 0.0 {
            return Err(ValidationError::NegativeMass { loc: body.loc.clone(), body: body.cad_name.clone(), mass: body.mass });
        }
        check_inertia(body, &mut warnings);
        check_density(body, &mut warnings);
    }
    for (j, joint) in model.joints.iter().enumerate() {
        let (a, b) = (hierarchy::node_of(model, joint.base), hierarchy::node_of(model, joint.follower));
        let location = format!("{} (joint \"{}\", nodeID \"{}\")", joint.loc, joint.cad_name, joint.node_id);
        if a == b {
            return Err(ValidationError::SelfJoint {
                loc: joint.loc.clone(),
                joint: joint.cad_name.clone(),
                what: if matches!(a, Node::Body(_)) { "body" } else { "ground" },
                base: model.frame(joint.base).name.clone(),
                follower: model.frame(joint.follower).name.clone(),
            });
        }
        for p in &joint.primitives {
            let movable = matches!(p.kind, PrimitiveKind::Revolute | PrimitiveKind::Prismatic);
            if movable && kinematics::clean_axis(&p.axis_world).is_none() {
                warnings.push(Warning::new(
                    "zero-axis",
                    format!(
                        "{} primitive has axis ({}, {}, {}), which has no direction; it is emitted as rigid",
                        p.kind.as_str(),
                        readable(p.axis_world.x),
                        readable(p.axis_world.y),
                        readable(p.axis_world.z)
                    ),
                    location.clone(),
                ));
            }
        }
        warnings.extend(kinematics::check(model, joint, &analysis.chains[j], &location));
    }
    check_massless_leaves(model, &analysis, &mut warnings);
    let free = &analysis.hierarchy.free_bodies;
    if !free.is_empty() {
        let names: Vec<String> = free.iter().map(|b| format!("\"{}\"", model.body(*b).cad_name)).collect();
        warnings.push(Warning::new(
            "free-bodies",
            format!(
                "{} bodies have no path to a ground and float freely from their CAD pose (6 degrees of freedom per free group): {}",
                free.len(),
                crate::pipeline::ir::bounded_list(&names, 20)
            ),
            model.source.file.clone(),
        ));
    }
    let without: Vec<String> = model
        .bodies
        .iter()
        .filter(|b| b.mesh.is_none() && b.geometry_file.is_none() && !is_root_part(b))
        .map(|b| format!("\"{}\" ({})", b.cad_name, b.node_id))
        .collect();
    if !without.is_empty() {
        warnings.push(Warning::new(
            "no-geometry",
            format!("{} bodies have no geometry: {}", without.len(), crate::pipeline::ir::bounded_list(&without, 20)),
            model.source.file.clone(),
        ));
    }
    Ok(Validated { analysis, warnings })
}

/// A zero-mass placeholder every assembly and subsystem has.
pub fn is_root_part(b: &Body) -> bool {
    b.mass == 0.0 && b.cad_name == "RootPart"
}

fn body_location(b: &Body) -> String {
    format!("{} (body \"{}\", nodeID \"{}\")", b.loc, b.cad_name, b.node_id)
}

fn fmt_matrix(m: &Matrix3<f64>) -> String {
    let rows: Vec<String> = (0..3).map(|r| format!("[{:e}, {:e}, {:e}]", m[(r, 0)], m[(r, 1)], m[(r, 2)])).collect();
    format!("[{}]", rows.join(", "))
}

fn check_inertia(body: &Body, warnings: &mut Vec<Warning>) {
    let i = body.inertia_cg;
    let scale = i.abs().max();
    if scale == 0.0 {
        return;
    }
    let asym = (i - i.transpose()).abs().max();
    if asym > 1e-6 * scale {
        warnings.push(Warning::new(
            "inertia-not-symmetric",
            format!(
                "inertia tensor {} kg*m^2 is not symmetric (largest difference {:e}); its symmetric part is used",
                fmt_matrix(&i),
                asym
            ),
            body_location(body),
        ));
    }
    let sym = (i + i.transpose()) * 0.5;
    let mut eig: Vec<f64> = SymmetricEigen::new(sym).eigenvalues.iter().copied().collect();
    eig.sort_by(f64::total_cmp);
    let tol = 1e-6 * scale;
    if eig[0] < -tol {
        warnings.push(Warning::new(
            "inertia-not-positive",
            format!(
                "inertia tensor is not positive semi-definite: principal moments {:e}, {:e}, {:e} kg*m^2 (a known fault of mirrored Creo parts: correct the mass properties in CAD)",
                eig[0], eig[1], eig[2]
            ),
            body_location(body),
        ));
    } else if eig[0] + eig[1] < eig[2] - tol {
        warnings.push(Warning::new(
            "inertia-triangle-inequality",
            format!(
                "principal moments {:e} + {:e} < {:e} kg*m^2 violate the triangle inequality: no real mass distribution has this inertia",
                eig[0], eig[1], eig[2]
            ),
            body_location(body),
        ));
    }
}

fn check_density(body: &Body, warnings: &mut Vec<Warning>) {
    let Some(volume) = body.volume.filter(|v| *v > 0.0) else { return };
    if body.mass <= 0.0 {
        return;
    }
    let density = body.mass / volume;
    if let Some((_, units)) = UNIT_DENSITIES.iter().find(|(d, _)| ((density - d) / d).abs() < 1e-4) {
        warnings.push(Warning::new(
            "no-material",
            format!(
                "mass equals volume numerically ({units}; density {} kg/m^3): the part probably has no material assigned in CAD, so its mass and inertia are wrong",
                readable(density)
            ),
            body_location(body),
        ));
    } else if !(100.0..=25_000.0).contains(&density) {
        warnings.push(Warning::new(
            "density-implausible",
            format!(
                "density {} kg/m^3 (mass {} kg, volume {} m^3) is outside 100..25000 kg/m^3",
                readable(density),
                readable(body.mass),
                readable(volume)
            ),
            body_location(body),
        ));
    }
}

/// A massless body at the end of a movable joint makes the model singular.
fn check_massless_leaves(model: &Model, analysis: &Analysis, warnings: &mut Vec<Warning>) {
    let mut degree = vec![0usize; model.bodies.len()];
    for joint in &model.joints {
        for f in [joint.base, joint.follower] {
            if let Node::Body(b) = hierarchy::node_of(model, f) {
                degree[b.index()] += 1;
            }
        }
    }
    for (j, joint) in model.joints.iter().enumerate() {
        if analysis.chains[j].elements.is_empty() {
            continue;
        }
        if let Node::Body(b) = hierarchy::node_of(model, joint.follower) {
            let body = model.body(b);
            if body.mass == 0.0 && degree[b.index()] == 1 {
                warnings.push(Warning::new(
                    "massless-leaf",
                    format!(
                        "body \"{}\" has zero mass and hangs only from movable joint \"{}\": the model will be singular",
                        body.cad_name, joint.cad_name
                    ),
                    body_location(body),
                ));
            }
        }
    }
}

#[cfg(test)]
mod readable_tests {
    use super::readable;

    #[test]
    fn numbers_in_messages_are_short() {
        assert_eq!(readable(12.5), "12.5");
        assert_eq!(readable(0.0), "0");
        assert_eq!(readable(5e-324), "4.940656e-324");
        assert_eq!(readable(-2.5e9), "-2.500000e9");
        assert_eq!(readable(0.123456789), "0.1234568");
    }
}
