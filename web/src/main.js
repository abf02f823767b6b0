// The single-page app: a hash router over five screens. Every screen gets its data from the API.

import './style.css';
import { h, fill, errorBox, clearStaleStatus } from './ui.js';
import { renderModels, renderModel } from './views/models.js';
import { renderLibrary } from './views/library.js';
import { renderSettings } from './views/settings.js';

const routes = [
  [/^#?\/?$/, () => renderModels],
  [/^#\/models\/?$/, () => renderModels],
  [/^#\/models\/([^/]+)\/?$/, (m) => (main) => renderModel(main, decodeURIComponent(m[1]))],
  [/^#\/models\/([^/]+)\/versions\/(\d+)(?:\/(\w+))?\/?$/, (m) => async (main) => {
    // three.js and the viewer load only when a model is opened.
    const { renderViewer } = await import('./views/model.js');
    return renderViewer(main, decodeURIComponent(m[1]), Number(m[2]), m[3]);
  }],
  [/^#\/results(?:\/([^/]+))?\/?$/, (m) => async (main) => {
    // three.js loads only when the page is opened.
    const { renderStandalone } = await import('./views/standalone.js');
    return renderStandalone(main, m[1] ? decodeURIComponent(m[1]) : undefined);
  }],
  [/^#\/library\/?$/, () => renderLibrary],
  [/^#\/settings\/?$/, () => renderSettings],
];

let cleanup = null;
let generation = 0;

async function route() {
  const hash = location.hash || '#/models';
  const main = document.getElementById('main');
  cleanup?.();
  cleanup = null;
  // An error said on the previous page (e.g. a first contact of another model) does not stay.
  clearStaleStatus();
  generation += 1;
  const mine = generation;
  for (const a of document.querySelectorAll('[data-nav]')) {
    const on = hash.startsWith(`#/${a.dataset.nav}`) || (a.dataset.nav === 'models' && hash === '#/');
    if (on) a.setAttribute('aria-current', 'page');
    else a.removeAttribute('aria-current');
  }
  const found = routes.find(([re]) => re.test(hash));
  if (!found) {
    fill(main, h('h1', {}, 'Not found'), h('p', {}, `Nothing at ${hash}. `, h('a', { href: '#/models' }, 'Go to the models.')));
    return;
  }
  const view = found[1](found[0].exec(hash));
  try {
    const c = await view(main);
    if (mine === generation) cleanup = typeof c === 'function' ? c : null;
    else if (typeof c === 'function') c();
  } catch (e) {
    if (mine === generation) fill(main, errorBox(e, 'This page could not be shown'));
  }
}

window.addEventListener('hashchange', () => {
  route();
  document.getElementById('main')?.focus({ preventScroll: true });
});
route();
