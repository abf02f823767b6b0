// The 3D view (three.js): every body's mesh in its CAD colour at its pose, joint axes as arrows,
// the world frame and a ground grid, orbit/pan/zoom, picking, a red-cyan anaglyph mode, and
// poses from the joint coordinates (kinematics.js). Renders on demand, not in a loop (in a WebXR
// headset, every frame the session asks for: enterVR).

import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { AnaglyphEffect } from 'three/addons/effects/AnaglyphEffect.js';
import { TransformControls } from 'three/addons/controls/TransformControls.js';
import { bodyDeltas, frameMatrix } from './kinematics.js';
import { poseAt } from '../views/scene-data.js';
import { xrPlacement } from './xr-data.js';
import { eyeSeparation, eyeCamera } from './stereo-data.js';

/** A scene with the viewers' lights: sky and ground, a sun, a fill light from below behind. */
export function litScene() {
  const scene = new THREE.Scene();
  scene.add(new THREE.HemisphereLight(0xffffff, 0x667788, 2.2));
  const sun = new THREE.DirectionalLight(0xffffff, 1.6);
  sun.position.set(1, 2, 1.5);
  scene.add(sun);
  const fill = new THREE.DirectionalLight(0xffffff, 0.6);
  fill.position.set(-1.5, -0.5, -1);
  scene.add(fill);
  return scene;
}

export const BACKGROUND = 0xf3f5f8;
const HIGHLIGHT = new THREE.Color(0xff9900);
const CONTACT = new THREE.Color(0xe01010); // bodies of a colliding pair
const CONTACT_LINE = 0x00b050; // closest-point lines (green: unlike the red tint of the pair)
const JOINT_COLORS = { revolute: 0xd03030, prismatic: 0x7030c0 };
const SCENE_COLOR = [0.62, 0.66, 0.72]; // scene objects without a colour of their own
/** Metres per unit of a scene mesh's file (the object's `unit`). */
export const MESH_UNITS = { m: 1, mm: 0.001, cm: 0.01, in: 0.0254 };

export class Viewer {
  /**
   * @param {HTMLElement} host  element the canvas goes into (sized by CSS)
   * @param {object} report     the conversion report
   * @param {Map<string, THREE.BufferGeometry>} meshes  body modelica_name → geometry in CS1, metres
   * @param {(sel: {kind: 'body'|'joint', name: string} | null) => void} onPick
   */
  constructor(host, report, meshes, onPick) {
    this.host = host;
    this.report = report;
    this.onPick = onPick;
    this.q = new Map();
    this.renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
    this.renderer.setClearColor(BACKGROUND);
    const canvas = this.renderer.domElement;
    canvas.tabIndex = 0;
    canvas.setAttribute('role', 'img');
    canvas.setAttribute(
      'aria-label',
      `3D view of ${report.model_name}: drag or Shift+arrow keys to orbit, right-drag or arrow keys to pan, wheel or + and - to zoom, click a body or joint to select it`,
    );
    canvas.classList.add('viewer-canvas');
    host.append(canvas);

    this.scene = litScene();

    this.bodies = new Map(); // name → {group, cad: Matrix4, materials}
    this.joints = new Map(); // name → {group, arrows}
    this.build(meshes);
    // Scene objects (issue 29): world objects under this group, attached ones in their body's group.
    this.sceneRoot = new THREE.Group();
    this.sceneRoot.name = 'scene-objects';
    this.scene.add(this.sceneRoot);
    this.sceneObjects = new Map(); // name → {mesh, parent, spec, scale}

    this.camera = new THREE.PerspectiveCamera(40, 1, this.size / 1000, this.size * 100);
    this.camera.up.copy(this.up);
    this.controls = new OrbitControls(this.camera, canvas);
    this.controls.listenToKeyEvents(canvas);
    this.controls.keyPanSpeed = 12;
    this.controls.addEventListener('change', () => this.invalidate());
    canvas.addEventListener('keydown', (e) => {
      const f = { '+': 0.85, '=': 0.85, '-': 1 / 0.85, _: 1 / 0.85 }[e.key];
      if (!f) return;
      e.preventDefault();
      this.camera.position.sub(this.controls.target).multiplyScalar(f).add(this.controls.target);
      this.controls.update();
    });
    this.anaglyph = null;
    this.eyes = {}; // the stereo eyes' reused cameras (stereo-data.js eyeCamera)
    this.resetView();

    this.resize = new ResizeObserver(() => this.fit());
    this.resize.observe(host);
    this.fit();
    this.installPicking(canvas);
  }

