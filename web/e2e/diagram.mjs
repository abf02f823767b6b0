// The "Modelica diagram" tab (issue 17), end to end (part of ui.mjs, on the model view of the
// uploaded arm): the Mechanics diagram drawn from the package's annotations shows every
// component of Mechanics.mo and a line per connect; clicking a body in it selects that body in
// the 3D view; Mechatronics adds its drive next to the joint it moves.

import assert from 'node:assert/strict';

export async function diagramSteps(page, { step, shot }) {
  const [, , id, , v] = new URL(page.url()).hash.split('/');
  const version = Number(v);
  assert.ok(id && version > 0, `on a model version page: ${page.url()}`);
  step('diagram: Mechanics');
  await page.getByRole('tab', { name: 'Modelica diagram' }).click();
  const view = page.locator('.diagram-view');
  await view.locator('svg g[data-component]').first().waitFor();
  // What the package says: every placed component, every connect.
  const pkg = await page.evaluate(async ({ id, version }) => {
    const r = await fetch(`/api/models/${id}/versions/${version}/report`);
    return r.json();
  }, { id, version });
  const shown = await view.locator('svg g[data-component]').evaluateAll((gs) => gs.map((g) => g.dataset.component));
  for (const b of pkg.bodies) assert.ok(shown.includes(b.modelica_name), `body ${b.modelica_name} in the diagram: ${shown}`);
  const lines = await view.locator('svg polyline').count();
  assert.ok(lines >= pkg.bodies.length, `a line per connection: ${lines}`);
  // A click on a body in the diagram selects it.
  const body = pkg.bodies.find((b) => b.shape) || pkg.bodies[0];
  await view.locator(`svg g[data-component="${body.modelica_name}"] > rect`).click();
  await page.locator('.selection').filter({ hasText: `Selected body ${body.modelica_name}` }).waitFor();
  // Its parameters show beside the diagram (issue 30).
  assert.match(await page.getByRole('table', { name: `Parameters of ${body.modelica_name}` }).textContent(), /kg/);
  // An icon per component, by its class kind; every name legible (≥ 9 px high) or hidden.
  const look = await view.evaluate((v) => {
    const gs = [...v.querySelectorAll('svg g[data-component]')];
    const small = gs
      .map((g) => g.querySelector(':scope > text'))
      .filter((t) => t && t.getAttribute('visibility') !== 'hidden' && t.getBoundingClientRect().height < 9)
      .map((t) => `${t.textContent} ${t.getBoundingClientRect().height.toFixed(1)}px`);
    return { components: gs.length, icons: v.querySelectorAll('svg g[data-component] > g.icon').length, kinds: [...new Set(gs.map((g) => g.dataset.kind))], small };
  });
  assert.equal(look.icons, look.components, `an icon per component: ${JSON.stringify(look)}`);
  assert.ok(look.kinds.includes('body') && look.kinds.includes('revolute'), `body and joint icons: ${look.kinds}`);
  assert.deepEqual(look.small, [], 'component names shown below 9 px');
  await shot(page, '28-modelica-diagram');

  step('diagram: Mechatronics');
  await page.getByRole('combobox', { name: 'Model' }).selectOption('Mechatronics');
  await page.locator('.diagram-status').filter({ hasText: 'Mechatronics:' }).waitFor();
  const drives = await view.locator('svg g[data-component^="drive_"]').count();
  // A drive's parameters: what the Drives tab stored for its joint (motor, gear, ratio, controller).
  const driveBox = view.locator('svg g[data-component^="drive_"]').first();
  const driveName = await driveBox.getAttribute('data-component');
  await driveBox.locator(':scope > rect').click();
  const params = page.getByRole('table', { name: `Parameters of ${driveName}` });
  await params.locator('th', { hasText: 'Motor' }).waitFor();
  const rows = Object.fromEntries(await params.locator('tr').evaluateAll((trs) => trs.map((tr) => [tr.querySelector('th').textContent, tr.querySelector('td').textContent])));
  const stored = await page.evaluate(async ({ id, joint }) => {
    const d = (await (await fetch(`/api/models/${id}/drives`, { headers: { 'X-Requested-With': 'cad2mo' } })).json()).drives.find((x) => x.joint === joint);
    const names = new Map((await (await fetch('/api/library/instances', { headers: { 'X-Requested-With': 'cad2mo' } })).json()).map((i) => [i.id, i.name]));
    return { motor: names.get(d.motor_instance), gear: names.get(d.gear_instance), controller: names.get(d.controller_instance) };
  }, { id, joint: driveName.slice('drive_'.length) });
  assert.equal(rows.Joint, driveName.slice('drive_'.length), JSON.stringify(rows));
  assert.deepEqual([rows.Motor, rows.Gear, rows.Controller], [stored.motor, stored.gear, stored.controller], `the drive's parameters: ${JSON.stringify(rows)}`);
  assert.ok(Number(rows.Ratio) > 0, `its ratio: ${JSON.stringify(rows)}`);
  await shot(page, '29-mechatronics-diagram');
  return { components: shown.length, lines, drives, kinds: look.kinds };
}
