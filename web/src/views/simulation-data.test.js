import test from 'node:test';
import assert from 'node:assert/strict';
import { simulationBody, driveRows } from './simulation-data.js';

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
