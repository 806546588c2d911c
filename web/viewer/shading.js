// Shading modes of the drawn patches: "normal" (the patch colours, lit), "zebra"
// (reflection lines, zebra-material.js), "mean" and "gauss" (curvature colour maps from the
// module's per-vertex H and K, curvature-colors.js), and a wireframe overlay that goes
// with any of them (three's WireframeGeometry as LineSegments over each patch).
// The meshes keep their normal material in userData.baseMaterial.
import * as THREE from 'three';
import { createZebraMaterial, setZebra } from './zebra-material.js';
import { createRamp, curvatureColors } from './curvature-colors.js';

export const MODES = ['normal', 'zebra', 'mean', 'gauss'];
const CURVATURE_KEY = { mean: 'meanCurvature', gauss: 'gaussCurvature' };

/** surfaces: the group of patch meshes; overlays: where the wireframe goes. */
export function createShading(surfaces, overlays) {
  const zebra = createZebraMaterial();
  // Unlit: the colour on screen is the legend's colour for the value.
  const curvature = new THREE.MeshBasicMaterial({
    vertexColors: true, side: THREE.DoubleSide, polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1,
  });
  const lines = new THREE.LineBasicMaterial({ color: 0x15181d, transparent: true, opacity: 0.55 });
  const wireGroup = new THREE.Group();
  wireGroup.name = 'wireframe';
  overlays.add(wireGroup);
  const lut = createRamp();
  let mode = 'normal';
  let range = null; // { min, max } of the curvature mode

  function meshes() {
    return surfaces.children.filter((m) => m.isMesh);
  }

  function applyMaterials() {
    for (const m of meshes()) {
      if (!m.userData.baseMaterial) m.userData.baseMaterial = m.material;
      const key = CURVATURE_KEY[mode];
      if (mode === 'zebra') m.material = zebra;
      else if (key && m.userData.curvature?.[key] && range) {
        const g = m.geometry;
        const values = m.userData.curvature[key];
        const old = g.getAttribute('color');
        const arr = curvatureColors(lut, values, range.min, range.max, old && old.count === values.length ? old.array : undefined);
        if (old && old.array === arr) old.needsUpdate = true;
        else g.setAttribute('color', new THREE.BufferAttribute(arr, 3));
        m.material = curvature;
      } else m.material = m.userData.baseMaterial;
    }
  }

  function rebuildWireframe(on) {
    for (const l of [...wireGroup.children]) {
      wireGroup.remove(l);
      l.geometry.dispose();
    }
    if (!on) return;
    for (const m of meshes()) {
      const w = new THREE.LineSegments(new THREE.WireframeGeometry(m.geometry), lines);
      w.name = `wireframe ${m.name}`;
      wireGroup.add(w);
    }
  }

  let wireOn = false;

  return {
    lut,
    /** mode: one of MODES; range: { min, max } for mean and gauss. */
    setMode(next, nextRange = null) {
      mode = MODES.includes(next) ? next : 'normal';
      range = nextRange;
      applyMaterials();
    },
    setZebra(opts) {
      setZebra(zebra, opts);
    },
    setWireframe(on) {
      wireOn = Boolean(on);
      rebuildWireframe(wireOn);
    },
    /** New meshes were drawn: give them the current mode and overlay. */
    refresh() {
      applyMaterials();
      rebuildWireframe(wireOn);
    },
    /** For the tests: { mode, wireframe: line objects drawn }. */
    state() {
      return { mode, wireframe: wireGroup.children.length };
    },
  };
}
