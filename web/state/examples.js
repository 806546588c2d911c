// Fetching the example catalogue and scenes. Errors become messages a user can act
// on (which URL, which HTTP status) because they end up in the status line.

const EXAMPLES_BASE = '/examples/';

async function fetchJson(url) {
  let res;
  try {
    res = await fetch(url);
  } catch (err) {
    throw new Error(`cannot fetch ${url}: ${err.message}`);
  }
  if (!res.ok) throw new Error(`cannot fetch ${url}: HTTP ${res.status}`);
  const text = await res.text();
  try {
    return JSON.parse(text);
  } catch (err) {
    throw new Error(`${url} is not valid JSON: ${err.message}`);
  }
}

/** The catalogue: [{ id, title, file, source }] in the order of examples/index.json. */
export async function loadExampleIndex() {
  const data = await fetchJson(EXAMPLES_BASE + 'index.json');
  const list = data && Array.isArray(data.examples) ? data.examples : null;
  if (!list || list.length === 0) throw new Error('examples/index.json lists no examples');
  return list.map((e, i) => {
    if (!e || typeof e.id !== 'string' || typeof e.file !== 'string') {
      throw new Error(`examples/index.json: entry ${i} needs string "id" and "file"`);
    }
    return { id: e.id, title: typeof e.title === 'string' ? e.title : e.id, file: e.file, source: e.source || null };
  });
}

// One scene fetched ahead (the one a cold start opens): taken by its first load.
let ahead = null; // { file, scene: Promise }

/**
 * A cold start's fetches, begun at once: the catalogue, then the scene of the example `hash`
 * (state/hash.js readHash) names, else of the first; loadExampleScene then finds that scene
 * under way or done. { index: Promise like loadExampleIndex's, scene: Promise that settles
 * once the scene is in and never rejects (the load that takes it reports failures) }.
 */
export function loadExamplesAhead(hash) {
  const index = loadExampleIndex();
  const scene = index.then((list) => {
    if (hash.kind === 'state') return;
    const entry = list.find((e) => e.id === hash.id) || list[0];
    if (!safeFileName(entry.file)) return;
    ahead = { file: entry.file, scene: fetchJson(EXAMPLES_BASE + entry.file) };
    return ahead.scene.then(() => {}, () => {});
  }, () => {});
  return { index, scene };
}

// Files are plain relative names inside examples/; anything else is refused.
const safeFileName = (file) => /^[A-Za-z0-9_\-./]+$/.test(file) && !file.split('/').includes('..') && !file.startsWith('/');

/** The scene object of one catalogue entry (a fresh object: it becomes page state). */
export async function loadExampleScene(entry) {
  if (!safeFileName(entry.file)) {
    throw new Error(`example "${entry.id}": refusing file name ${JSON.stringify(entry.file)}`);
  }
  let pending = null;
  if (ahead && ahead.file === entry.file) [pending, ahead] = [ahead.scene, null];
  const scene = await (pending || fetchJson(EXAMPLES_BASE + entry.file));
  if (!scene || typeof scene !== 'object' || Array.isArray(scene)) {
    throw new Error(`${entry.file} does not hold a scene object`);
  }
  return scene;
}
