// One converted version: the 3D view beside eight tabs (Structure with joint sliders, Report,
// Drives, Motion, Results, Live, Collision, Modelica diagram). Selecting a body or joint anywhere highlights it in the 3D view and in the lists.

import { unzipSync } from 'fflate';
import { STLLoader } from 'three/addons/loaders/STLLoader.js';
import { api, download, enc } from '../api.js';
import { h, fill, errorBox, say, tabs, num, plural } from '../ui.js';
import { Viewer, niceStep } from '../viewer/viewer.js';
import { immersiveSupport } from '../viewer/xr-data.js';
import { coordinates } from '../viewer/kinematics.js';
import { parseObj } from '../viewer/obj.js';
import { renderDrives } from './drives.js';
import { renderMotion } from './motion.js';
import { renderResults } from './results.js';
import { renderLive } from './live.js';
import { renderCollision } from './collision.js';
import { renderScene, sceneLayer } from './scene.js';
import { renderDiagram } from './diagram.js';
import { getUnits, setUnits, onUnits, toDisplay, fromDisplay, symbolOf, parseNumber } from '../units.js';
import { sizeLimits, loadSize, saveSize, clamp, abbreviate } from '../layout-data.js';

const DEG = 180 / Math.PI;

/** STL meshes of the package, by body Modelica name (geometry in CS1, metres). */
async function loadMeshes(version, report) {
  // Timings land in the Performance timeline (cad2mo:*), for profiling large models.
  const t0 = performance.now();
  const zip = new Uint8Array(await api(version.links.package, { accept: 'application/zip' }));
  const t1 = performance.now();
  const wanted = new Map();
  for (const b of report.bodies) if (b.shape) wanted.set(b.shape.replace(/\.dxf$/i, '.stl'), b.modelica_name);
  const files = unzipSync(zip, { filter: (f) => wanted.has(f.name) });
  const t2 = performance.now();
  const loader = new STLLoader();
  const out = new Map();
  for (const [name, bytes] of Object.entries(files)) {
    out.set(wanted.get(name), loader.parse(bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength)));
  }
  const t3 = performance.now();
  performance.measure('cad2mo:download', { start: t0, end: t1 });
  performance.measure('cad2mo:unzip', { start: t1, end: t2 });
  performance.measure('cad2mo:parse', { start: t2, end: t3 });
  // The collision shapes are unzipped from the same bytes when first shown.
  out.collisionShapes = () => collisionShapes(zip, report);
  return out;
}

/** Each body's collision shape from the package (Resources/Collision/<body>.obj), by body name. */
function collisionShapes(zip, report) {
  const names = new Set(report.bodies.map((b) => b.modelica_name));
  const files = unzipSync(zip, { filter: (f) => /\/Resources\/Collision\/[^/]+\.obj$/.test(f.name) });
  const out = new Map();
  const text = new TextDecoder();
  for (const [path, bytes] of Object.entries(files)) {
    const name = path.split('/').pop().replace(/\.obj$/, '');
    if (names.has(name)) out.set(name, parseObj(text.decode(bytes)));
  }
  return out;
}

