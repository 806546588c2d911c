// The size of an exported PNG: the canvas's drawing buffer times the chosen scale, reduced
// (keeping the aspect) to what the GPU can render into in one piece and to a memory cap.
export const MAX_PNG_PIXELS = 8192 * 8192; // 256 MiB of RGBA: the 2D canvas and the read-back hold it twice

/**
 * (width, height): the drawing buffer; scale: 1, 2 or 4; maxSide: the GPU's limit on a
 * render target's side. Returns { width, height, scale (the one used), clamped, limit }.
 */
export function pngSize(width, height, scale, maxSide, maxPixels = MAX_PNG_PIXELS) {
  let s = scale;
  let limit = null;
  if (Math.max(width, height) * s > maxSide) {
    s = maxSide / Math.max(width, height);
    limit = `the GPU renders at most ${maxSide} pixels a side`;
  }
  if (width * height * s * s > maxPixels) {
    s = Math.sqrt(maxPixels / (width * height));
    limit = `a PNG has at most ${Math.round(Math.sqrt(maxPixels))}² pixels`;
  }
  const w = Math.max(1, Math.floor(width * s));
  const h = Math.max(1, Math.floor(height * s));
  return { width: w, height: h, scale: s, clamped: s !== scale, limit };
}
