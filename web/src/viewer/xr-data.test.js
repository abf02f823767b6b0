import test from 'node:test';
import assert from 'node:assert/strict';
import { immersiveSupport, quaternionBetween, rotate, xrPlacement } from './xr-data.js';

test('the Enter VR button is enabled only when the browser says immersive VR works', async () => {
  const asked = [];
  const nav = (answer) => ({ xr: { isSessionSupported: async (mode) => (asked.push(mode), answer) } });
  assert.deepEqual(await immersiveSupport(nav(true), true), { supported: true, reason: '' });
  assert.deepEqual(asked, ['immersive-vr'], 'it asks for an immersive VR session');
  const no = await immersiveSupport(nav(false), true);
  assert.equal(no.supported, false);
  assert.match(no.reason, /no immersive VR device/);
  // Anything but true (a browser answering undefined) is no.
  assert.equal((await immersiveSupport(nav(undefined), true)).supported, false);
});

test('without WebXR, on an insecure page, on a refusal or no answer: disabled with the reason', async () => {
  const none = await immersiveSupport({}, true);
  assert.equal(none.supported, false);
  assert.match(none.reason, /no WebXR \(navigator\.xr\)/);
  assert.match((await immersiveSupport(undefined, true)).reason, /no WebXR/);
  assert.match((await immersiveSupport({ xr: {} }, true)).reason, /no WebXR/);
  // An insecure page is the reason even where a browser would have WebXR.
  const insecure = await immersiveSupport({ xr: { isSessionSupported: async () => true } }, false);
  assert.deepEqual([insecure.supported, /secure page/.test(insecure.reason)], [false, true]);
  const refused = await immersiveSupport({ xr: { isSessionSupported: async () => { throw new Error('blocked by permissions policy'); } } }, true);
  assert.equal(refused.supported, false);
  assert.match(refused.reason, /blocked by permissions policy/);
  const thrown = await immersiveSupport({ xr: { isSessionSupported: () => { throw new Error('sync'); } } }, true);
  assert.match(thrown.reason, /sync/);
  const silent = await immersiveSupport({ xr: { isSessionSupported: () => new Promise(() => {}) } }, true, 20);
  assert.equal(silent.supported, false);
  assert.match(silent.reason, /did not say within/);
});

const close = (a, b, eps = 1e-12) => a.every((x, i) => Math.abs(x - b[i]) < eps);

test('quaternions turn one direction onto another, opposite ones too', () => {
  for (const [a, b] of [[[0, 0, 1], [0, 1, 0]], [[1, 0, 0], [0, 1, 0]], [[0, 1, 0], [0, 1, 0]], [[0, -1, 0], [0, 1, 0]], [[0.6, 0, -0.8], [0, 1, 0]]]) {
    const q = quaternionBetween(a, b);
    assert.ok(Math.abs(Math.hypot(...q) - 1) < 1e-12, 'a unit quaternion');
    assert.ok(close(rotate(q, a), b), `${a} → ${rotate(q, a)}, wanted ${b}`);
  }
});

test('in VR the model stands upright on the floor in front of the user, at its true size', () => {
  // A z-up model (gravity -z), 0.2 × 0.4 × 1 m, standing from z = 0.5 to 1.5.
  const box = { min: [-0.1, 1.8, 0.5], max: [0.1, 2.2, 1.5] };
  const { quaternion, position } = xrPlacement([0, 0, 1], box, 1.0);
  const place = (p) => rotate(quaternion, p).map((x, i) => x + position[i]);
  const corners = [];
  for (const x of [box.min[0], box.max[0]]) for (const y of [box.min[1], box.max[1]]) for (const z of [box.min[2], box.max[2]]) corners.push(place([x, y, z]));
  const ys = corners.map((c) => c[1]);
  assert.ok(Math.abs(Math.min(...ys)) < 1e-12, 'its lowest point on the floor');
  assert.ok(Math.abs(Math.max(...ys) - 1) < 1e-12, 'upright: its 1 m height along +y, unscaled');
  const xs = corners.map((c) => c[0]);
  assert.ok(Math.abs(Math.min(...xs) + Math.max(...xs)) < 1e-12, 'centred left to right');
  const zs = corners.map((c) => c[2]);
  assert.ok(Math.max(...zs) < -0.9, `in front of the user (−z), clear of them: ${Math.max(...zs)}`);
  // A y-up model keeps its orientation.
  assert.ok(close(xrPlacement([0, 1, 0], box).quaternion, [0, 0, 0, 1]));
});