  /** Builds bodies, joint arrows, world frame and grid. */
  build(meshes) {
    const r = this.report;
    const g = r.options?.gravity || [0, 0, -9.81];
    this.up = new THREE.Vector3(-g[0], -g[1], -g[2]);
    if (this.up.lengthSq() === 0) this.up.set(0, 0, 1);
    this.up.normalize();

    const box = new THREE.Box3();
    for (const b of r.bodies) {
      const group = new THREE.Group();
      group.matrixAutoUpdate = false;
      group.name = b.modelica_name;
      const cad = frameMatrix(b.cs1);
      const color = srgb(b.color);
      const materials = [];
      const geom = meshes.get(b.modelica_name);
      if (geom) {
        const mat = new THREE.MeshStandardMaterial({ color, roughness: 0.65, metalness: 0.05, side: THREE.DoubleSide });
        materials.push(mat);
        const mesh = new THREE.Mesh(geom, mat);
        mesh.userData.pick = { kind: 'body', name: b.modelica_name };
        group.add(mesh);
      }
      this.scene.add(group);
      this.bodies.set(b.modelica_name, { group, cad, materials, hasMesh: !!geom, cg: new THREE.Vector3(...b.cg_world) });
      group.matrix.copy(cad);
      group.updateMatrixWorld(true);
      if (geom) box.expandByObject(group);
      else box.expandByPoint(new THREE.Vector3(...b.cg_world));
    }
    for (const j of r.joints) for (const e of j.elements) if (e.origin_world) box.expandByPoint(new THREE.Vector3(...e.origin_world));
    if (box.isEmpty()) box.set(new THREE.Vector3(-0.5, -0.5, -0.5), new THREE.Vector3(0.5, 0.5, 0.5));
    this.box = box;
    this.size = Math.max(box.getSize(new THREE.Vector3()).length(), 1e-3);

    // Bodies without a mesh: a small sphere at the CG, so they can be seen and picked.
    const dot = this.size * 0.015;
    for (const b of r.bodies) {
      const entry = this.bodies.get(b.modelica_name);
      if (entry.hasMesh || !(b.mass > 0)) continue;
      const mat = new THREE.MeshStandardMaterial({ color: srgb(b.color), roughness: 0.5 });
      entry.materials.push(mat);
      const s = new THREE.Mesh(new THREE.SphereGeometry(dot, 16, 12), mat);
      s.position.copy(new THREE.Vector3(...b.cg_world).applyMatrix4(entry.cad.clone().invert()));
      s.userData.pick = { kind: 'body', name: b.modelica_name };
      entry.group.add(s);
    }

    // Joint axes: one arrow per movable element, carried by the base side.
    const len = this.size * 0.12;
    for (const j of r.joints) {
      const group = new THREE.Group();
      group.matrixAutoUpdate = false;
      const arrows = [];
      for (const e of j.elements) {
        const a = new THREE.Vector3(...(e.axis_world || [0, 0, 0]));
        if (a.lengthSq() < 0.5 || !e.origin_world) continue;
        const color = JOINT_COLORS[e.kind] || 0x333333;
        const origin = new THREE.Vector3(...e.origin_world).addScaledVector(a.clone().normalize(), -len * 0.35);
        const arrow = new THREE.ArrowHelper(a.normalize(), origin, len, color, len * 0.28, len * 0.14);
        // Axes stay visible inside the bodies they sit in: drawn last, without depth test.
        for (const m of [arrow.line.material, arrow.cone.material]) {
          m.depthTest = false;
          m.transparent = true;
        }
        arrow.renderOrder = 10;
        arrow.line.renderOrder = 10;
        arrow.cone.renderOrder = 10;
        arrow.traverse((o) => (o.userData.pick = { kind: 'joint', name: j.modelica_name }));
        arrow.userData.color = color;
        arrows.push(arrow);
        group.add(arrow);
      }
      if (!arrows.length) continue;
      this.scene.add(group);
      this.joints.set(j.modelica_name, { group, arrows, base: j.base_body });
    }

    // World frame at the origin and a grid under the model, normal to "up" (against gravity).
    this.axes = new THREE.AxesHelper(this.size * 0.2);
    this.scene.add(this.axes);
    const step = niceStep(this.size / 10);
    const extent = Math.ceil((this.size * 1.5) / step) * step;
    this.grid = new THREE.GridHelper(extent * 2, Math.round((extent * 2) / step), 0x9aa4b0, 0xd0d6de);
    this.grid.quaternion.setFromUnitVectors(new THREE.Vector3(0, 1, 0), this.up);
    const centre = box.getCenter(new THREE.Vector3());
    let low = Infinity;
    for (const c of corners(box)) low = Math.min(low, c.dot(this.up));
    this.grid.position.copy(centre.clone().addScaledVector(this.up, low - centre.dot(this.up)));
    this.scene.add(this.grid);
    this.applyPose();
  }

  /** Poses every body and joint arrow for the current joint values. */
  applyPose() {
    const deltas = bodyDeltas(this.report, this.q);
    // Bodies posed by a result (setBodyPoses) override the joints' pose: their delta is then
    // pose · cad⁻¹, which also carries the joint arrows on them.
    for (const [name, m] of this.posed || []) {
      const b = this.bodies.get(name);
      if (b) deltas.set(name, m.clone().multiply(b.cad.clone().invert()));
    }
    this.deltas = deltas;
    for (const [name, b] of this.bodies) {
      const m = this.posed?.get(name);
      if (m) b.group.matrix.copy(m);
      else b.group.matrix.multiplyMatrices(deltas.get(name) || new THREE.Matrix4(), b.cad);
      b.group.matrixWorldNeedsUpdate = true;
    }
    for (const [, j] of this.joints) {
      j.group.matrix.copy(deltas.get(j.base) || new THREE.Matrix4());
      j.group.matrixWorldNeedsUpdate = true;
    }
    this.invalidate();
  }

  /**
   * Places bodies at world poses of a simulation result: `names[k]`'s CS1 frame at position
   * poses[7k..7k+2], rotation quaternion (x, y, z, w) poses[7k+3..7k+6] (body → world). Bodies
   * not named stay where the joint values put them. `null` hands every body back to the joints.
   */
  setBodyPoses(names, poses) {
    if (!names) {
      this.posed = null;
      this.applyPose();
      return;
    }
    this.posed ||= new Map();
    const p = new THREE.Vector3();
    const q = new THREE.Quaternion();
    const one = new THREE.Vector3(1, 1, 1);
    names.forEach((name, k) => {
      if (!this.bodies.has(name)) return;
      const o = 7 * k;
      p.set(poses[o], poses[o + 1], poses[o + 2]);
      q.set(poses[o + 3], poses[o + 4], poses[o + 5], poses[o + 6]).normalize();
      let m = this.posed.get(name);
      if (!m) this.posed.set(name, (m = new THREE.Matrix4()));
      m.compose(p, q, one);
    });
    this.applyPose();
  }

  setCoordinate(key, value) {
    this.q.set(key, value);
    this.applyPose();
  }

  /** Sets several coordinates (Map or [key, value] pairs) and poses once. */
  setCoordinates(entries) {
    for (const [k, v] of entries) this.q.set(k, v);
    this.applyPose();
  }

  /**
   * A semi-transparent second copy of the model at the joint values `q` (Map coordinate key →
   * value), e.g. the planned motion beside the simulated one; `null` removes it. The copy shares
   * the meshes' geometry and is not pickable.
   */
  setGhost(q) {
    if (!q) {
      if (this.ghost) {
        for (const g of this.ghost.values()) this.scene.remove(g);
        this.ghostMaterial.dispose();
        this.ghost = null;
        this.invalidate();
      }
      return;
    }
    if (!this.ghost) {
      this.ghost = new Map();
      this.ghostMaterial = new THREE.MeshBasicMaterial({ color: 0x2f6fd0, transparent: true, opacity: 0.3, depthWrite: false, side: THREE.DoubleSide });
      for (const [name, b] of this.bodies) {
        if (!b.hasMesh) continue;
        const g = new THREE.Group();
        g.matrixAutoUpdate = false;
        g.name = `ghost:${name}`;
        for (const child of b.group.children) {
          if (!child.isMesh) continue;
          const m = new THREE.Mesh(child.geometry, this.ghostMaterial);
          m.renderOrder = 5;
          g.add(m);
        }
        this.scene.add(g);
        this.ghost.set(name, g);
      }
    }
    const deltas = bodyDeltas(this.report, q);
    for (const [name, g] of this.ghost) {
      g.matrix.multiplyMatrices(deltas.get(name) || new THREE.Matrix4(), this.bodies.get(name).cad);
      g.matrixWorldNeedsUpdate = true;
    }
    this.invalidate();
  }

  resetPose() {
    this.q.clear();
    this.applyPose();
  }

