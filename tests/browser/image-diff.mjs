// Comparing screenshots of the 3D view: block-averaged images (noise of antialiasing
// and of SwiftShader's rasteriser averages out, and every pair compares fast) and the
// share of the drawn area where two of them differ visibly.
import { BACKGROUND } from './harness.mjs';

const VISIBLE = 24; // summed |ΔR|+|ΔG|+|ΔB| a viewer notices; png-decode.mjs uses the same for "not background"

/** Mean RGB over blocks of `block`×`block` pixels inside rect: { w, h, rgb: Float32Array }. */
export function blockAverage(img, rect, block = 4) {
  const w = Math.floor((rect.x1 - rect.x0) / block);
  const h = Math.floor((rect.y1 - rect.y0) / block);
  const rgb = new Float32Array(3 * w * h);
  const n = block * block;
  for (let by = 0; by < h; by++) {
    for (let bx = 0; bx < w; bx++) {
      let r = 0, g = 0, b = 0;
      for (let y = 0; y < block; y++) {
        const row = (rect.y0 + by * block + y) * img.width;
        for (let x = 0; x < block; x++) {
          const i = (row + rect.x0 + bx * block + x) * img.channels;
          r += img.data[i];
          g += img.data[i + 1];
          b += img.data[i + 2];
        }
      }
      const o = 3 * (by * w + bx);
      rgb[o] = r / n;
      rgb[o + 1] = g / n;
      rgb[o + 2] = b / n;
    }
  }
  return { w, h, rgb };
}

const isBackground = (rgb, o) =>
  Math.abs(rgb[o] - BACKGROUND[0]) + Math.abs(rgb[o + 1] - BACKGROUND[1]) + Math.abs(rgb[o + 2] - BACKGROUND[2]) <= VISIBLE;

/**
 * Of the blocks where either image shows a surface, the fraction that differ visibly
 * (0: the same picture, 1: nothing in common).
 */
export function drawnDifference(a, b) {
  if (a.w !== b.w || a.h !== b.h) throw new Error('images of different sizes');
  let drawn = 0, differ = 0;
  for (let o = 0; o < a.rgb.length; o += 3) {
    if (isBackground(a.rgb, o) && isBackground(b.rgb, o)) continue;
    drawn++;
    const d = Math.abs(a.rgb[o] - b.rgb[o]) + Math.abs(a.rgb[o + 1] - b.rgb[o + 1]) + Math.abs(a.rgb[o + 2] - b.rgb[o + 2]);
    if (d > VISIBLE) differ++;
  }
  return drawn ? differ / drawn : 0;
}
