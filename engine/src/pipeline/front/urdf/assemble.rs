//! Closing Drake `<loop_joint>`s: URDF's zero configuration need not satisfy them (Robotiq's
//! finger four-bars are open by up to 40 mm there), so the assembly pose is found first, the way
//! Drake assembles before simulating: Gauss-Newton with minimum-norm steps (SVD
//! pseudo-inverse) on the joints between each loop's links and their common ancestor, from the
//! zero configuration, so the nearest closed configuration is found. The IR's CAD pose is then
//! that assembled pose: each tree joint's start value is its assembled coordinate.

use nalgebra::{DMatrix, DVector, Isometry3, Translation3, Unit, UnitQuaternion, Vector3};

/// How a tree joint moves its child.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Motion {
    Revolute,
    Prismatic,
    /// Fixed, or any joint the assembly leaves alone.
    None,
}

/// A tree joint: the child link's pose is `parent * origin * motion(axis, q)`.
#[derive(Clone, Debug)]
pub(super) struct TreeJoint {
    /// Parent link (`None`: the world).
    pub parent: Option<usize>,
    pub child: usize,
    pub origin: Isometry3<f64>,
    /// Unit axis in the joint frame.
    pub axis: Vector3<f64>,
    pub motion: Motion,
}

/// A loop joint between a frame on link `a` (`ta` in `a`) and one on link `b`.
#[derive(Clone, Debug)]
pub(super) struct LoopSpec {
    pub a: usize,
    pub ta: Isometry3<f64>,
    pub b: usize,
    pub tb: Isometry3<f64>,
    /// Unit axis in the frame on `a`.
    pub axis: Vector3<f64>,
    pub motion: Motion,
    /// Fixed loop joint: the frames must coincide in full.
    pub fixed: bool,
}

pub(super) fn motion(m: Motion, axis: &Vector3<f64>, q: f64) -> Isometry3<f64> {
    match m {
        Motion::Revolute => {
            Isometry3::from_parts(Translation3::identity(), UnitQuaternion::from_axis_angle(&Unit::new_unchecked(*axis), q))
        }
        Motion::Prismatic => Isometry3::translation(axis.x * q, axis.y * q, axis.z * q),
        Motion::None => Isometry3::identity(),
    }
}

/// World pose of every link at joint values `q` (per tree joint); `order` lists the joints so
/// that a parent's pose is known before its children's (roots are at the identity).
pub(super) fn poses(nlinks: usize, joints: &[TreeJoint], order: &[usize], q: &[f64]) -> Vec<Isometry3<f64>> {
    let mut pose = vec![Isometry3::identity(); nlinks];
    for &k in order {
        let j = &joints[k];
        let p = j.parent.map_or(Isometry3::identity(), |p| pose[p]);
        pose[j.child] = p * j.origin * motion(j.motion, &j.axis, q[k]);
    }
    pose
}

/// The loops' violation at `pose`: per loop, the distance between the frames' origins (along the
/// axis only for prismatic loops: the perpendicular part) and, unless fixed, the misalignment of
/// the axes (the cross product); for fixed loops the rotation between the frames.
fn residual(loops: &[LoopSpec], pose: &[Isometry3<f64>]) -> DVector<f64> {
    let mut r = Vec::with_capacity(loops.len() * 6);
    for l in loops {
        let (fa, fb) = (pose[l.a] * l.ta, pose[l.b] * l.tb);
        let d = fa.translation.vector - fb.translation.vector;
        let na = fa.rotation * l.axis;
        let nb = fb.rotation * l.axis;
        let d = if l.motion == Motion::Prismatic { d - na * na.dot(&d) } else { d };
        r.extend(d.iter());
        if l.fixed {
            r.extend((fa.rotation.inverse() * fb.rotation).scaled_axis().iter());
        } else {
            r.extend(na.cross(&nb).iter());
        }
    }
    DVector::from_vec(r)
}

/// Largest loop violation accepted as closed (m, or rad for the axis terms).
pub(super) const CLOSED: f64 = 1e-12;

