// Unit tests of the browser's forward kinematics (node --test, run by tests/ui.rs).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { Vector3 } from 'three';
import { bodyDeltas, coordinates, frameMatrix } from './kinematics.js';

const frame = (p, x = [1, 0, 0], y = [0, 1, 0]) => ({ position_world: p, x_axis_world: x, y_axis_world: y });
const body = (name, cs1) => ({ modelica_name: name, cs1 });
const joint = (name, base, follower, elements, inTree = true) => ({ modelica_name: name, base_body: base, follower_body: follower, elements, in_tree: inTree });
const rev = (axis, origin, q0 = 0) => ({ kind: 'revolute', axis_world: axis, origin_world: origin, initial_q: q0 });
const pri = (axis, origin, q0 = 0) => ({ kind: 'prismatic', axis_world: axis, origin_world: origin, initial_q: q0 });

// A double pendulum in the x-y plane: ground —(z at origin)— A —(z at (1,0,0))— B, bodies at rest along +x.
const report = {
  bodies: [body('A', frame([0, 0, 0])), body('B', frame([1, 0, 0]))],
  joints: [joint('j1', 'World', 'A', [rev([0, 0, 1], [0, 0, 0], 0.1)]), joint('j2', 'A', 'B', [rev([0, 0, 1], [1, 0, 0])])],
};

const near = (a, b, tol = 1e-12) => assert.ok(a.distanceTo(b) < tol, `${a.toArray()} != ${b.toArray()}`);

test('start values reproduce the CAD pose', () => {
  const d = bodyDeltas(report, new Map([['j1#0', 0.1]]));
  near(new Vector3(2, 0, 0).applyMatrix4(d.get('B')), new Vector3(2, 0, 0));
});

test('a revolute joint turns its whole follower side about its axis through its origin', () => {
  const d = bodyDeltas(report, new Map([['j1#0', 0.1 + Math.PI / 2]]));
  near(new Vector3(1, 0, 0).applyMatrix4(d.get('A')), new Vector3(0, 1, 0));
  near(new Vector3(2, 0, 0).applyMatrix4(d.get('B')), new Vector3(0, 2, 0));
});

test('joints compose along the chain', () => {
  const d = bodyDeltas(report, new Map([['j1#0', 0.1 + Math.PI / 2], ['j2#0', Math.PI / 2]]));
  // B's tip at (2,0,0): j2 turns it to (1,1,0), then j1 to (-1,1,0).
  near(new Vector3(2, 0, 0).applyMatrix4(d.get('B')), new Vector3(-1, 1, 0));
});

test('a joint walked from its follower side moves the base side the other way', () => {
  const flipped = { bodies: report.bodies, joints: [joint('j1', 'A', 'World', [rev([0, 0, 1], [0, 0, 0])])] };
  const d = bodyDeltas(flipped, new Map([['j1#0', Math.PI / 2]]));
  near(new Vector3(1, 0, 0).applyMatrix4(d.get('A')), new Vector3(0, -1, 0));
});

test('prismatic elements translate along their axis; elements of one joint compose in order', () => {
  const r = { bodies: [body('C', frame([0, 0, 0]))], joints: [joint('j', 'World', 'C', [pri([1, 0, 0], [0, 0, 0], 0.5), rev([0, 0, 1], [0.5, 0, 0])])] };
  const d = bodyDeltas(r, new Map([['j#0', 1.5], ['j#1', Math.PI]]));
  // The revolute (second) acts in the frame already moved by the slider: (1.5,0,0) → turn π about (0.5,0,0) → (-0.5,0,0) → +1 → (0.5,0,0).
  near(new Vector3(1.5, 0, 0).applyMatrix4(d.get('C')), new Vector3(0.5, 0, 0));
});

test('loop-closing joints are not walked and are not coordinates of the tree', () => {
  const r = { bodies: report.bodies, joints: [...report.joints, joint('cut', 'World', 'B', [rev([0, 0, 1], [2, 0, 0])], false)] };
  const c = coordinates(r);
  assert.deepEqual(c.map((x) => [x.key, x.inTree]), [['j1#0', true], ['j2#0', true], ['cut#0', false]]);
  const d = bodyDeltas(r, new Map([['cut#0', 1]]));
  near(new Vector3(2, 0, 0).applyMatrix4(d.get('B')), new Vector3(2, 0, 0));
});

test('frame matrices are right-handed from x and y', () => {
  const m = frameMatrix(frame([1, 2, 3], [0, 1, 0], [-1, 0, 0]));
  near(new Vector3(0, 0, 1).applyMatrix4(m), new Vector3(1, 2, 4));
  near(new Vector3(1, 0, 0).applyMatrix4(m), new Vector3(1, 3, 3));
});
