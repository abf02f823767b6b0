// Models: the list with the upload zone, and one model's page with its versions, a new-version
// upload, the diff between versions and the state of its drive assignments.

import { api, download, enc } from '../api.js';
import { h, fill, errorBox, say, confirmAction, when, bytes, newId, num, plural } from '../ui.js';
import { uploadZone } from './upload.js';

const statusBadge = (s) => h('span', { class: `badge badge-${s}` }, s);

/** Fields of the diff, as people read them: label, unit and scale of numbers. */
const DIFF_FIELDS = {
  mass: ['mass', 'kg', 1],
  cg_world: ['CG (world)', 'mm', 1000],
  inertia_cg: ['inertia about the CG', 'kg·m²', 1],
  axis_world: ['axis (world)', '', 1],
  cad_name: ['CAD name', '', 1],
  modelica_name: ['Modelica name', '', 1],
  node_id: ['node ID', '', 1],
  primitives: ['primitives', '', 1],
  base_body: ['base body', '', 1],
  follower_body: ['follower body', '', 1],
};

/** One changed field: "mass 0.31752 → 0.5 kg". */
function fieldChange(f) {
  const [label, unit, scale] = DIFF_FIELDS[f.field] || [f.field, '', 1];
  const show = (v) => {
    if (typeof v === 'number') return num(v * scale);
    if (Array.isArray(v)) return `(${v.map((x) => (Array.isArray(x) ? show(x) : typeof x === 'number' ? num(x * scale) : String(x))).join(', ')})`;
    return v === null || v === undefined ? '—' : String(v);
  };
  return `${label}: ${show(f.old)} → ${show(f.new)}${unit ? ` ${unit}` : ''}`;
}

export async function renderModels(main) {
  const list = h('div', { class: 'card' }, h('p', {}, 'Loading…'));
  fill(
    main,
    h('h1', {}, 'Models'),
    uploadZone({
      url: '/api/models',
      label: 'Upload a new model',
      askName: true,
      onAccepted: () => load(), // the new model shows up at once, its status followed
      onDone: (created, job) => {
        load();
        if (job.status === 'succeeded') location.hash = `#/models/${enc(created.model_id)}/versions/${created.version}`;
      },
    }),
    h('h2', {}, 'All models'),
    list,
  );

  let timer = null;
  async function load() {
    clearTimeout(timer);
    let models;
    try {
      models = await api('/api/models');
    } catch (e) {
      fill(list, errorBox(e, 'Could not load the models'));
      return;
    }
    // While a conversion is under way (here or from another client), follow it.
    if (models.some((m) => ['queued', 'running'].includes(m.latest_version?.status)) && list.isConnected) timer = setTimeout(load, 1000);
    if (!models.length) {
      fill(list, h('p', { class: 'muted' }, 'No models yet: upload a CAD export above.'));
      return;
    }
    const rows = models.map((m) => {
      const lv = m.latest_version;
      const href = `#/models/${enc(m.id)}`;
      return h(
        'tr',
        { dataset: { modelId: m.id } },
        h('th', { scope: 'row' }, h('a', { href }, m.name)),
        h('td', {}, lv ? `v${lv.version} ` : '—', lv ? statusBadge(lv.status) : null),
        h('td', {}, when(m.created_at)),
        h(
          'td',
          { class: 'actions' },
          lv && lv.status === 'succeeded'
            ? h('a', { class: 'button', href: `${href}/versions/${lv.version}`, 'aria-label': `3D view of ${m.name}` }, '3D view')
            : null,
          h('button', { type: 'button', class: 'danger', 'aria-label': `Delete ${m.name}`, onclick: () => remove(m) }, 'Delete'),
        ),
      );
    });
    fill(
      list,
      h(
        'div',
        { class: 'scroll' },
        h(
          'table',
          {},
          h('thead', {}, h('tr', {}, h('th', { scope: 'col' }, 'Name'), h('th', { scope: 'col' }, 'Latest'), h('th', { scope: 'col' }, 'Created'), h('th', { scope: 'col' }, h('span', { class: 'visually-hidden' }, 'Actions')))),
          h('tbody', {}, rows),
        ),
      ),
    );
  }

  async function remove(m) {
    if (!(await confirmAction(`Delete model "${m.name}" with all its versions and drives?`))) return;
    try {
      await api(`/api/models/${enc(m.id)}`, { method: 'DELETE' });
      say(`Deleted ${m.name}`, 'ok');
      load();
    } catch (e) {
      say(e.message, 'error');
    }
  }

  await load();
  return () => clearTimeout(timer);
}

