//! Forward kinematics and geometric Jacobians.

use nalgebra::{Isometry3, Matrix6xX, Vector3};

use super::{element_motion, Attachment, Mechanism, MechanismError};
use crate::pipeline::ir::{BodyId, FrameId};

/// World poses of every link frame at one set of coordinates (from [`Mechanism::forward`]).
#[derive(Clone, Debug, Default)]
pub struct Kinematics {
    pub(crate) links: Vec<Isometry3<f64>>,
}

impl Mechanism {
    /// Forward kinematics at tree coordinates `q` (length [`Mechanism::dof`]).
    pub fn forward(&self, q: &[f64]) -> Result<Kinematics, MechanismError> {
        self.check_len("coordinates", q)?;
        let mut k = Kinematics { links: Vec::with_capacity(self.links.len()) };
        self.forward_into(q, &mut k);
        Ok(k)
    }

    /// [`Mechanism::forward`] into an existing buffer (no allocation once it has grown);
    /// `q.len()` must be [`Mechanism::dof`].
    pub(crate) fn forward_into(&self, q: &[f64], k: &mut Kinematics) {
        k.links.clear();
        for (i, l) in self.links.iter().enumerate() {
            let parent = l.parent.and_then(|p| k.links.get(p)).copied().unwrap_or_else(Isometry3::identity);
            let qi = q.get(i).copied().unwrap_or(0.0);
            k.links.push(parent * l.x_tree * element_motion(l.prismatic, &l.axis, qi));
        }
    }

    /// World pose of whatever sits at `at`.
    pub fn attachment_pose(&self, k: &Kinematics, at: &Attachment) -> Isometry3<f64> {
        at.link.and_then(|l| k.links.get(l)).copied().unwrap_or_else(Isometry3::identity) * at.offset
    }

    /// World pose of a body's CS1 frame.
    pub fn body_pose(&self, k: &Kinematics, b: BodyId) -> Result<Isometry3<f64>, MechanismError> {
        let at = self.body_attachment(b).ok_or_else(|| MechanismError::Internal(format!("no body {}", b.0)))?;
        Ok(self.attachment_pose(k, at))
    }

    /// World pose of a CAD frame.
    pub fn frame_pose(&self, k: &Kinematics, f: FrameId) -> Result<Isometry3<f64>, MechanismError> {
        let at = self.frame_attachment(f).ok_or_else(|| MechanismError::Internal(format!("no frame {}", f.0)))?;
        Ok(self.attachment_pose(k, at))
    }

    /// Geometric Jacobian of a CAD frame: 6 x [`Mechanism::dof`], rows `[angular; linear]` in
    /// world coordinates, the linear part being the velocity of the frame's origin. Columns of
    /// coordinates that do not move the frame are zero.
    pub fn jacobian(&self, k: &Kinematics, f: FrameId) -> Result<Matrix6xX<f64>, MechanismError> {
        let at = *self.frame_attachment(f).ok_or_else(|| MechanismError::Internal(format!("no frame {}", f.0)))?;
        let mut j = Matrix6xX::zeros(self.links.len());
        self.jacobian_into(k, &at, &mut j);
        Ok(j)
    }

    /// Fills the columns of `j` (6 x dof, zeroed by the caller) for the links moving `at`.
    pub(crate) fn jacobian_into(&self, k: &Kinematics, at: &Attachment, j: &mut Matrix6xX<f64>) {
        let p = self.attachment_pose(k, at).translation.vector;
        let mut cur = at.link;
        while let Some(i) = cur {
            let (Some(l), Some(pose)) = (self.links.get(i), k.links.get(i)) else { break };
            let a: Vector3<f64> = pose.rotation * l.axis;
            if l.prismatic {
                j.fixed_view_mut::<3, 1>(3, i).copy_from(&a);
            } else {
                j.fixed_view_mut::<3, 1>(0, i).copy_from(&a);
                j.fixed_view_mut::<3, 1>(3, i).copy_from(&a.cross(&(p - pose.translation.vector)));
            }
            cur = l.parent;
        }
    }
}
