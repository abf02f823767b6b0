import test from 'node:test';
import assert from 'node:assert/strict';
import { componentKind, labelPlan, parseTitle, LABEL_PX, MIN_BOX_PX, namePrefix, shortName, fitLabels } from './diagram-data.js';

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

test('the prefix most names share is dropped from the labels, an ellipsis in its place', () => {
  const hand = ['world', 'RootPart', 'SIM_L_HAND_PALM_NAKED', 'SIM_L_HAND_PALM_NAKED_CS2', 'SIM_L_HAND_PROX_LITTLE_FINGER', 'SIM_L_HAND_DISTAL_THUMB', 'SIM_L_HAND_PALM_ADDUCTION'];
  assert.equal(namePrefix(hand), 'SIM_L_HAND_');
  assert.equal(namePrefix(['a_b', 'c_d']), '', 'no shared prefix');
  assert.equal(namePrefix(['AB_x1', 'AB_x2', 'CD_y', 'EF_z']), '', 'shared by too few, and too short');
  assert.equal(namePrefix(['J_', 'J_']), '', 'a prefix leaves some of the name');
  assert.equal(shortName('SIM_L_HAND_PALM_NAKED_CS2', 'SIM_L_HAND_', 30), '…PALM_NAKED_CS2');
  assert.equal(shortName('SIM_L_HAND_PROX_LITTLE_FINGER', 'SIM_L_HAND_', 12), '…PROX_…INGER');
  assert.equal(shortName('world', 'SIM_L_HAND_', 12), 'world', 'names without the prefix stay');
});

test('fitLabels: names that would overlap are cut down, else hidden; earlier ones win', () => {
  const label = (cx, y0, width, chars) => ({ cx, y0, y1: y0 + 10, width, chars });
  // Three 60-unit names at 50 apart in a row: the middle one is cut, the third fits beside it.
  assert.deepEqual(fitLabels([label(0, 0, 60, 12), label(100, 0, 60, 12), label(50, 0, 60, 12)]), [12, 12, 7]);
  // No room at all: hidden.
  assert.deepEqual(fitLabels([label(0, 0, 60, 12), label(2, 0, 60, 12)]), [12, 0]);
  // Another row is free, so is a name far away.
  assert.deepEqual(fitLabels([label(0, 0, 60, 12), label(0, 11, 60, 12), label(500, 0, 60, 12)]), [12, 12, 12]);
  // The gap kept between names.
  assert.deepEqual(fitLabels([label(0, 0, 60, 12), label(61, 0, 60, 12)], { pad: 0 }), [12, 12]);
  assert.deepEqual(fitLabels([label(0, 0, 60, 12), label(61, 0, 60, 12)], { pad: 2, minChars: 12 }), [12, 0]);
  // A check of measured boxes: overlapping ones are hidden, never cut.
  assert.deepEqual(fitLabels([label(0, 0, 60, 12), label(50, 0, 60, 12)], { shrink: false }), [12, 0]);
  // What is kept never overlaps, whatever the input (a dense random sheet).
  let seed = 7;
  const rnd = () => ((seed = (seed * 16807) % 2147483647) / 2147483647);
  const many = Array.from({ length: 400 }, () => label(rnd() * 1000, Math.floor(rnd() * 40) * 6, 20 + rnd() * 80, 10 + Math.floor(rnd() * 20)));
  const kept = fitLabels(many, { pad: 1 });
  const boxes = many.map((l, i) => ({ x0: l.cx - (l.width / l.chars) * kept[i] / 2, x1: l.cx + (l.width / l.chars) * kept[i] / 2, y0: l.y0, y1: l.y1, on: kept[i] > 0 })).filter((b) => b.on);
  for (let i = 0; i < boxes.length; i++) {
    for (let j = i + 1; j < boxes.length; j++) {
      const [a, b] = [boxes[i], boxes[j]];
      assert.ok(!(a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1), `kept names ${i} and ${j} overlap`);
    }
  }
  assert.ok(boxes.length > 100 && boxes.length < 400, `${boxes.length} of 400 kept`);
});
