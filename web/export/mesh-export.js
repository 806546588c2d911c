// OBJ, binary STL, GLB and 3MF of the model's watertight mesh (the worker's modelMesh: the
// patches share the vertices of their joins, analysis/watertight_mesh.hpp), with three.js's
// own exporters and @jscadui/3mf-export (ManifoldCAD's 3MF writer) zipped by fflate, loaded
// on first use (the cold-start bundle does not carry them).
// One mesh per body (its vertices only, so each file's indices close it), a geometry group and
// a plain MeshStandardMaterial per patch, named after it, in the patch's drawn colour (the
// zebra and curvature shaders must not leak into a file). A body of one patch is named after
// the patch, others "body N". Coordinates stay the scene's (z up), as the CLI's exports do.
import * as THREE from 'three';

const loadObj = () => import('three/addons/exporters/OBJExporter.js');
const loadStl = () => import('three/addons/exporters/STLExporter.js');
const loadGltf = () => import('three/addons/exporters/GLTFExporter.js');
const load3mf = () => Promise.all([import('@jscadui/3mf-export'), import('fflate')]);

/** The drawn patches' colours by name (viewer's surfaces group), for the exported materials. */
export function drawnColours(surfaces) {
  const colours = new Map();
  for (const m of surfaces.children) {
    if (!m.isMesh) continue;
    const base = m.userData.baseMaterial || m.material; // the patch colour, whatever the shading
    colours.set(m.name, base.color ? base.color.getHex() : 0xcccccc);
  }
  return colours;
}

/**
 * Each body's own vertices and triangles: { name, patches: [{ name, start, count }],
 * positions, normals (Float32Array), indices (Uint32Array) }, in body order.
 */
export function bodyMeshes(model) {
  const bodies = [];
  for (const part of model.parts) {
    const b = (bodies[part.body] ??= { parts: [] });
    b.parts.push(part);
  }
  return bodies.filter(Boolean).map((b, k) => {
    const local = new Map();
    const positions = [], normals = [], indices = [], patches = [];
    for (const part of b.parts) {
      const start = indices.length;
      for (const v of part.indices) {
        let id = local.get(v);
        if (id === undefined) {
          id = local.size;
          local.set(v, id);
          for (let d = 0; d < 3; ++d) positions.push(model.positions[3 * v + d]), normals.push(model.normals[3 * v + d]);
        }
        indices.push(id);
      }
      patches.push({ name: part.name, start, count: indices.length - start });
    }
    return {
      name: b.parts.length === 1 ? b.parts[0].name : `body ${k + 1}`,
      patches,
      positions: new Float32Array(positions),
      normals: new Float32Array(normals),
      indices: new Uint32Array(indices),
    };
  });
}

/** A THREE.Scene of the bodies for three's exporters; disposeCopy frees it. */
export function modelScene(model, colours = new Map()) {
  const out = new THREE.Scene();
  for (const body of bodyMeshes(model)) {
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(body.positions, 3));
    g.setAttribute('normal', new THREE.BufferAttribute(body.normals, 3));
    g.setIndex(new THREE.BufferAttribute(body.indices, 1));
    const materials = body.patches.map((p, k) => {
      g.addGroup(p.start, p.count, k);
      return new THREE.MeshStandardMaterial({ name: p.name, color: colours.get(p.name) ?? 0xcccccc, roughness: 0.55, metalness: 0.05, side: THREE.DoubleSide });
    });
    const mesh = new THREE.Mesh(g, materials);
    mesh.name = body.name;
    mesh.userData = { patches: body.patches.map((p) => p.name) };
    out.add(mesh);
  }
  return out;
}

/** Free what modelScene made. */
export function disposeCopy(copy) {
  copy.traverse((o) => {
    if (!o.isMesh) return;
    o.geometry.dispose();
    for (const m of [o.material].flat()) m.dispose();
  });
}

// OBJ's "o" line runs to the end of the line and most readers split it at blanks. Control
// characters go too: C0, DEL and C1 (NEL U+0085 is a line break to some readers, and not in \s).
const objName = (name) => String(name).replace(/[\s\u0000-\u001f\u007f-\u009f]+/g, '_') || 'patch';

/** The bodies as OBJ text: one "o" per body, v / vn / f, no materials. */
export async function exportObj(model, colours) {
  const { OBJExporter } = await loadObj();
  const copy = modelScene(model, colours);
  for (const m of copy.children) {
    m.name = objName(m.name);
    m.material = m.material[0]; // OBJExporter takes one material; its name is cleared below
    m.material.name = ''; // no "usemtl" line: there is no .mtl file to go with it
  }
  try {
    return new OBJExporter().parse(copy);
  } finally {
    disposeCopy(copy);
  }
}

/** The bodies as binary STL (an ArrayBuffer: 84 + 50 bytes per triangle). */
export async function exportStl(model, colours) {
  const { STLExporter } = await loadStl();
  const copy = modelScene(model, colours);
  try {
    return new STLExporter().parse(copy, { binary: true }).buffer;
  } finally {
    disposeCopy(copy);
  }
}

/** The bodies as GLB (glTF 2.0 binary, an ArrayBuffer): a mesh per body, a primitive per patch. */
export async function exportGlb(model, colours, sceneName) {
  const { GLTFExporter } = await loadGltf();
  const copy = modelScene(model, colours);
  copy.name = sceneName;
  try {
    return await new GLTFExporter().parseAsync(copy, { binary: true, onlyVisible: false });
  } finally {
    disposeCopy(copy);
  }
}

// The 3MF writer puts names and the title into its XML as they are: escaped here, so a name
// from a shared link never becomes markup.
const xmlText = (s) => String(s).replace(/[\u0000-\u0008\u000b\u000c\u000e-\u001f]/g, ' ')
  .replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;').replace(/'/g, '&apos;');

/**
 * The bodies as 3MF (a Uint8Array zip): one object per body, each a build item; units as the
 * scene's (millimetres, the 3MF default a slicer assumes). Floats to 9 digits: every float32
 * reads back as itself.
 */
export async function export3mf(model, title) {
  const [{ to3dmodel, fileForContentTypes, FileForRelThumbnail }, { zipSync, strToU8 }] = await load3mf();
  const meshes = bodyMeshes(model).map((b, k) => ({ id: String(k + 1), name: xmlText(b.name), vertices: b.positions, indices: b.indices }));
  const xml = to3dmodel({
    meshes,
    items: meshes.map((m) => ({ objectID: m.id })),
    precision: 9,
    header: { unit: 'millimeter', title: xmlText(title), application: 'pdesurf' },
  });
  const rels = new FileForRelThumbnail();
  rels.add3dModel('3D/3dmodel.model');
  return zipSync({
    [fileForContentTypes.name]: strToU8(fileForContentTypes.content),
    [rels.name]: strToU8(rels.content),
    '3D/3dmodel.model': strToU8(xml),
  });
}