  /**
   * The world matrix now of a frame given at the CAD pose (`position`, row-major `rotation`
   * frame → world) on body `body`: the body's delta times the CAD-pose matrix.
   */
  frameNow(frame) {
    const m0 = new THREE.Matrix4();
    const r = frame.rotation || [[1, 0, 0], [0, 1, 0], [0, 0, 1]];
    m0.set(r[0][0], r[0][1], r[0][2], frame.position[0], r[1][0], r[1][1], r[1][2], frame.position[1], r[2][0], r[2][1], r[2][2], frame.position[2], 0, 0, 0, 1);
    const d = this.deltas?.get(frame.body) || new THREE.Matrix4();
    return d.clone().multiply(m0);
  }

  /**
   * A translate/rotate gizmo (three.js TransformControls) at world matrix `m`. `onDrag(matrix)`
   * runs while it is dragged, `onEnd(matrix)` when released. Returns the gizmo's handle
   * {setPose(m), setMode(mode), matrix(), dispose()}.
   */
  showGizmo(m, { onDrag, onEnd } = {}) {
    this.hideGizmo();
    const target = new THREE.Object3D();
    m.decompose(target.position, target.quaternion, target.scale);
    target.scale.set(1, 1, 1);
    this.scene.add(target);
    const tc = new TransformControls(this.camera, this.renderer.domElement);
    tc.setSize(0.9);
    tc.attach(target);
    const helper = tc.getHelper();
    this.scene.add(helper);
    const matrix = () => {
      target.updateMatrix();
      return target.matrix.clone();
    };
    tc.addEventListener('change', () => this.invalidate());
    tc.addEventListener('dragging-changed', (e) => {
      this.controls.enabled = !e.value;
      if (!e.value) onEnd?.(matrix());
    });
    tc.addEventListener('objectChange', () => onDrag?.(matrix()));
    const handle = {
      controls: tc,
      target,
      setPose: (p) => {
        if (tc.dragging) return;
        p.decompose(target.position, target.quaternion, target.scale);
        target.scale.set(1, 1, 1);
        this.invalidate();
      },
      setMode: (mode) => {
        tc.setMode(mode);
        this.invalidate();
      },
      matrix,
      dispose: () => {
        tc.detach();
        this.scene.remove(helper);
        this.scene.remove(target);
        tc.dispose();
        this.controls.enabled = true;
        if (this.gizmo === handle) this.gizmo = null;
        this.invalidate();
      },
    };
    this.gizmo = handle;
    this.invalidate();
    return handle;
  }

  hideGizmo() {
    this.gizmo?.dispose();
  }

  // ------------------------------------------------------------ scene objects (issue 29)

  /**
   * Draws the scene's objects (the API's form: shape, position, rotation rows, colour, visible,
   * attached_to) with the model: primitives as three.js geometries in their own frames
   * (cylinders and capsules along z, a plane as its z = 0 surface), mesh objects from
   * `meshes` (mesh name → geometry in the file's units, scaled by the object's unit; a mesh not
   * loaded yet is drawn as a small wire box). A world object sits in the world; an attached one
   * in its body's frame_a (CS1), so it moves with the body whatever poses it (joint values,
   * results, the live view). Replaces what was drawn before.
   */
  setSceneObjects(objects, meshes = new Map()) {
    this.clearSceneObjects();
    for (const o of objects) {
      const own = sceneGeometry(o.shape, this.size);
      const file = o.shape.kind === 'mesh' ? meshes.get(o.shape.mesh) : null;
      const geom = own || file || new THREE.BoxGeometry(this.size * 0.05, this.size * 0.05, this.size * 0.05);
      const color = srgb(o.color || SCENE_COLOR);
      const plane = o.shape.kind === 'plane';
      const mat = new THREE.MeshStandardMaterial({
        color,
        roughness: 0.7,
        metalness: 0.05,
        side: THREE.DoubleSide,
        wireframe: !own && !file,
        transparent: plane,
        opacity: plane ? 0.55 : 1,
        depthWrite: !plane,
      });
      const mesh = new THREE.Mesh(geom, mat);
      mesh.name = `scene:${o.name}`;
      mesh.matrixAutoUpdate = false;
      mesh.userData.pick = { kind: 'object', name: o.name };
      mesh.userData.ownGeometry = !file;
      mesh.visible = o.visible !== false;
      const body = o.attached_to ? this.bodies.get(o.attached_to) : null;
      const parent = body ? body.group : this.sceneRoot;
      parent.add(mesh);
      const scale = file ? MESH_UNITS[o.shape.unit || 'm'] || 1 : 1;
      const entry = { mesh, parent, spec: o, scale };
      this.sceneObjects.set(o.name, entry);
      const p = poseAt(o, this.sceneTime || 0);
      this.placeObject(entry, p.position, p.rotation);
    }
    this.paintBodies();
    this.invalidate();
  }

  clearSceneObjects() {
    for (const o of this.sceneObjects.values()) {
      o.parent.remove(o.mesh);
      if (o.mesh.userData.ownGeometry) o.mesh.geometry.dispose();
      o.mesh.material.dispose();
    }
    this.sceneObjects.clear();
    this.invalidate();
  }

  placeObject(entry, position, rotation) {
    entry.mesh.matrix.copy(poseMatrix(position, rotation));
    if (entry.scale !== 1) entry.mesh.matrix.scale(new THREE.Vector3(entry.scale, entry.scale, entry.scale));
    entry.mesh.matrixWorldNeedsUpdate = true;
  }

  /** Moves one drawn object to a new pose (its own frame: world, or its body's CS1). */
  setSceneObjectPose(name, position, rotation) {
    const e = this.sceneObjects.get(name);
    if (!e) return;
    e.spec = { ...e.spec, position, rotation };
    this.placeObject(e, position, rotation);
    this.invalidate();
  }

  /**
   * The time (s) of the motion or result shown: moving objects go where their prescribed motion
   * puts them then (0: their pose at the start, as the Scene tab edits it).
   */
  setSceneTime(t) {
    this.sceneTime = t;
    let moved = false;
    for (const e of this.sceneObjects.values()) {
      if (e.spec.kind !== 'moving') continue;
      const p = poseAt(e.spec, t);
      this.placeObject(e, p.position, p.rotation);
      moved = true;
    }
    if (moved) this.invalidate();
  }

  setSceneObjectVisible(name, on) {
    const e = this.sceneObjects.get(name);
    if (e) e.mesh.visible = !!on;
    this.invalidate();
  }

  /** The world matrix of the frame an object's pose is given in (identity, or its body's CS1 now). */
  objectParentMatrix(name) {
    const e = this.sceneObjects.get(name);
    if (!e || e.parent === this.sceneRoot) return new THREE.Matrix4();
    e.parent.updateMatrixWorld(true);
    return e.parent.matrixWorld.clone();
  }

  /** An object's frame in the world now (unscaled): parent · pose. */
  objectWorldPose(name) {
    const e = this.sceneObjects.get(name);
    if (!e) return null;
    return this.objectParentMatrix(name).multiply(poseMatrix(e.spec.position, e.spec.rotation));
  }

