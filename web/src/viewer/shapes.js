// The 3D view of a standalone result: the Dymola visual shapes of any Modelica model drawn as
// primitives in their colours (box, cylinder, sphere, cone; a labelled small box for file and
// other shapes until the user supplies the files: DXF 3D faces or STL, drawn in the shape's
// frame scaled by length, width and height) and its frames as small axis triads, posed from the shape stream. The same
// style as the model viewer: light background, hemisphere and two directional lights, a grid
// normal to "up" (+y, MSL's default gravity along −y), orbit controls; renders on demand.

import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { BACKGROUND, niceStep, litScene } from './viewer.js';
import { shapeMatrix, shortName, fileLabel } from '../views/shapes-data.js';

/** Unit primitives along +x from 0 to 1 (see shapeMatrix). */
function unitGeometries() {
  const box = new THREE.BoxGeometry(1, 1, 1).translate(0.5, 0, 0);
  const cyl = new THREE.CylinderGeometry(0.5, 0.5, 1, 32).rotateZ(-Math.PI / 2).translate(0.5, 0, 0);
  const cone = new THREE.ConeGeometry(0.5, 1, 32).rotateZ(-Math.PI / 2).translate(0.5, 0, 0);
  const sphere = new THREE.SphereGeometry(0.5, 32, 16).translate(0.5, 0, 0);
  return { box, cylinder: cyl, pipecylinder: cyl, cone, sphere, file: box, other: box };
}

/** A text sprite (the file path of a file shape), sized in world units by `height`. */
function label(text, height) {
  const font = 28;
  const c = document.createElement('canvas');
  const ctx = c.getContext('2d');
  ctx.font = `${font}px sans-serif`;
  c.width = Math.ceil(ctx.measureText(text).width) + 12;
  c.height = font + 12;
  ctx.font = `${font}px sans-serif`;
  ctx.fillStyle = 'rgba(255,255,255,0.8)';
  ctx.fillRect(0, 0, c.width, c.height);
  ctx.fillStyle = '#222';
  ctx.textBaseline = 'middle';
  ctx.fillText(text, 6, c.height / 2);
  const tex = new THREE.CanvasTexture(c);
  tex.colorSpace = THREE.SRGBColorSpace;
  const s = new THREE.Sprite(new THREE.SpriteMaterial({ map: tex, depthTest: false, transparent: true }));
  s.scale.set((height * c.width) / c.height, height, 1);
  s.renderOrder = 2;
  return s;
}

export class ShapeView {
  /**
   * @param {HTMLElement} host  element the canvas goes into (sized by CSS)
   * @param {{shapes: object[], frames: string[]}} def  GET /api/results/{id}/shapes
   * @param {string} title  for the canvas's accessible name
   * @param {{min: number[], max: number[]}|null} bounds  what the whole result occupies (streamBounds)
   */
  constructor(host, def, title, bounds) {
    this.bounds = bounds;
    this.host = host;
    this.def = def;
    this.renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
    this.renderer.setClearColor(BACKGROUND);
    const canvas = this.renderer.domElement;
    canvas.tabIndex = 0;
    canvas.setAttribute('role', 'img');
    canvas.setAttribute('aria-label', `3D view of ${title}: drag or Shift+arrow keys to orbit, right-drag or arrow keys to pan, wheel to zoom`);
    canvas.classList.add('viewer-canvas');
    host.append(canvas);

    this.scene = litScene();
    this.up = new THREE.Vector3(0, 1, 0);

    const geo = unitGeometries();
    /** @type {{name: string, kind: string, color: number[], mesh: THREE.Mesh, label: THREE.Sprite|null}[]} */
    this.shapes = def.shapes.map((s) => {
      const [r, g, b] = s.color || [160, 160, 160];
      const mat = new THREE.MeshStandardMaterial({
        color: new THREE.Color().setRGB(r / 255, g / 255, b / 255, THREE.SRGBColorSpace),
        roughness: 0.75 - 0.5 * (s.specular || 0),
        metalness: 0.05,
        side: THREE.DoubleSide,
      });
      const mesh = new THREE.Mesh(geo[s.kind] || geo.other, mat);
      mesh.matrixAutoUpdate = false;
      mesh.name = s.name;
      this.scene.add(mesh);
      return { name: s.name, kind: s.kind, color: [r, g, b], mesh, label: null, file: s.file };
    });
    this.frames = def.frames.map((name) => {
      const axes = new THREE.AxesHelper(1);
      axes.name = name;
      axes.material.depthTest = false;
      axes.renderOrder = 1;
      this.scene.add(axes);
      return { name, axes };
    });

    this.camera = new THREE.PerspectiveCamera(40, 1, 0.001, 1000);
    this.camera.up.copy(this.up);
    this.controls = new OrbitControls(this.camera, canvas);
    this.controls.listenToKeyEvents(canvas);
    this.controls.addEventListener('change', () => this.invalidate());
    this.grid = null;
    this.framed = false;
    this.resize = new ResizeObserver(() => this.fit());
    this.resize.observe(host);
    this.fit();
  }

  /**
   * Poses every shape and frame from the stream's state at one time (shapesAt), and the first
   * time fits the camera, grid and triad size to what is drawn.
   */
  setState(v) {
    const m = new THREE.Matrix4();
    const e = new Array(16);
    this.last = v;
    this.def.shapes.forEach((s, k) => {
      shapeMatrix(this.shapes[k].matrixKind || s.kind, v, 12 * k, e);
      m.fromArray(e);
      const entry = this.shapes[k];
      entry.mesh.matrix.copy(m);
      entry.mesh.matrixWorldNeedsUpdate = true;
    });
    const base = 12 * this.shapes.length;
    this.frames.forEach((f, k) => {
      const o = base + 7 * k;
      f.axes.position.set(v[o], v[o + 1], v[o + 2]);
      f.axes.quaternion.set(v[o + 3], v[o + 4], v[o + 5], v[o + 6]);
    });
    if (!this.framed) this.frameAll();
    this.shapes.forEach((entry, k) => entry.label?.position.set(v[12 * k], v[12 * k + 1], v[12 * k + 2]));
    this.invalidate();
  }

