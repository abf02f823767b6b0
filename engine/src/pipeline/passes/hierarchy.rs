//! The body/joint hierarchy: a spanning tree from the grounds, the loops it leaves, free bodies.
//!
//! The XML is a graph (bodies and grounds are nodes, joints are edges). The tree is built
//! Kruskal-style over joints ordered (welds first, then by `node_id`), with every ground joined to
//! the world up front. Welds first means a loop is closed by a movable joint whenever one exists
//! in it; ordering by `node_id` (never file order) keeps the choice stable across re-exports.

use std::collections::{BTreeSet, VecDeque};

use crate::pipeline::ir::{BodyId, FrameId, FrameOwner, JointId, Model};

/// A node of the graph: a body or a ground (grounds are all fixed to the world).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Node {
    Body(BodyId),
    Ground(crate::pipeline::ir::GroundId),
}

/// What kind of loop a joint outside the tree closes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LoopKind {
    /// A loop with movable joints: `passes::loops` decides how its closing joint is emitted.
    Kinematic,
    /// A weld closing a loop of welds only: redundant, not emitted (the frames are already
    /// rigidly related through the tree).
    Rigid,
}

/// One closed kinematic loop.
#[derive(Clone, Debug)]
pub struct Loop {
    /// The joint outside the tree that closes the loop.
    pub closing: JointId,
    /// The tree joints on the path between the closing joint's two sides: from its base side up
    /// to the common ancestor, then down to its follower side.
    pub path: Vec<JointId>,
    /// How many of `path`'s joints lie on the base side (the rest lie on the follower side).
    pub base_side: usize,
    pub kind: LoopKind,
}

/// Side table of the hierarchy pass.
#[derive(Clone, Debug, Default)]
pub struct Hierarchy {
    /// Tree joints in breadth-first order from the grounds.
    pub tree: Vec<JointId>,
    /// Joints outside the tree, one per loop.
    pub loops: Vec<Loop>,
    /// Bodies without a path to any ground, sorted by `node_id`.
    pub free_bodies: Vec<BodyId>,
    /// The root of each free component (its body with the smallest `node_id`): it carries the
    /// component's initial pose.
    pub free_roots: Vec<BodyId>,
    /// Depth of each body in the tree (grounds are depth 0); `None` for free bodies.
    pub depth: Vec<Option<u32>>,
    /// Per joint: true when it lies on some loop (tree path or closing joint).
    pub in_loop: Vec<bool>,
    /// Per tree joint: true when its follower side is the child (farther from the root), so the
    /// child's motion relative to the parent is the joint's own motion; false when reversed.
    pub follower_is_child: Vec<bool>,
}

impl Hierarchy {
    pub fn loop_of_closing(&self, j: JointId) -> Option<&Loop> {
        self.loops.iter().find(|l| l.closing == j)
    }
}

/// The node a frame belongs to.
pub fn node_of(model: &Model, f: FrameId) -> Node {
    match model.frame(f).owner {
        FrameOwner::Body(b) => Node::Body(b),
        FrameOwner::Ground(g) => Node::Ground(g),
    }
}

/// Union-find over `0..n` (path halving; the smaller root wins, so results do not depend on
/// the order of unions).
pub(super) struct Dsu(Vec<usize>);

impl Dsu {
    pub(super) fn new(n: usize) -> Dsu {
        Dsu((0..n).collect())
    }

    pub(super) fn find(&mut self, mut x: usize) -> usize {
        while self.0[x] != x {
            self.0[x] = self.0[self.0[x]];
            x = self.0[x];
        }
        x
    }
    /// Joins the sets of `a` and `b`; false when they were one already.
    pub(super) fn union(&mut self, a: usize, b: usize) -> bool {
        let (ra, rb) = (self.find(a), self.find(b));
        if ra == rb {
            return false;
        }
        self.0[ra.max(rb)] = ra.min(rb);
        true
    }
}

/// Builds the hierarchy. Infallible: every graph has a spanning forest.
pub fn build(model: &Model) -> Hierarchy {
    build_with(model, &BTreeSet::new())
}

