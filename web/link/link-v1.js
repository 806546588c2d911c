// Link version 1 (docs/scene-format-v2.md, "Shareable links"): the payload is
// base64url(deflate-raw(UTF-8 JSON of { scene, grid?, camera? })).
import { LinkError } from './link-error.js';
import { encodeBase64url, decodeBase64url } from './base64url.js';
// Loaded on first use: a page opened without a link never parses the inflater (pako).
const deflate = () => import('./deflate.js');
import { parseStrictJson } from './strict-json.js';

export const MAX_INFLATED_BYTES = 1 << 20; // 1 MiB (cpp/common/limits.hpp kInflatedBytes); a larger scene is shared as a file
export const GRID_MIN = 4;
export const GRID_MAX = 256;

const isObject = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);
const isVec3 = (v) => Array.isArray(v) && v.length === 3 && v.every(Number.isFinite);
const isGridSize = (n) => Number.isInteger(n) && n >= GRID_MIN && n <= GRID_MAX;

/** Only the fields a version-1 link carries; grid and camera when well formed. */
export function pickState(obj) {
  const out = { scene: obj.scene };
  const g = obj.grid;
  if (isObject(g) && isGridSize(g.nu) && isGridSize(g.nv)) out.grid = { nu: g.nu, nv: g.nv };
  const c = obj.camera;
  if (isObject(c) && isVec3(c.position) && isVec3(c.target)) {
    out.camera = { position: [...c.position], target: [...c.target] };
  }
  return out;
}

export async function encodeV1(state) {
  if (!isObject(state) || !isObject(state.scene)) throw new LinkError('nothing to link: the page has no scene');
  const bytes = new TextEncoder().encode(JSON.stringify(pickState(state)));
  if (bytes.length > MAX_INFLATED_BYTES) {
    // code TooLarge: the page then says so and keeps no stale link (web/features/share.js).
    throw Object.assign(new LinkError(`the scene is too large for a link (${bytes.length} bytes, at most ${MAX_INFLATED_BYTES})`), { code: 'TooLarge' });
  }
  return encodeBase64url(await (await deflate()).deflateRaw(bytes));
}

/**
 * Invalid grid or camera fields are dropped (the page falls back to its defaults);
 * everything else that is wrong throws a LinkError.
 */
export async function decodeV1(payload) {
  const bytes = await (await deflate()).inflateRawCapped(decodeBase64url(payload), MAX_INFLATED_BYTES);
  let text;
  try {
    text = new TextDecoder('utf-8', { fatal: true }).decode(bytes);
  } catch {
    throw new LinkError('the link is damaged: its content is not UTF-8 text');
  }
  const obj = parseStrictJson(text);
  if (!isObject(obj)) throw new LinkError('the link holds no page state (not a JSON object)');
  if (!('scene' in obj)) throw new LinkError('the link holds no scene');
  if (!isObject(obj.scene)) throw new LinkError('the link\'s scene is not a JSON object');
  return pickState(obj);
}