export async function renderViewer(main, id, v, initialTab) {
  fill(main, h('p', {}, 'Loading the model…'));
  const [model, version] = await Promise.all([api(`/api/models/${enc(id)}`), api(`/api/models/${enc(id)}/versions/${v}`)]);
  if (version.status !== 'succeeded') {
    fill(
      main,
      h('p', { class: 'crumbs' }, h('a', { href: '#/models' }, 'Models'), ' / ', h('a', { href: `#/models/${enc(id)}` }, model.name)),
      h('h1', {}, `${model.name} v${v}`),
      version.status === 'failed'
        ? errorBox({ message: version.error?.detail || 'the conversion failed' }, 'Conversion failed')
        : h('p', {}, `This version is ${version.status}; reload when it is converted.`),
    );
    return;
  }
  // The joints' position limits span the sliders (none while the service cannot tell).
  const jointsInfo = api(`/api/models/${enc(id)}/joints`).catch(() => null);
  const report = await api(version.links.report);
  const meshes = await loadMeshes(version, report);
  const limitsOf = new Map();
  for (const j of (await jointsInfo)?.joints || []) if (Array.isArray(j.limits?.position)) limitsOf.set(j.name, j.limits.position);

  let selection = null;
  const listeners = new Set(); // each list re-marks its selected entry
  const select = (sel, { scroll = true } = {}) => {
    selection = sel;
    viewer.select(sel);
    for (const f of listeners) f(sel, scroll);
    info.textContent = sel ? `Selected ${sel.kind} ${sel.name}` : 'Nothing selected';
    fill(details, sel ? describe(report, sel) : null);
  };

  const stage = h('div', { class: 'stage' });
  const info = h('p', { class: 'selection muted', 'aria-live': 'polite' }, 'Nothing selected');
  // Scrolls sideways by itself if a value cannot wrap (never the page).
  const details = h('div', { class: 'details scroll' });
  const anaglyph = h('input', { type: 'checkbox', id: 'anaglyph' });
  const grid = h('input', { type: 'checkbox', id: 'grid', checked: true });
  const shapesBox = h('input', { type: 'checkbox', id: 'collision-shapes' });
  const units = getUnits();
  const angleSel = h('select', { id: 'unit-angle' }, h('option', { value: 'deg', selected: units.angle === 'deg' }, 'degrees'), h('option', { value: 'rad', selected: units.angle === 'rad' }, 'radians'));
  const lengthSel = h('select', { id: 'unit-length' }, h('option', { value: 'mm', selected: units.length === 'mm' }, 'mm'), h('option', { value: 'm', selected: units.length === 'm' }, 'm'));
  // Viewports: one perspective view, four (top, front, side orthographic + perspective),
  // side-by-side stereo or dual output (the right eye in a second window, for polarised dual
  // projection: one window per projector), beside the red-cyan anaglyph; the measuring tool.
  const layoutSel = h(
    'select',
    { id: 'view-layout' },
    h('option', { value: 'single' }, 'Single view'),
    h('option', { value: 'quad' }, 'Four views'),
    h('option', { value: 'sbs' }, 'Side-by-side stereo'),
    h('option', { value: 'dual', title: 'The left eye here, the right eye in a window of its own (move it to the second projector; double-click it for full screen)' }, 'Dual output stereo (second window)'),
  );
  // Named views of the whole model, framing the selection, see-through bodies.
  const viewSel = h('select', { id: 'named-view', 'aria-label': 'Named view' }, h('option', { value: '' }, 'View from…'), ...['iso', 'top', 'front', 'side'].map((v) => h('option', { value: v }, { iso: 'Iso', top: 'Top', front: 'Front', side: 'Side' }[v])));
  const transparentBox = h('input', { type: 'checkbox', id: 'transparent' });
  // Contact points and closest-point lines of the collision checks, when there are any.
  const contactsBox = h('input', { type: 'checkbox', id: 'contact-points', checked: true });
  const measureOut = h('output', { class: 'measure-out', 'aria-live': 'polite' });
  // Immersive VR (WebXR): enabled only when the browser says an immersive session works; until
  // then, and otherwise, disabled with the reason as its tooltip (on the wrapper too: a disabled
  // button gets no pointer events in some browsers).
  const vrBtn = h('button', { type: 'button', id: 'enter-vr', disabled: true, title: 'Checking whether this browser offers immersive VR…', 'data-xr': 'checking' }, 'Enter VR');
  const vrWrap = h('span', { class: 'vr-wrap', title: vrBtn.title }, vrBtn);
  const measureBtn = h('button', { type: 'button', id: 'measure', 'aria-pressed': 'false' }, 'Measure');
  angleSel.addEventListener('change', () => setUnits({ angle: angleSel.value }));
  lengthSel.addEventListener('change', () => setUnits({ length: lengthSel.value }));
  const toolbar = h(
    'div',
    // A row that wraps in a wide window and scrolls by itself in a narrow one.
    { class: 'toolbar scroll', role: 'toolbar', 'aria-label': '3D view' },
    h('button', { type: 'button', onclick: () => viewer.resetView() }, 'Reset view'),
    h('button', { type: 'button', onclick: () => resetPose() }, 'Reset pose'),
    h('span', { class: 'check' }, anaglyph, h('label', { for: 'anaglyph' }, 'Red-cyan anaglyph')),
    h('span', { class: 'check' }, grid, h('label', { for: 'grid' }, 'Grid and world frame')),
    viewSel,
    h('button', { type: 'button', id: 'fit-selection', onclick: () => viewer.fitSelection?.() }, 'Fit selection'),
    h('span', { class: 'check' }, shapesBox, h('label', { for: 'collision-shapes' }, 'Collision shapes')),
    h('span', { class: 'check' }, transparentBox, h('label', { for: 'transparent' }, 'Transparent')),
    h('span', { class: 'check' }, contactsBox, h('label', { for: 'contact-points' }, 'Contact points')),
    h('span', { class: 'check' }, h('label', { for: 'view-layout' }, 'Viewports'), layoutSel),
    vrWrap,
    measureBtn,
    measureOut,
    h('span', { class: 'check units' }, h('label', { for: 'unit-angle' }, 'Angles'), angleSel, h('label', { for: 'unit-length' }, 'Lengths'), lengthSel),
    h('button', { type: 'button', onclick: () => download(version.links.package, `${report.package_name}-v${v}.zip`).catch((e) => say(e.message, 'error')) }, 'Download package'),
    h('button', { type: 'button', onclick: () => download(version.links.urdf, `${report.package_name}-v${v}.urdf`).catch((e) => say(e.message, 'error')) }, 'Download URDF'),
  );

  const tv = performance.now();
  let viewer;
  try {
    viewer = new Viewer(stage, report, meshes, (sel) => select(sel));
  } catch (e) {
    // No WebGL here: the lists, report and drives still work.
    viewer = blindViewer();
    stage.replaceChildren(errorBox(e, 'The 3D view needs WebGL, which this browser does not offer'));
  }
  performance.measure('cad2mo:scene', { start: tv });
  window.cad2moViewer = viewer; // for the end-to-end tests and the console
  // The scene's objects (issue 29) in the 3D view, whichever tab is shown; the Scene tab edits them.
  const layer = sceneLayer(id, viewer);
  const sceneLoaded = layer.load();
  sceneLoaded.catch((e) => say(`The scene could not be loaded: ${e.message}`, 'error'));
  anaglyph.addEventListener('change', () => viewer.setAnaglyph(anaglyph.checked));
  const vrReason = (why) => {
    vrBtn.title = why;
    vrWrap.title = why;
  };
  immersiveSupport(navigator, window.isSecureContext).then(({ supported, reason }) => {
    const ok = supported && typeof viewer.enterVR === 'function';
    vrBtn.disabled = !ok;
    vrBtn.dataset.xr = ok ? 'supported' : 'unsupported';
    vrReason(ok ? 'View the model at its true size in your VR headset (WebXR)' : reason || 'The 3D view needs WebGL for VR');
  });
  vrBtn.addEventListener('click', async () => {
    vrBtn.disabled = true;
    try {
      const session = await viewer.enterVR(navigator.xr);
      vrBtn.dataset.xr = 'immersive';
      session.addEventListener('end', () => {
        vrBtn.disabled = false;
        vrBtn.dataset.xr = 'supported';
      });
    } catch (e) {
      vrBtn.disabled = false;
      say(`Could not enter VR: ${e?.message || e}`, 'error');
    }
  });
  layoutSel.addEventListener('change', () => {
    if (layoutSel.value !== 'dual' || !viewer.openDualOutput) return viewer.setLayout?.(layoutSel.value);
    // Opened now, in the user's gesture (a pop-up blocker lets it through).
    const win = window.open('', `cad2mo-right-eye-${id}-${v}`, 'popup,width=960,height=600');
    if (!win) {
      layoutSel.value = 'single';
      viewer.setLayout('single');
      say('The browser blocked the second window: allow pop-ups for this page to use dual output.', 'error');
      return;
    }
    try {
      viewer.openDualOutput(win, () => {
        if (layoutSel.value === 'dual') layoutSel.value = 'single';
      });
      say('Dual output: the right eye is in the second window; move it to the second projector or output and double-click it for full screen.', 'ok');
    } catch (e) {
      win.close();
      layoutSel.value = 'single';
      viewer.setLayout('single');
      say(`The second window could not draw: ${e.message}`, 'error');
    }
  });
  const showMeasure = (m) => {
    const u = getUnits();
    measureOut.textContent = m.distance === null ? 'Pick the second point' : `Distance ${num(toDisplay(m.distance, 'm', u))} ${symbolOf('m', u)}`;
    measureOut.dataset.distance = m.distance === null ? '' : String(m.distance);
  };
  measureBtn.addEventListener('click', () => {
    const on = measureBtn.getAttribute('aria-pressed') !== 'true';
    measureBtn.setAttribute('aria-pressed', String(on));
    measureBtn.textContent = on ? 'Stop measuring' : 'Measure';
    viewer.setMeasuring?.(on, showMeasure);
    measureOut.textContent = on ? 'Pick two points on the model' : '';
    delete measureOut.dataset.distance;
  });
  grid.addEventListener('change', () => viewer.setGrid(grid.checked));
  viewSel.addEventListener('change', () => {
    if (viewSel.value) viewer.namedView?.(viewSel.value);
    viewSel.value = '';
  });
  transparentBox.addEventListener('change', () => viewer.setTransparent?.(transparentBox.checked));
  contactsBox.addEventListener('change', () => {
    const n = viewer.setContactsShown?.(contactsBox.checked);
    if (contactsBox.checked && !n) say('No contact points to show: run a collision check (Collision tab or a motion’s check) first', 'info');
  });
  shapesBox.addEventListener('change', () => {
    try {
      const n = viewer.setCollisionShapes?.(shapesBox.checked, shapesBox.checked && !viewer.collisionShapes ? meshes.collisionShapes() : null);
      if (shapesBox.checked && !n) say('This version has no collision shapes in its package', 'info');
    } catch (e) {
      shapesBox.checked = false;
      say(`The collision shapes could not be read: ${e.message}`, 'error');
    }
  });
  const sliders = new Map();
  const resetPose = () => {
    viewer.resetPose();
    for (const [, s] of sliders) s.reset();
    motion?.poseChanged?.();
  };
  // Joint values by the joint coordinate's Modelica name (as the drives and motions API name
  // them): the sliders' own code path, for the motion player and the IK gizmo.
  const coords = coordinates(report);
  const byElement = new Map(coords.filter((c) => c.inTree).map((c) => [c.element, c]));
  const setJoints = (values) => {
    const entries = [];
    for (const [name, value] of Object.entries(values)) {
      const c = byElement.get(name);
      if (!c || !Number.isFinite(value)) continue;
      entries.push([c.key, value]);
    }
    viewer.setCoordinates(entries);
    for (const [key, value] of entries) sliders.get(key)?.set(value);
  };
  // The planned motion as a ghost beside the simulated one (joint values by name; null hides it).
  const setGhost = (values) => {
    if (!values) return viewer.setGhost?.(null);
    const q = new Map();
    for (const [name, value] of Object.entries(values)) {
      const c = byElement.get(name);
      if (c && Number.isFinite(value)) q.set(c.key, value);
    }
    viewer.setGhost?.(q);
  };
  const currentJoints = () => {
    const out = {};
    for (const [name, c] of byElement) out[name] = viewer.q?.get(c.key) ?? c.q0;
    return out;
  };

  const tabSpec = [
    { id: 'structure', label: 'Structure', render: (p) => renderStructure(p) },
    { id: 'report', label: 'Report', render: (p) => renderReport(p) },
    { id: 'drives', label: 'Drives', render: (p) => renderDrives(p, { modelId: id, version, report, select, selected: () => selection, onSelect: (f) => listeners.add(f) }) },
    { id: 'motion', label: 'Motion', render: (p) => (motion = renderMotion(p, { modelId: id, version, versionNumber: v, report, viewer, setJoints, setGhost, currentJoints, say, stage: motionStage, drivesChanged })) },
    { id: 'results', label: 'Results', render: (p) => (results = renderResults(p, { modelId: id, versionNumber: v, viewer, say, select, stage: resultsStage })) },
    { id: 'live', label: 'Live', render: (p) => (live = renderLive(p, { modelId: id, versionNumber: v, viewer, say, stage: liveStage })) },
    { id: 'collision', label: 'Collision', render: (p) => (collision = renderCollision(p, { modelId: id, versionNumber: v, viewer, say, resetPose })) },
    {
      id: 'scene',
      label: 'Scene',
      render: (p) =>
        (scene = renderScene(p, {
          modelId: id,
          versionNumber: v,
          bodies: (report.bodies || []).map((b) => b.modelica_name),
          viewer,
          layer,
          loaded: sceneLoaded,
          select,
          onSelect: (f) => listeners.add(f),
          say,
          // The Collision tab's interferences depend on the scene.
          sceneSaved: () => collision?.reload?.(),
        })),
    },
    { id: 'diagram', label: 'Modelica diagram', render: (p) => renderDiagram(p, { modelId: id, version, report, select, stage: diagramStage }) },
  ];
  let collision = null;
  let scene = null;
  let motion = null;
  let results = null;
  let live = null;
  // A drive changed elsewhere (the motion's sizing): the Drives tab renders afresh when shown.
  const drivesChanged = () => delete t.panel('drives').dataset.rendered;
  // The motion's player, plots and sizing go under the 3D view, shown with the Motion tab.
  const motionStage = h('div', { class: 'motion-stage', hidden: true });
  // A result's player and plots likewise, shown with the Results tab (whose poses apply only then).
  const resultsStage = h('div', { class: 'motion-stage results-stage', hidden: true });
  // The live stream's numbers likewise, shown with the Live tab (whose poses apply only then).
  const liveStage = h('div', { class: 'motion-stage live-stage', hidden: true });
  // The Modelica diagram likewise, shown with its tab.
  const diagramStage = h('div', { class: 'motion-stage diagram-stage', hidden: true });
  let workspaceEl = null; // set once built; tabs() calls onChange before
  const t = tabs(tabSpec, {
    initial: tabSpec.some((x) => x.id === initialTab) ? initialTab : 'structure',
    label: 'Model details',
    onChange: (tab) => {
      motionStage.hidden = tab !== 'motion';
      resultsStage.hidden = tab !== 'results';
      liveStage.hidden = tab !== 'live';
      diagramStage.hidden = tab !== 'diagram';
      // The diagram takes the dock at full width and most of the height; the 3D view stays above.
      workspaceEl?.classList.toggle('diagram-mode', tab === 'diagram');
      // Hide before show: both tabs pose the bodies, and hiding one hands them back to the joints.
      if (tab !== 'results') results?.shown(false);
      if (tab !== 'live') live?.shown(false);
      // Collision marks in 3D belong to the tab that drew them.
      if (tab !== 'collision') collision?.shown(false);
      // The scene's gizmo belongs to its tab.
      scene?.shown(tab === 'scene');
      if (tab !== 'motion') motion?.shown?.(false);
      if (tab === 'results') results?.shown(true);
      if (tab === 'live') live?.shown(true);
      history.replaceState(null, '', `#/models/${enc(id)}/versions/${v}${tab === 'structure' ? '' : '/' + tab}`);
    },
  });

  // The workspace: the 3D view (always on screen), the side panel with the tabs, and the bottom
  // dock with the player, plots and the selection's details; both panels resize by their
  // splitters (mouse or arrow keys) and keep their sizes in localStorage.
  const view3d = h('section', { class: 'view3d', 'aria-label': '3D view' }, toolbar, stage, info);
  const side = h('section', { class: 'side', 'aria-label': 'Model details' }, t.el);
  const dock = h('section', { class: 'dock', 'aria-label': 'Player, plots and details' }, motionStage, resultsStage, liveStage, diagramStage, details);
  const workspace = h('div', { class: 'workspace model-layout' });
  const limitsNow = () => sizeLimits(window.innerWidth, window.innerHeight);
  let sideW = loadSize(localStorage, 'cad2mo.layout.side', Math.round(window.innerWidth * 0.38), limitsNow().side.min, limitsNow().side.max);
  let dockH = loadSize(localStorage, 'cad2mo.layout.dock', Math.round(window.innerHeight * 0.26), limitsNow().dock.min, limitsNow().dock.max);
  const applySizes = () => {
    const l = limitsNow();
    workspace.style.setProperty('--side-w', `${clamp(sideW, l.side.min, l.side.max)}px`);
    workspace.style.setProperty('--dock-h', `${clamp(dockH, l.dock.min, l.dock.max)}px`);
    // Wide windows: the workspace fills the window below its heading; narrow ones stack.
    const wide = window.matchMedia('(min-width: 901px)').matches;
    workspace.style.height = wide ? `${Math.max(480, window.innerHeight - workspace.getBoundingClientRect().top - window.scrollY - 8)}px` : '';
  };
  const splitV = splitter({
    orientation: 'vertical',
    label: 'Resize the side panel',
    get: () => sideW,
    set: (x) => ((sideW = clamp(x, limitsNow().side.min, limitsNow().side.max)), applySizes()),
    save: () => saveSize(localStorage, 'cad2mo.layout.side', sideW),
    sign: -1,
  });
  const splitH = splitter({
    orientation: 'horizontal',
    label: 'Resize the bottom dock',
    get: () => dockH,
    set: (x) => ((dockH = clamp(x, limitsNow().dock.min, limitsNow().dock.max)), applySizes()),
    save: () => saveSize(localStorage, 'cad2mo.layout.dock', dockH),
    sign: -1,
  });
  workspace.append(view3d, splitH, dock, splitV, side);
  workspaceEl = workspace;
  workspace.classList.toggle('diagram-mode', !diagramStage.hidden);
  fill(
    main,
    h(
      'div',
      { class: 'model-head' },
      h('p', { class: 'crumbs' }, h('a', { href: '#/models' }, 'Models'), ' / ', h('a', { href: `#/models/${enc(id)}` }, model.name), ' / ', `v${v}`),
      h('h1', {}, `${model.name} `, h('small', { class: 'muted' }, `v${v} · package ${report.package_name}`)),
    ),
    workspace,
  );
  applySizes();
  window.addEventListener('resize', applySizes);
  // Units changed in the toolbar: every number shown in the old unit is drawn again.
  const offUnits = onUnits(() => {
    delete t.panel('structure').dataset.rendered;
    if (t.panel('structure').hidden === false) {
      t.panel('structure').dataset.rendered = '1';
      renderStructure(t.panel('structure'));
    }
    motion?.unitsChanged?.();
    if (selection) fill(details, describe(report, selection));
  });


  // ---- Structure: bodies and joints, with a slider per joint coordinate.
  function renderStructure(panel) {
    const coords = coordinates(report);
    const bodyItems = report.bodies.map((b) => {
      const btn = h('button', { type: 'button', class: 'pick', dataset: { body: b.modelica_name }, onclick: () => select({ kind: 'body', name: b.modelica_name }) }, b.modelica_name);
      return h(
        'li',
        { dataset: { body: b.modelica_name } },
        h('span', { class: 'swatch', style: `background: rgb(${b.color.map((c) => Math.round(c * 255)).join(',')})`, 'aria-hidden': 'true' }),
        btn,
        h('small', { class: 'muted' }, ` ${b.cad_name} · ${num(b.mass)} kg${b.triangles ? ` · ${b.triangles} triangles` : ' · no shape'}`),
      );
    });
    const jointItems = report.joints
      .filter((j) => j.elements.length || j.emitted_as !== 'connect')
      .map((j) => {
        const btn = h('button', { type: 'button', class: 'pick', dataset: { joint: j.modelica_name }, onclick: () => select({ kind: 'joint', name: j.modelica_name }) }, j.modelica_name);
        const rows = coords.filter((c) => c.joint === j.modelica_name && c.inTree).map((c) => slider(c));
        const note = j.in_tree ? (j.in_loop ? 'in a loop: moving it opens the loop in this view' : '') : 'closes a loop (moves with the others)';
        return h(
          'li',
          { dataset: { joint: j.modelica_name } },
          btn,
          h('small', { class: 'muted' }, ` ${j.emitted_as} · ${j.base_body} → ${j.follower_body}${note ? ' · ' + note : ''}`),
          rows,
        );
      });
    fill(
      panel,
      h('h2', {}, `Joints (${jointItems.length})`),
      h('ul', { class: 'picklist joints' }, jointItems),
      h('h2', {}, `Bodies (${report.bodies.length})`),
      h('ul', { class: 'picklist bodies' }, bodyItems),
    );
    listeners.add((sel, scroll) => {
      for (const li of panel.querySelectorAll('li[data-body], li[data-joint]')) {
        const on = sel && ((sel.kind === 'body' && li.dataset.body === sel.name) || (sel.kind === 'joint' && li.dataset.joint === sel.name));
        li.classList.toggle('selected', !!on);
        li.querySelector('button.pick')?.setAttribute('aria-pressed', String(!!on));
        if (on && scroll && !panel.hidden) li.scrollIntoView({ block: 'nearest' });
      }
    });
  }

  function slider(c) {
    const si = c.kind === 'revolute' ? 'rad' : 'm';
    const u = getUnits();
    const sym = symbolOf(si, u);
    const shown = (q) => toDisplay(q, si, u);
    const start = shown(c.q0); // the CAD pose, exactly
    // The joint's limits when known (widened to hold the CAD pose), else a turn or the model's size.
    const lim = limitsOf.get(c.element);
    let lo;
    let hi;
    if (lim && Number.isFinite(lim[0]) && Number.isFinite(lim[1]) && lim[1] > lim[0]) {
      lo = Math.min(shown(lim[0]), start);
      hi = Math.max(shown(lim[1]), start);
    } else {
      const span = si === 'rad' ? shown(Math.PI) : shown(Math.max(0.05, viewer.size));
      lo = start - span;
      hi = start + span;
    }
    // step="any": the CAD pose and every typed value are reachable, not snapped to a grid; the
    // arrow keys move by a round step of the span.
    const keyStep = niceStep((hi - lo) / 400);
    const input = h('input', { type: 'range', id: `q-${c.key}`, min: String(lo), max: String(hi), step: 'any', value: String(start), dataset: { coordinate: c.key } });
    const entry = h('input', { type: 'text', inputmode: 'decimal', id: `qv-${c.key}`, class: 'q-entry', value: num(start), autocomplete: 'off', 'aria-label': `${c.element} [${sym}]` });
    const msg = h('span', { class: 'field-msg', 'aria-live': 'polite' });
    const apply = (x, fromEntry = false) => {
      input.value = String(x);
      if (!fromEntry) entry.value = num(x);
      entry.setAttribute('aria-invalid', 'false');
      msg.textContent = '';
      viewer.setCoordinate(c.key, fromDisplay(x, si, u));
      motion?.poseChanged?.();
    };
    input.addEventListener('input', () => apply(Number(input.value)));
    input.addEventListener('keydown', (e) => {
      const d = { ArrowRight: 1, ArrowUp: 1, ArrowLeft: -1, ArrowDown: -1, PageUp: 10, PageDown: -10 }[e.key];
      if (d === undefined) return;
      e.preventDefault();
      apply(clamp(Number(input.value) + d * keyStep, lo, hi));
    });
    entry.addEventListener('change', () => {
      const x = parseNumber(entry.value);
      const bad = x === null || Number.isNaN(x) ? `${c.element}: "${entry.value}" is not a number` : x < lo - 1e-9 || x > hi + 1e-9 ? `${c.element}: ${num(x)} ${sym} is outside ${num(lo)} … ${num(hi)} ${sym}` : null;
      entry.setAttribute('aria-invalid', String(!!bad));
      msg.textContent = bad || '';
      if (!bad) apply(x, true);
    });
    for (const el of [input, entry]) el.addEventListener('focus', () => select({ kind: 'joint', name: c.joint }, { scroll: false }));
    sliders.set(c.key, {
      reset: () => ((input.value = String(start)), (entry.value = num(start)), (msg.textContent = '')),
      set: (value) => {
        const x = shown(value);
        input.value = String(x);
        entry.value = num(x);
      },
    });
    return h(
      'div',
      { class: 'slider' },
      h('label', { for: input.id, title: c.element }, `${abbreviate(c.element, 40)} (${c.kind}, CAD pose ${num(start)} ${sym}${lim ? `, limits ${num(lo)} … ${num(hi)}` : ''})`),
      input,
      h('span', { class: 'q-value' }, entry, h('span', { class: 'unit' }, sym)),
      msg,
    );
  }

  // ---- Report: warnings, loops, free bodies and geometry matches, linked to the 3D view.
  function renderReport(panel) {
    const byNode = new Map();
    for (const b of report.bodies) byNode.set(b.node_id, { kind: 'body', name: b.modelica_name });
    for (const j of report.joints) byNode.set(j.node_id, { kind: 'joint', name: j.modelica_name });
    const byCad = new Map(report.bodies.map((b) => [b.cad_name, { kind: 'body', name: b.modelica_name }]));
    const link = (sel, text) =>
      sel ? h('button', { type: 'button', class: 'link', onclick: () => select(sel), 'aria-label': `Show ${sel.kind} ${sel.name} in 3D` }, text || sel.name) : text;
    const subject = (w) => {
      const m = /nodeID "([^"]+)"/.exec(w.location || '') || /nodeID "([^"]+)"/.exec(w.message);
      if (m && byNode.has(m[1])) return byNode.get(m[1]);
      const b = /body "([^"]+)"/.exec(w.message) || /body "([^"]+)"/.exec(w.location || '');
      return b ? byCad.get(b[1]) : null;
    };
    const warnings = report.warnings.map((w) =>
      h('li', {}, h('code', {}, w.code), ' ', w.message, w.location ? h('small', { class: 'muted' }, ` (${w.location})`) : null, ' ', link(subject(w), subject(w) ? 'show' : null)),
    );
    const loops = report.loops.map((l) =>
      h(
        'li',
        {},
        `${l.kind} loop closed by `,
        link({ kind: 'joint', name: l.closing_joint }),
        ': ',
        l.joints.map((j, i) => [i ? ' → ' : '', link({ kind: 'joint', name: j })]),
        h(
          'div',
          { class: 'loop-facts' },
          l.kind === 'rigid'
            ? `welds only; cut: ${l.cut}`
            : `rank ${l.rank} of ${plural(l.coordinates, 'coordinate')}, mobility ${l.mobility}; ${l.independent_equations} of ${l.closing_equations} closing equations independent; cut: ${l.cut}`,
        ),
        h('small', { class: l.redundant_emitted ? 'warn' : 'muted' }, l.why),
      ),
    );
    const free = report.free_bodies.map((b) => h('li', {}, link({ kind: 'body', name: b }), ' is connected to nothing (a free body)'));
    const matches = [];
    if (report.vrml) {
      for (const b of report.bodies) {
        for (const m of report.vrml.bodies[b.node_id] || []) {
          matches.push(
            h('tr', {}, h('th', { scope: 'row' }, link({ kind: 'body', name: b.modelica_name })), h('td', {}, m.node_path), h('td', {}, m.rule), h('td', {}, `${num(m.distance_m * 1000)} mm`), h('td', {}, `${num(m.angle_rad * DEG)}°`), h('td', {}, m.triangles)),
          );
        }
      }
    }
    const stl = report.bodies.filter((b) => b.geometry.length && !report.vrml);
    fill(
      panel,
      h('h2', {}, `Warnings (${warnings.length})`),
      warnings.length ? h('ul', { class: 'report-list' }, warnings) : h('p', { class: 'muted' }, 'None.'),
      h('h2', {}, `Loops (${loops.length})`),
      loops.length ? h('ul', { class: 'report-list' }, loops) : h('p', { class: 'muted' }, 'None: the joints form a tree.'),
      h('h2', {}, `Free bodies (${free.length})`),
      free.length ? h('ul', { class: 'report-list' }, free) : h('p', { class: 'muted' }, 'None.'),
      h('h2', {}, 'Geometry'),
      report.vrml
        ? [
            h('p', {}, `VRML files: ${report.vrml.files.join(', ')}; scale ${report.vrml.scale} m per unit; ${report.vrml.unmatched.length} unmatched shapes.`),
            h('div', { class: 'scroll' }, h('table', {}, h('thead', {}, h('tr', {}, ['Body', 'VRML node', 'Rule', 'Distance', 'Angle', 'Triangles'].map((c) => h('th', { scope: 'col' }, c)))), h('tbody', {}, matches))),
            report.vrml.unmatched.length ? h('ul', {}, report.vrml.unmatched.map((u) => h('li', {}, typeof u === 'string' ? u : JSON.stringify(u)))) : null,
          ]
        : h('ul', { class: 'report-list' }, stl.map((b) => h('li', {}, link({ kind: 'body', name: b.modelica_name }), `: ${b.geometry.join(', ')} (${b.triangles} triangles)`))),
    );
  }

  return () => {
    window.removeEventListener('resize', applySizes);
    offUnits();
    motion?.dispose?.();
    results?.dispose();
    live?.dispose();
    collision?.dispose();
    scene?.dispose();
    viewer.dispose();
    if (window.cad2moViewer === viewer) delete window.cad2moViewer;
  };
}

