// Browser forward kinematics as a command, for tests/ui.rs to compare with the Modelica model:
// reads [{report, q: {key: value}}] (JSON, a file named on the command line) and prints, per
// case, every body's CS1 world matrix (column-major, 16 numbers) for those joint values.
import { readFileSync } from 'node:fs';
import { bodyDeltas, frameMatrix } from '../src/viewer/kinematics.js';

const cases = JSON.parse(readFileSync(process.argv[2], 'utf8'));
const out = cases.map(({ report, q }) => {
  const deltas = bodyDeltas(report, new Map(Object.entries(q)));
  const poses = {};
  for (const b of report.bodies) poses[b.modelica_name] = deltas.get(b.modelica_name).clone().multiply(frameMatrix(b.cs1)).elements;
  return poses;
});
console.log(JSON.stringify(out));
