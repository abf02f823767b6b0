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

/// Gauss-Newton iterations per group of coupled loops.
const ITERATIONS: usize = 100;

/// Most assembly work, in units of one link pose composed (or one residual row) per Jacobian
/// column evaluated plus one multiply-add of the pseudo-inverse's decomposition, summed over the
/// iterations of every group (about 2 s in a release build). Many independent loops (a gripper's
/// four-bars) cost little each; what is refused is a loop across a very long chain or many loops
/// coupled through one chain.
pub(super) const MAX_ASSEMBLY_WORK: u64 = 50_000_000;

/// Why the loops were not closed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum NotClosed {
    /// Gauss-Newton stopped above [`CLOSED`] (the largest violation left).
    Open(f64),
    /// The next iteration would pass [`MAX_ASSEMBLY_WORK`]: `work` units were needed.
    TooCostly { work: u64 },
}

/// Joint values closing every loop, nearest to zero; [`NotClosed::Open`] when Gauss-Newton does
/// not get below [`CLOSED`] (the loops cannot close near the zero configuration).
///
/// Loops that share no movable joint on their paths to the root are independent (neither moves
/// the other's links), so each group of coupled loops is solved on its own over the joints it
/// depends on: the work is the sum of the groups', not the square of all of them.
pub(super) fn assemble(nlinks: usize, joints: &[TreeJoint], order: &[usize], loops: &[LoopSpec]) -> Result<Vec<f64>, NotClosed> {
    let mut q = vec![0.0; joints.len()];
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
    let paths: Vec<(Vec<usize>, Vec<usize>)> = loops.iter().map(|l| (ancestors(l.a), ancestors(l.b))).collect();
    // Groups: loops joined when a movable joint is an ancestor of a link of each.
    let mut group: Vec<usize> = (0..loops.len()).collect();
    fn find(group: &mut [usize], mut i: usize) -> usize {
        while group[i] != i {
            group[i] = group[group[i]];
            i = group[i];
        }
        i
    }
    let mut owner: Vec<Option<usize>> = vec![None; joints.len()];
    for (i, (pa, pb)) in paths.iter().enumerate() {
        for &k in pa.iter().chain(pb) {
            if joints[k].motion == Motion::None {
                continue;
            }
            match owner[k] {
                Some(o) => {
                    let (ro, ri) = (find(&mut group, o), find(&mut group, i));
                    group[ro.max(ri)] = ro.min(ri);
                }
                None => owner[k] = Some(i),
            }
        }
    }
    let mut members: Vec<Vec<usize>> = vec![Vec::new(); loops.len()];
    for i in 0..loops.len() {
        let r = find(&mut group, i);
        members[r].push(i);
    }
    let position = {
        let mut at = vec![usize::MAX; joints.len()];
        for (i, &k) in order.iter().enumerate() {
            at[k] = i;
        }
        at
    };
    let mut pose = vec![Isometry3::identity(); nlinks];
    let mut work = 0u64;
    let mut worst = 0.0f64;
    let mut mark = vec![false; joints.len()];
    for ids in members.iter().filter(|m| !m.is_empty()) {
        let specs: Vec<LoopSpec> = ids.iter().map(|&i| loops[i].clone()).collect();
        // Unknowns: movable joints on the path from either loop link up to (not past) their
        // common ancestor. The joints to evaluate: every ancestor of a loop link, parents first.
        let mut vars: Vec<usize> = Vec::new();
        let mut eval: Vec<usize> = Vec::new();
        for &i in ids {
            let (pa, pb) = &paths[i];
            for &k in pb {
                mark[k] = true;
            }
            let in_a: Vec<usize> = pa.iter().copied().filter(|&k| !mark[k]).collect();
            for &k in pb {
                mark[k] = false;
            }
            for &k in pa {
                mark[k] = true;
            }
            let in_b: Vec<usize> = pb.iter().copied().filter(|&k| !mark[k]).collect();
            for &k in pa {
                mark[k] = false;
            }
            vars.extend(in_a.into_iter().chain(in_b).filter(|&k| joints[k].motion != Motion::None));
            eval.extend(pa.iter().chain(pb).copied().filter(|&k| position[k] != usize::MAX));
        }
        vars.sort_unstable();
        vars.dedup();
        eval.sort_unstable_by_key(|&k| position[k]);
        eval.dedup();
        let rows = 6 * specs.len() as u64;
        let v = vars.len() as u64;
        let iteration = (2 * v + 1) * (eval.len() as u64 + specs.len() as u64) + rows * v * rows.min(v);
        let mut violation = |q: &[f64]| {
            for &k in &eval {
                let j = &joints[k];
                let p = j.parent.map_or(Isometry3::identity(), |p| pose[p]);
                pose[j.child] = p * j.origin * motion(j.motion, &j.axis, q[k]);
            }
            residual(&specs, &pose)
        };
        let mut r = violation(&q);
        for _ in 0..ITERATIONS {
            if r.amax() <= CLOSED || vars.is_empty() {
                break;
            }
            work = work.saturating_add(iteration);
            if work > MAX_ASSEMBLY_WORK {
                return Err(NotClosed::TooCostly { work });
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
        worst = worst.max(r.amax());
    }
    if worst <= CLOSED {
        Ok(q)
    } else {
        Err(NotClosed::Open(worst))
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
