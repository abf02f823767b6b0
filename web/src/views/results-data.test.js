import test from 'node:test';
import assert from 'node:assert/strict';
import { parsePoses, bracket, posesAt, slerp, valueAt, signalsCsv, csvName } from './results-data.js';

/** A pose stream as the contract lays it out. */
function stream(steps, b) {
  const buf = new ArrayBuffer(16 + steps.length * (1 + 7 * b) * 4);
  const v = new DataView(buf);
  [0x43, 0x32, 0x4d, 0x50].forEach((c, i) => v.setUint8(i, c));
  v.setUint32(4, 1, true);
  v.setUint32(8, b, true);
  v.setUint32(12, steps.length, true);
  let at = 16;
  for (const [t, ...vals] of steps) {
    v.setFloat32(at, t, true);
    at += 4;
    for (const x of vals) {
      v.setFloat32(at, x, true);
      at += 4;
    }
  }
  return buf;
}

const c = Math.cos(Math.PI / 4);
// One body: at t=0 at the origin, unrotated; at t=1 at (2, 0, 0) turned 90° about z.
const two = stream(
  [
    [0, 0, 0, 0, 0, 0, 0, 1],
    [1, 2, 0, 0, 0, 0, c, c],
  ],
  1,
);

test('parsePoses reads the header and steps, and refuses what is not a pose stream', () => {
  const s = parsePoses(two, ['B1']);
  assert.deepEqual([...s.times], [0, 1]);
  assert.equal(s.poses.length, 14);
  assert.ok(Math.abs(s.poses[7 + 6] - c) < 1e-7);
  assert.throws(() => parsePoses(new ArrayBuffer(8)), /shorter than its header/);
  assert.throws(() => parsePoses(two.slice(0, 40)), /truncated/);
  assert.throws(() => parsePoses(two, ['B1', 'B2']), /2/);
  const bad = two.slice(0);
  new DataView(bad).setUint8(0, 0x58);
  assert.throws(() => parsePoses(bad), /not "C2MP"/);
});

test('bracket finds the step, clamps, and takes the later of repeated instants', () => {
  const t = [0, 1, 1, 2];
  assert.deepEqual(bracket(t, -1), { i: 0, a: 0 });
  assert.deepEqual(bracket(t, 0.25), { i: 0, a: 0.25 });
  assert.deepEqual(bracket(t, 1), { i: 2, a: 0 });
  assert.deepEqual(bracket(t, 1.5), { i: 2, a: 0.5 });
  assert.deepEqual(bracket(t, 5), { i: 3, a: 0 });
  assert.deepEqual(bracket([], 5), { i: -1, a: 0 });
});

test('posesAt lerps positions and slerps rotations', () => {
  const s = parsePoses(two, ['B1']);
  const half = posesAt(s, 0.5);
  assert.ok(Math.abs(half[0] - 1) < 1e-6);
  // Halfway: 45° about z.
  const q45 = [0, 0, Math.sin(Math.PI / 8), Math.cos(Math.PI / 8)];
  for (let k = 0; k < 4; k++) assert.ok(Math.abs(half[3 + k] - q45[k]) < 1e-6, `${half}`);
  const end = posesAt(s, 7);
  assert.ok(Math.abs(end[0] - 2) < 1e-6 && Math.abs(end[6] - c) < 1e-6);
});

test('slerp goes the short way and normalises', () => {
  const out = slerp([0, 0, 0, 1], 0, [0, 0, -c, -c], 0, 0.5, [0, 0, 0, 0]);
  // -q is the same rotation: the halfway point is 45° about +z, not 135° about -z.
  assert.ok(Math.abs(out[2] - Math.sin(Math.PI / 8)) < 1e-9 && Math.abs(out[3] - Math.cos(Math.PI / 8)) < 1e-9, `${out}`);
  const n = slerp([0, 0, 0, 2], 0, [0, 0, 0, 2], 0, 0.3, [0, 0, 0, 0]);
  assert.deepEqual(n, [0, 0, 0, 1]);
});

test('valueAt interpolates, and is null outside the data', () => {
  const s = { t: [0, 1, 2], y: [0, 10, 0] };
  assert.equal(valueAt(s, 0.5), 5);
  assert.equal(valueAt(s, 1), 10);
  assert.equal(valueAt(s, 2), 0);
  assert.equal(valueAt(s, 3), null);
  assert.equal(valueAt({ t: [], y: [] }, 0), null);
});

test('signalsCsv: one time column when shared, merged instants otherwise; names quoted', () => {
  const a = { name: 'J.phi', unit: 'rad', t: [0, 1], y: [0.5, 1.5] };
  const b = { name: 'B.frame_a.R.T[1,1]', unit: '1', t: [0, 1], y: [1, -1] };
  assert.equal(signalsCsv([a, b]), 'time [s],J.phi [rad],"B.frame_a.R.T[1,1]"\n0,0.5,1\n1,1.5,-1\n');
  const c2 = { name: 'x', unit: 'm', t: [0.5, 1], y: [7, 8] };
  assert.equal(signalsCsv([a, c2]), 'time [s],J.phi [rad],x [m]\n0,0.5,\n0.5,,7\n1,1.5,8\n');
  assert.equal(signalsCsv([]), 'time [s]\n');
  assert.equal(csvName('full Robot.MAT'), 'full_Robot-signals.csv');
});

test('missingJoints names the tree coordinates a result lacks', async () => {
  const { missingJoints } = await import('./results-data.js');
  const report = {
    joints: [
      { modelica_name: 'J1', in_tree: true, elements: [{ kind: 'revolute', modelica_name: 'J1' }] },
      { modelica_name: 'J2', in_tree: true, elements: [{ kind: 'prismatic', modelica_name: 'J2' }] },
      { modelica_name: 'W', in_tree: true, elements: [{ kind: 'weld', modelica_name: 'W' }] },
      { modelica_name: 'C', in_tree: false, elements: [{ kind: 'revolute', modelica_name: 'C' }] },
    ],
  };
  assert.deepEqual(missingJoints(report, ['J1']), ['J2']);
  assert.deepEqual(missingJoints(report, ['J1', 'J2']), []);
  assert.deepEqual(missingJoints(report, undefined), ['J1', 'J2']);
});
