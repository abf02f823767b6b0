import test from 'node:test';
import assert from 'node:assert/strict';
import { parseObj } from './obj.js';

test('OBJ: vertices, triangles, polygons fanned, slashes and negative indices', () => {
  const o = parseObj('# shape\no part\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1/1 3/3 4/4\nf -4 -3 -2 -1\n');
  assert.deepEqual(o.positions, [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0]);
  assert.deepEqual(o.indices, [0, 1, 2, 0, 2, 3, 0, 1, 2, 0, 2, 3]);
  assert.throws(() => parseObj('v 0 0\n'), /bad vertex/);
  assert.throws(() => parseObj('v 0 0 0\nf 1 2 3\n'), /bad face/);
});
