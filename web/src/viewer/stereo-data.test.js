import test from 'node:test';
import assert from 'node:assert/strict';
import { PerspectiveCamera, Vector3 } from 'three';
import { eyeSeparation, eyeCamera } from './stereo-data.js';

/** A camera 2 m from the target (0, 0, 0.3) looking at it from an oblique direction, z up. */
function camera() {
  const c = new PerspectiveCamera(40, 1.6, 0.001, 100);
  c.up.set(0, 0, 1);
  c.position.set(1.2, -1.4, 1.1);
  c.lookAt(0, 0, 0.3);
  c.updateMatrixWorld();
  c.updateProjectionMatrix();
  return c;
}

test('the eyes are a thirtieth of the viewing distance apart', () => {
  assert.equal(eyeSeparation(3), 0.1);
  assert.equal(eyeSeparation(0.03), 0.001);
  assert.equal(eyeSeparation(0), 0);
  assert.equal(eyeSeparation(-1), 0);
});

test('each eye sits half the separation to its side of the camera, along its right', () => {
  const c = camera();
  const target = new Vector3(0, 0, 0.3);
  const d = c.position.distanceTo(target);
  const rig = {};
  const left = eyeCamera(rig, c, d, 'left', 1.6).getWorldPosition(new Vector3());
  const right = eyeCamera(rig, c, d, 'right', 1.6).getWorldPosition(new Vector3());
  const rightAxis = new Vector3().setFromMatrixColumn(c.matrixWorld, 0);
  assert.ok(Math.abs(left.distanceTo(right) - d / 30) < 1e-12, `${left.distanceTo(right)} apart`);
  assert.ok(left.clone().add(right).multiplyScalar(0.5).distanceTo(c.position) < 1e-12, 'symmetric about the camera');
  assert.ok(Math.abs(right.clone().sub(left).normalize().dot(rightAxis) - 1) < 1e-12, 'the right eye is on the right');
});

test('the eyes converge at the target (no parallax there), nearer points stand out', () => {
  const c = camera();
  const target = new Vector3(0, 0, 0.3);
  const d = c.position.distanceTo(target);
  const rig = {};
  const ndc = (side, p) => p.clone().project(eyeCamera(rig, c, d, side, 1.6));
  const l = ndc('left', target);
  const r = ndc('right', target);
  assert.ok(Math.abs(l.x - r.x) < 1e-9 && Math.abs(l.y - r.y) < 1e-9, `the target is at the same place in both eyes: ${l.x} / ${r.x}`);
  // A point halfway to the camera: crossed parallax (left eye sees it further right).
  const near = target.clone().lerp(c.position, 0.5);
  assert.ok(ndc('left', near).x > ndc('right', near).x + 1e-3, 'a nearer point stands out of the screen');
  // The same eyes whatever the viewport's aspect (the dual output's second window may differ).
  const wide = eyeCamera(rig, c, d, 'right', 2.5).getWorldPosition(new Vector3());
  assert.ok(wide.distanceTo(eyeCamera(rig, c, d, 'right', 1.6).getWorldPosition(new Vector3())) < 1e-12);
});
