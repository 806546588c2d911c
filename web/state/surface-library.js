// The library of primary surfaces the Add menu offers, and addSurface, which puts one in a
// scene as a "surface" patch whose expressions use fresh scene parameters (so sliders edit
// it and blends by reference follow).
//
// Parametrisations (docs/blends-by-reference.md: a blend meets a surface's t0 or t1 border):
// t runs ACROSS the borders a blend will meet (along a cylinder's axis, radially on an
// annulus, by polar angle on a sphere zone, along the tube of a torus); v runs along them.
// Closed families have v in [0, 2π], so any two closed surfaces can be blended border to
// border; the open ones (rectangles) have v in [-1, 1] (y = w·v), so any two open ones can.
// Defaults: an annulus of radii 2..3 at z = 0 and a cylinder of radius 1 from z = 1.5 to 3
// make a good first fillet (blend annulus t0 to cylinder t0).
import { isObject, checkNewPatchName, uniquePatchName, parameterPrefix, uniqueParameterName } from './patch-names.js';
import { replaceNames, checkExpression } from './expr-text.js';

const CLOSED = [0, '2*pi'];
const OPEN = [-1, 1];
const param = (key, label, value, min, max) => ({ key, label, value, min, max });

/** A patch from a template whose texts name the entry's keys: keys become parameter names. */
function fromTemplate(tpl, names) {
  const sub = (x) => (typeof x === 'string' ? replaceNames(x, names) : x);
  return {
    kind: 'surface',
    t_range: tpl.t_range.map(sub),
    v_range: tpl.v_range.map(sub),
    x: sub(tpl.x), y: sub(tpl.y), z: sub(tpl.z),
  };
}

const fixed = (tpl) => (names) => fromTemplate(tpl, names);

// z = f(x, y): f is typed in x and y (and the entry's keys, and any scene parameter).
const explicit = (xText, yText, ranges) => (names, options = {}) => {
  const f = replaceNames(String(options.f ?? 'a*(x^2 - y^2)'), { x: xText, y: yText });
  return fromTemplate({ ...ranges, x: xText, y: yText, z: f }, names);
};

export const SURFACE_LIBRARY = [
  {
    id: 'annulus', label: 'plane disc / annulus', closed: true,
    params: [param('r0', 'inner radius (0: a disc)', 2, 0, 10), param('r1', 'outer radius', 3, 0.1, 12), param('h', 'height', 0, -10, 10)],
    build: fixed({ t_range: ['r0', 'r1'], v_range: CLOSED, x: 't*cos(v)', y: 't*sin(v)', z: 'h' }),
  },
  {
    id: 'rectangle', label: 'plane rectangle', closed: false,
    params: [param('x0', 'x from', -2, -10, 10), param('x1', 'x to', 2, -10, 10), param('w', 'half width in y', 2, 0.1, 10), param('h', 'height', 0, -10, 10)],
    build: fixed({ t_range: ['x0', 'x1'], v_range: OPEN, x: 't', y: 'w*v', z: 'h' }),
  },
  {
    id: 'cylinder', label: 'cylinder', closed: true,
    params: [param('r', 'radius', 1, 0.05, 10), param('z0', 'z from', 1.5, -10, 10), param('z1', 'z to', 3, -10, 10)],
    build: fixed({ t_range: ['z0', 'z1'], v_range: CLOSED, x: 'r*cos(v)', y: 'r*sin(v)', z: 't' }),
  },
  {
    id: 'cone', label: 'cone (frustum)', closed: true,
    params: [param('r0', 'radius at the start', 1, 0, 10), param('r1', 'radius at the end', 0.5, 0, 10),
      param('z0', 'z from', 1.5, -10, 10), param('z1', 'z to', 3, -10, 10)],
    build: fixed({ t_range: [0, 1], v_range: CLOSED, x: '(r0 + (r1 - r0)*t)*cos(v)', y: '(r0 + (r1 - r0)*t)*sin(v)', z: 'z0 + (z1 - z0)*t' }),
  },
  {
    id: 'sphere', label: 'sphere zone', closed: true,
    params: [param('R', 'radius', 1, 0.05, 10), param('c', 'height of the centre', 2.5, -10, 10),
      param('th0', 'polar angle from (from the bottom pole)', 0.6, 0.01, 3.13), param('th1', 'polar angle to', 2.8, 0.01, 3.13)],
    build: fixed({ t_range: ['th0', 'th1'], v_range: CLOSED, x: 'R*sin(t)*cos(v)', y: 'R*sin(t)*sin(v)', z: 'c - R*cos(t)' }),
  },
  {
    id: 'torus', label: 'torus zone', closed: true,
    params: [param('R', 'ring radius', 1.2, 0.1, 10), param('r', 'tube radius', 0.5, 0.05, 5), param('c', 'height of the centre', 2.5, -10, 10),
      param('a0', 'tube angle from (0: outer equator)', -1.2, -6.28, 6.28), param('a1', 'tube angle to', 2.5, -6.28, 6.28)],
    build: fixed({ t_range: ['a0', 'a1'], v_range: CLOSED, x: '(R + r*cos(t))*cos(v)', y: '(R + r*cos(t))*sin(v)', z: 'c + r*sin(t)' }),
  },
  {
    id: 'ellipsoid', label: 'ellipsoid zone', closed: true,
    params: [param('a', 'semi-axis x', 1.2, 0.05, 10), param('b', 'semi-axis y', 0.8, 0.05, 10), param('cz', 'semi-axis z', 1, 0.05, 10),
      param('c', 'height of the centre', 2.5, -10, 10), param('th0', 'polar angle from (from the bottom)', 0.6, 0.01, 3.13), param('th1', 'polar angle to', 2.8, 0.01, 3.13)],
    build: fixed({ t_range: ['th0', 'th1'], v_range: CLOSED, x: 'a*sin(t)*cos(v)', y: 'b*sin(t)*sin(v)', z: 'c - cz*cos(t)' }),
  },
  {
    id: 'hyperboloid', label: 'hyperboloid of one sheet', closed: true,
    params: [param('a', 'waist radius', 0.8, 0.05, 10), param('cz', 'axial scale', 1, 0.05, 10), param('c', 'height of the waist', 2.5, -10, 10),
      param('s0', 'parameter from', -1, -4, 4), param('s1', 'parameter to', 1, -4, 4)],
    build: fixed({ t_range: ['s0', 's1'], v_range: CLOSED, x: 'a*cosh(t)*cos(v)', y: 'a*cosh(t)*sin(v)', z: 'c + cz*sinh(t)' }),
  },
  {
    id: 'explicit-disc', label: 'z = f(x, y) over a disc', closed: true, options: ['f'],
    params: [param('r0', 'inner radius (0: a full disc)', 0.5, 0, 10), param('r1', 'outer radius', 3, 0.1, 12), param('a', 'amplitude a in f', 0.1, -2, 2)],
    build: explicit('t*cos(v)', 't*sin(v)', { t_range: ['r0', 'r1'], v_range: CLOSED }),
  },
  {
    id: 'explicit-rectangle', label: 'z = f(x, y) over a rectangle', closed: false, options: ['f'],
    params: [param('x0', 'x from', -2, -10, 10), param('x1', 'x to', 2, -10, 10), param('w', 'half width in y', 2, 0.1, 10), param('a', 'amplitude a in f', 0.3, -2, 2)],
    build: explicit('t', 'w*v', { t_range: ['x0', 'x1'], v_range: OPEN }),
  },
  {
    id: 'custom', label: 'custom (x, y, z in t and v)', closed: true, options: ['x', 'y', 'z', 't_range', 'v_range'],
    params: [],
    build: (names, o = {}) => fromTemplate({
      t_range: o.t_range ?? [0, 1], v_range: o.v_range ?? CLOSED,
      x: String(o.x ?? 'cos(v)'), y: String(o.y ?? 'sin(v)'), z: String(o.z ?? 't'),
    }, names),
  },
];

