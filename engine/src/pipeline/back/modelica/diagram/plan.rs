//! Where the Mechanics diagram wants each component, from the kinematic tree.
//!
//! Columns are tree depths, left to right: the world (with the grounds' frames) in column 0,
//! every body at its depth. A body's group stands in its column: the frame its parent's joint
//! arrives at on the left (mirrored, so the joint's `frame_b` meets it head on), the body at
//! the top right with its other frames and its shape below. The joint that carries a body
//! stands in the gap left of the body's column, on the body's first row, its chain of elements
//! left to right; loop-closing joints and mimic couplings get rows of their own under it, in the
//! gap left of the deeper of their two sides. Siblings go top to bottom, each below the whole
//! subtree of the one before it. Rows an earlier version used (by node ID) are kept when still
//! free, so a CAD change moves only what it touched.

use std::collections::{BTreeMap, HashMap};

use super::Want;
use crate::pipeline::ir::{BodyId, FrameId, FrameOwner, JointId, Model};
use crate::pipeline::passes::kinematics::is_identity;
use crate::pipeline::passes::loops::Cut;
use crate::pipeline::valid::Validated;

/// Row pitch and the largest half size of a component.
pub const ROW: i32 = 100;
pub const HALF: i32 = 20;
/// Column: the mirrored arrival frames' sub-column, a 40-unit corridor, the body sub-column.
const COL_WIDTH: i32 = 4 * HALF + 40;
/// A joint element's pitch in a gap.
const PITCH: i32 = 2 * HALF + 40;

/// Half size that keeps a name readable (MSL icons draw the name 1.5 extents wide).
pub fn half_for(name: &str) -> i32 {
    let len = name.chars().count() as i32;
    (((len * 4 + 4) / 5 + 4) / 5 * 5).clamp(10, HALF)
}

/// A group: the world (index 0) or body `b` (index `b + 1`).
fn group_of_frame(model: &Model, f: FrameId) -> usize {
    match model.frame(f).owner {
        FrameOwner::Body(b) => b.index() + 1,
        FrameOwner::Ground(_) => 0,
    }
}

/// Where a frame's fixed transform stands when not in the body's sub-column: mirrored, in the
/// arrival sub-column, at this row of the group.
#[derive(Clone, Copy, Debug)]
enum Side {
    Left(i32),
}

/// The spots of one model's components.
#[derive(Clone, Debug, Default)]
pub struct Plan {
    col: Vec<usize>,
    row: Vec<i32>,
    col_x: Vec<i32>,
    /// Per joint: the x of the gap's first and last element slots, the y, and whether the
    /// chain runs right to left (its base is the group on the right).
    joint: Vec<Option<(i32, i32, i32, bool)>>,
    frame_side: HashMap<FrameId, Side>,
    /// The right-hand slot of each frame that stands there.
    frame_slot: HashMap<FrameId, i32>,
    /// Per coupling follower joint: its row's x and y.
    coupling: HashMap<usize, (i32, i32)>,
    /// Group positions (column, row) by node ID (`world` for the world), for the next version.
    pub groups: BTreeMap<String, (i32, i32)>,
}