/// [`build`], with the joints of `cut_last` taken into the tree only after every other joint of
/// their kind, so that each one closes a loop it lies on (the loop pass uses this to move a cut to
/// a better joint).
pub fn build_with(model: &Model, cut_last: &BTreeSet<JointId>) -> Hierarchy {
    let nb = model.bodies.len();
    let ng = model.grounds.len();
    // Node index: bodies 0..nb, grounds nb..nb+ng, the world nb+ng.
    let world = nb + ng;
    let index = |n: Node| match n {
        Node::Body(b) => b.index(),
        Node::Ground(g) => nb + g.index(),
    };
    let mut dsu = Dsu::new(world + 1);
    for g in 0..ng {
        dsu.union(nb + g, world);
    }
    let mut order: Vec<JointId> = model.joint_ids().collect();
    order.sort_by(|a, b| {
        let (ja, jb) = (model.joint(*a), model.joint(*b));
        (!ja.is_weld(), cut_last.contains(a), &ja.node_id).cmp(&(!jb.is_weld(), cut_last.contains(b), &jb.node_id))
    });
    let mut adjacency: Vec<Vec<(JointId, usize)>> = vec![Vec::new(); world + 1];
    let mut closers = Vec::new();
    for j in order {
        let joint = model.joint(j);
        let a = index(node_of(model, joint.base));
        let b = index(node_of(model, joint.follower));
        if dsu.union(a, b) {
            adjacency[a].push((j, b));
            adjacency[b].push((j, a));
        } else {
            closers.push(j);
        }
    }
    for g in 0..ng {
        adjacency[world].push((JointId(u32::MAX), nb + g));
    }

    // Breadth-first from the world, then from each free component (rooted at its smallest node_id).
    let mut depth: Vec<Option<u32>> = vec![None; world + 1];
    let mut parent: Vec<Option<(JointId, usize)>> = vec![None; world + 1];
    let mut follower_is_child = vec![false; model.joints.len()];
    let mut tree = Vec::new();
    let mut bfs = |root: usize, depth: &mut Vec<Option<u32>>, tree: &mut Vec<JointId>| {
        depth[root] = Some(0);
        let mut queue = VecDeque::from([root]);
        while let Some(n) = queue.pop_front() {
            let mut next: Vec<(JointId, usize)> = adjacency[n].clone();
            next.sort_by(|x, y| sort_key(model, x.0).cmp(&sort_key(model, y.0)));
            for (j, m) in next {
                if depth[m].is_none() {
                    depth[m] = Some(depth[n].unwrap_or(0) + u32::from(j.0 != u32::MAX));
                    parent[m] = (j.0 != u32::MAX).then_some((j, n));
                    if j.0 != u32::MAX {
                        tree.push(j);
                        follower_is_child[j.index()] = index(node_of(model, model.joint(j).follower)) == m;
                    }
                    queue.push_back(m);
                }
            }
        }
    };
    bfs(world, &mut depth, &mut tree);
    let mut free_bodies: Vec<BodyId> = (0..nb).filter(|&i| depth[i].is_none()).map(|i| BodyId(i as u32)).collect();
    free_bodies.sort_by(|a, b| model.body(*a).node_id.cmp(&model.body(*b).node_id));
    let mut free_depth = depth.clone();
    let mut free_roots = Vec::new();
    for b in &free_bodies {
        if free_depth[b.index()].is_none() {
            free_roots.push(*b);
            bfs(b.index(), &mut free_depth, &mut tree);
        }
    }

    let mut in_loop = vec![false; model.joints.len()];
    let mut loops = Vec::new();
    closers.sort_by(|a, b| model.joint(*a).node_id.cmp(&model.joint(*b).node_id));
    for j in closers {
        let joint = model.joint(j);
        let a = index(node_of(model, joint.base));
        let b = index(node_of(model, joint.follower));
        let (path, base_side) = tree_path(a, b, &parent, &free_depth);
        let all_welds = std::iter::once(&j).chain(&path).all(|j| model.joint(*j).is_weld());
        let kind = if all_welds { LoopKind::Rigid } else { LoopKind::Kinematic };
        if kind != LoopKind::Rigid {
            in_loop[j.index()] = true;
            for p in &path {
                in_loop[p.index()] = true;
            }
        }
        loops.push(Loop { closing: j, path, base_side, kind });
    }
    let depth = (0..nb).map(|i| free_depth[i]).collect();
    Hierarchy { tree, loops, free_bodies, free_roots, depth, in_loop, follower_is_child }
}

fn sort_key(model: &Model, j: JointId) -> (bool, &str) {
    if j.0 == u32::MAX {
        return (false, "");
    }
    let joint = model.joint(j);
    (!joint.is_weld(), joint.node_id.as_str())
}

/// Tree joints between nodes `a` and `b` (via their lowest common ancestor): those from `a` up,
/// then those down to `b`, and how many are on `a`'s side.
fn tree_path(mut a: usize, mut b: usize, parent: &[Option<(JointId, usize)>], depth: &[Option<u32>]) -> (Vec<JointId>, usize) {
    let d = |n: usize| depth[n].unwrap_or(0);
    let (mut up_a, mut up_b) = (Vec::new(), Vec::new());
    while d(a) > d(b) {
        let Some((j, p)) = parent[a] else { break };
        up_a.push(j);
        a = p;
    }
    while d(b) > d(a) {
        let Some((j, p)) = parent[b] else { break };
        up_b.push(j);
        b = p;
    }
    while a != b {
        match (parent[a], parent[b]) {
            (Some((ja, pa)), Some((jb, pb))) => {
                up_a.push(ja);
                up_b.push(jb);
                a = pa;
                b = pb;
            }
            // Different roots (two grounds joined through the world): the world closes the path.
            _ => break,
        }
    }
    up_b.reverse();
    let base_side = up_a.len();
    up_a.extend(up_b);
    (up_a, base_side)
}