  /** The pose (position, rotation rows) in an object's own frame of a world matrix. */
  objectLocalPose(name, world) {
    const local = this.objectParentMatrix(name).invert().multiply(world);
    return poseOf(local);
  }

  /** Meshes that can be picked as surfaces: the bodies' and the visible scene objects'. */
  surfaces() {
    return [this.sceneRoot, ...[...this.bodies.values()].map((b) => b.group)];
  }

  /** The world box of a drawn object (its mesh's vertices). */
  objectBox(name) {
    const e = this.sceneObjects.get(name);
    if (!e) return null;
    e.parent.updateMatrixWorld(true);
    e.mesh.updateMatrixWorld(true);
    return new THREE.Box3().setFromObject(e.mesh, true);
  }

  /**
   * Snap by dropping: how far object `name` can move against "up" (along gravity) before it
   * rests on the first surface below it (a body or another visible object), from rays cast down
   * from its footprint (the centre and corners of its box at its lowest level). Returns
   * {distance, onto} or null when nothing is below.
   */
  dropDistance(name) {
    const box = this.objectBox(name);
    if (!box) return null;
    const up = this.up;
    const cs = corners(box);
    const low = Math.min(...cs.map((c) => c.dot(up)));
    const centre = box.getCenter(new THREE.Vector3());
    const lift = this.size * 1e-4; // start just above the footprint, so a resting object finds its support at ≈ 0
    const starts = [centre, ...cs].map((c) => c.clone().addScaledVector(up, low - c.dot(up) + lift));
    const ray = new THREE.Raycaster();
    const down = up.clone().negate();
    let best = null;
    for (const p of starts) {
      ray.set(p, down);
      const hit = ray
        .intersectObjects(this.surfaces(), true)
        .find((h) => h.object.userData.pick && h.object.visible && h.object.userData.pick.name !== name && isShown(h.object));
      if (hit && (!best || hit.distance < best.distance)) best = { distance: hit.distance - lift, onto: hit.object.userData.pick };
    }
    return best;
  }

  /** The pose in body `body`'s CS1 as it is now (the world when null) of a world matrix. */
  localPoseIn(body, world) {
    const b = body ? this.bodies.get(body) : null;
    if (body && !b) return null;
    if (!b) return poseOf(world);
    b.group.updateMatrixWorld(true);
    return poseOf(b.group.matrixWorld.clone().invert().multiply(world));
  }

  /** An object's pose in its own frame after moving it by world translation `d` (m). */
  objectPoseMovedBy(name, d) {
    const world = this.objectWorldPose(name);
    if (!world) return null;
    return this.objectLocalPose(name, new THREE.Matrix4().makeTranslation(d[0], d[1], d[2]).multiply(world));
  }

  /** The middle of an object's underside (its box's centre at its lowest level along "up"), world. */
  objectFoot(name) {
    const box = this.objectBox(name);
    if (!box) return null;
    const low = Math.min(...corners(box).map((c) => c.dot(this.up)));
    const centre = box.getCenter(new THREE.Vector3());
    return centre.addScaledVector(this.up, low - centre.dot(this.up)).toArray();
  }

  /**
   * The next click on the 3D view picks a surface point instead of selecting: `done({point,
   * object})` with the world point and what it lies on ({kind, name}), or done(null) for a miss.
   * Object `exclude` (the one being placed) is not a surface. `cancelSurfacePick()` stops waiting.
   */
  pickSurface(exclude, done) {
    this.surfacePick = { exclude, done };
  }

  cancelSurfacePick() {
    this.surfacePick = null;
  }

  /** Where a world point is on the canvas, in CSS pixels (for tests and overlays). */
  toScreen(p) {
    const v = new THREE.Vector3(...p).project(this.camera);
    const c = this.renderer.domElement;
    return { x: ((v.x + 1) / 2) * c.clientWidth, y: ((1 - v.y) / 2) * c.clientHeight };
  }

  /** Frames the whole model from an oblique direction. */
  resetView() {
    const centre = this.box.getCenter(new THREE.Vector3());
    const up = this.up;
    // A side direction perpendicular to "up", then lifted: an isometric-like view.
    const side = Math.abs(up.z) > 0.9 ? new THREE.Vector3(1, -1.4, 0) : new THREE.Vector3(1, 0, 1.4);
    side.addScaledVector(up, -side.dot(up)).normalize();
    const dir = side.addScaledVector(up, 0.6).normalize();
    const dist = (this.size / 2 / Math.tan((this.camera.fov * Math.PI) / 360)) * 1.15;
    this.camera.position.copy(centre).addScaledVector(dir, dist);
    this.camera.near = dist / 200;
    this.camera.far = dist * 50;
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(centre);
    this.controls.update();
    this.invalidate();
  }

  /**
   * A named view of the whole model: 'top' (looking down, against "up"), 'front', 'side'
   * (horizontal, as in the four-viewport layout) or 'iso' (the oblique view of Reset view).
   */
  namedView(name) {
    const { fwd, right } = this.horizontalAxes();
    // Top: straight down, a hair behind so that "forward" points up the screen (the orbit keeps
    // "up" as the camera's up and cannot sit exactly on it).
    const iso = fwd.clone().negate().add(right).normalize().addScaledVector(this.up, 0.8);
    const dir = { top: this.up.clone().addScaledVector(fwd, -1e-4), front: fwd.clone().negate(), side: right.clone(), iso }[name];
    if (!dir) throw new Error(`unknown view ${name}`);
    this.lookAlong(dir, this.poseBox());
  }

  /**
   * Frames the selected body (its meshes or CG dot) or joint (its arrows) from the current
   * viewing direction; the whole model when nothing is selected. Returns whether a selection was framed.
   */
  fitSelection() {
    const sel = this.selected;
    const box = new THREE.Box3();
    if (sel?.kind === 'body' && this.bodies.has(sel.name)) box.expandByObject(this.bodies.get(sel.name).group);
    else if (sel?.kind === 'joint' && this.joints.has(sel.name)) for (const a of this.joints.get(sel.name).arrows) box.expandByObject(a);
    else if (sel?.kind === 'object' && this.sceneObjects.has(sel.name)) box.union(this.objectBox(sel.name));
    const dir = this.camera.position.clone().sub(this.controls.target).normalize();
    this.lookAlong(dir, box.isEmpty() ? this.poseBox() : box);
    return !box.isEmpty();
  }

  /** Places the perspective camera on `dir` (from the target towards the eye) so that `box` fills the view. */
  lookAlong(dir, box) {
    const centre = box.getCenter(new THREE.Vector3());
    const size = Math.max(box.getSize(new THREE.Vector3()).length(), this.size / 1000);
    // The box's bounding sphere inside the narrower of the two half-angles of the view.
    const half = (this.camera.fov * Math.PI) / 360;
    const narrow = Math.min(half, Math.atan(Math.tan(half) * this.camera.aspect));
    const dist = (size / 2 / Math.sin(narrow)) * 1.05;
    this.camera.position.copy(centre).addScaledVector(dir.clone().normalize(), dist);
    this.camera.near = dist / 200;
    this.camera.far = dist * 50 + this.size * 10;
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(centre);
    this.controls.update();
    this.camera.updateMatrixWorld();
    this.invalidate();
  }

