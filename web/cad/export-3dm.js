// The page's way to write and to read a .3dm file (write-3dm.js and read-3dm.js in
// rhino-worker.js, see there why): the worker starts on the first .3dm export or opening, so
// nothing of rhino3dm is fetched before, and stays for the next ones. The worker's URL is
// relative: beside this file in web/cad/, beside the bundle's chunks in build/web/
// (scripts/build-web.mjs).
import { createWorkerClient } from './worker-client.js';

const request = createWorkerClient(() => new Worker(new URL('./rhino-worker.js', import.meta.url), { type: 'module' }), "rhino3dm's worker");

/** The bytes of a .3dm file of `surfaces` joined as `breps` (write-3dm.js's write3dm, off the page's thread). */
export async function export3dm(surfaces, { tolerance, title, breps, archive } = {}) {
  return (await request({ surfaces, tolerance, title, breps, archive })).bytes;
}

/** A .3dm file's bytes (an ArrayBuffer, handed over) as a scene (read-3dm.js's read3dm, off the page's thread). */
export async function import3dm(bytes, fileName) {
  return (await request({ read: bytes, fileName }, [bytes])).scene;
}
