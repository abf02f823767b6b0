import test from 'node:test';
import assert from 'node:assert/strict';
import { simulationBody, driveRows, contactLine } from './simulation-data.js';

test('simulationBody sends tolerances only when set, in SI', () => {
  assert.deepEqual(simulationBody({ motionId: 'm', motionDuration: 2, maxJointErrorMilli: '', maxToolErrorMm: '' }), { duration: 2.5, drives: true, motion_id: 'm' });
  assert.deepEqual(simulationBody({ motionId: 'm', motionDuration: 100, maxJointErrorMilli: 5, maxToolErrorMm: 2 }), {
    duration: 60,
    drives: true,
    motion_id: 'm',
    max_joint_error: 0.005,
    max_tool_error: 0.002,
  });
});

test('driveRows states current and voltage against their limits and the saturation', () => {
  const rows = driveRows({ drives: [{ joint: 'J1', unit: 'rad', max_error: 0.01, rms_error: 0.005, max_current: 5, i_max: 10, max_voltage: 24, v_max: 24, saturated: [[0.1, 0.25]] }] });
  assert.equal(rows[0].current, '5.00 / 10.0 A');
  assert.equal(rows[0].currentShare, 0.5);
  assert.equal(rows[0].voltageShare, 1);
  assert.equal(rows[0].saturated, '0.100–0.250 s');
  assert.equal(driveRows({ drives: [{ ...{ joint: 'J2', unit: 'm', max_error: 0, rms_error: 0, max_current: 1, i_max: 2, max_voltage: 1, v_max: 2 }, saturated: [] }] })[0].saturated, 'never');
});

test('tracking errors: simulated minus planned on the planned grid, missing joints named', async () => {
  const { trackingErrors, valueAt, positionVariable } = await import('./simulation-data.js');
  assert.equal(positionVariable('J1', 'rad'), 'J1.phi');
  assert.equal(positionVariable('S', 'm'), 'S.s');
  const s = { t: [0, 1, 2], y: [0, 10, 30] };
  assert.equal(valueAt(s, 0.5), 5);
  assert.equal(valueAt(s, 1.5), 20);
  assert.equal(valueAt(s, -1), 0);
  assert.equal(valueAt(s, 9), 30);
  assert.equal(valueAt({ t: [], y: [] }, 1), null);
  const traj = { t: [0, 0.5, 1, 1.5], joints: ['J1', 'S', 'J3'], units: ['rad', 'm', 'rad'], q: [[0, 1, 2, 3], [0, 0, 0, 0], [5, 5, 5, 5]] };
  const sim = new Map([
    ['J1.phi', { t: [0, 1], y: [0, 2.2] }],
    ['S.s', { t: [0, 1], y: [0.001, 0.001] }],
  ]);
  const e = trackingErrors(traj, sim);
  // The run ends at 1 s: the planned instants after it are left out.
  assert.deepEqual(e.t, [0, 0.5, 1]);
  assert.deepEqual(e.names, ['J1', 'S']);
  assert.deepEqual(e.units, ['rad', 'm']);
  assert.deepEqual(e.missing, ['J3']);
  assert.ok(Math.abs(e.series[0][1] - 0.1) < 1e-12 && Math.abs(e.series[0][2] - 0.2) < 1e-12, JSON.stringify(e.series[0]));
  assert.deepEqual(e.series[1], [0.001, 0.001, 0.001]);
});

test('contactLine names the first contact along the simulated motion, or says there is none', () => {
  assert.equal(contactLine({}), null);
  const clear = contactLine({ collisions: { samples: 2001, pairs_checked: 3, first_contact: null, contacts: [] } });
  assert.deepEqual(clear, { contact: false, text: 'No contact along the simulated motion (3 checked pairs, 2001 samples).' });
  const hit = contactLine({
    collisions: {
      samples: 2001,
      pairs_checked: 3,
      first_contact: { a: 'arm', b: 'obstacle', time: 0.3315 },
      contacts: [{ a: 'arm', b: 'obstacle', first_contact: 0.3315, max_depth: 0.01 }, { a: 'base', b: 'crate', first_contact: 0.8, max_depth: 0.1 }],
    },
  });
  assert.equal(hit.contact, true);
  assert.equal(hit.text, 'First contact along the simulated motion: arm touches obstacle at 0.332 s. 2 pairs touch: arm/obstacle at 0.332 s, base/crate at 0.800 s.');
  assert.equal(contactLine({ collisions: { samples: 2001, pairs_checked: 0, first_contact: null, contacts: [], not_checked: 'too large' } }).text, 'Contacts not checked: too large.');
  assert.equal(simulationBody({ motionId: 'm', motionDuration: 1, maxJointErrorMilli: '', maxToolErrorMm: '', live: true }).live, true);
});