export const libraryEntry = (id) => SURFACE_LIBRARY.find((e) => e.id === id);

/** Check what build produced against the scene plus the new parameters; throws naming the field. */
function checkBuilt(scene, patch, newParams) {
  const probe = { parameters: { ...scene.parameters, ...newParams } };
  for (const key of ['t_range', 'v_range']) {
    const r = patch[key];
    if (!Array.isArray(r) || r.length !== 2) throw new Error(`${key}: expected [from, to]`);
    r.forEach((x, k) => checkExpression(probe, x, [], `${key}[${k}]`));
  }
  for (const axis of ['x', 'y', 'z']) checkExpression(probe, patch[axis], ['t', 'v'], axis);
}

/**
 * Add a library surface: a unique patch name (`cylinder1`, … or options.name), parameters
 * `${name}_${key}` (unique, valid for the core), version raised to 4. options: { name } and
 * the entry's own options (f for the explicit ones; x, y, z, t_range, v_range for custom).
 * Returns the new patch's name. Throws (the scene unchanged) on a bad kind, name or text.
 */
export function addSurface(scene, kindId, options = {}) {
  const entry = libraryEntry(kindId);
  if (!entry) throw new Error(`kind: no library surface ${JSON.stringify(kindId)} (${SURFACE_LIBRARY.map((e) => e.id).join(', ')})`);
  if (!isObject(scene) || !Array.isArray(scene.patches)) throw new Error('scene: expected a scene with a patches array');
  if (scene.version === 1) throw new Error('version: a version-1 scene has no "surface" patches; surfaces can be added to scenes of version 2 and later');
  const name = options.name ?? uniquePatchName(scene, kindId.replace(/-/g, '_'));
  checkNewPatchName(scene, name);
  const prefix = parameterPrefix(name, kindId.replace(/-/g, '_'));
  const taken = new Set();
  const names = {};
  const created = {};
  for (const p of entry.params) {
    names[p.key] = uniqueParameterName(scene, prefix, p.key, taken);
    taken.add(names[p.key]);
    created[names[p.key]] = { value: p.value, min: p.min, max: p.max, label: p.label };
  }
  // The entry's keys inside user text (f) name its parameters too.
  if (entry.options?.includes('f') && options.f !== undefined) {
    const keys = Object.fromEntries(entry.params.map((p) => [p.key, { value: p.value }]));
    checkExpression({ parameters: { ...scene.parameters, ...keys } }, options.f, ['x', 'y'], 'f');
  }
  const patch = { name, ...entry.build(names, options) };
  checkBuilt(scene, patch, created);
  // Validated: now change the scene.
  if (!isObject(scene.parameters)) scene.parameters = {};
  Object.assign(scene.parameters, created);
  scene.patches.push(patch);
  if (!(scene.version >= 4)) scene.version = 4;
  return name;
}