impl Plan {
    pub fn new(model: &Model, v: &Validated, hints: &BTreeMap<String, (i32, i32)>) -> Plan {
        let h = &v.analysis.hierarchy;
        let n = model.bodies.len() + 1;
        // The tree: parent and child group of each tree joint.
        let mut children: Vec<Vec<(usize, JointId)>> = vec![Vec::new(); n];
        let mut parent: Vec<Option<usize>> = vec![None; n];
        let mut into: Vec<Option<JointId>> = vec![None; n];
        for &j in &h.tree {
            let joint = model.joint(j);
            let (p, c) = if h.follower_is_child.get(j.index()).copied().unwrap_or(true) {
                (group_of_frame(model, joint.base), group_of_frame(model, joint.follower))
            } else {
                (group_of_frame(model, joint.follower), group_of_frame(model, joint.base))
            };
            if c == 0 || parent[c].is_some() || p == c {
                continue;
            }
            parent[c] = Some(p);
            into[c] = Some(j);
            children[p].push((c, j));
        }
        // Depths: the world 0; roots of free components (no parent) 1.
        let mut col = vec![0usize; n];
        let mut order = Vec::with_capacity(n);
        let mut roots = vec![0usize];
        roots.extend((1..n).filter(|&g| parent[g].is_none()));
        for &r in &roots {
            col[r] = usize::from(r != 0);
            let mut stack = vec![r];
            while let Some(g) = stack.pop() {
                order.push(g);
                for &(c, _) in children[g].iter().rev() {
                    col[c] = col[g] + 1;
                    stack.push(c);
                }
            }
        }
        // Which frames get components (as the writer decides) and where.
        let needs = |f: FrameId| -> bool {
            let fr = model.frame(f);
            match fr.owner {
                FrameOwner::Body(b) => {
                    let body = model.body(b);
                    f != body.cs1 && !is_identity(&(model.frame(body.cs1).pose.inverse() * fr.pose))
                }
                FrameOwner::Ground(_) => !is_identity(&fr.pose),
            }
        };
        let mut frame_side: HashMap<FrameId, Side> = HashMap::new();
        let mut extra_rows = vec![0i32; n];
        let mut joint_at: Vec<Option<(usize, i32, bool)>> = vec![None; model.joints.len()];
        for (g, j) in into.iter().enumerate() {
            let Some(j) = *j else { continue };
            let joint = model.joint(j);
            let base_is_child = group_of_frame(model, joint.base) == g;
            let arrival = if base_is_child { joint.base } else { joint.follower };
            frame_side.entry(arrival).or_insert(Side::Left(0));
            joint_at[j.index()] = Some((g, 0, base_is_child));
        }
        for (l, info) in h.loops.iter().zip(&v.analysis.loops.loops) {
            if info.cut == Cut::Omitted {
                continue;
            }
            let joint = model.joint(l.closing);
            let (gb, gf) = (group_of_frame(model, joint.base), group_of_frame(model, joint.follower));
            let a = if col[gb] > col[gf] { gb } else { gf };
            extra_rows[a] += 1;
            let slot = extra_rows[a];
            let near = if a == gb { joint.base } else { joint.follower };
            if a != 0 {
                frame_side.entry(near).or_insert(Side::Left(slot));
            }
            joint_at[l.closing.index()] = Some((a, slot, a == gb));
        }
        let mut coupling_at: Vec<(usize, usize, i32)> = Vec::new();
        for c in &model.couplings {
            let f = c.follower.index();
            if let Some(Some((g, 0, _))) = joint_at.get(f) {
                extra_rows[*g] += 1;
                coupling_at.push((f, *g, extra_rows[*g]));
            }
        }
        // Right-hand slots per group: the body, its shape, then its frames (the world: the
        // grounds' frames). A frame keeps the slot an earlier version gave it when still free.
        let shape_slot = |g: usize| g > 0 && model.bodies[g - 1].mesh.as_ref().is_some_and(|m| !m.triangles.is_empty());
        let first_frame_slot = |g: usize| if g == 0 { 0 } else { 1 + i32::from(shape_slot(g)) };
        let mut used = crate::pipeline::back::modelica::write::shown_frames(model);
        let mut seen = std::collections::HashSet::new();
        used.retain(|f| seen.insert(*f) && needs(*f));
        let mut left_rows = vec![0i32; n];
        let mut slots_taken: Vec<std::collections::BTreeSet<i32>> = vec![Default::default(); n];
        let mut frame_slot: HashMap<FrameId, i32> = HashMap::new();
        let frame_key = |f: FrameId| format!("frame {}", model.frame(f).node_id);
        let mut unhinted = Vec::new();
        for &f in &used {
            let g = group_of_frame(model, f);
            if let Some(Side::Left(r)) = frame_side.get(&f) {
                left_rows[g] = left_rows[g].max(r + 1);
                continue;
            }
            match hints.get(&frame_key(f)) {
                Some(&(_, slot)) if slot >= first_frame_slot(g) && slot < 10_000 && slots_taken[g].insert(slot) => {
                    frame_slot.insert(f, slot);
                }
                _ => unhinted.push(f),
            }
        }
        for f in unhinted {
            let g = group_of_frame(model, f);
            let mut slot = first_frame_slot(g);
            while slots_taken[g].contains(&slot) {
                slot += 1;
            }
            slots_taken[g].insert(slot);
            frame_slot.insert(f, slot);
        }
        let right: Vec<i32> = (0..n).map(|g| slots_taken[g].iter().next_back().map_or(first_frame_slot(g), |s| s + 1)).collect();
        let rows: Vec<i32> = (0..n).map(|g| right[g].max(left_rows[g]).max(1 + extra_rows[g]).max(1)).collect();

        // Rows: first the groups whose earlier rows are still free, then the others, depth first.
        let key = |g: usize| if g == 0 { "world".to_string() } else { model.bodies[g - 1].node_id.clone() };
        let max_col = col.iter().copied().max().unwrap_or(0);
        let mut taken: Vec<Vec<(i32, i32)>> = vec![Vec::new(); max_col + 1];
        let free = |taken: &Vec<(i32, i32)>, r: i32, len: i32| taken.iter().all(|&(a, b)| r + len <= a || b <= r);
        let mut row: Vec<Option<i32>> = vec![None; n];
        for &g in &order {
            if let Some(&(c, r)) = hints.get(&key(g)) {
                if c == col[g] as i32 && r >= 0 && free(&taken[col[g]], r, rows[g]) {
                    taken[col[g]].push((r, r + rows[g]));
                    row[g] = Some(r);
                }
            }
        }
        // Each group at the first free row from `desired` in its column, its children below one
        // another from its row on; returns the subtree's bottom. Iterative (an explicit stack of
        // (group, next child, next row, bottom so far)): a chain's depth is not the thread's stack.
        fn place(
            root: usize,
            desired: i32,
            col: &[usize],
            rows: &[i32],
            children: &[Vec<(usize, JointId)>],
            taken: &mut [Vec<(i32, i32)>],
            row: &mut [Option<i32>],
        ) -> i32 {
            let mut start = |g: usize, desired: i32| -> i32 {
                match row[g] {
                    Some(r) => r,
                    None => {
                        let t = &mut taken[col[g]];
                        let mut r = desired;
                        while let Some(&(_, b)) = t.iter().find(|&&(a, b)| r < b && a < r + rows[g]) {
                            r = b;
                        }
                        t.push((r, r + rows[g]));
                        row[g] = Some(r);
                        r
                    }
                }
            };
            let r = start(root, desired);
            let mut stack: Vec<(usize, usize, i32, i32)> = vec![(root, 0, r, r + rows[root])];
            loop {
                let Some(top) = stack.last_mut() else { return 0 };
                let (g, k, next) = (top.0, top.1, top.2);
                if let Some(&(c, _)) = children[g].get(k) {
                    top.1 += 1;
                    let r = start(c, next);
                    stack.push((c, 0, r, r + rows[c]));
                    continue;
                }
                let bottom = top.3;
                stack.pop();
                match stack.last_mut() {
                    Some(parent) => {
                        parent.2 = bottom;
                        parent.3 = parent.3.max(bottom);
                    }
                    None => return bottom,
                }
            }
        }
        let mut next = 0;
        for &r in &roots {
            next = place(r, next, &col, &rows, &children, &mut taken, &mut row);
        }
        let row: Vec<i32> = row.into_iter().map(|r| r.unwrap_or(0)).collect();

        // Gap widths: the longest chain standing in each.
        let mut slots = vec![1usize; max_col + 2];
        for (j, at) in joint_at.iter().enumerate() {
            if let Some((g, _, _)) = at {
                let chain = &v.analysis.chains[j];
                let count =
                    chain.elements.len().max(1) + usize::from(!is_identity(&chain.residual)) + usize::from(!is_identity(&chain.pre)) + 1;
                let gap = col[*g].max(1);
                slots[gap] = slots[gap].max(count);
            }
        }
        let mut col_x = vec![0i32; max_col + 2];
        for k in 1..col_x.len() {
            col_x[k] = col_x[k - 1] + COL_WIDTH + PITCH * slots[k] as i32 + 40;
        }
        let joint = joint_at
            .iter()
            .map(|at| {
                at.map(|(g, slot, rev)| {
                    let gap = col[g].max(1);
                    let x0 = col_x[gap - 1] + COL_WIDTH + 40 + HALF;
                    (x0, x0 + PITCH * (slots[gap] as i32 - 1), -(row[g] + slot) * ROW, rev)
                })
            })
            .collect();
        let mut coupling = HashMap::new();
        for (f, g, slot) in coupling_at {
            let gap = col[g].max(1);
            coupling.insert(f, (col_x[gap - 1] + COL_WIDTH + 40 + HALF, -(row[g] + slot) * ROW));
        }
        let mut groups: BTreeMap<String, (i32, i32)> = (0..n).map(|g| (key(g), (col[g] as i32, row[g]))).collect();
        for (f, slot) in &frame_slot {
            groups.entry(frame_key(*f)).or_insert((-1, *slot));
        }
        Plan { col, row, col_x, joint, frame_side, frame_slot, coupling, groups }
    }

