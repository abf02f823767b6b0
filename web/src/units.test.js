import test from 'node:test';
import assert from 'node:assert/strict';
import { toDisplay, fromDisplay, symbolOf, factorOf, normalizeUnits, parseNumber, plotUnit, getUnits, setUnits, onUnits } from './units.js';

test('angles and lengths in the chosen unit, both ways', () => {
  const deg = { angle: 'deg', length: 'mm' };
  const si = { angle: 'rad', length: 'm' };
  assert.equal(toDisplay(Math.PI / 2, 'rad', deg), 90);
  assert.equal(toDisplay(Math.PI / 2, 'rad', si), Math.PI / 2);
  assert.equal(toDisplay(0.0125, 'm', deg), 12.5);
  assert.equal(toDisplay(0.0125, 'prismatic', si), 0.0125);
  assert.equal(toDisplay(0.3, 'revolute', deg), Number((0.3 * 180 / Math.PI).toPrecision(12)));
  assert.equal(toDisplay(Math.PI / 6, 'rad', deg), 30);
  assert.equal(fromDisplay(90, 'rad', deg), Math.PI / 2);
  assert.equal(fromDisplay(12.5, 'm', deg), 0.0125);
  assert.equal(fromDisplay(0.5, 'rad', si), 0.5);
  // The CAD pose is exactly 0 in every unit.
  assert.equal(toDisplay(0, 'rad', deg), 0);
  assert.ok(Object.is(toDisplay(-0, 'm', deg), 0));
  assert.equal(symbolOf('rad', deg), '°');
  assert.equal(symbolOf('rad', si), 'rad');
  assert.equal(symbolOf('m', deg), 'mm');
  assert.equal(symbolOf('m', si), 'm');
  assert.equal(plotUnit('rad', '/s²', deg), '°/s²');
  assert.equal(factorOf('m', { length: 'm' }), 1);
});

test('unknown choices fall back to degrees and millimetres', () => {
  assert.deepEqual(normalizeUnits(null), { angle: 'deg', length: 'mm' });
  assert.deepEqual(normalizeUnits({ angle: 'grad', length: 'm' }), { angle: 'deg', length: 'm' });
  assert.deepEqual(normalizeUnits({ angle: 'toString' }), { angle: 'deg', length: 'mm' });
});

test('typed numbers: decimal comma, exponent, empty and garbage', () => {
  assert.equal(parseNumber(' 1,5 '), 1.5);
  assert.equal(parseNumber('-2e-3'), -0.002);
  assert.equal(parseNumber('.5'), 0.5);
  assert.equal(parseNumber(''), null);
  assert.ok(Number.isNaN(parseNumber('12 mm')));
  assert.ok(Number.isNaN(parseNumber('0x10')));
});

test('the choice is stored and announced', () => {
  const store = new Map();
  const storage = { getItem: (k) => store.get(k) ?? null, setItem: (k, v) => store.set(k, v) };
  const seen = [];
  const off = onUnits((u) => seen.push(u.angle));
  assert.deepEqual(getUnits(storage), { angle: 'deg', length: 'mm' });
  setUnits({ angle: 'rad' }, storage);
  assert.deepEqual(JSON.parse(store.get('cad2mo.units')), { angle: 'rad', length: 'mm' });
  assert.deepEqual(seen, ['rad']);
  off();
  setUnits({ angle: 'deg' }, storage);
  assert.deepEqual(seen, ['rad']);
});
