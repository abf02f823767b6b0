import test from 'node:test';
import assert from 'node:assert/strict';
import { newObject, freshName, rotationFromAngles, anglesFromRotation, withPose, errorsByObject, describe } from './scene-data.js';

test('new objects get free names and default shapes', () => {
  assert.equal(freshName('box', ['box1', 'box2', 'arm']), 'box3');
  const o = newObject('cylinder', []);
  assert.deepEqual(o.shape, { kind: 'cylinder', radius: 0.1, length: 0.2 });
  assert.equal(o.name, 'cylinder1');
  assert.throws(() => newObject('cone', []));
});

test('rotations from typed angles are orthonormal and read back', () => {
  const angles = [30, -45, 120];
  const r = rotationFromAngles(angles);
  for (let i = 0; i < 3; i += 1) {
    for (let j = 0; j < 3; j += 1) {
      const dot = r[0][i] * r[0][j] + r[1][i] * r[1][j] + r[2][i] * r[2][j];
      assert.ok(Math.abs(dot - (i === j ? 1 : 0)) < 1e-12);
    }
  }
  // 90° about z turns x into y: the first column is (0, 1, 0).
  const z = rotationFromAngles([0, 0, 90]);
  assert.ok(Math.abs(z[1][0] - 1) < 1e-12 && Math.abs(z[0][1] + 1) < 1e-12);
  anglesFromRotation(r).forEach((a, k) => assert.ok(Math.abs(a - angles[k]) < 1e-9));
});

test('typed poses are checked and errors are named', () => {
  const o = newObject('box', []);
  assert.deepEqual(withPose(o, ['1', '2', '3'], ['0', '0', '0']).object.position, [1, 2, 3]);
  assert.match(withPose(o, ['1', '', '3'], ['0', '0', '0']).error, /^position/);
  assert.match(withPose(o, ['1', '2', '3'], ['x', '0', '0']).error, /^rotation/);
  const byObj = errorsByObject([{ field: 'objects[1].shape.size', message: 'bad' }, { field: 'scene', message: 'not JSON' }]);
  assert.deepEqual(byObj.get(1), ['shape.size: bad']);
  assert.deepEqual(byObj.get(-1), ['scene: not JSON']);
  assert.equal(describe({ ...o, kind: 'free' }), 'box (0.2 × 0.2 × 0.2 m), free');
});