  /** Camera, grid, triads and labels sized to the current bounds. */
  frameAll() {
    this.framed = true;
    this.scene.updateMatrixWorld(true);
    const box = new THREE.Box3();
    if (this.bounds) box.set(new THREE.Vector3(...this.bounds.min), new THREE.Vector3(...this.bounds.max));
    for (const s of this.shapes) box.expandByObject(s.mesh);
    for (const f of this.frames) box.expandByPoint(f.axes.position);
    if (box.isEmpty() || !Number.isFinite(box.min.x)) box.set(new THREE.Vector3(-0.5, -0.5, -0.5), new THREE.Vector3(0.5, 0.5, 0.5));
    const size = Math.max(box.getSize(new THREE.Vector3()).length(), 0.05);
    this.box = box;
    this.size = size;
    for (const f of this.frames) f.axes.scale.setScalar(size * 0.06);
    this.shapes.forEach((s) => {
      if ((s.kind !== 'file' && s.kind !== 'other') || s.drawnFrom) return;
      s.label = label(s.file ? fileLabel(s.file) : shortName(s.name), size * 0.03);
      s.label.center.set(0, 0);
      this.scene.add(s.label);
    });
    const step = niceStep(size / 10);
    const extent = Math.ceil(size / step) * step;
    this.grid = new THREE.GridHelper(extent * 2, Math.round((extent * 2) / step), 0x9aa4b0, 0xd0d6de);
    const centre = box.getCenter(new THREE.Vector3());
    this.grid.position.set(centre.x, Math.min(0, box.min.y), centre.z);
    this.scene.add(this.grid);
    this.worldAxes = new THREE.AxesHelper(size * 0.15);
    this.scene.add(this.worldAxes);
    this.camera.near = size / 1000;
    this.camera.far = size * 100;
    this.resetView();
  }

  resetView() {
    const box = this.box || new THREE.Box3(new THREE.Vector3(-0.5, -0.5, -0.5), new THREE.Vector3(0.5, 0.5, 0.5));
    const centre = box.getCenter(new THREE.Vector3());
    const d = (this.size || 1) * 1.2;
    this.controls.target.copy(centre);
    this.camera.position.copy(centre).add(new THREE.Vector3(0.9, 0.6, 1.3).normalize().multiplyScalar(d));
    this.camera.updateProjectionMatrix();
    this.controls.update();
    this.invalidate();
  }

  setGrid(on) {
    if (this.grid) this.grid.visible = on;
    if (this.worldAxes) this.worldAxes.visible = on;
    this.invalidate();
  }

  fit() {
    const w = this.host.clientWidth || 1;
    const h = this.host.clientHeight || 1;
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.invalidate();
  }

  invalidate() {
    if (this.pending) return;
    this.pending = requestAnimationFrame(() => {
      this.pending = 0;
      this.render();
    });
  }

  render() {
    this.renderer.render(this.scene, this.camera);
    this.host.dataset.rendered = String(Number(this.host.dataset.rendered || 0) + 1);
  }

  /**
   * Draws the file shapes `indices` with `geometry` (the file's coordinates, in the shape's
   * frame) instead of their labelled box; `from` names the file (inspect() reports it).
   * `scaled(k)`: whether shape k scales the file by its length, width and height (MSL's
   * extra ≠ 0); otherwise the file's coordinates are metres as they stand (extra = 0, the default).
   */
  useFile(indices, geometry, from, scaled = () => false) {
    if (!geometry.getAttribute('normal')) geometry.computeVertexNormals();
    for (const k of indices) {
      const s = this.shapes[k];
      if (!s) continue;
      s.mesh.geometry = geometry;
      s.drawnFrom = from;
      s.matrixKind = scaled(k) ? 'file' : 'file-raw';
      if (s.label) {
        this.scene.remove(s.label);
        s.label.material.map?.dispose();
        s.label.material.dispose();
        s.label = null;
      }
    }
    if (this.last) this.setState(this.last);
    this.invalidate();
  }

  /** What the scene draws now, for the end-to-end tests: world matrices, bounds and colours. */
  inspect() {
    this.scene.updateMatrixWorld(true);
    const c = new THREE.Color();
    return {
      shapes: this.shapes.map((s) => {
        const b = new THREE.Box3().expandByObject(s.mesh);
        c.copy(s.mesh.material.color);
        return {
          name: s.name,
          kind: s.kind,
          matrix: Array.from(s.mesh.matrixWorld.elements),
          min: b.min.toArray(),
          max: b.max.toArray(),
          color: s.color,
          hex: c.getHexString(THREE.SRGBColorSpace),
          visible: s.mesh.visible,
          from: s.drawnFrom || null,
          scaled: s.drawnFrom ? s.matrixKind === 'file' : null,
          vertices: s.mesh.geometry.getAttribute('position').count,
        };
      }),
      frames: this.frames.map((f) => ({ name: f.name, position: f.axes.position.toArray(), quaternion: f.axes.quaternion.toArray() })),
    };
  }

  dispose() {
    cancelAnimationFrame(this.pending);
    this.resize.disconnect();
    this.controls.dispose();
    this.scene.traverse((o) => {
      o.geometry?.dispose?.();
      for (const m of [].concat(o.material || [])) {
        m.map?.dispose();
        m.dispose();
      }
    });
    this.renderer.dispose();
    this.renderer.domElement.remove();
  }
}
