import test from 'node:test';
import assert from 'node:assert/strict';
import { parseShapePoses, shapesAt, shapeAxes, shapeMatrix, shortName, streamBounds, fileLabel } from './shapes-data.js';

/** A stream as the service writes it: steps [{t, shapes: [[12]], frames: [[7]]}]. */
function stream(steps, S, F) {
  const floats = [];
  for (const s of steps) floats.push(s.t, ...s.shapes.flat(), ...s.frames.flat());
  const buf = new ArrayBuffer(20 + 4 * floats.length);
  const v = new DataView(buf);
  'C2MS'.split('').forEach((c, i) => v.setUint8(i, c.charCodeAt(0)));
  [1, S, F, steps.length].forEach((x, i) => v.setUint32(4 + 4 * i, x, true));
  floats.forEach((x, i) => v.setFloat32(20 + 4 * i, x, true));
  return buf;
}

const box = (x) => [x, 0, 0, 1, 0, 0, 0, 1, 0, 0.4, 0.2, 0.1];
const q90z = [0, 0, Math.SQRT1_2, Math.SQRT1_2];

test('parses and interpolates shapes and frames', () => {
  const buf = stream(
    [
      { t: 0, shapes: [box(0)], frames: [[0, 0, 0, 0, 0, 0, 1]] },
      { t: 1, shapes: [box(1)], frames: [[2, 0, 0, ...q90z]] },
    ],
    1,
    1,
  );
  const s = parseShapePoses(buf);
  assert.equal(s.shapes, 1);
  assert.equal(s.frames, 1);
  assert.equal(s.stride, 19);
  assert.deepEqual([...s.times], [0, 1]);
  const at = shapesAt(s, 0.25);
  assert.ok(Math.abs(at[0] - 0.25) < 1e-7);
  assert.ok(Math.abs(at[12] - 0.5) < 1e-7);
  // Half of 90° about z at a quarter: 22.5°.
  assert.ok(Math.abs(at[17] - Math.sin(Math.PI / 16)) < 1e-6, `${at[17]}`);
  assert.ok(Math.abs(at[18] - Math.cos(Math.PI / 16)) < 1e-6);
  // Clamped at the ends.
  assert.ok(Math.abs(shapesAt(s, 5)[0] - 1) < 1e-7);
});

test('refuses a wrong or truncated stream', () => {
  assert.throws(() => parseShapePoses(new ArrayBuffer(8)), /shorter/);
  const buf = stream([{ t: 0, shapes: [box(0)], frames: [] }], 1, 0);
  assert.throws(() => parseShapePoses(buf.slice(0, buf.byteLength - 4)), /truncated/);
  new DataView(buf).setUint8(3, 80);
  assert.throws(() => parseShapePoses(buf), /C2MP/);
});

test('shape axes: ry made perpendicular, degenerate inputs fall back', () => {
  const { ex, ey, ez } = shapeAxes([2, 0, 0], [1, 1, 0]);
  assert.deepEqual(ex, [1, 0, 0]);
  assert.deepEqual(ey, [0, 1, 0]);
  assert.deepEqual(ez, [0, 0, 1]);
  const d = shapeAxes([0, 0, 0], [0, 0, 0]);
  assert.deepEqual(d.ex, [1, 0, 0]);
  assert.equal(Math.abs(d.ey[0]) < 1e-12, true);
  const z = shapeAxes([0, 0, 3], [0, 0, 1]);
  assert.deepEqual(z.ex, [0, 0, 1]);
  assert.ok(Math.abs(z.ex[0] * z.ey[0] + z.ex[1] * z.ey[1] + z.ex[2] * z.ey[2]) < 1e-12);
});

