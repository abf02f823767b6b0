// Shared by the end-to-end scripts: Chromium as this machine runs it, and the 3D pixel check.
import { chromium } from 'playwright-core';
import assert from 'node:assert/strict';

/** Debian's Chromium, headless, without network chatter (the machine's network is closed). */
export function launch() {
  return chromium.launch({
    executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
    args: [
      '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync',
      '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
    ],
  });
}

/** Waits until the model view has drawn, with its meshes loaded. */
export async function waitForModel(page) {
  await page.locator('.stage canvas').waitFor();
  await page.waitForFunction(() => Number(document.querySelector('.stage')?.dataset.rendered) > 0 && window.cad2moViewer);
}

/**
 * Page-side helpers the pixel checks share, installed before the page's scripts run (call once,
 * right after the page is made): `window.e2ePixels.read(canvas)` renders the viewer and reads a
 * canvas (default: the 3D view) back at its CSS size; `window.e2ePixels.count(px, rect, box, margin)`
 * counts, every second pixel of `rect`, those that differ from the background inside `box`
 * (grown by `margin`) and outside it, with a signature of where they are.
 */
export async function installPixelProbe(page) {
  await page.addInitScript(() => {
    const bg = [0xf3, 0xf5, 0xf8];
    window.e2ePixels = {
      async read(canvas) {
        const v = window.cad2moViewer;
        await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
        v.render();
        const c = canvas || v.renderer.domElement;
        const w = c.clientWidth;
        const h = c.clientHeight;
        const ctx = Object.assign(document.createElement('canvas'), { width: w, height: h }).getContext('2d');
        ctx.drawImage(c, 0, 0, w, h);
        return { img: ctx.getImageData(0, 0, w, h).data, w, h };
      },
      drawn({ img, w }, x, y) {
        const i = (y * w + x) * 4;
        return Math.abs(img[i] - bg[0]) + Math.abs(img[i + 1] - bg[1]) + Math.abs(img[i + 2] - bg[2]) > 24;
      },
      count(px, rect, box, margin) {
        let all = 0;
        let hit = 0;
        let outside = 0;
        let stray = 0;
        let sig = 0;
        for (let y = rect.y0; y < rect.y1; y += 2) {
          for (let x = rect.x0; x < rect.x1; x += 2) {
            const inside = x >= box.x0 - margin && x <= box.x1 + margin && y >= box.y0 - margin && y <= box.y1 + margin;
            const d = this.drawn(px, x, y);
            if (inside) all++;
            else outside++;
            if (d) {
              if (inside) hit++;
              else stray++;
              sig = (sig * 31 + (x - rect.x0) * 7 + (y - rect.y0)) % 1000003;
            }
          }
        }
        return { all, hit, outside, stray, share: hit / Math.max(all, 1), sig };
      },
    };
  });
}

/**
 * Reads the 3D canvas back and counts pixels that differ from the background, inside and outside
 * the screen rectangle the model's meshes project to (the grid and world frame are hidden first
 * and shown again after). Asserts the model is drawn where it should be and nowhere else.
 */
export async function checkModelPixels(page, { hidden = 0 } = {}) {
  const grid = page.getByLabel('Grid and world frame');
  await grid.uncheck();
  const pixels = await page.evaluate(async () => {
    const v = window.cad2moViewer;
    const px = await window.e2ePixels.read();
    const { img, w, h } = px;
    const box = v.screenBox();
    const n = window.e2ePixels.count(px, { x0: 0, y0: 0, x1: w, y1: h }, box, 1);
    const [inside, insideHit, outside, outsideHit] = [n.all, n.hit, n.outside, n.stray];
    // CAD colours: pixels whose chromaticity is that of a body's colour, inside its own box.
    // Shading scales linear r, g and b alike, so r/(r+g+b) etc. of the linear values survive
    // it (the canvas holds sRGB); greys are skipped.
    const lin = (c) => (c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4);
    const chroma = (r, g, b) => {
      const l = [lin(r), lin(g), lin(b)];
      const s = l[0] + l[1] + l[2] || 1;
      return l.map((x) => x / s);
    };
    const colours = [];
    for (const b of v.report.bodies) {
      const [r, g, b2] = b.color;
      if (!v.bodies.get(b.modelica_name)?.hasMesh || Math.max(r, g, b2) - Math.min(r, g, b2) < 0.15) continue;
      const want = chroma(r, g, b2);
      const sb = v.screenBox(b.modelica_name);
      let found = 0;
      for (let y = Math.max(0, Math.floor(sb.y0)); y < Math.min(h, sb.y1); y += 1) {
        for (let x = Math.max(0, Math.floor(sb.x0)); x < Math.min(w, sb.x1); x += 1) {
          const i = (y * w + x) * 4;
          const got = chroma(img[i] / 255, img[i + 1] / 255, img[i + 2] / 255);
          if (Math.abs(got[0] - want[0]) + Math.abs(got[1] - want[1]) + Math.abs(got[2] - want[2]) < 0.1) found++;
        }
      }
      colours.push({ body: b.modelica_name, found });
    }
    return { w, h, box, inside, insideHit, outside, outsideHit, bodies: v.bodies.size, colours };
  });
  await grid.check();
  assert.ok(pixels.box.x1 - pixels.box.x0 > pixels.w * 0.2, `the model fills a fair part of the view: ${JSON.stringify(pixels)}`);
  assert.ok(pixels.insideHit / pixels.inside > 0.1, `the model's region is mostly background: ${JSON.stringify(pixels)}`);
  assert.ok(pixels.outsideHit / Math.max(pixels.outside, 1) < 0.02, `pixels drawn outside the model's region: ${JSON.stringify(pixels)}`);
  // `hidden`: how many coloured bodies the default view may hide (behind others).
  assert.ok(pixels.colours.filter((c) => c.found < 20).length <= hidden, `bodies drawn in their CAD colours: ${JSON.stringify(pixels.colours)}`);
  return pixels;
}

/** Every form control on the page has an accessible name (label, aria-label or aria-labelledby). */
export async function checkLabels(page, where) {
  const unlabelled = await page.evaluate(() =>
    [...document.querySelectorAll('input, select, textarea, button')]
      .filter((el) => el.type !== 'hidden' && !(el.labels && el.labels.length) && !el.getAttribute('aria-label') && !el.getAttribute('aria-labelledby') && !(el.tagName === 'BUTTON' && el.textContent.trim()))
      .map((el) => el.outerHTML.slice(0, 120)),
  );
  assert.deepEqual(unlabelled, [], `unlabelled controls on ${where}`);
}

/** Largest distance between where two column-major poses put a few body-fixed points. */
export function poseDistance(a, b) {
  let worst = 0;
  for (const p of [[0, 0, 0], [0.1, 0, 0], [0, 0.1, 0], [0, 0, 0.1], [0.05, -0.03, 0.08]]) {
    const at = (e) => [0, 1, 2].map((i) => e[i] * p[0] + e[4 + i] * p[1] + e[8 + i] * p[2] + e[12 + i]);
    const x = at(a);
    const y = at(b);
    worst = Math.max(worst, Math.hypot(x[0] - y[0], x[1] - y[1], x[2] - y[2]));
  }
  return worst;
}
