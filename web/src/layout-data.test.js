import test from 'node:test';
import assert from 'node:assert/strict';
import { clamp, sizeLimits, loadSize, saveSize, abbreviate, filterRows } from './layout-data.js';

test('panel sizes are clamped to what the window leaves the 3D view', () => {
  assert.equal(clamp(5, 0, 3), 3);
  assert.equal(clamp(-1, 0, 3), 0);
  const l = sizeLimits(1440, 900);
  assert.deepEqual(l.side, { min: 280, max: 1080 });
  assert.deepEqual(l.dock, { min: 96, max: 640 });
  // A window too small for both: the minimum wins.
  assert.equal(sizeLimits(500, 300).side.max, 280);
});

test('sizes persist, and a bad or out-of-range stored size falls back or is clamped', () => {
  const store = new Map();
  const storage = { getItem: (k) => store.get(k) ?? null, setItem: (k, v) => store.set(k, v) };
  assert.equal(loadSize(storage, 'side', 560, 280, 1000), 560);
  saveSize(storage, 'side', 612.4);
  assert.equal(store.get('side'), '612');
  assert.equal(loadSize(storage, 'side', 560, 280, 1000), 612);
  assert.equal(loadSize(storage, 'side', 560, 280, 500), 500);
  store.set('side', 'wide');
  assert.equal(loadSize(storage, 'side', 560, 280, 1000), 560);
  const refusing = { getItem: () => { throw new Error('denied'); }, setItem: () => { throw new Error('denied'); } };
  assert.equal(loadSize(refusing, 'side', 400, 280, 1000), 400);
  assert.doesNotThrow(() => saveSize(refusing, 'side', 1));
});

test('long CAD names are cut in the middle, keeping both ends', () => {
  const n = 'SIM_L_HAND_MK3_THUMB_PROXIMAL_TO_THUMB_DISTAL_JOINT';
  const a = abbreviate(n, 24);
  assert.ok(a.length <= 24, a);
  assert.ok(a.includes('…'));
  assert.ok(n.startsWith(a.split('…')[0]), a);
  assert.ok(n.endsWith(a.split('…')[1]), a);
  assert.equal(a.split('…')[1], 'DISTAL_JOINT'.slice(-a.split('…')[1].length));
  // The head ends at a separator when one is near: whole words, not "SIM_L_HAND_M…".
  assert.ok(abbreviate(n, 26).startsWith('SIM_L_HAND_…'), abbreviate(n, 26));
  // ... and the tail starts at a word.
  assert.equal(abbreviate('SIM_L_HAND_PALM_NAKED_SIM_L_HAND_PROX_LITTLE_FINGER', 28), 'SIM_L_HAND_…LITTLE_FINGER');
  assert.equal(abbreviate('J1', 24), 'J1');
  assert.equal(abbreviate(n, n.length), n);
  // Two names that differ only at the end stay different.
  assert.notEqual(abbreviate(`${n}_1`, 20), abbreviate(`${n}_2`, 20));
});

test('the joint filter matches every word anywhere in the name', () => {
  const rows = ['thumb_proximal', 'thumb_distal', 'index_distal'];
  assert.deepEqual(filterRows(rows, ''), rows);
  assert.deepEqual(filterRows(rows, 'DISTAL'), ['thumb_distal', 'index_distal']);
  assert.deepEqual(filterRows(rows, 'distal thumb'), ['thumb_distal']);
  assert.deepEqual(filterRows([{ name: 'a_b' }], 'b', (r) => r.name), [{ name: 'a_b' }]);
});

test('abbreviations of a set of names are all different', async () => {
  const { abbreviateAll } = await import('./layout-data.js');
  const names = ['SIM_L_HAND_PALM_NAKED_SIM_L_HAND_PROX_LITTLE_FINGER', 'SIM_L_HAND_PROX_LITTLE_FINGER_SIM_L_HAND_DIST_LITTLE_FINGER', 'SIM_L_HAND_PALM_NAKED_SIM_L_HAND_METACARPUS_INDEX', 'J1', 'J1'];
  const shown = abbreviateAll(names, 28);
  const texts = [...new Set(names)].map((n) => shown.get(n));
  assert.equal(new Set(texts).size, texts.length, JSON.stringify(texts));
  for (const n of names) assert.ok(shown.get(n).length <= Math.max(28, n.length));
  assert.equal(shown.get('J1'), 'J1');
  // Without a clash, the plain abbreviation.
  assert.equal(shown.get(names[2]), 'SIM_L_HAND_…METACARPUS_INDEX');
});
