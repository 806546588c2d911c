// The page's way to read a STEP file (read-step.js in occt-worker.js, see there why): the
// worker starts on the first STEP file opened, so nothing of Open CASCADE (23 MB of wasm) is
// fetched before, and stays for the next ones. Its URL is relative: beside this file in
// web/cad/, beside the bundle's chunks in build/web/ (scripts/build-web.mjs).
import { createWorkerClient } from './worker-client.js';

const request = createWorkerClient(() => new Worker(new URL('./occt-worker.js', import.meta.url), { type: 'module' }), "Open CASCADE's worker");

/**
 * A STEP file's bytes (an ArrayBuffer, handed over) as a scene, off the page's thread.
 * onProgress({ loaded, total }): Open CASCADE's download, the first time (bytes).
 */
export async function importStep(bytes, fileName, { onProgress = null } = {}) {
  return (await request({ read: bytes, fileName }, [bytes], { onProgress })).scene;
}
