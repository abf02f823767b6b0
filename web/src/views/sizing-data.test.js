import test from 'node:test';
import assert from 'node:assert/strict';
import { sizingQuery, verdict, standingLabel, limitingText, valueSource } from './sizing-data.js';

test('sizingQuery sends only what is set, the reserve as a fraction', () => {
  assert.equal(sizingQuery({ reservePercent: '', dwell: '' }), '');
  assert.equal(sizingQuery({ reservePercent: 20, dwell: 1.5 }), '?reserve=0.2&dwell=1.5');
  const q = sizingQuery({ reservePercent: 10, dwell: '', amplifier: 'a1', supplyVoltage: 24, brake: 'bus', busCapacitance: 0.001, busVoltageMax: 60, brakePower: 50 });
  assert.equal(q, '?reserve=0.1&amplifier=a1&supply_voltage=24&bus_capacitance=0.001&bus_voltage_max=60');
  assert.equal(sizingQuery({ reservePercent: '', dwell: '', brake: 'resistor', brakePower: 50, supplyVoltage: 24 }), '?brake_power=50');
  assert.equal(sizingQuery({ reservePercent: '', dwell: '', screwLife: 20000 }), '?screw_life=20000');
  assert.equal(sizingQuery({ reservePercent: '', dwell: '', screwLife: '' }), '');
});

test('verdict distinguishes fail, not evaluated and the reserve', () => {
  assert.equal(verdict({ status: 'fail', pass: false }), 'FAIL');
  assert.equal(verdict({ status: 'not_evaluated', pass: true }), 'not evaluated');
  assert.equal(verdict({ status: 'pass', pass: true, within_reserve: false }), 'pass, below reserve');
  assert.equal(verdict({ status: 'pass', pass: true, within_reserve: true }), 'pass');
  assert.equal(verdict({ status: 'pass', pass: true, within_reserve: null }), 'pass');
});

test('alternative texts', () => {
  assert.equal(standingLabel('passes_with_reserve'), 'passes with reserve');
  assert.equal(limitingText({ limiting: { label: 'RMS motor torque', margin: 0.1234 } }), 'RMS motor torque (margin 12.3 %)');
  assert.equal(limitingText({ limiting: null }), 'no limiting check');
});

test('valueSource finds the clause of one value', () => {
  const s = 'FAULHABER ... Values (column 1331 T 006 SR): V_max = line 1 nominal voltage 6 V; R = line 2 terminal resistance 2,83 Ω; k = line 11 torque constant 5,35 mNm/A; T_nom = line 28 torque up to 3,2 mNm. d = 0: the data sheet prints no viscous coefficient.';
  assert.equal(valueSource(s, 'R'), 'line 2 terminal resistance 2,83 Ω');
  assert.equal(valueSource(s, 'V_max'), 'line 1 nominal voltage 6 V');
  assert.equal(valueSource(s, 'T_nom'), 'line 28 torque up to 3,2 mNm');
  assert.equal(valueSource(s, 'w_max'), null);
  assert.equal(valueSource(s, 'k'), 'line 11 torque constant 5,35 mNm/A');
  assert.equal(valueSource('', 'R'), null);
});
