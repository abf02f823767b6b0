//! Frames given relative to other frames, and joint axes given in a joint frame's axes.
//!
//! A frame's position vector starts at the origin of its `positionOrigin` frame X and has its
//! components in the axes of its `positionReferenceFrame` Y; its orientation is relative to its
//! `orientationReferenceFrame` Z: `p = origin(X) + R(Y) p_given`, `R = R(Z) R_given`. X, Y and Z
//! are `WORLD`, a frame of the same body by name, or `ADJOINING` (the other frame of the one
//! joint using this frame). Each frame is read with its pose as given; [`Lower::place_frames`]
//! replaces it by the world pose once the joints are known, walking references depth first
//! (iteratively: chains may be long) and reporting cycles.

use nalgebra::{Isometry3, Translation3};

use super::{Lower, Result};
use crate::pipeline::front::simmechanics::dom::NodeId;
use crate::pipeline::front::simmechanics::error::{XmlError, XmlErrorKind};
use crate::pipeline::ir::{FrameId, FrameOwner};

/// Index of `positionOrigin` in [`FrameRefs`].
pub(super) const ORIGIN: usize = 0;
/// Index of `positionReferenceFrame`.
pub(super) const AXES: usize = 1;
/// Index of `orientationReferenceFrame`.
pub(super) const ORIENTATION: usize = 2;

/// What a body frame's references may be.
const BODY_FRAME_REFS: &str = "WORLD, ADJOINING or the name of a frame of the same body";
/// What a ground frame's references may be.
const GROUND_FRAME_REFS: &str = "WORLD or ADJOINING";
/// What a primitive's `referenceFrame` may be.
const AXIS_REFS: &str = "WORLD, BASE or FOLLOWER";

/// A frame reference other than `WORLD`.
#[derive(Clone, Debug)]
pub(super) enum Reference {
    /// The frame at the other end of the joint using this frame.
    Adjoining,
    /// A frame of the same body, by `name`.
    Named(String),
}

/// A frame's origin, position-axes and orientation references (`None`: `WORLD`), each with the
/// element it was read from.
pub(super) type FrameRefs = [Option<(Reference, NodeId)>; 3];

/// The axes a primitive's `axis` is given in.
#[derive(Clone, Copy, Debug)]
pub(super) enum AxisFrame {
    World,
    Base,
    Follower,
}

/// Depth-first state of one frame.
#[derive(Clone, Copy, PartialEq)]
enum Visit {
    New,
    Open,
    Placed,
}

impl Lower<'_, '_> {
    /// Reads a frame reference element; `None` is `WORLD`.
    pub(super) fn frame_reference(&self, node: NodeId, owner: FrameOwner) -> Result<Option<Reference>> {
        let value = self.value(node)?;
        match (&*value, owner) {
            ("WORLD", _) => Ok(None),
            ("ADJOINING", _) => Ok(Some(Reference::Adjoining)),
            (_, FrameOwner::Body(_)) => Ok(Some(Reference::Named(value.into_owned()))),
            (_, FrameOwner::Ground(_)) => Err(self.unsupported(node, GROUND_FRAME_REFS)),
        }
    }

    /// Reads a primitive's `referenceFrame`.
    pub(super) fn axis_frame(&self, node: NodeId) -> Result<AxisFrame> {
        match &*self.value(node)? {
            "WORLD" => Ok(AxisFrame::World),
            "BASE" => Ok(AxisFrame::Base),
            "FOLLOWER" => Ok(AxisFrame::Follower),
            _ => Err(self.unsupported(node, AXIS_REFS)),
        }
    }

    fn unsupported(&self, node: NodeId, expected: &'static str) -> XmlError {
        let value = self.value(node).map(|v| v.into_owned()).unwrap_or_default();
        self.err(node, XmlErrorKind::UnsupportedReferenceFrame { value, expected })
    }

    /// Replaces every frame's pose as given by its world pose. Needs the joints resolved.
    pub(super) fn place_frames(&mut self) -> Result<()> {
        let refs = std::mem::take(&mut self.frame_refs);
        if refs.iter().flatten().all(Option::is_none) {
            return Ok(());
        }
        let joints = self.joints_per_frame();
        let mut targets = Vec::with_capacity(refs.len());
        for (i, frame_refs) in refs.iter().enumerate() {
            let mut t = [None; 3];
            for (slot, r) in t.iter_mut().zip(frame_refs) {
                if let Some((reference, node)) = r {
                    *slot = Some(self.target(FrameId(i as u32), reference, *node, &joints)?);
                }
            }
            targets.push(t);
        }
        let mut visit = vec![Visit::New; targets.len()];
        let mut stack: Vec<FrameId> = Vec::new();
        for start in 0..targets.len() {
            if visit[start] != Visit::New {
                continue;
            }
            visit[start] = Visit::Open;
            stack.push(FrameId(start as u32));
            while let Some(&f) = stack.last() {
                let next = targets[f.index()].iter().flatten().find(|t| visit[t.index()] != Visit::Placed);
                match next {
                    Some(&t) if visit[t.index()] == Visit::Open => {
                        return Err(self.cycle(&stack, t, &targets, &refs));
                    }
                    Some(&t) => {
                        visit[t.index()] = Visit::Open;
                        stack.push(t);
                    }
                    None => {
                        let pose = self.world_pose(f, &targets[f.index()]);
                        self.model.frames[f.index()].pose = pose;
                        visit[f.index()] = Visit::Placed;
                        stack.pop();
                    }
                }
            }
        }
        Ok(())
    }

