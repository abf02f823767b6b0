//! Lumping welded groups into one body (an option): fewer bodies, fewer states, faster simulation.
//!
//! Bodies joined by tree welds form a group. The group's representative is its body nearest the
//! ground (ties by `node_id`); it keeps its name, node ID and CS1. The lumped body's mass is the
//! sum, its centre of gravity the mass-weighted mean, and its inertia the sum of every member's
//! inertia moved to the common centre of gravity with the parallel-axis theorem, resolved in the
//! axes of the representative's CG frame:
//!
//! `I = Σ R_i I_i R_iᵀ + m_i (|d_i|² E - d_i d_iᵀ)`, `d_i = c_i - c`, in world axes, then
//! `I_cg = R_cgᵀ I R_cg`.
//!
//! Every member frame moves to the representative (its world pose is unchanged), member meshes
//! are transformed into the representative's CS1, and the internal welds disappear.

use std::collections::BTreeMap;
use std::sync::Arc;

use nalgebra::{Matrix3, Vector3};

use super::hierarchy::{self, Hierarchy, Node};
use crate::pipeline::ir::{BodyId, FrameId, FrameOwner, JointId, Mesh, Model};

/// The lumped model and, per representative `node_id`, the `node_id`s merged into it.
pub struct Lumped {
    pub model: Model,
    pub merged: BTreeMap<String, Vec<String>>,
    /// The welds inside lumped groups, which the lumped model no longer has.
    pub absorbed: Vec<Absorbed>,
}

/// A weld absorbed into a lumped body.
#[derive(Clone, Debug, PartialEq)]
pub struct Absorbed {
    pub cad_name: String,
    pub node_id: String,
    /// `node_id` of the lumped body (the group's representative).
    pub body: String,
}

/// Lumps welded groups. Bodies that are not welded to another body come through unchanged.
pub fn lump(model: &Model, h: &Hierarchy) -> Lumped {
    // Union-find over bodies through tree welds between two bodies.
    let nb = model.bodies.len();
    let mut group = hierarchy::Dsu::new(nb);
    let mut internal: Vec<JointId> = Vec::new();
    for &j in &h.tree {
        let joint = model.joint(j);
        if !joint.is_weld() {
            continue;
        }
        if let (Node::Body(a), Node::Body(b)) = (hierarchy::node_of(model, joint.base), hierarchy::node_of(model, joint.follower)) {
            group.union(a.index(), b.index());
            internal.push(j);
        }
    }
    // Rigid loops closed by welds inside a group are internal too.
    for l in &h.loops {
        if l.kind == hierarchy::LoopKind::Rigid {
            internal.push(l.closing);
        }
    }
    let mut members: BTreeMap<usize, Vec<BodyId>> = BTreeMap::new();
    for i in 0..nb {
        let r = group.find(i);
        members.entry(r).or_default().push(BodyId(i as u32));
    }
    let mut rep_of = vec![BodyId(0); nb];
    let mut merged = BTreeMap::new();
    let mut out = model.clone();
    for list in members.values() {
        let rep = *list
            .iter()
            .min_by(|a, b| {
                let da = h.depth[a.index()].unwrap_or(u32::MAX);
                let db = h.depth[b.index()].unwrap_or(u32::MAX);
                (da, &model.body(**a).node_id).cmp(&(db, &model.body(**b).node_id))
            })
            .unwrap_or(&list[0]);
        for b in list {
            rep_of[b.index()] = rep;
        }
        if list.len() > 1 {
            combine(model, &mut out, rep, list);
            let mut names: Vec<String> = list.iter().filter(|b| **b != rep).map(|b| model.body(*b).node_id.clone()).collect();
            names.sort();
            merged.insert(model.body(rep).node_id.clone(), names);
        }
    }
    // Renumber: keep representatives in their original order.
    let keep: Vec<BodyId> = model.body_ids().filter(|b| rep_of[b.index()] == *b).collect();
    let mut new_index = vec![BodyId(0); nb];
    for (k, b) in keep.iter().enumerate() {
        new_index[b.index()] = BodyId(k as u32);
    }
    let bodies = keep.iter().map(|b| out.bodies[b.index()].clone()).collect();
    out.bodies = bodies;
    for f in &mut out.frames {
        if let FrameOwner::Body(b) = f.owner {
            f.owner = FrameOwner::Body(new_index[rep_of[b.index()].index()]);
        }
    }
    internal.sort();
    internal.dedup();
    let absorbed = internal
        .iter()
        .map(|j| {
            let joint = model.joint(*j);
            let b = match hierarchy::node_of(model, joint.base) {
                Node::Body(b) => b,
                Node::Ground(_) => match hierarchy::node_of(model, joint.follower) {
                    Node::Body(b) => b,
                    Node::Ground(_) => BodyId(0),
                },
            };
            Absorbed {
                cad_name: joint.cad_name.clone(),
                node_id: joint.node_id.clone(),
                body: model.body(rep_of[b.index()]).node_id.clone(),
            }
        })
        .collect();
    out.joints = model.joint_ids().filter(|j| internal.binary_search(j).is_err()).map(|j| model.joint(j).clone()).collect();
    // Couplings refer to movable joints, which all survive; their indices shift.
    let kept: Vec<_> = model.joint_ids().filter(|j| internal.binary_search(j).is_err()).collect();
    out.couplings = model
        .couplings
        .iter()
        .filter_map(|c| {
            let at = |j| kept.binary_search(&j).ok().map(|k| crate::pipeline::ir::JointId(k as u32));
            Some(crate::pipeline::ir::Coupling { follower: at(c.follower)?, leader: at(c.leader)?, ..c.clone() })
        })
        .collect();
    Lumped { model: out, merged, absorbed }
}