/// Joint values closing every loop, nearest to zero; `Err(violation)` when Gauss-Newton does not
/// get below [`CLOSED`] (the loops cannot close near the zero configuration).
pub(super) fn assemble(nlinks: usize, joints: &[TreeJoint], order: &[usize], loops: &[LoopSpec]) -> Result<Vec<f64>, f64> {
    let mut q = vec![0.0; joints.len()];
    // Unknowns: movable joints on the path from either loop link up to (not past) their common
    // ancestor.
    let parent_joint = {
        let mut pj = vec![None; nlinks];
        for (k, j) in joints.iter().enumerate() {
            pj[j.child] = Some(k);
        }
        pj
    };
    let ancestors = |mut link: usize| {
        let mut out = Vec::new();
        let mut guard = 0;
        while let Some(k) = parent_joint[link] {
            out.push(k);
            match joints[k].parent {
                Some(p) if guard < nlinks => link = p,
                _ => break,
            }
            guard += 1;
        }
        out
    };
    let mut vars: Vec<usize> = Vec::new();
    for l in loops {
        let (pa, pb) = (ancestors(l.a), ancestors(l.b));
        for k in pa.iter().filter(|k| !pb.contains(k)).chain(pb.iter().filter(|k| !pa.contains(k))) {
            if joints[*k].motion != Motion::None && !vars.contains(k) {
                vars.push(*k);
            }
        }
    }
    vars.sort_unstable();
    let violation = |q: &[f64]| residual(loops, &poses(nlinks, joints, order, q));
    let mut r = violation(&q);
    for _ in 0..100 {
        if r.amax() <= CLOSED || vars.is_empty() {
            break;
        }
        let h = 1e-6;
        let mut jac = DMatrix::zeros(r.len(), vars.len());
        for (c, &k) in vars.iter().enumerate() {
            let mut qp = q.clone();
            qp[k] += h;
            let mut qm = q.clone();
            qm[k] -= h;
            jac.set_column(c, &((violation(&qp) - violation(&qm)) / (2.0 * h)));
        }
        let Ok(pinv) = jac.pseudo_inverse(1e-10) else { break };
        let mut step = -(pinv * &r);
        let norm = step.norm();
        if norm > 0.5 {
            step *= 0.5 / norm;
        }
        for (c, &k) in vars.iter().enumerate() {
            q[k] += step[c];
        }
        r = violation(&q);
    }
    if r.amax() <= CLOSED {
        Ok(q)
    } else {
        Err(r.amax())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A parallelogram four-bar built open (the coupler 0.1 rad off): assembly closes it and the
    /// loop frames then coincide.
    #[test]
    fn closes_an_open_four_bar() {
        let z = Vector3::z();
        let j = |parent, child, x: f64, y: f64| TreeJoint {
            parent,
            child,
            origin: Isometry3::translation(x, y, 0.0),
            axis: z,
            motion: Motion::Revolute,
        };
        // links: 0 ground, 1 crank, 2 coupler, 3 rocker
        let mut joints = vec![j(Some(0), 1, 0.0, 0.0), j(Some(1), 2, 0.0, 1.0), j(Some(0), 3, 2.0, 0.0)];
        joints[1].origin *= Isometry3::rotation(z * 0.1);
        let order = [0, 1, 2];
        let loops = [LoopSpec {
            a: 2,
            ta: Isometry3::translation(2.0, 0.0, 0.0),
            b: 3,
            tb: Isometry3::translation(0.0, 1.0, 0.0),
            axis: z,
            motion: Motion::Revolute,
            fixed: false,
        }];
        let open = residual(&loops, &poses(4, &joints, &order, &[0.0; 3]));
        assert!(open.amax() > 0.05);
        let q = assemble(4, &joints, &order, &loops).expect("closes");
        let p = poses(4, &joints, &order, &q);
        assert!(residual(&loops, &p).amax() <= CLOSED);
        // Small correction: the nearest closed configuration, not a far branch.
        assert!(q.iter().all(|v| v.abs() < 0.5), "{q:?}");
    }
}