  /**
   * The box around the bodies as they are posed now and the visible scene objects (planes
   * aside: they are drawn wider than the model); the model's box when none has a shape.
   */
  poseBox() {
    const box = new THREE.Box3();
    for (const b of this.bodies.values()) if (b.hasMesh) box.expandByObject(b.group);
    for (const [name, o] of this.sceneObjects) if (o.spec.shape.kind !== 'plane' && isShown(o.mesh)) box.union(this.objectBox(name));
    return box.isEmpty() ? this.box.clone() : box;
  }

  /** The horizontal "forward" (the world axis least aligned with up) and "right" directions. */
  horizontalAxes() {
    const up = this.up;
    const axes = [new THREE.Vector3(1, 0, 0), new THREE.Vector3(0, 1, 0), new THREE.Vector3(0, 0, 1)];
    const fwd = axes.sort((a, b) => Math.abs(a.dot(up)) - Math.abs(b.dot(up)))[0].clone();
    fwd.addScaledVector(up, -fwd.dot(up)).normalize();
    return { fwd, right: new THREE.Vector3().crossVectors(fwd, up).normalize() };
  }

  /** See-through bodies (opacity 0.35, no depth writes) so inner parts and axes show; returns the opacity. */
  setTransparent(on) {
    this.transparentOn = !!on;
    for (const b of this.bodies.values()) {
      for (const m of b.materials) {
        m.transparent = this.transparentOn;
        m.opacity = this.transparentOn ? 0.35 : 1;
        m.depthWrite = !this.transparentOn;
        m.needsUpdate = true;
      }
    }
    this.invalidate();
    return this.transparentOn ? 0.35 : 1;
  }

  /**
   * The viewport layout: 'single' (the perspective view), 'quad' (top, front and side
   * orthographic views beside the perspective one), 'sbs' (side-by-side stereo: left eye on the
   * left half, right eye on the right, for 3D displays and projectors that split one picture) or
   * 'dual' (dual output for polarised projection: the left eye here, the right eye in a second
   * window of its own, `openDualOutput`). Any other layout closes the second window.
   */
  setLayout(mode) {
    this.layout = ['quad', 'sbs', 'dual'].includes(mode) ? mode : 'single';
    if (this.layout !== 'dual') this.closeDualOutput();
    this.host.dataset.layout = this.layout;
    this.labels?.remove();
    this.labels = null;
    if (this.layout !== 'single') {
      const names = { quad: ['Top', 'Front', 'Side', 'Perspective'], sbs: ['Left eye', 'Right eye'], dual: ['Left eye (the right eye is in its own window)'] }[this.layout];
      this.labels = document.createElement('div');
      this.labels.className = `viewport-labels viewport-${this.layout}`;
      this.labels.setAttribute('aria-hidden', 'true');
      for (const n of names) {
        const d = document.createElement('span');
        d.textContent = n;
        this.labels.append(d);
      }
      this.host.append(this.labels);
    }
    this.invalidate();
  }

  /**
   * Dual output: this view shows the left eye and `win` (a window this page opened, e.g.
   * window.open('', ...), on the second projector or output) the right eye of the same camera,
   * drawn from this page's scene with a renderer of its own whenever this view draws, so both
   * stay in step (camera, poses, selection). Double-click the second window for full screen.
   * `onClosed` is called when that window closes; the layout is then single again.
   */
  openDualOutput(win, onClosed) {
    this.closeDualOutput();
    const doc = win.document;
    doc.title = `${this.report.model_name}: right eye (cad2mo)`;
    for (const el of [doc.documentElement, doc.body]) Object.assign(el.style, { margin: '0', height: '100%', overflow: 'hidden', background: '#f3f5f8' });
    const canvas = doc.createElement('canvas');
    Object.assign(canvas.style, { display: 'block', width: '100%', height: '100%' });
    canvas.setAttribute('role', 'img');
    canvas.setAttribute('aria-label', `Right eye of the 3D view of ${this.report.model_name}`);
    canvas.className = 'right-eye';
    doc.body.replaceChildren(canvas);
    const renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
    renderer.setPixelRatio(Math.min(win.devicePixelRatio || 1, 2));
    renderer.setClearColor(BACKGROUND);
    const redraw = () => this.invalidate();
    const closed = () => {
      if (this.dual?.win !== win) return;
      this.closeDualOutput();
      if (this.layout === 'dual') this.setLayout('single');
      onClosed?.();
    };
    win.addEventListener('resize', redraw);
    win.addEventListener('pagehide', closed);
    canvas.addEventListener('dblclick', () => canvas.requestFullscreen?.().catch(() => {}));
    this.dual = { win, canvas, renderer, closed, frames: 0 };
    this.setLayout('dual');
    return canvas;
  }

  /** Closes the dual output's second window (if open). */
  closeDualOutput() {
    const d = this.dual;
    if (!d) return;
    this.dual = null;
    d.renderer.dispose();
    if (!d.win.closed) d.win.close();
  }

  /** The right eye in the dual output's second window. */
  renderSecondEye() {
    const d = this.dual;
    if (!d) return;
    if (d.win.closed) return d.closed();
    const w = Math.max(d.win.innerWidth, 1);
    const hgt = Math.max(d.win.innerHeight, 1);
    d.renderer.setSize(w, hgt, false);
    d.renderer.render(this.scene, this.eye('right', w / hgt));
    d.frames += 1;
    d.canvas.dataset.rendered = String(d.frames);
  }

  /** The camera of one stereo eye ('left', 'right') for a viewport of that aspect. */
  eye(side, aspect) {
    return eyeCamera((this.eyes[side] ||= {}), this.camera, this.viewDistance(), side, aspect);
  }

  /** The distance from the camera to the orbit target: the stereo eyes' convergence. */
  viewDistance() {
    return this.camera.position.distanceTo(this.controls.target);
  }

  /** An orthographic camera looking at the model along `dir` (towards the model) with `up`. */
  orthoCamera(dir, up, aspect) {
    const centre = this.box.getCenter(new THREE.Vector3());
    const s = (this.size / 2) * 1.1;
    const [hw, hh] = aspect >= 1 ? [s * aspect, s] : [s, s / aspect];
    const cam = new THREE.OrthographicCamera(-hw, hw, hh, -hh, this.size / 1000, this.size * 20);
    cam.up.copy(up);
    cam.position.copy(centre).addScaledVector(dir, -this.size * 4);
    cam.lookAt(centre);
    cam.updateProjectionMatrix();
    cam.updateMatrixWorld(); // project() works before the first render too
    return cam;
  }