test('shape matrix scales the unit primitive per kind', () => {
  // Along y, width axis along -x: length 2, width 0.5, height 0.3, at (1, 2, 3).
  const v = [1, 2, 3, 0, 1, 0, -1, 0, 0, 2, 0.5, 0.3];
  const m = shapeMatrix('box', v);
  const apply = (p) => [0, 1, 2].map((i) => m[i] * p[0] + m[4 + i] * p[1] + m[8 + i] * p[2] + m[12 + i]);
  assert.deepEqual(apply([1, 0, 0]), [1, 4, 3]); // the far end, length along y
  assert.deepEqual(apply([0, 0.5, 0]), [0.75, 2, 3]); // half the width along -x
  assert.deepEqual(apply([0, 0, 0.5]), [1, 2, 3.15]); // ez = ex × ey = y × -x = z
  const c = shapeMatrix('cylinder', v);
  assert.equal(c[10], 0.5); // diameter = width, height ignored
  const s = shapeMatrix('sphere', v);
  assert.equal(s[1], 2);
  assert.equal(s[10], 2);
  // A user's file with extra = 0: placed and turned, its coordinates not scaled.
  const f = shapeMatrix('file-raw', v);
  const applyF = (p) => [0, 1, 2].map((i) => f[i] * p[0] + f[4 + i] * p[1] + f[8 + i] * p[2] + f[12 + i]);
  assert.deepEqual(applyF([1, 0, 0]), [1, 3, 3]);
  assert.deepEqual(applyF([0, 0, 1]), [1, 2, 4]);
  assert.deepEqual(shapeMatrix('file', v), m, 'extra ≠ 0: scaled like a box');
});

test('short names', () => {
  assert.equal(shortName('robot.mechanics.b1.shape'), 'b1.shape');
  assert.equal(shortName('shape'), 'shape');
});

test('stream bounds cover the whole motion', () => {
  const steps = [0, 1, 2].map((t) => ({ t, shapes: [box(t)], frames: [[-1, 0, t, 0, 0, 0, 1]] }));
  const b = streamBounds(parseShapePoses(stream(steps, 1, 1)));
  // The box runs from x = 0 to 2 + 0.4, padded by half its largest cross size (0.1).
  assert.deepEqual(b.min.map((x) => Math.round(x * 1e6) / 1e6), [-1, -0.1, -0.1]);
  assert.deepEqual(b.max.map((x) => Math.round(x * 1e6) / 1e6), [2.5, 0.1, 2]);
  assert.equal(streamBounds(parseShapePoses(stream([{ t: 0, shapes: [], frames: [] }], 0, 0))), null);
});

test('file shape labels', () => {
  assert.equal(fileLabel('modelica://Modelica/Resources/Data/Shapes/RobotR3/b0.dxf"]'), 'b0.dxf');
  assert.equal(fileLabel('C:\\shapes\\a.stl'), 'a.stl');
  assert.equal(fileLabel('"part.stl"'), 'part.stl');
});

test('chosen files draw the file shapes that name them, by name without extension and case', async () => {
  const { matchShapeFiles } = await import('./shapes-data.js');
  const shapes = [
    { kind: 'file', file: 'modelica://Modelica/Resources/Data/Shapes/RobotR3/b0.dxf' },
    { kind: 'box' },
    { kind: 'file', file: 'modelica://Modelica/Resources/Data/Shapes/RobotR3/b1.dxf' },
    { kind: 'file', file: 'modelica://Modelica/Resources/Data/Shapes/RobotR3/b0.dxf' },
    { kind: 'file', file: 'modelica://Modelica/Resources/Data/Shapes/RobotR3/b2.dxf' },
  ];
  const m = matchShapeFiles(shapes, ['B0.STL', 'b2.dxf', 'notes.dxf']);
  assert.deepEqual([...m.used], [['B0.STL', [0, 3]], ['b2.dxf', [4]]]);
  assert.deepEqual(m.unused, ['notes.dxf']);
  assert.deepEqual(m.missing, ['b1.dxf']);
  assert.deepEqual(matchShapeFiles(shapes, []).missing, ['b0.dxf', 'b1.dxf', 'b2.dxf']);
});
