import test from 'node:test';
import assert from 'node:assert/strict';
import { parseDxfFaces } from './dxf.js';

/** A DXF as AutoCAD R12 writes it: codes right-aligned, one value a line. */
const dxf = (entities, eol = '\n') =>
  ['  0', 'SECTION', '  2', 'HEADER', '  9', '$ACADVER', '  1', 'AC1009', '  0', 'ENDSEC', '  0', 'SECTION', '  2', 'ENTITIES', ...entities, '  0', 'ENDSEC', '  0', 'EOF', ''].join(eol);
const face = (c, extra = []) => ['  0', '3DFACE', '  8', 'b0', ...extra, ...c.flatMap((p, k) => [` 1${k}`, String(p[0]), ` 2${k}`, String(p[1]), ` 3${k}`, String(p[2])])];

test('3DFACEs: a triangle (fourth corner repeated) and a quad (two triangles)', () => {
  const tri = face([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 1, 0]]);
  const quad = face([[0, 0, 1], [2, 0, 1], [2, 3, 1], [0, 3, 1]], [' 62', '5']);
  const { positions, faces } = parseDxfFaces(dxf([...tri, '  0', 'LINE', ' 10', '9', ' 20', '9', ' 30', '9', ...quad], '\r\n'), 'b0.dxf');
  assert.equal(faces, 2);
  assert.deepEqual([...positions], [0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 2, 0, 1, 2, 3, 1, 0, 0, 1, 2, 3, 1, 0, 3, 1]);
});

test('a face without a corner, a bad number, no faces and garbage are refused by name', () => {
  assert.throws(() => parseDxfFaces(dxf(face([[0, 0, 0], [1, 0, 0]])), 'b1.dxf'), /b1\.dxf: 3DFACE at line \d+ lacks corner 3/);
  assert.throws(() => parseDxfFaces(dxf(['  0', '3DFACE', ' 10', 'one']), 'b2.dxf'), /b2\.dxf: line \d+: "one" is not a number \(group 10/);
  assert.throws(() => parseDxfFaces(dxf(['  0', 'LINE', ' 10', '0']), 'b3.dxf'), /b3\.dxf has no 3DFACE entities/);
  assert.throws(() => parseDxfFaces('solid x\nfacet normal 0 0 1\n', 'b4.dxf'), /b4\.dxf: line 1 is not a group code/);
  assert.throws(() => parseDxfFaces('', 'b5.dxf'), /b5\.dxf is empty/);
});