export async function renderModel(main, id) {
  const model = await api(`/api/models/${enc(id)}`);
  const versionsBox = h('div', { class: 'card' });
  const diffBox = h('section', { class: 'card', 'aria-labelledby': 'diff-h' });
  const drivesBox = h('section', { class: 'card', 'aria-labelledby': 'drives-h' });
  fill(
    main,
    h('p', { class: 'crumbs' }, h('a', { href: '#/models' }, 'Models'), ' / '),
    h('h1', {}, model.name),
    h('h2', {}, 'Versions'),
    versionsBox,
    uploadZone({
      url: `/api/models/${enc(id)}/versions`,
      label: 'Upload a new version (the CAD export after a change)',
      onAccepted: () => loadVersions(),
      onDone: async (created, job) => {
        const versions = await loadVersions();
        await loadDrives();
        const prev = versions.filter((v) => v.version < created.version && v.status === 'succeeded').pop();
        if (prev && job.status === 'succeeded') showDiff(prev.version, created.version);
      },
    }),
    diffBox,
    drivesBox,
  );

  let versions = [];
  async function loadVersions() {
    try {
      versions = await api(`/api/models/${enc(id)}/versions`);
    } catch (e) {
      fill(versionsBox, errorBox(e, 'Could not load the versions'));
      return [];
    }
    const rows = versions.map((v) => {
      const s = v.summary;
      const ok = v.status === 'succeeded';
      return h(
        'tr',
        { dataset: { version: v.version } },
        h('th', { scope: 'row' }, `v${v.version}`),
        h('td', {}, statusBadge(v.status)),
        h('td', {}, s ? [plural(s.bodies, 'body', 'bodies'), plural(s.joints, 'joint'), plural(s.loops, 'loop'), plural(s.warnings, 'warning')].join(', ') : v.error?.detail || ''),
        h('td', {}, `${v.bundle.name} (${bytes(v.bundle.size)})`, h('br'), h('small', { class: 'muted' }, when(v.created_at))),
        h(
          'td',
          { class: 'actions' },
          ok ? h('a', { class: 'button', href: `#/models/${enc(id)}/versions/${v.version}`, 'aria-label': `3D view of version ${v.version}` }, '3D view') : null,
          ok ? h('button', { type: 'button', 'aria-label': `Download the package of version ${v.version}`, onclick: () => dl(v.links.package, `package-v${v.version}.zip`) }, 'Package') : null,
          ok ? h('button', { type: 'button', 'aria-label': `Download the URDF of version ${v.version}`, onclick: () => dl(v.links.urdf, `robot-v${v.version}.urdf`) }, 'URDF') : null,
          h('button', { type: 'button', 'aria-label': `Download the bundle of version ${v.version}`, onclick: () => dl(v.links.bundle, v.bundle.name) }, 'Bundle'),
          h('button', { type: 'button', class: 'danger', 'aria-label': `Delete version ${v.version}`, onclick: () => removeVersion(v.version) }, 'Delete'),
        ),
      );
    });
    fill(
      versionsBox,
      h(
        'div',
        { class: 'scroll' },
        h(
          'table',
          {},
          h('thead', {}, h('tr', {}, ['Version', 'Status', 'Contents', 'Bundle', 'Actions'].map((c) => h('th', { scope: 'col' }, c)))),
          h('tbody', {}, rows),
        ),
      ),
      h('div', { class: 'row' }, h('button', { type: 'button', class: 'danger', onclick: removeModel }, 'Delete this model')),
    );
    renderDiffPicker();
    return versions;
  }

  async function dl(path, name) {
    try {
      await download(path, name);
    } catch (e) {
      say(e.message, 'error');
    }
  }

  async function removeVersion(v) {
    if (!(await confirmAction(`Delete version ${v} of "${model.name}"?`))) return;
    try {
      await api(`/api/models/${enc(id)}/versions/${v}`, { method: 'DELETE' });
      say(`Deleted version ${v}`, 'ok');
      loadVersions();
    } catch (e) {
      say(e.message, 'error');
    }
  }

  async function removeModel() {
    if (!(await confirmAction(`Delete model "${model.name}" with all its versions and drives?`))) return;
    try {
      await api(`/api/models/${enc(id)}`, { method: 'DELETE' });
      say(`Deleted ${model.name}`, 'ok');
      location.hash = '#/models';
    } catch (e) {
      say(e.message, 'error');
    }
  }

  const diffOut = h('div', { class: 'diff-out' });
  function renderDiffPicker() {
    const done = versions.filter((v) => v.status === 'succeeded').map((v) => v.version);
    if (done.length < 2) {
      fill(diffBox, h('h2', { id: 'diff-h' }, 'Changes between versions'), h('p', { class: 'muted' }, 'Upload a new version to compare it with this one.'));
      return;
    }
    const pick = (label, value) => {
      const s = h('select', { id: newId('v') }, done.map((v) => h('option', { value: v, selected: v === value }, `v${v}`)));
      return [h('label', { for: s.id }, label), s];
    };
    const [lf, from] = pick('From', done[done.length - 2]);
    const [lt, to] = pick('To', done[done.length - 1]);
    fill(
      diffBox,
      h('h2', { id: 'diff-h' }, 'Changes between versions'),
      h('form', { class: 'row', onsubmit: (e) => { e.preventDefault(); showDiff(Number(from.value), Number(to.value)); } }, lf, from, lt, to, h('button', { type: 'submit' }, 'Compare')),
      diffOut,
    );
  }

  async function showDiff(from, to) {
    if (!diffBox.contains(diffOut)) renderDiffPicker();
    fill(diffOut, h('p', {}, 'Comparing…'));
    let d;
    try {
      d = await api(`/api/models/${enc(id)}/diff?from=${from}&to=${to}`);
    } catch (e) {
      fill(diffOut, errorBox(e, 'Could not compare'));
      return;
    }
    const section = (title, c) => {
      const items = [
        ...c.added.map((i) => h('li', { class: 'added' }, h('strong', {}, 'added '), `${i.modelica_name} (${i.cad_name})`)),
        ...c.removed.map((i) => h('li', { class: 'removed' }, h('strong', {}, 'removed '), `${i.modelica_name} (${i.cad_name})`)),
        ...c.changed.map((i) =>
          h(
            'li',
            { class: 'changed' },
            h('strong', {}, 'changed '),
            `${i.modelica_name} (${i.cad_name})`,
            h('ul', {}, i.changes.map((f) => h('li', {}, fieldChange(f)))),
          ),
        ),
      ];
      return [h('h3', {}, title), items.length ? h('ul', { class: 'diff' }, items) : h('p', { class: 'muted' }, 'No change.')];
    };
    fill(diffOut, h('p', {}, `v${from} → v${to}`), section('Bodies', d.bodies), section('Joints', d.joints));
  }

  async function loadDrives() {
    let d;
    try {
      d = await api(`/api/models/${enc(id)}/drives`);
    } catch (e) {
      fill(drivesBox, h('h2', { id: 'drives-h' }, 'Drives'), errorBox(e));
      return;
    }
    const orphaned = d.drives.filter((x) => x.status === 'orphaned');
    const active = d.drives.filter((x) => x.status === 'active');
    const latest = versions.filter((v) => v.status === 'succeeded').pop();
    fill(
      drivesBox,
      h('h2', { id: 'drives-h' }, 'Drives'),
      h('p', {}, `${plural(active.length, 'active drive')} on ${plural(d.joints.length, 'drivable joint')} of v${d.version ?? '—'}.`),
      latest ? h('a', { class: 'button', href: `#/models/${enc(id)}/versions/${latest.version}/drives` }, 'Edit drives') : null,
      orphaned.length
        ? h(
            'div',
            { class: 'warning', role: 'alert' },
            h('strong', {}, plural(orphaned.length, 'orphaned drive')),
            h('p', {}, 'These joints are gone from the latest version; their assignments are kept (and left out of the package) until you delete them or the joint returns.'),
            h(
              'ul',
              { class: 'orphaned' },
              orphaned.map((o) =>
                h(
                  'li',
                  {},
                  h('code', {}, o.joint),
                  ` (node ${o.joint_node_id}) `,
                  h('button', { type: 'button', class: 'danger', 'aria-label': `Remove the orphaned drive of ${o.joint}`, onclick: () => removeDrive(o.joint) }, 'Remove'),
                ),
              ),
            ),
          )
        : null,
    );
  }

  async function removeDrive(joint) {
    if (!(await confirmAction(`Remove the drive of ${joint}? Its motor and gear choice is lost.`, 'Remove'))) return;
    try {
      await api(`/api/models/${enc(id)}/drives/${enc(joint)}`, { method: 'DELETE' });
      say(`Removed the drive of ${joint}`, 'ok');
      loadDrives();
    } catch (e) {
      say(e.message, 'error');
    }
  }

  await loadVersions();
  await loadDrives();
}
