// The Results page (top navigation): simulation results of any Modelica model, not only the ones
// converted here (MSL's RobotR3 simulated in Dymola, say). Upload a .mat, list, open and delete
// the standalone results; an open result shows its summary, its Dymola visual shapes and frames
// in 3D animated from the shape stream with the timeline player, and the charts of searched
// variables with the CSV export (the player and charts are the Results tab's, result-kit.js).
// File shapes (RobotR3's b0.dxf … b6.dxf) are labelled boxes until the user chooses the files
// (DXF 3D faces or STL, read in the browser, not uploaded): each then draws the shapes naming it.

import { api, enc } from '../api.js';
import { h, fill, errorBox, confirmAction, num, bytes, when, plural, say } from '../ui.js';
import { resultUpload, resultTable, resultPlayer, resultCharts, deleteResult } from './result-kit.js';
import { parseShapePoses, shapesAt, streamBounds, matchShapeFiles, fileLabel } from './shapes-data.js';
import { ShapeView } from '../viewer/shapes.js';
import { parseDxfFaces } from '../viewer/dxf.js';

const LIST = '/api/results';

/**
 * @param {HTMLElement} main
 * @param {string|undefined} initialId  a result to open (#/results/ID)
 */
export async function renderStandalone(main, initialId) {
  let results = [];
  let current = null;
  let stream = null;
  let state = null;
  let view = null;
  let disposed = false;
  let opening = 0;

  const uploadBox = h('section', { class: 'results-upload', 'aria-label': 'Upload a result' });
  const listBox = h('div', { class: 'results-list-box' });
  const summaryBox = h('div', { class: 'result-summary-box' });
  const filesBox = h('div', { class: 'shape-files-box' });
  const stage = h('div', { class: 'stage shapes-stage' });
  const grid = h('input', { type: 'checkbox', id: 'shapes-grid', checked: true });
  grid.addEventListener('change', () => view?.setGrid(grid.checked));
  const toolbar = h(
    'div',
    { class: 'toolbar', role: 'toolbar', 'aria-label': '3D view' },
    h('button', { type: 'button', onclick: () => view?.resetView() }, 'Reset view'),
    h('span', { class: 'check' }, grid, h('label', { for: grid.id }, 'Grid and world frame')),
  );
  const playerBox = h('div', { class: 'player-box results-player' });
  const plotsBox = h('div', { class: 'result-plots' });
  const view3d = h('section', { class: 'view3d results-stage', 'aria-label': '3D view', hidden: true }, toolbar, stage, playerBox);

  fill(
    main,
    h('h1', {}, 'Results'),
    h('p', { class: 'muted' }, 'Simulation results of any Modelica model: the Dymola visual shapes (MSL Visualizers, the bodies’ shapes) and frames drawn in 3D, any variable plotted.'),
    h('div', { class: 'results-top' }, uploadBox, listBox),
    h('div', { class: 'model-layout' }, view3d, h('section', { class: 'side' }, summaryBox, filesBox)),
    plotsBox,
  );

  const player = resultPlayer(playerBox, {
    times: () => stream?.times,
    onTime(t) {
      if (view && stream) {
        state = shapesAt(stream, t, state);
        view.setState(state);
      }
      plots.update();
    },
  });
  const plots = resultCharts(plotsBox, { result: () => current, time: () => player.time, seek: (t) => player.seek(t), say });

  resultUpload(uploadBox, {
    url: LIST,
    hint: 'Drop a .mat file here, or press to choose one: a Dymola or OpenModelica result of any model.',
    say,
    done(created) {
      results = [...results.filter((r) => r.id !== created.id), created];
      renderList();
      open(created);
      return `${created.name}: ${plural(created.variables, 'variable')}, ${plural(created.instants, 'instant')}, ${plural(created.shapes || 0, 'shape')}, ${plural(created.frames || 0, 'frame')}.`;
    },
  });

  function renderList() {
    listBox.dataset.state = 'listed'; // the e2e run waits for it (the list loads after the page opens)
    if (!results.length) {
      fill(listBox, h('p', { class: 'muted' }, 'No results yet.'));
      return;
    }
    fill(listBox, resultTable(results, { current, open, remove }));
  }

  async function remove(r) {
    if (!(await deleteResult(r, say, confirmAction))) return;
    results = results.filter((x) => x.id !== r.id);
    if (current?.id === r.id) close();
    renderList();
  }

  function renderSummary(r, def) {
    const rows = [];
    const row = (k, ...v) => rows.push(h('tr', {}, h('th', { scope: 'row' }, k), h('td', {}, ...v)));
    row('Variables', String(r.variables));
    row('Instants', String(r.instants));
    row('Time span', `${num(r.start)} … ${num(r.stop)} s`);
    row('Precision', r.precision);
    row('File', `${bytes(r.size)}, uploaded ${when(r.created_at)}`);
    const kinds = new Map();
    for (const s of def?.shapes || []) kinds.set(s.kind, (kinds.get(s.kind) || 0) + 1);
    const kindText = kinds.size ? ` (${[...kinds].map(([k, n]) => `${n} ${k}`).join(', ')})` : '';
    row('Shapes', `${r.shapes ?? def?.shapes.length ?? 0}${kindText}`);
    row('Frames', String(r.frames ?? def?.frames.length ?? 0));
    fill(
      summaryBox,
      h('h2', {}, `Result ${r.name}`),
      h('table', { class: 'details-table result-summary', 'aria-label': `Summary of result ${r.name}` }, h('tbody', {}, rows)),
    );
  }

  /**
   * The chooser of the files a result's file shapes name (shown while some are boxes): chosen
   * DXF or STL files are read here and drawn in place of the boxes of the shapes naming them.
   */
  function renderFiles(def) {
    const named = matchShapeFiles(def.shapes, []).missing;
    if (!view || !named.length) return fill(filesBox);
    const input = h('input', { type: 'file', id: 'shape-files', multiple: true, accept: '.dxf,.stl' });
    const out = h('div', { class: 'shape-files-out', 'aria-live': 'polite' });
    input.addEventListener('change', async () => {
      const files = [...input.files];
      if (!files.length) return;
      const shown = view;
      const m = matchShapeFiles(def.shapes, files.map((f) => f.name));
      const drawn = [];
      const refused = [];
      for (const f of files) {
        const idx = m.used.get(f.name);
        if (!idx) continue;
        try {
          const geometry = await readShapeFile(f);
          const extras = await Promise.all(idx.map((k) => extraOf(def.shapes[k].name)));
          if (shown !== view) return;
          view.useFile(idx, geometry, f.name, (k) => extras[idx.indexOf(k)] !== 0);
          drawn.push(`${f.name} (${plural(idx.length, 'shape')})`);
        } catch (e) {
          refused.push(e);
        }
      }
      const left = [...new Set(def.shapes.flatMap((x, k) => (x.kind === 'file' && x.file && !view.shapes[k]?.drawnFrom ? [fileLabel(x.file)] : [])))];
      fill(
        out,
        drawn.length ? h('p', { class: 'ok', role: 'status' }, `Drawn from ${drawn.join(', ')}.`) : null,
        m.unused.length ? h('p', { class: 'warning' }, `No shape of this result names ${m.unused.join(', ')}.`) : null,
        ...refused.map((e) => errorBox(e, 'A file could not be read')),
        left.length ? h('p', { class: 'muted' }, `Still boxes: ${left.join(', ')}.`) : null,
      );
      input.value = '';
    });
    fill(
      filesBox,
      h('h3', {}, 'Shape files'),
      h('p', { class: 'muted' }, `${plural(named.length, 'file')} named by this result's shapes ${named.length === 1 ? 'is' : 'are'} drawn as labelled boxes: ${named.join(', ')}. Choose ${named.length === 1 ? 'it' : 'them'} (DXF or STL, e.g. from the Modelica library's Resources folder the shapes name) to draw the shapes; they are read in this browser, not uploaded.`),
      h('p', {}, h('label', { for: input.id }, 'Shape files (DXF or STL) '), input),
      out,
    );
  }

  /**
   * MSL's `extra` of a file shape from the result (the shape's own, else its owner's, as
   * BodyShape passes it down): non-zero scales the file by length, width and height. Absent: 0,
   * MSL's default.
   */
  async function extraOf(shapeName) {
    const owner = shapeName.split('.').slice(0, -1).join('.');
    const id = enc(current.id);
    for (const n of [`${shapeName}.extra`, owner && `${owner}.extra`].filter(Boolean)) {
      // Searched first: asking for the series of a name the result lacks is a 404.
      const found = await api(`/api/results/${id}/variables?search=${enc(n)}&limit=50`).catch(() => null);
      if (!found?.variables?.some((v) => v.name === n)) continue;
      const got = await api(`/api/results/${id}/series?name=${enc(n)}&width=10`).catch(() => null);
      const y = got?.variables?.[0]?.y?.[0];
      if (Number.isFinite(y)) return y;
    }
    return 0;
  }

    /** A chosen shape file as a three.js geometry: DXF 3D faces or STL (binary or ASCII). */
  async function readShapeFile(file) {
    if (/\.stl$/i.test(file.name)) {
      const { STLLoader } = await import('three/addons/loaders/STLLoader.js');
      const g = new STLLoader().parse(await file.arrayBuffer());
      if (!g.getAttribute('position')?.count) throw new Error(`${file.name} has no triangles`);
      return g;
    }
    const { positions } = parseDxfFaces(await file.text(), file.name);
    const { BufferGeometry, BufferAttribute } = await import('three');
    const g = new BufferGeometry();
    g.setAttribute('position', new BufferAttribute(positions, 3));
    return g;
  }

  function dropView() {
    view?.dispose();
    if (window.cad2moShapes === view) delete window.cad2moShapes;
    view = null;
    delete stage.dataset.rendered;
    fill(stage);
  }

  async function open(r) {
    const mine = ++opening;
    current = r;
    stream = null;
    state = null;
    dropView();
    history.replaceState(null, '', `#/results/${enc(r.id)}`);
    renderList();
    renderSummary(r, null);
    fill(filesBox);
    view3d.hidden = false;
    plots.clear();
    player.clear(h('p', { role: 'status' }, `Loading the shapes of ${r.name}…`));
    let def;
    let s;
    try {
      const [d, buf] = await Promise.all([
        api(`/api/results/${enc(r.id)}/shapes`),
        api(`/api/results/${enc(r.id)}/shape-poses`, { accept: 'application/octet-stream' }),
      ]);
      def = d;
      s = parseShapePoses(buf);
      if (s.shapes !== def.shapes.length || s.frames !== def.frames.length) {
        throw new Error(`the shape stream has ${s.shapes} shapes and ${s.frames} frames, the result lists ${def.shapes.length} and ${def.frames.length}`);
      }
    } catch (e) {
      if (mine === opening) player.clear(errorBox(e, 'The shapes could not be loaded'));
      return;
    }
    if (mine !== opening || disposed) return;
    renderSummary(r, def);
    stream = s;
    state = new Float64Array(s.stride);
    if (s.shapes + s.frames > 0) {
      try {
        view = new ShapeView(stage, def, r.name, streamBounds(s));
        window.cad2moShapes = view; // for the end-to-end tests and the console
      } catch (e) {
        fill(stage, errorBox(e, 'The 3D view needs WebGL, which this browser does not offer'));
      }
    } else {
      fill(stage, h('p', { class: 'warning stage-note' }, 'This result has no visual shapes or frames to draw.'));
    }
    renderFiles(def);
    plots.show();
    player.show(r, h('h3', {}, `Play ${r.name} `, h('small', { class: 'muted' }, `${num(r.stop - r.start)} s, ${plural(s.shapes, 'shape')} and ${plural(s.frames, 'frame')} drawn`)));
  }

  function close() {
    opening += 1;
    current = null;
    stream = null;
    player.clear();
    plots.clear();
    dropView();
    fill(summaryBox);
    fill(filesBox);
    view3d.hidden = true;
    history.replaceState(null, '', '#/results');
  }

  fill(listBox, h('p', { class: 'muted' }, 'Loading the results…'));
  let listed = true;
  try {
    results = await api(LIST);
  } catch (e) {
    fill(listBox, errorBox(e, 'The results could not be listed'));
    results = [];
    listed = false;
  }
  if (listed) {
    renderList();
    const first = initialId && results.find((r) => r.id === initialId);
    if (first) open(first);
    else if (initialId) say(`There is no result ${initialId}.`, 'error');
  }

  return () => {
    disposed = true;
    player.stop();
    plots.dispose();
    dropView();
  };
}
