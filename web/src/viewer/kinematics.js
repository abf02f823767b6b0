// Forward kinematics of a converted model, from its conversion report alone.
//
// The report gives every body's CS1 pose at the CAD pose and, for every joint element, its axis
// and origin in world coordinates at the CAD pose. Moving element k of a joint by dq from its
// start value moves the follower side about (revolute) or along (prismatic) that world axis, and
// the elements of one joint compose in order: M = M1 · M2 · … (each Mk in CAD-pose world
// coordinates, see the derivation in ARCHITECTURE.md). Walking the spanning tree (the joints the
// report marks `in_tree`) from the grounds gives each body a "delta" transform D with
// world_now = D · world_at_CAD_pose. A joint reached from its follower side moves its base side
// by the inverse motion. Loop-closing joints are not walked: moving a joint of a loop opens it.

import { Matrix4, Vector3 } from 'three';

/** The movable coordinates of the model: revolute and prismatic elements of tree joints. */
export function coordinates(report) {
  const out = [];
  for (const j of report.joints) {
    j.elements.forEach((e, k) => {
      if (e.kind !== 'revolute' && e.kind !== 'prismatic') return;
      const a = new Vector3(...e.axis_world);
      if (a.lengthSq() < 0.5) return;
      out.push({
        key: `${j.modelica_name}#${k}`,
        joint: j.modelica_name,
        element: e.modelica_name || j.modelica_name,
        index: k,
        kind: e.kind,
        q0: e.initial_q,
        axis: e.axis_world,
        origin: e.origin_world,
        inTree: j.in_tree,
      });
    });
  }
  return out;
}

/** The relative motion of one joint (follower w.r.t. base, world coordinates at the CAD pose). */
export function jointMotion(joint, q) {
  const m = new Matrix4();
  joint.elements.forEach((e, k) => {
    const v = q.get(`${joint.modelica_name}#${k}`);
    if (v === undefined || (e.kind !== 'revolute' && e.kind !== 'prismatic')) return;
    const d = v - e.initial_q;
    if (d === 0) return;
    const a = new Vector3(...e.axis_world).normalize();
    const mk = new Matrix4();
    if (e.kind === 'prismatic') {
      mk.makeTranslation(a.x * d, a.y * d, a.z * d);
    } else {
      const [ox, oy, oz] = e.origin_world;
      mk.makeTranslation(ox, oy, oz)
        .multiply(new Matrix4().makeRotationAxis(a, d))
        .multiply(new Matrix4().makeTranslation(-ox, -oy, -oz));
    }
    m.multiply(mk);
  });
  return m;
}

/**
 * Delta transforms of every body (and ground) for joint values `q` (Map key → value, rad or m;
 * missing keys stay at the start value). Returns Map name → Matrix4.
 */
export function bodyDeltas(report, q) {
  const bodies = new Set(report.bodies.map((b) => b.modelica_name));
  const adj = new Map();
  const link = (n, entry) => {
    if (!adj.has(n)) adj.set(n, []);
    adj.get(n).push(entry);
  };
  const grounds = new Set();
  for (const j of report.joints) {
    for (const n of [j.base_body, j.follower_body]) if (!bodies.has(n)) grounds.add(n);
    if (!j.in_tree) continue;
    link(j.base_body, { joint: j, other: j.follower_body, fromBase: true });
    link(j.follower_body, { joint: j, other: j.base_body, fromBase: false });
  }
  const delta = new Map();
  const walk = (roots) => {
    const queue = [];
    for (const r of roots) {
      if (delta.has(r)) continue;
      delta.set(r, new Matrix4());
      queue.push(r);
    }
    while (queue.length) {
      const u = queue.shift();
      for (const { joint, other, fromBase } of adj.get(u) || []) {
        if (delta.has(other)) continue;
        const m = jointMotion(joint, q);
        if (!fromBase) m.invert();
        delta.set(other, delta.get(u).clone().multiply(m));
        queue.push(other);
      }
    }
  };
  walk([...grounds]);
  for (const b of bodies) walk([b]); // free bodies and anything not reached from a ground
  return delta;
}

/** The CAD-pose world matrix of a report frame (position, x axis, y axis). */
export function frameMatrix(f) {
  const x = new Vector3(...f.x_axis_world).normalize();
  const y = new Vector3(...f.y_axis_world).normalize();
  const z = new Vector3().crossVectors(x, y).normalize();
  const m = new Matrix4().makeBasis(x, y, z);
  m.setPosition(...f.position_world);
  return m;
}
