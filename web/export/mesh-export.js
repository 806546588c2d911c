// OBJ, binary STL and GLB of the drawn patches with three.js's own exporters, loaded on
// first use (the cold-start bundle does not carry them). The exporters get a clean copy of
// the patch meshes, never the drawn ones: plain MeshStandardMaterials in the patch colours
// (the zebra and curvature shaders of viewer/shading.js must not leak into a file), copied
// arrays (a solve arriving during an export must not change it half-way), one mesh per
// patch named after it. Coordinates stay the scene's (z up), as the CLI's exports do.
import * as THREE from 'three';

const loadObj = () => import('three/addons/exporters/OBJExporter.js');
const loadStl = () => import('three/addons/exporters/STLExporter.js');
const loadGltf = () => import('three/addons/exporters/GLTFExporter.js');

function copyAttribute(attr) {
  return new THREE.BufferAttribute(attr.array.slice(0, attr.count * attr.itemSize), attr.itemSize);
}

// glTF puts the texture origin at the top left, OBJ at the bottom left: TEXCOORD_0 is
// (u, 1 - v), as cli/glb_writer.cpp writes it, so a texture maps the same way in both.
function flippedUv(attr) {
  const a = attr.array.slice(0, attr.count * 2);
  for (let k = 1; k < a.length; k += 2) a[k] = 1 - a[k];
  return new THREE.BufferAttribute(a, 2);
}

/**
 * surfaces: the viewer's group of patch meshes. Returns a THREE.Scene holding one clean
 * mesh per patch (name = the patch's name; userData.kind = the patch's kind).
 * forGltf: uvs flipped to glTF's convention.
 */
export function cleanSurfaceCopy(surfaces, { forGltf = false } = {}) {
  const out = new THREE.Scene();
  const materials = new Map(); // one exported material per patch colour
  for (const m of surfaces.children) {
    if (!m.isMesh) continue;
    const src = m.geometry;
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', copyAttribute(src.getAttribute('position')));
    g.setAttribute('normal', copyAttribute(src.getAttribute('normal')));
    const uv = src.getAttribute('uv');
    if (uv) g.setAttribute('uv', forGltf ? flippedUv(uv) : copyAttribute(uv));
    g.setIndex(copyAttribute(src.getIndex()));
    const base = m.userData.baseMaterial || m.material; // the patch colour, whatever the shading
    const hex = base.color ? base.color.getHex() : 0xcccccc;
    if (!materials.has(hex)) {
      const kindName = m.userData.kind === 'pde' || m.userData.kind === 'fill' || m.userData.kind === 'bezier' ? 'solved' : 'primary';
      materials.set(hex, new THREE.MeshStandardMaterial({
        name: kindName, color: hex, roughness: base.roughness ?? 0.55, metalness: base.metalness ?? 0.05, side: THREE.DoubleSide,
      }));
    }
    const mesh = new THREE.Mesh(g, materials.get(hex));
    mesh.name = m.name;
    if (m.userData.kind) mesh.userData = { kind: m.userData.kind };
    out.add(mesh);
  }
  return out;
}

/** Free what cleanSurfaceCopy made. */
export function disposeCopy(copy) {
  const materials = new Set();
  copy.traverse((o) => {
    if (!o.isMesh) return;
    o.geometry.dispose();
    materials.add(o.material);
  });
  for (const m of materials) m.dispose();
}

// OBJ's "o" line runs to the end of the line and most readers split it at blanks. Control
// characters go too: C0, DEL and C1 (NEL U+0085 is a line break to some readers, and not in \s).
const objName = (name) => String(name).replace(/[\s\u0000-\u001f\u007f-\u009f]+/g, '_') || 'patch';

/** The patches as OBJ text: one "o" per patch, v / vt / vn / f, no materials. */
export async function exportObj(surfaces) {
  const { OBJExporter } = await loadObj();
  const copy = cleanSurfaceCopy(surfaces);
  for (const m of copy.children) {
    m.name = objName(m.name);
    m.material.name = ''; // no "usemtl" line: there is no .mtl file to go with it
  }
  try {
    return new OBJExporter().parse(copy);
  } finally {
    disposeCopy(copy);
  }
}

/** The patches as binary STL (an ArrayBuffer: 84 + 50 bytes per triangle). */
export async function exportStl(surfaces) {
  const { STLExporter } = await loadStl();
  const copy = cleanSurfaceCopy(surfaces);
  try {
    return new STLExporter().parse(copy, { binary: true }).buffer;
  } finally {
    disposeCopy(copy);
  }
}

/** The patches as GLB (glTF 2.0 binary, an ArrayBuffer): one node and mesh per patch. */
export async function exportGlb(surfaces, sceneName) {
  const { GLTFExporter } = await loadGltf();
  const copy = cleanSurfaceCopy(surfaces, { forGltf: true });
  copy.name = sceneName;
  try {
    return await new GLTFExporter().parseAsync(copy, { binary: true, onlyVisible: false });
  } finally {
    disposeCopy(copy);
  }
}