/**
 * A splitter between two panels: drag it, or focus it and press the arrow keys (16 px, Page keys
 * 64 px). `get`/`set` read and change the panel's size, `save` keeps it; `sign` -1 when moving
 * right/down shrinks the panel.
 */
function splitter({ orientation, label, get, set, save, sign }) {
  const vertical = orientation === 'vertical';
  const el = h('div', { class: `splitter splitter-${orientation}`, role: 'separator', tabindex: '0', 'aria-orientation': orientation, 'aria-label': label, title: label });
  el.addEventListener('pointerdown', (e) => {
    e.preventDefault();
    el.setPointerCapture(e.pointerId);
    const from = vertical ? e.clientX : e.clientY;
    const size0 = get();
    const move = (m) => set(size0 + sign * ((vertical ? m.clientX : m.clientY) - from));
    const up = () => {
      el.removeEventListener('pointermove', move);
      el.removeEventListener('pointerup', up);
      el.removeEventListener('pointercancel', up);
      save();
    };
    el.addEventListener('pointermove', move);
    el.addEventListener('pointerup', up);
    el.addEventListener('pointercancel', up);
  });
  el.addEventListener('keydown', (e) => {
    const keys = vertical ? { ArrowLeft: -16, ArrowRight: 16, PageUp: -64, PageDown: 64 } : { ArrowUp: -16, ArrowDown: 16, PageUp: -64, PageDown: 64 };
    const d = keys[e.key];
    if (d === undefined) return;
    e.preventDefault();
    set(get() + sign * d);
    save();
  });
  return el;
}