  /**
   * The viewports of the current layout: [{x, y, w, h, camera}] in canvas CSS pixels from the
   * top-left corner. The orthographic directions follow "up" (against gravity).
   */
  viewports() {
    const w = Math.max(this.host.clientWidth, 1);
    const hgt = Math.max(this.host.clientHeight, 1);
    if (this.layout === 'quad') {
      const hw = Math.floor(w / 2);
      const hh = Math.floor(hgt / 2);
      const up = this.up.clone();
      // A horizontal "forward" direction: the world axis least aligned with up, made horizontal.
      const { fwd, right } = this.horizontalAxes();
      const a = (ww, h2) => ww / Math.max(h2, 1);
      this.perspQuad ||= new THREE.PerspectiveCamera();
      this.perspQuad.copy(this.camera);
      this.perspQuad.aspect = a(w - hw, hgt - hh);
      this.perspQuad.updateProjectionMatrix();
      return [
        { x: 0, y: 0, w: hw, h: hh, camera: this.orthoCamera(up.clone().negate(), fwd, a(hw, hh)), name: 'top' },
        { x: hw, y: 0, w: w - hw, h: hh, camera: this.orthoCamera(fwd, up, a(w - hw, hh)), name: 'front' },
        { x: 0, y: hh, w: hw, h: hgt - hh, camera: this.orthoCamera(right.clone().negate(), up, a(hw, hgt - hh)), name: 'side' },
        { x: hw, y: hh, w: w - hw, h: hgt - hh, camera: this.perspQuad, name: 'perspective' },
      ];
    }
    if (this.layout === 'sbs') {
      // Each eye keeps the picture's proportions in its half (full side-by-side).
      const hw = Math.floor(w / 2);
      return [
        { x: 0, y: 0, w: hw, h: hgt, camera: this.eye('left', hw / hgt), name: 'left' },
        { x: hw, y: 0, w: w - hw, h: hgt, camera: this.eye('right', (w - hw) / hgt), name: 'right' },
      ];
    }
    if (this.layout === 'dual') {
      return [{ x: 0, y: 0, w, h: hgt, camera: this.eye('left', w / hgt), name: 'left' }];
    }
    return [{ x: 0, y: 0, w, h: hgt, camera: this.camera, name: 'single' }];
  }

  setAnaglyph(on) {
    if (on && !this.anaglyph) {
      this.anaglyph = new AnaglyphEffect(this.renderer);
      this.fit();
    }
    this.anaglyphOn = on;
    this.invalidate();
  }

  setGrid(on) {
    this.grid.visible = on;
    this.axes.visible = on;
    this.invalidate();
  }

  /**
   * The measuring tool: while on, clicks pick points on the meshes instead of selecting; every
   * second point closes a measurement, drawn as a line, reported to `onMeasure({a, b, distance})`.
   */
  setMeasuring(on, onMeasure) {
    this.measuring = !!on;
    this.onMeasure = onMeasure;
    this.measurePts = [];
    if (!on) this.clearMeasure();
  }

  clearMeasure() {
    if (this.measureObj) {
      this.scene.remove(this.measureObj);
      this.measureObj.traverse((o) => {
        o.geometry?.dispose?.();
        o.material?.dispose?.();
      });
      this.measureObj = null;
    }
    this.invalidate();
  }

  /** Adds a picked point (world, m) to the measurement; null (a miss) is ignored. */
  measurePoint(p) {
    if (!p) return;
    if (this.measurePts.length >= 2) this.measurePts = [];
    this.measurePts.push(p.clone());
    this.clearMeasure();
    const g = new THREE.Group();
    const dot = this.size * 0.008;
    for (const q of this.measurePts) {
      const m = new THREE.Mesh(new THREE.SphereGeometry(dot, 12, 8), new THREE.MeshBasicMaterial({ color: 0xe07000, depthTest: false }));
      m.position.copy(q);
      m.renderOrder = 20;
      g.add(m);
    }
    if (this.measurePts.length === 2) {
      const [a, b] = this.measurePts;
      const line = new THREE.Line(new THREE.BufferGeometry().setFromPoints([a, b]), new THREE.LineBasicMaterial({ color: 0xe07000, depthTest: false }));
      line.renderOrder = 20;
      g.add(line);
      this.onMeasure?.({ a: a.toArray(), b: b.toArray(), distance: a.distanceTo(b) });
    } else this.onMeasure?.({ a: this.measurePts[0].toArray(), b: null, distance: null });
    this.measureObj = g;
    this.scene.add(g);
    this.invalidate();
  }

  /**
   * Shows (on) or hides each body's collision shape, drawn as a translucent orange wireframe
   * in the body's frame: `shapes` maps body names to {positions, indices} in CS1 (metres),
   * given on the first call that shows them.
   */
  setCollisionShapes(on, shapes) {
    if (on && !this.collisionShapes && shapes) {
      this.collisionShapes = new Map();
      this.collisionMaterial = new THREE.MeshBasicMaterial({ color: 0xe06000, wireframe: true, transparent: true, opacity: 0.35, depthTest: false });
      for (const [name, s] of shapes) {
        const b = this.bodies.get(name);
        if (!b || !s.indices.length) continue;
        const g = new THREE.BufferGeometry();
        g.setAttribute('position', new THREE.Float32BufferAttribute(s.positions, 3));
        g.setIndex(s.indices);
        const m = new THREE.Mesh(g, this.collisionMaterial);
        m.renderOrder = 15;
        b.group.add(m);
        this.collisionShapes.set(name, m);
      }
    }
    for (const m of this.collisionShapes?.values() || []) m.visible = !!on;
    this.invalidate();
    return this.collisionShapes?.size ?? 0;
  }

  /** Highlights one body or joint (null clears). */
  select(sel) {
    this.selected = sel;
    this.paintBodies();
    for (const [name, j] of this.joints) {
      const on = sel?.kind === 'joint' && sel.name === name;
      for (const a of j.arrows) {
        a.setColor(on ? HIGHLIGHT : a.userData.color);
        a.scale.setScalar(on ? 1.4 : 1);
      }
    }
    this.invalidate();
  }

  /** Emissive tint: the selected body or scene object orange, those of a marked (colliding) pair red. */
  paintBodies() {
    const sel = this.selected;
    for (const [name, o] of this.sceneObjects || []) {
      const m = o.mesh.material;
      if (sel?.kind === 'object' && sel.name === name) m.emissive.copy(HIGHLIGHT).multiplyScalar(0.45);
      else if (this.marked?.has(name)) m.emissive.copy(CONTACT).multiplyScalar(0.55);
      else m.emissive.setRGB(0, 0, 0);
    }
    for (const [name, b] of this.bodies) {
      const on = sel?.kind === 'body' && sel.name === name;
      const marked = this.marked?.has(name);
      for (const m of b.materials) {
        if (on) m.emissive.copy(HIGHLIGHT).multiplyScalar(0.45);
        else if (marked) m.emissive.copy(CONTACT).multiplyScalar(0.55);
        else m.emissive.setRGB(0, 0, 0);
      }
    }
  }

