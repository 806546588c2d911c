// Colours of a curvature map: three.js's Lut ('cooltowarm', a diverging map: blue for
// negative, grey at the middle, red for positive) over the scale's [min, max].
// The Lut's hex stops are taken as sRGB (what the legend canvas shows), so vertex colours
// are converted to linear: after the renderer's sRGB output the surface shows the same
// colour as the legend for the same value (with an unlit MeshBasicMaterial).
import * as THREE from 'three';
import { Lut } from 'three/addons/math/Lut.js';

export const COLOR_MAP = 'cooltowarm';
const STEPS = 256;

export function createRamp() {
  return new Lut(COLOR_MAP, STEPS);
}

/** The ramp's colour of `value` as sRGB bytes [r, g, b] (for the legend and the tests). */
export function rampBytes(lut, value) {
  const c = lut.getColor(value);
  return [Math.round(c.r * 255), Math.round(c.g * 255), Math.round(c.b * 255)];
}

/** Per-vertex linear RGB (Float32Array(3V)) of `values` on [min, max]. */
export function curvatureColors(lut, values, min, max, out = new Float32Array(3 * values.length)) {
  lut.setMin(min);
  lut.setMax(max);
  const c = new THREE.Color();
  for (let k = 0; k < values.length; k++) {
    const x = Number.isFinite(values[k]) ? values[k] : 0;
    c.copy(lut.getColor(x)).convertSRGBToLinear();
    out[3 * k] = c.r;
    out[3 * k + 1] = c.g;
    out[3 * k + 2] = c.b;
  }
  return out;
}

/** Draw the ramp from min (left) to max (right) into a canvas. */
export function paintRamp(lut, canvas) {
  const ctx = canvas.getContext('2d');
  const { width, height } = canvas;
  for (let x = 0; x < width; x++) {
    const [r, g, b] = rampBytes(lut, lut.minV + ((x + 0.5) / width) * (lut.maxV - lut.minV));
    ctx.fillStyle = `rgb(${r}, ${g}, ${b})`;
    ctx.fillRect(x, 0, 1, height);
  }
}