    /// Turns primitive axes given in a joint frame's axes into world axes (frames placed).
    pub(super) fn rotate_axes(&mut self, axis_frames: &[Vec<AxisFrame>]) {
        let frames = &self.model.frames;
        for (joint, axes) in self.model.joints.iter_mut().zip(axis_frames) {
            for (p, axis) in joint.primitives.iter_mut().zip(axes) {
                let by = match axis {
                    AxisFrame::World => continue,
                    AxisFrame::Base => joint.base,
                    AxisFrame::Follower => joint.follower,
                };
                p.axis_world = frames[by.index()].pose.rotation * p.axis_world;
            }
        }
    }

    /// The world pose of `f` from its pose as given and its (placed) reference frames.
    fn world_pose(&self, f: FrameId, targets: &[Option<FrameId>; 3]) -> Isometry3<f64> {
        let world = |t: Option<FrameId>| t.map_or_else(Isometry3::identity, |t| self.model.frame(t).pose);
        let given = self.model.frame(f).pose;
        let origin = world(targets[ORIGIN]).translation.vector;
        let position = origin + world(targets[AXES]).rotation * given.translation.vector;
        Isometry3::from_parts(Translation3::from(position), world(targets[ORIENTATION]).rotation * given.rotation)
    }

    /// Per frame: how many joints use it and the other frame of the last one.
    fn joints_per_frame(&self) -> Vec<(usize, Option<FrameId>)> {
        let mut out = vec![(0, None); self.model.frames.len()];
        for j in &self.model.joints {
            for (this, other) in [(j.base, j.follower), (j.follower, j.base)] {
                if let Some(slot) = out.get_mut(this.index()) {
                    *slot = (slot.0 + 1, Some(other));
                }
            }
        }
        out
    }

    /// The frame `reference` (read from `node`, a reference of frame `f`) points at.
    fn target(&self, f: FrameId, reference: &Reference, node: NodeId, joints: &[(usize, Option<FrameId>)]) -> Result<FrameId> {
        let frame = self.model.frame(f);
        match reference {
            Reference::Adjoining => match joints.get(f.index()) {
                Some(&(1, Some(other))) => Ok(other),
                other => {
                    let kind = XmlErrorKind::AdjoiningNotOneJoint { frame: frame.name.clone(), joints: other.map_or(0, |o| o.0) };
                    Err(self.err(node, kind))
                }
            },
            Reference::Named(name) => {
                let siblings = match frame.owner {
                    FrameOwner::Body(b) => self.model.bodies[b.index()].frames.as_slice(),
                    FrameOwner::Ground(_) => &[],
                };
                if let Some(&id) = siblings.iter().find(|&&s| self.model.frame(s).name == *name) {
                    return Ok(id);
                }
                if !is_frame_name(name) {
                    return Err(self.unsupported(node, BODY_FRAME_REFS));
                }
                let kind = XmlErrorKind::UnknownFrameName { frame: frame.name.clone(), name: name.clone() };
                Err(self.err(node, kind))
            }
        }
    }

    /// The error for the cycle closed by `back` (a frame on `stack`, which is a reference path).
    fn cycle(&self, stack: &[FrameId], back: FrameId, targets: &[[Option<FrameId>; 3]], refs: &[FrameRefs]) -> XmlError {
        let start = stack.iter().position(|&f| f == back).unwrap_or(0);
        let cycle = &stack[start..];
        // The element of `back`'s reference to the next frame on the cycle (always there).
        let second = cycle.get(1).copied().unwrap_or(back);
        let node = targets[back.index()]
            .iter()
            .zip(&refs[back.index()])
            .find_map(|(&t, r)| r.as_ref().filter(|_| t == Some(second)).map(|&(_, n)| n))
            .unwrap_or(self.doc.root());
        let owner = self.model.frame(back).owner;
        let label = |f: FrameId| {
            let frame = self.model.frame(f);
            match frame.owner {
                o if o == owner => frame.name.clone(),
                FrameOwner::Body(b) => {
                    format!("{} of body \"{}\"", frame.name, self.model.bodies[b.index()].cad_name)
                }
                FrameOwner::Ground(g) => {
                    format!("{} of ground \"{}\"", frame.name, self.model.grounds[g.index()].name)
                }
            }
        };
        let names: Vec<String> = cycle.iter().chain([&back]).map(|&f| label(f)).collect();
        let kind = XmlErrorKind::FrameCycle { cycle: names.join(" -> ") };
        self.err(node, kind)
    }
}

/// `CG` or `CS` and digits: what exports call body frames.
fn is_frame_name(name: &str) -> bool {
    name == "CG" || name.strip_prefix("CS").is_some_and(|n| !n.is_empty() && n.bytes().all(|b| b.is_ascii_digit()))
}