    fn left_x(&self, g: usize) -> i32 {
        self.col_x[self.col[g]] + HALF
    }
    fn right_x(&self, g: usize) -> i32 {
        self.col_x[self.col[g]] + 3 * HALF + 40
    }
    fn y(&self, g: usize, slot: i32) -> i32 {
        -(self.row[g] + slot) * ROW
    }

    pub fn world(&self, half: i32) -> Want {
        Want { x: self.left_x(0), y: self.y(0, 0), half, flip: false }
    }

    pub fn body(&self, b: BodyId, half: i32) -> Want {
        Want { x: self.right_x(b.index() + 1), y: self.y(b.index() + 1, 0), half, flip: false }
    }

    pub fn frame(&self, model: &Model, f: FrameId, half: i32) -> Want {
        let g = group_of_frame(model, f);
        match self.frame_side.get(&f) {
            Some(Side::Left(slot)) => Want { x: self.left_x(g), y: self.y(g, *slot), half, flip: true },
            None => {
                let slot = self.frame_slot.get(&f).copied().unwrap_or(0);
                Want { x: self.right_x(g), y: self.y(g, slot), half, flip: false }
            }
        }
    }

    /// The shape stands right under its body.
    pub fn shape(&self, b: BodyId, half: i32) -> Want {
        Want { x: self.right_x(b.index() + 1), y: self.y(b.index() + 1, 1), half, flip: false }
    }

    /// Component `k` of joint `j`'s chain (axes, elements, offset, in order): from the left
    /// end of its gap, or mirrored from the right end when the chain runs right to left.
    pub fn element(&self, j: JointId, k: usize, half: i32) -> Want {
        match self.joint.get(j.index()).copied().flatten() {
            Some((x0, x1, y, rev)) => {
                let x = if rev { x1 - PITCH * k as i32 } else { x0 + PITCH * k as i32 };
                Want { x, y, half, flip: rev }
            }
            None => Want { x: self.col_x[0], y: self.y(0, 0), half, flip: false },
        }
    }

    /// Component `k` of the coupling whose follower is joint `j`.
    pub fn coupling(&self, j: JointId, k: usize, half: i32) -> Want {
        let (x, y) = self.coupling.get(&j.index()).copied().unwrap_or((self.col_x[0], 0));
        Want { x: x + PITCH * k as i32, y, half, flip: false }
    }
}