  /**
   * Collision overlays: bodies `names` tinted red, and `lines` [{from, to}] (world points, m)
   * drawn as segments with a dot at each end, over the meshes (no depth test). Empty clears.
   */
  setContacts(names = [], lines = []) {
    this.marked = new Set(names.filter((n) => this.bodies.has(n) || this.sceneObjects.has(n)));
    this.paintBodies();
    if (this.contactGroup) {
      this.scene.remove(this.contactGroup);
      this.contactGroup.traverse((o) => {
        o.geometry?.dispose?.();
        o.material?.dispose?.();
      });
    }
    this.contactGroup = new THREE.Group();
    this.contactGroup.name = 'contacts';
    const dot = this.size * 0.01;
    for (const l of lines) {
      const a = new THREE.Vector3(...l.from);
      const b = new THREE.Vector3(...l.to);
      const geom = new THREE.BufferGeometry().setFromPoints([a, b]);
      const line = new THREE.Line(geom, new THREE.LineBasicMaterial({ color: CONTACT_LINE, depthTest: false, transparent: true }));
      line.renderOrder = 20;
      line.userData.contact = { from: [...l.from], to: [...l.to] };
      this.contactGroup.add(line);
      for (const p of [a, b]) {
        const s = new THREE.Mesh(new THREE.SphereGeometry(dot, 12, 8), new THREE.MeshBasicMaterial({ color: CONTACT_LINE, depthTest: false, transparent: true }));
        s.position.copy(p);
        s.renderOrder = 20;
        this.contactGroup.add(s);
      }
    }
    this.contactGroup.visible = !this.contactsHidden;
    this.scene.add(this.contactGroup);
    this.invalidate();
  }

  /** Shows or hides the contact points and lines (kept while hidden); returns how many lines there are. */
  setContactsShown(on) {
    this.contactsHidden = !on;
    if (this.contactGroup) this.contactGroup.visible = !!on;
    this.invalidate();
    return this.contactLines().length;
  }

  /** The contact lines drawn now, read from the scene: [{from, to}] in world coordinates. */
  contactLines() {
    const out = [];
    this.contactGroup?.traverse((o) => {
      if (!o.isLine) return;
      o.updateMatrixWorld(true);
      const pos = o.geometry.getAttribute('position');
      const p = (i) => new THREE.Vector3(pos.getX(i), pos.getY(i), pos.getZ(i)).applyMatrix4(o.matrixWorld).toArray();
      out.push({ from: p(0), to: p(1) });
    });
    return out;
  }

  fit() {
    const w = Math.max(this.host.clientWidth, 1);
    const hgt = Math.max(this.host.clientHeight, 1);
    this.renderer.setSize(w, hgt, false);
    this.anaglyph?.setSize(w, hgt);
    this.camera.aspect = w / hgt;
    this.camera.updateProjectionMatrix();
    this.invalidate();
  }

  invalidate() {
    // In a headset the session's own loop draws every frame.
    if (this.frame || this.xrSession) return;
    this.frame = requestAnimationFrame(() => {
      this.frame = null;
      this.render();
    });
  }

  render() {
    const t0 = performance.now();
    if (this.anaglyphOn && this.anaglyph) {
      // Eye separation and focal plane scale with the viewing distance (models are mm to m).
      const dist = this.viewDistance();
      this.anaglyph.eyeSep = eyeSeparation(dist);
      this.anaglyph.planeDistance = dist;
      this.anaglyph.render(this.scene, this.camera);
    }
    else if (this.layout !== 'single') {
      const hgt = Math.max(this.host.clientHeight, 1);
      const r = this.renderer;
      // The whole canvas first: no part of an earlier picture survives in a viewport.
      r.setScissorTest(false);
      r.setViewport(0, 0, Math.max(this.host.clientWidth, 1), hgt);
      r.clear();
      r.setScissorTest(true);
      for (const v of this.viewports()) {
        // three.js viewports count from the bottom-left corner.
        r.setViewport(v.x, hgt - v.y - v.h, v.w, v.h);
        r.setScissor(v.x, hgt - v.y - v.h, v.w, v.h);
        r.render(this.scene, v.camera);
      }
      r.setScissorTest(false);
      r.setViewport(0, 0, Math.max(this.host.clientWidth, 1), hgt);
    } else this.renderer.render(this.scene, this.camera);
    if (this.layout === 'dual') this.renderSecondEye();
    this.host.dataset.rendered = String((Number(this.host.dataset.rendered) || 0) + 1);
    if (this.host.dataset.rendered === '1') performance.measure('cad2mo:first-frame', { start: t0 });
  }

  /**
   * Immersive VR (WebXR, three.js `renderer.xr`): requests an 'immersive-vr' session from `xr`
   * (navigator.xr), stands the model upright on the floor in front of the user at its true size
   * (xrPlacement), and renders every frame the headset asks for until the session ends, when
   * the page's view comes back as it was. Resolves with the session; rejects with the browser's
   * reason (no device, permission refused).
   */
  async enterVR(xr) {
    const session = await xr.requestSession('immersive-vr', { optionalFeatures: ['local-floor'] });
    const box = new THREE.Box3();
    for (const [, b] of this.bodies) if (b.hasMesh) box.expandByObject(b.group);
    if (box.isEmpty()) box.setFromObject(this.scene);
    const place = xrPlacement(this.up.toArray(), { min: box.min.toArray(), max: box.max.toArray() });
    const xrm = this.renderer.xr;
    xrm.enabled = true;
    // Without a floor-level space the origin is at the eyes: the floor is about 1.6 m below.
    const floor = session.enabledFeatures?.includes?.('local-floor') !== false;
    xrm.setReferenceSpaceType(floor ? 'local-floor' : 'local');
    this.scene.quaternion.fromArray(place.quaternion);
    this.scene.position.fromArray(place.position);
    if (!floor) this.scene.position.y -= 1.6;
    this.scene.updateMatrixWorld(true);
    const end = () => {
      this.renderer.setAnimationLoop(null);
      xrm.enabled = false;
      this.scene.quaternion.identity();
      this.scene.position.set(0, 0, 0);
      this.scene.updateMatrixWorld(true);
      this.xrSession = null;
      this.host.dataset.xr = 'ended';
      this.fit();
    };
    session.addEventListener('end', end);
    try {
      await xrm.setSession(session);
    } catch (e) {
      end();
      await session.end().catch(() => {});
      throw e;
    }
    this.xrSession = session;
    this.host.dataset.xr = 'immersive';
    this.renderer.setAnimationLoop(() => this.renderer.render(this.scene, this.camera));
    return session;
  }

