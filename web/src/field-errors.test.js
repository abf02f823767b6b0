import { test } from 'node:test';
import assert from 'node:assert/strict';
import { placeFieldErrors, driveControl } from './field-errors.js';

test('drive fields map to their controls', () => {
  assert.equal(driveControl('overrides.gear.ratio'), 'gear.ratio');
  assert.equal(driveControl('overrides.motor.R'), 'motor.R');
  assert.equal(driveControl('controller_instance'), 'controller');
  assert.equal(driveControl('reference.value'), 'reference');
  assert.equal(driveControl('reference'), 'reference');
  assert.equal(driveControl('drive'), null);
  assert.equal(driveControl('overrides.brake.x'), null);
});

test('messages go to their control, the rest stays for the summary', () => {
  const errors = [
    { field: 'overrides.gear.ratio', message: 'must not be 0' },
    { field: 'overrides.gear.ratio', message: 'must not be 0' },
    { field: 'overrides.gear.ratio', message: 'above 1000' },
    { field: 'drive', message: 'a lead screw needs a prismatic joint' },
    { message: 'no field' },
  ];
  const { at, rest } = placeFieldErrors(errors, driveControl);
  assert.deepEqual([...at], [['gear.ratio', ['must not be 0', 'above 1000']]]);
  assert.deepEqual(rest.map((e) => e.message), ['a lead screw needs a prismatic joint', 'no field']);
  assert.deepEqual(placeFieldErrors(undefined, driveControl), { at: new Map(), rest: [] });
});