/** Stands in for the 3D view where WebGL is missing. */
function blindViewer() {
  const noop = () => {};
  return { size: 1, q: new Map(), select: noop, setCoordinate: noop, setCoordinates: noop, setBodyPoses: noop, frameNow: () => null, showGizmo: () => null, hideGizmo: noop, setSceneObjects: noop, objectWorldPose: () => null, resetPose: noop, resetView: noop, setAnaglyph: noop, setGrid: noop, setContacts: noop, contactLines: () => [], dispose: noop };
}

const mm = (v) => v.map((x) => num(x * 1000)).join(', ');

/** The selected body's or joint's data, as the conversion report has it. */
function describe(report, sel) {
  const rows = [];
  const row = (k, ...v) => rows.push(h('tr', {}, h('th', { scope: 'row' }, k), h('td', {}, ...v)));
  if (sel.kind === 'body') {
    const b = report.bodies.find((x) => x.modelica_name === sel.name);
    if (!b) return null;
    row('CAD name', b.cad_name, h('small', { class: 'muted' }, ` (nodeID ${b.node_id})`));
    if (b.subsystem.length) row('Subsystem', b.subsystem.join(' / '));
    row('Mass', `${num(b.mass)} kg`);
    row('CG (world)', `${mm(b.cg_world)} mm`);
    row('Inertia about CG', h('span', { class: 'matrix scroll' }, b.inertia_cg.map((r) => h('span', {}, r.map(num).join('  ')))), ' kg·m²');
    row('CS1 (world)', `${mm(b.cs1.position_world)} mm`);
    row('Shape', b.triangles ? `${b.triangles} triangles from ${b.geometry.join(', ') || 'VRML'}` : 'none');
    if (b.lumped.length) row('Lumped', b.lumped.join(', '));
  } else {
    const j = report.joints.find((x) => x.modelica_name === sel.name);
    if (!j) return null;
    row('CAD name', j.cad_name, h('small', { class: 'muted' }, ` (nodeID ${j.node_id})`));
    row('Emitted as', j.emitted_as, j.in_loop ? ' (in a loop)' : '', j.in_tree ? '' : ' (closes a loop)');
    row('Connects', `${j.base_body} → ${j.follower_body}`);
    for (const e of j.elements) {
      if (e.kind !== 'revolute' && e.kind !== 'prismatic') {
        row(e.modelica_name, e.kind);
        continue;
      }
      const si = e.kind === 'revolute' ? 'rad' : 'm';
      const start = `${num(toDisplay(e.initial_q, si, getUnits()))} ${symbolOf(si, getUnits())}`;
      row(e.modelica_name, `${e.kind} about (${e.axis_world.map(num).join(', ')}) through (${mm(e.origin_world)}) mm, start ${start}`);
    }
    row('Start fixed', j.start_fixed ? 'yes' : 'no (solved with the loop)');
  }
  return h('table', { class: 'details-table', 'aria-label': `Details of ${sel.kind} ${sel.name}` }, h('tbody', {}, rows));
}