  /**
   * Where the model's meshes are on screen, in canvas CSS pixels: {x0, y0, x1, y1}; in viewport
   * `vp` (one of viewports()) when given, else in the whole canvas through the main camera.
   */
  screenBox(name, vp) {
    const out = { x0: Infinity, y0: Infinity, x1: -Infinity, y1: -Infinity };
    const canvas = this.renderer.domElement;
    const cam = vp?.camera || this.camera;
    const [ox, oy, w, hgt] = vp ? [vp.x, vp.y, vp.w, vp.h] : [0, 0, canvas.clientWidth, canvas.clientHeight];
    for (const [n, b] of this.bodies) {
      if (!b.hasMesh || (name && n !== name)) continue;
      b.group.updateMatrixWorld(true);
      const box = new THREE.Box3().setFromObject(b.group);
      for (const c of corners(box)) {
        const p = c.project(cam);
        const x = ox + ((p.x + 1) / 2) * w;
        const y = oy + ((1 - p.y) / 2) * hgt;
        out.x0 = Math.min(out.x0, x);
        out.y0 = Math.min(out.y0, y);
        out.x1 = Math.max(out.x1, x);
        out.y1 = Math.max(out.y1, y);
      }
    }
    return out;
  }

  installPicking(canvas) {
    const ray = new THREE.Raycaster();
    ray.params.Line.threshold = this.size * 0.01;
    let down = null;
    canvas.addEventListener('pointerdown', (e) => (down = { x: e.clientX, y: e.clientY }));
    canvas.addEventListener('pointerup', (e) => {
      if (!down || Math.hypot(e.clientX - down.x, e.clientY - down.y) > 4) return;
      // A click on the gizmo's handles is the gizmo's, not a pick.
      if (this.gizmo?.controls.axis) return;
      const r = canvas.getBoundingClientRect();
      // The viewport under the pointer, and the point in its own coordinates.
      const cx = e.clientX - r.left;
      const cy = e.clientY - r.top;
      const vp = this.viewports().find((v) => cx >= v.x && cx < v.x + v.w && cy >= v.y && cy < v.y + v.h) || this.viewports()[0];
      const p = new THREE.Vector2(((cx - vp.x) / vp.w) * 2 - 1, -((cy - vp.y) / vp.h) * 2 + 1);
      ray.setFromCamera(p, vp.camera);
      if (this.surfacePick) {
        const { exclude, done } = this.surfacePick;
        this.surfacePick = null;
        const hit = ray.intersectObjects(this.surfaces(), true).find((h) => h.object.userData.pick && h.object.visible && h.object.userData.pick.name !== exclude);
        // Kept for the end-to-end test: what the last surface pick found.
        this.surfacePicked = hit ? { point: hit.point.toArray(), object: hit.object.userData.pick } : null;
        done(this.surfacePicked);
        return;
      }
      if (this.measuring) {
        const hit = ray.intersectObjects(this.surfaces(), true).find((h) => h.object.userData.pick && h.object.visible);
        this.measurePoint(hit ? hit.point : null);
        return;
      }
      const targets = [this.sceneRoot];
      for (const [, b] of this.bodies) targets.push(b.group);
      for (const [, j] of this.joints) targets.push(j.group);
      const hits = ray.intersectObjects(targets, true).filter((h) => h.object.userData.pick && h.object.visible);
      // Joint arrows win over the body they sit in when both are hit.
      const hit = hits.find((h) => h.object.userData.pick.kind === 'joint') || hits[0];
      this.onPick(hit ? hit.object.userData.pick : null);
    });
  }

  dispose() {
    this.closeDualOutput();
    this.xrSession?.end().catch(() => {});
    this.setGhost(null);
    this.clearMeasure();
    this.labels?.remove();
    this.hideGizmo();
    cancelAnimationFrame(this.frame);
    this.resize.disconnect();
    this.controls.dispose();
    this.scene.traverse((o) => {
      o.geometry?.dispose?.();
      if (o.material) [].concat(o.material).forEach((m) => m.dispose());
    });
    this.anaglyph?.dispose?.();
    this.renderer.dispose();
    this.renderer.domElement.remove();
  }
}

function corners(box) {
  const out = [];
  for (const x of [box.min.x, box.max.x]) for (const y of [box.min.y, box.max.y]) for (const z of [box.min.z, box.max.z]) out.push(new THREE.Vector3(x, y, z));
  return out;
}

/** 1, 2 or 5 times a power of ten, at least x. */
export function niceStep(x) {
  const p = 10 ** Math.floor(Math.log10(x));
  for (const m of [1, 2, 5, 10]) if (m * p >= x) return m * p;
  return 10 * p;
}

/** A CAD colour (sRGB components in 0..1, as in the report and the Modelica shapes). */
function srgb([r, g, b]) {
  return new THREE.Color().setRGB(r, g, b, THREE.SRGBColorSpace);
}

/** Whether an object and all its parents are visible. */
function isShown(o) {
  for (let x = o; x; x = x.parent) if (!x.visible) return false;
  return true;
}

/** A matrix from a position and rotation rows (frame → parent). */
export function poseMatrix(p, r = [[1, 0, 0], [0, 1, 0], [0, 0, 1]]) {
  return new THREE.Matrix4().set(r[0][0], r[0][1], r[0][2], p[0], r[1][0], r[1][1], r[1][2], p[1], r[2][0], r[2][1], r[2][2], p[2], 0, 0, 0, 1);
}

/** Position and rotation rows of a rigid matrix (its rotation made orthonormal: the gizmo's quaternion). */
export function poseOf(m) {
  const position = new THREE.Vector3();
  const q = new THREE.Quaternion();
  m.decompose(position, q, new THREE.Vector3());
  const e = new THREE.Matrix4().makeRotationFromQuaternion(q.normalize()).elements;
  return { position: position.toArray(), rotation: [0, 1, 2].map((i) => [e[i], e[i + 4], e[i + 8]]) };
}

/**
 * A primitive's geometry in its own frame (SI): box edges x, y, z; cylinder and capsule along z,
 * centred; a sphere; a plane as a square of its z = 0 surface, a few model sizes wide (the
 * collision checks take it 200 m wide). Null for a mesh shape.
 */
function sceneGeometry(s, modelSize) {
  switch (s.kind) {
    case 'box':
      return new THREE.BoxGeometry(...s.size);
    case 'cylinder':
      return new THREE.CylinderGeometry(s.radius, s.radius, s.length, 32).rotateX(Math.PI / 2);
    case 'sphere':
      return new THREE.SphereGeometry(s.radius, 32, 16);
    case 'capsule':
      return new THREE.CapsuleGeometry(s.radius, s.length, 8, 24).rotateX(Math.PI / 2);
    case 'plane': {
      const w = niceStep(modelSize * 4);
      return new THREE.PlaneGeometry(w, w);
    }
    default:
      return null;
  }
}
