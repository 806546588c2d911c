// The 3D view: renderer, camera, orbit controls, lights, the patch meshes and the
// bezier overlays (nets, normals, the control-point editor).
// Renders on demand (after a change or a camera move) to keep idle CPU at zero.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { meshFromPatch, updateMeshFromPatch, fitsMesh, shaderWarmUpMeshes } from './patch-mesh.js';
import { createCameraRig } from './camera-rig.js';
import { createBezierLayer } from './bezier-layer.js';
import { createControlPointEditor } from './control-point-editor.js';
import { createShading } from './shading.js';
import { createJoinHighlight } from './join-highlight.js';
import { createBorderPicker } from './border-picker.js';
import { createPlacementGizmo } from './placement-gizmo.js';
import { createPatchMarks } from './patch-marks.js';
import { createPatchClick } from './patch-click.js';

export const BACKGROUND = 0x20242b;

/**
 * container: the element to draw into. bezierEditing: { pointOf(patch, i, j) -> [x, y, z],
 * onPick(patch, i, j), onMove(patch, i, j, [x, y, z]) } for the control-point editor.
 * onFirstSurfaceFrame(ms): called once, when the first frame showing a surface is presented.
 */
export function createViewer(container, bezierEditing, { onFirstSurfaceFrame = null } = {}) {
  const renderer = new THREE.WebGLRenderer({ antialias: true });
  renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
  renderer.setClearColor(BACKGROUND, 1);
  // Hidden and not drawn until the first solve is shown (the page's background is the
  // same colour): a cold start's first frames then wait for no shader compile, which the
  // GPU process does meanwhile (see the warm-up below).
  renderer.domElement.style.visibility = 'hidden';
  let shown = false;
  container.appendChild(renderer.domElement);

  const scene = new THREE.Scene();
  const camera = new THREE.PerspectiveCamera(40, 1, 0.01, 1000);
  camera.up.set(0, 0, 1); // scenes are modelled with z up; set before the controls read it
  camera.position.set(6, -8, 5);

  // Lights ride with the camera so the surface facing the user is always lit.
  scene.add(new THREE.HemisphereLight(0xffffff, 0x505058, 2.0));
  const key = new THREE.DirectionalLight(0xffffff, 2.2);
  key.position.set(0.6, 1.2, 2);
  camera.add(key);
  scene.add(camera);

  const surfaces = new THREE.Group();
  scene.add(surfaces);

  // Overlays are kept out of `surfaces`: framing and the checksum see the patches only.
  const overlays = new THREE.Group();
  scene.add(overlays);
  const bezier = createBezierLayer(overlays);
  const shading = createShading(surfaces, overlays);
  const joins = createJoinHighlight(overlays);

  const controls = new OrbitControls(camera, renderer.domElement);
  // Zoom limits, clipping planes, fit, double-click and keys; renders on every camera change.
  const rig = createCameraRig({ camera, controls, surfaces, dom: renderer.domElement, render });
  const editor = createControlPointEditor({
    scene, camera, dom: renderer.domElement, orbit: controls, layer: bezier, render, ...bezierEditing,
  });
  // The modeller's tools (idle until the page uses them): the gizmo first, so its presses
  // are seen as its own before the picker's listeners run.
  const placement = createPlacementGizmo({ scene, camera, dom: renderer.domElement, orbit: controls, render });
  const borders = createBorderPicker({ scene, camera, dom: renderer.domElement, render, overlays, busy: placement.busy });
  const marks = createPatchMarks(surfaces);
  const clicks = createPatchClick({ camera, dom: renderer.domElement, surfaces,
    busy: () => placement.busy() || borders.state().enabled || Boolean(editor.active()) });

  // Coalesced: every change within a frame (a solve drawn, marks, shading, the gizmo) draws
  // once, at the next animation frame. A software GL (SwiftShader) renders each call in
  // full and the compositor waits for all of them: a solve drawn during a gizmo drag cost
  // 0.5-2 s of main thread in headless Chromium before.
  let frame = 0;
  let surfaceDrawn = false;
  let afterShown = []; // callbacks for once the next frame drawn is on screen
  function draw() {
    frame = 0;
    const firstSurface = !surfaceDrawn && surfaces.children.length > 0;
    if (firstSurface) performance.mark('pdesurf:first-draw');
    renderer.render(scene, camera);
    if (firstSurface) {
      surfaceDrawn = true;
      // What a visitor sees first (scripts/bench-page.mjs, the cold start): marked first.
      if (onFirstSurfaceFrame) afterShown.unshift(() => onFirstSurfaceFrame(performance.now()));
    }
    // The next frame's callback runs once this frame has gone to the compositor.
    if (afterShown.length > 0) {
      const callbacks = afterShown;
      afterShown = [];
      requestAnimationFrame(() => callbacks.forEach((f) => f()));
    }
  }
  function render() {
    camera.updateMatrixWorld(); // hit tests and screenOf read the camera before the frame
    if (shown && !frame) frame = requestAnimationFrame(draw);
  }

  function resize() {
    const w = Math.max(1, container.clientWidth);
    const h = Math.max(1, container.clientHeight);
    renderer.setSize(w, h, false);
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
    joins.setResolution(w, h);
    render();
  }
  new ResizeObserver(resize).observe(container);
  resize();

  // Compile the patch materials' shaders now (with the scene's lights, which are part of a
  // program), while the first solve runs in the worker, instead of in the first frame that
  // shows a surface; nothing else: the other materials (overlays, markers) wait for use.
  const warmUp = new THREE.Group();
  warmUp.add(...shaderWarmUpMeshes());
  // Without KHR_parallel_shader_compile (SwiftShader) compileAsync only warns and compiles:
  // compile() starts the same work in the GPU process without the warning. Then, still before
  // that frame, each program's first use (three reads its link status and uniform locations,
  // waiting for the GPU process to have linked it: 15-25 ms of the first frame with SwiftShader).
  const firstUse = () => {
    if (shown) return;
    try {
      for (const m of warmUp.children) renderer.properties.get(m.material).currentProgram?.getUniforms();
    } catch {
      // only a warm-up: the first frame does it (and reports a failure) otherwise
    }
  };
  if (renderer.extensions.has('KHR_parallel_shader_compile')) renderer.compileAsync(warmUp, camera, scene).then(firstUse, () => {});
  else {
    renderer.compile(warmUp, camera, scene);
    // A task of its own, queued as messages are: before a result the worker posts later, and
    // after one already here (that frame then does it).
    const channel = new MessageChannel();
    channel.port1.onmessage = () => {
      channel.port1.close();
      firstUse();
    };
    channel.port2.postMessage(null);
  }

  return {
    renderer,
    camera,
    controls,
    editor,
    /** Hover and pick a surface's border t0 or t1 (border-picker.js). */
    borders,
    /** Move, turn and scale a surface (placement-gizmo.js). */
    placement,
    /** fn(name | null) on a click on a patch or on the background (patch-click.js). */
    onPatchClick: clicks.onClick,

    /**
     * Replace the drawn patches with freshly solved ones: in place when the same patches
     * come back on the same grid (a slider drag), else new meshes.
     */
    setPatches(patches) {
      if (!shown) {
        shown = true;
        renderer.domElement.style.visibility = '';
      }
      const meshes = surfaces.children;
      if (meshes.length === patches.length && patches.every((p, k) => fitsMesh(meshes[k], p))) {
        patches.forEach((p, k) => updateMeshFromPatch(meshes[k], p));
      } else {
        for (const m of [...meshes]) {
          surfaces.remove(m);
          m.geometry.dispose(); // materials are shared, keep them
        }
        for (const p of patches) surfaces.add(meshFromPatch(p));
      }
      marks.solved();
      rig.invalidate();
      shading.refresh();
      bezier.update(patches);
      borders.setPatches(patches);
      editor.refresh();
      render();
    },

    /** Whether the meshes drawn are exactly these solved patches' (the same arrays). */
    shows(patches) {
      const meshes = surfaces.children;
      return meshes.length === patches.length && patches.every((p, k) => meshes[k].geometry.getAttribute('position').array === p.positions);
    },

    /** The drawn mesh of the patch `name`, or null. */
    meshOf: marks.meshOf,

    /** Show or hide one patch (kept across solves). */
    setPatchVisible(name, on) {
      marks.setVisible(name, on);
      render();
    },

    /** Tint the patch `name` as the selected one (kept across solves); null: none. */
    select(name) {
      marks.select(name);
      render();
    },

    /** For the tests: { selected, tinted, hidden }. */
    marks: marks.state,

    /** Shading mode (viewer/shading.js MODES); range { min, max } for the curvature maps. */
    setShading(mode, range = null) {
      shading.setMode(mode, range);
      render();
    },

    /** Zebra stripes: { angleDeg, widthDeg }. */
    setZebra(opts) {
      shading.setZebra(opts);
      render();
    },

    setWireframe(on) {
      shading.setWireframe(on);
      render();
    },

    /** Thick lines along joins: [{ key, patch (solved), end, fail }]. */
    highlightJoins(items) {
      joins.show(items);
      render();
    },

    /** The colour ramp (three's Lut) the curvature maps use. */
    ramp: shading.lut,

    /** For the tests: { mode, wireframe, highlights: [keys] }. */
    analysisState() {
      return { ...shading.state(), highlights: joins.keys() };
    },

    /** Show or hide one overlay (solvedNet, initialNet, normals) of a bezier patch. */
    setOverlay(patchName, key, on) {
      bezier.setVisible(patchName, key, on);
      render();
    },

    /** Edit the initial net of `patchName` at (i, j); null stops editing. */
    editControlPoint(patchName, i, j) {
      bezier.setEditing(patchName);
      editor.setActive(patchName, i, j);
    },

    /** A new scene: no overlay shown, nothing being edited. */
    resetOverlays() {
      bezier.reset();
      editor.setActive(null);
    },

    /** Visible overlays, for the tests: { solvedNets, initialNets, netPoints, arrows }. */
    overlayCounts() {
      return bezier.counts();
    },

    /** Where a world point appears in the page (client pixels), for the tests. */
    screenOf(xyz) {
      const v = new THREE.Vector3().fromArray(xyz).project(camera);
      const rect = renderer.domElement.getBoundingClientRect();
      return { x: rect.left + ((v.x + 1) / 2) * rect.width, y: rect.top + ((1 - v.y) / 2) * rect.height };
    },

    /** Vertex k of the patch named `name` as [x, y, z], or null. */
    vertexWorld(name, k) {
      const m = surfaces.children.find((c) => c.name === name);
      if (!m) return null;
      const p = m.geometry.getAttribute('position');
      if (k < 0 || k >= p.count) return null;
      return [p.getX(k), p.getY(k), p.getZ(k)];
    },

    /** Where vertex k of the patch named `name` appears in the page, or null. */
    vertexScreen(name, k) {
      const xyz = this.vertexWorld(name, k);
      return xyz && this.screenOf(xyz);
    },

    /** Calls f once the next frame drawn is on screen (after the patches set now are shown). */
    afterNextFrame(f) {
      afterShown.push(f);
      render();
    },
    /** Frame every patch: a new example, or byUser (the fit button, F); slider moves keep the view. */
    fit(byUser = false) {
      rig.fit(byUser);
    },

    /** For the tests: clipping planes, zoom limits and the scene's radius (camera-rig.js). */
    cameraState() {
      return rig.state();
    },

    /** The view as plain arrays, for links: { position: [x, y, z], target: [x, y, z] }. */
    getCamera() {
      return { position: camera.position.toArray(), target: controls.target.toArray() };
    },

    /** Restore a view from getCamera()'s form (a shared link's camera). */
    setCamera({ position, target }) {
      camera.position.fromArray(position);
      controls.target.fromArray(target);
      rig.afterMove();
    },

    /** The three.js scene and its group of patch meshes, for the exports (web/export/). */
    sceneGraph() {
      return { scene, surfaces };
    },

    /** Position arrays of the drawn meshes, in draw order. */
    positionArrays() {
      return surfaces.children.map((m) => m.geometry.getAttribute('position').array);
    },

    render,
  };
}
