import test from 'node:test';
import assert from 'node:assert/strict';
import {
  mm,
  pairKey,
  shapeRows,
  matrixRows,
  pairEdit,
  resetAllEdit,
  witnessLine,
  interferenceText,
  sweepRows,
  firstContactText,
  contactMarkers,
  touchedBy,
} from './collision-data.js';

const matrix = {
  bodies: ['BASE', 'LINK_UPPER', 'LINK_FORE'],
  pairs: [
    { a: 'BASE', b: 'LINK_UPPER', allowed: true, default: true, custom: false, why: 'joined by BASE_LINK' },
    { a: 'BASE', b: 'LINK_FORE', allowed: false, default: false, custom: false, why: 'not joined: checked' },
    { a: 'LINK_UPPER', b: 'LINK_FORE', allowed: false, default: true, custom: true, why: 'set by the user' },
  ],
  orphans: [{ a: 'GONE', b: 'BASE', allowed: true, default: false, custom: true, why: 'a body is not in this version' }],
};

test('mm rounds metres to micrometre-precise millimetres', () => {
  assert.equal(mm(0.013428201845614746), 13.428);
  assert.equal(mm(-0.0012777703553188593), -1.278);
  assert.equal(mm(0), 0);
  assert.equal(mm(NaN), null);
});

test('pairKey ignores the order', () => {
  assert.equal(pairKey('A', 'B'), pairKey('B', 'A'));
  assert.notEqual(pairKey('A', 'B'), pairKey('A', 'C'));
});

test('shapeRows: bodies with shapes first, values in display units', () => {
  const rows = shapeRows([
    { body: 'Root', kind: 'none', parts: 0, vertices: 0, fit_error: 0, volume_ratio: 0, source_triangles: 0, warnings: ['no mesh: the body has no collision shape'] },
    { body: 'BASE', kind: 'box', parts: 1, vertices: 8, fit_error: 0.0004, volume_ratio: 1.08349, source_triangles: 12, warnings: [] },
  ]);
  assert.deepEqual(rows.map((r) => r.body), ['BASE', 'Root']);
  assert.equal(rows[0].fitErrorMm, 0.4);
  assert.equal(rows[0].volumeRatio, 1.083);
  assert.equal(rows[1].fitErrorMm, null);
  assert.equal(rows[1].volumeRatio, null);
  assert.deepEqual(rows[1].warnings, ['no mesh: the body has no collision shape']);
  assert.deepEqual(shapeRows(undefined), []);
});

test('matrixRows: state says may touch or checked, default or custom', () => {
  const rows = matrixRows(matrix);
  assert.deepEqual(rows.map((r) => r.state), ['may touch (default)', 'checked (default)', 'checked (custom)']);
  assert.equal(rows[0].why, 'joined by BASE_LINK');
  assert.deepEqual(matrixRows(null), []);
});

test('pairEdit: a change away from the default is stored, back to the default resets', () => {
  assert.deepEqual(pairEdit(matrix, 'BASE', 'LINK_UPPER', false), { pairs: [{ a: 'BASE', b: 'LINK_UPPER', allowed: false }] });
  // Given in the other order: the service's order is kept.
  assert.deepEqual(pairEdit(matrix, 'LINK_UPPER', 'BASE', false), { pairs: [{ a: 'BASE', b: 'LINK_UPPER', allowed: false }] });
  assert.deepEqual(pairEdit(matrix, 'LINK_UPPER', 'LINK_FORE', true), { pairs: [{ a: 'LINK_UPPER', b: 'LINK_FORE', allowed: null }] });
  assert.deepEqual(pairEdit(matrix, 'BASE', 'LINK_FORE', true), { pairs: [{ a: 'BASE', b: 'LINK_FORE', allowed: true }] });
  assert.deepEqual(pairEdit(matrix, 'BASE', 'LINK_FORE', null), { pairs: [{ a: 'BASE', b: 'LINK_FORE', allowed: null }] });
});

test('resetAllEdit resets the custom pairs of this version only', () => {
  assert.deepEqual(resetAllEdit(matrix), { pairs: [{ a: 'LINK_UPPER', b: 'LINK_FORE', allowed: null }] });
  assert.deepEqual(resetAllEdit({ bodies: [], pairs: [] }), { pairs: [] });
});

test('witnessLine and interferenceText', () => {
  const i = { a: 'BASE', b: 'LINK_UPPER', depth: 0.013428201845614746, point_a: [0.006, 0.09, 0.002], point_b: [0.006, 0.07657179815438522, 0.002], normal: [0, 1, 0] };
  const l = witnessLine(i);
  assert.deepEqual(l.from, [0.006, 0.09, 0.002]);
  assert.deepEqual(l.to, [0.006, 0.07657179815438522, 0.002]);
  assert.ok(Math.abs(l.length - 0.013428201845614746) < 1e-12);
  assert.equal(interferenceText(i), 'BASE and LINK_UPPER intersect by 13.428 mm');
});

const sweep = {
  motion: 'swing',
  samples: 1201,
  rate_hz: 1000,
  guarantee: 'conservative',
  first_contact: { a: 'BASE', b: 'LINK_FORE', time: 0.511 },
  pairs: [
    { a: 'BASE', b: 'LINK_FORE', min_distance: -0.0037007486280692947, at: 0.537, first_contact: 0.511, max_depth: 0.0037007486280692947, point_a: [0, 0, 0], point_b: [0, 0, 0.001] },
    { a: 'BASE', b: 'TOOL', min_distance: 0.05, at: 0.2, first_contact: null, max_depth: 0, point_a: [0, 0, 0], point_b: [0, 0, 0.05] },
    { a: 'LINK_UPPER', b: 'TOOL', min_distance: -0.001, at: 1.5, first_contact: 1.4, max_depth: 0.001, point_a: [0, 0, 0], point_b: [0, 0, 0.05] },
  ],
};

test('sweepRows and firstContactText', () => {
  const rows = sweepRows(sweep);
  assert.deepEqual(rows.map((r) => [r.minDistanceMm, r.touches]), [[-3.701, true], [50, false], [-1, true]]);
  assert.equal(rows[0].maxDepthMm, 3.701);
  assert.equal(firstContactText(sweep), 'First contact: BASE and LINK_FORE at 0.511 s');
  assert.match(firstContactText({ first_contact: null, pairs: [{}] }), /^No contact: .*1 checked pairs/);
});

test('contactMarkers: one per touching pair, in time order, placed on the duration', () => {
  const m = contactMarkers(sweep, 2);
  assert.deepEqual(m.map((x) => [x.a, x.b, x.time, x.left]), [['BASE', 'LINK_FORE', 0.511, 25.55], ['LINK_UPPER', 'TOOL', 1.4, 70]]);
  assert.equal(contactMarkers(sweep, 1)[1].left, 100, 'clamped');
  assert.deepEqual(contactMarkers(null, 1), []);
});

test('touchedBy: pairs whose first contact is at or before t (half a sample of slack)', () => {
  assert.deepEqual(touchedBy(sweep, 0.5).map((p) => p.b), []);
  assert.deepEqual(touchedBy(sweep, 0.5106).map((p) => p.b), ['LINK_FORE']);
  assert.deepEqual(touchedBy(sweep, 2).map((p) => p.b), ['LINK_FORE', 'TOOL']);
});