/// Writes the combined mass properties, frames and mesh of `list` into `out.bodies[rep]`.
fn combine(model: &Model, out: &mut Model, rep: BodyId, list: &[BodyId]) {
    let mass: f64 = list.iter().map(|b| model.body(*b).mass).sum();
    let cg_of = |b: BodyId| model.frame(model.body(b).cg).pose.translation.vector;
    let c: Vector3<f64> =
        if mass > 0.0 { list.iter().map(|b| cg_of(*b) * model.body(*b).mass).sum::<Vector3<f64>>() / mass } else { cg_of(rep) };
    let mut inertia_world = Matrix3::zeros();
    for b in list {
        let body = model.body(*b);
        let r = model.frame(body.cg).pose.rotation.to_rotation_matrix().into_inner();
        let d = cg_of(*b) - c;
        inertia_world += r * body.inertia_cg * r.transpose() + (Matrix3::identity() * d.norm_squared() - d * d.transpose()) * body.mass;
    }
    let rep_body = model.body(rep);
    let rep_cg = rep_body.cg;
    let r_cg = model.frame(rep_cg).pose.rotation.to_rotation_matrix().into_inner();
    let cs1 = model.frame(rep_body.cs1).pose;

    // The representative's CG frame moves to the combined centre of gravity.
    out.frames[rep_cg.index()].pose.translation.vector = c;
    let mut frames: Vec<FrameId> = Vec::new();
    let mut mesh: Option<Mesh> = None;
    let mut sources = Vec::new();
    let mut volume = Some(0.0);
    for b in list {
        let body = model.body(*b);
        frames.extend(body.frames.iter().filter(|f| *b == rep || (**f != body.cg)).copied());
        if let Some(m) = &body.mesh {
            let mut m = Mesh::clone(m);
            let to_rep = cs1.inverse() * model.frame(body.cs1).pose;
            m.transform(&to_rep);
            match &mut mesh {
                Some(acc) => acc.append(&m),
                None => mesh = Some(m),
            }
        }
        sources.extend(body.geometry_sources.iter().cloned());
        volume = match (volume, body.volume) {
            (Some(a), Some(v)) => Some(a + v),
            _ => None,
        };
    }
    let target = &mut out.bodies[rep.index()];
    target.mass = mass;
    target.inertia_cg = r_cg.transpose() * inertia_world * r_cg;
    target.frames = frames;
    target.mesh = mesh.map(Arc::new);
    target.geometry_sources = sources;
    target.volume = volume;
    target.surface_area = None;
    if target.material.is_none() {
        target.material = list.iter().find_map(|b| model.body(*b).material.clone());
    }
}
