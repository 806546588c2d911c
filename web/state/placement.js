// Where a surface patch sits (scene version 4, field `placement`, docs/scene-format-v4.md):
//   X' = T + R·diag(s)·X,  R = Rx(rx)·Ry(ry)·Rz(rz), s one number or [sx, sy, sz]
// three.js Euler order 'XYZ' (the same matrix), angles in degrees in the file. Each value
// is a number or an expression over the scene's parameters (no variables).
import { isObject, requirePatch } from './patch-names.js';
import { numberField } from './expr-text.js';

const isZero = (x) => x === 0;

const MAX_DEGREES = 1e6; // the core refuses angles beyond (docs/scene-format-v4.md)

// Checks each entry (numberField throws on text the core refuses or non-finite values);
// `each(value, path)` adds a check of the entry's value.
function triple(scene, value, path, fallback, each = () => {}) {
  if (value === undefined) return [fallback, fallback, fallback];
  if (!Array.isArray(value) || value.length !== 3) throw new Error(`${path}: expected [x, y, z]`);
  value.forEach((x, k) => each(numberField(scene, x, `${path}[${k}]`), `${path}[${k}]`));
  return value.map((x) => (typeof x === 'number' ? x : String(x)));
}

function checkAngle(x, path) {
  if (Math.abs(x) > MAX_DEGREES) throw new Error(`${path}: an angle beyond ±${MAX_DEGREES} degrees`);
}

function checkScale(x, path) {
  if (x === 0) throw new Error(`${path}: must not be 0 (a scale of 0 flattens the surface)`);
}

/**
 * Set (replace) a surface's placement: { translate: [x, y, z], rotate: [rx, ry, rz] in
 * degrees, scale: s or [sx, sy, sz] }; a missing part is the identity. The field is omitted when all of it
 * is the identity (as numbers). Refuses non-finite values, text the core would refuse, and
 * a scale that is 0, naming the field. Raises the scene to version 4.
 */
export function setPlacement(scene, name, placement = {}) {
  const patch = requirePatch(scene, name);
  const path = `${name}.placement`;
  if (patch.kind !== 'surface') throw new Error(`${path}: only "surface" patches have a placement (${JSON.stringify(name)} is ${patch.kind})`);
  if (!isObject(placement)) throw new Error(`${path}: expected { translate, rotate, scale }`);
  for (const key of Object.keys(placement)) {
    if (!['translate', 'rotate', 'scale'].includes(key)) throw new Error(`${path}.${key}: unknown (translate, rotate, scale)`);
  }
  if (scene.version === 1) throw new Error('version: a version-1 scene has no "surface" patches');
  const translate = triple(scene, placement.translate, `${path}.translate`, 0);
  const rotate = triple(scene, placement.rotate, `${path}.rotate`, 0, checkAngle);
  let scale = placement.scale ?? 1;
  if (Array.isArray(scale)) scale = triple(scene, scale, `${path}.scale`, 1, checkScale);
  else {
    scale = typeof scale === 'number' ? scale : String(scale);
    checkScale(numberField(scene, scale, `${path}.scale`), `${path}.scale`);
  }
  const unit = Array.isArray(scale) ? scale.every((x) => x === 1) : scale === 1;
  if (translate.every(isZero) && rotate.every(isZero) && unit) {
    delete patch.placement;
    return;
  }
  patch.placement = { translate, rotate, scale };
  if (!(scene.version >= 4)) scene.version = 4;
}

/** R = Rx·Ry·Rz for angles in degrees, as rows. */
export function rotationMatrix([rx, ry, rz]) {
  const [a, b, c] = [rx, ry, rz].map((d) => (d * Math.PI) / 180);
  const [ca, sa, cb, sb, cc, sc] = [Math.cos(a), Math.sin(a), Math.cos(b), Math.sin(b), Math.cos(c), Math.sin(c)];
  // three.js Matrix4.makeRotationFromEuler, order 'XYZ'.
  return [
    [cb * cc, -cb * sc, sb],
    [ca * sc + sa * sb * cc, ca * cc - sa * sb * sc, -sa * cb],
    [sa * sc - ca * sb * cc, sa * cc + ca * sb * sc, ca * cb],
  ];
}

/** Where a point X of the surface lands under `placement` (values evaluated with the scene's parameters). */
export function placePoint(scene, placement, X) {
  if (!isObject(placement)) return [...X];
  const num = (x, path) => numberField(scene, x, path);
  const T = (placement.translate ?? [0, 0, 0]).map((x, k) => num(x, `placement.translate[${k}]`));
  const R = rotationMatrix((placement.rotate ?? [0, 0, 0]).map((x, k) => num(x, `placement.rotate[${k}]`)));
  const sc = placement.scale ?? 1;
  const s = Array.isArray(sc) ? sc.map((x, k) => num(x, `placement.scale[${k}]`)) : [0, 1, 2].map(() => num(sc, 'placement.scale'));
  return R.map((row, i) => T[i] + row[0] * s[0] * X[0] + row[1] * s[1] * X[1] + row[2] * s[2] * X[2]);
}

/** The placement with every entry a number: parameters and expressions evaluated (the gizmo's). */
export function placementValues(scene, placement) {
  if (!isObject(placement)) return { translate: [0, 0, 0], rotate: [0, 0, 0], scale: 1 };
  const num = (x, path) => numberField(scene, x, path);
  const three = (v, fallback, path) => (v ?? [fallback, fallback, fallback]).map((x, k) => num(x, `${path}[${k}]`));
  const sc = placement.scale ?? 1;
  return {
    translate: three(placement.translate, 0, 'placement.translate'),
    rotate: three(placement.rotate, 0, 'placement.rotate'),
    scale: Array.isArray(sc) ? three(sc, 1, 'placement.scale') : num(sc, 'placement.scale'),
  };
}

const parameterNamed = (scene, x) => (typeof x === 'string' && Object.hasOwn(scene.parameters ?? {}, x.trim()) ? x.trim() : null);

/**
 * A gizmo drag's placement `now` (numbers, a uniform scale) set on a surface whose placement
 * may name the scene's parameters: an entry that is a parameter's name moves that parameter
 * (within its range: the surface stops at its end, as the slider does), a number is replaced,
 * any other expression is kept (the drag cannot move along it). The aeroplane's wing sits at
 * translate ["wing_x", 0, 0]: dragging it along x is dragging wing_x. One edit: one undo step.
 */
export function dragPlacement(scene, name, now) {
  const patch = requirePatch(scene, name);
  const old = patch.placement;
  if (!isObject(old)) return setPlacement(scene, name, now);
  const moved = (was, value) => {
    if (was === undefined || typeof was === 'number') return value;
    const p = parameterNamed(scene, was);
    if (!p) return was;
    const param = scene.parameters[p];
    const lo = Number.isFinite(param.min) ? param.min : -Infinity, hi = Number.isFinite(param.max) ? param.max : Infinity;
    param.value = Math.min(hi, Math.max(lo, value));
    return was;
  };
  const three = (was, values) => values.map((x, k) => moved(was?.[k], x));
  const scale = Array.isArray(old.scale) ? three(old.scale, [now.scale, now.scale, now.scale]) : moved(old.scale, now.scale);
  setPlacement(scene, name, { translate: three(old.translate, now.translate), rotate: three(old.rotate, now.rotate), scale });
}
