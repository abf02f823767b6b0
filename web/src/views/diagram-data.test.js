import test from 'node:test';
import assert from 'node:assert/strict';
import { componentKind, labelPlan, parseTitle, LABEL_PX, MIN_BOX_PX } from './diagram-data.js';

test('component kinds from MSL and generated class names', () => {
  assert.equal(componentKind('Modelica.Mechanics.MultiBody.World'), 'world');
  assert.equal(componentKind('Modelica.Mechanics.MultiBody.Parts.Fixed'), 'fixed');
  assert.equal(componentKind('Modelica.Mechanics.MultiBody.Parts.FixedTranslation'), 'translation');
  assert.equal(componentKind('Modelica.Mechanics.MultiBody.Parts.Body'), 'body');
  assert.equal(componentKind('Modelica.Mechanics.MultiBody.Parts.BodyShape'), 'body');
  assert.equal(componentKind('Modelica.Mechanics.MultiBody.Joints.Revolute'), 'revolute');
  assert.equal(componentKind('Modelica.Mechanics.MultiBody.Joints.Prismatic'), 'prismatic');
  assert.equal(componentKind('ARM.Motors.DCPermanentMagnet'), 'motor');
  assert.equal(componentKind('ARM.Gears.GearWithEfficiency'), 'gear');
  assert.equal(componentKind('ARM.Controllers.CascadePPI'), 'controller');
  assert.equal(componentKind('Modelica.Mechanics.Rotational.Sensors.AngleSensor'), 'sensor');
  assert.equal(componentKind('ARM.Drives.Drive'), 'drive');
  assert.equal(componentKind('ARM.Components.Collision.BodyForce'), 'force');
  assert.equal(componentKind('Something.Else'), 'other');
  assert.equal(componentKind(undefined), 'other');
});

test('labels are LABEL_PX high on screen at any zoom, or hidden', () => {
  for (const scale of [0.5, 1, 2.5, 8]) {
    const p = labelPlan(scale, 20);
    if (p.visible) assert.ok(Math.abs(p.fontSize * scale - LABEL_PX) < 1e-9, `${scale}: ${p.fontSize}`);
    assert.ok(!p.visible || p.fontSize * scale >= 9, 'a shown label is at least 9 px high');
  }
  // A 20-unit component at 0.5 px per unit is 10 px wide on screen: no label.
  assert.deepEqual(labelPlan(0.5, 20), { visible: false, fontSize: 0 });
  assert.equal(labelPlan(MIN_BOX_PX / 20, 20).visible, true);
  assert.equal(labelPlan(0, 20).visible, false);
});

test('the component title splits into class and name', () => {
  assert.deepEqual(parseTitle('Modelica.Mechanics.MultiBody.Parts.Body LINK1'), { className: 'Modelica.Mechanics.MultiBody.Parts.Body', name: 'LINK1' });
  assert.deepEqual(parseTitle('World'), { className: 'World', name: '' });
});

test('a drive component shows its motor, gear, ratio, controller and overrides', async () => {
  const { driveParamRows } = await import('./diagram-data.js');
  const inst = new Map([
    ['m1', { name: 'maxon RE 40' }],
    ['g1', { name: 'GP 52 C', values: { ratio: 43 } }],
    ['c1', { name: 'Cascade PI' }],
  ]);
  const d = { joint: 'J1', motor_instance: 'm1', gear_instance: 'g1', controller_instance: 'c1', overrides: { gear: { ratio: 100, eta: 0.8 } }, status: 'active' };
  assert.deepEqual(driveParamRows('J1', d, inst), [['Joint', 'J1'], ['Motor', 'maxon RE 40'], ['Gear', 'GP 52 C'], ['Ratio', '100'], ['Controller', 'Cascade PI'], ['gear.eta', '0.8']]);
  assert.deepEqual(driveParamRows('J1', { ...d, overrides: {} }, inst).find((r) => r[0] === 'Ratio'), ['Ratio', '43'], "the gear's own ratio");
  assert.deepEqual(driveParamRows('J2', undefined, inst), [['Joint', 'J2'], ['Drive', 'none stored for this joint']]);
  assert.deepEqual(driveParamRows('J1', { ...d, status: 'orphaned' }, inst).pop(), ['Status', 'orphaned']);
});
