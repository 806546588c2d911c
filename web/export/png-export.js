// A PNG of the current view at 1×, 2× or 4× the canvas's drawing-buffer size, optionally
// with a transparent background. Rendered off screen into a multisampled sRGB render target
// (the GPU encodes the colours as the canvas's own output does), read back, flipped to top
// first and encoded by a 2D canvas. The on-screen canvas, its size and its clear colour are
// left as they were.
import * as THREE from 'three';
import { pngSize } from './png-size.js';

const SAMPLES = 4;

/** The largest render-target side this renderer allows. */
export function maxRenderSide(renderer) {
  const gl = renderer.getContext();
  const dims = gl.getParameter(gl.MAX_VIEWPORT_DIMS);
  return Math.min(renderer.capabilities.maxTextureSize, gl.getParameter(gl.MAX_RENDERBUFFER_SIZE), dims[0], dims[1]);
}

// Read back with a transparent background, edge pixels are premultiplied (coverage × colour,
// blended in linear light); a PNG stores straight alpha. Partly covered pixels are few.
const srgbToLinear = (c) => (c < 0.04045 ? c * 0.0773993808 : Math.pow(c * 0.9478672986 + 0.0521327014, 2.4));
const linearToSrgb = (c) => (c < 0.0031308 ? c * 12.92 : 1.055 * Math.pow(c, 0.41666) - 0.055);
const toLinear = new Float32Array(256).map((_, i) => srgbToLinear(i / 255));
function unpremultiply(px) {
  for (let k = 0; k < px.length; k += 4) {
    const a = px[k + 3];
    if (a === 0 || a === 255) continue;
    for (let c = 0; c < 3; c++) {
      const linear = Math.min(1, toLinear[px[k + c]] / (a / 255));
      px[k + c] = Math.round(linearToSrgb(linear) * 255);
    }
  }
}

/**
 * { renderer, scene, camera }: the viewer's; scale: 1, 2 or 4; transparent: no background.
 * Returns { blob, width, height, scale, clamped, limit }.
 */
export async function renderPng({ renderer, scene, camera }, { scale, transparent }) {
  const buffer = renderer.getDrawingBufferSize(new THREE.Vector2());
  const size = pngSize(buffer.x, buffer.y, scale, maxRenderSide(renderer));
  const { width, height } = size;
  const target = new THREE.WebGLRenderTarget(width, height, {
    samples: Math.min(SAMPLES, renderer.capabilities.maxSamples),
    colorSpace: THREE.SRGBColorSpace,
    type: THREE.UnsignedByteType,
    depthBuffer: true,
  });
  const previousTarget = renderer.getRenderTarget();
  const clearColor = renderer.getClearColor(new THREE.Color());
  const clearAlpha = renderer.getClearAlpha();
  const pixels = new Uint8Array(width * height * 4);
  try {
    if (transparent) renderer.setClearColor(clearColor, 0);
    renderer.setRenderTarget(target);
    renderer.clear();
    renderer.render(scene, camera);
    renderer.readRenderTargetPixels(target, 0, 0, width, height, pixels);
  } finally {
    renderer.setRenderTarget(previousTarget);
    renderer.setClearColor(clearColor, clearAlpha);
    target.dispose();
  }
  if (transparent) unpremultiply(pixels);

  // WebGL rows run bottom to top; an image's top to bottom.
  const image = new ImageData(width, height);
  const row = width * 4;
  for (let y = 0; y < height; y++) image.data.set(pixels.subarray((height - 1 - y) * row, (height - y) * row), y * row);
  const canvas = document.createElement('canvas');
  canvas.width = width;
  canvas.height = height;
  canvas.getContext('2d').putImageData(image, 0, 0);
  const blob = await new Promise((resolve, reject) => {
    canvas.toBlob((b) => (b ? resolve(b) : reject(new Error(`the browser could not encode a ${width}×${height} PNG`))), 'image/png');
  });
  canvas.width = canvas.height = 0; // let the browser drop the pixels now
  return { blob, ...size };
}
